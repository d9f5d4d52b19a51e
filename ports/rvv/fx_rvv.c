/* fx_rvv.c - the fixed-point lane op layer (src/fx/fx_ops.h) on RVV 1.0,
 * vector-length agnostic: VLMAX lanes of 32 bits in a vuint32m1_t, a 64-bit
 * lane value one element of a vuint64m2_t (the same lane count at twice the
 * LMUL): the exact 32x32->64 product is one widening vwmulu, its high word
 * a narrowing shift, the 64/32 division one vdivu / vremu at SEW 64 (exact),
 * the integer root lane by lane (the scalar primitive).  Every op runs on
 * all VLMAX lanes; the batch loads and stores use the strip's vl (nothing
 * past n is read or written).  Integer instructions only, bit-identical to
 * the scalar specification (tests/fx/test_fx_ports.c and the pinned
 * hashes, run at VLEN 128, 256 and 512 by tests/suites/54-rvv.sh).
 *
 * RVV 1.0 has no clz (that is Zvbb): clz(a) = 1054 - the biased exponent
 * of a widened exactly to double (vfwcvt, exact for every u32), and 0 gives
 * 1054, held at 32 by a min.  Shift counts by register use the low 5 bits
 * (SEW 32) or 6 bits (SEW 64); the bodies' counts are all in range
 * (src/fx/fx_ops.h). */
#include <riscv_vector.h>
#include <stdint.h>
#include <stddef.h>
#include "../../src/fx/fx_prims.h"

typedef vint32m1_t fxv_i32;
typedef vuint32m1_t fxv_u32;
typedef vuint64m2_t fxv_u64;
#define FXV_W 0 /* run time: facet_rvv_lanes() */
#define FXV_STEP vsetvlmax_e32m1()
#define FXV_PORT_NAME "rvv"
#define FXV_PORT_VAR facet_fx_port_rvv
#define FXV_FAST_PORT_VAR facet_fx_fast_port_rvv
/* Which kernels of each tier run on these lanes; the others run the tier's
 * scalar loop.  Measured: executed instructions per sample under
 * qemu-riscv64 at VLEN 128 (64-sample batches of in-domain inputs, a
 * -DFACET_FX_ALL_LANES build; VLEN 512 in brackets), on lanes where the
 * scalar loop executed >= 1.15x as many.  Fast: every kernel (4.0 to 7.5;
 * 14.6 to 27.2).  Precise: every kernel but loh_from_dots, whose one root is
 * lane by lane (0.96; 1.07): 1.33 (2.07) smith_g2_uncorrelated to 9.44
 * (35.5) g_kelemen, brdf_hammon 2.04 (4.73).  (Before: no precise kernel on
 * lanes.) */
#define FXV_LANES_FX(X) X(noh_from_dots) X(fresnel_schlick) X(ggx_d) X(ggx_aniso_d) X(smith_g1) X(smith_g2)      \
    X(smith_g2_uncorrelated) X(smith_vis) X(smith_g1_hammon) X(smith_g2_hammon) X(smith_vis_hammon)                \
    X(g_implicit) X(g_neumann) X(g_cook_torrance) X(g_kelemen) X(smith_g1_beckmann) X(smith_g1_schlick_beckmann) \
    X(smith_vis_joint_approx) X(smith_vis_fit) X(diffuse_hammon) X(brdf_hammon)
#define FXV_LANES_FX_FAST_ALL 1

/* FXV_INLINE the ops, FXV_BODY the precise body's functions (src/fx/fx_ops.h):
 * inlined, so a kernel is one sequence of vector instructions; a body need
 * not use every op */
#define FXV_INLINE static inline __attribute__((always_inline, unused))
#define FXV_BODY FXV_INLINE
#define FXV_VL_ ((size_t)-1) /* VLMAX: see FACET_RVV_VL_ in facet/rvv.h */
FXV_INLINE fxv_u32 fxv_k32(uint32_t c) { return vmv_v_x_u32m1(c, FXV_VL_); }
FXV_INLINE fxv_u32 fxv_clamp(fxv_i32 x, int32_t lo, int32_t hi)
{
    size_t vl = FXV_VL_;
    return vreinterpret_v_i32m1_u32m1(vmin_vx_i32m1(vmax_vx_i32m1(x, lo, vl), hi, vl));
}
FXV_INLINE fxv_u32 fxv_clamp_off(fxv_i32 x, int32_t lo, int32_t hi)
{
    size_t vl = FXV_VL_;
    fxv_i32 c = vmin_vx_i32m1(vmax_vx_i32m1(x, lo, vl), hi, vl);
    return vreinterpret_v_i32m1_u32m1(vsub_vx_i32m1(c, lo, vl));
}
FXV_INLINE fxv_u32 fxv_add32(fxv_u32 a, fxv_u32 b) { return vadd_vv_u32m1(a, b, FXV_VL_); }
FXV_INLINE fxv_u32 fxv_sub32(fxv_u32 a, fxv_u32 b) { return vsub_vv_u32m1(a, b, FXV_VL_); }
FXV_INLINE fxv_u32 fxv_mul32(fxv_u32 a, fxv_u32 b) { return vmul_vv_u32m1(a, b, FXV_VL_); }
FXV_INLINE fxv_u32 fxv_shr(fxv_u32 a, int k) { return vsrl_vx_u32m1(a, (size_t)k, FXV_VL_); }
FXV_INLINE fxv_u32 fxv_shl(fxv_u32 a, int k) { return vsll_vx_u32m1(a, (size_t)k, FXV_VL_); }
FXV_INLINE fxv_u32 fxv_shrv(fxv_u32 a, fxv_u32 n) { return vsrl_vv_u32m1(a, n, FXV_VL_); }
FXV_INLINE fxv_u32 fxv_shlv(fxv_u32 a, fxv_u32 n) { return vsll_vv_u32m1(a, n, FXV_VL_); }
/* all-ones where a < b (unsigned), else 0 */
FXV_INLINE fxv_u32 fxv_lt(fxv_u32 a, fxv_u32 b)
{
    size_t vl = FXV_VL_;
    return vmerge_vxm_u32m1(vmsltu_vv_u32m1_b32(a, b, vl), vmv_v_x_u32m1(0, vl), ~0u, vl);
}
/* m is a mask (all-ones or 0): a where it is set */
FXV_INLINE fxv_u32 fxv_sel(fxv_u32 m, fxv_u32 a, fxv_u32 b)
{
    size_t vl = FXV_VL_;
    return vmerge_vvm_u32m1(vmsne_vx_u32m1_b32(m, 0, vl), b, a, vl);
}
FXV_INLINE fxv_u32 fxv_min(fxv_u32 a, fxv_u32 b) { return vminu_vv_u32m1(a, b, FXV_VL_); }
FXV_INLINE fxv_u32 fxv_max(fxv_u32 a, fxv_u32 b) { return vmaxu_vv_u32m1(a, b, FXV_VL_); }
FXV_INLINE fxv_u32 fxv_and(fxv_u32 a, fxv_u32 b) { return vand_vv_u32m1(a, b, FXV_VL_); }
FXV_INLINE fxv_u32 fxv_or(fxv_u32 a, fxv_u32 b) { return vor_vv_u32m1(a, b, FXV_VL_); }
FXV_INLINE fxv_u32 fxv_not(fxv_u32 a) { return vnot_v_u32m1(a, FXV_VL_); }
FXV_INLINE fxv_u32 fxv_clz(fxv_u32 a)
{
    size_t vl = FXV_VL_;
    vuint64m2_t d = vreinterpret_v_f64m2_u64m2(vfwcvt_f_xu_v_f64m2(a, vl)); /* exact */
    fxv_u32 e = vnsrl_wx_u32m1(d, 52, vl);                                 /* 1023 + floor(log2 a) */
    return vminu_vx_u32m1(vrsub_vx_u32m1(e, 1054u, vl), 32u, vl);
}
/* a gather: an indexed load with byte offsets 4 i */
FXV_INLINE fxv_u32 fxv_lut(const uint32_t *t, fxv_u32 i)
{
    size_t vl = FXV_VL_;
    return vluxei32_v_u32m1(t, vsll_vx_u32m1(i, 2, vl), vl);
}

FXV_INLINE fxv_u64 fxv_mulw(fxv_u32 a, fxv_u32 b) { return vwmulu_vv_u64m2(a, b, FXV_VL_); }
FXV_INLINE fxv_u64 fxv_wide(fxv_u32 a) { return vwaddu_vx_u64m2(a, 0, FXV_VL_); }
FXV_INLINE fxv_u32 fxv_lo(fxv_u64 a) { return vnsrl_wx_u32m1(a, 0, FXV_VL_); }
FXV_INLINE fxv_u32 fxv_hi(fxv_u64 a) { return vnsrl_wx_u32m1(a, 32, FXV_VL_); }
FXV_INLINE fxv_u32 fxv_narrow(fxv_u64 a) { return vnsrl_wx_u32m1(a, 0, FXV_VL_); }
FXV_INLINE fxv_u64 fxv_add64(fxv_u64 a, fxv_u64 b) { return vadd_vv_u64m2(a, b, FXV_VL_); }
FXV_INLINE fxv_u64 fxv_sub64(fxv_u64 a, fxv_u64 b) { return vsub_vv_u64m2(a, b, FXV_VL_); }
FXV_INLINE fxv_u64 fxv_shr64(fxv_u64 a, int k) { return vsrl_vx_u64m2(a, (size_t)k, FXV_VL_); }
FXV_INLINE fxv_u64 fxv_shl64(fxv_u64 a, int k) { return vsll_vx_u64m2(a, (size_t)k, FXV_VL_); }
FXV_INLINE fxv_u64 fxv_shrv64(fxv_u64 a, fxv_u32 n) { return vsrl_vv_u64m2(a, fxv_wide(n), FXV_VL_); }
FXV_INLINE fxv_u64 fxv_shlv64(fxv_u64 a, fxv_u32 n) { return vsll_vv_u64m2(a, fxv_wide(n), FXV_VL_); }
FXV_INLINE fxv_u64 fxv_and64(fxv_u64 a, uint64_t c) { return vand_vx_u64m2(a, c, FXV_VL_); }
FXV_INLINE fxv_u32 fxv_lt64(fxv_u64 a, fxv_u64 b)
{
    size_t vl = FXV_VL_;
    return vmerge_vxm_u32m1(vmsltu_vv_u64m2_b32(a, b, vl), vmv_v_x_u32m1(0, vl), ~0u, vl);
}
FXV_INLINE fxv_u64 fxv_sel64(fxv_u32 m, fxv_u64 a, fxv_u64 b)
{
    size_t vl = FXV_VL_;
    return vmerge_vvm_u64m2(vmsne_vx_u32m1_b32(m, 0, vl), b, a, vl);
}
/* the exact quotient and remainder at SEW 64 (q < 2^32: u1 < d) */
FXV_INLINE fxv_u32 fxv_div64(fxv_u32 u1, fxv_u32 u0, fxv_u32 d, fxv_u32 *r)
{
    size_t vl = FXV_VL_;
    fxv_u64 u = vor_vv_u64m2(vsll_vx_u64m2(fxv_wide(u1), 32, vl), fxv_wide(u0), vl), dw = fxv_wide(d);
    *r = fxv_narrow(vremu_vv_u64m2(u, dw, vl));
    return fxv_narrow(vdivu_vv_u64m2(u, dw, vl));
}
/* lane by lane: the scalar primitive (not always_inline: a variable-length
 * array) */
static inline __attribute__((unused)) fxv_u32 fxv_isqrt64(fxv_u64 x, fxv_u64 *rem)
{
    size_t n = vsetvlmax_e64m2(), j;
    uint64_t xb[n], sb[n], gb[n];
    vse64_v_u64m2(xb, x, n);
    for (j = 0; j < n; j++)
        gb[j] = facet_fx_isqrt64_rem(xb[j], &sb[j]);
    *rem = vle64_v_u64m2(sb, n);
    return fxv_narrow(vle64_v_u64m2(gb, n));
}

/* loads and stores: strips of VLMAX lanes, the last one with vl = n - i;
 * a uint64_t output lane is one element of the u64m2 result */
FXV_INLINE fxv_i32 fxv_load_n(const int32_t *p, size_t r)
{
    return vreinterpret_v_u32m1_i32m1(vle32_v_u32m1((const uint32_t *)p, r));
}
#define fxv_load(p) fxv_load_n((p), FXV_VL_)
FXV_INLINE void fxv_store_n_int32_t(int32_t *p, fxv_u32 v, size_t r) { vse32_v_i32m1(p, vreinterpret_v_u32m1_i32m1(v), r); }
FXV_INLINE void fxv_store_n_uint32_t(uint32_t *p, fxv_u32 v, size_t r) { vse32_v_u32m1(p, v, r); }
FXV_INLINE void fxv_store_n_uint64_t(uint64_t *p, fxv_u64 v, size_t r) { vse64_v_u64m2(p, v, r); }
#define fxv_store_int32_t(p, v) fxv_store_n_int32_t((p), (v), FXV_VL_)
#define fxv_store_uint32_t(p, v) fxv_store_n_uint32_t((p), (v), FXV_VL_)
#define fxv_store_uint64_t(p, v) fxv_store_n_uint64_t((p), (v), FXV_VL_)

#include "../../src/fx/fx_batch_body.h"
