/* fx_avx2.c - the fixed-point lane op layer (src/fx/fx_ops.h) on AVX2: 4
 * lanes, each a uint64_t in a __m256i (vpmuludq for the exact 32x32->64
 * products), int32 inputs clamped as 4 dwords (vpmaxsd / vpminsd) before
 * they are widened; the 64/32 division and the integer root lane by lane
 * (the scalar primitives: x86-64's divq).  Integer instructions only.
 * Bit-identical to the scalar specification (tests/fx/test_fx_ports.c).
 * Dispatched for the avx2 and avx512 ports (src/core/dispatch.c). */
#if !defined(__AVX2__)
#error "fx_avx2.c needs AVX2 (-mavx2): built by ports/avx2/port.mk"
#endif
#include <immintrin.h>
#include <stddef.h>
#include <stdint.h>
#include "../../src/fx/fx_prims.h"

typedef __m128i fxv_i32;
typedef __m256i fxv_u32; /* values below 2^32 in 64-bit lanes */
typedef __m256i fxv_u64;
#define FXV_W 4
#define FXV_STEP 4
#define FXV_PORT_NAME "avx2"
#define FXV_PORT_VAR facet_fx_port_avx2
#define FXV_FAST_PORT_VAR facet_fx_fast_port_avx2
/* Which kernels of each tier run on these lanes; the others run the tier's
 * scalar loop.  Measured (FACET_FX_TIMING=1 tests/fx/test_fx_ports on a
 * -DFACET_FX_ALL_LANES build, 200000-sample batches, rdtsc ratios in one
 * run, AMD EPYC): on lanes where the scalar loop took >= 1.15x the time in
 * each of 3 runs (min ratio in brackets).  Precise: fresnel_schlick (4.3),
 * g_implicit (6.0), g_neumann (7.3), ggx_d (1.7), ggx_aniso_d (1.25),
 * smith_g1 (1.20), smith_g2_uncorrelated (1.32), g_cook_torrance (1.16),
 * brdf_hammon (1.20); not: loh_from_dots 0.77, smith_g1_hammon 0.86,
 * smith_g1_schlick_beckmann 0.79, smith_g2_hammon 0.96, smith_g2 0.97, the
 * rest 1.0 to 1.08 (the division and root lane by lane, 4 divq in a row).
 * Fast: fresnel_schlick (3.2), fresnel_schlick_f90 (3.3), fresnel_schlick_sg
 * (2.1), g_implicit (5.8), g_neumann (6.0), ggx_d (1.30), ggx_aniso_d (1.64),
 * beckmann_d (1.62), gtr_d (1.35), noh_from_dots (1.43), loh_from_dots
 * (1.17), g_cook_torrance (1.31), g_kelemen (1.48), smith_g1_gtr (1.21),
 * diffuse_burley (1.64), diffuse_hammon (1.25), diffuse_hammon_hybrid
 * (1.20), diffuse_hammon_cheap (1.19); not: the Smith and Vis terms 0.29 to
 * 1.12, brdf_hammon 0.87, blinn_phong_d 1.01, diffuse_oren_nayar 1.04,
 * fresnel_cook_torrance 1.08 (the 32-bit stages on 64-bit lanes, the table
 * gathers).  (Before this measurement: Fresnel alone in both tiers.) */
#define FXV_LANES_FX(X) X(fresnel_schlick) X(g_implicit) X(g_neumann) X(ggx_d) X(ggx_aniso_d) X(smith_g1) \
    X(smith_g2_uncorrelated) X(g_cook_torrance) X(brdf_hammon)
#define FXV_LANES_FX_FAST(X) X(fresnel_schlick) X(fresnel_schlick_f90) X(fresnel_schlick_sg) X(g_implicit) \
    X(g_neumann) X(ggx_d) X(ggx_aniso_d) X(beckmann_d) X(gtr_d) X(noh_from_dots) X(loh_from_dots)           \
    X(g_cook_torrance) X(g_kelemen) X(smith_g1_gtr) X(diffuse_burley) X(diffuse_hammon)                      \
    X(diffuse_hammon_hybrid) X(diffuse_hammon_cheap)

/* FXV_INLINE the ops, FXV_BODY the precise body's functions (src/fx/fx_ops.h):
 * inlined, so a kernel is one sequence of vector instructions; a body need
 * not use every op */
#define FXV_INLINE static inline __attribute__((always_inline, unused))
#define FXV_BODY FXV_INLINE
#define FXV_M32_ _mm256_set1_epi64x(0xFFFFFFFFll)

FXV_INLINE fxv_u32 fxv_k32(uint32_t c) { return _mm256_set1_epi64x((long long)c); }
FXV_INLINE fxv_u32 fxv_clamp(fxv_i32 x, int32_t lo, int32_t hi)
{
    return _mm256_cvtepu32_epi64(_mm_min_epi32(_mm_max_epi32(x, _mm_set1_epi32(lo)), _mm_set1_epi32(hi)));
}
FXV_INLINE fxv_u32 fxv_clamp_off(fxv_i32 x, int32_t lo, int32_t hi)
{
    __m128i c = _mm_min_epi32(_mm_max_epi32(x, _mm_set1_epi32(lo)), _mm_set1_epi32(hi));
    return _mm256_cvtepu32_epi64(_mm_sub_epi32(c, _mm_set1_epi32(lo)));
}
FXV_INLINE fxv_u32 fxv_add32(fxv_u32 a, fxv_u32 b) { return _mm256_add_epi64(a, b); }
FXV_INLINE fxv_u32 fxv_sub32(fxv_u32 a, fxv_u32 b) { return _mm256_sub_epi64(a, b); }
FXV_INLINE fxv_u32 fxv_mul32(fxv_u32 a, fxv_u32 b) { return _mm256_mul_epu32(a, b); }
/* a left shift is masked back to 32 bits (mod 2^32, as the scalar ops) */
FXV_INLINE fxv_u32 fxv_shr(fxv_u32 a, int k) { return _mm256_srl_epi64(a, _mm_cvtsi32_si128(k)); }
FXV_INLINE fxv_u32 fxv_shl(fxv_u32 a, int k) { return _mm256_and_si256(_mm256_sll_epi64(a, _mm_cvtsi32_si128(k)), FXV_M32_); }
FXV_INLINE fxv_u32 fxv_shrv(fxv_u32 a, fxv_u32 n) { return _mm256_srlv_epi64(a, n); }
FXV_INLINE fxv_u32 fxv_shlv(fxv_u32 a, fxv_u32 n) { return _mm256_and_si256(_mm256_sllv_epi64(a, n), FXV_M32_); }
/* values below 2^32: signed 64-bit compares order them */
FXV_INLINE fxv_u32 fxv_lt(fxv_u32 a, fxv_u32 b) { return _mm256_cmpgt_epi64(b, a); }
FXV_INLINE fxv_u32 fxv_sel(fxv_u32 m, fxv_u32 a, fxv_u32 b) { return _mm256_blendv_epi8(b, a, m); }
FXV_INLINE fxv_u32 fxv_min(fxv_u32 a, fxv_u32 b) { return fxv_sel(fxv_lt(a, b), a, b); }
FXV_INLINE fxv_u32 fxv_max(fxv_u32 a, fxv_u32 b) { return fxv_sel(fxv_lt(a, b), b, a); }
FXV_INLINE fxv_u32 fxv_and(fxv_u32 a, fxv_u32 b) { return _mm256_and_si256(a, b); }
FXV_INLINE fxv_u32 fxv_or(fxv_u32 a, fxv_u32 b) { return _mm256_or_si256(a, b); }
FXV_INLINE fxv_u32 fxv_not(fxv_u32 a) { return _mm256_xor_si256(a, FXV_M32_); }
/* leading zeros of the 32-bit value: a 5-step binary search (AVX2 has no
 * vector lzcnt); 32 for 0 */
FXV_INLINE fxv_u32 fxv_clz(fxv_u32 a)
{
    fxv_u32 n = _mm256_setzero_si256();
    int s;
    for (s = 16; s >= 1; s >>= 1) {
        fxv_u32 m = fxv_lt(a, fxv_k32(1u << (32 - s))); /* top s bits clear */
        n = _mm256_add_epi64(n, _mm256_and_si256(m, fxv_k32((uint32_t)s)));
        a = fxv_sel(m, fxv_shl(a, s), a);
    }
    return _mm256_add_epi64(n, _mm256_and_si256(fxv_lt(a, fxv_k32(1)), fxv_k32(1)));
}
FXV_INLINE fxv_u32 fxv_lut(const uint32_t *t, fxv_u32 i)
{
    return _mm256_cvtepu32_epi64(_mm256_i64gather_epi32((const int *)t, i, 4));
}

FXV_INLINE fxv_u64 fxv_mulw(fxv_u32 a, fxv_u32 b) { return _mm256_mul_epu32(a, b); }
FXV_INLINE fxv_u64 fxv_wide(fxv_u32 a) { return a; }
FXV_INLINE fxv_u32 fxv_lo(fxv_u64 a) { return _mm256_and_si256(a, FXV_M32_); }
FXV_INLINE fxv_u32 fxv_hi(fxv_u64 a) { return _mm256_srli_epi64(a, 32); }
FXV_INLINE fxv_u32 fxv_narrow(fxv_u64 a) { return a; }
FXV_INLINE fxv_u64 fxv_add64(fxv_u64 a, fxv_u64 b) { return _mm256_add_epi64(a, b); }
FXV_INLINE fxv_u64 fxv_sub64(fxv_u64 a, fxv_u64 b) { return _mm256_sub_epi64(a, b); }
FXV_INLINE fxv_u64 fxv_shr64(fxv_u64 a, int k) { return _mm256_srl_epi64(a, _mm_cvtsi32_si128(k)); }
FXV_INLINE fxv_u64 fxv_shl64(fxv_u64 a, int k) { return _mm256_sll_epi64(a, _mm_cvtsi32_si128(k)); }
FXV_INLINE fxv_u64 fxv_shrv64(fxv_u64 a, fxv_u32 n) { return _mm256_srlv_epi64(a, n); }
FXV_INLINE fxv_u64 fxv_shlv64(fxv_u64 a, fxv_u32 n) { return _mm256_sllv_epi64(a, n); }
FXV_INLINE fxv_u64 fxv_and64(fxv_u64 a, uint64_t c) { return _mm256_and_si256(a, _mm256_set1_epi64x((long long)c)); }
/* unsigned 64-bit order: the signed compare with the top bits flipped */
FXV_INLINE fxv_u32 fxv_lt64(fxv_u64 a, fxv_u64 b)
{
    const __m256i t = _mm256_set1_epi64x((long long)0x8000000000000000ull);
    return _mm256_cmpgt_epi64(_mm256_xor_si256(b, t), _mm256_xor_si256(a, t));
}
/* a mask's low dword copied to its high dword (fxv_not leaves the high one) */
FXV_INLINE fxv_u64 fxv_sel64(fxv_u32 m, fxv_u64 a, fxv_u64 b)
{
    return _mm256_blendv_epi8(b, a, _mm256_shuffle_epi32(m, _MM_SHUFFLE(2, 2, 0, 0)));
}
/* lane by lane: the scalar primitives */
FXV_INLINE fxv_u32 fxv_div64(fxv_u32 u1, fxv_u32 u0, fxv_u32 d, fxv_u32 *r)
{
    uint64_t a[4], b[4], c[4], q[4], s[4];
    int j;
    _mm256_storeu_si256((__m256i *)a, u1);
    _mm256_storeu_si256((__m256i *)b, u0);
    _mm256_storeu_si256((__m256i *)c, d);
    for (j = 0; j < 4; j++) {
        uint32_t rem;
        q[j] = fxp_div64((uint32_t)a[j], (uint32_t)b[j], (uint32_t)c[j], &rem);
        s[j] = rem;
    }
    *r = _mm256_loadu_si256((const __m256i *)s);
    return _mm256_loadu_si256((const __m256i *)q);
}
FXV_INLINE fxv_u32 fxv_isqrt64(fxv_u64 x, fxv_u64 *rem)
{
    uint64_t a[4], g[4], s[4];
    int j;
    _mm256_storeu_si256((__m256i *)a, x);
    for (j = 0; j < 4; j++)
        g[j] = facet_fx_isqrt64_rem(a[j], &s[j]);
    *rem = _mm256_loadu_si256((const __m256i *)s);
    return _mm256_loadu_si256((const __m256i *)g);
}

/* loads and stores: whole vectors, the tail through a zero-padded copy */
FXV_INLINE fxv_i32 fxv_load(const int32_t *p) { return _mm_loadu_si128((const __m128i *)p); }
FXV_INLINE fxv_i32 fxv_load_n(const int32_t *p, size_t r)
{
    int32_t b[4] = { 0, 0, 0, 0 };
    size_t j;
    for (j = 0; j < r; j++)
        b[j] = p[j];
    return fxv_load(b);
}
/* the low dword of each lane, packed */
FXV_INLINE void fxv_store32_(void *p, fxv_u32 v)
{
    const __m256i idx = _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6);
    _mm_storeu_si128((__m128i *)p, _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(v, idx)));
}
FXV_INLINE void fxv_store_n32_(uint32_t *p, fxv_u32 v, size_t r)
{
    uint32_t b[4];
    size_t j;
    fxv_store32_(b, v);
    for (j = 0; j < r; j++)
        p[j] = b[j];
}
#define fxv_store_int32_t fxv_store32_
#define fxv_store_uint32_t fxv_store32_
#define fxv_store_n_int32_t(p, v, r) fxv_store_n32_((uint32_t *)(p), (v), (r))
#define fxv_store_n_uint32_t fxv_store_n32_
FXV_INLINE void fxv_store_uint64_t(uint64_t *p, fxv_u64 v) { _mm256_storeu_si256((__m256i *)p, v); }
FXV_INLINE void fxv_store_n_uint64_t(uint64_t *p, fxv_u64 v, size_t r)
{
    uint64_t b[4];
    size_t j;
    fxv_store_uint64_t(b, v);
    for (j = 0; j < r; j++)
        p[j] = b[j];
}

#include "../../src/fx/fx_batch_body.h"
