/* pictures.h - the report's pictures, as 8-bit RGB buffers (malloc'd).
 * All evaluate facet's scalar f32 kernels (or the oracle where stated). */
#ifndef FACET_BENCH_PICTURES_H
#define FACET_BENCH_PICTURES_H

typedef struct pic {
    int w, h;
    unsigned char *rgb;
    char title[160];
    char caption[600];
} pic;

/* Disney-style BRDF slices: theta_h across (0..90 deg), theta_d down
 * (0..90 deg), phi_d = 90 deg; rows: variants, columns: alpha values. */
pic pic_slices(void);
/* lit spheres across alpha (columns) for each diffuse and specular
 * variant (rows), one directional light, view along -z */
pic pic_spheres(void);
/* relative model error heatmap over (N.L across, N.V up) of an
 * approximation against the exact term; which: 0 Vis Hammon vs exact
 * Vis, 1 G2 uncorrelated vs correlated, 2 G1 Hammon vs exact (G1(N.L) x axis
 * only, N.V ignored: shown over (N.V, alpha) instead), 3 Lambert vs Hammon
 * diffuse, 4 brdf_hammon vs the exact-Vis model.  Columns: alpha values. */
pic pic_heatmap(int which);
#define PIC_N_HEATMAPS 5
/* f32 arithmetic error of brdf_hammon (scalar) vs the oracle over (N.L, N.V) */
pic pic_heatmap_f32(void);
/* fixed-point brdf_hammon over (N.L, N.V) in the f32 map's geometry:
 * which 0: arithmetic error vs the oracle at the same Q15 inputs;
 * which 1: including the Q15 rounding of the inputs (vs the float dots) */
pic pic_heatmap_fx(int which);
/* the colour bar used by the heatmaps: log10 error from -7 to 0 */
pic pic_colorbar(void);

void pic_free(pic *p);

#endif
