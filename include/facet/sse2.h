/* facet/sse2.h - the SSE2 f32 port: every kernel as a FACET_INLINE function
 * on __m128 (4 lanes), named facet_<kernel>_f32_sse2.  Contracts: facet.h;
 * the same bounds hold in every lane.
 *
 * SSE2 has no FMA, so fma is a multiply and an add, and the exact square
 * error comes from a Dekker split by bit mask.  Reciprocal and rsqrt use the
 * IEEE divps and sqrtps ("precise"): a 12-bit rcpps would need two Newton
 * steps of three dependent operations each to meet the bounds, which costs
 * about what divps does on the cores that lack AVX2. */
#ifndef FACET_SSE2_H
#define FACET_SSE2_H

#if !defined(__SSE2__)
#error "facet/sse2.h needs SSE2 (-msse2; always on for x86-64)"
#endif
#include <emmintrin.h>
#include <stddef.h>
#include "facet/common.h"

FACET_INLINE __m128 facet_sse2_set(float x) { return _mm_set1_ps(x); }
FACET_INLINE __m128 facet_sse2_add(__m128 a, __m128 b) { return _mm_add_ps(a, b); }
FACET_INLINE __m128 facet_sse2_sub(__m128 a, __m128 b) { return _mm_sub_ps(a, b); }
FACET_INLINE __m128 facet_sse2_mul(__m128 a, __m128 b) { return _mm_mul_ps(a, b); }
FACET_INLINE __m128 facet_sse2_fma(__m128 a, __m128 b, __m128 c) { return _mm_add_ps(_mm_mul_ps(a, b), c); }
FACET_INLINE __m128 facet_sse2_fnma(__m128 a, __m128 b, __m128 c) { return _mm_sub_ps(c, _mm_mul_ps(a, b)); }
/* minps/maxps return the second operand when either is NaN; the kernels
 * only pass NaN-free values here (clamp handles the inputs). */
FACET_INLINE __m128 facet_sse2_min(__m128 a, __m128 b) { return _mm_min_ps(a, b); }
FACET_INLINE __m128 facet_sse2_max(__m128 a, __m128 b) { return _mm_max_ps(a, b); }
FACET_INLINE __m128 facet_sse2_sel_lt(__m128 a, __m128 b, __m128 x, __m128 y)
{
    __m128 m = _mm_cmplt_ps(a, b);
    return _mm_or_ps(_mm_and_ps(m, x), _mm_andnot_ps(m, y));
}
/* max(x, lo) returns lo for NaN x (second operand), then min(., hi). */
FACET_INLINE __m128 facet_sse2_clamp(__m128 x, __m128 lo, __m128 hi)
{
    return _mm_min_ps(_mm_max_ps(x, lo), hi);
}
/* r where neither a nor b is NaN, else +0: cmpordps and a mask */
FACET_INLINE __m128 facet_sse2_keep_ord(__m128 r, __m128 a, __m128 b)
{
    return _mm_and_ps(r, _mm_cmpord_ps(a, b));
}
FACET_INLINE __m128 facet_sse2_keep_ord4(__m128 r, __m128 a, __m128 b, __m128 c, __m128 d)
{
    return _mm_and_ps(r, _mm_and_ps(_mm_cmpord_ps(a, b), _mm_cmpord_ps(c, d)));
}
FACET_INLINE __m128 facet_sse2_rcp(__m128 x) { return _mm_div_ps(_mm_set1_ps(1.0f), x); }
FACET_INLINE __m128 facet_sse2_rsqrt(__m128 x) { return _mm_div_ps(_mm_set1_ps(1.0f), _mm_sqrt_ps(x)); }
FACET_INLINE __m128 facet_sse2_sqr_err(__m128 a, __m128 p)
{
    __m128 hi = _mm_and_ps(a, _mm_castsi128_ps(_mm_set1_epi32(FACET_CAST(int, 0xfffff000u))));
    __m128 lo = _mm_sub_ps(a, hi);
    __m128 t = _mm_sub_ps(_mm_mul_ps(hi, hi), p);
    t = _mm_add_ps(t, _mm_mul_ps(_mm_add_ps(hi, hi), lo));
    return _mm_add_ps(t, _mm_mul_ps(lo, lo));
}
/* c - a*a without an FMA: (c - p) - (a*a - p), p = a*a rounded and its
 * exact error; c - p is exact where it cancels (Sterbenz), so the result is
 * one rounding of the exact value there and two elsewhere (the kernels'
 * exact peak) */
FACET_INLINE __m128 facet_sse2_sqr_sub(__m128 a, __m128 c)
{
    __m128 p = _mm_mul_ps(a, a);
    return _mm_sub_ps(_mm_sub_ps(c, p), facet_sse2_sqr_err(a, p));
}

/* The fast tier (f32_fast): rcpps / rsqrtps (relative error <= 1.5 * 2^-12)
 * and one Newton step each, leaving about 1.5 (1.5 * 2^-12)^2 < 2^-21 plus
 * the step's rounding. */
FACET_INLINE __m128 facet_sse2_rcp_fast(__m128 x)
{
    __m128 r = _mm_rcp_ps(x);
    return _mm_mul_ps(r, _mm_sub_ps(_mm_set1_ps(2.0f), _mm_mul_ps(x, r)));
}
FACET_INLINE __m128 facet_sse2_rsqrt_fast(__m128 x)
{
    __m128 y = _mm_rsqrt_ps(x);
    __m128 h = _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(0.5f), x), _mm_mul_ps(y, y));
    return _mm_mul_ps(y, _mm_sub_ps(_mm_set1_ps(1.5f), h));
}
/* a / b and sqrt(x) (b, x positive and normal): divps and sqrtps in both
 * tiers, correctly rounded; a quotient through rcpps and a Newton step costs
 * more operations than divps (measured: the fast tier's brdf_hammon was the
 * slower one with it). */
FACET_INLINE __m128 facet_sse2_div(__m128 a, __m128 b) { return _mm_div_ps(a, b); }
FACET_INLINE __m128 facet_sse2_div_fast(__m128 a, __m128 b) { return _mm_div_ps(a, b); }
FACET_INLINE __m128 facet_sse2_sqrt(__m128 x) { return _mm_sqrt_ps(x); }
FACET_INLINE __m128 facet_sse2_sqrt_fast(__m128 x) { return _mm_sqrt_ps(x); }

/* Tails, so that a loop over any n needs no padding by the caller:
 * facet_sse2_load_n(p, r) loads r floats (0 <= r <= 4) from p into the first
 * r lanes and 0.5 (inside every kernel's domain) into the others, reading
 * nothing past p + r; facet_sse2_store_n(p, v, r) stores the first r lanes,
 * writing nothing else.  Scalar-finished: through a 4-float stack copy (SSE2 has no masked load).  The loop:
 *     for (i = 0; i + 4 <= n; i += 4)
 *         store(out + i, kernel(load(x + i), ...));
 *     if (i < n)
 *         facet_sse2_store_n(out + i, kernel(facet_sse2_load_n(x + i, n - i), ...), n - i);
 * All loads of a block come before its store, so out may be one of the
 * inputs.  Tested at every n mod 4 (tests/f32/test_tails.c). */
FACET_INLINE __m128 facet_sse2_load_n(const float *p, size_t r)
{
    float t[4];
    facet_tail_in_(t, 4, p, r);
    return _mm_loadu_ps(t);
}
FACET_INLINE void facet_sse2_store_n(float *p, __m128 v, size_t r)
{
    float t[4];
    _mm_storeu_ps(t, v);
    facet_tail_out_(p, t, 4, r);
}

/* Exponent-bit ops (exp2/log2 of f32_body.h and the samplers):
 *   exp2i(k)    2^k for an integral-valued k in [-126, 127] (exponent bits)
 *   getexp(x)   floor(log2 x) as a float, x positive and normal
 *   getmant(x)  x / 2^getexp(x), in [1, 2) */
FACET_INLINE __m128 facet_sse2_exp2i(__m128 k)
{
    __m128i e = _mm_add_epi32(_mm_cvttps_epi32(k), _mm_set1_epi32(127));
    return _mm_castsi128_ps(_mm_slli_epi32(e, 23));
}
FACET_INLINE __m128 facet_sse2_getexp(__m128 x)
{
    __m128i e = _mm_srli_epi32(_mm_castps_si128(x), 23);
    return _mm_cvtepi32_ps(_mm_sub_epi32(e, _mm_set1_epi32(127)));
}
FACET_INLINE __m128 facet_sse2_getmant(__m128 x)
{
    __m128i m = _mm_and_si128(_mm_castps_si128(x), _mm_set1_epi32(0x007fffff));
    return _mm_castsi128_ps(_mm_or_si128(m, _mm_set1_epi32(0x3f800000)));
}

#define FACET_V __m128
#define FACET_PORT_NAME sse2
#define FACET_BODY_SAMPLES 0
#include "facet/detail/f32_tiers.h"

#endif

/* ---- sampling ops and the samplers (see facet/scalar.h) ------------------- */
#ifndef FACET_SSE2_SAMPLE_H
#define FACET_SSE2_SAMPLE_H


#define FACET_V __m128
#define FACET_PORT_NAME sse2
#define FACET_BODY_SAMPLES 1
#include "facet/detail/f32_tiers.h"

#endif
