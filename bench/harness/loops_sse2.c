/* loops_sse2.c - benchmark loops over the inline SSE2 kernels (facet/sse2.h),
 * 4 samples per call.  Built with -msse2 on x86 (bench/bench.mk); run only
 * where the library says this CPU runs its sse2 port (always on x86-64). */
#include "facet.h"
#include "loops.h"
#if defined(__SSE2__) && defined(__has_include)
#if __has_include("facet/sse2.h")
#define HAVE_SSE2_H 1
#endif
#endif

#ifdef HAVE_SSE2_H
#include "facet/sse2.h"

static int avail(void) { return facet_port_supported("sse2"); }

#define LP_V __m128
#define LP_W 4
#define LP_LOAD(p) _mm_loadu_ps(p)
#define LP_STORE(p, v) _mm_storeu_ps((p), (v))
#define LP_FEED(x, y) _mm_add_ps((x), _mm_mul_ps((y), _mm_setzero_ps()))
#define LP_ZERO _mm_setzero_ps()
#define LP_K(name, tier) facet_##name##_##tier##_sse2
#define LP_NAME sse2_inline
#define LP_PATH "inline"
#define LP_PORT "sse2"
#define LP_AVAIL avail
#include "loops_body.h"
#else
static int never(void) { return 0; }
static const bench_loop none[1];
const bench_loops bench_loops_sse2_inline = { "inline", "sse2", 4, never, none, "f32", 0 };
const bench_loops bench_loops_sse2_inline_fast = { "inline", "sse2", 4, never, none, "f32_fast", 0 };
#endif
