/* port.h - what a port gives the dispatcher (src/core/dispatch.c): a batch
 * function per kernel and format.  Private to the library.
 * Names generated here from src/core/kernels.def: the members of
 * facet_f32_port and facet_fx_port; from src/core/ports.def: the tables'
 * declarations. */
#ifndef FACET_PORT_H
#define FACET_PORT_H

#include <stddef.h>
#include <stdint.h>
#include "kernel_list.h"

#define FACET_F32_PARAM_(q) const float *x##q
#define FACET_FX_PARAM_(q) const int32_t *x##q

/* The streams of an RGB batch (src/f32/f32_rgb_batch_body.h): each a pointer and an
 * element stride, 1 = planar, 3 = interleaved, 0 = one uniform value (f0 and
 * albedo each: a textured material has per-pixel albedo and uniform f0). */
typedef struct facet_rgb_io {
    float *out[3];
    ptrdiff_t out_stride;
    const float *alpha;
    ptrdiff_t alpha_stride;
    const float *f0[3], *albedo[3];
    ptrdiff_t f0_stride, albedo_stride;
} facet_rgb_io;

/* f32, one sample: the port's per-sample entries of a tier (the scalar body,
 * facet/scalar.h, compiled with the port's flags: src/f32/f32_one_body.h);
 * facet_<name>_f32 and _f32_fast call the active port's (src/core/dispatch.c) */
#define FACET_F32_ONE_PARAM_(q) float x##q
typedef struct facet_f32_one {
#define FACET_KERNEL(name, NAME, n, fx_type, ...) float (*name)(FACET_EACH_INPUT(n, FACET_F32_ONE_PARAM_));
#include "kernels.def"
#undef FACET_KERNEL
    void (*brdf_hammon_rgb)(float out[3], float nol, float nov, float lov, float alpha, const float f0[3],
                            const float albedo[3]);
} facet_f32_one;

/* f32: out[i] = facet_<name>_f32(x0[i], ...), any n, out may be an input */
typedef struct facet_f32_port {
    const char *name;
    int lanes;
#define FACET_KERNEL(name, NAME, n, fx_type, ...) \
    void (*name)(float *out, FACET_EACH_INPUT(n, FACET_F32_PARAM_), size_t count);
#include "kernels.def"
#undef FACET_KERNEL
    /* brdf_hammon with RGB f0 and albedo, the geometry once per sample */
    void (*brdf_hammon_rgb)(const facet_rgb_io *io, const float *nol, const float *nov,
                            const float *lov, size_t count);
    /* lanes 0 (vector-length agnostic): the lanes on this CPU, asked only
     * where the CPU runs the port; NULL for a port of fixed lanes */
    int (*lanes_fn)(void);
    /* the per-sample entries of the same tier, from the port's own object */
    const facet_f32_one *one;
} facet_f32_port;

/* fx: bit-identical to the scalar specification (src/fx/fx_kernels.c).  A
 * NULL member means the port has no code of its own for that kernel (none
 * measured faster than the scalar loop): the dispatcher runs the scalar
 * port's loop.  One member per fixed-point kernel in both tiers' tables; a
 * kernel with the fast tier only (kernels.def fx_code fast) is NULL in
 * every precise table (no facet_<name>_fx_batch calls it). */
typedef struct facet_fx_port {
    const char *name;
    int lanes;
#define FACET_KERNEL(name, NAME, n, fx_type, ...) FACET_IF_FX(fx_type, \
    void (*name)(fx_type *out, FACET_EACH_INPUT(n, FACET_FX_PARAM_), size_t count);)
#include "kernels.def"
#undef FACET_KERNEL
} facet_fx_port;

/* Names generated here from src/core/ports.def: every port's tables, declared
 * for every line (a table exists where the line's guard holds):
 *   f32: facet_port_<name>_f32, _f32_fast (ports/<isa>/f32_<isa>.c,
 *        src/f32/f32_batch_scalar.c; src/f32/f32_port_body.h makes them)
 *   fx:  facet_fx_port_<fx>, facet_fx_fast_port_<fx_fast> (ports/<isa>/fx_<isa>.c;
 *        scalar: src/fx/fx_kernels.c and src/fx/fx_fast.c, every kernel, the
 *        scalar loops) */
#define FACET_PORT(name, guard, cpu, fx, fx_fast, ...)                           \
    extern const facet_f32_port facet_port_##name##_f32, facet_port_##name##_f32_fast; \
    extern const facet_fx_port facet_fx_port_##fx, facet_fx_fast_port_##fx_fast;
#include "ports.def"
#undef FACET_PORT

/* the fx port of the active port for a tier (0: fx, 1: fx_fast), never
 * NULL: src/core/dispatch.c (a build without the dispatcher, firmware, has no
 * port table at all: src/fx/fx_firmware_batch.c) */
const facet_fx_port *facet_fx_active_port(int fast);

#endif
