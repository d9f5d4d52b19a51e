/* fx_batch.c - the public facet_<kernel>_fx_batch entry points: the active
 * port's own fixed-point code for the kernel where it has some, the scalar
 * loop (src/fx_kernels.c) otherwise.  Bit-identical either way.
 * Names generated here from src/kernels.def: one entry point per
 * fixed-point kernel. */
#include "facet/fx.h"
#include "port.h"

#define PARAM_(q) const int32_t *x##q
#define ARG_(q) x##q
#define FACET_KERNEL(name, NAME, n, fx_type, ...) FACET_IF_FX(fx_type,                  \
    void facet_##name##_fx_batch(fx_type *out, FACET_EACH_INPUT(n, PARAM_), size_t count) \
    {                                                                                   \
        const facet_fx_port *fx = facet_fx_active_port();                               \
        (fx->name ? fx->name : facet_fx_port_scalar.name)(out, FACET_EACH_INPUT(n, ARG_), count); \
    })
#include "kernels.def"
#undef FACET_KERNEL
