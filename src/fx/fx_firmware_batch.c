/* fx_firmware_batch.c - the fixed-point batch API for firmware: every
 * facet_<kernel>_fx_batch and _fx_fast_batch of facet/fx.h as its own loop
 * over the scalar kernel, with no port table, no dispatcher, no CPU
 * detection, no f32 code and no libm.  Each function references only its
 * own kernel, so a link with -ffunction-sections -fdata-sections
 * -Wl,--gc-sections keeps just the kernels the firmware calls (a loop
 * through the port table would keep all of them, both tiers).  Bit-
 * identical to libfacet's batches (the same scalar kernels; libfacet's own
 * scalar loops are src/fx/fx_batch_scalar.h).  One of `make fx-sources`; not
 * part of libfacet, whose src/fx/fx_batch.c dispatches.
 * Names generated here from src/core/kernels.def: the fast batch for every
 * fixed-point kernel, the precise one where it has a precise kernel
 * (fx_code both, not fast). */
#include "facet/fx.h"
#include "../core/kernel_list.h"

#define PARAM_(q) const int32_t *x##q
#define AT_(q) x##q[i]
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...)     \
    FACET_IF_PRECISE(fx_code,                                                              \
    void facet_##name##_fx_batch(fx_type *out, FACET_EACH_INPUT(n, PARAM_), size_t count)  \
    {                                                                                      \
        size_t i;                                                                          \
        for (i = 0; i < count; i++) {                                                      \
            out[i] = facet_##name##_fx(FACET_EACH_INPUT(n, AT_));                          \
        }                                                                                  \
    })                                                                                     \
    FACET_IF_FX(fx_type,                                                                   \
    void facet_##name##_fx_fast_batch(fx_type *out, FACET_EACH_INPUT(n, PARAM_), size_t count) \
    {                                                                                      \
        size_t i;                                                                          \
        for (i = 0; i < count; i++) {                                                      \
            out[i] = facet_##name##_fx_fast(FACET_EACH_INPUT(n, AT_));                     \
        }                                                                                  \
    })
#include "../core/kernels.def"
#undef FACET_KERNEL

const char *facet_fx_port_name(void)
{
    return "scalar";
}
