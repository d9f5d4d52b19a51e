/* fx_rgb.c - the fixed-point RGB batches of brdf_hammon, both tiers
 * (facet/fx.h): the scalar loop over facet_brdf_hammon_rgb_fx[_fast], which
 * share the geometry across channels (src/fx/fx_body.h, src/fx/fx_fast_body.h)
 * and give each channel the per-channel kernel's bits, so these are the
 * per-channel kernels' bits on every port; the scalar loop everywhere
 * (no port runs the RGB form on lanes); part of the firmware sources (make
 * fx-sources). */
#include <stddef.h>
#include "facet/fx.h"

/* Per tier: the planar loop gathers each sample's channels (three arrays:
 * no contiguous copy a compiler could turn into memcpy); the interleaved
 * batch calls the RGB kernel on its arrays in place. */
#define RGB_FX_(tier)                                                                          \
    static void rgb_loop_##tier(uint64_t *const out[3], const int32_t *nol, const int32_t *nov, \
                                const int32_t *lov, const int32_t *alpha,                       \
                                const int32_t *const f0[3], const int32_t *const albedo[3],     \
                                size_t n)                                                        \
    {                                                                                           \
        size_t i;                                                                               \
        for (i = 0; i < n; i++) {                                                               \
            int32_t f[3], a[3];                                                                 \
            uint64_t o[3];                                                                      \
            int c;                                                                              \
            for (c = 0; c < 3; c++) {                                                           \
                f[c] = f0[c][i];                                                                  \
                a[c] = albedo[c][i];                                                              \
            }                                                                                   \
            facet_brdf_hammon_rgb_##tier(o, nol[i], nov[i], lov[i], alpha[i], f, a);            \
            for (c = 0; c < 3; c++) {                                                           \
                out[c][i] = o[c];                                                               \
            }                                                                                   \
        }                                                                                       \
    }                                                                                           \
    void facet_brdf_hammon_rgb_##tier##_batch(uint64_t *const out[3], const int32_t *nol,       \
                                              const int32_t *nov, const int32_t *lov,           \
                                              const int32_t *alpha, const int32_t *const f0[3], \
                                              const int32_t *const albedo[3], size_t n)         \
    {                                                                                           \
        rgb_loop_##tier(out, nol, nov, lov, alpha, f0, albedo, n);                              \
    }                                                                                           \
    void facet_brdf_hammon_rgb_##tier##_batch_interleaved(uint64_t *out, const int32_t *nol,    \
                                                          const int32_t *nov,                   \
                                                          const int32_t *lov,                   \
                                                          const int32_t *alpha,                 \
                                                          const int32_t *f0,                    \
                                                          const int32_t *albedo, size_t n)      \
    {   /* in place: no copies (copy loops of 3 became memcpy calls at -Os on M0); */           \
        size_t i; /* out overlaps no input (facet/fx.h) */                                      \
        for (i = 0; i < n; i++) {                                                               \
            facet_brdf_hammon_rgb_##tier(&out[3u * i], nol[i], nov[i], lov[i], alpha[i], &f0[3u * i], \
                                         &albedo[3u * i]);                                      \
        }                                                                                       \
    }
RGB_FX_(fx)
RGB_FX_(fx_fast)
