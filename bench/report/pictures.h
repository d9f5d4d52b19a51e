/* pictures.h - the report's pictures, as 8-bit RGB buffers (malloc'd).
 * All evaluate facet's scalar f32 kernels (or the oracle where stated). */
#ifndef FACET_BENCH_PICTURES_H
#define FACET_BENCH_PICTURES_H

/* How the report labels a picture (report.c draws it as SVG around the
 * PNG): a grid of cols x rows panels of pw x ph pixels, the first at (x0,
 * y0), gap pixels apart; a title over each column and beside each row; per
 * panel axes (ticks under the bottom row and left of the first column) with
 * linear or log10 scales; and, for colour-mapped pictures, the colour bar's
 * range in log10 units.  cols == 0: no labels. */
typedef struct pic_axes {
    int cols, rows, x0, y0, pw, ph, gap;
    char col_title[12][40], row_title[24][48];
    char xlabel[48], ylabel[48];
    double xmin, xmax, ymin, ymax; /* value at the panel's left / right, bottom / top edge */
    int xlog, ylog;                /* 1: the scale is log10 (ticks at powers of 2 or 10) */
    double bar_lo, bar_hi;         /* colour bar: log10 of the value at its ends (bar_lo < bar_hi) */
    char bar_label[80];            /* "" : no colour bar */
} pic_axes;

typedef struct pic {
    int w, h;
    unsigned char *rgb;
    char title[160];
    char caption[600];
    pic_axes ax;
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
/* a horizontal colour bar of the heatmaps' ramp, W x H pixels (the report
 * labels it from the picture's ax.bar_lo .. bar_hi) */
pic pic_colorbar(int w, int h);

/* linear value -> sRGB encoding (IEC 61966-2-1), clamped to [0, 1] */
double pic_srgb(double x);

void pic_free(pic *p);

#endif
