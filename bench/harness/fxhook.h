/* fxhook.h - the fixed-point kernels (facet/fx.h) as benchmark loops.
 *
 * The inputs are converted to Q15 outside the timed loops (bench_fx_q15:
 * round to nearest, ties up, the fx.h rule; then clamped to the kernel's fx
 * domain, so the oracle sees exactly what the kernel sees).  Three loops
 * per kernel, all on raw Q15 int32 arrays:
 *   batch(out, in, n)  facet_<kernel>_fx_batch on whatever port
 *                      facet_set_port() selected (fx ports dispatch there)
 *   call(out, in, n)   out[i] = facet_<kernel>_fx(in[0][i], ...), one call
 *                      per sample (the scalar library function)
 *   chain(out, in, n)  the calls in a dependent chain: the first input of
 *                      call i+1 is in[0][i+1] + (int32)y_i * z with z an
 *                      opaque zero (a volatile read before the loop), so the
 *                      domain is kept but the call waits for y_i
 * `out` holds n raw outputs in the kernel's container (int32_t, uint32_t
 * or uint64_t: bench_fx_raw reads one widened).  bench_fx_identity_chain
 * is the chain without a kernel (its overhead, subtracted from latencies).
 * bench_fx_find() returns NULL for a kernel without an fx version. */
#ifndef FACET_BENCH_FXHOOK_H
#define FACET_BENCH_FXHOOK_H

#include <stddef.h>
#include <stdint.h>
#include "facet/fx.h"

typedef void (*bench_fx_fn)(void *out, const int32_t *const *in, size_t n);

typedef struct bench_fx {
    const char *kernel;
    const facet_fx_kernel *fk;   /* the fx table entry: domain, format, bound */
    bench_fx_fn batch, call, chain; /* NULL: the fast tier only (fk->fx NULL) */
    bench_fx_fn fast_batch, fast_call, fast_chain; /* the same, facet_<kernel>_fx_fast */
} bench_fx;

const bench_fx *bench_fx_find(const char *kernel);
int bench_fx_available(void);
void bench_fx_identity_chain(void *out, const int32_t *const *in, size_t n);

/* x * 2^15 rounded to nearest, ties up (fx.h), saturated to int32; NaN -> 0 */
int32_t bench_fx_q15(double x);
/* raw output i of an out array written by one of the loops, widened */
uint64_t bench_fx_raw(const bench_fx *f, const void *out, size_t i);
/* raw output as a real value: raw * 2^-out_frac (Q15 outputs are signed) */
double bench_fx_value(const bench_fx *f, uint64_t raw);

#endif
