/* f16_port.h - what an f16 port gives the dispatcher (src/core/dispatch.c):
 * one batch function per kernel of src/core/f16_kernels.def with an f16
 * form.  Private to the library.  The tables are named by the f16 column of
 * src/core/ports.def: facet_f16_port_<f16> (ports/<isa>/f16_<isa>.c; the
 * scalar one src/f16/f16_batch_scalar.c), each made by
 * src/f16/f16_port_body.h. */
#ifndef FACET_F16_PORT_H
#define FACET_F16_PORT_H

#include <stddef.h>
#include <stdint.h>
#include "f16_list.h"

#define FACET_F16_PARAM_(q) const uint16_t *x##q

/* out[i] = facet_<name>_f16(x0[i], ...), any count, out may be an input */
typedef struct facet_f16_port {
    const char *name;
    int lanes; /* 0: vector-length agnostic (rvvfp16: VLEN / 16) */
#define FACET_F16(name, NAME, n, form, why) \
    FACET_IF_F16(form, void (*name)(uint16_t *out, FACET_EACH_INPUT(n, FACET_F16_PARAM_), size_t count);)
#include "f16_kernels.def"
#undef FACET_F16
    /* what the CPU needs for it, as a refusal names it ("" for scalar) */
    const char *needs;
} facet_f16_port;

#define FACET_PORT(name, guard, cpu, fx, fx_fast, f16, f16_cpu) extern const facet_f16_port facet_f16_port_##f16;
#include "ports.def"
#undef FACET_PORT

#endif
