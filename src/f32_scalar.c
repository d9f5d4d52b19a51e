/* f32_scalar.c - the library's f32 entry points of both tiers: the scalar
 * port, out of line.
 * Names generated here from src/kernels.def: facet_<kernel>_f32 and
 * facet_<kernel>_f32_fast. */
#include "facet.h"
#include "facet/scalar.h"
#include "kernel_list.h"

#define PARAM_(q) float x##q
#define ARG_(q) x##q
#define FACET_KERNEL(name, NAME, n, ...)                                               \
    float facet_##name##_f32(FACET_EACH_INPUT(n, PARAM_))                              \
    {                                                                                  \
        return facet_##name##_f32_scalar(FACET_EACH_INPUT(n, ARG_));                   \
    }                                                                                  \
    float facet_##name##_f32_fast(FACET_EACH_INPUT(n, PARAM_))                         \
    {                                                                                  \
        return facet_##name##_f32_fast_scalar(FACET_EACH_INPUT(n, ARG_));              \
    }
#include "kernels.def"
#undef FACET_KERNEL

void facet_brdf_hammon_rgb_f32(float out[3], float nol, float nov, float lov,
                               float alpha, const float f0[3], const float albedo[3])
{
    facet_brdf_hammon_rgb_f32_scalar(out, nol, nov, lov, alpha, f0, albedo);
}

void facet_brdf_hammon_rgb_f32_fast(float out[3], float nol, float nov, float lov,
                                    float alpha, const float f0[3], const float albedo[3])
{
    facet_brdf_hammon_rgb_f32_fast_scalar(out, nol, nov, lov, alpha, f0, albedo);
}
