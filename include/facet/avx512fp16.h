/* facet/avx512fp16.h - the AVX-512 FP16 binary16 port: every f16 kernel as
 * a static inline function on __m512h (32 binary16 lanes), named
 * facet_<kernel>_f16_avx512fp16.  Contracts: facet/f16.h; the same bounds
 * hold in every lane.  Compile with -mavx512fp16 -mavx512bw -mavx512vl
 * -mavx512f (gcc 12, clang 14), and run it only where the CPU has AVX-512
 * FP16 (facet_f16_port_supported("avx512fp16")).
 *
 * Binary16 ops: vaddph, vmulph, vfmadd...ph, vminph/vmaxph, vcmpph into
 * mask registers.  Reciprocal and rsqrt: vrcpph / vrsqrtph unrefined.  The
 * SDM bounds their relative error by 2^-11 + 2^-14 (the intrinsics guide's
 * 1.5 * 2^-12 is not what this Xeon returns: over every normal binary16
 * input its largest errors are 1.03 * 2^-11 and 1.00 * 2^-11, 91% and 98%
 * of results correctly rounded), barely above a correctly rounded result's
 * 2^-11, which a Newton step in binary16 would leave anyway (its own
 * rounding) at 2 (rcp) and 4 (rsqrt) more operations;
 * FACET_AVX512FP16_TEST_WORST_ESTIMATES (tests/suites/15-worst-estimates.sh)
 * replaces them by the binary16 values farthest from the exact ones within
 * the SDM bound, and the bounds of facet/f16.h hold for those too.
 * Quotients a rcp(b), roots x rsqrt(x); vdivph and vsqrtph are correctly
 * rounded but measured 24 and 34 TSC ticks per zmm here (vdivps: 9), so
 * they are not used.  The f32 lanes (FACET_W: two __m512, the low and the
 * high 16 lanes) use vcvtph2psx / vcvtps2phx and the AVX-512F estimates
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
/* Test builds only (tests/suites/15-worst-estimates.sh): each estimate the
 * binary16 neighbour of the exact value farthest from it within just under
 * the architectural bound 2^-11 + 2^-14 (the other neighbour where the
 * farther one is beyond it); the f32 estimates off by just under 2^-14. */
FACET_INLINE __m256h facet_avx512fp16_worst_half_(__m512 e)
{
    __m256h dn = _mm512_cvtx_roundps_ph(e, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
    __m256h up = _mm512_cvtx_roundps_ph(e, _MM_FROUND_TO_POS_INF | _MM_FROUND_NO_EXC);
    __m512 edn = _mm512_div_ps(_mm512_sub_ps(e, _mm512_cvtxph_ps(dn)), e);
    __m512 eup = _mm512_div_ps(_mm512_sub_ps(_mm512_cvtxph_ps(up), e), e);
    __m512 lim = _mm512_set1_ps(0.99f * (1.0f / 2048.0f + 1.0f / 16384.0f));
    __mmask16 dn_far = _mm512_cmp_ps_mask(edn, eup, _CMP_GT_OQ);
    __mmask16 far_ok = _mm512_cmp_ps_mask(_mm512_max_ps(edn, eup), lim, _CMP_LT_OQ);
    __mmask16 take_dn = (__mmask16)((dn_far & far_ok) | (~dn_far & ~far_ok & 0xffff));
    return _mm256_castsi256_ph(_mm256_mask_blend_epi16(take_dn, _mm256_castph_si256(up), _mm256_castph_si256(dn)));
}
FACET_INLINE __m512h facet_avx512fp16_worst_(__m512h x, int root)
{
    __m512i b = _mm512_castph_si512(x);
    __m512 lo = _mm512_cvtxph_ps(_mm256_castsi256_ph(_mm512_castsi512_si256(b)));
    __m512 hi = _mm512_cvtxph_ps(_mm256_castsi256_ph(_mm512_extracti64x4_epi64(b, 1)));
    __m256i rlo, rhi;
    if (root) {
        lo = _mm512_sqrt_ps(lo);
        hi = _mm512_sqrt_ps(hi);
    }
    rlo = _mm256_castph_si256(facet_avx512fp16_worst_half_(_mm512_div_ps(_mm512_set1_ps(1.0f), lo)));
    rhi = _mm256_castph_si256(facet_avx512fp16_worst_half_(_mm512_div_ps(_mm512_set1_ps(1.0f), hi)));
    return _mm512_castsi512_ph(_mm512_inserti64x4(_mm512_castsi256_si512(rlo), rhi, 1));
}
FACET_INLINE __m512 facet_avx512fp16_worst_w_(__m512 exact, __m512 x)
{
    __m512i s = _mm512_slli_epi32(_mm512_srli_epi32(_mm512_castps_si512(x), 12), 31);
    __m512 d = _mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(_mm512_set1_ps(0.99f / 16384.0f)), s));
    return _mm512_fmadd_ps(exact, d, exact);
}
#define facet_avx512fp16_rcp_est_(x) facet_avx512fp16_worst_((x), 0)
#define facet_avx512fp16_rsqrt_est_(x) facet_avx512fp16_worst_((x), 1)
#define facet_avx512fp16_rcp14_(x) facet_avx512fp16_worst_w_(_mm512_div_ps(_mm512_set1_ps(1.0f), (x)), (x))
#define facet_avx512fp16_rsqrt14_(x) \
    facet_avx512fp16_worst_w_(_mm512_div_ps(_mm512_set1_ps(1.0f), _mm512_sqrt_ps(x)), (x))
#else
#define facet_avx512fp16_rcp_est_(x) _mm512_rcp_ph(x)
#define facet_avx512fp16_rsqrt_est_(x) _mm512_rsqrt_ph(x)
#define facet_avx512fp16_rcp14_(x) _mm512_rcp14_ps(x)
#define facet_avx512fp16_rsqrt14_(x) _mm512_rsqrt14_ps(x)
#endif
FACET_INLINE __m512h facet_avx512fp16_h_rcp(__m512h x) { return facet_avx512fp16_rcp_est_(x); }
FACET_INLINE __m512h facet_avx512fp16_h_rsqrt(__m512h x) { return facet_avx512fp16_rsqrt_est_(x); }
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
FACET_AVX512FP16_W_UN_(rcp, facet_avx512fp16_rcp14_)
FACET_AVX512FP16_W_UN_(rsqrt, facet_avx512fp16_rsqrt14_)
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
/* x rounded to binary16 (vcvtps2phx: the MXCSR rounding, to nearest even;
 * from 65520 on +Inf) */
FACET_INLINE __m512h facet_avx512fp16_h_narrow(facet_avx512fp16_w x)
{
    __m256i lo = _mm256_castph_si256(_mm512_cvtxps_ph(x.lo));
    __m256i hi = _mm256_castph_si256(_mm512_cvtxps_ph(x.hi));
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
