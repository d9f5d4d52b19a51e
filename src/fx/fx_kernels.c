/* fx_kernels.c - the precise fixed-point tier's scalar kernels (facet/fx.h):
 * the bodies of src/fx/fx_body.h on one lane (src/fx/fx_ops_scalar.h),
 * the portable specification every port reproduces bit for bit.  Integer
 * arithmetic only (uint32 and uint64; products through fxp_mul64).
 * Formats, domain and rounding: facet/fx.h. */
#include "facet/fx.h"
#include "../core/port.h"
#include "fx_ops_scalar.h"
#include "fx_body.h"

/* Names generated here from src/core/kernels.def: facet_<kernel>_fx for
 * every kernel with a precise fixed-point kernel. */
#define PARAM_(q) int32_t x##q
#define ARG_(q) x##q
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    FACET_IF_PRECISE(fx_code,                                                          \
    fx_type facet_##name##_fx(FACET_EACH_INPUT(n, PARAM_))                             \
    {                                                                                  \
        return (fx_type)fxb_##name(FACET_EACH_INPUT(n, ARG_));                         \
    })
#include "../core/kernels.def"
#undef FACET_KERNEL

void facet_brdf_hammon_rgb_fx(uint64_t out[3], int32_t nol, int32_t nov, int32_t lov, int32_t alpha,
                              const int32_t f0[3], const int32_t albedo[3])
{
    fxv_u32 FXB_BRDF_GEOM_ARGS_(G_);
    int c;
    fxb_brdf_geometry(nol, nov, lov, alpha, FXB_BRDF_GEOM_ARGS_(&G_));
    for (c = 0; c < 3; c++) {
        out[c] = fxb_brdf_channel(FXB_BRDF_GEOM_ARGS_(G_), f0[c], albedo[c]);
    }
}

/* ---- the scalar port's batches: src/fx/fx_batch_scalar.h ----------------- */
#define FX_TIER fx
#define FX_SCALAR_VAR facet_fx_port_scalar
#define FX_TIER_PRECISE 1
#include "fx_batch_scalar.h"
