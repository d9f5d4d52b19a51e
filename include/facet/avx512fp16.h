/* facet/avx512fp16.h - the AVX-512 FP16 binary16 port: every f16 kernel as
 * a static inline function on __m512h (32 binary16 lanes), named
 * facet_<kernel>_f16_avx512fp16.  Contracts: facet/f16.h; the same bounds
 * hold in every lane.  Compile with -mavx512fp16 -mavx512bw -mavx512vl
 * -mavx512f (gcc 12, clang 14), and run it only where the CPU has AVX-512
 * FP16 (facet_f16_port_supported("avx512fp16")).
 *
 * Binary16 ops: vaddph, vmulph, vfmadd...ph, vminph/vmaxph, vcmpph into
 * mask registers.  Reciprocal and rsqrt: vrcpph / vrsqrtph (relative error
 * < 2^-11 + 2^-14 by the architecture: Intel SDM, VRCPPH and VRSQRTPH; the
 * Intrinsics Guide says 1.5 * 2^-12) and one Newton step each in binary16,
 * which takes it to 2^-21 before the step's own rounding; quotients
 * a rcp(b), roots x rsqrt(x).  Checked with this CPU's estimates and with
 * estimates at the bound (FACET_AVX512FP16_TEST_WORST_ESTIMATES).  The f32 lanes (FACET_W: two __m512, the low and the high 16
 * lanes) use vcvtph2psx / vcvtps2phx and the AVX-512F estimates
 * vrcp14ps / vrsqrt14ps (2^-14) unrefined: what they feed is narrowed to
 * binary16 (2^-11) afterwards. */
#ifndef FACET_AVX512FP16_H
#define FACET_AVX512FP16_H

#if !defined(__AVX512FP16__) || !defined(__AVX512BW__) || !defined(__AVX512VL__)
#error "facet/avx512fp16.h needs AVX-512 FP16, BW and VL (-mavx512fp16 -mavx512bw -mavx512vl)"
#endif
#include <immintrin.h>
#include <stddef.h>
#include <stdint.h>
#include "facet/common.h"
#include "facet/f16.h"

/* a binary16 constant (__extension__: _Float16 is not ISO C, and the
 * header compiles under -pedantic) */
#define FACET_AVX512FP16_C_(x) _mm512_set1_ph(__extension__ FACET_CAST(_Float16, (x)))

typedef struct facet_avx512fp16_w {
    __m512 lo, hi;
} facet_avx512fp16_w;

FACET_INLINE __m512h facet_avx512fp16_h_set(float x) { return FACET_AVX512FP16_C_(x); }
FACET_INLINE __m512h facet_avx512fp16_h_add(__m512h a, __m512h b) { return _mm512_add_ph(a, b); }
FACET_INLINE __m512h facet_avx512fp16_h_sub(__m512h a, __m512h b) { return _mm512_sub_ph(a, b); }
FACET_INLINE __m512h facet_avx512fp16_h_mul(__m512h a, __m512h b) { return _mm512_mul_ph(a, b); }
FACET_INLINE __m512h facet_avx512fp16_h_fma(__m512h a, __m512h b, __m512h c) { return _mm512_fmadd_ph(a, b, c); }
FACET_INLINE __m512h facet_avx512fp16_h_fnma(__m512h a, __m512h b, __m512h c) { return _mm512_fnmadd_ph(a, b, c); }
FACET_INLINE __m512h facet_avx512fp16_h_min(__m512h a, __m512h b) { return _mm512_min_ph(a, b); }
FACET_INLINE __m512h facet_avx512fp16_h_max(__m512h a, __m512h b) { return _mm512_max_ph(a, b); }
/* vmaxph returns the second operand when either is NaN: NaN -> lo */
FACET_INLINE __m512h facet_avx512fp16_h_clamp(__m512h x, __m512h lo, __m512h hi)
{
    return _mm512_min_ph(_mm512_max_ph(x, lo), hi);
}
FACET_INLINE __m512h facet_avx512fp16_h_keep_ord(__m512h r, __m512h a, __m512h b)
{
    return _mm512_mask_blend_ph(_mm512_cmp_ph_mask(a, b, _CMP_ORD_Q), _mm512_setzero_ph(), r);
}
FACET_INLINE __m512h facet_avx512fp16_h_keep_ord4(__m512h r, __m512h a, __m512h b, __m512h c, __m512h d)
{
    return _mm512_mask_blend_ph(_mm512_mask_cmp_ph_mask(_mm512_cmp_ph_mask(a, b, _CMP_ORD_Q), c, d, _CMP_ORD_Q),
                                _mm512_setzero_ph(), r);
}
#ifdef FACET_AVX512FP16_TEST_WORST_ESTIMATES
/* Test builds only (tests/suites/15-worst-estimates.sh): per lane the
 * binary16 value farthest from the exact 1/x (rs = 0) or 1/sqrt(x) (rs = 1)
 * whose relative error is still below the SDM's bound 2^-11 + 2^-14: the
 * nearest one, or one or two steps of the last bit away from it, on the
 * side bit 2 of x picks (so that it varies).  x: 16 positive normals. */
FACET_INLINE __m256h facet_avx512fp16_worst16_(__m256h x, int rs)
{
    const __m512 one = _mm512_set1_ps(1.0f), bound = _mm512_set1_ps(5.4931640625e-04f); /* 2^-11 + 2^-14 */
    __m512 xf = _mm512_cvtxph_ps(x), root = _mm512_sqrt_ps(xf);
    __m512 exact = _mm512_div_ps(one, rs ? root : xf), scale = rs ? root : xf;
    __m256i xb = _mm256_castph_si256(x), r0 = _mm256_castph_si256(_mm512_cvtxps_ph(exact));
    __m256i s = _mm256_sub_epi16(_mm256_slli_epi16(_mm256_and_si256(_mm256_srli_epi16(xb, 2), _mm256_set1_epi16(1)), 1),
                                 _mm256_set1_epi16(1));
    __m256i r1 = _mm256_add_epi16(r0, s), r2 = _mm256_add_epi16(r1, s);
    __m512 e1 = _mm512_abs_ps(_mm512_fmsub_ps(_mm512_cvtxph_ps(_mm256_castsi256_ph(r1)), scale, one));
    __m512 e2 = _mm512_abs_ps(_mm512_fmsub_ps(_mm512_cvtxph_ps(_mm256_castsi256_ph(r2)), scale, one));
    __m256i r = _mm256_mask_blend_epi16(_mm512_cmp_ps_mask(e1, bound, _CMP_LT_OQ), r0, r1);
    return _mm256_castsi256_ph(_mm256_mask_blend_epi16(_mm512_cmp_ps_mask(e2, bound, _CMP_LT_OQ), r, r2));
}
FACET_INLINE __m512h facet_avx512fp16_worst_(__m512h x, int rs)
{
    __m512i b = _mm512_castph_si512(x);
    __m256i lo = _mm256_castph_si256(facet_avx512fp16_worst16_(_mm256_castsi256_ph(_mm512_castsi512_si256(b)), rs));
    __m256i hi = _mm256_castph_si256(facet_avx512fp16_worst16_(_mm256_castsi256_ph(_mm512_extracti64x4_epi64(b, 1)), rs));
    return _mm512_castsi512_ph(_mm512_inserti64x4(_mm512_castsi256_si512(lo), hi, 1));
}
#define facet_avx512fp16_rcp_est_(x) facet_avx512fp16_worst_((x), 0)
#define facet_avx512fp16_rsqrt_est_(x) facet_avx512fp16_worst_((x), 1)
#else
#define facet_avx512fp16_rcp_est_(x) _mm512_rcp_ph(x)
#define facet_avx512fp16_rsqrt_est_(x) _mm512_rsqrt_ph(x)
#endif
FACET_INLINE __m512h facet_avx512fp16_h_rcp(__m512h x)
{
    __m512h r = facet_avx512fp16_rcp_est_(x);
    return _mm512_fmadd_ph(r, _mm512_fnmadd_ph(x, r, FACET_AVX512FP16_C_(1.0f)), r);
}
FACET_INLINE __m512h facet_avx512fp16_h_rsqrt(__m512h x)
{
    __m512h y = facet_avx512fp16_rsqrt_est_(x);
    __m512h e = _mm512_fnmadd_ph(_mm512_mul_ph(x, y), y, FACET_AVX512FP16_C_(1.0f));
    return _mm512_fmadd_ph(_mm512_mul_ph(FACET_AVX512FP16_C_(0.5f), y), e, y);
}
FACET_INLINE __m512h facet_avx512fp16_h_div(__m512h a, __m512h b) { return _mm512_mul_ph(a, facet_avx512fp16_h_rcp(b)); }
FACET_INLINE __m512h facet_avx512fp16_h_sqrt(__m512h x) { return _mm512_mul_ph(x, facet_avx512fp16_h_rsqrt(x)); }

/* ---- the f32 lanes ---- */
FACET_INLINE facet_avx512fp16_w facet_avx512fp16_h_w_set(float x)
{
    facet_avx512fp16_w r;
    r.lo = r.hi = _mm512_set1_ps(x);
    return r;
}
#define FACET_AVX512FP16_W_BIN_(name, f)                                                       \
    FACET_INLINE facet_avx512fp16_w facet_avx512fp16_h_w_##name(facet_avx512fp16_w a, facet_avx512fp16_w b) \
    {                                                                                          \
        facet_avx512fp16_w r;                                                                  \
        r.lo = f(a.lo, b.lo);                                                                  \
        r.hi = f(a.hi, b.hi);                                                                  \
        return r;                                                                              \
    }
#define FACET_AVX512FP16_W_TRI_(name, f)                                                       \
    FACET_INLINE facet_avx512fp16_w facet_avx512fp16_h_w_##name(facet_avx512fp16_w a, facet_avx512fp16_w b, \
                                                                facet_avx512fp16_w c)          \
    {                                                                                          \
        facet_avx512fp16_w r;                                                                  \
        r.lo = f(a.lo, b.lo, c.lo);                                                            \
        r.hi = f(a.hi, b.hi, c.hi);                                                            \
        return r;                                                                              \
    }
#define FACET_AVX512FP16_W_UN_(name, f)                                                        \
    FACET_INLINE facet_avx512fp16_w facet_avx512fp16_h_w_##name(facet_avx512fp16_w a)         \
    {                                                                                          \
        facet_avx512fp16_w r;                                                                  \
        r.lo = f(a.lo);                                                                        \
        r.hi = f(a.hi);                                                                        \
        return r;                                                                              \
    }
FACET_AVX512FP16_W_BIN_(add, _mm512_add_ps)
FACET_AVX512FP16_W_BIN_(sub, _mm512_sub_ps)
FACET_AVX512FP16_W_BIN_(mul, _mm512_mul_ps)
FACET_AVX512FP16_W_BIN_(min, _mm512_min_ps)
FACET_AVX512FP16_W_BIN_(max, _mm512_max_ps)
FACET_AVX512FP16_W_TRI_(fma, _mm512_fmadd_ps)
FACET_AVX512FP16_W_TRI_(fnma, _mm512_fnmadd_ps)
FACET_AVX512FP16_W_UN_(rcp, _mm512_rcp14_ps)
FACET_AVX512FP16_W_UN_(rsqrt, _mm512_rsqrt14_ps)
FACET_INLINE facet_avx512fp16_w facet_avx512fp16_h_w_sqr_err(facet_avx512fp16_w a, facet_avx512fp16_w p)
{
    facet_avx512fp16_w r;
    r.lo = _mm512_fmsub_ps(a.lo, a.lo, p.lo);
    r.hi = _mm512_fmsub_ps(a.hi, a.hi, p.hi);
    return r;
}
#undef FACET_AVX512FP16_W_BIN_
#undef FACET_AVX512FP16_W_TRI_
#undef FACET_AVX512FP16_W_UN_
FACET_INLINE facet_avx512fp16_w facet_avx512fp16_h_widen(__m512h v)
{
    facet_avx512fp16_w r;
    __m512i b = _mm512_castph_si512(v);
    r.lo = _mm512_cvtxph_ps(_mm256_castsi256_ph(_mm512_castsi512_si256(b)));
    r.hi = _mm512_cvtxph_ps(_mm256_castsi256_ph(_mm512_extracti64x4_epi64(b, 1)));
    return r;
}
/* min(x, 65504) rounded to binary16 (vcvtps2phx: the MXCSR rounding, to
 * nearest even) */
FACET_INLINE __m512h facet_avx512fp16_h_narrow(facet_avx512fp16_w x)
{
    __m512 m = _mm512_set1_ps(65504.0f);
    __m256i lo = _mm256_castph_si256(_mm512_cvtxps_ph(_mm512_min_ps(x.lo, m)));
    __m256i hi = _mm256_castph_si256(_mm512_cvtxps_ph(_mm512_min_ps(x.hi, m)));
    return _mm512_castsi512_ph(_mm512_inserti64x4(_mm512_castsi256_si512(lo), hi, 1));
}

/* Tails: facet_avx512fp16_load_n(p, r) loads r binary16 values
 * (0 <= r <= 32) into the first r lanes and 0.5 into the others, reading
 * nothing past p + r; facet_avx512fp16_store_n(p, v, r) stores the first r
 * lanes.  Masked (AVX-512 BW), no stack copy. */
FACET_INLINE __mmask32 facet_avx512fp16_mask_(size_t r)
{
    return FACET_CAST(__mmask32, r >= 32 ? 0xffffffffu : (1u << r) - 1u);
}
FACET_INLINE __m512h facet_avx512fp16_load(const uint16_t *p) { return _mm512_castsi512_ph(_mm512_loadu_si512(p)); }
FACET_INLINE void facet_avx512fp16_store(uint16_t *p, __m512h v) { _mm512_storeu_si512(p, _mm512_castph_si512(v)); }
FACET_INLINE __m512h facet_avx512fp16_load_n(const uint16_t *p, size_t r)
{
    return _mm512_castsi512_ph(_mm512_mask_loadu_epi16(_mm512_set1_epi16(0x3800), facet_avx512fp16_mask_(r), p));
}
FACET_INLINE void facet_avx512fp16_store_n(uint16_t *p, __m512h v, size_t r)
{
    _mm512_mask_storeu_epi16(p, facet_avx512fp16_mask_(r), _mm512_castph_si512(v));
}

#define FACET_V __m512h
#define FACET_W facet_avx512fp16_w
#define FACET_OP(op) facet_avx512fp16_h_##op
#define FACET_K(k) facet_##k##_f16_avx512fp16
#include "facet/detail/f16_body.h"
#undef FACET_V
#undef FACET_W
#undef FACET_OP
#undef FACET_K

#endif
