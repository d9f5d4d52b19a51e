/* fx_batch_scalar.h - a fixed-point tier's scalar port: one loop per kernel
 * over facet_<kernel>_<FX_TIER> and the tier's port table.  Included once
 * by the file of each tier's scalar kernels (src/fx/fx_kernels.c: fx,
 * src/fx/fx_fast.c: fx_fast) with
 *   FX_TIER        the tier token (fx, fx_fast)
 *   FX_SCALAR_VAR  the table variable (facet_fx_port_scalar, ...)
 *   FX_TIER_PRECISE  1 for the precise tier (fx): only the kernels with a
 *                  precise kernel (fx_code both) have a loop there
 * Names generated here from src/core/kernels.def: one loop per fixed-point
 * kernel of the tier (the table's other members NULL).  Each element is
 * read before its output is written, so out may be the same array as an
 * input. */
#include "../core/port.h"

#if FX_TIER_PRECISE
#define FXSL_IF(fx_type, fx_code, ...) FACET_IF_PRECISE(fx_code, __VA_ARGS__)
#else
#define FXSL_IF(fx_type, fx_code, ...) FACET_IF_FX(fx_type, __VA_ARGS__)
#endif

#define FXSL_CAT_(a, b, c) a##b##c
#define FXSL_CAT(a, b, c) FXSL_CAT_(a, b, c)
#define FXSL_PARAM_(q) const int32_t *x##q
#define FXSL_AT_(q) x##q[i]
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    FXSL_IF(fx_type, fx_code,                                                        \
    static void FXSL_CAT(scalar_, name, _loop)(fx_type *out, FACET_EACH_INPUT(n, FXSL_PARAM_), \
                                               size_t count)                         \
    {                                                                                \
        size_t i;                                                                    \
        for (i = 0; i < count; i++)                                                  \
            out[i] = FXSL_CAT(facet_##name##_, FX_TIER, )(FACET_EACH_INPUT(n, FXSL_AT_)); \
    })
#include "../core/kernels.def"
#undef FACET_KERNEL

const facet_fx_port FX_SCALAR_VAR = {
    "scalar", 1,
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    FXSL_IF(fx_type, fx_code, .name = FXSL_CAT(scalar_, name, _loop),)
#include "../core/kernels.def"
#undef FACET_KERNEL
};
