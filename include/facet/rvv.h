/* facet/rvv.h - the RISC-V Vector f32 port (RVV 1.0, vector-length
 * agnostic: one binary for any VLEN; clang >= 14 with -march=rv64gcv, the
 * v0.10 intrinsic names of clang 14, no __riscv_ prefix): every kernel as a
 * FACET_INLINE function on vfloat32m1_t (or vfloat32m2_t with
 * FACET_RVV_LMUL 2), named facet_<kernel>_f32_rvv and
 * facet_<kernel>_f32_fast_rvv.  Contracts: facet.h; the same bounds hold in
 * every lane.
 *
 * Every op works on all VLMAX lanes (vsetvlmax): a caller loads and stores
 * with the strip's vl (vle32 / vse32 with vl = vsetvl(n)), so nothing past n
 * is read or written; the lanes past vl hold whatever the load left there
 * and their results are never stored (nothing traps: floating-point
 * exceptions only set flags).
 *
 * Reciprocal and rsqrt start from RVV's 7-bit estimates (vfrec7, vfrsqrt7:
 * relative error <= 2^-7), then Newton steps, each squaring the error:
 *   1/x:       r + r (1 - x r), fused:   2^-7 -> 2^-14 -> 2^-28;
 *   1/sqrt(x): y + (y/2)(1 - x y^2):     2^-7 -> 2^-13.4 -> 2^-25.8;
 * the precise tier takes two steps (below the rounding), the fast tier one.
 * The clamps are compare-and-select (a NaN input becomes the low end), and
 * vfmin / vfmax see only NaN-free values. */
#ifndef FACET_RVV_H
#define FACET_RVV_H

#if !defined(__riscv_vector)
#error "facet/rvv.h needs the V extension (clang --target=riscv64-linux-gnu -march=rv64gcv)"
#endif
#include <riscv_vector.h>
#include <stddef.h>
#include <stdint.h>
#include "facet/common.h"

#ifndef FACET_RVV_LMUL
#define FACET_RVV_LMUL 1
#endif
/* the intrinsic names for the chosen LMUL: f32 vector, u32/i32 vector,
 * mask (SEW / LMUL: b32 for m1, b16 for m2) */
#if FACET_RVV_LMUL == 2
#define FACET_RVV_F_(op) op##_f32m2
#define FACET_RVV_U_(op) op##_u32m2
#define FACET_RVV_I_(op) op##_i32m2
#define FACET_RVV_FB_(op) op##_f32m2_b16
#define FACET_RVV_UB_(op) op##_u32m2_b16
#define FACET_RVV_M_(op) op##_b16
typedef vfloat32m2_t facet_rvv_v;
typedef vuint32m2_t facet_rvv_u;
typedef vint32m2_t facet_rvv_i;
typedef vbool16_t facet_rvv_mask;
#define facet_rvv_vlmax() vsetvlmax_e32m2()
#define facet_rvv_vl(n) vsetvl_e32m2(n)
#define facet_rvv_f2u_(v) vreinterpret_v_f32m2_u32m2(v)
#define facet_rvv_u2f_(v) vreinterpret_v_u32m2_f32m2(v)
#define facet_rvv_i2f_(v) vreinterpret_v_i32m2_f32m2(v)
#define facet_rvv_u2i_(v) vreinterpret_v_u32m2_i32m2(v)
#else
#define FACET_RVV_F_(op) op##_f32m1
#define FACET_RVV_U_(op) op##_u32m1
#define FACET_RVV_I_(op) op##_i32m1
#define FACET_RVV_FB_(op) op##_f32m1_b32
#define FACET_RVV_UB_(op) op##_u32m1_b32
#define FACET_RVV_M_(op) op##_b32
typedef vfloat32m1_t facet_rvv_v;
typedef vuint32m1_t facet_rvv_u;
typedef vint32m1_t facet_rvv_i;
typedef vbool32_t facet_rvv_mask;
#define facet_rvv_vlmax() vsetvlmax_e32m1()
#define facet_rvv_vl(n) vsetvl_e32m1(n)
#define facet_rvv_f2u_(v) vreinterpret_v_f32m1_u32m1(v)
#define facet_rvv_u2f_(v) vreinterpret_v_u32m1_f32m1(v)
#define facet_rvv_i2f_(v) vreinterpret_v_i32m1_f32m1(v)
#define facet_rvv_u2i_(v) vreinterpret_v_u32m1_i32m1(v)
#endif
/* the ops' vl: all ones, which RVV reads as VLMAX (an AVL >= 2 VLMAX
 * gives vl = VLMAX) and clang as its VLMAX sentinel, so one vsetvli serves
 * a whole run of ops (vsetvlmax() in each op was one vsetvli per op: clang
 * 14 does not merge them) */
#define FACET_RVV_VL_ FACET_CAST(size_t, -1)

FACET_INLINE facet_rvv_v facet_rvv_set(float x) { return FACET_RVV_F_(vfmv_v_f)(x, FACET_RVV_VL_); }
FACET_INLINE facet_rvv_v facet_rvv_add(facet_rvv_v a, facet_rvv_v b) { return FACET_RVV_F_(vfadd_vv)(a, b, FACET_RVV_VL_); }
FACET_INLINE facet_rvv_v facet_rvv_sub(facet_rvv_v a, facet_rvv_v b) { return FACET_RVV_F_(vfsub_vv)(a, b, FACET_RVV_VL_); }
FACET_INLINE facet_rvv_v facet_rvv_mul(facet_rvv_v a, facet_rvv_v b) { return FACET_RVV_F_(vfmul_vv)(a, b, FACET_RVV_VL_); }
/* a*b + c and c - a*b, one rounding (vfmacc: vd + vs1 vs2; vfnmsac: vd - vs1 vs2) */
FACET_INLINE facet_rvv_v facet_rvv_fma(facet_rvv_v a, facet_rvv_v b, facet_rvv_v c)
{
    return FACET_RVV_F_(vfmacc_vv)(c, a, b, FACET_RVV_VL_);
}
FACET_INLINE facet_rvv_v facet_rvv_fnma(facet_rvv_v a, facet_rvv_v b, facet_rvv_v c)
{
    return FACET_RVV_F_(vfnmsac_vv)(c, a, b, FACET_RVV_VL_);
}
FACET_INLINE facet_rvv_v facet_rvv_min(facet_rvv_v a, facet_rvv_v b) { return FACET_RVV_F_(vfmin_vv)(a, b, FACET_RVV_VL_); }
FACET_INLINE facet_rvv_v facet_rvv_max(facet_rvv_v a, facet_rvv_v b) { return FACET_RVV_F_(vfmax_vv)(a, b, FACET_RVV_VL_); }
/* a < b ? x : y (vmerge takes its second operand where the mask is set;
 * vmflt is false for NaN, as in C) */
FACET_INLINE facet_rvv_v facet_rvv_sel_lt(facet_rvv_v a, facet_rvv_v b, facet_rvv_v x, facet_rvv_v y)
{
    size_t vl = FACET_RVV_VL_;
    return FACET_RVV_F_(vmerge_vvm)(FACET_RVV_FB_(vmflt_vv)(a, b, vl), y, x, vl);
}
/* r where neither a nor b is NaN, else +0: the self-compares (vmfeq, an
 * IEEE quiet compare: false for NaN) of both, one mask and, one merge */
FACET_INLINE facet_rvv_v facet_rvv_keep_ord(facet_rvv_v r, facet_rvv_v a, facet_rvv_v b)
{
    size_t vl = FACET_RVV_VL_;
    facet_rvv_mask ord = FACET_RVV_M_(vmand_mm)(FACET_RVV_FB_(vmfeq_vv)(a, a, vl), FACET_RVV_FB_(vmfeq_vv)(b, b, vl), vl);
    return FACET_RVV_F_(vmerge_vvm)(ord, FACET_RVV_F_(vfmv_v_f)(0.0f, vl), r, vl);
}
FACET_INLINE facet_rvv_v facet_rvv_keep_ord4(facet_rvv_v r, facet_rvv_v a, facet_rvv_v b, facet_rvv_v c, facet_rvv_v d)
{
    size_t vl = FACET_RVV_VL_;
    facet_rvv_mask o1 = FACET_RVV_M_(vmand_mm)(FACET_RVV_FB_(vmfeq_vv)(a, a, vl), FACET_RVV_FB_(vmfeq_vv)(b, b, vl), vl);
    facet_rvv_mask o2 = FACET_RVV_M_(vmand_mm)(FACET_RVV_FB_(vmfeq_vv)(c, c, vl), FACET_RVV_FB_(vmfeq_vv)(d, d, vl), vl);
    return FACET_RVV_F_(vmerge_vvm)(FACET_RVV_M_(vmand_mm)(o1, o2, vl), FACET_RVV_F_(vfmv_v_f)(0.0f, vl), r, vl);
}
/* compare-and-select, not vfmax (which would return the number): a NaN
 * input must become lo */
FACET_INLINE facet_rvv_v facet_rvv_clamp(facet_rvv_v x, facet_rvv_v lo, facet_rvv_v hi)
{
    size_t vl = FACET_RVV_VL_;
    x = FACET_RVV_F_(vmerge_vvm)(FACET_RVV_FB_(vmfgt_vv)(x, lo, vl), lo, x, vl);
    return FACET_RVV_F_(vmerge_vvm)(FACET_RVV_FB_(vmflt_vv)(x, hi, vl), hi, x, vl);
}
/* Newton steps from the 7-bit estimates (the kernels never take 1/0:
 * their clamps keep every divisor positive) */
FACET_INLINE facet_rvv_v facet_rvv_rcp_steps_(facet_rvv_v x, int steps)
{
    size_t vl = FACET_RVV_VL_;
    facet_rvv_v r = FACET_RVV_F_(vfrec7_v)(x, vl), e;
    int i;
    for (i = 0; i < steps; i++) {
        e = FACET_RVV_F_(vfnmsac_vv)(FACET_RVV_F_(vfmv_v_f)(1.0f, vl), x, r, vl); /* 1 - x r */
        r = FACET_RVV_F_(vfmacc_vv)(r, r, e, vl);                              /* r + r e */
    }
    return r;
}
FACET_INLINE facet_rvv_v facet_rvv_rsqrt_steps_(facet_rvv_v x, int steps)
{
    size_t vl = FACET_RVV_VL_;
    facet_rvv_v y = FACET_RVV_F_(vfrsqrt7_v)(x, vl), e;
    int i;
    for (i = 0; i < steps; i++) {
        e = FACET_RVV_F_(vfnmsac_vv)(FACET_RVV_F_(vfmv_v_f)(1.0f, vl), FACET_RVV_F_(vfmul_vv)(x, y, vl), y, vl);
        y = FACET_RVV_F_(vfmacc_vv)(y, FACET_RVV_F_(vfmul_vf)(y, 0.5f, vl), e, vl); /* y + (y/2) e */
    }
    return y;
}
#ifndef FACET_RVV_STEPS
#define FACET_RVV_STEPS 2 /* the precise tier */
#endif
#ifndef FACET_RVV_STEPS_FAST
#define FACET_RVV_STEPS_FAST 1 /* the fast tier */
#endif
FACET_INLINE facet_rvv_v facet_rvv_rcp(facet_rvv_v x) { return facet_rvv_rcp_steps_(x, FACET_RVV_STEPS); }
FACET_INLINE facet_rvv_v facet_rvv_rsqrt(facet_rvv_v x) { return facet_rvv_rsqrt_steps_(x, FACET_RVV_STEPS); }
FACET_INLINE facet_rvv_v facet_rvv_rcp_fast(facet_rvv_v x) { return facet_rvv_rcp_steps_(x, FACET_RVV_STEPS_FAST); }
FACET_INLINE facet_rvv_v facet_rvv_rsqrt_fast(facet_rvv_v x) { return facet_rvv_rsqrt_steps_(x, FACET_RVV_STEPS_FAST); }
/* a / b and sqrt(x) (b, x positive and normal): a times the tier's
 * reciprocal, x times its rsqrt (vfdiv / vfsqrt are long-latency, often
 * unpipelined, on the cores there are; the estimates and steps pipeline). */
FACET_INLINE facet_rvv_v facet_rvv_div(facet_rvv_v a, facet_rvv_v b) { return facet_rvv_mul(a, facet_rvv_rcp(b)); }
FACET_INLINE facet_rvv_v facet_rvv_div_fast(facet_rvv_v a, facet_rvv_v b) { return facet_rvv_mul(a, facet_rvv_rcp_fast(b)); }
FACET_INLINE facet_rvv_v facet_rvv_sqrt(facet_rvv_v x) { return facet_rvv_mul(x, facet_rvv_rsqrt(x)); }
FACET_INLINE facet_rvv_v facet_rvv_sqrt_fast(facet_rvv_v x) { return facet_rvv_mul(x, facet_rvv_rsqrt_fast(x)); }
/* a*a - p, one rounding (vfmsac: vs1 vs2 - vd) */
FACET_INLINE facet_rvv_v facet_rvv_sqr_err(facet_rvv_v a, facet_rvv_v p)
{
    return FACET_RVV_F_(vfmsac_vv)(p, a, a, FACET_RVV_VL_);
}
/* c - a*a, one rounding of the exact value (the kernels' exact peak) */
FACET_INLINE facet_rvv_v facet_rvv_sqr_sub(facet_rvv_v a, facet_rvv_v c)
{
    return FACET_RVV_F_(vfnmsac_vv)(c, a, a, FACET_RVV_VL_);
}

/* Exponent-bit ops (exp2/log2 of f32_body.h and the samplers):
 *   exp2i(k)    2^k for an integral-valued k in [-126, 127] (exponent bits)
 *   getexp(x)   floor(log2 x) as a float, x positive and normal
 *   getmant(x)  x / 2^getexp(x), in [1, 2) */
FACET_INLINE facet_rvv_v facet_rvv_exp2i(facet_rvv_v k)
{
    size_t vl = FACET_RVV_VL_;
    /* k is integral: the dynamic rounding mode's convert (vfcvt.x.f) is
     * exact; not vfcvt.rtz, whose static rounding mode qemu 7.2 cannot
     * translate (decode_save_opc assertion, fixed in qemu 8) */
    facet_rvv_i e = FACET_RVV_I_(vadd_vx)(FACET_RVV_I_(vfcvt_x_f_v)(k, vl), 127, vl);
    return facet_rvv_i2f_(FACET_RVV_I_(vsll_vx)(e, 23, vl));
}
FACET_INLINE facet_rvv_v facet_rvv_getexp(facet_rvv_v x)
{
    size_t vl = FACET_RVV_VL_;
    facet_rvv_u e = FACET_RVV_U_(vsrl_vx)(facet_rvv_f2u_(x), 23, vl);
    return FACET_RVV_F_(vfcvt_f_x_v)(FACET_RVV_I_(vsub_vx)(facet_rvv_u2i_(e), 127, vl), vl);
}
FACET_INLINE facet_rvv_v facet_rvv_getmant(facet_rvv_v x)
{
    size_t vl = FACET_RVV_VL_;
    facet_rvv_u m = FACET_RVV_U_(vand_vx)(facet_rvv_f2u_(x), 0x007fffffu, vl);
    return facet_rvv_u2f_(FACET_RVV_U_(vor_vx)(m, 0x3f800000u, vl));
}

/* The strip helpers of a caller's loop: vl = facet_rvv_vl(n - i) lanes
 * (at most VLMAX), loaded and stored with that vl: nothing past n. */
FACET_INLINE facet_rvv_v facet_rvv_load(const float *p, size_t vl) { return FACET_RVV_F_(vle32_v)(p, vl); }
FACET_INLINE void facet_rvv_store(float *p, facet_rvv_v v, size_t vl) { FACET_RVV_F_(vse32_v)(p, v, vl); }

#define FACET_V facet_rvv_v
#define FACET_PORT_NAME rvv
#define FACET_BODY_SAMPLES 0
#include "facet/detail/f32_tiers.h"

#endif

/* ---- sampling ops and the samplers (see facet/scalar.h) ------------------- */
#ifndef FACET_RVV_SAMPLE_H
#define FACET_RVV_SAMPLE_H

#define FACET_V facet_rvv_v
#define FACET_PORT_NAME rvv
#define FACET_BODY_SAMPLES 1
#include "facet/detail/f32_tiers.h"

#endif
