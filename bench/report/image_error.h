/* image_error.h - the error a viewer sees: lit spheres rendered with each
 * format, tier and port of brdf_hammon (and with the exact-Vis model)
 * against the same spheres from the double oracle, compared as 8-bit sRGB
 * codes and as CIE76 colour differences. */
#ifndef FACET_BENCH_IMAGE_ERROR_H
#define FACET_BENCH_IMAGE_ERROR_H

#include "pictures.h"

/* the most rows img_error_run fills */
#define IMG_ERR_MAX 20

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

/* Renders the scene (pictures.c's light and view; columns alpha 0.005 ..
 * 1.0, rows a dielectric and a metal) with every candidate this machine
 * runs (f32 both tiers on every port, fixed point both tiers, binary16 on
 * every f16 table, with the f32 and fixed-point rows over the same
 * spheres, alpha >= 2^-7) and fills out[] (at most max entries); returns
 * the count.  *ref gets
 * the oracle render and *diff a grid of the code differences, one row per
 * candidate (x 32, so 8 codes are white), both labelled (pic_axes). */
int img_error_run(img_err *out, int max, pic *ref, pic *diff);

/* The same measures for two 8-bit RGB images over the n pixels idx[] (the
 * rasterizer's shaded pixels): fills e's code and delta E fields. */
void img_compare_rgb8(img_err *e, const unsigned char *got, const unsigned char *want, const int *idx, long n);

/* The menu's variants in image space (image_error.c: each sphere BRDF
 * assembled as D * Vis * F + diffuse from double oracles except the
 * variant's part): per variant the implementation error of its kernel
 * forms against the render from its own oracle, and, where the variant
 * approximates a reference term, the model error of its oracle render
 * against the reference's. */
typedef struct img_variant {
    char name[48];        /* "gtr_d (gamma 1.5)" */
    char term[8];         /* "D", "Vis", "G2", "G1", "F", "diffuse" */
    char reference[48];   /* "" (none: a model of its own) or the reference */
    int have[4];          /* f32, f32_fast (active port), fx, fx_fast (Q15 dots) */
    img_err impl[4];
    int has_model, is_reference; /* is_reference: the variant is the reference itself */
    img_err model;
} img_variant;

/* the number of variants img_variants_run can fill */
int img_variant_count(void);
/* Fills out[] (at most max; returns the count), port with the f32 rows'
 * port (the best this CPU runs) and *diff with the model rows' difference
 * grid (rows: the variants that are not the reference itself, labelled). */
int img_variants_run(img_variant *out, int max, pic *diff, char *port, size_t port_cap);

#endif
