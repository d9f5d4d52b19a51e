/* raster_avx2.c - the rasterizer's AVX2-inline shading path: 8 pixels per
 * facet_brdf_hammon_f32_avx2 call.  Built with -mavx2 -mfma on x86; runs
 * only where facet_port_supported("avx2") (AVX2 + FMA, OS saves YMM). */
#include "facet.h"
#include "raster.h"
#if defined(__AVX2__) && defined(__FMA__) && defined(__has_include)
#if __has_include("facet/avx2.h")
#define HAVE_AVX2_H 1
#endif
#endif

#ifdef HAVE_AVX2_H
#include "facet/avx2.h"
static int shade(rs_gbuf *g);
int rs_shade_avx2(rs_gbuf *g)
{
    return facet_port_supported("avx2") ? shade(g) : 0;
}
#define V __m256
#define W 8
#define LD _mm256_loadu_ps
#define ST _mm256_storeu_ps
#define SET1 _mm256_set1_ps
#define ADD _mm256_add_ps
#define SUB _mm256_sub_ps
#define MUL _mm256_mul_ps
#define DIV _mm256_div_ps
#define SQRT _mm256_sqrt_ps
#define MAX _mm256_max_ps
#define BRDF_RGB facet_brdf_hammon_rgb_f32_avx2
#define SHADE_FN static int shade
#include "raster_simd_body.h"
#else
int rs_shade_avx2(rs_gbuf *g)
{
    (void)g;
    return 0;
}
#endif
