/* fx_avx2.c - the fixed-point kernels on AVX2: the op layer of
 * src/fx_vbody.h on 8 uint64_t lanes held in two __m256i (every op is done
 * on both halves, so the two independent dependency chains interleave and
 * the "while any lane" loops run over 8 lanes).  vpmuludq for the exact
 * 32x32->64 products, vpsllvq/vpsrlvq for per-lane shifts, vpcmpgtq with
 * the sign bit flipped for unsigned compares, vpblendvb for selects,
 * vpgatherqd for the seed tables.  Integer instructions only.
 * Bit-identical to src/fx_kernels.c (tests/test_fx_ports.c). */
#if !defined(__AVX2__)
#error "fx_avx2.c needs AVX2 (-mavx2): built by ports/avx2/port.mk"
#endif
#include <immintrin.h>
#include <stdint.h>
#include <string.h>

typedef struct { __m256i a, b; } fv;
#define FXV_W 8
#define FXV_PORT avx2
/* Dispatched only where measured faster than the scalar loop, which on
 * x86-64 divides with the native instruction (fx_div64) while 64-bit lanes
 * here divide in software: `facet bench --format fx` on an AVX-512 Xeon,
 * TSC ticks/sample scalar vs avx2: fresnel_schlick 4.4 vs 2.1; every other
 * kernel 1.2x-6x slower here (ggx_d 14.4 vs 83.2, brdf_hammon 345 vs 490). */
#define FXV_FASTER FX_BIT(FX_FRESNEL_SCHLICK)

static inline fv fv_2(__m256i a, __m256i b)
{
    fv r;
    r.a = a;
    r.b = b;
    return r;
}
#define FXV_OP2(name, intr)                                                        \
    static inline fv name(fv x, fv y) { return fv_2(intr(x.a, y.a), intr(x.b, y.b)); }

static inline fv fv_set(uint64_t c)
{
    long long s;
    __m256i v;
    memcpy(&s, &c, sizeof s); /* the bits, no out-of-range conversion */
    v = _mm256_set1_epi64x(s);
    return fv_2(v, v);
}
FXV_OP2(fv_add, _mm256_add_epi64)
FXV_OP2(fv_sub, _mm256_sub_epi64)
FXV_OP2(fv_and, _mm256_and_si256)
FXV_OP2(fv_or, _mm256_or_si256)
FXV_OP2(fv_xor, _mm256_xor_si256)
FXV_OP2(fv_shlv, _mm256_sllv_epi64)
FXV_OP2(fv_shrv, _mm256_srlv_epi64)
FXV_OP2(fv_mul32, _mm256_mul_epu32)
FXV_OP2(fv_sgt, _mm256_cmpgt_epi64)
FXV_OP2(fv_eq, _mm256_cmpeq_epi64)
static inline fv fv_shl(fv x, int k)
{
    __m128i c = _mm_cvtsi32_si128(k);
    return fv_2(_mm256_sll_epi64(x.a, c), _mm256_sll_epi64(x.b, c));
}
static inline fv fv_shr(fv x, int k)
{
    __m128i c = _mm_cvtsi32_si128(k);
    return fv_2(_mm256_srl_epi64(x.a, c), _mm256_srl_epi64(x.b, c));
}
static inline fv fv_gt(fv x, fv y)
{
    const __m256i s = _mm256_set1_epi64x(-0x7FFFFFFFFFFFFFFFll - 1);
    return fv_2(_mm256_cmpgt_epi64(_mm256_xor_si256(x.a, s), _mm256_xor_si256(y.a, s)),
                _mm256_cmpgt_epi64(_mm256_xor_si256(x.b, s), _mm256_xor_si256(y.b, s)));
}
static inline fv fv_sel(fv m, fv x, fv y)
{
    return fv_2(_mm256_blendv_epi8(y.a, x.a, m.a), _mm256_blendv_epi8(y.b, x.b, m.b));
}
static inline int fv_any(fv m)
{
    __m256i o = _mm256_or_si256(m.a, m.b);
    return !_mm256_testz_si256(o, o);
}
/* binary search, 6 steps (AVX2 has no vector lzcnt) */
static inline fv fv_clz64(fv x)
{
    fv n = fv_set(0), z = fv_set(0), m;
#define FXV_CLZ_STEP(bits)                                                                 \
    m = fv_eq(fv_shr(x, 64 - (bits)), z);                                                  \
    n = fv_add(n, fv_and(m, fv_set(bits)));                                                \
    x = fv_sel(m, fv_shl(x, bits), x);
    FXV_CLZ_STEP(32)
    FXV_CLZ_STEP(16)
    FXV_CLZ_STEP(8)
    FXV_CLZ_STEP(4)
    FXV_CLZ_STEP(2)
#undef FXV_CLZ_STEP
    m = fv_eq(fv_shr(x, 63), z);
    return fv_add(n, fv_and(m, fv_set(1)));
}
static inline fv fv_lut(const uint32_t *t, fv i)
{
    return fv_2(_mm256_cvtepu32_epi64(_mm256_i64gather_epi32((const int *)t, i.a, 4)),
                _mm256_cvtepu32_epi64(_mm256_i64gather_epi32((const int *)t, i.b, 4)));
}
static inline fv fv_load(const int32_t *p)
{
    __m256i w = _mm256_loadu_si256((const __m256i *)p);
    return fv_2(_mm256_cvtepi32_epi64(_mm256_castsi256_si128(w)),
                _mm256_cvtepi32_epi64(_mm256_extracti128_si256(w, 1)));
}
static inline void fv_store32(void *p, fv v)
{
    const __m256i idx = _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6);
    __m256i lo = _mm256_permutevar8x32_epi32(v.a, idx), hi = _mm256_permutevar8x32_epi32(v.b, idx);
    _mm256_storeu_si256((__m256i *)p, _mm256_permute2x128_si256(lo, hi, 0x20));
}
static inline void fv_store64(void *p, fv v)
{
    _mm256_storeu_si256((__m256i *)p, v.a);
    _mm256_storeu_si256((__m256i *)p + 1, v.b);
}

#include "../../src/fx_vbody.h"
