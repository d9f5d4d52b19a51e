/* wcet_main.c - the Cortex-M image behind tests/cortexm/wcet.sh: calls every
 * fixed-point kernel of both tiers (facet_<kernel>_fx, facet_<kernel>_fx_fast)
 * directly, once per vector, on the golden vectors of `facet vectors
 * <kernel> --count WCET_RANDOM --seed 1` (src/cli/fx.c, the same rule: the
 * edge cases, each distinct one once, then WCET_RANDOM pseudo-random
 * in-domain vectors from splitmix64), under qemu-system-arm with an
 * instruction trace, so wcet.sh can cut out each call (bench/cortexm/
 * cortexm_trace.awk) and take the minimum and maximum per kernel.  The
 * domains come from the kernel table (facet_fx_kernel_find); the results go
 * to a volatile sink. */
#include <stdint.h>
#include <string.h>
#include "facet/fx.h"

#include "../../src/core/kernel_list.h"

#ifndef WCET_RANDOM
#define WCET_RANDOM 256
#endif
#define MAX_EDGES (FACET_FX_MAX_INPUTS * 14 + 2)
#define MAX_VECTORS (MAX_EDGES + WCET_RANDOM)

volatile uint64_t wcet_sink;
static int32_t vec[MAX_VECTORS][FACET_FX_MAX_INPUTS];
static int n_vec;

static uint64_t rng_next(uint64_t *s) /* splitmix64, as src/cli/fx.c */
{
    uint64_t z = (*s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static void put_edge(const facet_fx_kernel *k, const int32_t *in)
{
    int i;
    for (i = 0; i < n_vec; i++)
        if (!memcmp(vec[i], in, (size_t)k->n_inputs * sizeof *in))
            return;
    memcpy(vec[n_vec++], in, sizeof vec[0]);
}

/* the vectors of `facet vectors NAME --count WCET_RANDOM --seed 1` */
static void make_vectors(const char *name)
{
    const facet_fx_kernel *k = facet_fx_kernel_find(name);
    const int32_t extra[] = { INT32_MIN, -1, 0, 1, 32767, 32768, 32769, INT32_MAX };
    int32_t mid[FACET_FX_MAX_INPUTS] = { 0 }, in[FACET_FX_MAX_INPUTS] = { 0 };
    uint64_t seed = 1;
    int i, e, j;
    n_vec = 0;
    if (!k)
        return;
    for (i = 0; i < k->n_inputs; i++)
        mid[i] = k->lo[i] + (k->hi[i] - k->lo[i]) / 2;
    for (i = 0; i < k->n_inputs; i++) {
        const int32_t own[] = { k->lo[i], k->lo[i] + 1, k->hi[i] - 1, k->hi[i], k->lo[i] - 1, k->hi[i] + 1 };
        for (e = 0; e < (int)(sizeof own / sizeof own[0] + sizeof extra / sizeof extra[0]); e++) {
            memcpy(in, mid, sizeof in);
            in[i] = e < 6 ? own[e] : extra[e - 6];
            put_edge(k, in);
        }
    }
    for (e = 0; e < 2; e++) {
        for (i = 0; i < k->n_inputs; i++)
            in[i] = e ? k->hi[i] : k->lo[i];
        put_edge(k, in);
    }
    for (j = 0; j < WCET_RANDOM; j++) {
        for (i = 0; i < k->n_inputs; i++)
            vec[n_vec][i] = k->lo[i] + (int32_t)(rng_next(&seed) % (uint64_t)(k->hi[i] - k->lo[i] + 1));
        n_vec++;
    }
}

#define ARG_(q) v[q]
/* one loop per kernel and tier (the precise tier: not the kernels with the
 * fast tier only) */
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...)             \
    FACET_IF_FX(fx_type, make_vectors(#name);                                                      \
                FACET_IF_PRECISE(fx_code, for (j = 0; j < n_vec; j++) {                            \
                    const int32_t *v = vec[j];                                                     \
                    wcet_sink = (uint64_t)facet_##name##_fx(FACET_EACH_INPUT(n, ARG_));            \
                })                                                                                 \
                for (j = 0; j < n_vec; j++) {                                                      \
                    const int32_t *v = vec[j];                                                     \
                    wcet_sink = (uint64_t)facet_##name##_fx_fast(FACET_EACH_INPUT(n, ARG_));       \
                })

int main(void)
{
    int j;
#include "../../src/core/kernels.def"
    (void)j;
    return 0;
}
