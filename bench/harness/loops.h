/* loops.h - one benchmark loop per kernel per way of calling it.
 *
 * A loop table has one entry per kernel, in kernels.def order:
 *   thr(out, in, n)    out[i] = kernel(in[0][i], in[1][i], ...), i < n
 *   chain(out, in, n)  the same inputs through a dependent chain: the first
 *                      input of call i+1 is in[0][i+1] + y_i * 0 (exact, so
 *                      the domain is kept, but the call waits for y_i);
 *                      writes the last result to out[0].  NULL: no chain.
 * Index FACET_BENCH_IDENTITY (past the kernels) is the chain's own overhead:
 * y = in[0][i] + y * 0 with no kernel, subtracted from latencies.
 * Inline loops need n to be a multiple of their lane count (8 suffices). */
#ifndef FACET_BENCH_LOOPS_H
#define FACET_BENCH_LOOPS_H

#include <stddef.h>

typedef void (*bench_fn)(float *out, const float *const *in, size_t n);
/* a sampler's loop (src/core/sample_kernels.def): out[o][i] = output o of the
 * sampler at in[0][i], ...; n a multiple of the lane count */
typedef void (*bench_sfn)(float *const *out, const float *const *in, size_t n);

typedef struct bench_loop {
    bench_fn thr, chain;
} bench_loop;

typedef struct bench_loops {
    const char *path;   /* "inline", "call", "batch" */
    const char *port;   /* a port (src/core/ports.def); "auto": the batch API */
    int lanes;
    int (*available)(void);
    const bench_loop *k; /* facet_kernel_count() + 1 entries */
    const char *tier;   /* "f32" or "f32_fast" */
    const bench_sfn *s; /* facet_sampler_count() throughput loops of the
                         * samplers (inline and call paths), or NULL */
} bench_loops;

/* every loop table compiled for this target; NULL-terminated */
extern const bench_loops *const bench_loop_tables[];


/* the scalar port's and the batch API's (each port's inline tables,
 * bench_loops_<port>_inline: loops_port.h, listed by loops_tables.c) */
extern const bench_loops bench_loops_scalar_inline, bench_loops_scalar_call, bench_loops_batch;
/* the same for the fast tier (facet_<kernel>_f32_fast...) */
extern const bench_loops bench_loops_scalar_inline_fast, bench_loops_scalar_call_fast,
    bench_loops_batch_fast;

#endif
