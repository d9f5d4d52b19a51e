/* fxhook.c - see fxhook.h. */
#include <math.h>
#include <string.h>
#include "fxhook.h"

static volatile int32_t opaque_zero; /* always 0; the compiler cannot know */

#define FX_A1(i) in[0][i]
#define FX_A2(i) in[0][i], in[1][i]
#define FX_A3(i) FX_A2(i), in[2][i]
#define FX_A5(i) FX_A3(i), in[3][i], in[4][i]
#define FX_A6(i) FX_A5(i), in[5][i]
#define FX_C1(i) in[0][i] + (int32_t)(uint32_t)y * z
#define FX_C2(i) FX_C1(i), in[1][i]
#define FX_C3(i) FX_C2(i), in[2][i]
#define FX_C5(i) FX_C3(i), in[3][i], in[4][i]
#define FX_C6(i) FX_C5(i), in[5][i]
#define FX_B1 in[0]
#define FX_B2 in[0], in[1]
#define FX_B3 FX_B2, in[2]
#define FX_B5 FX_B3, in[3], in[4]
#define FX_B6 FX_B5, in[5]

/* name, arity, output container */
#define FX_KERNELS(X)                                                                              \
    X(noh_from_dots, 3, int32_t) X(loh_from_dots, 1, int32_t) X(fresnel_schlick, 2, int32_t)        \
    X(ggx_d, 2, uint32_t) X(smith_g1, 2, int32_t) X(smith_g2, 3, int32_t)                           \
    X(smith_g2_uncorrelated, 3, int32_t) X(smith_vis, 3, uint32_t) X(smith_g1_hammon, 2, int32_t)   \
    X(smith_g2_hammon, 3, int32_t) X(smith_vis_hammon, 3, uint32_t)                                 \
    X(diffuse_hammon, 5, uint32_t) X(brdf_hammon, 6, uint64_t)

#define FX_LOOPS(name, n, T)                                                                       \
    static void batch_##name(void *out, const int32_t *const *in, size_t n_)                       \
    {                                                                                              \
        facet_##name##_fx_batch((T *)out, FX_B##n, n_);                                            \
    }                                                                                              \
    static void call_##name(void *out, const int32_t *const *in, size_t n_)                        \
    {                                                                                              \
        T *o = (T *)out;                                                                           \
        size_t i;                                                                                  \
        for (i = 0; i < n_; i++)                                                                   \
            o[i] = facet_##name##_fx(FX_A##n(i));                                                  \
    }                                                                                              \
    static void chain_##name(void *out, const int32_t *const *in, size_t n_)                       \
    {                                                                                              \
        T y = 0;                                                                                   \
        int32_t z = opaque_zero;                                                                   \
        size_t i;                                                                                  \
        for (i = 0; i < n_; i++)                                                                   \
            y = facet_##name##_fx(FX_C##n(i));                                                     \
        *(T *)out = y;                                                                             \
    }
FX_KERNELS(FX_LOOPS)

void bench_fx_identity_chain(void *out, const int32_t *const *in, size_t n_)
{
    int32_t y = 0, z = opaque_zero;
    size_t i;
    for (i = 0; i < n_; i++)
        y = in[0][i] + (int32_t)(uint32_t)y * z;
    *(int32_t *)out = y;
}

#define FX_ENTRY(name, n, T) { #name, NULL, batch_##name, call_##name, chain_##name },
static bench_fx table[] = { FX_KERNELS(FX_ENTRY) };

int bench_fx_available(void)
{
    return 1;
}

const bench_fx *bench_fx_find(const char *kernel)
{
    size_t i;
    for (i = 0; kernel && i < sizeof table / sizeof table[0]; i++)
        if (!strcmp(table[i].kernel, kernel)) {
            if (!table[i].fk)
                table[i].fk = facet_fx_kernel_find(kernel);
            return table[i].fk ? &table[i] : NULL;
        }
    return NULL;
}

int32_t bench_fx_q15(double x)
{
    double y = floor(x * 32768.0 + 0.5);
    if (!(y == y))
        return 0;
    if (y >= 2147483647.0)
        return INT32_MAX;
    if (y <= -2147483648.0)
        return INT32_MIN;
    return (int32_t)y;
}

uint64_t bench_fx_raw(const bench_fx *f, const void *out, size_t i)
{
    if (f->fk->out_bits == 64)
        return ((const uint64_t *)out)[i];
    return ((const uint32_t *)out)[i];
}

double bench_fx_value(const bench_fx *f, uint64_t raw)
{
    if (!strcmp(f->fk->out_format, "Q15")) /* Q15 outputs are int32_t */
        return ldexp((double)(int32_t)(uint32_t)raw, -15);
    return ldexp((double)raw, -f->fk->out_frac);
}
