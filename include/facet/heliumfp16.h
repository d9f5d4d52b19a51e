/* facet/heliumfp16.h - the Helium binary16 port (Armv8.1-M MVE with floating
 * point: Cortex-M55, M85): every f16 kernel as a static inline function on
 * float16x8_t (8 binary16 lanes), named facet_<kernel>_f16_heliumfp16.
 * Contracts: facet/f16.h.  Compile with -mcpu=cortex-m55 -mfloat-abi=hard
 * (MVE-F: __ARM_FEATURE_MVE & 2); run where MVFR1.MVE is 2 (MVE with
 * half- and single-precision floating point: facet_f16_port_supported
 * ("heliumfp16")).
 *
 * MVE has no reciprocal or rsqrt estimate and no vector divide or root, so
 * both start from a bit-level seed and take two Newton steps (after one,
 * 2.6e-3 and 1.8e-3 remain before any rounding: above the bounds of the
 * kernels that divide, e.g. smith_vis_hammon's 1.8e-3), in both lane
 * formats.  Relative errors:
 *   binary16 1/x     seed bits 0x7798 - bits(x) (<= 0.0508, 2^-4.30, the
 *                    minimax constant over [1, 2)); r + r (1 - x r), fused,
 *                    twice: the seed's error to the fourth power (2^-17.2)
 *                    plus the roundings; measured over every binary16 x
 *                    in [2^-14, 2^14]: 5.531e-4 (2^-10.82; the correctly
 *                    rounded 1/x: 4.88e-4)
 *   binary16 1/sqrt  seed bits 0x59bb - bits(x)/2 (<= 0.0345, 2^-4.86);
 *                    y + (y/2) (1 - (x y) y), twice: 2^-17.6 plus the
 *                    roundings (x y's is the largest, 2^-12 in the last
 *                    step); over every positive normal binary16 x:
 *                    5.834e-4 (2^-10.74)
 *   f32 1/x, 1/sqrt  (FACET_W) facet/helium.h's seeds 0x7ef311c3 and
 *                    0x5f375a86, two steps each (the rsqrt's as
 *                    y + y (1/2 - (x/2) y^2), x/2 exact in f32): over every
 *                    float of the seeds' period ([1, 2) for 1/x, [1, 4) for
 *                    1/sqrt; x times 2^k, resp. 4^k, scales every step
 *                    exactly),
 *                    6.57e-6 (2^-17.22) and at most 4.75e-6 (2^-17.68):
 *                    below the 2^-14 of the other ports' f32 estimates
 *                    that f16_body.h budgets for.
 * tests/f16/test_f16_estimates.c proves each on the M55 image, exhaustively
 * over those inputs, against 5.54e-4, 5.84e-4, 6.6e-6 and 5.0e-6.
 * Quotients a rcp(b), roots x rsqrt(x).  MVE's VCMP LT is true for
 * unordered operands, so the clamp compares with GT only (a NaN input
 * gives the low end) and NaN is found on the bits (facet/helium.h).
 * The f32 lanes (FACET_W): two float32x4_t, the even binary16 lanes and the
 * odd ones (VCVTB / VCVTT, round to nearest even).
 *
 * GNU as 2.40 (Debian's binutils-arm-none-eabi) encodes the MVE forms of
 * VCVTB / VCVTT between binary16 and f32 with the Q register numbers
 * doubled (`vcvtb.f16.f32 q0, q1` assembles as q0, q2: objdump and
 * llvm-objdump-16 both decode it so, and qemu executes it so), so with gcc
 * the four conversions are inline assembly emitting the encoding itself
 * (.inst.w, the register numbers taken from the operands' names); clang's
 * integrated assembler encodes the intrinsics correctly. */
#ifndef FACET_HELIUMFP16_H
#define FACET_HELIUMFP16_H

#if !defined(__ARM_FEATURE_MVE) || !(__ARM_FEATURE_MVE & 2)
#error "facet/heliumfp16.h needs MVE with floating point (-mcpu=cortex-m55 -mfloat-abi=hard)"
#endif
#include <arm_mve.h>
#include <stddef.h>
#include <stdint.h>
#include "facet/common.h"
#include "facet/f16.h"

typedef struct facet_heliumfp16_w {
    float32x4_t lo, hi; /* the even binary16 lanes, the odd ones */
} facet_heliumfp16_w;

FACET_INLINE float16x8_t facet_heliumfp16_h_set(float x) { return vdupq_n_f16(FACET_CAST(float16_t, x)); }
FACET_INLINE float16x8_t facet_heliumfp16_h_add(float16x8_t a, float16x8_t b) { return vaddq_f16(a, b); }
FACET_INLINE float16x8_t facet_heliumfp16_h_sub(float16x8_t a, float16x8_t b) { return vsubq_f16(a, b); }
FACET_INLINE float16x8_t facet_heliumfp16_h_mul(float16x8_t a, float16x8_t b) { return vmulq_f16(a, b); }
/* a*b + c and c - a*b, one rounding */
FACET_INLINE float16x8_t facet_heliumfp16_h_fma(float16x8_t a, float16x8_t b, float16x8_t c) { return vfmaq_f16(c, a, b); }
FACET_INLINE float16x8_t facet_heliumfp16_h_fnma(float16x8_t a, float16x8_t b, float16x8_t c) { return vfmsq_f16(c, a, b); }
FACET_INLINE float16x8_t facet_heliumfp16_h_min(float16x8_t a, float16x8_t b) { return vminnmq_f16(a, b); }
FACET_INLINE float16x8_t facet_heliumfp16_h_max(float16x8_t a, float16x8_t b) { return vmaxnmq_f16(a, b); }
/* compare-and-select (GT only): NaN and -Inf to lo, +Inf to hi */
FACET_INLINE float16x8_t facet_heliumfp16_h_clamp(float16x8_t x, float16x8_t lo, float16x8_t hi)
{
    x = vpselq_f16(x, lo, vcmpgtq_f16(x, lo));
    return vpselq_f16(x, hi, vcmpgtq_f16(hi, x));
}
/* r where no input is NaN, else +0: the bits without the sign, the largest,
 * above +Inf's (0x7c00 << 1) exactly where one is a NaN */
FACET_INLINE float16x8_t facet_heliumfp16_h_keep_ord(float16x8_t r, float16x8_t a, float16x8_t b)
{
    uint16x8_t ia = vshlq_n_u16(vreinterpretq_u16_f16(a), 1);
    uint16x8_t ib = vshlq_n_u16(vreinterpretq_u16_f16(b), 1);
    mve_pred16_t nan = vcmphiq_u16(vmaxq_u16(ia, ib), vdupq_n_u16(0xf800u));
    return vpselq_f16(vdupq_n_f16(FACET_CAST(float16_t, 0.0f)), r, nan);
}
FACET_INLINE float16x8_t facet_heliumfp16_h_keep_ord4(float16x8_t r, float16x8_t a, float16x8_t b, float16x8_t c,
                                                      float16x8_t d)
{
    uint16x8_t ia = vshlq_n_u16(vreinterpretq_u16_f16(a), 1);
    uint16x8_t ib = vshlq_n_u16(vreinterpretq_u16_f16(b), 1);
    uint16x8_t ic = vshlq_n_u16(vreinterpretq_u16_f16(c), 1);
    uint16x8_t id = vshlq_n_u16(vreinterpretq_u16_f16(d), 1);
    mve_pred16_t nan = vcmphiq_u16(vmaxq_u16(vmaxq_u16(ia, ib), vmaxq_u16(ic, id)), vdupq_n_u16(0xf800u));
    return vpselq_f16(vdupq_n_f16(FACET_CAST(float16_t, 0.0f)), r, nan);
}
/* 1/x, x a positive normal: the seed and two Newton steps (above) */
FACET_INLINE float16x8_t facet_heliumfp16_h_rcp(float16x8_t x)
{
    float16x8_t one = vdupq_n_f16(FACET_CAST(float16_t, 1.0f));
    float16x8_t r = vreinterpretq_f16_u16(vsubq_u16(vdupq_n_u16(0x7798u), vreinterpretq_u16_f16(x)));
    r = vfmaq_f16(r, r, vfmsq_f16(one, x, r));
    return vfmaq_f16(r, r, vfmsq_f16(one, x, r));
}
/* 1/sqrt(x), x a positive normal: y + (y/2) (1 - (x y) y), twice (not
 * x/2 once: below 2^-13 it is a binary16 subnormal and inexact) */
FACET_INLINE float16x8_t facet_heliumfp16_h_rsqrt(float16x8_t x)
{
    float16x8_t one = vdupq_n_f16(FACET_CAST(float16_t, 1.0f)), half = vdupq_n_f16(FACET_CAST(float16_t, 0.5f));
    float16x8_t y = vreinterpretq_f16_u16(vsubq_u16(vdupq_n_u16(0x59bbu), vshrq_n_u16(vreinterpretq_u16_f16(x), 1)));
    y = vfmaq_f16(y, vmulq_f16(half, y), vfmsq_f16(one, vmulq_f16(x, y), y));
    return vfmaq_f16(y, vmulq_f16(half, y), vfmsq_f16(one, vmulq_f16(x, y), y));
}
FACET_INLINE float16x8_t facet_heliumfp16_h_div(float16x8_t a, float16x8_t b) { return vmulq_f16(a, facet_heliumfp16_h_rcp(b)); }
FACET_INLINE float16x8_t facet_heliumfp16_h_sqrt(float16x8_t x) { return vmulq_f16(x, facet_heliumfp16_h_rsqrt(x)); }

/* ---- the f32 lanes ---- */
FACET_INLINE facet_heliumfp16_w facet_heliumfp16_h_w_set(float x)
{
    facet_heliumfp16_w r;
    r.lo = r.hi = vdupq_n_f32(x);
    return r;
}
#define FACET_HELIUMFP16_W_BIN_(name, e)                                                             \
    FACET_INLINE facet_heliumfp16_w facet_heliumfp16_h_w_##name(facet_heliumfp16_w a, facet_heliumfp16_w b) \
    {                                                                                                \
        facet_heliumfp16_w r;                                                                        \
        r.lo = e(a.lo, b.lo);                                                                        \
        r.hi = e(a.hi, b.hi);                                                                        \
        return r;                                                                                    \
    }
FACET_HELIUMFP16_W_BIN_(add, vaddq_f32)
FACET_HELIUMFP16_W_BIN_(sub, vsubq_f32)
FACET_HELIUMFP16_W_BIN_(mul, vmulq_f32)
FACET_HELIUMFP16_W_BIN_(min, vminnmq_f32)
FACET_HELIUMFP16_W_BIN_(max, vmaxnmq_f32)
#undef FACET_HELIUMFP16_W_BIN_
FACET_INLINE facet_heliumfp16_w facet_heliumfp16_h_w_fma(facet_heliumfp16_w a, facet_heliumfp16_w b,
                                                         facet_heliumfp16_w c)
{
    facet_heliumfp16_w r;
    r.lo = vfmaq_f32(c.lo, a.lo, b.lo);
    r.hi = vfmaq_f32(c.hi, a.hi, b.hi);
    return r;
}
FACET_INLINE facet_heliumfp16_w facet_heliumfp16_h_w_fnma(facet_heliumfp16_w a, facet_heliumfp16_w b,
                                                          facet_heliumfp16_w c)
{
    facet_heliumfp16_w r;
    r.lo = vfmsq_f32(c.lo, a.lo, b.lo);
    r.hi = vfmsq_f32(c.hi, a.hi, b.hi);
    return r;
}
/* a a - p exactly (p = fl(a a)): -p + a a, fused */
FACET_INLINE facet_heliumfp16_w facet_heliumfp16_h_w_sqr_err(facet_heliumfp16_w a, facet_heliumfp16_w p)
{
    facet_heliumfp16_w r;
    r.lo = vfmaq_f32(vnegq_f32(p.lo), a.lo, a.lo);
    r.hi = vfmaq_f32(vnegq_f32(p.hi), a.hi, a.hi);
    return r;
}
FACET_INLINE float32x4_t facet_heliumfp16_rcp4_(float32x4_t x)
{
    float32x4_t one = vdupq_n_f32(1.0f);
    float32x4_t r = vreinterpretq_f32_u32(vsubq_u32(vdupq_n_u32(0x7ef311c3u), vreinterpretq_u32_f32(x)));
    r = vfmaq_f32(r, r, vfmsq_f32(one, x, r));
    return vfmaq_f32(r, r, vfmsq_f32(one, x, r));
}
FACET_INLINE float32x4_t facet_heliumfp16_rsqrt4_(float32x4_t x)
{
    float32x4_t half = vdupq_n_f32(0.5f);
    float32x4_t hx = vmulq_f32(x, half);
    float32x4_t y = vreinterpretq_f32_u32(vsubq_u32(vdupq_n_u32(0x5f375a86u), vshrq_n_u32(vreinterpretq_u32_f32(x), 1)));
    y = vfmaq_f32(y, y, vfmsq_f32(half, vmulq_f32(hx, y), y));
    return vfmaq_f32(y, y, vfmsq_f32(half, vmulq_f32(hx, y), y));
}
FACET_INLINE facet_heliumfp16_w facet_heliumfp16_h_w_rcp(facet_heliumfp16_w x)
{
    facet_heliumfp16_w r;
    r.lo = facet_heliumfp16_rcp4_(x.lo);
    r.hi = facet_heliumfp16_rcp4_(x.hi);
    return r;
}
FACET_INLINE facet_heliumfp16_w facet_heliumfp16_h_w_rsqrt(facet_heliumfp16_w x)
{
    facet_heliumfp16_w r;
    r.lo = facet_heliumfp16_rsqrt4_(x.lo);
    r.hi = facet_heliumfp16_rsqrt4_(x.hi);
    return r;
}

/* The conversions: VCVTB / VCVTT (the even / odd binary16 lanes), rounded
 * to nearest even.  With gcc the encoding itself (GNU as 2.40 misencodes the
 * Q registers, above): T1 of VCVTB/VCVTT, halfword 0xee3f (f32 to binary16)
 * or 0xfe3f (binary16 to f32), then Qd << 13 | T << 12 | 0xe01 | Qm << 1;
 * the register numbers come from the operands' names q0..q7. */
#if defined(__clang__)
#define FACET_HELIUMFP16_WIDEN_B_(v) vcvtbq_f32_f16(v)
#define FACET_HELIUMFP16_WIDEN_T_(v) vcvttq_f32_f16(v)
#define FACET_HELIUMFP16_NARROW_(lo, hi) vcvttq_f16_f32(vcvtbq_f16_f32(vreinterpretq_f16_f32(lo), (lo)), (hi))
#else
#define FACET_HELIUMFP16_QN_                                                                 \
    ".ifndef .Lfacet_heliumfp16_qn\n\t.set .Lfacet_heliumfp16_qn, 1\n"                       \
    "\t.macro facet_heliumfp16_qn s, q\n\t.irp n, 0, 1, 2, 3, 4, 5, 6, 7\n\t.ifc \\q, q\\n\n" \
    "\t.set \\s, \\n\n\t.endif\n\t.endr\n\t.endm\n\t.endif\n"                                 \
    "\tfacet_heliumfp16_qn .Lfacet_heliumfp16_d, %q0\n\tfacet_heliumfp16_qn .Lfacet_heliumfp16_m, %q1\n"
#define FACET_HELIUMFP16_INST_(op) \
    "\t.inst.w " op " | (.Lfacet_heliumfp16_d << 13) | (.Lfacet_heliumfp16_m << 1)"
FACET_INLINE float32x4_t facet_heliumfp16_widen_b_(float16x8_t v)
{
    float32x4_t r;
    __asm__(FACET_HELIUMFP16_QN_ FACET_HELIUMFP16_INST_("0xfe3f0e01") : "=w"(r) : "w"(v));
    return r;
}
FACET_INLINE float32x4_t facet_heliumfp16_widen_t_(float16x8_t v)
{
    float32x4_t r;
    __asm__(FACET_HELIUMFP16_QN_ FACET_HELIUMFP16_INST_("0xfe3f1e01") : "=w"(r) : "w"(v));
    return r;
}
/* the bottom halves from lo (their top halves whatever the register held:
 * the second conversion writes them), then the top halves from hi */
FACET_INLINE float16x8_t facet_heliumfp16_narrow_(float32x4_t lo, float32x4_t hi)
{
    float16x8_t r;
    __asm__(FACET_HELIUMFP16_QN_ FACET_HELIUMFP16_INST_("0xee3f0e01") : "=w"(r) : "w"(lo));
    __asm__(FACET_HELIUMFP16_QN_ FACET_HELIUMFP16_INST_("0xee3f1e01") : "+w"(r) : "w"(hi));
    return r;
}
#undef FACET_HELIUMFP16_QN_
#undef FACET_HELIUMFP16_INST_
#define FACET_HELIUMFP16_WIDEN_B_(v) facet_heliumfp16_widen_b_(v)
#define FACET_HELIUMFP16_WIDEN_T_(v) facet_heliumfp16_widen_t_(v)
#define FACET_HELIUMFP16_NARROW_(lo, hi) facet_heliumfp16_narrow_((lo), (hi))
#endif
FACET_INLINE facet_heliumfp16_w facet_heliumfp16_h_widen(float16x8_t v)
{
    facet_heliumfp16_w r;
    r.lo = FACET_HELIUMFP16_WIDEN_B_(v);
    r.hi = FACET_HELIUMFP16_WIDEN_T_(v);
    return r;
}
/* min(x, 65504) rounded to binary16 (x >= 0, NaN-free) */
FACET_INLINE float16x8_t facet_heliumfp16_h_narrow(facet_heliumfp16_w x)
{
    float32x4_t m = vdupq_n_f32(65504.0f);
    return FACET_HELIUMFP16_NARROW_(vminnmq_f32(x.lo, m), vminnmq_f32(x.hi, m));
}
#undef FACET_HELIUMFP16_WIDEN_B_
#undef FACET_HELIUMFP16_WIDEN_T_
#undef FACET_HELIUMFP16_NARROW_

/* Whole vectors and tails: facet_heliumfp16_load_n(p, r) loads r binary16
 * values (0 <= r <= 8) into the first r lanes and 0.5 into the others,
 * reading nothing past p + r; facet_heliumfp16_store_n(p, v, r) stores the
 * first r lanes.  Tail-predicated (VCTP), no stack copy. */
FACET_INLINE float16x8_t facet_heliumfp16_load(const uint16_t *p) { return vreinterpretq_f16_u16(vldrhq_u16(p)); }
FACET_INLINE void facet_heliumfp16_store(uint16_t *p, float16x8_t v) { vstrhq_u16(p, vreinterpretq_u16_f16(v)); }
FACET_INLINE float16x8_t facet_heliumfp16_load_n(const uint16_t *p, size_t r)
{
    mve_pred16_t m = vctp16q(FACET_CAST(uint32_t, r < 8 ? r : 8));
    return vreinterpretq_f16_u16(vpselq_u16(vldrhq_z_u16(p, m), vdupq_n_u16(0x3800u), m));
}
FACET_INLINE void facet_heliumfp16_store_n(uint16_t *p, float16x8_t v, size_t r)
{
    vstrhq_p_u16(p, vreinterpretq_u16_f16(v), vctp16q(FACET_CAST(uint32_t, r < 8 ? r : 8)));
}

#define FACET_V float16x8_t
#define FACET_W facet_heliumfp16_w
#define FACET_OP(op) facet_heliumfp16_h_##op
#define FACET_K(k) facet_##k##_f16_heliumfp16
#include "facet/detail/f16_body.h"
#undef FACET_V
#undef FACET_W
#undef FACET_OP
#undef FACET_K

#endif
