/* facet/neonfp16.h - the ARMv8.2-A FP16 NEON binary16 port (aarch64): every
 * f16 kernel as a static inline function on float16x8_t (8 binary16 lanes),
 * named facet_<kernel>_f16_neonfp16.  Contracts: facet/f16.h.  Compile with
 * -march=armv8.2-a+fp16; run only where the CPU has FP16 arithmetic
 * (facet_f16_port_supported("neonfp16"): HWCAP FPHP and ASIMDHP).
 *
 * Reciprocal and rsqrt: frecpe / frsqrte (8-bit estimates) and one Newton
 * step each (frecps / frsqrts, fused): 2^-16 before the step's rounding.
 * Min and max are the NaN-propagating fmin/fmax except the clamp's low end,
 * fmaxnm (a NaN input gives the low end, as on the other ports).  The f32
 * lanes (FACET_W): two float32x4_t, fcvtl/fcvtl2 and fcvtn/fcvtn2 (the
 * FPCR rounding, to nearest even), estimates with one Newton step. */
#ifndef FACET_NEONFP16_H
#define FACET_NEONFP16_H

#if !defined(__aarch64__) || !defined(__ARM_FEATURE_FP16_VECTOR_ARITHMETIC)
#error "facet/neonfp16.h needs aarch64 with FP16 arithmetic (-march=armv8.2-a+fp16)"
#endif
#include <arm_neon.h>
#include <stddef.h>
#include <stdint.h>
#include "facet/common.h"
#include "facet/f16.h"

typedef struct facet_neonfp16_w {
    float32x4_t lo, hi;
} facet_neonfp16_w;

FACET_INLINE float16x8_t facet_neonfp16_h_set(float x) { return vdupq_n_f16(FACET_CAST(float16_t, x)); }
FACET_INLINE float16x8_t facet_neonfp16_h_add(float16x8_t a, float16x8_t b) { return vaddq_f16(a, b); }
FACET_INLINE float16x8_t facet_neonfp16_h_sub(float16x8_t a, float16x8_t b) { return vsubq_f16(a, b); }
FACET_INLINE float16x8_t facet_neonfp16_h_mul(float16x8_t a, float16x8_t b) { return vmulq_f16(a, b); }
FACET_INLINE float16x8_t facet_neonfp16_h_fma(float16x8_t a, float16x8_t b, float16x8_t c) { return vfmaq_f16(c, a, b); }
FACET_INLINE float16x8_t facet_neonfp16_h_fnma(float16x8_t a, float16x8_t b, float16x8_t c) { return vfmsq_f16(c, a, b); }
FACET_INLINE float16x8_t facet_neonfp16_h_min(float16x8_t a, float16x8_t b) { return vminq_f16(a, b); }
FACET_INLINE float16x8_t facet_neonfp16_h_max(float16x8_t a, float16x8_t b) { return vmaxq_f16(a, b); }
FACET_INLINE float16x8_t facet_neonfp16_h_clamp(float16x8_t x, float16x8_t lo, float16x8_t hi)
{
    return vminq_f16(vmaxnmq_f16(x, lo), hi);
}
FACET_INLINE float16x8_t facet_neonfp16_h_keep_ord(float16x8_t r, float16x8_t a, float16x8_t b)
{
    uint16x8_t m = vandq_u16(vceqq_f16(a, a), vceqq_f16(b, b));
    return vreinterpretq_f16_u16(vandq_u16(m, vreinterpretq_u16_f16(r)));
}
FACET_INLINE float16x8_t facet_neonfp16_h_keep_ord4(float16x8_t r, float16x8_t a, float16x8_t b, float16x8_t c,
                                                     float16x8_t d)
{
    uint16x8_t m = vandq_u16(vandq_u16(vceqq_f16(a, a), vceqq_f16(b, b)), vandq_u16(vceqq_f16(c, c), vceqq_f16(d, d)));
    return vreinterpretq_f16_u16(vandq_u16(m, vreinterpretq_u16_f16(r)));
}
FACET_INLINE float16x8_t facet_neonfp16_h_rcp(float16x8_t x)
{
    float16x8_t r = vrecpeq_f16(x);
    return vmulq_f16(r, vrecpsq_f16(x, r));
}
FACET_INLINE float16x8_t facet_neonfp16_h_rsqrt(float16x8_t x)
{
    float16x8_t y = vrsqrteq_f16(x);
    return vmulq_f16(y, vrsqrtsq_f16(vmulq_f16(x, y), y));
}
FACET_INLINE float16x8_t facet_neonfp16_h_div(float16x8_t a, float16x8_t b) { return vmulq_f16(a, facet_neonfp16_h_rcp(b)); }
FACET_INLINE float16x8_t facet_neonfp16_h_sqrt(float16x8_t x) { return vmulq_f16(x, facet_neonfp16_h_rsqrt(x)); }

/* ---- the f32 lanes ---- */
FACET_INLINE facet_neonfp16_w facet_neonfp16_h_w_set(float x)
{
    facet_neonfp16_w r;
    r.lo = r.hi = vdupq_n_f32(x);
    return r;
}
#define FACET_NEONFP16_W_BIN_(name, e)                                                         \
    FACET_INLINE facet_neonfp16_w facet_neonfp16_h_w_##name(facet_neonfp16_w a, facet_neonfp16_w b) \
    {                                                                                          \
        facet_neonfp16_w r;                                                                    \
        r.lo = e(a.lo, b.lo);                                                                  \
        r.hi = e(a.hi, b.hi);                                                                  \
        return r;                                                                              \
    }
FACET_NEONFP16_W_BIN_(add, vaddq_f32)
FACET_NEONFP16_W_BIN_(sub, vsubq_f32)
FACET_NEONFP16_W_BIN_(mul, vmulq_f32)
FACET_NEONFP16_W_BIN_(min, vminq_f32)
FACET_NEONFP16_W_BIN_(max, vmaxq_f32)
#undef FACET_NEONFP16_W_BIN_
FACET_INLINE facet_neonfp16_w facet_neonfp16_h_w_fma(facet_neonfp16_w a, facet_neonfp16_w b, facet_neonfp16_w c)
{
    facet_neonfp16_w r;
    r.lo = vfmaq_f32(c.lo, a.lo, b.lo);
    r.hi = vfmaq_f32(c.hi, a.hi, b.hi);
    return r;
}
FACET_INLINE facet_neonfp16_w facet_neonfp16_h_w_fnma(facet_neonfp16_w a, facet_neonfp16_w b, facet_neonfp16_w c)
{
    facet_neonfp16_w r;
    r.lo = vfmsq_f32(c.lo, a.lo, b.lo);
    r.hi = vfmsq_f32(c.hi, a.hi, b.hi);
    return r;
}
/* a a - p exactly (p = fl(a a)): -(p - a a), fused */
FACET_INLINE facet_neonfp16_w facet_neonfp16_h_w_sqr_err(facet_neonfp16_w a, facet_neonfp16_w p)
{
    facet_neonfp16_w r;
    r.lo = vnegq_f32(vfmsq_f32(p.lo, a.lo, a.lo));
    r.hi = vnegq_f32(vfmsq_f32(p.hi, a.hi, a.hi));
    return r;
}
FACET_INLINE float32x4_t facet_neonfp16_rcp4_(float32x4_t x)
{
    float32x4_t r = vrecpeq_f32(x);
    return vmulq_f32(r, vrecpsq_f32(x, r));
}
FACET_INLINE float32x4_t facet_neonfp16_rsqrt4_(float32x4_t x)
{
    float32x4_t y = vrsqrteq_f32(x);
    return vmulq_f32(y, vrsqrtsq_f32(vmulq_f32(x, y), y));
}
FACET_INLINE facet_neonfp16_w facet_neonfp16_h_w_rcp(facet_neonfp16_w x)
{
    facet_neonfp16_w r;
    r.lo = facet_neonfp16_rcp4_(x.lo);
    r.hi = facet_neonfp16_rcp4_(x.hi);
    return r;
}
FACET_INLINE facet_neonfp16_w facet_neonfp16_h_w_rsqrt(facet_neonfp16_w x)
{
    facet_neonfp16_w r;
    r.lo = facet_neonfp16_rsqrt4_(x.lo);
    r.hi = facet_neonfp16_rsqrt4_(x.hi);
    return r;
}
FACET_INLINE facet_neonfp16_w facet_neonfp16_h_widen(float16x8_t v)
{
    facet_neonfp16_w r;
    r.lo = vcvt_f32_f16(vget_low_f16(v));
    r.hi = vcvt_high_f32_f16(v);
    return r;
}
/* rounded to binary16 by the FPCR (to nearest even; from 65520 on +Inf) */
FACET_INLINE float16x8_t facet_neonfp16_h_narrow(facet_neonfp16_w x)
{
    return vcvt_high_f16_f32(vcvt_f16_f32(x.lo), x.hi);
}

/* whole vectors and tails (the tail staged through 8 values, 0.5 in the
 * unused lanes: nothing read or written past p + r) */
FACET_INLINE float16x8_t facet_neonfp16_load(const uint16_t *p) { return vreinterpretq_f16_u16(vld1q_u16(p)); }
FACET_INLINE void facet_neonfp16_store(uint16_t *p, float16x8_t v) { vst1q_u16(p, vreinterpretq_u16_f16(v)); }
FACET_INLINE float16x8_t facet_neonfp16_load_n(const uint16_t *p, size_t r)
{
    uint16_t t[8];
    size_t j;
    for (j = 0; j < 8; j++)
        t[j] = j < r ? p[j] : 0x3800u;
    return facet_neonfp16_load(t);
}
FACET_INLINE void facet_neonfp16_store_n(uint16_t *p, float16x8_t v, size_t r)
{
    uint16_t t[8];
    size_t j;
    facet_neonfp16_store(t, v);
    for (j = 0; j < r && j < 8; j++)
        p[j] = t[j];
}

#define FACET_V float16x8_t
#define FACET_W facet_neonfp16_w
#define FACET_OP(op) facet_neonfp16_h_##op
#define FACET_K(k) facet_##k##_f16_neonfp16
#include "facet/detail/f16_body.h"
#undef FACET_V
#undef FACET_W
#undef FACET_OP
#undef FACET_K

#endif
