/* facet/neon.h - the NEON f32 port (aarch64, and armv7 with
 * -mfpu=neon-vfpv4 -mfloat-abi=hard): every kernel as a FACET_INLINE function
 * on float32x4_t, named facet_<kernel>_f32_neon.  Contracts: facet.h; the
 * same bounds hold in every lane.
 *
 * vrecpe/vrsqrte give only ~8 bits (relative error <= 2^-8), so three Newton
 * steps follow (vrecps / vrsqrts: 2^-8 -> 2^-16 -> 2^-32 -> rounding).
 * armv7 NEON always flushes denormals to zero: denormal inputs act as 0 and
 * intermediates below 2^-126 become 0, so on armv7 results below 2^-60 are
 * good to (bound * 2^-60) absolutely rather than relatively (facet.h);
 * aarch64 keeps denormals unless the caller sets FPCR.FZ. */
#ifndef FACET_NEON_H
#define FACET_NEON_H

#if !defined(__ARM_NEON)
#error "facet/neon.h needs NEON (aarch64, or armv7 with -mfpu=neon-vfpv4 -mfloat-abi=hard)"
#endif
#if !defined(__aarch64__) && !defined(__ARM_FEATURE_FMA)
#error "facet/neon.h on armv7 needs VFPv4 fused multiply-add (-mfpu=neon-vfpv4)"
#endif
#include <arm_neon.h>
#include <stddef.h>
#include "facet/common.h"

FACET_INLINE float32x4_t facet_neon_set(float x) { return vdupq_n_f32(x); }
FACET_INLINE float32x4_t facet_neon_add(float32x4_t a, float32x4_t b) { return vaddq_f32(a, b); }
FACET_INLINE float32x4_t facet_neon_sub(float32x4_t a, float32x4_t b) { return vsubq_f32(a, b); }
FACET_INLINE float32x4_t facet_neon_mul(float32x4_t a, float32x4_t b) { return vmulq_f32(a, b); }
FACET_INLINE float32x4_t facet_neon_fma(float32x4_t a, float32x4_t b, float32x4_t c) { return vfmaq_f32(c, a, b); }
FACET_INLINE float32x4_t facet_neon_fnma(float32x4_t a, float32x4_t b, float32x4_t c) { return vfmsq_f32(c, a, b); }
/* vminq/vmaxq propagate NaN; the kernels pass only NaN-free values here. */
FACET_INLINE float32x4_t facet_neon_min(float32x4_t a, float32x4_t b) { return vminq_f32(a, b); }
FACET_INLINE float32x4_t facet_neon_max(float32x4_t a, float32x4_t b) { return vmaxq_f32(a, b); }
FACET_INLINE float32x4_t facet_neon_sel_lt(float32x4_t a, float32x4_t b, float32x4_t x, float32x4_t y)
{
    return vbslq_f32(vcltq_f32(a, b), x, y);
}
/* compare-and-select, not vmaxq: a NaN input must become lo */
FACET_INLINE float32x4_t facet_neon_clamp(float32x4_t x, float32x4_t lo, float32x4_t hi)
{
    x = vbslq_f32(vcgtq_f32(x, lo), x, lo);
    return vbslq_f32(vcltq_f32(x, hi), x, hi);
}
/* r where neither a nor b is NaN, else +0: vmaxq is NaN when either
 * operand is (aarch64 and armv7 alike), so one self-compare of it finds both */
FACET_INLINE float32x4_t facet_neon_keep_ord(float32x4_t r, float32x4_t a, float32x4_t b)
{
    float32x4_t m = vmaxq_f32(a, b);
    return vreinterpretq_f32_u32(vandq_u32(vreinterpretq_u32_f32(r), vceqq_f32(m, m)));
}
FACET_INLINE float32x4_t facet_neon_keep_ord4(float32x4_t r, float32x4_t a, float32x4_t b, float32x4_t c,
                                             float32x4_t d)
{
    float32x4_t m = vmaxq_f32(vmaxq_f32(a, b), vmaxq_f32(c, d));
    return vreinterpretq_f32_u32(vandq_u32(vreinterpretq_u32_f32(r), vceqq_f32(m, m)));
}
FACET_INLINE float32x4_t facet_neon_rcp(float32x4_t x)
{
    float32x4_t r = vrecpeq_f32(x);
    r = vmulq_f32(r, vrecpsq_f32(x, r));
    r = vmulq_f32(r, vrecpsq_f32(x, r));
    /* last step fused: r + r (1 - x r) */
    return vfmaq_f32(r, r, vfmsq_f32(vdupq_n_f32(1.0f), x, r));
}
FACET_INLINE float32x4_t facet_neon_rsqrt(float32x4_t x)
{
    float32x4_t y = vrsqrteq_f32(x), e;
    y = vmulq_f32(y, vrsqrtsq_f32(vmulq_f32(x, y), y));
    y = vmulq_f32(y, vrsqrtsq_f32(vmulq_f32(x, y), y));
    /* last step fused: y + y (1 - x y^2) / 2 */
    e = vfmsq_f32(vdupq_n_f32(1.0f), vmulq_f32(x, y), y);
    return vfmaq_f32(y, vmulq_n_f32(y, 0.5f), e);
}
FACET_INLINE float32x4_t facet_neon_sqr_err(float32x4_t a, float32x4_t p)
{
    return vfmsq_f32(vnegq_f32(p), a, vnegq_f32(a)); /* a*a - p, one rounding */
}
/* c - a*a, one rounding of the exact value (the kernels' exact peak) */
FACET_INLINE float32x4_t facet_neon_sqr_sub(float32x4_t a, float32x4_t c) { return vfmsq_f32(c, a, a); }

/* The fast tier (f32_fast): two steps instead of three (2^-8 -> 2^-16 ->
 * 2^-32 before rounding; the second fused). */
FACET_INLINE float32x4_t facet_neon_rcp_fast(float32x4_t x)
{
    float32x4_t r = vrecpeq_f32(x);
    r = vmulq_f32(r, vrecpsq_f32(x, r));
    return vfmaq_f32(r, r, vfmsq_f32(vdupq_n_f32(1.0f), x, r));
}
FACET_INLINE float32x4_t facet_neon_rsqrt_fast(float32x4_t x)
{
    float32x4_t y = vrsqrteq_f32(x), e;
    y = vmulq_f32(y, vrsqrtsq_f32(vmulq_f32(x, y), y));
    e = vfmsq_f32(vdupq_n_f32(1.0f), vmulq_f32(x, y), y);
    return vfmaq_f32(y, vmulq_n_f32(y, 0.5f), e);
}
/* a / b and sqrt(x) (b, x positive and normal): a times the tier's
 * reciprocal, x times its rsqrt (armv7 NEON has no vector divide or square
 * root; on aarch64 the estimate and steps pipeline where fdiv / fsqrt do
 * not). */
FACET_INLINE float32x4_t facet_neon_div(float32x4_t a, float32x4_t b) { return vmulq_f32(a, facet_neon_rcp(b)); }
FACET_INLINE float32x4_t facet_neon_div_fast(float32x4_t a, float32x4_t b) { return vmulq_f32(a, facet_neon_rcp_fast(b)); }
FACET_INLINE float32x4_t facet_neon_sqrt(float32x4_t x) { return vmulq_f32(x, facet_neon_rsqrt(x)); }
FACET_INLINE float32x4_t facet_neon_sqrt_fast(float32x4_t x) { return vmulq_f32(x, facet_neon_rsqrt_fast(x)); }

/* Tails, so that a loop over any n needs no padding by the caller:
 * facet_neon_load_n(p, r) loads r floats (0 <= r <= 4) from p into the first
 * r lanes and 0.5 (inside every kernel's domain) into the others, reading
 * nothing past p + r; facet_neon_store_n(p, v, r) stores the first r lanes,
 * writing nothing else.  Scalar-finished: through a 4-float stack copy.  The loop:
 *     for (i = 0; i + 4 <= n; i += 4)
 *         store(out + i, kernel(load(x + i), ...));
 *     if (i < n)
 *         facet_neon_store_n(out + i, kernel(facet_neon_load_n(x + i, n - i), ...), n - i);
 * All loads of a block come before its store, so out may be one of the
 * inputs.  Tested at every n mod 4 (tests/f32/test_tails.c). */
FACET_INLINE float32x4_t facet_neon_load_n(const float *p, size_t r)
{
    float t[4];
    facet_tail_in_(t, 4, p, r);
    return vld1q_f32(t);
}
FACET_INLINE void facet_neon_store_n(float *p, float32x4_t v, size_t r)
{
    float t[4];
    vst1q_f32(t, v);
    facet_tail_out_(p, t, 4, r);
}

/* Exponent-bit ops (exp2/log2 of f32_body.h and the samplers):
 *   exp2i(k)    2^k for an integral-valued k in [-126, 127] (exponent bits)
 *   getexp(x)   floor(log2 x) as a float, x positive and normal
 *   getmant(x)  x / 2^getexp(x), in [1, 2) */
FACET_INLINE float32x4_t facet_neon_exp2i(float32x4_t k)
{
    int32x4_t e = vaddq_s32(vcvtq_s32_f32(k), vdupq_n_s32(127));
    return vreinterpretq_f32_s32(vshlq_n_s32(e, 23));
}
FACET_INLINE float32x4_t facet_neon_getexp(float32x4_t x)
{
    int32x4_t e = vreinterpretq_s32_u32(vshrq_n_u32(vreinterpretq_u32_f32(x), 23));
    return vcvtq_f32_s32(vsubq_s32(e, vdupq_n_s32(127)));
}
FACET_INLINE float32x4_t facet_neon_getmant(float32x4_t x)
{
    uint32x4_t m = vandq_u32(vreinterpretq_u32_f32(x), vdupq_n_u32(0x007fffffu));
    return vreinterpretq_f32_u32(vorrq_u32(m, vdupq_n_u32(0x3f800000u)));
}

#define FACET_V float32x4_t
#define FACET_PORT_NAME neon
#define FACET_BODY_SAMPLES 0
#include "facet/detail/f32_tiers.h"

#endif

/* ---- sampling ops and the samplers (see facet/scalar.h) ------------------- */
#ifndef FACET_NEON_SAMPLE_H
#define FACET_NEON_SAMPLE_H


#define FACET_V float32x4_t
#define FACET_PORT_NAME neon
#define FACET_BODY_SAMPLES 1
#include "facet/detail/f32_tiers.h"

#endif
