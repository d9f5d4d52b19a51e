/* fx_fast.c - the fx_fast tier's scalar kernels (facet/fx.h "fast tier"):
 * the bodies of src/fx/fx_fast_body.h on one lane (src/fx/fx_ops_scalar.h), the
 * specification every port of the tier reproduces bit for bit. */
#include "facet/fx.h"
#define FXV_CONSTANT_TIME 1 /* branch-free machine code where the op layer can (fx_ops_scalar.h) */
#include "fx_ops_scalar.h"
#include "fx_fast_body.h"

#include "../core/port.h"

/* Names generated here from src/core/kernels.def: facet_<kernel>_fx_fast for
 * every kernel with a fixed-point version. */
#define PARAM_(q) int32_t x##q
#define ARG_(q) x##q
#define FACET_KERNEL(name, NAME, n, fx_type, ...) FACET_IF_FX(fx_type, \
    fx_type facet_##name##_fx_fast(FACET_EACH_INPUT(n, PARAM_))        \
    {                                                                  \
        return (fx_type)fxq_##name(FACET_EACH_INPUT(n, ARG_));         \
    })
#include "../core/kernels.def"
#undef FACET_KERNEL

void facet_brdf_hammon_rgb_fx_fast(uint64_t out[3], int32_t nol, int32_t nov, int32_t lov,
                                   int32_t alpha, const int32_t f0[3], const int32_t albedo[3])
{
    fxv_u32 FXQ_BRDF_GEOM_ARGS_(G_);
    int c;
    fxq_brdf_geometry(nol, nov, lov, alpha, FXQ_BRDF_GEOM_ARGS_(&G_));
    for (c = 0; c < 3; c++) {
        out[c] = fxq_brdf_channel(FXQ_BRDF_GEOM_ARGS_(G_), f0[c], albedo[c]);
    }
}

/* ---- the scalar port's batches: src/fx/fx_batch_scalar.h ----------------- */
#define FX_TIER fx_fast
#define FX_SCALAR_VAR facet_fx_fast_port_scalar
#define FX_TIER_PRECISE 0
#include "fx_batch_scalar.h"
