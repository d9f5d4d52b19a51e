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
#include "facet/f16.h"
#include "facet/oracle.h"
#include "harness/bench.h"
#include "image_error.h"
#include "kernel_facts.h"

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
    /* for the menu's variants: the half-vector dots, the tangent frame's
     * (T = Y x N normalised, B = N x T), alpha_y = alpha / 2, f90 = 1 and
     * the variant's gamma */
    float *noh, *voh, *toh, *boh, *ay, *one, *gamma;
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
    s->noh = malloc((size_t)cap * sizeof(float));
    s->voh = malloc((size_t)cap * sizeof(float));
    s->toh = malloc((size_t)cap * sizeof(float));
    s->boh = malloc((size_t)cap * sizeof(float));
    s->ay = malloc((size_t)cap * sizeof(float));
    s->one = malloc((size_t)cap * sizeof(float));
    s->gamma = malloc((size_t)cap * sizeof(float));
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
                    double nz, nl, H[3], h, t;
                    if (r2 >= 1)
                        continue;
                    nz = sqrt(1 - r2);
                    nl = u * L[0] + w * L[1] + nz * L[2];
                    if (nl <= 0)
                        continue;
                    H[0] = L[0], H[1] = L[1], H[2] = L[2] + 1; /* L + V, V = +z */
                    h = sqrt(H[0] * H[0] + H[1] * H[1] + H[2] * H[2]);
                    H[0] /= h, H[1] /= h, H[2] /= h;
                    s->noh[n] = (float)(u * H[0] + w * H[1] + nz * H[2]);
                    s->voh[n] = (float)H[2];
                    t = sqrt(nz * nz + u * u); /* T = (nz, 0, -u) / t, B = N x T */
                    s->toh[n] = (float)((nz * H[0] - u * H[2]) / t);
                    s->boh[n] = (float)((-w * u * H[0] + (u * u + nz * nz) * H[1] - w * nz * H[2]) / t);
                    s->ay[n] = (float)(ie_alpha[ai] * 0.5);
                    s->one[n] = 1.0f;
                    s->gamma[n] = 2.0f;
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
    free(s->noh), free(s->voh), free(s->toh), free(s->boh), free(s->ay), free(s->one), free(s->gamma);
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
    static double lin[256];
    static int init;
    double r, g, b;
    if (!init) { /* the 256 decoded codes, once */
        int k;
        for (k = 0; k < 256; k++)
            lin[k] = srgb_decode(k / 255.0);
        init = 1;
    }
    r = lin[code[0] & 255], g = lin[code[1] & 255], b = lin[code[2] & 255];
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

/* compares n pixels' codes: the candidate's (got) with the reference's (want) */
static void compare(img_err *e, const int (*got)[3], const int (*want)[3], long n)
{
    double *dc = malloc((size_t)(n ? n : 1) * sizeof(double)), *de = malloc((size_t)(n ? n : 1) * sizeof(double));
    double sc = 0, sd = 0;
    long i, off = 0;
    int c;
    e->max_code = e->max_de = e->mean_code = e->mean_de = e->frac_diff = e->p99_code = e->p99_de = 0;
    e->pixels = n;
    for (i = 0; i < n; i++) {
        double la[3], lb[3], d = 0, dE = 0;
        for (c = 0; c < 3; c++)
            if (fabs((double)got[i][c] - want[i][c]) > d)
                d = fabs((double)got[i][c] - want[i][c]);
        if (d > 0) { /* (identical codes: delta E 0) */
            lab_of(got[i], la);
            lab_of(want[i], lb);
            dE = sqrt((la[0] - lb[0]) * (la[0] - lb[0]) + (la[1] - lb[1]) * (la[1] - lb[1]) +
                      (la[2] - lb[2]) * (la[2] - lb[2]));
        }
        dc[i] = d, de[i] = dE;
        sc += d, sd += dE;
        off += d > 0;
        if (d > e->max_code)
            e->max_code = d;
        if (dE > e->max_de)
            e->max_de = dE;
    }
    if (n) {
        e->mean_code = sc / (double)n;
        e->mean_de = sd / (double)n;
        e->frac_diff = (double)off / (double)n;
        e->p99_code = p99(dc, n);
        e->p99_de = p99(de, n);
    }
    free(dc);
    free(de);
}

/* compare over the lit pixels of the spheres whose alpha is >= amin (the
 * binary16 rows: its domain starts at 2^-7) */
static void compare_from(img_err *e, const scene *s, const int (*got)[3], const int (*want)[3], double amin)
{
    int (*g)[3] = malloc((size_t)(s->n ? s->n : 1) * sizeof *g), (*w)[3] = malloc((size_t)(s->n ? s->n : 1) * sizeof *w);
    long i, m = 0;
    for (i = 0; i < s->n; i++)
        if (s->a[i] >= amin) {
            memcpy(g[m], got[i], sizeof g[m]);
            memcpy(w[m], want[i], sizeof w[m]);
            m++;
        }
    compare(e, (const int (*)[3])g, (const int (*)[3])w, m);
    free(g);
    free(w);
}

/* row `row` of a difference grid: per lit pixel the largest channel's
 * code difference x 32 (white from 8 codes), dark blue where identical;
 * spheres with alpha below amin left as background */
static void diff_place_from(pic *diff, const scene *s, const int (*got)[3], const int (*want)[3], int row,
                            double amin)
{
    long i;
    int c;
    for (i = 0; i < s->n; i++) {
        int x = IE_GAP + s->sphere[i] * (IE_S + IE_GAP) + s->px[i];
        int y = IE_GAP + row * (IE_S + IE_GAP) + s->py[i], v;
        unsigned char *q = diff->rgb + ((size_t)y * (size_t)diff->w + (size_t)x) * 3;
        double d = 0;
        if (s->a[i] < amin)
            continue;
        for (c = 0; c < 3; c++)
            if (fabs((double)got[i][c] - want[i][c]) > d)
                d = fabs((double)got[i][c] - want[i][c]);
        v = (int)(d * 32 > 255 ? 255 : d * 32);
        q[0] = q[1] = q[2] = (unsigned char)v;
        if (v == 0)
            q[0] = q[1] = 0, q[2] = 70; /* lit, no difference: dark blue */
    }
}

static void diff_place(pic *diff, const scene *s, const int (*got)[3], const int (*want)[3], int row)
{
    diff_place_from(diff, s, got, want, row, 0.0);
}

void img_compare_rgb8(img_err *e, const unsigned char *got, const unsigned char *want, const int *idx, long n)
{
    int (*g)[3] = malloc((size_t)(n ? n : 1) * sizeof *g), (*w)[3] = malloc((size_t)(n ? n : 1) * sizeof *w);
    long i;
    int c;
    for (i = 0; i < n; i++)
        for (c = 0; c < 3; c++) {
            g[i][c] = got[(size_t)idx[i] * 3 + (size_t)c];
            w[i][c] = want[(size_t)idx[i] * 3 + (size_t)c];
        }
    memset(e, 0, sizeof *e);
    compare(e, (const int (*)[3])g, (const int (*)[3])w, n);
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
    int n = 0, c, k, rows_max = IMG_ERR_MAX;
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
            compare(&out[n], (const int (*)[3])got, (const int (*)[3])want, s.n);
            diff_place(diff, &s, (const int (*)[3])got, (const int (*)[3])want, n);
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
        compare(&out[n], (const int (*)[3])got, (const int (*)[3])want, s.n);
        diff_place(diff, &s, (const int (*)[3])got, (const int (*)[3])want, n);
        n++;
    }
    /* binary16: every f16 table this CPU runs (each once, through the first
     * port whose line selects it), the dots rounded to binary16 as a caller
     * must (input rounding included, as for fixed point), against the float
     * reference, over the spheres with alpha >= 2^-7 (the f16 domain); beside
     * them the best f32 port and both fixed-point tiers over the same spheres */
    {
        const double amin = FACET_F16_ALPHA_MIN;
        const char *done[8];
        int nd = 0, d, j;
        facet_f16 *h[6], *ho = malloc((size_t)s.n * sizeof(facet_f16));
        for (j = 0; j < 6; j++)
            h[j] = malloc((size_t)s.n * sizeof(facet_f16));
        for (pi = 0; pi < facet_port_count() && n < max && n < rows_max; pi++) {
            int sup = 0, seen = 0;
            const char *pn = facet_port_at(pi, &sup, NULL), *hn;
            if (!pn || !sup || facet_set_port(pn) != 0)
                continue;
            hn = facet_f16_port_name();
            for (d = 0; d < nd; d++)
                seen |= !strcmp(done[d], hn);
            if (seen || nd == 8)
                continue;
            done[nd++] = hn;
            for (c = 0; c < 3; c++) {
                const float *in[6] = { s.nl, s.nv, s.lv, s.a, s.f0[c], s.alb[c] };
                for (j = 0; j < 6; j++)
                    facet_f16_from_f32_batch(h[j], in[j], (size_t)s.n);
                facet_brdf_hammon_f16_batch(ho, h[0], h[1], h[2], h[3], h[4], h[5], (size_t)s.n);
                for (i = 0; i < s.n; i++)
                    got[i][c] = code_of(facet_f32_from_f16(ho[i]), s.nl[i]);
            }
            snprintf(out[n].name, sizeof out[n].name, "f16 %s (binary16 dots, alpha >= 2^-7)", hn);
            snprintf(out[n].against, sizeof out[n].against, "oracle");
            compare_from(&out[n], &s, (const int (*)[3])got, (const int (*)[3])want, amin);
            diff_place_from(diff, &s, (const int (*)[3])got, (const int (*)[3])want, n, amin);
            n++;
            /* the best table's arithmetic alone: against the oracle at the same
             * binary16 inputs (clamped to the f16 domain), as the f32 rows */
            if (nd == 1 && n < max && n < rows_max) {
                int (*w16)[3] = malloc((size_t)s.n * sizeof *w16);
                for (c = 0; c < 3; c++) {
                    const float *in[6] = { s.nl, s.nv, s.lv, s.a, s.f0[c], s.alb[c] };
                    for (j = 0; j < 6; j++)
                        facet_f16_from_f32_batch(h[j], in[j], (size_t)s.n);
                    for (i = 0; i < s.n; i++) {
                        double x[6];
                        for (j = 0; j < 6; j++)
                            x[j] = facet_f32_from_f16(h[j][i]);
                        x[0] = x[0] > FACET_F16_COS_MIN ? x[0] : FACET_F16_COS_MIN;
                        x[1] = x[1] > FACET_F16_COS_MIN ? x[1] : FACET_F16_COS_MIN;
                        x[3] = x[3] > FACET_F16_ALPHA_MIN ? x[3] : FACET_F16_ALPHA_MIN;
                        w16[i][c] = code_of(facet_oracle_brdf_hammon(x[0], x[1], x[2], x[3], x[4], x[5]), s.nl[i]);
                    }
                }
                snprintf(out[n].name, sizeof out[n].name, "f16 %s (alpha >= 2^-7)", hn);
                snprintf(out[n].against, sizeof out[n].against, "oracle, binary16 inputs");
                compare_from(&out[n], &s, (const int (*)[3])got, (const int (*)[3])w16, amin);
                diff_place_from(diff, &s, (const int (*)[3])got, (const int (*)[3])w16, n, amin);
                n++;
                free(w16);
            }
        }
        facet_set_port("auto");
        if (nd && n < max && n < rows_max) {
            for (c = 0; c < 3; c++) {
                facet_brdf_hammon_f32_batch(o, s.nl, s.nv, s.lv, s.a, s.f0[c], s.alb[c], (size_t)s.n);
                for (i = 0; i < s.n; i++)
                    got[i][c] = code_of(o[i], s.nl[i]);
            }
            snprintf(out[n].name, sizeof out[n].name, "f32 %s (alpha >= 2^-7)", facet_port_name());
            snprintf(out[n].against, sizeof out[n].against, "oracle");
            compare_from(&out[n], &s, (const int (*)[3])got, (const int (*)[3])want, amin);
            diff_place_from(diff, &s, (const int (*)[3])got, (const int (*)[3])want, n, amin);
            n++;
        }
        for (k = 0; nd && fk && k < 2 && n < max && n < rows_max; k++) {
            for (c = 0; c < 3; c++) {
                const float *in[6] = { s.nl, s.nv, s.lv, s.a, s.f0[c], s.alb[c] };
                for (j = 0; j < 6; j++)
                    for (i = 0; i < s.n; i++)
                        q[j][i] = q15_in(in[j][i], fk->lo[j], fk->hi[j]);
                (k ? fk->fx_fast_batch : fk->fx_batch)(o64, (const int32_t *const *)q, (size_t)s.n);
                for (i = 0; i < s.n; i++)
                    got[i][c] = code_of(ldexp((double)o64[i], -fk->out_frac), s.nl[i]);
            }
            snprintf(out[n].name, sizeof out[n].name, "%s (Q15 dots, alpha >= 2^-7)", k ? "fx_fast" : "fx");
            snprintf(out[n].against, sizeof out[n].against, "oracle");
            compare_from(&out[n], &s, (const int (*)[3])got, (const int (*)[3])want, amin);
            diff_place_from(diff, &s, (const int (*)[3])got, (const int (*)[3])want, n, amin);
            n++;
        }
        for (j = 0; j < 6; j++)
            free(h[j]);
        free(ho);
    }
    if (n < max && n < rows_max) {
        snprintf(out[n].name, sizeof out[n].name, "model: exact-Vis BRDF");
        snprintf(out[n].against, sizeof out[n].against, "brdf_hammon oracle");
        compare(&out[n], (const int (*)[3])model, (const int (*)[3])want, s.n);
        diff_place(diff, &s, (const int (*)[3])model, (const int (*)[3])want, n);
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

/* ---- the menu's variants in image space ------------------------------------
 * A sphere BRDF is assembled as D * Vis * F + diffuse, each part from the
 * double oracle (GGX D, exact height-correlated Smith Vis, Schlick F,
 * Hammon's diffuse) except the one the variant computes.  A G1 variant
 * gives Vis = G1(N.L) G1(N.V) / (4 N.L N.V) with its own D (Beckmann's for
 * the Beckmann G1s, GTR's at the same gamma for smith_g1_gtr); a G2 variant
 * Vis = G2 / (4 N.L N.V).  Inputs: the dots of the scene rounded to float
 * (N.H, V.H from H = normalize(L + V); the Fresnel cosine is V.H; tangent
 * frame T = Y x N; alpha_y = alpha / 2; f90 = 1). */
int img_variant_count(void) { return kf_variant_count(); }

/* the float input stream a kernel input names (dir 1: a G1's N.V input
 * takes N.L) */
static const float *ie_input(const scene *s, const char *nm, int c, int dir)
{
    if (!strcmp(nm, "nol")) return s->nl;
    if (!strcmp(nm, "nov")) return dir ? s->nl : s->nv;
    if (!strcmp(nm, "lov")) return s->lv;
    if (!strcmp(nm, "noh")) return s->noh;
    if (!strcmp(nm, "voh") || !strcmp(nm, "loh") || !strcmp(nm, "cos")) return s->voh;
    if (!strcmp(nm, "toh")) return s->toh;
    if (!strcmp(nm, "boh")) return s->boh;
    if (!strcmp(nm, "alpha") || !strcmp(nm, "alpha_x")) return s->a;
    if (!strcmp(nm, "alpha_y")) return s->ay;
    if (!strcmp(nm, "gamma")) return s->gamma;
    if (!strcmp(nm, "f0")) return s->f0[c];
    if (!strcmp(nm, "f90")) return s->one;
    if (!strcmp(nm, "albedo")) return s->alb[c];
    return NULL;
}

/* the variant's term per pixel, channel c, direction dir, from source
 * src: 0 the double oracle, 1 f32, 2 f32_fast (batch, active port), 3 fx,
 * 4 fx_fast (inputs rounded to Q15, raised to the domain floors).  Returns
 * 0 if the kernel has no such form. */
static int ie_term(double *t, const scene *s, const facet_kernel *k, int src, int c, int dir, float *o, void *oq,
                   int32_t **q)
{
    const float *in[FACET_MAX_INPUTS];
    long i;
    int j;
    for (j = 0; j < k->n_inputs; j++)
        if (!(in[j] = ie_input(s, k->inputs[j], c, dir)))
            return 0;
    if (src == 0) {
        for (i = 0; i < s->n; i++) {
            double x[FACET_MAX_INPUTS];
            for (j = 0; j < k->n_inputs; j++)
                x[j] = in[j][i];
            t[i] = k->oracle(x);
        }
    } else if (src <= 2) {
        void (*b)(float *, const float *const *, size_t) = src == 1 ? k->f32_batch : k->f32_fast_batch;
        if (!b)
            return 0;
        b(o, in, (size_t)s->n);
        for (i = 0; i < s->n; i++)
            t[i] = o[i];
    } else {
        const facet_fx_kernel *f = facet_fx_kernel_find(k->name);
        void (*b)(void *, const int32_t *const *, size_t);
        if (!f)
            return 0;
        b = src == 3 ? f->fx_batch : f->fx_fast_batch;
        if (!b)
            return 0;
        for (j = 0; j < f->n_inputs; j++)
            for (i = 0; i < s->n; i++)
                q[j][i] = q15_in(in[j][i], f->lo[j], f->hi[j]);
        b(oq, (const int32_t *const *)q, (size_t)s->n);
        for (i = 0; i < s->n; i++) {
            double raw = f->out_bits == 64 ? (double)((const uint64_t *)oq)[i]
                       : f->out_format[0] == 'Q' ? (double)((const int32_t *)oq)[i]
                                                 : (double)((const uint32_t *)oq)[i];
            t[i] = ldexp(raw, -f->out_frac);
        }
    }
    return 1;
}

static int ie_per_channel(const facet_kernel *k)
{
    int j;
    for (j = 0; j < k->n_inputs; j++)
        if (!strcmp(k->inputs[j], "f0") || !strcmp(k->inputs[j], "albedo"))
            return 1;
    return 0;
}

/* codes of D * Vis * F + diffuse per pixel and channel (NULL parts: the
 * base's), the arrays n or 3 x n long */
static void ie_codes(int (*code)[3], const scene *s, const double *D, const double *V, double *const F[3],
                     double *const Df[3])
{
    long i;
    int c;
    for (i = 0; i < s->n; i++)
        for (c = 0; c < 3; c++)
            code[i][c] = code_of(D[i] * V[i] * F[c][i] + Df[c][i], s->nl[i]);
}

/* the exact GTR G1 is a quadrature (~0.1 ms a call): each distinct float
 * (N.V, alpha, gamma) of the scene once (the two materials' spheres share
 * their dots, and a sphere's N.V takes a few hundred values) */
static double g1_gtr_exact_memo(float nov, float alpha, float gamma)
{
    enum { BITS = 16 };
    static struct { float n, a, g; int used; double v; } *tab;
    static long used;
    uint32_t h, b[3];
    if (!tab)
        tab = calloc((size_t)1 << BITS, sizeof *tab);
    if (!tab || used > 3L << (BITS - 2)) /* (no table, or 3/4 full) */
        return facet_oracle_smith_g1_gtr_exact(nov, alpha, gamma);
    memcpy(&b[0], &nov, 4), memcpy(&b[1], &alpha, 4), memcpy(&b[2], &gamma, 4);
    h = (b[0] * 2654435761u) ^ (b[1] * 2246822519u) ^ (b[2] * 3266489917u);
    for (h >>= 32 - BITS;; h = (h + 1) & ((1u << BITS) - 1)) {
        if (!tab[h].used) {
            tab[h].n = nov, tab[h].a = alpha, tab[h].g = gamma, tab[h].used = 1;
            used++;
            tab[h].v = facet_oracle_smith_g1_gtr_exact(nov, alpha, gamma);
            return tab[h].v;
        }
        if (tab[h].n == nov && tab[h].a == alpha && tab[h].g == gamma)
            return tab[h].v;
    }
}

int img_variants_run(img_variant *out, int max, pic *diff, char *port, size_t port_cap)
{
    scene s;
    long n, i;
    int v, c, src, j, rows = 0, nv = 0;
    double *D0, *V0, *F0[3], *Df0[3], *t3[3], *tt, *t1, *Dv, *Vv, *Fv[3], *Dfv[3];
    int (*want)[3], (*got)[3], (*model)[3];
    float *o;
    uint64_t *oq;
    int32_t *q[FACET_MAX_INPUTS];
    scene_make(&s);
    n = s.n;
#define ALLOC_D(p) p = malloc((size_t)n * sizeof(double))
    ALLOC_D(D0), ALLOC_D(V0), ALLOC_D(tt), ALLOC_D(t1), ALLOC_D(Dv), ALLOC_D(Vv);
    for (c = 0; c < 3; c++)
        ALLOC_D(F0[c]), ALLOC_D(Df0[c]), ALLOC_D(t3[c]), ALLOC_D(Fv[c]), ALLOC_D(Dfv[c]);
    want = malloc((size_t)n * sizeof *want);
    got = malloc((size_t)n * sizeof *got);
    model = malloc((size_t)n * sizeof *model);
    o = malloc((size_t)n * sizeof(float));
    oq = malloc((size_t)n * sizeof(uint64_t));
    for (j = 0; j < FACET_MAX_INPUTS; j++)
        q[j] = malloc((size_t)n * sizeof(int32_t));
    /* the base parts, double oracles at the float dots */
    for (i = 0; i < n; i++) {
        D0[i] = facet_oracle_ggx_d(s.noh[i], s.a[i]);
        V0[i] = facet_oracle_smith_vis(s.nl[i], s.nv[i], s.a[i]);
        for (c = 0; c < 3; c++) {
            F0[c][i] = facet_oracle_fresnel_schlick(s.f0[c][i], s.voh[i]);
            Df0[c][i] = facet_oracle_diffuse_hammon(s.nl[i], s.nv[i], s.lv[i], s.a[i], s.alb[c][i]);
        }
    }
    facet_set_port("auto");
    snprintf(port, port_cap, "%s", facet_port_name());
    *diff = (pic){ 0 };
    diff->w = IE_NA * IE_NM * (IE_S + IE_GAP) + IE_GAP;
    diff->h = 24 * (IE_S + IE_GAP) + IE_GAP;
    diff->rgb = calloc((size_t)diff->w * (size_t)diff->h * 3, 1);
    memset(diff->rgb, 24, (size_t)diff->w * (size_t)diff->h * 3);
    for (v = 0; v < kf_variant_count() && nv < max; v++) {
        const kf_variant *fv = kf_variant_at(v);
        const facet_kernel *k = facet_kernel_find(fv->kernel);
        img_variant *r = &out[nv];
        int role = fv->role, pc;
        if (!k)
            continue;
        memset(r, 0, sizeof *r);
        pc = ie_per_channel(k);
        snprintf(r->name, sizeof r->name, "%s", fv->name);
        snprintf(r->term, sizeof r->term, "%s", fv->role_name);
        snprintf(r->reference, sizeof r->reference, "%s", fv->ref_name);
        for (i = 0; i < n; i++)
            s.gamma[i] = (float)(fv->gamma > 0 ? fv->gamma : 2);
        /* the variant's own D for the G1s of another distribution */
        for (i = 0; i < n; i++)
            Dv[i] = fv->ref == KF_REF_G1_BECKMANN ? facet_oracle_beckmann_d(s.noh[i], s.a[i])
                  : fv->ref == KF_REF_G1_GTR ? facet_oracle_gtr_d(s.noh[i], s.a[i], s.gamma[i]) : D0[i];
        /* src 0 (the oracle) first: the reference of the implementation rows */
        for (src = 0; src <= 4; src++) {
            int okk = 1;
            for (c = 0; c < 3 && okk; c++) {
                if (c > 0 && !pc) {
                    memcpy(t3[c], t3[0], (size_t)n * sizeof(double));
                    continue;
                }
                if (role == KF_ROLE_G1) {
                    okk = ie_term(tt, &s, k, src, c, 1, o, oq, q) && ie_term(t1, &s, k, src, c, 0, o, oq, q);
                    for (i = 0; okk && i < n; i++)
                        t3[c][i] = tt[i] * t1[i] / (4.0 * s.nl[i] * s.nv[i]);
                } else {
                    okk = ie_term(t3[c], &s, k, src, c, 0, o, oq, q);
                    if (role == KF_ROLE_G2)
                        for (i = 0; okk && i < n; i++)
                            t3[c][i] /= 4.0 * s.nl[i] * s.nv[i];
                }
            }
            if (!okk)
                continue;
            /* assemble: the variant's part replaces the base's */
            memcpy(Vv, V0, (size_t)n * sizeof(double));
            for (c = 0; c < 3; c++) {
                memcpy(Fv[c], F0[c], (size_t)n * sizeof(double));
                memcpy(Dfv[c], Df0[c], (size_t)n * sizeof(double));
            }
            {
                const double *Duse = Dv;
                if (role == KF_ROLE_D)
                    Duse = t3[0];
                else if (role == KF_ROLE_VIS || role == KF_ROLE_G2 || role == KF_ROLE_G1)
                    memcpy(Vv, t3[0], (size_t)n * sizeof(double));
                else if (role == KF_ROLE_F)
                    for (c = 0; c < 3; c++)
                        memcpy(Fv[c], t3[c], (size_t)n * sizeof(double));
                else
                    for (c = 0; c < 3; c++)
                        memcpy(Dfv[c], t3[c], (size_t)n * sizeof(double));
                ie_codes(src ? got : want, &s, Duse, Vv, Fv, Dfv);
            }
            if (src) {
                compare(&r->impl[src - 1], (const int (*)[3])got, (const int (*)[3])want, n);
                r->have[src - 1] = 1;
            }
        }
        /* the model row: the variant's oracle render against the reference's */
        if (fv->ref != KF_REF_NONE) {
            const double *Duse = Dv;
            memcpy(Vv, V0, (size_t)n * sizeof(double));
            for (c = 0; c < 3; c++) {
                memcpy(Fv[c], F0[c], (size_t)n * sizeof(double));
                memcpy(Dfv[c], Df0[c], (size_t)n * sizeof(double));
            }
            for (i = 0; i < n; i++)
                switch (fv->ref) {
                case KF_REF_GGX_D: tt[i] = facet_oracle_ggx_d(s.noh[i], s.a[i]); break;
                case KF_REF_VIS: Vv[i] = V0[i]; break;
                case KF_REF_G1_BECKMANN:
                    Vv[i] = facet_oracle_smith_g1_beckmann_exact(s.nl[i], s.a[i]) *
                            facet_oracle_smith_g1_beckmann_exact(s.nv[i], s.a[i]) / (4.0 * s.nl[i] * s.nv[i]);
                    break;
                case KF_REF_G1_GTR:
                    Vv[i] = g1_gtr_exact_memo(s.nl[i], s.a[i], s.gamma[i]) *
                            g1_gtr_exact_memo(s.nv[i], s.a[i], s.gamma[i]) / (4.0 * s.nl[i] * s.nv[i]);
                    break;
                case KF_REF_FRESNEL:
                    for (c = 0; c < 3; c++)
                        Fv[c][i] = facet_oracle_fresnel_cook_torrance(s.f0[c][i], s.voh[i]);
                    break;
                }
            if (fv->ref == KF_REF_GGX_D)
                Duse = tt;
            ie_codes(model, &s, Duse, Vv, Fv, Dfv);
            compare(&r->model, (const int (*)[3])want, (const int (*)[3])model, n);
            r->has_model = 1;
            r->is_reference = fv->is_reference;
            /* the figure: every variant that is not the reference itself (all-blue rows: identical) */
            if (!r->is_reference && rows < 24) {
                diff_place(diff, &s, (const int (*)[3])want, (const int (*)[3])model, rows);
                snprintf(diff->ax.row_title[rows], sizeof diff->ax.row_title[rows], "%s", r->name);
                rows++;
            }
        }
        nv++;
    }
    diff->h = rows * (IE_S + IE_GAP) + IE_GAP;
    for (j = 0; j < IE_NA * IE_NM && j < 12; j++)
        snprintf(diff->ax.col_title[j], sizeof diff->ax.col_title[j], "%s %g", j < IE_NA ? "diel." : "gold",
                 ie_alpha[j % IE_NA]);
    diff->ax.cols = IE_NA * IE_NM;
    diff->ax.rows = rows;
    diff->ax.x0 = diff->ax.y0 = IE_GAP;
    diff->ax.pw = diff->ax.ph = IE_S;
    diff->ax.gap = IE_GAP;
    snprintf(diff->title, sizeof diff->title, "Model error in image space: each variant against its exact reference");
    snprintf(diff->caption, sizeof diff->caption,
             "Rows: the menu's variants that approximate a reference term (both rendered from double oracles; the "
             "other parts of D * Vis * F + diffuse are the base's: GGX D, exact height-correlated Smith Vis, Schlick "
             "F, Hammon diffuse). Per lit pixel, the largest code difference of the three channels, x 32 (grey 32 = "
             "1 code, white >= 8 codes); dark blue: lit and identical. Columns as the reference spheres.");
    for (j = 0; j < FACET_MAX_INPUTS; j++)
        free(q[j]);
    free(oq), free(o), free(model), free(got), free(want);
    free(D0), free(V0), free(tt), free(t1), free(Dv), free(Vv);
    for (c = 0; c < 3; c++)
        free(F0[c]), free(Df0[c]), free(t3[c]), free(Fv[c]), free(Dfv[c]);
    scene_free(&s);
    return nv;
}
