/* image_error.h - the error a viewer sees: lit spheres rendered with each
 * format, tier and port of brdf_hammon (and with the exact-Vis model)
 * against the same spheres from the double oracle, compared as 8-bit sRGB
 * codes and as CIE76 colour differences. */
#ifndef FACET_BENCH_IMAGE_ERROR_H
#define FACET_BENCH_IMAGE_ERROR_H

#include "pictures.h"

typedef struct img_err {
    char name[48];      /* "f32 avx2", "fx_fast", "model: exact Vis" */
    char against[24];   /* "oracle" or "brdf_hammon oracle" */
    /* per pixel: the largest |code difference| of its three channels */
    double max_code, p99_code, mean_code;
    double frac_diff;   /* fraction of pixels with any channel off */
    /* CIE76 delta E between the two sRGB colours (D65 white) */
    double max_de, p99_de, mean_de;
    long pixels;
} img_err;

/* Renders the scene (pictures.c's light and view; columns alpha 0.02 ..
 * 1.0, rows a dielectric and a metal) with every candidate this machine
 * runs and fills out[] (at most max entries); returns the count.  *ref gets
 * the oracle render and *diff a grid of the code differences, one row per
 * candidate (x 32, so 8 codes are white), both labelled (pic_axes). */
int img_error_run(img_err *out, int max, pic *ref, pic *diff);

/* The same measures for two 8-bit RGB images over the n pixels idx[] (the
 * rasterizer's shaded pixels): fills e's code and delta E fields. */
void img_compare_rgb8(img_err *e, const unsigned char *got, const unsigned char *want, const int *idx, long n);

#endif
