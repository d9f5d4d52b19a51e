/* facet/avx512.h - the AVX-512F f32 port: every kernel as a static inline
 * function on __m512 (16 lanes), named facet_<kernel>_f32_avx512.
 * Contracts: facet.h; the same bounds hold in every lane.
 *
 * Reciprocal and rsqrt: vrcp14ps / vrsqrt14ps (relative error < 2^-14 by
 * the architecture) plus one Newton step each, fused: 2^-14 -> 2^-28 for
 * rcp and 1.5 * 2^-28 for rsqrt, i.e. only the step's rounding remains.
 * Checked with this CPU's estimates and with estimates emulated at the
 * architectural bound (FACET_AVX512_TEST_WORST_ESTIMATES). */
#ifndef FACET_AVX512_H
#define FACET_AVX512_H

#if !defined(__AVX512F__)
#error "facet/avx512.h needs AVX-512F (-mavx512f)"
#endif
#include <immintrin.h>
#include <stddef.h>
#include "facet/common.h"

FACET_INLINE __m512 facet_avx512_set(float x) { return _mm512_set1_ps(x); }
FACET_INLINE __m512 facet_avx512_add(__m512 a, __m512 b) { return _mm512_add_ps(a, b); }
FACET_INLINE __m512 facet_avx512_sub(__m512 a, __m512 b) { return _mm512_sub_ps(a, b); }
FACET_INLINE __m512 facet_avx512_mul(__m512 a, __m512 b) { return _mm512_mul_ps(a, b); }
FACET_INLINE __m512 facet_avx512_fma(__m512 a, __m512 b, __m512 c) { return _mm512_fmadd_ps(a, b, c); }
FACET_INLINE __m512 facet_avx512_fnma(__m512 a, __m512 b, __m512 c) { return _mm512_fnmadd_ps(a, b, c); }
FACET_INLINE __m512 facet_avx512_min(__m512 a, __m512 b) { return _mm512_min_ps(a, b); }
FACET_INLINE __m512 facet_avx512_max(__m512 a, __m512 b) { return _mm512_max_ps(a, b); }
FACET_INLINE __m512 facet_avx512_sel_lt(__m512 a, __m512 b, __m512 x, __m512 y)
{
    return _mm512_mask_blend_ps(_mm512_cmp_ps_mask(a, b, _CMP_LT_OQ), y, x);
}
/* vmaxps returns the second operand when either is NaN: NaN -> lo. */
FACET_INLINE __m512 facet_avx512_clamp(__m512 x, __m512 lo, __m512 hi)
{
    return _mm512_min_ps(_mm512_max_ps(x, lo), hi);
}
/* r where neither a nor b is NaN, else +0: an ordered compare into a mask
 * register and a zero-masked move */
FACET_INLINE __m512 facet_avx512_keep_ord(__m512 r, __m512 a, __m512 b)
{
    return _mm512_maskz_mov_ps(_mm512_cmp_ps_mask(a, b, _CMP_ORD_Q), r);
}
/* four inputs: the second compare under the first one's mask (the AND for
 * free), one zero-masked move */
FACET_INLINE __m512 facet_avx512_keep_ord4(__m512 r, __m512 a, __m512 b, __m512 c, __m512 d)
{
    return _mm512_maskz_mov_ps(_mm512_mask_cmp_ps_mask(_mm512_cmp_ps_mask(a, b, _CMP_ORD_Q), c, d, _CMP_ORD_Q), r);
}

#ifdef FACET_AVX512_TEST_WORST_ESTIMATES
/* Test builds only: estimates off by just under the architectural bound
 * 2^-14, the sign taken from bit 12 of x so that it varies. */
FACET_INLINE __m512 facet_avx512_worst_(__m512 exact, __m512 x)
{
    __m512i b = _mm512_slli_epi32(_mm512_srli_epi32(_mm512_castps_si512(x), 12), 31);
    __m512 d = _mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(_mm512_set1_ps(0.99f / 16384.0f)), b));
    return _mm512_fmadd_ps(exact, d, exact);
}
#define facet_avx512_rcp_est_(x) facet_avx512_worst_(_mm512_div_ps(_mm512_set1_ps(1.0f), (x)), (x))
#define facet_avx512_rsqrt_est_(x) \
    facet_avx512_worst_(_mm512_div_ps(_mm512_set1_ps(1.0f), _mm512_sqrt_ps(x)), (x))
#else
#define facet_avx512_rcp_est_(x) _mm512_rcp14_ps(x)
#define facet_avx512_rsqrt_est_(x) _mm512_rsqrt14_ps(x)
#endif

FACET_INLINE __m512 facet_avx512_rcp(__m512 x)
{
    __m512 r = facet_avx512_rcp_est_(x);
    return _mm512_fmadd_ps(r, _mm512_fnmadd_ps(x, r, _mm512_set1_ps(1.0f)), r);
}
FACET_INLINE __m512 facet_avx512_rsqrt(__m512 x)
{
    __m512 y = facet_avx512_rsqrt_est_(x);
    __m512 e = _mm512_fnmadd_ps(_mm512_mul_ps(x, y), y, _mm512_set1_ps(1.0f));
    return _mm512_fmadd_ps(_mm512_mul_ps(_mm512_set1_ps(0.5f), y), e, y);
}
FACET_INLINE __m512 facet_avx512_sqr_err(__m512 a, __m512 p) { return _mm512_fmsub_ps(a, a, p); }
/* c - a*a, one rounding of the exact value (the kernels' exact peak) */
FACET_INLINE __m512 facet_avx512_sqr_sub(__m512 a, __m512 c) { return _mm512_fnmadd_ps(a, a, c); }

/* The fast tier (f32_fast): the 14-bit estimates as they are (relative
 * error < 2^-14 each). */
FACET_INLINE __m512 facet_avx512_rcp_fast(__m512 x) { return facet_avx512_rcp_est_(x); }
FACET_INLINE __m512 facet_avx512_rsqrt_fast(__m512 x) { return facet_avx512_rsqrt_est_(x); }
/* a / b and sqrt(x) (b, x positive and normal): vdivps and vsqrtps,
 * correctly rounded, on the divide/sqrt unit beside the FMA and add pipes
 * (measured on Zen 5: one vdivps per 2.5 cycles beside two FMAs per cycle;
 * cheaper there than the estimate, its step and the multiply, so the fast
 * tier divides too).  The fast tier's root is x times the raw 14-bit rsqrt
 * estimate (relative error < 2^-14 + 1 rounding): vsqrtps's latency sits on
 * the Fresnel tail's chain. */
FACET_INLINE __m512 facet_avx512_div(__m512 a, __m512 b) { return _mm512_div_ps(a, b); }
FACET_INLINE __m512 facet_avx512_div_fast(__m512 a, __m512 b) { return _mm512_div_ps(a, b); }
FACET_INLINE __m512 facet_avx512_sqrt(__m512 x) { return _mm512_sqrt_ps(x); }
FACET_INLINE __m512 facet_avx512_sqrt_fast(__m512 x) { return _mm512_mul_ps(x, facet_avx512_rsqrt_est_(x)); }

/* Tails, so that a loop over any n needs no padding by the caller:
 * facet_avx512_load_n(p, r) loads r floats (0 <= r <= 16) from p into the first
 * r lanes and 0.5 (inside every kernel's domain) into the others, reading
 * nothing past p + r; facet_avx512_store_n(p, v, r) stores the first r lanes,
 * writing nothing else.  Masked (AVX-512 mask registers): no stack copy.  The loop:
 *     for (i = 0; i + 16 <= n; i += 16)
 *         store(out + i, kernel(load(x + i), ...));
 *     if (i < n)
 *         facet_avx512_store_n(out + i, kernel(facet_avx512_load_n(x + i, n - i), ...), n - i);
 * All loads of a block come before its store, so out may be one of the
 * inputs.  Tested at every n mod 16 (tests/f32/test_tails.c). */
FACET_INLINE __m512 facet_avx512_load_n(const float *p, size_t r)
{
    return _mm512_mask_loadu_ps(_mm512_set1_ps(0.5f), FACET_CAST(__mmask16, (1u << r) - 1u), p);
}
FACET_INLINE void facet_avx512_store_n(float *p, __m512 v, size_t r)
{
    _mm512_mask_storeu_ps(p, FACET_CAST(__mmask16, (1u << r) - 1u), v);
}

/* Exponent-bit ops (exp2/log2 of f32_body.h and the samplers):
 *   exp2i(k)    2^k for an integral-valued k in [-126, 127] (exponent bits)
 *   getexp(x)   floor(log2 x) as a float, x positive and normal
 *   getmant(x)  x / 2^getexp(x), in [1, 2) */
FACET_INLINE __m512 facet_avx512_exp2i(__m512 k)
{
    __m512i e = _mm512_add_epi32(_mm512_cvttps_epi32(k), _mm512_set1_epi32(127));
    return _mm512_castsi512_ps(_mm512_slli_epi32(e, 23));
}
FACET_INLINE __m512 facet_avx512_getexp(__m512 x)
{
    __m512i e = _mm512_srli_epi32(_mm512_castps_si512(x), 23);
    return _mm512_cvtepi32_ps(_mm512_sub_epi32(e, _mm512_set1_epi32(127)));
}
FACET_INLINE __m512 facet_avx512_getmant(__m512 x)
{
    __m512i m = _mm512_and_si512(_mm512_castps_si512(x), _mm512_set1_epi32(0x007fffff));
    return _mm512_castsi512_ps(_mm512_or_si512(m, _mm512_set1_epi32(0x3f800000)));
}

#define FACET_V __m512
#define FACET_PORT_NAME avx512
#define FACET_BODY_SAMPLES 0
#include "facet/detail/f32_tiers.h"

#endif

/* ---- sampling ops and the samplers (see facet/scalar.h) ------------------- */
#ifndef FACET_AVX512_SAMPLE_H
#define FACET_AVX512_SAMPLE_H


#define FACET_V __m512
#define FACET_PORT_NAME avx512
#define FACET_BODY_SAMPLES 1
#include "facet/detail/f32_tiers.h"

#endif
