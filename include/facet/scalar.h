/* facet/scalar.h - the scalar f32 port: every kernel as a static inline
 * function on float, named facet_<kernel>_f32_scalar.
 *
 * This is the reference port and the fallback, and what the library's
 * per-sample calls run (each port's object compiles it with that port's
 * flags: src/f32/f32_one_body.h).  Its ops follow the includer's flags:
 *   - portable (C99 only): rsqrt is a bit-level seed plus three Newton steps
 *     (no libm sqrtf), the reciprocal is the IEEE division; fma only where
 *     the target has it (__FMA__ or AVX-512F on x86, __ARM_FEATURE_FMA on
 *     ARM, the F extension on RISC-V); otherwise a*b+c is two rounded operations and
 *     the exact square error comes from a Dekker split;
 *   - x86 with FMA (-mfma or -mavx512f, -march=x86-64-v3 and up; GCC or
 *     clang): the hardware's estimates rcpss / rsqrtss with the refinement
 *     of facet/avx2.h, and divss / sqrtss for quotients and roots: lane
 *     for lane the AVX2 port's arithmetic.  FACET_SCALAR_PORTABLE forces
 *     the portable ops.
 * The contracts of the kernels are in facet.h.
 */
#ifndef FACET_SCALAR_H
#define FACET_SCALAR_H

#include <stdint.h>
#include "facet/common.h"

#if (defined(__FMA__) || defined(__AVX512F__) || defined(__ARM_FEATURE_FMA) || defined(__riscv_flen)) \
    && defined(__GNUC__)
#define FACET_SCALAR_HAS_FMA 1
#else
#define FACET_SCALAR_HAS_FMA 0
#endif
/* x86 with FMA (and so AVX): the AVX2 port's ops on one lane, below */
#if FACET_SCALAR_HAS_FMA && (defined(__x86_64__) || defined(__i386__)) && !defined(FACET_SCALAR_PORTABLE)
#define FACET_SCALAR_X86_EST 1
#include <immintrin.h>
#else
#define FACET_SCALAR_X86_EST 0
#endif

FACET_INLINE float facet_scalar_set(float x) { return x; }
FACET_INLINE float facet_scalar_add(float a, float b) { return a + b; }
FACET_INLINE float facet_scalar_sub(float a, float b) { return a - b; }
FACET_INLINE float facet_scalar_mul(float a, float b) { return a * b; }
/* a*b + c; fused where the hardware fuses. */
FACET_INLINE float facet_scalar_fma(float a, float b, float c)
{
#if FACET_SCALAR_HAS_FMA
    return __builtin_fmaf(a, b, c);
#else
    float p = a * b;
    return p + c;
#endif
}

/* c - a*b */
FACET_INLINE float facet_scalar_fnma(float a, float b, float c)
{
    return facet_scalar_fma(-a, b, c);
}

FACET_INLINE float facet_scalar_min(float a, float b) { return a < b ? a : b; }
FACET_INLINE float facet_scalar_max(float a, float b) { return a > b ? a : b; }

/* a < b ? x : y */
FACET_INLINE float facet_scalar_sel_lt(float a, float b, float x, float y)
{
    return a < b ? x : y;
}

/* Clamp to [lo, hi]; NaN goes to lo, -Inf to lo, +Inf to hi. */
FACET_INLINE float facet_scalar_clamp(float x, float lo, float hi)
{
    x = x > lo ? x : lo;
    return x < hi ? x : hi;
}

/* r where neither a nor b is NaN, else +0 (the kernels' NaN rule, f32_body.h:
 * one ordered compare of two inputs and a select) */
FACET_INLINE float facet_scalar_keep_ord(float r, float a, float b)
{
    return (a == a && b == b) ? r : 0.0f;
}
/* the same for four inputs (the NaN rule of kernels with 3 or more) */
FACET_INLINE float facet_scalar_keep_ord4(float r, float a, float b, float c, float d)
{
    return (a == a && b == b && c == c && d == d) ? r : 0.0f;
}

#if FACET_SCALAR_X86_EST
/* x86 with FMA: the hardware's estimates and square root, one lane of the
 * AVX2 port's ops (with AVX-512F too: rcpss / rsqrtss, not the 14-bit
 * forms, so that one refinement covers every x86 FMA target) */
FACET_INLINE float facet_scalar_hw_sqrt_(float x) { return _mm_cvtss_f32(_mm_sqrt_ss(_mm_set_ss(x))); }
#ifdef FACET_SCALAR_TEST_WORST_ESTIMATES
/* Test builds only: estimates off by the architectural bound 1.5 * 2^-12,
 * the sign from bit 12 of x, as the AVX2 port emulates its own
 * (tests/suites/15-worst-estimates.sh). */
FACET_INLINE float facet_scalar_worst_(float exact, float x)
{
    union { float f; uint32_t u; } b;
    const float d = 1.5f / 4096.0f;
    b.f = x;
    return __builtin_fmaf(exact, (b.u & 0x1000u) ? -d : d, exact);
}
#define facet_scalar_rcp_est_(x) facet_scalar_worst_(1.0f / (x), (x))
#define facet_scalar_rsqrt_est_(x) facet_scalar_worst_(1.0f / facet_scalar_hw_sqrt_(x), (x))
#else
#define facet_scalar_rcp_est_(x) _mm_cvtss_f32(_mm_rcp_ss(_mm_set_ss(x)))
#define facet_scalar_rsqrt_est_(x) _mm_cvtss_f32(_mm_rsqrt_ss(_mm_set_ss(x)))
#endif
/* facet/avx2.h: the third-order steps r (1 + e + e^2) and
 * y (1 + e/2 + 3e^2/8) (error < 5e-11 from a 1.5 * 2^-12 estimate), the
 * fast tier one Newton step each (about 1.5 e^2 < 2^-21) */
FACET_INLINE float facet_scalar_rcp(float x)
{
    float r = facet_scalar_rcp_est_(x);
    float e = __builtin_fmaf(-x, r, 1.0f);
    return __builtin_fmaf(__builtin_fmaf(e, e, e), r, r);
}
FACET_INLINE float facet_scalar_rsqrt(float x)
{
    float y = facet_scalar_rsqrt_est_(x);
    float e = __builtin_fmaf(-(x * y), y, 1.0f);
    float p = __builtin_fmaf(e, 0.375f, 0.5f);
    return __builtin_fmaf(e * p, y, y);
}
FACET_INLINE float facet_scalar_rcp_fast(float x)
{
    float r = facet_scalar_rcp_est_(x);
    return __builtin_fmaf(r, __builtin_fmaf(-x, r, 1.0f), r);
}
FACET_INLINE float facet_scalar_rsqrt_fast(float x)
{
    float y = facet_scalar_rsqrt_est_(x);
    float e = __builtin_fmaf(-(x * y), y, 1.0f);
    return __builtin_fmaf(0.5f * y, e, y);
}
FACET_INLINE float facet_scalar_sqrt_fast(float x) { return facet_scalar_hw_sqrt_(x); }
FACET_INLINE float facet_scalar_sqrt(float x) { return facet_scalar_hw_sqrt_(x); }
#endif

#if !FACET_SCALAR_X86_EST
/* 1/x for x in [2^-126, 2^126]: the IEEE division. */
FACET_INLINE float facet_scalar_rcp(float x) { return 1.0f / x; }

/* 1/sqrt(x) for x in [2^-126, 2^126].  Seed: the exponent-halving bit trick
 * with constant 0x5f375a86 (relative error <= 3.5e-2).  Each Newton step
 * y' = y + y(1 - x y^2)/2 maps a relative error e to about 1.5 e^2:
 * 3.5e-2 -> 1.8e-3 -> 4.9e-6 -> 3.6e-11, so three steps leave only the
 * rounding of the steps themselves (about 1 ulp). */
FACET_INLINE float facet_scalar_rsqrt_steps_(float x, int steps)
{
    union { float f; uint32_t u; } b;
    float y, e;
    int i;
    b.f = x;
    b.u = 0x5f375a86u - (b.u >> 1);
    y = b.f;
    for (i = 0; i < steps; i++) {
        e = facet_scalar_fnma(x * y, y, 1.0f);
        y = facet_scalar_fma(0.5f * y, e, y);
    }
    return y;
}
FACET_INLINE float facet_scalar_rsqrt(float x) { return facet_scalar_rsqrt_steps_(x, 3); }

/* The fast tier (f32_fast): the same division, and rsqrt with two Newton
 * steps instead of three (3.5e-2 -> 1.8e-3 -> 4.9e-6, about 2^-17.6). */
FACET_INLINE float facet_scalar_rcp_fast(float x) { return 1.0f / x; }
FACET_INLINE float facet_scalar_rsqrt_fast(float x) { return facet_scalar_rsqrt_steps_(x, 2); }

/* sqrt(x) for x positive and normal: x rsqrt(x) (no libm), with the
 * tier's rsqrt. */
FACET_INLINE float facet_scalar_sqrt(float x) { return x * facet_scalar_rsqrt(x); }
FACET_INLINE float facet_scalar_sqrt_fast(float x) { return x * facet_scalar_rsqrt_fast(x); }
#endif /* !FACET_SCALAR_X86_EST */

/* a / b for b positive and normal (the quotients of f32_body.h; its op
 * counts take them as a multiply plus a reciprocal): the IEEE division in
 * both tiers. */
FACET_INLINE float facet_scalar_div(float a, float b) { return a / b; }
FACET_INLINE float facet_scalar_div_fast(float a, float b) { return a / b; }

/* Exact a*a - p for p = fl(a*a) (no overflow/underflow in range).  Without
 * FMA: Dekker, splitting a by masking the low 12 significand bits, so the
 * halves' products are exact whatever the compiler contracts. */
FACET_INLINE float facet_scalar_sqr_err(float a, float p)
{
#if FACET_SCALAR_HAS_FMA
    return __builtin_fmaf(a, a, -p);
#else
    union { float f; uint32_t u; } b;
    float hi, lo;
    b.f = a;
    b.u &= 0xfffff000u;
    hi = b.f;
    lo = a - hi;
    return ((hi * hi - p) + 2.0f * hi * lo) + lo * lo;
#endif
}

/* c - a*a: one rounding of the exact value with FMA; without, (c - p) -
 * (a*a - p), p = a*a rounded and its exact error, one rounding where c - p
 * cancels (Sterbenz, exact) and two elsewhere (the kernels' exact peak). */
FACET_INLINE float facet_scalar_sqr_sub(float a, float c)
{
#if FACET_SCALAR_HAS_FMA
    return __builtin_fmaf(-a, a, c);
#else
    float p = a * a;
    return (c - p) - facet_scalar_sqr_err(a, p);
#endif
}


/* Exponent-bit ops (exp2/log2 of f32_body.h and the samplers):
 *   exp2i(k)    2^k for an integral-valued k in [-126, 127] (exponent bits)
 *   getexp(x)   floor(log2 x) as a float, x positive and normal
 *   getmant(x)  x / 2^getexp(x), in [1, 2) */
FACET_INLINE float facet_scalar_exp2i(float k)
{
    union { float f; uint32_t u; } b;
    b.u = FACET_CAST(uint32_t, FACET_CAST(int32_t, k) + 127) << 23;
    return b.f;
}
FACET_INLINE float facet_scalar_getexp(float x)
{
    union { float f; uint32_t u; } b;
    b.f = x;
    return FACET_CAST(float, FACET_CAST(int32_t, b.u >> 23) - 127);
}
FACET_INLINE float facet_scalar_getmant(float x)
{
    union { float f; uint32_t u; } b;
    b.f = x;
    b.u = (b.u & 0x007fffffu) | 0x3f800000u;
    return b.f;
}

#define FACET_V float
#define FACET_PORT_NAME scalar
#define FACET_BODY_SAMPLES 0
#include "facet/detail/f32_tiers.h"

#endif

/* ---- sampling ops and the samplers ----------------------------------------
 * The samplers of both tiers (their exponent-bit ops are above, with the
 * kernels' ops), facet_<sampler>_f32_scalar and
 * facet_<sampler>_f32_fast_scalar.  Every port header has the same section. */
#ifndef FACET_SCALAR_SAMPLE_H
#define FACET_SCALAR_SAMPLE_H


#define FACET_V float
#define FACET_PORT_NAME scalar
#define FACET_BODY_SAMPLES 1
#include "facet/detail/f32_tiers.h"

#endif
