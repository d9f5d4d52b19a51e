/* pictures.c - see pictures.h. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "facet/scalar.h"
#include "facet/oracle.h"
#include "facet/fx.h"
#include "harness/bench.h"
#include "pictures.h"

#define PI_ 3.14159265358979323846

static pic pic_new(int w, int h)
{
    pic p;
    memset(&p, 0, sizeof p);
    p.w = w;
    p.h = h;
    p.rgb = calloc((size_t)w * (size_t)h * 3, 1);
    return p;
}

void pic_free(pic *p)
{
    free(p->rgb);
    p->rgb = NULL;
}

/* the panel grid of a picture, for the report's labels (pictures.h) */
static void grid(pic *p, int cols, int rows, int S, int gap)
{
    p->ax.cols = cols;
    p->ax.rows = rows;
    p->ax.x0 = gap;
    p->ax.y0 = gap;
    p->ax.pw = S;
    p->ax.ph = S;
    p->ax.gap = gap;
}

static void put(pic *p, int x, int y, const double c[3])
{
    unsigned char *q;
    int k;
    if (x < 0 || y < 0 || x >= p->w || y >= p->h)
        return;
    q = p->rgb + ((size_t)y * (size_t)p->w + (size_t)x) * 3;
    for (k = 0; k < 3; k++) {
        double v = c[k];
        v = v <= 0 ? 0 : v >= 1 ? 1 : v;
        q[k] = (unsigned char)(v * 255 + 0.5);
    }
}

/* linear -> sRGB-encoded, clamped to [0, 1] (pictures.h) */
double pic_srgb(double x)
{
    if (!(x > 0))
        return 0;
    if (x >= 1)
        return 1;
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1 / 2.4) - 0.055;
}

/* a perceptual-ish ramp (dark blue -> teal -> yellow -> white), t in [0, 1] */
static void ramp(double t, double c[3])
{
    static const double k[5][3] = {
        { 0.05, 0.03, 0.20 }, { 0.20, 0.25, 0.60 }, { 0.10, 0.60, 0.55 }, { 0.95, 0.85, 0.20 },
        { 1.00, 1.00, 1.00 },
    };
    double s;
    int i;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    s = t * 4;
    i = (int)s;
    if (i > 3)
        i = 3;
    s -= i;
    c[0] = k[i][0] + s * (k[i + 1][0] - k[i][0]);
    c[1] = k[i][1] + s * (k[i + 1][1] - k[i][1]);
    c[2] = k[i][2] + s * (k[i + 1][2] - k[i][2]);
}

/* log10 error in [-7, 0] -> colour */
static void err_colour(double e, double c[3])
{
    double l = e > 0 ? log10(e) : -8;
    ramp((l + 7) / 7, c);
}

/* (theta_h, theta_d, phi_d) -> (N.L, N.V, L.V) */
static void half_diff(double th, double td, double pd, double *nl, double *nv, double *lv)
{
    /* H at (th, 0); L, V symmetric about H at angle td, azimuth pd around H */
    double h[3] = { sin(th), 0, cos(th) }, b[3] = { cos(th), 0, -sin(th) }, t[3] = { 0, 1, 0 };
    double d[3], L[3], V[3];
    int k;
    for (k = 0; k < 3; k++)
        d[k] = sin(td) * (cos(pd) * b[k] + sin(pd) * t[k]);
    for (k = 0; k < 3; k++) {
        L[k] = cos(td) * h[k] + d[k];
        V[k] = cos(td) * h[k] - d[k];
    }
    *nl = L[2];
    *nv = V[2];
    *lv = L[0] * V[0] + L[1] * V[1] + L[2] * V[2];
}

/* the variants shown in slices and spheres */
#define N_VAR 5
static const char *var_name[N_VAR] = {
    "brdf_hammon (all)", "spec: D Vis_hammon F", "spec: D Vis_exact F", "diffuse_hammon", "lambert",
};

static double variant(int v, double nl, double nv, double lv, double a, double f0, double alb)
{
    float fnl = (float)nl, fnv = (float)nv, flv = (float)lv, fa = (float)a;
    float noh = facet_noh_from_dots_f32_scalar(fnl, fnv, flv);
    float loh = facet_loh_from_dots_f32_scalar(flv);
    float F = facet_fresnel_schlick_f32_scalar((float)f0, loh);
    float D = facet_ggx_d_f32_scalar(noh, fa);
    switch (v) {
    case 0: return facet_brdf_hammon_f32_scalar(fnl, fnv, flv, fa, (float)f0, (float)alb);
    case 1: return (double)D * facet_smith_vis_hammon_f32_scalar(fnl, fnv, fa) * F;
    case 2: return (double)D * facet_smith_vis_f32_scalar(fnl, fnv, fa) * F;
    case 3: return facet_diffuse_hammon_f32_scalar(fnl, fnv, flv, fa, (float)alb);
    default: return facet_lambert_f32_scalar((float)alb);
    }
}

pic pic_slices(void)
{
    static const double alphas[3] = { 0.05, 0.25, 0.6 };
    int S = 96, gap = 4, v, ai, x, y;
    pic p = pic_new(3 * (S + gap) + gap, N_VAR * (S + gap) + gap);
    for (v = 0; v < N_VAR; v++)
        for (ai = 0; ai < 3; ai++)
            for (y = 0; y < S; y++)
                for (x = 0; x < S; x++) {
                    double th = (x + 0.5) / S * (PI_ / 2), td = (y + 0.5) / S * (PI_ / 2);
                    double nl, nv, lv, f, c[3];
                    half_diff(th, td, PI_ / 2, &nl, &nv, &lv);
                    if (nl <= 0 || nv <= 0) {
                        c[0] = c[1] = c[2] = 0.12;
                    } else {
                        f = variant(v, nl, nv, lv, alphas[ai], 0.04, 0.8);
                        /* log tone: f in [1e-3, 1e3] -> [0, 1] */
                        ramp((log10(f > 1e-6 ? f : 1e-6) + 3) / 6, c);
                    }
                    put(&p, gap + ai * (S + gap) + x, gap + v * (S + gap) + y, c);
                }
    grid(&p, 3, N_VAR, S, gap);
    for (ai = 0; ai < 3; ai++)
        snprintf(p.ax.col_title[ai], sizeof p.ax.col_title[ai], "alpha = %g", alphas[ai]);
    for (v = 0; v < N_VAR; v++)
        snprintf(p.ax.row_title[v], sizeof p.ax.row_title[v], "%s", var_name[v]);
    snprintf(p.ax.xlabel, sizeof p.ax.xlabel, "theta_h (deg)");
    snprintf(p.ax.ylabel, sizeof p.ax.ylabel, "theta_d (deg)");
    p.ax.xmin = 0, p.ax.xmax = 90, p.ax.ymin = 90, p.ax.ymax = 0; /* theta_d grows downwards */
    p.ax.bar_lo = -3, p.ax.bar_hi = 3;
    snprintf(p.ax.bar_label, sizeof p.ax.bar_label, "BRDF value (1/sr)");
    snprintf(p.title, sizeof p.title, "BRDF slices");
    snprintf(p.caption, sizeof p.caption,
             "Disney-style slices: theta_h 0..90 deg across, theta_d 0..90 deg down, phi_d = 90 deg. "
             "Columns alpha = 0.05, 0.25, 0.6; rows: %s; %s; %s; %s; %s. f0 = 0.04, albedo = 0.8. "
             "Colour: log10 BRDF from -3 (dark) to +3 (white); grey: below the horizon.",
             var_name[0], var_name[1], var_name[2], var_name[3], var_name[4]);
    return p;
}

pic pic_spheres(void)
{
    static const double alphas[6] = { 0.02, 0.06, 0.15, 0.3, 0.6, 1.0 };
    int S = 72, gap = 4, v, ai, x, y;
    double Ld[3] = { -0.45, 0.55, 0.70 }, l;
    pic p = pic_new(6 * (S + gap) + gap, N_VAR * (S + gap) + gap);
    l = sqrt(Ld[0] * Ld[0] + Ld[1] * Ld[1] + Ld[2] * Ld[2]);
    Ld[0] /= l; Ld[1] /= l; Ld[2] /= l;
    memset(p.rgb, 24, (size_t)p.w * (size_t)p.h * 3);
    for (v = 0; v < N_VAR; v++)
        for (ai = 0; ai < 6; ai++)
            for (y = 0; y < S; y++)
                for (x = 0; x < S; x++) {
                    double u = (x + 0.5) / S * 2 - 1, w = 1 - (y + 0.5) / S * 2, r2 = u * u + w * w;
                    double n[3], nl, nv, lv, f, c[3];
                    if (r2 >= 1)
                        continue;
                    n[0] = u; n[1] = w; n[2] = sqrt(1 - r2);
                    nl = n[0] * Ld[0] + n[1] * Ld[1] + n[2] * Ld[2];
                    nv = n[2];
                    lv = Ld[2];
                    if (nl <= 0) {
                        f = 0;
                    } else {
                        f = variant(v, nl, nv, lv, alphas[ai], 0.04, 0.7) * nl * 2.2;
                    }
                    c[0] = c[1] = c[2] = pic_srgb(f + 0.02);
                    put(&p, gap + ai * (S + gap) + x, gap + v * (S + gap) + y, c);
                }
    grid(&p, 6, N_VAR, S, gap);
    for (ai = 0; ai < 6; ai++)
        snprintf(p.ax.col_title[ai], sizeof p.ax.col_title[ai], "alpha = %g", alphas[ai]);
    for (v = 0; v < N_VAR; v++)
        snprintf(p.ax.row_title[v], sizeof p.ax.row_title[v], "%s", var_name[v]);
    snprintf(p.title, sizeof p.title, "Lit spheres across alpha");
    snprintf(p.caption, sizeof p.caption,
             "One directional light from the upper left, view along the axis, radiance = BRDF * N.L * 2.2, "
             "sRGB, no tone curve. Columns alpha = 0.02, 0.06, 0.15, 0.3, 0.6, 1.0; rows: %s; %s; %s; %s; %s.",
             var_name[0], var_name[1], var_name[2], var_name[3], var_name[4]);
    return p;
}

static const char *hm_name[PIC_N_HEATMAPS] = {
    "Vis: Hammon vs exact correlated Smith",
    "G2: uncorrelated vs height-correlated Smith",
    "G1: Hammon (Schlick-GGX k = alpha/2) vs exact Smith",
    "Diffuse: Lambert vs Hammon's GGX diffuse",
    "BRDF: brdf_hammon vs the exact-Vis model",
};

/* the model error of approximation `which` at one point (double, oracle) */
static double model_err(int which, double nl, double nv, double a)
{
    double lv = nl * nv; /* phi = 90 deg between L and V */
    switch (which) {
    case 0: return bench_rel_err(facet_oracle_smith_vis_hammon(nl, nv, a), facet_oracle_smith_vis(nl, nv, a));
    case 1: return bench_rel_err(facet_oracle_smith_g2_uncorrelated(nl, nv, a), facet_oracle_smith_g2(nl, nv, a));
    case 2: return bench_rel_err(facet_oracle_smith_g1_hammon(nl, a), facet_oracle_smith_g1(nl, a));
    case 3: return bench_rel_err(facet_oracle_lambert(0.8), facet_oracle_diffuse_hammon(nl, nv, lv, a, 0.8));
    default: return bench_rel_err(facet_oracle_brdf_hammon(nl, nv, lv, a, 0.04, 0.8),
                                  bench_oracle_brdf_exact(nl, nv, lv, a, 0.04, 0.8));
    }
}

/* Four square panels side by side, one per alpha; cell() gives the value
 * err_colour() maps at (N.L, N.V) = ((x + 0.5)/S, 1 - (y + 0.5)/S). */
typedef double (*panel_cell)(const void *ctx, double nl, double nv, double a, int y, int S);

static pic panels(const double alphas[4], panel_cell cell, const void *ctx)
{
    int S = 96, gap = 4, ai, x, y;
    pic p = pic_new(4 * (S + gap) + gap, S + 2 * gap);
    memset(p.rgb, 255, (size_t)p.w * (size_t)p.h * 3);
    for (ai = 0; ai < 4; ai++)
        for (y = 0; y < S; y++)
            for (x = 0; x < S; x++) {
                double c[3];
                err_colour(cell(ctx, (x + 0.5) / S, 1 - (y + 0.5) / S, alphas[ai], y, S), c);
                put(&p, gap + ai * (S + gap) + x, gap + y, c);
            }
    grid(&p, 4, 1, S, gap);
    for (ai = 0; ai < 4; ai++)
        snprintf(p.ax.col_title[ai], sizeof p.ax.col_title[ai], "alpha = %g", alphas[ai]);
    snprintf(p.ax.xlabel, sizeof p.ax.xlabel, "N.L");
    snprintf(p.ax.ylabel, sizeof p.ax.ylabel, "N.V");
    p.ax.xmin = 0, p.ax.xmax = 1, p.ax.ymin = 0, p.ax.ymax = 1;
    p.ax.bar_lo = -7, p.ax.bar_hi = 0;
    snprintf(p.ax.bar_label, sizeof p.ax.bar_label, "relative error");
    return p;
}

static double model_cell(const void *ctx, double nl, double nv, double a, int y, int S)
{
    int which = *(const int *)ctx;
    if (which == 2) /* G1 has one cosine: x = N.V, y = alpha (log, 2^-10..1) */
        return model_err(which, nl, nl, pow(2.0, -10.0 * (y + 0.5) / S));
    return model_err(which, nl, nv, a);
}

pic pic_heatmap(int which)
{
    static const double alphas[4] = { 0.02, 0.1, 0.4, 1.0 };
    pic p = panels(alphas, model_cell, &which);
    snprintf(p.title, sizeof p.title, "%s", hm_name[which]);
    if (which == 2) { /* one cosine: the panels are all the same (N.V, alpha) map */
        p.ax.cols = 1;
        snprintf(p.ax.col_title[0], sizeof p.ax.col_title[0], "every alpha");
        snprintf(p.ax.xlabel, sizeof p.ax.xlabel, "N.V");
        snprintf(p.ax.ylabel, sizeof p.ax.ylabel, "alpha");
        p.ax.ymin = 1.0 / 1024, p.ax.ymax = 1, p.ax.ylog = 1;
    } else if (which >= 3) {
        snprintf(p.ax.xlabel, sizeof p.ax.xlabel, "N.L (L.V = N.L N.V)");
    }
    if (which == 2)
        snprintf(p.caption, sizeof p.caption,
                 "Relative model error, log10 from -7 (dark) to 0 (white). x: N.V 0..1; y: alpha "
                 "from 1 (top) to 2^-10 (bottom), log scale (the four panels are identical).");
    else
        snprintf(p.caption, sizeof p.caption,
                 "Relative model error over N.L (x, 0..1) and N.V (y, 0 at the bottom), log10 from "
                 "-7 (dark) to 0 (white); panels alpha = 0.02, 0.1, 0.4, 1.0%s.",
                 which >= 3 ? "; L.V = N.L N.V (L and V 90 deg apart in azimuth), albedo 0.8, f0 0.04" : "");
    return p;
}

/* L.V in the plane of incidence with L and V mirror-symmetric in azimuth,
 * so that N.H ~ 1 along the diagonal N.L = N.V (the specular peak) */
static double mirror_lov(double nl, double nv)
{
    return nl * nv - sqrt((1.0 - nl * nl) * (1.0 - nv * nv));
}

static double f32_cell(const void *ctx, double dnl, double dnv, double da, int y, int S)
{
    float nl = (float)dnl, nv = (float)dnv, a = (float)da;
    float lv = (float)mirror_lov(nl, nv);
    (void)ctx, (void)y, (void)S;
    /* shifted by 1e3: -10 .. -3 mapped onto the bar */
    return 1e3 * bench_rel_err(facet_brdf_hammon_f32_scalar(nl, nv, lv, a, 0.04f, 0.8f),
                               facet_oracle_brdf_hammon(nl, nv, lv, a, 0.04, 0.8));
}

pic pic_heatmap_f32(void)
{
    static const double alphas[4] = { 0.001, 0.02, 0.2, 1.0 };
    pic p = panels(alphas, f32_cell, NULL);
    p.ax.bar_lo = -10, p.ax.bar_hi = -3;
    snprintf(p.ax.xlabel, sizeof p.ax.xlabel, "N.L (plane of incidence)");
    snprintf(p.title, sizeof p.title, "brdf_hammon f32 (scalar) vs oracle");
    snprintf(p.caption, sizeof p.caption,
             "Relative arithmetic error of the f32 kernel, log10 from -10 (dark) to -3 (white), over N.L "
             "(x) and N.V (y) in the plane of incidence (L, V mirror-symmetric in azimuth, so the specular "
             "peak lies on the diagonal); panels alpha = 2^-10, 0.02, 0.2, 1.");
    return p;
}

static int32_t q15(double x)
{
    return (int32_t)floor(x * 32768.0 + 0.5); /* ties up, the fx.h rule */
}

static double fx_cell(const void *ctx, double nl, double nv, double a, int y, int S)
{
    int which = *(const int *)ctx;
    double lv = mirror_lov(nl, nv), got;
    int32_t in[6];
    (void)y, (void)S;
    in[0] = q15(nl); in[1] = q15(nv); in[2] = q15(lv);
    in[3] = q15(a); in[4] = q15(0.04); in[5] = q15(0.8);
    if (in[0] < FACET_FX_COS_MIN) in[0] = FACET_FX_COS_MIN;
    if (in[1] < FACET_FX_COS_MIN) in[1] = FACET_FX_COS_MIN;
    if (in[3] < FACET_FX_ALPHA_MIN) in[3] = FACET_FX_ALPHA_MIN;
    got = ldexp((double)facet_brdf_hammon_fx(in[0], in[1], in[2], in[3], in[4], in[5]), -24);
    if (which == 0) /* -10 .. -3, as the f32 map */
        return 1e3 * bench_rel_err(got, facet_oracle_brdf_hammon(in[0] / 32768.0, in[1] / 32768.0,
                                                                 in[2] / 32768.0, in[3] / 32768.0,
                                                                 in[4] / 32768.0, in[5] / 32768.0));
    return bench_rel_err(got, facet_oracle_brdf_hammon(nl, nv, lv, a, 0.04, 0.8));
}

pic pic_heatmap_fx(int which)
{
    static const double alphas[4] = { 0.001, 0.02, 0.2, 1.0 };
    pic p = panels(alphas, fx_cell, &which);
    snprintf(p.ax.xlabel, sizeof p.ax.xlabel, "N.L (plane of incidence)");
    if (which == 0) {
        p.ax.bar_lo = -10, p.ax.bar_hi = -3;
        snprintf(p.title, sizeof p.title, "brdf_hammon fixed point vs oracle at the same Q15 inputs");
        snprintf(p.caption, sizeof p.caption,
                 "Relative arithmetic error of facet_brdf_hammon_fx (UQ40.24) against the double oracle "
                 "evaluated at the same Q15 inputs, log10 from -10 (dark) to -3 (white); same geometry as "
                 "the f32 map (plane of incidence, specular peak on the diagonal); panels alpha = 0.001 "
                 "(Q15: 33 = 2^-10 + 1 LSB), 0.02, 0.2, 1; f0 0.04, albedo 0.8.");
    } else {
        snprintf(p.title, sizeof p.title, "brdf_hammon fixed point incl. Q15 input rounding vs oracle");
        snprintf(p.caption, sizeof p.caption,
                 "Relative error of facet_brdf_hammon_fx fed with the dots rounded to Q15 (N.L, N.V raised "
                 "to the fx floor 2^-8) against the oracle at the unrounded dots, log10 from -7 (dark) to 0 "
                 "(white): what a renderer sees. The input rounding dominates at the sharp peak of small "
                 "alpha and at grazing angles; panels alpha = 0.001, 0.02, 0.2, 1.");
    }
    return p;
}

pic pic_colorbar(int W, int H)
{
    int x, y;
    pic p = pic_new(W, H);
    for (x = 0; x < W; x++)
        for (y = 0; y < H; y++) {
            double c[3];
            ramp((x + 0.5) / W, c);
            put(&p, x, y, c);
        }
    snprintf(p.title, sizeof p.title, "colour bar");
    return p;
}
