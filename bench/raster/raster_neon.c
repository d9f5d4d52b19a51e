/* raster_neon.c - the rasterizer's NEON-inline shading path: 4 pixels per
 * facet_brdf_hammon_f32_neon call (aarch64; armv7 where HWCAP has NEON and
 * VFPv4 - this object alone gets -mfpu=neon-vfpv4).  Divisions and square
 * roots use the port's own refined rcp/rsqrt (armv7 NEON has no vector
 * divide or square root). */
#include "facet.h"
#include "raster.h"

#if defined(__ARM_NEON)
#include "facet/neon.h"

static float32x4_t div_(float32x4_t a, float32x4_t b) { return vmulq_f32(a, facet_neon_rcp(b)); }
static float32x4_t sqrt_(float32x4_t x) { return vmulq_f32(x, facet_neon_rsqrt(x)); }

static int shade(rs_gbuf *g);
int rs_shade_neon(rs_gbuf *g)
{
    return facet_port_supported("neon") ? shade(g) : 0; /* armv7: HWCAP */
}
#define V float32x4_t
#define W 4
#define LD vld1q_f32
#define ST vst1q_f32
#define SET1 vdupq_n_f32
#define ADD vaddq_f32
#define SUB vsubq_f32
#define MUL vmulq_f32
#define DIV div_
#define SQRT sqrt_
#define MAX vmaxq_f32
#define BRDF_RGB facet_brdf_hammon_rgb_f32_neon
#define SHADE_FN static int shade
#include "raster_simd_body.h"
#else
int rs_shade_neon(rs_gbuf *g)
{
    (void)g;
    return 0;
}
#endif
