/* loops_batch.c - benchmark loops over the batch API facet_<k>_f32_batch:
 * one call per pass, on whatever port facet_set_port() chose.  No chain
 * (the latency of a port is its inline kernel's, see loops_<port>.c). */
#include "facet.h"
#include "loops.h"

static int always(void) { return 1; }

#define B1(name) facet_##name##_f32_batch(out, in[0], n)
#define B2(name) facet_##name##_f32_batch(out, in[0], in[1], n)
#define B3(name) facet_##name##_f32_batch(out, in[0], in[1], in[2], n)
#define B5(name) facet_##name##_f32_batch(out, in[0], in[1], in[2], in[3], in[4], n)
#define B6(name) facet_##name##_f32_batch(out, in[0], in[1], in[2], in[3], in[4], in[5], n)
#define K(name, NAME, n_, ...) \
    static void batch_##name(float *out, const float *const *in, size_t n) { B##n_(name); }
#include "../src/kernels.def"
#undef K

static const bench_loop k_[] = {
#define K(name, NAME, n, ...) { batch_##name, 0 },
#include "../src/kernels.def"
#undef K
    { 0, 0 },
};

const bench_loops bench_loops_batch = { "batch", "auto", 1, always, k_ };
