/* f32_table.c - the kernel table behind facet_kernel_at/find and the
 * sampler table behind facet_sampler_at/find (for tools and tests).
 * Names generated here from src/core/kernels.def: one table row and its five
 * array-argument wrappers per kernel; from src/core/sample_kernels.def: one
 * row and its five wrappers per sampler. */
#include <string.h>
#include "facet.h"
#include "facet/oracle.h"
#include "facet/scalar.h"
#include "../core/kernel_list.h"
#include "../core/sample_port.h"

static int any_nan(const double *in, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (in[i] != in[i])
            return 1;
    return 0;
}

#define SAMPLE_(q) in[q]
/* the oracle entry applies the kernels' NaN rule (facet.h): a NaN input -> 0 */
#define FACET_KERNEL(name, NAME, n, ...)                                                       \
    static float f32_##name(const float *in) { return facet_##name##_f32(FACET_EACH_INPUT(n, SAMPLE_)); } \
    static double oracle_##name(const double *in)                                              \
    {                                                                                          \
        if (any_nan(in, n))                                                                    \
            return 0.0;                                                                        \
        return facet_oracle_##name(FACET_EACH_INPUT(n, SAMPLE_));                              \
    }                                                                                          \
    static void batch_##name(float *out, const float *const *in, size_t count)                 \
    {                                                                                          \
        facet_##name##_f32_batch(out, FACET_EACH_INPUT(n, SAMPLE_), count);                    \
    }                                                                                          \
    static float f32_fast_##name(const float *in)                                              \
    {                                                                                          \
        return facet_##name##_f32_fast(FACET_EACH_INPUT(n, SAMPLE_));                          \
    }                                                                                          \
    static void batch_fast_##name(float *out, const float *const *in, size_t count)            \
    {                                                                                          \
        facet_##name##_f32_fast_batch(out, FACET_EACH_INPUT(n, SAMPLE_), count);               \
    }
#include "../core/kernels.def"
#undef FACET_KERNEL

static const facet_kernel table[] = {
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    { #name, n, { FACET_MAP_INPUTS(n, FACET_IN_NAME, __VA_ARGS__) }, f32_##name, oracle_##name, batch_##name, FACET_ERR_##NAME##_F32, \
      f32_fast_##name, batch_fast_##name, FACET_ERR_##NAME##_F32_FAST },
#include "../core/kernels.def"
#undef FACET_KERNEL
};

size_t facet_kernel_count(void) { return sizeof table / sizeof table[0]; }

const facet_kernel *facet_kernel_at(size_t i)
{
    return i < facet_kernel_count() ? &table[i] : NULL;
}

const facet_kernel *facet_kernel_find(const char *name)
{
    size_t i;
    for (i = 0; name && i < facet_kernel_count(); i++)
        if (strcmp(table[i].name, name) == 0)
            return &table[i];
    return NULL;
}

/* ---- the sampler table ------------------------------------------------------ */
#define ERR_abs 1
#define ERR_rel 0
#define FACET_SAMPLER(name, NAME, kind, err, n_out, n_in, ...)                          \
    static void t_f32_##name(float *out, const float *in)                              \
    {                                                                                  \
        FACET_SAMPLE_CALL(kind, facet_##name##_f32_scalar, out, n_out, in, n_in);      \
    }                                                                                  \
    static void t_fast_##name(float *out, const float *in)                             \
    {                                                                                  \
        FACET_SAMPLE_CALL(kind, facet_##name##_f32_fast_scalar, out, n_out, in, n_in); \
    }                                                                                  \
    static void t_oracle_##name(double *out, const double *in)                         \
    {                                                                                  \
        FACET_SAMPLE_CALL_ARRAY(kind, facet_oracle_##name, out, in, n_in);             \
    }                                                                                  \
    static void t_batch_##name(float *const *out, const float *const *in, size_t n)    \
    {                                                                                  \
        facet_##name##_f32_batch(FACET_SAMPLE_ARGS(n_out, out), FACET_SAMPLE_ARGS(n_in, in), n); \
    }                                                                                  \
    static void t_fast_batch_##name(float *const *out, const float *const *in, size_t n) \
    {                                                                                  \
        facet_##name##_f32_fast_batch(FACET_SAMPLE_ARGS(n_out, out), FACET_SAMPLE_ARGS(n_in, in), n); \
    }
#include "../core/sample_kernels.def"
#undef FACET_SAMPLER

#define BRACE_(...) { __VA_ARGS__ }
static const facet_sampler samplers[] = {
#define FACET_SAMPLER(name, NAME, kind, err, n_out, n_in, outs, ins)                    \
    { #name, n_in, BRACE_ ins, n_out, BRACE_ outs, ERR_##err, t_f32_##name, t_oracle_##name, \
      t_batch_##name, FACET_ERR_##NAME##_F32, t_fast_##name, t_fast_batch_##name,      \
      FACET_ERR_##NAME##_F32_FAST },
#include "../core/sample_kernels.def"
#undef FACET_SAMPLER
};

size_t facet_sampler_count(void) { return sizeof samplers / sizeof samplers[0]; }

const facet_sampler *facet_sampler_at(size_t i)
{
    return i < facet_sampler_count() ? &samplers[i] : NULL;
}

const facet_sampler *facet_sampler_find(const char *name)
{
    size_t i;
    for (i = 0; name && i < facet_sampler_count(); i++)
        if (!strcmp(samplers[i].name, name))
            return &samplers[i];
    return NULL;
}
