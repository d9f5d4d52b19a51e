/* fx_active_scalar.c - the fixed-point batch API without the dispatcher,
 * for firmware: with src/fx_core.c, src/fx_kernels.c, src/fx_batch.c (and
 * src/fx_table.c for the kernel table) it links on its own, no f32 code, no
 * CPU detection, no libm; every batch runs the scalar loop.  Not part of
 * libfacet, whose dispatcher defines this function (src/dispatch.c). */
#include "../port.h"

const facet_fx_port *facet_fx_active_port(int fast)
{
    return fast ? &facet_fx_fast_port_scalar : &facet_fx_port_scalar;
}
