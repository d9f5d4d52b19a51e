/* fx_avx2.c - the lane op layer of src/fx/fx_body.h on AVX2: 4 lanes, each a
 * uint64_t in a __m256i (vpmuludq for the exact 32x32->64 products), int32
 * inputs clamped as 4 dwords (vpmaxsd / vpminsd) before they are widened.
 * Integer instructions only.  Bit-identical to the scalar specification
 * (tests/fx/test_fx_ports.c).  Dispatched for the avx2 and avx512 ports
 * (src/core/dispatch.c). */
#if !defined(__AVX2__)
#error "fx_avx2.c needs AVX2 (-mavx2): built by ports/avx2/port.mk"
#endif
#include <immintrin.h>
#include <stdint.h>

typedef __m128i fxv_i32;
typedef __m256i fxv_u32; /* values below 2^32 in 64-bit lanes */
typedef __m256i fxv_u64;
#define FXV_W 4
#define FXV_PORT_NAME "avx2"
#define FXV_PORT_VAR facet_fx_port_avx2
#define FXV_FAST_PORT_VAR facet_fx_fast_port_avx2
/* the fast tier on lanes only where fx_code is lanes (Fresnel): for every
 * other kernel the scalar loop measured faster (0.44x to 0.78x here: the
 * 32-bit stages on 64-bit lanes, the table gathers; README "SIMD ports") */

static inline fxv_u32 fxv_k32(uint32_t c) { return _mm256_set1_epi64x((long long)c); }
static inline fxv_u32 fxv_clamp(fxv_i32 x, int32_t lo, int32_t hi)
{
    return _mm256_cvtepu32_epi64(_mm_min_epi32(_mm_max_epi32(x, _mm_set1_epi32(lo)), _mm_set1_epi32(hi)));
}
static inline fxv_u32 fxv_add32(fxv_u32 a, fxv_u32 b) { return _mm256_add_epi64(a, b); }
static inline fxv_u32 fxv_sub32(fxv_u32 a, fxv_u32 b) { return _mm256_sub_epi64(a, b); }
static inline fxv_u32 fxv_mul32(fxv_u32 a, fxv_u32 b) { return _mm256_mul_epu32(a, b); }
static inline fxv_u64 fxv_mulw(fxv_u32 a, fxv_u32 b) { return _mm256_mul_epu32(a, b); }
static inline fxv_u64 fxv_add64(fxv_u64 a, fxv_u64 b) { return _mm256_add_epi64(a, b); }
static inline fxv_u64 fxv_shr64(fxv_u64 a, int k) { return _mm256_srl_epi64(a, _mm_cvtsi32_si128(k)); }
static inline fxv_u64 fxv_and64(fxv_u64 a, uint64_t c) { return _mm256_and_si256(a, _mm256_set1_epi64x((long long)c)); }
static inline fxv_u32 fxv_lo(fxv_u64 a) { return _mm256_and_si256(a, _mm256_set1_epi64x(0xFFFFFFFFll)); }
static inline fxv_u32 fxv_hi(fxv_u64 a) { return _mm256_srli_epi64(a, 32); }
static inline fxv_u32 fxv_narrow(fxv_u64 a) { return a; }

/* the fast tier's ops (src/fx/fx_body.h's list; src/fx/fx_fast_body.h): values
 * below 2^32 in 64-bit lanes, so signed 64-bit compares order them and a
 * left shift is masked back to 32 bits (mod 2^32, as the scalar ops) */
#define FXV_M32_ _mm256_set1_epi64x(0xFFFFFFFFll)
/* the fast tier's ops: a kernel body need not use all of them */
#define FXV_FAST_ static inline __attribute__((unused))
FXV_FAST_ fxv_u32 fxv_shr(fxv_u32 a, int k) { return _mm256_srl_epi64(a, _mm_cvtsi32_si128(k)); }
FXV_FAST_ fxv_u32 fxv_shl(fxv_u32 a, int k) { return _mm256_and_si256(_mm256_sll_epi64(a, _mm_cvtsi32_si128(k)), FXV_M32_); }
FXV_FAST_ fxv_u32 fxv_shrv(fxv_u32 a, fxv_u32 n) { return _mm256_srlv_epi64(a, n); }
FXV_FAST_ fxv_u32 fxv_shlv(fxv_u32 a, fxv_u32 n) { return _mm256_and_si256(_mm256_sllv_epi64(a, n), FXV_M32_); }
FXV_FAST_ fxv_u32 fxv_lt(fxv_u32 a, fxv_u32 b) { return _mm256_cmpgt_epi64(b, a); }
FXV_FAST_ fxv_u32 fxv_sel(fxv_u32 m, fxv_u32 a, fxv_u32 b) { return _mm256_blendv_epi8(b, a, m); }
FXV_FAST_ fxv_u32 fxv_min(fxv_u32 a, fxv_u32 b) { return fxv_sel(fxv_lt(a, b), a, b); }
FXV_FAST_ fxv_u32 fxv_max(fxv_u32 a, fxv_u32 b) { return fxv_sel(fxv_lt(a, b), b, a); }
FXV_FAST_ fxv_u32 fxv_and(fxv_u32 a, fxv_u32 b) { return _mm256_and_si256(a, b); }
FXV_FAST_ fxv_u32 fxv_or(fxv_u32 a, fxv_u32 b) { return _mm256_or_si256(a, b); }
FXV_FAST_ fxv_u32 fxv_not(fxv_u32 a) { return _mm256_xor_si256(a, FXV_M32_); }
/* leading zeros of the 32-bit value: a 5-step binary search (AVX2 has no
 * vector lzcnt); 32 for 0 */
FXV_FAST_ fxv_u32 fxv_clz(fxv_u32 a)
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
FXV_FAST_ fxv_u32 fxv_clamp_off(fxv_i32 x, int32_t lo, int32_t hi)
{
    __m128i c = _mm_min_epi32(_mm_max_epi32(x, _mm_set1_epi32(lo)), _mm_set1_epi32(hi));
    return _mm256_cvtepu32_epi64(_mm_sub_epi32(c, _mm_set1_epi32(lo)));
}
FXV_FAST_ fxv_u32 fxv_lut(const uint32_t *t, fxv_u32 i)
{
    return _mm256_cvtepu32_epi64(_mm256_i64gather_epi32((const int *)t, i, 4));
}

static inline fxv_i32 fxv_load(const int32_t *p) { return _mm_loadu_si128((const __m128i *)p); }
/* the low dword of each lane, packed */
static inline void fxv_store32_(void *p, fxv_u32 v)
{
    const __m256i idx = _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6);
    _mm_storeu_si128((__m128i *)p, _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(v, idx)));
}
#define fxv_store_int32_t fxv_store32_
#define fxv_store_uint32_t fxv_store32_
/* macros, not functions: a port need not use every output type (clang
 * warns about an unused static function) */
#define fxv_store_uint64_t(p, v) _mm256_storeu_si256((__m256i *)(p), (v))

#include "../../src/fx/fx_batch_body.h"
