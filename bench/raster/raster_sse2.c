/* raster_sse2.c - the rasterizer's SSE2-inline shading path: 4 pixels per
 * facet_brdf_hammon_f32_sse2 call.  Built with -msse2 on x86; runs only
 * where facet_port_supported("sse2") (always on x86-64). */
#include "facet.h"
#include "raster.h"
#if defined(__SSE2__) && defined(__has_include)
#if __has_include("facet/sse2.h")
#define HAVE_SSE2_H 1
#endif
#endif

#ifdef HAVE_SSE2_H
#include "facet/sse2.h"
static int shade(rs_gbuf *g);
int rs_shade_sse2(rs_gbuf *g)
{
    return facet_port_supported("sse2") ? shade(g) : 0;
}
#define V __m128
#define W 4
#define LD _mm_loadu_ps
#define ST _mm_storeu_ps
#define SET1 _mm_set1_ps
#define ADD _mm_add_ps
#define SUB _mm_sub_ps
#define MUL _mm_mul_ps
#define DIV _mm_div_ps
#define SQRT _mm_sqrt_ps
#define MAX _mm_max_ps
#define BRDF_RGB facet_brdf_hammon_rgb_f32_sse2
#define SHADE_FN static int shade
#include "raster_simd_body.h"
#else
int rs_shade_sse2(rs_gbuf *g)
{
    (void)g;
    return 0;
}
#endif
