/* fx_avx2.c - the lane op layer of src/fx_body.h on AVX2: 4 lanes, each a
 * uint64_t in a __m256i (vpmuludq for the exact 32x32->64 products), int32
 * inputs clamped as 4 dwords (vpmaxsd / vpminsd) before they are widened.
 * Integer instructions only.  Bit-identical to the scalar specification
 * (tests/test_fx_ports.c).  Dispatched for the avx2 and avx512 ports
 * (src/dispatch.c). */
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

#include "../../src/fx_vbatch.h"
