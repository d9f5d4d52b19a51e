/* f32_rvv.c - the RVV port's batch functions (RVV 1.0, vector-length
 * agnostic: VLMAX lanes of 32 bits, whatever the VLEN).  Strip-mined: each
 * strip vl = vsetvl(n - i) lanes, loaded and stored with that vl (unit
 * stride, or strided vlse32 / vsse32 for the RGB layouts), so nothing past
 * n is read or written and no tail needs a stack copy; all of a strip's
 * inputs are loaded before its outputs are stored, so out may alias any
 * input.  Built with clang (RVV_CC, ports/rvv/port.mk). */
#include "facet/rvv.h"
#include "../../src/core/port.h"
#include "../../src/core/sample_port.h"

/* the lanes of one strip at most (VLMAX): facet_port_at's "lanes" */
int facet_rvv_lanes(void) { return (int)facet_rvv_vlmax(); }

#define RB_PARAM_(q) const float *x##q
#define RB_LOAD_(q) facet_rvv_load(x##q + i, vl)

/* Names generated here from src/core/kernels.def: one batch function per kernel
 * and tier, and the two port tables. */
#define RB_DEF_(name, n, tier)                                                              \
    static void rb_##name##_##tier(float *out, FACET_EACH_INPUT(n, RB_PARAM_), size_t count) \
    {                                                                                      \
        size_t i, vl;                                                                      \
        for (i = 0; i < count; i += vl) {                                                  \
            vl = facet_rvv_vl(count - i);                                                  \
            facet_rvv_store(out + i, facet_##name##_##tier##_rvv(FACET_EACH_INPUT(n, RB_LOAD_)), vl); \
        }                                                                                  \
    }
#define FACET_KERNEL(name, NAME, n, ...) RB_DEF_(name, n, f32) RB_DEF_(name, n, f32_fast)
#include "../../src/core/kernels.def"
#undef FACET_KERNEL

/* RGB: each stream an element stride (src/core/port.h: 1 planar, 3 interleaved,
 * 0 uniform): a strided load (vlse32, the stride in bytes; 0 broadcasts
 * the one value), every output a strided store */
FACET_INLINE facet_rvv_v rb_load_s_(const float *p, ptrdiff_t s, size_t i, size_t vl)
{
    return FACET_RVV_F_(vlse32_v)(p + (ptrdiff_t)i * s, s * (ptrdiff_t)sizeof(float), vl);
}
FACET_INLINE void rb_store_s_(float *p, ptrdiff_t s, size_t i, facet_rvv_v v, size_t vl)
{
    FACET_RVV_F_(vsse32_v)(p + (ptrdiff_t)i * s, s * (ptrdiff_t)sizeof(float), v, vl);
}
#define RB_RGB_(tier)                                                                       \
    static void rb_brdf_hammon_rgb_##tier(const facet_rgb_io *io, const float *nol, const float *nov, \
                                          const float *lov, size_t count)                  \
    {                                                                                      \
        size_t i, vl;                                                                      \
        ptrdiff_t as = io->alpha_stride, ms = io->material_stride, os = io->out_stride;    \
        for (i = 0; i < count; i += vl) {                                                  \
            facet_rvv_v r, g, b;                                                           \
            vl = facet_rvv_vl(count - i);                                                  \
            facet_brdf_hammon_rgb_##tier##_rvv(                                            \
                &r, &g, &b, facet_rvv_load(nol + i, vl), facet_rvv_load(nov + i, vl),     \
                facet_rvv_load(lov + i, vl), rb_load_s_(io->alpha, as, i, vl),             \
                rb_load_s_(io->f0[0], ms, i, vl), rb_load_s_(io->f0[1], ms, i, vl),        \
                rb_load_s_(io->f0[2], ms, i, vl), rb_load_s_(io->albedo[0], ms, i, vl),    \
                rb_load_s_(io->albedo[1], ms, i, vl), rb_load_s_(io->albedo[2], ms, i, vl)); \
            rb_store_s_(io->out[0], os, i, r, vl);                                         \
            rb_store_s_(io->out[1], os, i, g, vl);                                         \
            rb_store_s_(io->out[2], os, i, b, vl);                                         \
        }                                                                                  \
    }
RB_RGB_(f32)
RB_RGB_(f32_fast)

/* lanes 0: vector-length agnostic, facet_port_at asks facet_rvv_lanes() */
const facet_f32_port facet_port_rvv_f32 = {
    "rvv", 0,
#define FACET_KERNEL(name, NAME, n, ...) rb_##name##_f32,
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
    rb_brdf_hammon_rgb_f32,
};
const facet_f32_port facet_port_rvv_f32_fast = {
    "rvv", 0,
#define FACET_KERNEL(name, NAME, n, ...) rb_##name##_f32_fast,
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
    rb_brdf_hammon_rgb_f32_fast,
};

/* the samplers (src/core/sample_port.h): outputs through pointers to three
 * locals (sizeless vectors have no arrays), loads and stores with vl */
#define RS_IN_1 facet_rvv_load(in[0] + i, vl)
#define RS_IN_2 RS_IN_1, facet_rvv_load(in[1] + i, vl)
#define RS_IN_3 RS_IN_2, facet_rvv_load(in[2] + i, vl)
#define RS_IN_4 RS_IN_3, facet_rvv_load(in[3] + i, vl)
#define RS_IN_5 RS_IN_4, facet_rvv_load(in[4] + i, vl)
#define RS_IN_6 RS_IN_5, facet_rvv_load(in[5] + i, vl)
#define RS_IN_7 RS_IN_6, facet_rvv_load(in[6] + i, vl)
#define RS_IN_8 RS_IN_7, facet_rvv_load(in[7] + i, vl)
#define RS_CALL_vec_2(k, n_in) k(&o0, &o1, RS_IN_##n_in)
#define RS_CALL_vec_3(k, n_in) k(&o0, &o1, &o2, RS_IN_##n_in)
#define RS_CALL_ret_1(k, n_in) o0 = k(RS_IN_##n_in)
#define RS_STORE_1 facet_rvv_store(out[0] + i, o0, vl)
#define RS_STORE_2 RS_STORE_1; facet_rvv_store(out[1] + i, o1, vl)
#define RS_STORE_3 RS_STORE_2; facet_rvv_store(out[2] + i, o2, vl)
#define RS_DEF_(name, kind, n_out, n_in, tier)                                              \
    static void rs_##name##_##tier(float *const *out, const float *const *in, size_t count) \
    {                                                                                      \
        size_t i, vl;                                                                      \
        for (i = 0; i < count; i += vl) {                                                  \
            facet_rvv_v o0, o1, o2;                                                        \
            vl = facet_rvv_vl(count - i);                                                  \
            RS_CALL_##kind##_##n_out(facet_##name##_##tier##_rvv, n_in);                   \
            RS_STORE_##n_out;                                                              \
            (void)o1;                                                                      \
            (void)o2;                                                                      \
        }                                                                                  \
    }
#define FACET_SAMPLER(name, NAME, kind, err, n_out, n_in, ...) \
    RS_DEF_(name, kind, n_out, n_in, f32) RS_DEF_(name, kind, n_out, n_in, f32_fast)
#include "../../src/core/sample_kernels.def"
#undef FACET_SAMPLER

const facet_sample_port facet_sample_port_rvv_f32 = {
    "rvv", 0,
#define FACET_SAMPLER(name, ...) rs_##name##_f32,
#include "../../src/core/sample_kernels.def"
#undef FACET_SAMPLER
};
const facet_sample_port facet_sample_port_rvv_f32_fast = {
    "rvv", 0,
#define FACET_SAMPLER(name, ...) rs_##name##_f32_fast,
#include "../../src/core/sample_kernels.def"
#undef FACET_SAMPLER
};
