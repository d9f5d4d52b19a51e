/* image_error.c - see image_error.h.
 *
 * Scene: spheres seen along the axis (V = +z) under one directional light
 * (the direction of pictures.c's spheres), radiance = BRDF * N.L * E with
 * E = 2.2, tone-mapped per channel by c / (1 + c) (so that highlights stay
 * below white and their errors stay visible: a clamp would hide them) and
 * encoded as 8-bit sRGB.  Columns alpha = 0.005 .. 1.0; rows a dielectric
 * (f0 0.04, albedo 0.80 0.30 0.20) and gold (f0 1.00 0.71 0.29, albedo 0).
 * Only lit pixels (N.L > 0) count.
 *
 * The f32 candidates get the dots rounded to float, and the reference is
 * the oracle at those same float dots: their difference is the kernel's
 * arithmetic error only.  The fixed-point candidates get the dots rounded
 * to Q15 (and raised to the fx domain floors) and are compared with the
 * same float reference: the input rounding is part of what fixed point
 * costs a picture.  The model row compares the exact-Vis model with
 * brdf_hammon's own oracle: Hammon's Vis approximation, in codes. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "facet/fx.h"
#include "facet/oracle.h"
#include "harness/bench.h"
#include "image_error.h"

#define IE_S 64
#define IE_GAP 4
#define IE_NA 6
#define IE_NM 2
static const double ie_alpha[IE_NA] = { 0.005, 0.02, 0.08, 0.2, 0.5, 1.0 };
static const char *const ie_mat_name[IE_NM] = { "dielectric", "gold" };
static const double ie_f0[IE_NM][3] = { { 0.04, 0.04, 0.04 }, { 1.00, 0.71, 0.29 } };
static const double ie_alb[IE_NM][3] = { { 0.80, 0.30, 0.20 }, { 0, 0, 0 } };

/* the lit pixels of the scene, as the batch API wants them */
typedef struct scene {
    long n;
    float *nl, *nv, *lv, *a, *f0[3], *alb[3];
    int *sphere, *px, *py; /* which sphere (material * IE_NA + alpha), pixel in it */
} scene;

static void scene_make(scene *s)
{
    double L[3] = { -0.45, 0.55, 0.70 }, l = sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
    long cap = (long)IE_NA * IE_NM * IE_S * IE_S, n = 0;
    int m, ai, x, y, c;
    L[0] /= l, L[1] /= l, L[2] /= l;
    memset(s, 0, sizeof *s);
    s->nl = malloc((size_t)cap * sizeof(float));
    s->nv = malloc((size_t)cap * sizeof(float));
    s->lv = malloc((size_t)cap * sizeof(float));
    s->a = malloc((size_t)cap * sizeof(float));
    for (c = 0; c < 3; c++) {
        s->f0[c] = malloc((size_t)cap * sizeof(float));
        s->alb[c] = malloc((size_t)cap * sizeof(float));
    }
    s->sphere = malloc((size_t)cap * sizeof(int));
    s->px = malloc((size_t)cap * sizeof(int));
    s->py = malloc((size_t)cap * sizeof(int));
    for (m = 0; m < IE_NM; m++)
        for (ai = 0; ai < IE_NA; ai++)
            for (y = 0; y < IE_S; y++)
                for (x = 0; x < IE_S; x++) {
                    double u = (x + 0.5) / IE_S * 2 - 1, w = 1 - (y + 0.5) / IE_S * 2, r2 = u * u + w * w;
                    double nz, nl;
                    if (r2 >= 1)
                        continue;
                    nz = sqrt(1 - r2);
                    nl = u * L[0] + w * L[1] + nz * L[2];
                    if (nl <= 0)
                        continue;
                    s->nl[n] = (float)nl;
                    s->nv[n] = (float)nz;
                    s->lv[n] = (float)L[2];
                    s->a[n] = (float)ie_alpha[ai];
                    for (c = 0; c < 3; c++) {
                        s->f0[c][n] = (float)ie_f0[m][c];
                        s->alb[c][n] = (float)ie_alb[m][c];
                    }
                    s->sphere[n] = m * IE_NA + ai;
                    s->px[n] = x;
                    s->py[n] = y;
                    n++;
                }
    s->n = n;
}

static void scene_free(scene *s)
{
    int c;
    free(s->nl), free(s->nv), free(s->lv), free(s->a);
    for (c = 0; c < 3; c++)
        free(s->f0[c]), free(s->alb[c]);
    free(s->sphere), free(s->px), free(s->py);
}

static double srgb_decode(double v)
{
    return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}

/* BRDF value at a lit pixel -> 8-bit sRGB code */
static int code_of(double brdf, double nl)
{
    double c = brdf * nl * 2.2;
    if (!(c > 0))
        c = 0;
    return (int)floor(255.0 * pic_srgb(c / (1.0 + c)) + 0.5);
}

static double lab_f(double t)
{
    return t > 216.0 / 24389.0 ? cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0;
}

static void lab_of(const int code[3], double lab[3])
{
    double r = srgb_decode(code[0] / 255.0), g = srgb_decode(code[1] / 255.0), b = srgb_decode(code[2] / 255.0);
    double X = 0.4124564 * r + 0.3575761 * g + 0.1804375 * b;
    double Y = 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
    double Z = 0.0193339 * r + 0.1191920 * g + 0.9503041 * b;
    double fx = lab_f(X / 0.95047), fy = lab_f(Y), fz = lab_f(Z / 1.08883);
    lab[0] = 116 * fy - 16;
    lab[1] = 500 * (fx - fy);
    lab[2] = 200 * (fy - fz);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double p99(double *v, long n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n ? v[(long)floor(0.99 * (double)(n - 1))] : 0;
}

/* compares the candidate's codes (got) with the reference's (want) */
static void compare(img_err *e, const scene *s, int (*got)[3], int (*want)[3], pic *diff, int row)
{
    double *dc = malloc((size_t)s->n * sizeof(double)), *de = malloc((size_t)s->n * sizeof(double));
    double sc = 0, sd = 0;
    long i, off = 0;
    int c;
    e->max_code = e->max_de = 0;
    for (i = 0; i < s->n; i++) {
        double la[3], lb[3], d = 0, dE;
        for (c = 0; c < 3; c++)
            if (fabs((double)got[i][c] - want[i][c]) > d)
                d = fabs((double)got[i][c] - want[i][c]);
        lab_of(got[i], la);
        lab_of(want[i], lb);
        dE = sqrt((la[0] - lb[0]) * (la[0] - lb[0]) + (la[1] - lb[1]) * (la[1] - lb[1]) +
                  (la[2] - lb[2]) * (la[2] - lb[2]));
        dc[i] = d, de[i] = dE;
        sc += d, sd += dE;
        off += d > 0;
        if (d > e->max_code)
            e->max_code = d;
        if (dE > e->max_de)
            e->max_de = dE;
        if (diff) {
            int x = IE_GAP + s->sphere[i] * (IE_S + IE_GAP) + s->px[i];
            int y = IE_GAP + row * (IE_S + IE_GAP) + s->py[i];
            unsigned char *q = diff->rgb + ((size_t)y * (size_t)diff->w + (size_t)x) * 3;
            int v = (int)(d * 32 > 255 ? 255 : d * 32);
            q[0] = q[1] = q[2] = (unsigned char)v;
            if (v == 0)
                q[0] = q[1] = 0, q[2] = 70; /* lit, no difference: dark blue */
        }
    }
    e->pixels = s->n;
    e->mean_code = sc / (double)s->n;
    e->mean_de = sd / (double)s->n;
    e->frac_diff = (double)off / (double)s->n;
    e->p99_code = p99(dc, s->n);
    e->p99_de = p99(de, s->n);
    free(dc);
    free(de);
}

void img_compare_rgb8(img_err *e, const unsigned char *got, const unsigned char *want, const int *idx, long n)
{
    int (*g)[3] = malloc((size_t)(n ? n : 1) * sizeof *g), (*w)[3] = malloc((size_t)(n ? n : 1) * sizeof *w);
    scene s;
    long i;
    int c;
    for (i = 0; i < n; i++)
        for (c = 0; c < 3; c++) {
            g[i][c] = got[(size_t)idx[i] * 3 + (size_t)c];
            w[i][c] = want[(size_t)idx[i] * 3 + (size_t)c];
        }
    memset(&s, 0, sizeof s);
    s.n = n;
    if (n)
        compare(e, &s, g, w, NULL, 0);
    else
        memset(e, 0, sizeof *e);
    free(g);
    free(w);
}

static int32_t q15_in(float x, int32_t lo, int32_t hi)
{
    double r = floor((double)x * 32768.0 + 0.5); /* ties up, the fx.h rule */
    return (int32_t)(r < lo ? lo : r > hi ? hi : r);
}

int img_error_run(img_err *out, int max, pic *ref, pic *diff)
{
    scene s;
    int (*want)[3], (*got)[3], (*model)[3];
    float *o = NULL;
    int32_t *q[6];
    uint64_t *o64;
    const facet_fx_kernel *fk = facet_fx_kernel_find("brdf_hammon");
    int n = 0, c, k, rows_max = 16;
    long i;
    size_t pi;
    scene_make(&s);
    want = malloc((size_t)s.n * sizeof *want);
    got = malloc((size_t)s.n * sizeof *got);
    model = malloc((size_t)s.n * sizeof *model);
    o = malloc((size_t)s.n * sizeof(float));
    o64 = malloc((size_t)s.n * sizeof(uint64_t));
    for (k = 0; k < 6; k++)
        q[k] = malloc((size_t)s.n * sizeof(int32_t));
    for (i = 0; i < s.n; i++)
        for (c = 0; c < 3; c++) {
            want[i][c] = code_of(facet_oracle_brdf_hammon(s.nl[i], s.nv[i], s.lv[i], s.a[i], s.f0[c][i], s.alb[c][i]),
                                 s.nl[i]);
            model[i][c] = code_of(bench_oracle_brdf_exact(s.nl[i], s.nv[i], s.lv[i], s.a[i], s.f0[c][i], s.alb[c][i]),
                                  s.nl[i]);
        }
    /* the reference picture, and the difference grid (one row per candidate) */
    *ref = (pic){ 0 };
    ref->w = IE_NA * IE_NM * (IE_S + IE_GAP) + IE_GAP;
    ref->h = IE_S + 2 * IE_GAP;
    ref->rgb = calloc((size_t)ref->w * (size_t)ref->h * 3, 1);
    *diff = (pic){ 0 };
    diff->w = ref->w;
    diff->h = rows_max * (IE_S + IE_GAP) + IE_GAP;
    diff->rgb = calloc((size_t)diff->w * (size_t)diff->h * 3, 1);
    memset(ref->rgb, 24, (size_t)ref->w * (size_t)ref->h * 3);
    memset(diff->rgb, 24, (size_t)diff->w * (size_t)diff->h * 3);
    for (i = 0; i < s.n; i++) {
        int x = IE_GAP + s.sphere[i] * (IE_S + IE_GAP) + s.px[i], y = IE_GAP + s.py[i];
        unsigned char *p = ref->rgb + ((size_t)y * (size_t)ref->w + (size_t)x) * 3;
        p[0] = (unsigned char)want[i][0], p[1] = (unsigned char)want[i][1], p[2] = (unsigned char)want[i][2];
    }
    /* f32, both tiers, every port this CPU runs */
    for (pi = 0; pi < facet_port_count() && n + 2 < max && n + 2 < rows_max; pi++) {
        int sup = 0, lanes = 0, tier;
        const char *pn = facet_port_at(pi, &sup, &lanes);
        if (!pn || !sup || facet_set_port(pn) != 0)
            continue;
        for (tier = 0; tier < 2; tier++) {
            for (c = 0; c < 3; c++) {
                (tier ? facet_brdf_hammon_f32_fast_batch : facet_brdf_hammon_f32_batch)(
                    o, s.nl, s.nv, s.lv, s.a, s.f0[c], s.alb[c], (size_t)s.n);
                for (i = 0; i < s.n; i++)
                    got[i][c] = code_of(o[i], s.nl[i]);
            }
            snprintf(out[n].name, sizeof out[n].name, "%s %s", tier ? "f32_fast" : "f32", pn);
            snprintf(out[n].against, sizeof out[n].against, "oracle");
            compare(&out[n], &s, got, want, diff, n);
            n++;
        }
    }
    facet_set_port("auto");
    /* fixed point, both tiers (bit-exact on every port) */
    for (k = 0; fk && k < 2 && n < max && n < rows_max; k++) {
        for (c = 0; c < 3; c++) {
            const float *in[6] = { s.nl, s.nv, s.lv, s.a, s.f0[c], s.alb[c] };
            int j;
            for (j = 0; j < 6; j++)
                for (i = 0; i < s.n; i++)
                    q[j][i] = q15_in(in[j][i], fk->lo[j], fk->hi[j]);
            (k ? fk->fx_fast_batch : fk->fx_batch)(o64, (const int32_t *const *)q, (size_t)s.n);
            for (i = 0; i < s.n; i++)
                got[i][c] = code_of(ldexp((double)o64[i], -fk->out_frac), s.nl[i]);
        }
        snprintf(out[n].name, sizeof out[n].name, "%s (Q15 dots)", k ? "fx_fast" : "fx");
        snprintf(out[n].against, sizeof out[n].against, "oracle");
        compare(&out[n], &s, got, want, diff, n);
        n++;
    }
    if (n < max && n < rows_max) {
        snprintf(out[n].name, sizeof out[n].name, "model: exact-Vis BRDF");
        snprintf(out[n].against, sizeof out[n].against, "brdf_hammon oracle");
        compare(&out[n], &s, model, want, diff, n);
        n++;
    }
    diff->h = n * (IE_S + IE_GAP) + IE_GAP;
    /* labels */
    for (k = 0; k < IE_NA * IE_NM && k < 12; k++) {
        snprintf(ref->ax.col_title[k], sizeof ref->ax.col_title[k], "%s %g", k < IE_NA ? "diel." : "gold",
                 ie_alpha[k % IE_NA]);
        snprintf(diff->ax.col_title[k], sizeof diff->ax.col_title[k], "%s", ref->ax.col_title[k]);
    }
    ref->ax.cols = diff->ax.cols = IE_NA * IE_NM;
    ref->ax.rows = 1;
    diff->ax.rows = n;
    ref->ax.x0 = diff->ax.x0 = ref->ax.y0 = diff->ax.y0 = IE_GAP;
    ref->ax.pw = diff->ax.pw = ref->ax.ph = diff->ax.ph = IE_S;
    ref->ax.gap = diff->ax.gap = IE_GAP;
    for (k = 0; k < n; k++)
        snprintf(diff->ax.row_title[k], sizeof diff->ax.row_title[k], "%s", out[k].name);
    snprintf(ref->title, sizeof ref->title, "Reference spheres (double oracle of brdf_hammon)");
    snprintf(ref->caption, sizeof ref->caption,
             "Columns: material (%s: f0 0.04, albedo 0.80 0.30 0.20; %s: f0 1.00 0.71 0.29, albedo 0) and "
             "alpha. Light from the upper left, view along the axis, radiance = BRDF * N.L * 2.2, tone "
             "c / (1 + c) per channel, 8-bit sRGB.", ie_mat_name[0], ie_mat_name[1]);
    snprintf(diff->title, sizeof diff->title, "Difference images (8-bit sRGB codes)");
    snprintf(diff->caption, sizeof diff->caption,
             "Per lit pixel, the largest code difference of the three channels against the oracle render, x 32 "
             "(grey 32 = 1 code, white >= 8 codes); dark blue: lit and identical; the model row against "
             "brdf_hammon's own oracle.");
    for (k = 0; k < 6; k++)
        free(q[k]);
    free(o64);
    free(o);
    free(model);
    free(got);
    free(want);
    scene_free(&s);
    return n;
}
