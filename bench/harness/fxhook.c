/* fxhook.c - see fxhook.h. */
#include <math.h>
#include <string.h>
#include "fxhook.h"
#include "src/core/kernel_list.h"

static volatile int32_t opaque_zero; /* always 0; the compiler cannot know */

#define ROW_(q) in[q][i]
#define COL_(q) in[q]
#define CHAINED_(q) (q == 0 ? in[0][i] + (int32_t)(uint32_t)y * z : in[q][i])

/* Names generated here from src/core/kernels.def: three loops per fixed-point
 * kernel and tier (the fast tier only where fx_code is fast: NULL in the
 * table), and the table. */
#define FX_LOOPS(name, T, tier, suffix, n)                                                         \
    static void batch_##name##suffix(void *out, const int32_t *const *in, size_t n_)               \
    {                                                                                              \
        facet_##name##_##tier##_batch((T *)out, FACET_EACH_INPUT(n, COL_), n_);                    \
    }                                                                                              \
    static void call_##name##suffix(void *out, const int32_t *const *in, size_t n_)                \
    {                                                                                              \
        T *o = (T *)out;                                                                           \
        size_t i;                                                                                  \
        for (i = 0; i < n_; i++)                                                                   \
            o[i] = facet_##name##_##tier(FACET_EACH_INPUT(n, ROW_));                               \
    }                                                                                              \
    static void chain_##name##suffix(void *out, const int32_t *const *in, size_t n_)               \
    {                                                                                              \
        T y = 0;                                                                                   \
        int32_t z = opaque_zero;                                                                   \
        size_t i;                                                                                  \
        for (i = 0; i < n_; i++)                                                                   \
            y = facet_##name##_##tier(FACET_EACH_INPUT(n, CHAINED_));                              \
        *(T *)out = y;                                                                             \
    }
#define FACET_KERNEL(name, NAME, n, T, fx_frac, fx_max, fx_format, fx_code, ...) \
    FACET_IF_PRECISE(fx_code, FX_LOOPS(name, T, fx, , n)) FACET_IF_FX(T, FX_LOOPS(name, T, fx_fast, _fast, n))
#include "src/core/kernels.def"
#undef FACET_KERNEL

void bench_fx_identity_chain(void *out, const int32_t *const *in, size_t n_)
{
    int32_t y = 0, z = opaque_zero;
    size_t i;
    for (i = 0; i < n_; i++)
        y = in[0][i] + (int32_t)(uint32_t)y * z;
    *(int32_t *)out = y;
}

static bench_fx table[] = {
#define FACET_KERNEL(name, NAME, n, T, fx_frac, fx_max, fx_format, fx_code, ...)                            \
    FACET_IF_FX(T, { #name, NULL, FACET_PRECISE_OR(fx_code, batch_##name, NULL),                            \
                     FACET_PRECISE_OR(fx_code, call_##name, NULL), FACET_PRECISE_OR(fx_code, chain_##name, NULL), \
                     batch_##name##_fast, call_##name##_fast, chain_##name##_fast },)
#include "src/core/kernels.def"
#undef FACET_KERNEL
};

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
