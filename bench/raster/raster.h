/* raster.h - a small software rasterizer that shades with facet.
 *
 * rs_render() rasterizes a procedural scene (a row of spheres across alpha
 * and a curved, rippled floor mesh) with a perspective camera: triangles
 * set up in clip space, edge functions over the bounding box, a z-buffer,
 * and perspective-correct interpolation of world position and vertex
 * normal.  The result is a G-buffer of covered pixels in SoA form (position,
 * normal, material).  The rs_shade_* functions then light every covered
 * pixel with a directional and a point light, all shading the same way:
 *   radiance_c = sum_lights brdf_hammon(N.L, N.V, L.V, alpha, f0_c, albedo_c)
 *                          * max(N.L, 0) * E_c(light)
 * so the images differ only by the BRDF arithmetic.  Paths:
 *   scalar   facet_brdf_hammon_f32_scalar per pixel, light and channel
 *   avx2     facet_brdf_hammon_f32_avx2, 8 pixels per call (raster_avx2.c)
 *   sse2     facet_brdf_hammon_f32_sse2, 4 pixels per call (raster_sse2.c)
 *   neon     facet_brdf_hammon_f32_neon, 4 pixels per call (raster_neon.c)
 *   batch    deferred: the dots of all pixels for a light into arrays, one
 *            facet_brdf_hammon_f32_batch call per light and channel
 *   rgb      deferred, one facet_brdf_hammon_rgb_f32_batch call per light
 *            (the geometry once per pixel; per-pixel material arrays)
 *   material deferred, one facet_brdf_hammon_rgb_f32_batch_material call per
 *            light and material run (the G-buffer is grouped by material:
 *            no material arrays read at all)
 *   pixel    the per-pixel vector entry facet_shade_hammon_rgb_f32 (N, L,
 *            V and the material), one call per pixel and light
 *   fx       facet_brdf_hammon_fx per pixel, light and channel: the float
 *            dots rounded to Q15 (ties up), N.L and N.V raised to the fx
 *            cos floor 2^-8, the UQ40.24 result converted back to float
 *   oracle   facet_oracle_brdf_hammon in double: the reference image
 */
#ifndef FACET_BENCH_RASTER_H
#define FACET_BENCH_RASTER_H

#include <stddef.h>
#include "facet.h"

#define RS_MAX_RUNS 16

typedef struct rs_light {
    int point;          /* 0: directional (dir = towards the light), 1: point */
    float v[3];         /* direction or position */
    float e[3];         /* irradiance (point: at distance 1) */
} rs_light;

typedef struct rs_gbuf {
    int w, h;
    int n, cap;                 /* covered pixels; arrays padded to cap (multiple of 8) */
    int *idx;                   /* pixel index y*w + x */
    float *px, *py, *pz;        /* world position */
    float *nx, *ny, *nz;        /* interpolated normal (not normalised) */
    float *alpha, *f0[3], *alb[3];
    float *out[3];              /* shaded linear radiance */
    float *s[8];                /* scratch arrays for the batch path */
    float cam[3];
    /* the pixels are grouped by material: run r is [run_start, + run_len),
     * all of material mat[r] (the uniform-material path) */
    int n_runs, run_start[RS_MAX_RUNS], run_len[RS_MAX_RUNS];
    facet_material_f32 mat[RS_MAX_RUNS];
    int n_lights;
    rs_light light[2];
    long triangles;             /* triangles rasterized */
} rs_gbuf;

rs_gbuf *rs_render(int w, int h);
void rs_free(rs_gbuf *g);

void rs_shade_scalar(rs_gbuf *g);
void rs_shade_batch(rs_gbuf *g);
void rs_shade_rgb(rs_gbuf *g);
void rs_shade_material(rs_gbuf *g);
void rs_shade_pixel(rs_gbuf *g);
void rs_shade_oracle(rs_gbuf *g);
/* the SIMD paths: 0 where the port is not compiled in or not on this CPU
 * (facet_port_supported), else 1 */
int rs_shade_avx2(rs_gbuf *g);
int rs_shade_sse2(rs_gbuf *g);
int rs_shade_neon(rs_gbuf *g);
int rs_shade_fx(rs_gbuf *g);      /* facet/fx.h (always 1) */

/* Tone map (exposure, clamp) and sRGB-encode g->out into rgb (w*h*3). */
void rs_to_srgb(const rs_gbuf *g, unsigned char *rgb);

/* max and mean absolute difference over all channels of covered pixels */
void rs_diff(const rs_gbuf *g, const unsigned char *a, const unsigned char *b, int *maxd,
             double *meand);

#endif
