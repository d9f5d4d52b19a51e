/* f32_rvv.c - the RVV port (RVV 1.0, vector-length agnostic: VLMAX lanes of
 * 32 bits, whatever the VLEN): its f32 kernel and sampler batches of both
 * tiers and their tables (src/f32/f32_port_body.h), over facet/rvv.h.
 * Whole vectors of VLMAX lanes, then the tail (n % VLMAX) loaded and stored
 * with vl = the elements left, so nothing past n is read or written and no
 * tail needs a stack copy; the RGB layouts by strided vlse32 / vsse32.
 * Built with clang (RVV_CC, ports/rvv/port.mk). */
#include "facet/rvv.h"

/* the lanes of one vector (VLMAX): facet_port_at's "lanes" (the tables'
 * lanes_fn, asked only where the CPU has V: vsetvli traps elsewhere) */
static int facet_rvv_lanes(void) { return (int)facet_rvv_vlmax(); }

/* a stream of element stride s (1 planar, 3 interleaved: the RGB batch),
 * r elements from element i: unit stride by vle32 / vse32, others by the
 * strided vlse32 / vsse32 (the stride in bytes) */
FACET_INLINE facet_rvv_v rb_load_s_(const float *p, ptrdiff_t s, size_t i, size_t r)
{
    if (s == 1)
        return facet_rvv_load(p + i, r);
    return FACET_RVV_F_(vlse32_v)(p + (ptrdiff_t)i * s, s * (ptrdiff_t)sizeof(float), r);
}
FACET_INLINE void rb_store_s_(float *p, ptrdiff_t s, size_t i, size_t r, facet_rvv_v v)
{
    FACET_RVV_F_(vsse32_v)(p + (ptrdiff_t)i * s, s * (ptrdiff_t)sizeof(float), v, r);
}

#define BATCH_PORT rvv
#define BATCH_V facet_rvv_v
#define BATCH_W 0 /* vector-length agnostic: facet_port_at asks BATCH_LANES_FN */
#define BATCH_STEP facet_rvv_vlmax()
#define BATCH_LANES_FN facet_rvv_lanes
#define BATCH_LOAD(p) facet_rvv_load((p), FACET_RVV_VL_)
#define BATCH_STORE(p, v) facet_rvv_store((p), (v), FACET_RVV_VL_)
#define BATCH_LOAD_N(p, r) facet_rvv_load((p), (r))
#define BATCH_STORE_N(p, v, r) facet_rvv_store((p), (v), (r))
#define BATCH_LOAD_S(p, s, i, r) rb_load_s_((p), (s), (i), (r))
#define BATCH_STORE_S(p, s, i, r, v) rb_store_s_((p), (s), (i), (r), (v))
#include "../../src/f32/f32_port_body.h"
