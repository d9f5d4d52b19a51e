/* sample_dispatch.c - the samplers' public entry points: the scalar
 * functions facet_<sampler>_f32 / _f32_fast (the scalar port, out of line),
 * the batch functions facet_<sampler>_f32_batch / _f32_fast_batch routed to
 * the port the kernels' dispatcher chose (src/core/dispatch.c, asked by name
 * through facet_port_name(), so facet_set_port and FACET_PORT steer both),
 * and the sampler table (facet_sampler_at / find) for tools.
 * Names generated here from src/core/sample_kernels.def. */
#include <string.h>
#include "facet.h"
#include "facet/oracle.h"
#include "facet/scalar.h"
#include "sample_port.h"

#if defined(__x86_64__) || defined(__i386__)
#define SAMPLE_X86 1
#elif defined(__aarch64__) || (defined(__arm__) && defined(__linux__))
#define SAMPLE_ARM 1
#elif defined(__ARM_FEATURE_MVE) && (__ARM_FEATURE_MVE & 2)
#define SAMPLE_HELIUM 1
#elif defined(__riscv) && __riscv_xlen == 64 && defined(__linux__) && defined(FACET_PORT_RVV)
#define SAMPLE_RVV 1
#endif

typedef struct { const facet_sample_port *f32, *f32_fast; } sample_entry;

/* the ports compiled in, as src/core/dispatch.c lists them */
static const sample_entry sample_ports[] = {
#if SAMPLE_X86
#if defined(__x86_64__)
    { &facet_sample_port_avx512_f32, &facet_sample_port_avx512_f32_fast },
#endif
    { &facet_sample_port_avx2_f32, &facet_sample_port_avx2_f32_fast },
    { &facet_sample_port_sse2_f32, &facet_sample_port_sse2_f32_fast },
#endif
#if SAMPLE_ARM
    { &facet_sample_port_neon_f32, &facet_sample_port_neon_f32_fast },
#endif
#if SAMPLE_HELIUM
    { &facet_sample_port_helium_f32, &facet_sample_port_helium_f32_fast },
#endif
#if SAMPLE_RVV
    { &facet_sample_port_rvv_f32, &facet_sample_port_rvv_f32_fast },
#endif
    { &facet_sample_port_scalar_f32, &facet_sample_port_scalar_f32_fast },
};
#define N_SAMPLE_PORTS (sizeof sample_ports / sizeof sample_ports[0])

/* the active port's sampler tables: a strcmp over at most four names per
 * batch call; the kernels' dispatcher has already checked the CPU */
static const sample_entry *sample_port(void)
{
    const char *name = facet_port_name();
    size_t i;
    for (i = 0; i + 1 < N_SAMPLE_PORTS; i++)
        if (!strcmp(name, sample_ports[i].f32->name))
            return &sample_ports[i];
    return &sample_ports[N_SAMPLE_PORTS - 1];
}

#define OUT_P_1 float *o0
#define OUT_P_2 OUT_P_1, float *o1
#define OUT_P_3 OUT_P_2, float *o2
#define OUT_A_1 o0
#define OUT_A_2 OUT_A_1, o1
#define OUT_A_3 OUT_A_2, o2
#define IN_P_1 const float *x0
#define IN_P_2 IN_P_1, const float *x1
#define IN_P_3 IN_P_2, const float *x2
#define IN_P_4 IN_P_3, const float *x3
#define IN_P_5 IN_P_4, const float *x4
#define IN_P_6 IN_P_5, const float *x5
#define IN_P_7 IN_P_6, const float *x6
#define IN_P_8 IN_P_7, const float *x7
#define IN_A_1 x0
#define IN_A_2 IN_A_1, x1
#define IN_A_3 IN_A_2, x2
#define IN_A_4 IN_A_3, x3
#define IN_A_5 IN_A_4, x4
#define IN_A_6 IN_A_5, x5
#define IN_A_7 IN_A_6, x6
#define IN_A_8 IN_A_7, x7
#define SC_P_1 float x0
#define SC_P_2 SC_P_1, float x1
#define SC_P_3 SC_P_2, float x2
#define SC_P_4 SC_P_3, float x3
#define SC_P_5 SC_P_4, float x4
#define SC_P_6 SC_P_5, float x5
#define SC_P_7 SC_P_6, float x6
#define SC_P_8 SC_P_7, float x7
#define CAT_(a, b) a##b
#define CAT(a, b) CAT_(a, b)

/* ---- batch entry points ------------------------------------------------ */
#define FACET_SAMPLER(name, NAME, kind, err, n_out, n_in, ...)                          \
    void facet_##name##_f32_batch(CAT(OUT_P_, n_out), CAT(IN_P_, n_in), size_t n)      \
    {                                                                                  \
        float *const o_[] = { CAT(OUT_A_, n_out) };                                    \
        const float *const i_[] = { CAT(IN_A_, n_in) };                                \
        sample_port()->f32->name(o_, i_, n);                                           \
    }                                                                                  \
    void facet_##name##_f32_fast_batch(CAT(OUT_P_, n_out), CAT(IN_P_, n_in), size_t n) \
    {                                                                                  \
        float *const o_[] = { CAT(OUT_A_, n_out) };                                    \
        const float *const i_[] = { CAT(IN_A_, n_in) };                                \
        sample_port()->f32_fast->name(o_, i_, n);                                      \
    }
#include "sample_kernels.def"
#undef FACET_SAMPLER

/* ---- scalar entry points ----------------------------------------------- */
#define SCALAR_DEF_vec(name, tier, n_in, n_out)                               \
    void facet_##name##_##tier(float out[n_out], CAT(SC_P_, n_in))           \
    {                                                                         \
        facet_##name##_##tier##_scalar(FACET_SAMPLE_OUTS(n_out, out), CAT(IN_A_, n_in));                \
    }
#define SCALAR_DEF_ret(name, tier, n_in, n_out)                               \
    float facet_##name##_##tier(CAT(SC_P_, n_in))                             \
    {                                                                         \
        return facet_##name##_##tier##_scalar(CAT(IN_A_, n_in));              \
    }
#define FACET_SAMPLER(name, NAME, kind, err, n_out, n_in, ...) \
    SCALAR_DEF_##kind(name, f32, n_in, n_out) SCALAR_DEF_##kind(name, f32_fast, n_in, n_out)
#include "sample_kernels.def"
#undef FACET_SAMPLER

/* ---- the sampler table -------------------------------------------------- */
#define ERR_abs 1
#define ERR_rel 0
#define FACET_SAMPLER(name, NAME, kind, err, n_out, n_in, ...)                          \
    static void t_f32_##name(float *out, const float *in)                              \
    {                                                                                  \
        FACET_SAMPLE_CALL(kind, facet_##name##_f32_scalar, out, n_out, in, n_in);             \
    }                                                                                  \
    static void t_fast_##name(float *out, const float *in)                             \
    {                                                                                  \
        FACET_SAMPLE_CALL(kind, facet_##name##_f32_fast_scalar, out, n_out, in, n_in);        \
    }                                                                                  \
    static void t_oracle_##name(double *out, const double *in)                         \
    {                                                                                  \
        FACET_SAMPLE_CALL_ARRAY(kind, facet_oracle_##name, out, in, n_in);                   \
    }                                                                                  \
    static void t_batch_##name(float *const *out, const float *const *in, size_t n)    \
    {                                                                                  \
        sample_port()->f32->name(out, in, n);                                          \
    }                                                                                  \
    static void t_fast_batch_##name(float *const *out, const float *const *in, size_t n) \
    {                                                                                  \
        sample_port()->f32_fast->name(out, in, n);                                     \
    }
#include "sample_kernels.def"
#undef FACET_SAMPLER

#define BRACE_(...) { __VA_ARGS__ }
static const facet_sampler samplers[] = {
#define FACET_SAMPLER(name, NAME, kind, err, n_out, n_in, outs, ins)                    \
    { #name, n_in, BRACE_ ins, n_out, BRACE_ outs, ERR_##err, t_f32_##name, t_oracle_##name,         \
      t_batch_##name, FACET_ERR_##NAME##_F32, t_fast_##name, t_fast_batch_##name,      \
      FACET_ERR_##NAME##_F32_FAST },
#include "sample_kernels.def"
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
