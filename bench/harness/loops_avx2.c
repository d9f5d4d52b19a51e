/* loops_avx2.c - benchmark loops over the inline AVX2 kernels (facet/avx2.h),
 * 8 samples per call.  Built with -mavx2 -mfma (bench/bench.mk); run only
 * where the library says this CPU runs its avx2 port (AVX2 + FMA, and the OS
 * saves YMM state). */
#include "facet.h"
#include "loops.h"
#if defined(__AVX2__) && defined(__FMA__) && defined(__has_include)
#if __has_include("facet/avx2.h")
#define HAVE_AVX2_H 1
#endif
#endif

#ifdef HAVE_AVX2_H
#include "facet/avx2.h"

static int avail(void) { return facet_port_supported("avx2"); }

#define LP_V __m256
#define LP_W 8
#define LP_LOAD(p) _mm256_loadu_ps(p)
#define LP_STORE(p, v) _mm256_storeu_ps((p), (v))
#define LP_FEED(x, y) _mm256_add_ps((x), _mm256_mul_ps((y), _mm256_setzero_ps()))
#define LP_ZERO _mm256_setzero_ps()
#define LP_K(name, tier) facet_##name##_##tier##_avx2
#define LP_NAME avx2_inline
#define LP_PATH "inline"
#define LP_PORT "avx2"
#define LP_AVAIL avail
#include "loops_body.h"
#else
static int never(void) { return 0; }
static const bench_loop none[1];
const bench_loops bench_loops_avx2_inline = { "inline", "avx2", 8, never, none, "f32", 0 };
const bench_loops bench_loops_avx2_inline_fast = { "inline", "avx2", 8, never, none, "f32_fast", 0 };
#endif
