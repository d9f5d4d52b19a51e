/* facet/helium.h - the Helium f32 port (Armv8.1-M MVE with floating point:
 * Cortex-M55, M85; -mcpu=cortex-m55 -mfloat-abi=hard): every kernel as a
 * FACET_INLINE function on float32x4_t, named facet_<kernel>_f32_helium and
 * facet_<kernel>_f32_fast_helium.  Contracts: facet.h; the same bounds hold
 * in every lane.
 *
 * MVE has no reciprocal or reciprocal-sqrt estimate (NEON's vrecpe /
 * vrsqrte) and no vector divide, so both start from a bit-level seed:
 *   1/x:       bits 0x7ef311c3 - bits(x), relative error <= 0.0505 (2^-4.3,
 *              measured over [1, 2)); each Newton step r + r (1 - x r), the
 *              residual fused, squares it: 2^-8.6, 2^-17.2, 2^-34.4;
 *   1/sqrt(x): bits 0x5f375a86 - bits(x)/2 (facet/scalar.h's seed, <= 3.5e-2),
 *              steps y + (y/2)(1 - x y^2): 1.8e-3, 4.9e-6, 3.6e-11.
 * The precise tier takes three steps of each (below the rounding), the fast
 * tier two (2^-17.2 and 2^-17.6).  MVE floating point flushes denormal
 * inputs and results to zero (it uses the standard FPSCR value, like armv7
 * NEON), so results below 2^-60 are good to (bound * 2^-60) absolutely
 * (facet.h).  vminnm / vmaxnm see only NaN-free values here; the clamps
 * are compare-and-select, so a NaN input becomes the low end. */
#ifndef FACET_HELIUM_H
#define FACET_HELIUM_H

#if !defined(__ARM_FEATURE_MVE) || !(__ARM_FEATURE_MVE & 2)
#error "facet/helium.h needs MVE with floating point (-mcpu=cortex-m55 -mfloat-abi=hard)"
#endif
#include <arm_mve.h>
#include <stddef.h>
#include "facet/common.h"

FACET_INLINE float32x4_t facet_helium_set(float x) { return vdupq_n_f32(x); }
FACET_INLINE float32x4_t facet_helium_add(float32x4_t a, float32x4_t b) { return vaddq_f32(a, b); }
FACET_INLINE float32x4_t facet_helium_sub(float32x4_t a, float32x4_t b) { return vsubq_f32(a, b); }
FACET_INLINE float32x4_t facet_helium_mul(float32x4_t a, float32x4_t b) { return vmulq_f32(a, b); }
/* a*b + c and c - a*b, one rounding */
FACET_INLINE float32x4_t facet_helium_fma(float32x4_t a, float32x4_t b, float32x4_t c) { return vfmaq_f32(c, a, b); }
FACET_INLINE float32x4_t facet_helium_fnma(float32x4_t a, float32x4_t b, float32x4_t c) { return vfmsq_f32(c, a, b); }
FACET_INLINE float32x4_t facet_helium_min(float32x4_t a, float32x4_t b) { return vminnmq_f32(a, b); }
FACET_INLINE float32x4_t facet_helium_max(float32x4_t a, float32x4_t b) { return vmaxnmq_f32(a, b); }
/* MVE's VCMP LT and LE are true for unordered operands (the Arm condition
 * codes after a float compare: "less than or unordered"), GT and GE are
 * false: so every "a < b" here is written b > a, false for NaN as in C */
FACET_INLINE float32x4_t facet_helium_sel_lt(float32x4_t a, float32x4_t b, float32x4_t x, float32x4_t y)
{
    return vpselq_f32(x, y, vcmpgtq_f32(b, a));
}
/* r where neither a nor b is NaN, else +0 (the NaN rule, f32_body.h NAN0_).
 * NaN is found on the bits (|x| above the infinity's pattern), not by a
 * float self-compare: with clang 14 the self-compare let NaN samples through
 * (test_f32_ports on the M55), and the bit test does not depend on how a
 * compiler lowers MVE's float compares. */
FACET_INLINE float32x4_t facet_helium_keep_ord(float32x4_t r, float32x4_t a, float32x4_t b)
{
    /* the bits without the sign, the larger of the two: above +Inf's bits
     * exactly where a or b is a NaN (one compare, no predicate OR) */
    uint32x4_t ia = vshlq_n_u32(vreinterpretq_u32_f32(a), 1);
    uint32x4_t ib = vshlq_n_u32(vreinterpretq_u32_f32(b), 1);
    mve_pred16_t nan = vcmphiq_u32(vmaxq_u32(ia, ib), vdupq_n_u32(0xff000000u));
    return vpselq_f32(vdupq_n_f32(0.0f), r, nan);
}
FACET_INLINE float32x4_t facet_helium_keep_ord4(float32x4_t r, float32x4_t a, float32x4_t b, float32x4_t c,
                                               float32x4_t d)
{
    uint32x4_t ia = vshlq_n_u32(vreinterpretq_u32_f32(a), 1);
    uint32x4_t ib = vshlq_n_u32(vreinterpretq_u32_f32(b), 1);
    uint32x4_t ic = vshlq_n_u32(vreinterpretq_u32_f32(c), 1);
    uint32x4_t id = vshlq_n_u32(vreinterpretq_u32_f32(d), 1);
    mve_pred16_t nan = vcmphiq_u32(vmaxq_u32(vmaxq_u32(ia, ib), vmaxq_u32(ic, id)), vdupq_n_u32(0xff000000u));
    return vpselq_f32(vdupq_n_f32(0.0f), r, nan);
}
/* compare-and-select, not vmaxnm (which would return the number): a NaN
 * input must become lo */
FACET_INLINE float32x4_t facet_helium_clamp(float32x4_t x, float32x4_t lo, float32x4_t hi)
{
    x = vpselq_f32(x, lo, vcmpgtq_f32(x, lo));
    return vpselq_f32(x, hi, vcmpgtq_f32(hi, x));
}
FACET_INLINE float32x4_t facet_helium_rcp_steps_(float32x4_t x, int steps)
{
    float32x4_t one = vdupq_n_f32(1.0f);
    float32x4_t r = vreinterpretq_f32_u32(vsubq_u32(vdupq_n_u32(0x7ef311c3u), vreinterpretq_u32_f32(x)));
    int i;
    for (i = 0; i < steps; i++)
        r = vfmaq_f32(r, r, vfmsq_f32(one, x, r)); /* r + r (1 - x r) */
    return r;
}
FACET_INLINE float32x4_t facet_helium_rsqrt_steps_(float32x4_t x, int steps)
{
    float32x4_t one = vdupq_n_f32(1.0f), y, e;
    uint32x4_t b = vshrq_n_u32(vreinterpretq_u32_f32(x), 1);
    int i;
    y = vreinterpretq_f32_u32(vsubq_u32(vdupq_n_u32(0x5f375a86u), b));
    for (i = 0; i < steps; i++) {
        e = vfmsq_f32(one, vmulq_f32(x, y), y);  /* 1 - x y^2 */
        y = vfmaq_f32(y, vmulq_n_f32(y, 0.5f), e);
    }
    return y;
}
FACET_INLINE float32x4_t facet_helium_rcp(float32x4_t x) { return facet_helium_rcp_steps_(x, 3); }
FACET_INLINE float32x4_t facet_helium_rsqrt(float32x4_t x) { return facet_helium_rsqrt_steps_(x, 3); }
FACET_INLINE float32x4_t facet_helium_sqr_err(float32x4_t a, float32x4_t p)
{
    return vfmsq_f32(vnegq_f32(p), a, vnegq_f32(a)); /* a*a - p, one rounding */
}
/* c - a*a, one rounding of the exact value (the kernels' exact peak) */
FACET_INLINE float32x4_t facet_helium_sqr_sub(float32x4_t a, float32x4_t c) { return vfmsq_f32(c, a, a); }
/* The fast tier (f32_fast): two steps each. */
FACET_INLINE float32x4_t facet_helium_rcp_fast(float32x4_t x) { return facet_helium_rcp_steps_(x, 2); }
FACET_INLINE float32x4_t facet_helium_rsqrt_fast(float32x4_t x) { return facet_helium_rsqrt_steps_(x, 2); }
/* a / b and sqrt(x) (b, x positive and normal): a times the tier's
 * reciprocal, x times its rsqrt (MVE has no vector divide or root). */
FACET_INLINE float32x4_t facet_helium_div(float32x4_t a, float32x4_t b) { return vmulq_f32(a, facet_helium_rcp(b)); }
FACET_INLINE float32x4_t facet_helium_div_fast(float32x4_t a, float32x4_t b) { return vmulq_f32(a, facet_helium_rcp_fast(b)); }
FACET_INLINE float32x4_t facet_helium_sqrt(float32x4_t x) { return vmulq_f32(x, facet_helium_rsqrt(x)); }
FACET_INLINE float32x4_t facet_helium_sqrt_fast(float32x4_t x) { return vmulq_f32(x, facet_helium_rsqrt_fast(x)); }

/* Tails, so that a loop over any n needs no padding by the caller:
 * facet_helium_load_n(p, r) loads r floats (0 <= r <= 4) into the first r
 * lanes and 0.5 (inside every kernel's domain) into the others, reading
 * nothing past p + r; facet_helium_store_n(p, v, r) stores the first r
 * lanes, writing nothing else.  Tail-predicated (VCTP), no stack copy.
 * Tested at every n mod 4 (tests/f32/test_tails.c, on the M55 image). */
FACET_INLINE float32x4_t facet_helium_load_n(const float *p, size_t r)
{
    mve_pred16_t m = vctp32q(FACET_CAST(uint32_t, r < 4 ? r : 4));
    return vpselq_f32(vldrwq_z_f32(p, m), vdupq_n_f32(0.5f), m);
}
FACET_INLINE void facet_helium_store_n(float *p, float32x4_t v, size_t r)
{
    vstrwq_p_f32(p, v, vctp32q(FACET_CAST(uint32_t, r < 4 ? r : 4)));
}

/* Exponent-bit ops (exp2/log2 of f32_body.h and the samplers):
 *   exp2i(k)    2^k for an integral-valued k in [-126, 127] (exponent bits)
 *   getexp(x)   floor(log2 x) as a float, x positive and normal
 *   getmant(x)  x / 2^getexp(x), in [1, 2) */
FACET_INLINE float32x4_t facet_helium_exp2i(float32x4_t k)
{
    int32x4_t e = vaddq_s32(vcvtq_s32_f32(k), vdupq_n_s32(127));
    return vreinterpretq_f32_s32(vshlq_n_s32(e, 23));
}
FACET_INLINE float32x4_t facet_helium_getexp(float32x4_t x)
{
    int32x4_t e = vreinterpretq_s32_u32(vshrq_n_u32(vreinterpretq_u32_f32(x), 23));
    return vcvtq_f32_s32(vsubq_s32(e, vdupq_n_s32(127)));
}
FACET_INLINE float32x4_t facet_helium_getmant(float32x4_t x)
{
    uint32x4_t m = vandq_u32(vreinterpretq_u32_f32(x), vdupq_n_u32(0x007fffffu));
    return vreinterpretq_f32_u32(vorrq_u32(m, vdupq_n_u32(0x3f800000u)));
}

#define FACET_V float32x4_t
#define FACET_PORT_NAME helium
#define FACET_BODY_SAMPLES 0
#include "facet/detail/f32_tiers.h"

#endif

/* ---- sampling ops and the samplers (see facet/scalar.h) ------------------- */
#ifndef FACET_HELIUM_SAMPLE_H
#define FACET_HELIUM_SAMPLE_H

#define FACET_V float32x4_t
#define FACET_PORT_NAME helium
#define FACET_BODY_SAMPLES 1
#include "facet/detail/f32_tiers.h"

#endif
