/* f32_entry.c - the library's per-sample f32 entry points of both tiers
 * beyond the kernels' (which src/core/dispatch.c routes to the active
 * port's per-sample entries, src/f32/f32_one_body.h): the vector entry
 * facet_shade_hammon_rgb_f32 (_fast) over the dispatched RGB call, and the
 * samplers, the scalar port out of line.
 * Names generated here from src/core/sample_kernels.def:
 * facet_<sampler>_f32 and facet_<sampler>_f32_fast. */
#include "facet.h"
#include "facet/scalar.h"
#include "../core/kernel_list.h"
#include "../core/sample_port.h"

#define ARG_(q) x##q

/* the vector entry: the dots, the kernel, the below-horizon rule, the N.L factor */
static float dot3_(const facet_vec3_f32 *a, const facet_vec3_f32 *b)
{
    return a->x * b->x + a->y * b->y + a->z * b->z;
}

#define SHADE_(name, rgb)                                                               \
    void name(float out[3], const facet_dirs_f32 *d, const facet_material_f32 *m)       \
    {                                                                                   \
        float nol = dot3_(&d->n, &d->l), nov = dot3_(&d->n, &d->v);                     \
        float lov = dot3_(&d->l, &d->v), brdf[3], k;                                    \
        int c;                                                                          \
        rgb(brdf, nol, nov, lov, m->alpha, m->f0, m->albedo);                           \
        /* 0 below the horizon and for NaN (the compare is false) */                    \
        k = nol > 0.0f ? (nol < 1.0f ? nol : 1.0f) : 0.0f;                              \
        for (c = 0; c < 3; c++)                                                         \
            out[c] = brdf[c] * k;                                                       \
    }
SHADE_(facet_shade_hammon_rgb_f32, facet_brdf_hammon_rgb_f32)
SHADE_(facet_shade_hammon_rgb_f32_fast, facet_brdf_hammon_rgb_f32_fast)

/* ---- the samplers ---------------------------------------------------------- */
#define S_PARAM_(q) float x##q
#define SCALAR_DEF_vec(name, tier, n_in, n_out)                                              \
    void facet_##name##_##tier(float out[n_out], FACET_SAMPLE_EACH(n_in, S_PARAM_))          \
    {                                                                                        \
        facet_##name##_##tier##_scalar(FACET_SAMPLE_OUTS(n_out, out), FACET_SAMPLE_EACH(n_in, ARG_)); \
    }
#define SCALAR_DEF_ret(name, tier, n_in, n_out)                                              \
    float facet_##name##_##tier(FACET_SAMPLE_EACH(n_in, S_PARAM_))                           \
    {                                                                                        \
        return facet_##name##_##tier##_scalar(FACET_SAMPLE_EACH(n_in, ARG_));                \
    }
#define FACET_SAMPLER(name, NAME, kind, err, n_out, n_in, ...) \
    SCALAR_DEF_##kind(name, f32, n_in, n_out) SCALAR_DEF_##kind(name, f32_fast, n_in, n_out)
#include "../core/sample_kernels.def"
#undef FACET_SAMPLER
