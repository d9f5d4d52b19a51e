/* loops_neon.c - benchmark loops over the inline NEON kernels (facet/neon.h),
 * 4 samples per call, on aarch64 / ARM with NEON (armv7: this object alone is
 * built with -mfpu=neon-vfpv4, bench/bench.mk).  Run only where the library
 * says this CPU runs its neon port (armv7: NEON and VFPv4 in HWCAP). */
#include "facet.h"
#include "loops.h"
#if (defined(__ARM_NEON) || defined(__aarch64__)) && defined(__has_include)
#if __has_include("facet/neon.h")
#define HAVE_NEON_H 1
#endif
#endif

#ifdef HAVE_NEON_H
#include "facet/neon.h"

static int avail(void) { return facet_port_supported("neon"); }

#define LP_V float32x4_t
#define LP_W 4
#define LP_LOAD(p) vld1q_f32(p)
#define LP_STORE(p, v) vst1q_f32((p), (v))
#define LP_FEED(x, y) vaddq_f32((x), vmulq_f32((y), vdupq_n_f32(0.0f)))
#define LP_ZERO vdupq_n_f32(0.0f)
#define LP_K(name, tier) facet_##name##_##tier##_neon
#define LP_NAME neon_inline
#define LP_PATH "inline"
#define LP_PORT "neon"
#define LP_AVAIL avail
#include "loops_body.h"
#else
static int never(void) { return 0; }
static const bench_loop none[1];
const bench_loops bench_loops_neon_inline = { "inline", "neon", 4, never, none, "f32", 0 };
const bench_loops bench_loops_neon_inline_fast = { "inline", "neon", 4, never, none, "f32_fast", 0 };
#endif
