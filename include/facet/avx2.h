/* facet/avx2.h - the AVX2 + FMA f32 port: every kernel as a static inline
 * function on __m256 (8 lanes), named facet_<kernel>_f32_avx2.  Contracts:
 * facet.h; the same bounds hold in every lane.
 *
 * Reciprocal and rsqrt: vrcpps / vrsqrtps (relative error <= 1.5 * 2^-12
 * on every x86 vendor, so Intel's and AMD's different tables are both
 * covered) refined by one third-order step each (below), which leaves only
 * rounding.  Checked with this CPU's estimates and with estimates emulated
 * at the architectural bound (FACET_AVX2_TEST_WORST_ESTIMATES,
 * tests/suites/15-worst-estimates.sh). */
#ifndef FACET_AVX2_H
#define FACET_AVX2_H

#if !defined(__AVX2__) || !defined(__FMA__)
#error "facet/avx2.h needs AVX2 and FMA (-mavx2 -mfma)"
#endif
#include <immintrin.h>
#include <stddef.h>
#include "facet/common.h"

FACET_INLINE __m256 facet_avx2_set(float x) { return _mm256_set1_ps(x); }
FACET_INLINE __m256 facet_avx2_add(__m256 a, __m256 b) { return _mm256_add_ps(a, b); }
FACET_INLINE __m256 facet_avx2_sub(__m256 a, __m256 b) { return _mm256_sub_ps(a, b); }
FACET_INLINE __m256 facet_avx2_mul(__m256 a, __m256 b) { return _mm256_mul_ps(a, b); }
FACET_INLINE __m256 facet_avx2_fma(__m256 a, __m256 b, __m256 c) { return _mm256_fmadd_ps(a, b, c); }
FACET_INLINE __m256 facet_avx2_fnma(__m256 a, __m256 b, __m256 c) { return _mm256_fnmadd_ps(a, b, c); }
FACET_INLINE __m256 facet_avx2_min(__m256 a, __m256 b) { return _mm256_min_ps(a, b); }
FACET_INLINE __m256 facet_avx2_max(__m256 a, __m256 b) { return _mm256_max_ps(a, b); }
FACET_INLINE __m256 facet_avx2_sel_lt(__m256 a, __m256 b, __m256 x, __m256 y)
{
    return _mm256_blendv_ps(y, x, _mm256_cmp_ps(a, b, _CMP_LT_OQ));
}
/* vmaxps returns the second operand when either is NaN: NaN -> lo. */
FACET_INLINE __m256 facet_avx2_clamp(__m256 x, __m256 lo, __m256 hi)
{
    return _mm256_min_ps(_mm256_max_ps(x, lo), hi);
}
/* r where neither a nor b is NaN, else +0: one ordered compare and a mask */
FACET_INLINE __m256 facet_avx2_keep_ord(__m256 r, __m256 a, __m256 b)
{
    return _mm256_and_ps(r, _mm256_cmp_ps(a, b, _CMP_ORD_Q));
}
FACET_INLINE __m256 facet_avx2_keep_ord4(__m256 r, __m256 a, __m256 b, __m256 c, __m256 d)
{
    return _mm256_and_ps(r, _mm256_and_ps(_mm256_cmp_ps(a, b, _CMP_ORD_Q), _mm256_cmp_ps(c, d, _CMP_ORD_Q)));
}
#ifdef FACET_AVX2_TEST_WORST_ESTIMATES
/* Test builds only: estimates off by exactly the architectural bound
 * 1.5 * 2^-12, the sign taken from bit 12 of x so that it varies. */
FACET_INLINE __m256 facet_avx2_worst_(__m256 exact, __m256 x)
{
    __m256i b = _mm256_slli_epi32(_mm256_srli_epi32(_mm256_castps_si256(x), 12), 31);
    __m256 d = _mm256_xor_ps(_mm256_set1_ps(1.5f / 4096.0f), _mm256_castsi256_ps(b));
    return _mm256_fmadd_ps(exact, d, exact);
}
#define facet_avx2_rcp_est_(x) facet_avx2_worst_(_mm256_div_ps(_mm256_set1_ps(1.0f), (x)), (x))
#define facet_avx2_rsqrt_est_(x) \
    facet_avx2_worst_(_mm256_div_ps(_mm256_set1_ps(1.0f), _mm256_sqrt_ps(x)), (x))
#else
#define facet_avx2_rcp_est_(x) _mm256_rcp_ps(x)
#define facet_avx2_rsqrt_est_(x) _mm256_rsqrt_ps(x)
#endif

/* 1/x: estimate r, e = 1 - x r, then r (1 + e + e^2): the third-order step
 * (one fma more than Newton's r (1 + e)) takes any estimate within the
 * architectural bound |e| <= 1.5 * 2^-12 to |e|^3 < 5e-11, so only the
 * step's own rounding (<= 1 ulp) remains. */
FACET_INLINE __m256 facet_avx2_rcp(__m256 x)
{
    __m256 r = facet_avx2_rcp_est_(x);
    __m256 e = _mm256_fnmadd_ps(x, r, _mm256_set1_ps(1.0f));
    return _mm256_fmadd_ps(_mm256_fmadd_ps(e, e, e), r, r);
}
/* 1/sqrt(x): estimate y, e = 1 - x y^2, then y (1 + e/2 + 3e^2/8) (the
 * series of (1 - e)^-1/2 to second order): error (5/16)|e|^3 < 2e-11. */
FACET_INLINE __m256 facet_avx2_rsqrt(__m256 x)
{
    __m256 y = facet_avx2_rsqrt_est_(x);
    __m256 e = _mm256_fnmadd_ps(_mm256_mul_ps(x, y), y, _mm256_set1_ps(1.0f));
    __m256 p = _mm256_fmadd_ps(e, _mm256_set1_ps(0.375f), _mm256_set1_ps(0.5f));
    return _mm256_fmadd_ps(_mm256_mul_ps(e, p), y, y);
}
FACET_INLINE __m256 facet_avx2_sqr_err(__m256 a, __m256 p) { return _mm256_fmsub_ps(a, a, p); }
/* c - a*a, one rounding of the exact value (the kernels' exact peak) */
FACET_INLINE __m256 facet_avx2_sqr_sub(__m256 a, __m256 c) { return _mm256_fnmadd_ps(a, a, c); }

/* The fast tier (f32_fast): the estimates and one Newton step each
 * (r + r e; y + y e / 2), leaving about 1.5 e^2 < 2^-21 of an estimate at
 * the architectural bound, plus the step's rounding. */
FACET_INLINE __m256 facet_avx2_rcp_fast(__m256 x)
{
    __m256 r = facet_avx2_rcp_est_(x);
    return _mm256_fmadd_ps(r, _mm256_fnmadd_ps(x, r, _mm256_set1_ps(1.0f)), r);
}
FACET_INLINE __m256 facet_avx2_rsqrt_fast(__m256 x)
{
    __m256 y = facet_avx2_rsqrt_est_(x);
    __m256 e = _mm256_fnmadd_ps(_mm256_mul_ps(x, y), y, _mm256_set1_ps(1.0f));
    return _mm256_fmadd_ps(_mm256_mul_ps(_mm256_set1_ps(0.5f), y), e, y);
}
/* a / b and sqrt(x) (b, x positive and normal): vdivps and vsqrtps in both
 * tiers, correctly rounded.  One instruction each on the divide/sqrt unit,
 * which runs beside the FMA and add pipes, where the estimate and its step
 * take three or four FMA-pipe operations plus the multiply. */
FACET_INLINE __m256 facet_avx2_div(__m256 a, __m256 b) { return _mm256_div_ps(a, b); }
FACET_INLINE __m256 facet_avx2_div_fast(__m256 a, __m256 b) { return _mm256_div_ps(a, b); }
FACET_INLINE __m256 facet_avx2_sqrt(__m256 x) { return _mm256_sqrt_ps(x); }
FACET_INLINE __m256 facet_avx2_sqrt_fast(__m256 x) { return _mm256_sqrt_ps(x); }

/* Tails, so that a loop over any n needs no padding by the caller:
 * facet_avx2_load_n(p, r) loads r floats (0 <= r <= 8) from p into the first
 * r lanes and 0.5 (inside every kernel's domain) into the others, reading
 * nothing past p + r; facet_avx2_store_n(p, v, r) stores the first r lanes,
 * writing nothing else.  Masked (vmaskmovps): no stack copy.  The loop:
 *     for (i = 0; i + 8 <= n; i += 8)
 *         store(out + i, kernel(load(x + i), ...));
 *     if (i < n)
 *         facet_avx2_store_n(out + i, kernel(facet_avx2_load_n(x + i, n - i), ...), n - i);
 * All loads of a block come before its store, so out may be one of the
 * inputs.  Tested at every n mod 8 (tests/f32/test_tails.c). */
FACET_INLINE __m256i facet_avx2_mask_n_(size_t r)
{
    return _mm256_cmpgt_epi32(_mm256_set1_epi32(FACET_CAST(int, r)), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
}
FACET_INLINE __m256 facet_avx2_load_n(const float *p, size_t r)
{
    __m256i m = facet_avx2_mask_n_(r);
    return _mm256_blendv_ps(_mm256_set1_ps(0.5f), _mm256_maskload_ps(p, m), _mm256_castsi256_ps(m));
}
FACET_INLINE void facet_avx2_store_n(float *p, __m256 v, size_t r)
{
    _mm256_maskstore_ps(p, facet_avx2_mask_n_(r), v);
}

/* Exponent-bit ops (exp2/log2 of f32_body.h and the samplers):
 *   exp2i(k)    2^k for an integral-valued k in [-126, 127] (exponent bits)
 *   getexp(x)   floor(log2 x) as a float, x positive and normal
 *   getmant(x)  x / 2^getexp(x), in [1, 2) */
FACET_INLINE __m256 facet_avx2_exp2i(__m256 k)
{
    __m256i e = _mm256_add_epi32(_mm256_cvttps_epi32(k), _mm256_set1_epi32(127));
    return _mm256_castsi256_ps(_mm256_slli_epi32(e, 23));
}
FACET_INLINE __m256 facet_avx2_getexp(__m256 x)
{
    __m256i e = _mm256_srli_epi32(_mm256_castps_si256(x), 23);
    return _mm256_cvtepi32_ps(_mm256_sub_epi32(e, _mm256_set1_epi32(127)));
}
FACET_INLINE __m256 facet_avx2_getmant(__m256 x)
{
    __m256i m = _mm256_and_si256(_mm256_castps_si256(x), _mm256_set1_epi32(0x007fffff));
    return _mm256_castsi256_ps(_mm256_or_si256(m, _mm256_set1_epi32(0x3f800000)));
}

#define FACET_V __m256
#define FACET_PORT_NAME avx2
#define FACET_BODY_SAMPLES 0
#include "facet/detail/f32_tiers.h"

#endif

/* ---- sampling ops and the samplers (see facet/scalar.h) ------------------- */
#ifndef FACET_AVX2_SAMPLE_H
#define FACET_AVX2_SAMPLE_H


#define FACET_V __m256
#define FACET_PORT_NAME avx2
#define FACET_BODY_SAMPLES 1
#include "facet/detail/f32_tiers.h"

#endif
