/* fx_batch.c - the public facet_<kernel>_fx_batch and _fx_fast_batch entry
 * points: the active port's own code for the kernel and tier where it has
 * some, the tier's scalar loop otherwise.  Bit-identical either way.
 * Names generated here from src/core/kernels.def: the fast entry point for
 * every fixed-point kernel, the precise one where it has a precise kernel
 * (fx_code both, not fast). */
#include "facet/fx.h"
#include "../core/port.h"

#define PARAM_(q) const int32_t *x##q
#define ARG_(q) x##q
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    FACET_IF_PRECISE(fx_code,                                                           \
    void facet_##name##_fx_batch(fx_type *out, FACET_EACH_INPUT(n, PARAM_), size_t count) \
    {                                                                                   \
        const facet_fx_port *fx = facet_fx_active_port(0);                              \
        (fx->name ? fx->name : facet_fx_port_scalar.name)(out, FACET_EACH_INPUT(n, ARG_), count); \
    })                                                                                  \
    FACET_IF_FX(fx_type,                                                                \
    void facet_##name##_fx_fast_batch(fx_type *out, FACET_EACH_INPUT(n, PARAM_), size_t count) \
    {                                                                                   \
        const facet_fx_port *fx = facet_fx_active_port(1);                              \
        (fx->name ? fx->name : facet_fx_fast_port_scalar.name)(out, FACET_EACH_INPUT(n, ARG_), count); \
    })
#include "../core/kernels.def"
#undef FACET_KERNEL
