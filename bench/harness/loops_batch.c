/* loops_batch.c - benchmark loops over the batch API facet_<k>_f32_batch:
 * one call per pass, on whatever port facet_set_port() chose.  No chain
 * (the latency of a port is its inline kernel's, see loops_<port>.c). */
#include "facet.h"
#include "loops.h"
#include "src/core/kernel_list.h"

static int always(void) { return 1; }

#define COL_(q) in[q]
/* Names generated here from src/core/kernels.def: one loop per kernel and tier. */
#define FACET_KERNEL(name, NAME, n_in, ...)                                    \
    static void batch_##name(float *out, const float *const *in, size_t n)     \
    {                                                                          \
        facet_##name##_f32_batch(out, FACET_EACH_INPUT(n_in, COL_), n);        \
    }                                                                          \
    static void batch_fast_##name(float *out, const float *const *in, size_t n) \
    {                                                                          \
        facet_##name##_f32_fast_batch(out, FACET_EACH_INPUT(n_in, COL_), n);   \
    }
#include "src/core/kernels.def"
#undef FACET_KERNEL

static const bench_loop k_[] = {
#define FACET_KERNEL(name, NAME, n, ...) { batch_##name, 0 },
#include "src/core/kernels.def"
#undef FACET_KERNEL
    { 0, 0 },
};

static const bench_loop k_fast_[] = {
#define FACET_KERNEL(name, NAME, n, ...) { batch_fast_##name, 0 },
#include "src/core/kernels.def"
#undef FACET_KERNEL
    { 0, 0 },
};

const bench_loops bench_loops_batch = { "batch", "auto", 1, always, k_, "f32", 0 };
const bench_loops bench_loops_batch_fast = { "batch", "auto", 1, always, k_fast_, "f32_fast", 0 };
