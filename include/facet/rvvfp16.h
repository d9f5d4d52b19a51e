/* facet/rvvfp16.h - the RISC-V Vector binary16 port (RVV 1.0 with Zvfh,
 * vector-length agnostic): every f16 kernel as a static inline function on
 * vfloat16m1_t (VLEN / 16 binary16 lanes), named
 * facet_<kernel>_f16_rvvfp16.  Contracts: facet/f16.h.  Compile with clang
 * >= 14, --target=riscv64-linux-gnu -march=rv64gcv_zfh (clang 14 knows no
 * `zvfh`: it gates the binary16 vector intrinsics on zfh; clang >= 16 takes
 * -march=rv64gcv_zvfh); run only where the CPU has V and Zvfh
 * (facet_f16_port_supported("rvvfp16"): AT_HWCAP's V and the riscv_hwprobe
 * system call's Zvfh bit, src/core/cpu.c).  The ops use no scalar binary16
 * arithmetic (Zfh): Zvfh implies only Zfhmin (tests/suites/54-rvv.sh
 * checks the port's object for it).
 *
 * The f32 lanes (FACET_W) are one vfloat32m2_t: the same VLEN / 16 samples
 * as 32-bit elements in a group of two vector registers (LMUL 2), reached
 * by RVV's widening and narrowing conversions vfwcvt.f.f.v / vfncvt.f.f.w
 * (exact, and rounded by frm, to nearest even), so no lane shuffles: every
 * f32-lane op is one m2 instruction, two m1 ones' work on most cores.
 * Every op runs at VLMAX (vl = all ones, as facet/rvv.h: one vsetvli per
 * run of ops of one SEW; e16/m1 and e32/m2 have the same VLMAX); a caller
 * loads and stores with the strip's vl.
 *
 * Reciprocal and rsqrt start from RVV's 7-bit estimates (vfrec7,
 * vfrsqrt7: defined bit for bit by the specification's tables, so qemu
 * computes what the hardware does; measured 2^-7.48 and 2^-7.31) and take
 * one Newton step (relative errors measured exhaustively: every positive
 * normal binary16 x, resp. every float of the tables' period):
 *   binary16 1/x     r + r (1 - x r), fused: 2^-14 before the step's
 *                    roundings (that of r + r e, 2^-11, dominates):
 *                    4.93e-4 (2^-10.99; the correctly rounded 1/x: 4.88e-4)
 *   binary16 1/sqrt  y + (y/2) (1 - (x y) y): 1.5 2^-14 plus the rounding
 *                    of x y (halved) and of the result: 5.78e-4 (2^-10.76)
 *   f32 1/x, 1/sqrt  the same steps in f32: 3.12e-5 (2^-14.97) and 5.91e-5
 *                    (2^-14.05), within the 2^-14 that facet/detail/
 *                    f16_body.h budgets for the f32 estimates
 * tests/f16/test_f16_estimates.c proves each (and the estimates within
 * 2^-7, the premise of one step) against 4.94e-4, 5.79e-4, 3.13e-5 and
 * 5.92e-5.  Quotients a rcp(b), roots x rsqrt(x).  The clamps are
 * compare-and-select (a NaN input becomes the low end); vfmin / vfmax see
 * only NaN-free values; NaN inputs are found by self-compares (vmfeq). */
#ifndef FACET_RVVFP16_H
#define FACET_RVVFP16_H

#if !defined(__riscv_vector) || !defined(__riscv_zfh)
#error "facet/rvvfp16.h needs V and binary16 vector arithmetic (clang --target=riscv64-linux-gnu -march=rv64gcv_zfh)"
#endif
#include <riscv_vector.h>
#include <stddef.h>
#include <stdint.h>
#include "facet/common.h"
#include "facet/f16.h"

typedef vfloat16m1_t facet_rvvfp16_v; /* VLEN / 16 binary16 lanes */
typedef vfloat32m2_t facet_rvvfp16_w; /* the same lanes in f32 (LMUL 2) */
typedef vbool16_t facet_rvvfp16_mask;

/* the ops' vl: all ones, read as VLMAX (facet/rvv.h) */
#define FACET_RVVFP16_VL_ FACET_CAST(size_t, -1)
#define facet_rvvfp16_vlmax() vsetvlmax_e16m1()
#ifndef FACET_RVVFP16_STEPS
#define FACET_RVVFP16_STEPS 1 /* Newton steps after vfrec7 / vfrsqrt7, binary16 */
#endif
#ifndef FACET_RVVFP16_W_STEPS
#define FACET_RVVFP16_W_STEPS 1 /* the same in the f32 lanes */
#endif

FACET_INLINE facet_rvvfp16_v facet_rvvfp16_h_set(float x)
{
    return vfmv_v_f_f16m1(FACET_CAST(_Float16, x), FACET_RVVFP16_VL_);
}
FACET_INLINE facet_rvvfp16_v facet_rvvfp16_h_add(facet_rvvfp16_v a, facet_rvvfp16_v b) { return vfadd_vv_f16m1(a, b, FACET_RVVFP16_VL_); }
FACET_INLINE facet_rvvfp16_v facet_rvvfp16_h_sub(facet_rvvfp16_v a, facet_rvvfp16_v b) { return vfsub_vv_f16m1(a, b, FACET_RVVFP16_VL_); }
FACET_INLINE facet_rvvfp16_v facet_rvvfp16_h_mul(facet_rvvfp16_v a, facet_rvvfp16_v b) { return vfmul_vv_f16m1(a, b, FACET_RVVFP16_VL_); }
/* a*b + c and c - a*b, one rounding (vfmacc: vd + vs1 vs2; vfnmsac: vd - vs1 vs2) */
FACET_INLINE facet_rvvfp16_v facet_rvvfp16_h_fma(facet_rvvfp16_v a, facet_rvvfp16_v b, facet_rvvfp16_v c)
{
    return vfmacc_vv_f16m1(c, a, b, FACET_RVVFP16_VL_);
}
FACET_INLINE facet_rvvfp16_v facet_rvvfp16_h_fnma(facet_rvvfp16_v a, facet_rvvfp16_v b, facet_rvvfp16_v c)
{
    return vfnmsac_vv_f16m1(c, a, b, FACET_RVVFP16_VL_);
}
FACET_INLINE facet_rvvfp16_v facet_rvvfp16_h_min(facet_rvvfp16_v a, facet_rvvfp16_v b) { return vfmin_vv_f16m1(a, b, FACET_RVVFP16_VL_); }
FACET_INLINE facet_rvvfp16_v facet_rvvfp16_h_max(facet_rvvfp16_v a, facet_rvvfp16_v b) { return vfmax_vv_f16m1(a, b, FACET_RVVFP16_VL_); }
/* compare-and-select, not vfmax (which returns the number): NaN and -Inf
 * to lo, +Inf to hi */
FACET_INLINE facet_rvvfp16_v facet_rvvfp16_h_clamp(facet_rvvfp16_v x, facet_rvvfp16_v lo, facet_rvvfp16_v hi)
{
    size_t vl = FACET_RVVFP16_VL_;
    x = vmerge_vvm_f16m1(vmfgt_vv_f16m1_b16(x, lo, vl), lo, x, vl);
    return vmerge_vvm_f16m1(vmflt_vv_f16m1_b16(x, hi, vl), hi, x, vl);
}
/* r where no input is NaN, else +0: self-compares (vmfeq, quiet: false for
 * NaN), mask ands, one merge */
FACET_INLINE facet_rvvfp16_v facet_rvvfp16_h_keep_ord(facet_rvvfp16_v r, facet_rvvfp16_v a, facet_rvvfp16_v b)
{
    size_t vl = FACET_RVVFP16_VL_;
    facet_rvvfp16_mask ord = vmand_mm_b16(vmfeq_vv_f16m1_b16(a, a, vl), vmfeq_vv_f16m1_b16(b, b, vl), vl);
    return vmerge_vvm_f16m1(ord, vfmv_v_f_f16m1(FACET_CAST(_Float16, 0.0f), vl), r, vl);
}
FACET_INLINE facet_rvvfp16_v facet_rvvfp16_h_keep_ord4(facet_rvvfp16_v r, facet_rvvfp16_v a, facet_rvvfp16_v b,
                                                       facet_rvvfp16_v c, facet_rvvfp16_v d)
{
    size_t vl = FACET_RVVFP16_VL_;
    facet_rvvfp16_mask o1 = vmand_mm_b16(vmfeq_vv_f16m1_b16(a, a, vl), vmfeq_vv_f16m1_b16(b, b, vl), vl);
    facet_rvvfp16_mask o2 = vmand_mm_b16(vmfeq_vv_f16m1_b16(c, c, vl), vmfeq_vv_f16m1_b16(d, d, vl), vl);
    return vmerge_vvm_f16m1(vmand_mm_b16(o1, o2, vl), vfmv_v_f_f16m1(FACET_CAST(_Float16, 0.0f), vl), r, vl);
}
/* 1/x and 1/sqrt(x), x a positive normal (the kernels' clamps keep every
 * divisor and radicand so): the estimate and FACET_RVVFP16_STEPS steps */
FACET_INLINE facet_rvvfp16_v facet_rvvfp16_h_rcp(facet_rvvfp16_v x)
{
    size_t vl = FACET_RVVFP16_VL_;
    facet_rvvfp16_v one = vfmv_v_f_f16m1(FACET_CAST(_Float16, 1.0f), vl), r = vfrec7_v_f16m1(x, vl);
    int i;
    for (i = 0; i < FACET_RVVFP16_STEPS; i++)
        r = vfmacc_vv_f16m1(r, r, vfnmsac_vv_f16m1(one, x, r, vl), vl); /* r + r (1 - x r) */
    return r;
}
FACET_INLINE facet_rvvfp16_v facet_rvvfp16_h_rsqrt(facet_rvvfp16_v x)
{
    size_t vl = FACET_RVVFP16_VL_;
    facet_rvvfp16_v one = vfmv_v_f_f16m1(FACET_CAST(_Float16, 1.0f), vl), y = vfrsqrt7_v_f16m1(x, vl), e;
    int i;
    for (i = 0; i < FACET_RVVFP16_STEPS; i++) {
        e = vfnmsac_vv_f16m1(one, vfmul_vv_f16m1(x, y, vl), y, vl);           /* 1 - (x y) y */
        y = vfmacc_vv_f16m1(y, vfmul_vf_f16m1(y, FACET_CAST(_Float16, 0.5f), vl), e, vl); /* y + (y/2) e */
    }
    return y;
}
FACET_INLINE facet_rvvfp16_v facet_rvvfp16_h_div(facet_rvvfp16_v a, facet_rvvfp16_v b)
{
    return vfmul_vv_f16m1(a, facet_rvvfp16_h_rcp(b), FACET_RVVFP16_VL_);
}
FACET_INLINE facet_rvvfp16_v facet_rvvfp16_h_sqrt(facet_rvvfp16_v x)
{
    return vfmul_vv_f16m1(x, facet_rvvfp16_h_rsqrt(x), FACET_RVVFP16_VL_);
}

/* ---- the f32 lanes (one vfloat32m2_t) ---- */
FACET_INLINE facet_rvvfp16_w facet_rvvfp16_h_w_set(float x) { return vfmv_v_f_f32m2(x, FACET_RVVFP16_VL_); }
FACET_INLINE facet_rvvfp16_w facet_rvvfp16_h_w_add(facet_rvvfp16_w a, facet_rvvfp16_w b) { return vfadd_vv_f32m2(a, b, FACET_RVVFP16_VL_); }
FACET_INLINE facet_rvvfp16_w facet_rvvfp16_h_w_sub(facet_rvvfp16_w a, facet_rvvfp16_w b) { return vfsub_vv_f32m2(a, b, FACET_RVVFP16_VL_); }
FACET_INLINE facet_rvvfp16_w facet_rvvfp16_h_w_mul(facet_rvvfp16_w a, facet_rvvfp16_w b) { return vfmul_vv_f32m2(a, b, FACET_RVVFP16_VL_); }
FACET_INLINE facet_rvvfp16_w facet_rvvfp16_h_w_fma(facet_rvvfp16_w a, facet_rvvfp16_w b, facet_rvvfp16_w c)
{
    return vfmacc_vv_f32m2(c, a, b, FACET_RVVFP16_VL_);
}
FACET_INLINE facet_rvvfp16_w facet_rvvfp16_h_w_fnma(facet_rvvfp16_w a, facet_rvvfp16_w b, facet_rvvfp16_w c)
{
    return vfnmsac_vv_f32m2(c, a, b, FACET_RVVFP16_VL_);
}
FACET_INLINE facet_rvvfp16_w facet_rvvfp16_h_w_min(facet_rvvfp16_w a, facet_rvvfp16_w b) { return vfmin_vv_f32m2(a, b, FACET_RVVFP16_VL_); }
FACET_INLINE facet_rvvfp16_w facet_rvvfp16_h_w_max(facet_rvvfp16_w a, facet_rvvfp16_w b) { return vfmax_vv_f32m2(a, b, FACET_RVVFP16_VL_); }
FACET_INLINE facet_rvvfp16_w facet_rvvfp16_h_w_rcp(facet_rvvfp16_w x)
{
    size_t vl = FACET_RVVFP16_VL_;
    facet_rvvfp16_w one = vfmv_v_f_f32m2(1.0f, vl), r = vfrec7_v_f32m2(x, vl);
    int i;
    for (i = 0; i < FACET_RVVFP16_W_STEPS; i++)
        r = vfmacc_vv_f32m2(r, r, vfnmsac_vv_f32m2(one, x, r, vl), vl);
    return r;
}
FACET_INLINE facet_rvvfp16_w facet_rvvfp16_h_w_rsqrt(facet_rvvfp16_w x)
{
    size_t vl = FACET_RVVFP16_VL_;
    facet_rvvfp16_w one = vfmv_v_f_f32m2(1.0f, vl), y = vfrsqrt7_v_f32m2(x, vl), e;
    int i;
    for (i = 0; i < FACET_RVVFP16_W_STEPS; i++) {
        e = vfnmsac_vv_f32m2(one, vfmul_vv_f32m2(x, y, vl), y, vl);
        y = vfmacc_vv_f32m2(y, vfmul_vf_f32m2(y, 0.5f, vl), e, vl);
    }
    return y;
}
/* binary16 to f32, exact (vfwcvt.f.f.v), and f32 (>= 0) to binary16
 * rounded by frm, to nearest even (vfncvt.f.f.w; from 65520 on +Inf, which
 * the body's final min turns into 65504) */
FACET_INLINE facet_rvvfp16_w facet_rvvfp16_h_widen(facet_rvvfp16_v v) { return vfwcvt_f_f_v_f32m2(v, FACET_RVVFP16_VL_); }
FACET_INLINE facet_rvvfp16_v facet_rvvfp16_h_narrow(facet_rvvfp16_w x) { return vfncvt_f_f_w_f16m1(x, FACET_RVVFP16_VL_); }

/* The strip helpers of a caller's loop: vl = facet_rvvfp16_vl(n - i)
 * binary16 values (at most VLMAX), loaded and stored with that vl: nothing
 * read or written past n; the lanes past vl hold whatever the load left
 * there, and their results are never stored (nothing traps). */
#define facet_rvvfp16_vl(n) vsetvl_e16m1(n)
FACET_INLINE facet_rvvfp16_v facet_rvvfp16_load(const uint16_t *p, size_t vl)
{
    return vreinterpret_v_u16m1_f16m1(vle16_v_u16m1(p, vl));
}
FACET_INLINE void facet_rvvfp16_store(uint16_t *p, facet_rvvfp16_v v, size_t vl)
{
    vse16_v_u16m1(p, vreinterpret_v_f16m1_u16m1(v), vl);
}

#define FACET_V facet_rvvfp16_v
#define FACET_W facet_rvvfp16_w
#define FACET_OP(op) facet_rvvfp16_h_##op
#define FACET_K(k) facet_##k##_f16_rvvfp16
#include "facet/detail/f16_body.h"
#undef FACET_V
#undef FACET_W
#undef FACET_OP
#undef FACET_K

#endif
