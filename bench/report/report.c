/* report.c - `facet-bench report OUTDIR [--quick]`: the benchmark part of
 * `make report`.  Runs every benchmark (bench.c), the model-error sweep of
 * every approximation, the pictures and the rasterizer, reads the modelled
 * cycles and code sizes that bench/report/report.sh left in OUTDIR (mca.tsv,
 * size.tsv, arm.tsv), and writes OUTDIR/bench.md, OUTDIR/index.html (self-
 * contained: inline SVG, PNGs as data URIs) and the PNG files. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "facet.h"
#include "facet/oracle.h"
#include "harness/bench.h"
#include "harness/cycles.h"
#include "pictures.h"
#include "image_error.h"
#include "geom.h"
#include "png.h"
#include "raster/raster.h"
#include "samplers.h"
#include "facet_bench.h"

#define PI_REPORT 3.14159265358979323846

static const char *outdir;
static FILE *md, *html;
static int quick;
static double tpc = 1.0;

static void say(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("report: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
}

/* ---- output helpers: every table goes to both Markdown and HTML ---------- */

static void both(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfprintf(md, fmt, ap);
    va_end(ap);
    va_start(ap, fmt);
    vfprintf(html, fmt, ap);
    va_end(ap);
}

static void h2(const char *t)
{
    fprintf(md, "\n## %s\n\n", t);
    fprintf(html, "<h2>%s</h2>\n", t);
}

static void para(const char *fmt, ...)
{
    char buf[4096];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    fprintf(md, "%s\n\n", buf);
    fprintf(html, "<p>%s</p>\n", buf);
}

static int tcols;
static void thead(int n, ...)
{
    va_list ap;
    int i;
    tcols = n;
    va_start(ap, n);
    fprintf(html, "<table><tr>");
    for (i = 0; i < n; i++) {
        const char *c = va_arg(ap, const char *);
        fprintf(md, "| %s ", c);
        fprintf(html, "<th>%s</th>", c);
    }
    va_end(ap);
    fprintf(md, "|\n");
    for (i = 0; i < n; i++)
        fprintf(md, "|---");
    fprintf(md, "|\n");
    fprintf(html, "</tr>\n");
}

static void trow(const char *cells[])
{
    int i;
    fprintf(html, "<tr>");
    for (i = 0; i < tcols; i++) {
        fprintf(md, "| %s ", cells[i]);
        fprintf(html, "<td>%s</td>", cells[i]);
    }
    fprintf(md, "|\n");
    fprintf(html, "</tr>\n");
}

static void tend(void)
{
    fprintf(md, "\n");
    fprintf(html, "</table>\n");
}

static char *fmt(char *b, size_t n, const char *f, ...)
{
    va_list ap;
    va_start(ap, f);
    vsnprintf(b, n, f, ap);
    va_end(ap);
    return b;
}

static const char *g3(char *b, double x)
{
    if (x != x)
        return strcpy(b, "nan");
    if (isinf(x))
        return strcpy(b, "inf");
    snprintf(b, 32, "%.3g", x);
    return b;
}

/* ---- labelled figures: the PNG inside an SVG with its titles, axes and
 * colour bar (pictures.h pic_axes) ------------------------------------------ */

/* tick values for [lo, hi] (either order): "nice" steps for a linear scale,
 * powers of 10 for a log one; returns the count */
static int ticks(double lo, double hi, int logscale, double *t, int max)
{
    double a = lo < hi ? lo : hi, b = lo < hi ? hi : lo, step, v;
    int n = 0;
    if (logscale) {
        for (v = ceil(log10(a) - 1e-9); v <= log10(b) + 1e-9 && n < max; v++)
            t[n++] = pow(10, v);
        return n;
    }
    step = pow(10, floor(log10((b - a) / 3)));
    if ((b - a) / step > 7)
        step *= (b - a) / step > 15 ? 5 : 2;
    if (b - a == 90)
        step = 30; /* degrees */
    for (v = ceil(a / step - 1e-9) * step; v <= b + 1e-9 * step && n < max; v += step)
        t[n++] = fabs(v) < 1e-12 ? 0 : v;
    return n;
}

/* where value v falls along a panel edge of `len` pixels running from `from`
 * to `to` (log10 scale if lg) */
static double along(double v, double from, double to, int lg, int len)
{
    if (lg)
        return (log10(v) - log10(from)) / (log10(to) - log10(from)) * len;
    return (v - from) / (to - from) * len;
}

static void svg_tick_label(FILE *f, double x, double y, const char *anchor, double v, int lg)
{
    if (lg)
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"%s\">10<tspan dy=\"-5\" font-size=\"8\">%g</tspan></text>",
                x, y, anchor, log10(v));
    else
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"%s\">%g</text>", x, y, anchor, v);
}

static void svg_figure(const pic *p, const char *b64)
{
    const pic_axes *a = &p->ax;
    int sc = p->w <= 460 ? 2 : 1, r, c, i, n;
    int rowt = 0, L, T = 22, B, W, H, bar = a->bar_label[0] != 0;
    int has_x = a->xlabel[0] != 0, has_y = a->ylabel[0] != 0;
    double t[16];
    for (r = 0; r < a->rows; r++)
        if ((int)strlen(a->row_title[r]) > rowt)
            rowt = (int)strlen(a->row_title[r]);
    L = 8 + (rowt ? rowt * 7 + 8 : 0) + (has_y ? 52 : 0);
    B = (has_x ? 38 : 4) + (bar ? 48 : 0);
    W = L + p->w * sc + 12;
    H = T + p->h * sc + B;
    fprintf(html, "<figure><svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
                  "font-family=\"sans-serif\" font-size=\"11\">", W, H);
    fprintf(html, "<image x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" style=\"image-rendering:pixelated\" "
                  "href=\"data:image/png;base64,%s\"/>", L, T, p->w * sc, p->h * sc, b64 ? b64 : "");
    for (c = 0; c < a->cols; c++) /* column titles */
        fprintf(html, "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%s</text>",
                L + (a->x0 + c * (a->pw + a->gap) + a->pw / 2.0) * sc, T - 6, a->col_title[c]);
    for (r = 0; r < a->rows; r++) /* row titles */
        if (a->row_title[r][0])
            fprintf(html, "<text x=\"6\" y=\"%.1f\">%s</text>",
                    T + (a->y0 + r * (a->ph + a->gap) + a->ph / 2.0) * sc + 4, a->row_title[r]);
    if (has_x) { /* x ticks under the bottom row of every column */
        double yb = T + (a->y0 + a->rows * (a->ph + a->gap) - a->gap) * sc;
        n = ticks(a->xmin, a->xmax, a->xlog, t, 16);
        for (c = 0; c < a->cols; c++) {
            for (i = 0; i < n; i++) {
                double u = along(t[i], a->xmin, a->xmax, a->xlog, a->pw);
                double x = L + (a->x0 + c * (a->pw + a->gap) + u) * sc;
                if (c + 1 < a->cols && u > a->pw - 0.5)
                    continue; /* the next panel's first label stands there */
                fprintf(html, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#333\"/>", x, yb, x, yb + 4);
                svg_tick_label(html, x, yb + 15, "middle", t[i], a->xlog);
            }
            fprintf(html, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-style=\"italic\">%s</text>",
                    L + (a->x0 + c * (a->pw + a->gap) + a->pw / 2.0) * sc, yb + 30, a->xlabel);
        }
    }
    if (has_y) { /* y ticks left of the first column, every row */
        double xl = L + a->x0 * sc;
        n = ticks(a->ymin, a->ymax, a->ylog, t, 16);
        for (r = 0; r < a->rows; r++) {
            double y0 = T + (a->y0 + r * (a->ph + a->gap)) * sc;
            for (i = 0; i < n; i++) {
                double v = along(t[i], a->ymin, a->ymax, a->ylog, a->ph);
                double y = y0 + (a->ph - v) * sc;
                if (r > 0 && v > a->ph - 0.5)
                    continue; /* the row above ends with this label */
                fprintf(html, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#333\"/>", xl - 4, y, xl, y);
                svg_tick_label(html, xl - 6, y + 4, "end", t[i], a->ylog);
            }
            fprintf(html, "<text transform=\"translate(%.1f,%.1f) rotate(-90)\" text-anchor=\"middle\" "
                          "font-style=\"italic\">%s</text>", xl - 40, y0 + a->ph * sc / 2.0, a->ylabel);
        }
    }
    if (bar) { /* the colour bar with a labelled tick per power of ten */
        int bw = p->w * sc < 420 ? p->w * sc : 420, bh = 12, k;
        double by = T + p->h * sc + (has_x ? 38 : 4) + 4;
        pic cb = pic_colorbar(bw, bh);
        unsigned char *buf;
        size_t nb = png_encode(&buf, cb.rgb, cb.w, cb.h);
        char *cb64 = nb ? png_base64(buf, nb) : NULL;
        fprintf(html, "<image x=\"%d\" y=\"%.1f\" width=\"%d\" height=\"%d\" href=\"data:image/png;base64,%s\"/>",
                L, by, bw, bh, cb64 ? cb64 : "");
        for (k = (int)ceil(a->bar_lo); k <= (int)floor(a->bar_hi); k++) {
            double x = L + (k - a->bar_lo) / (a->bar_hi - a->bar_lo) * bw;
            fprintf(html, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#333\"/>", x, by + bh, x, by + bh + 4);
            svg_tick_label(html, x, by + bh + 15, "middle", pow(10, k), 1);
        }
        fprintf(html, "<text x=\"%d\" y=\"%.1f\">%s</text>", L + bw + 8, by + 10, a->bar_label);
        free(cb64);
        if (nb)
            free(buf);
        pic_free(&cb);
    }
    fprintf(html, "</svg><figcaption><b>%s.</b> %s</figcaption></figure>\n", p->title, p->caption);
}

/* a PNG written to OUTDIR/name and inlined in the HTML (inside a labelled
 * SVG figure when the picture describes its panels) */
static void picture(const pic *p, const char *name)
{
    unsigned char *buf;
    size_t n = png_encode(&buf, p->rgb, p->w, p->h);
    char path[1024];
    char *b64;
    if (!n)
        return;
    snprintf(path, sizeof path, "%s/%s", outdir, name);
    {
        FILE *f = fopen(path, "wb");
        if (f) {
            if (fwrite(buf, 1, n, f) != n)
                say("short write: %s", path);
            fclose(f);
        }
    }
    b64 = png_base64(buf, n);
    if (p->ax.cols > 0)
        svg_figure(p, b64);
    else
        fprintf(html, "<figure><img alt=\"%s\" src=\"data:image/png;base64,%s\"><figcaption><b>%s.</b> %s</figcaption></figure>\n",
            p->title, b64 ? b64 : "", p->title, p->caption);
    fprintf(md, "![%s](%s)\n\n*%s.* %s\n\n", p->title, name, p->title, p->caption);
    free(b64);
    free(buf);
}

/* ---- results ----------------------------------------------------------------- */

typedef struct row {
    bench_row r;
    char kernel[32], format[16], port[32], path[16];
} row;

static row *rows;
static int n_rows, cap_rows;

static void collect(const bench_row *r, void *ctx)
{
    row *x;
    (void)ctx;
    if (n_rows == cap_rows) {
        cap_rows = cap_rows ? 2 * cap_rows : 64;
        rows = realloc(rows, (size_t)cap_rows * sizeof *rows);
    }
    x = &rows[n_rows++];
    x->r = *r;
    snprintf(x->kernel, sizeof x->kernel, "%s", r->kernel);
    snprintf(x->format, sizeof x->format, "%s", r->format);
    snprintf(x->port, sizeof x->port, "%s", r->port);
    snprintf(x->path, sizeof x->path, "%s", r->path);
    x->r.kernel = x->kernel;
    x->r.format = x->format;
    x->r.port = x->port;
    x->r.path = x->path;
}

static const row *find_row(const char *kernel, const char *format, const char *port, const char *path)
{
    int i;
    for (i = 0; i < n_rows; i++)
        if (!strcmp(rows[i].kernel, kernel) && !strcmp(rows[i].format, format) &&
            !strcmp(rows[i].port, port) && !strcmp(rows[i].path, path))
            return &rows[i];
    return NULL;
}

static double est(double ticks) { return ticks / tpc; }

/* find_row for samplers.c */
static const bench_row *find_bench_row(const char *kernel, const char *format, const char *port, const char *path)
{
    const row *x = find_row(kernel, format, port, path);
    return x ? &x->r : NULL;
}

/* ---- modelled cycles and sizes from report.sh --------------------------- */

/* a row of a .tsv: three names and a value (and a source), or with a
 * leading format column (mca.tsv) four names */
typedef struct tsv { char f[32], a[32], b[32], c[32]; double v; char src[64]; } tsv;
static tsv *mca, *sizes, *arm, *armvec;
static int n_mca, n_sizes, n_arm, n_armvec;

static tsv *read_tsv(const char *name, int *n, int with_format)
{
    char path[1024], line[512];
    FILE *f;
    tsv *t = NULL;
    int cap = 0;
    *n = 0;
    snprintf(path, sizeof path, "%s/%s", outdir, name);
    f = fopen(path, "r");
    if (!f)
        return NULL;
    while (fgets(line, sizeof line, f)) {
        tsv x;
        memset(&x, 0, sizeof x);
        if (line[0] == '#')
            continue;
        if (with_format ? sscanf(line, "%31s %31s %31s %31s %lf", x.f, x.a, x.b, x.c, &x.v) < 5
                        : sscanf(line, "%31s %31s %31s %lf %63s", x.a, x.b, x.c, &x.v, x.src) < 4)
            continue;
        if (*n == cap) {
            cap = cap ? 2 * cap : 64;
            t = realloc(t, (size_t)cap * sizeof *t);
        }
        t[(*n)++] = x;
    }
    fclose(f);
    return t;
}

/* mca.tsv: format port kernel cpu cycles_per_sample.  Only the f32 tiers'
 * batch loops are modelled: a fixed-point row has none (-1). */
static double mca_of(const char *format, const char *port, const char *kernel, const char *cpu)
{
    int i;
    for (i = 0; i < n_mca; i++)
        if (!strcmp(mca[i].f, format) && !strcmp(mca[i].a, port) && !strcmp(mca[i].b, kernel) &&
            !strcmp(mca[i].c, cpu))
            return mca[i].v;
    return -1;
}

/* size.tsv: format port kernel bytes */
static double size_of(const char *format, const char *port, const char *kernel)
{
    int i;
    for (i = 0; i < n_sizes; i++)
        if (!strcmp(sizes[i].a, format) && !strcmp(sizes[i].b, port) && !strcmp(sizes[i].c, kernel))
            return sizes[i].v;
    return -1;
}

/* arm.tsv: what(fx|f32soft) kernel cpu cycles_per_sample source */
static const tsv *arm_of(const char *what, const char *kernel, const char *cpu)
{
    int i;
    for (i = 0; i < n_arm; i++)
        if (!strcmp(arm[i].a, what) && !strcmp(arm[i].b, kernel) && !strcmp(arm[i].c, cpu))
            return &arm[i];
    return NULL;
}

/* arm_vec.tsv (bench/report/arm_targets.sh): format port kernel measure
 * value, the NEON and Helium ports' costs per sample; -1 if absent */
static double armvec_of(const char *format, const char *port, const char *kernel, const char *measure)
{
    int i;
    for (i = 0; i < n_armvec; i++)
        if (!strcmp(armvec[i].f, format) && !strcmp(armvec[i].a, port) && !strcmp(armvec[i].b, kernel) &&
            !strcmp(armvec[i].c, measure))
            return armvec[i].v;
    return -1;
}

/* arm_vec.status: "PORT ok HOW" or "PORT skipped WHY"; the line for port
 * (without the port's name) into b, or why there is none */
static int armvec_status(const char *port, char *b, size_t n)
{
    char path[1024], line[512];
    size_t k = strlen(port);
    FILE *f;
    snprintf(path, sizeof path, "%s/arm_vec.status", outdir);
    f = fopen(path, "r");
    snprintf(b, n, "skipped: no arm_vec.status (a facet-bench report run without bench/report/report.sh, "
                   "which runs bench/report/arm_targets.sh)");
    if (!f)
        return 0;
    while (fgets(line, sizeof line, f))
        if (!strncmp(line, port, k) && line[k] == ' ') {
            line[strcspn(line, "\n")] = 0;
            snprintf(b, n, "%s", line + k + 1);
            fclose(f);
            return !strncmp(line + k + 1, "ok", 2);
        }
    fclose(f);
    return 0;
}

/* ---- model error of the approximations -------------------------------------
 * Table-driven: one line per (approximation, exact reference, domain).  An
 * entry names the two double oracles as functions of its axes' values x[]
 * (the M2 / M3 wrappers below adapt a facet_oracle_* of 2 or 3 inputs
 * taken in axis order), the kernels whose cost the table shows, and up to
 * three axes (name, low end, high end, log-spaced or linear; the sweep
 * takes half its points log-spaced and half linear on each axis, so both
 * the grazing ends and the middle are dense).  Adding a pair is one line. */
typedef struct model_axis { const char *name; double lo, hi; } model_axis;

typedef struct tradeoff {
    const char *term, *approx, *exact;
    const char *cheap_kernel, *exact_kernel; /* for the cost columns */
    double (*f_approx)(const double *x), (*f_exact)(const double *x);
    int n_axes;
    model_axis axes[3];
    double max_rel, mean_rel, arg[3];
    long n;
} tradeoff;

#define M2(fn) static double m2_##fn(const double *x) { return facet_oracle_##fn(x[0], x[1]); }
#define M3(fn) static double m3_##fn(const double *x) { return facet_oracle_##fn(x[0], x[1], x[2]); }
M3(smith_vis) M3(smith_vis_hammon) M3(smith_vis_joint_approx) M3(smith_vis_fit)
M3(smith_g2) M3(smith_g2_hammon) M3(smith_g2_uncorrelated)
M2(smith_g1) M2(smith_g1_hammon) M2(smith_g1_beckmann) M2(smith_g1_beckmann_exact) M2(smith_g1_schlick_beckmann)
M2(fresnel_schlick) M2(fresnel_schlick_sg) M2(fresnel_cook_torrance)
M3(smith_g1_gtr) M3(smith_g1_gtr_exact)
/* the diffuse and whole-BRDF rows: L.V = N.L N.V (azimuths 90 deg apart), f0 = 0.04, albedo = 0.8 */
static double m_lambert(const double *x) { (void)x; return facet_oracle_lambert(0.8); }
static double m_diffuse_hammon(const double *x) { return facet_oracle_diffuse_hammon(x[0], x[1], x[0] * x[1], x[2], 0.8); }
static double m_brdf_hammon(const double *x) { return facet_oracle_brdf_hammon(x[0], x[1], x[0] * x[1], x[2], 0.04, 0.8); }
static double m_brdf_exact(const double *x) { return bench_oracle_brdf_exact(x[0], x[1], x[0] * x[1], x[2], 0.04, 0.8); }

/* the classic G terms (no alpha) and Schlick with f90 = 1, on the same
 * geometry: L.V = N.L N.V, N.H and V.H from the identities (geom.c) */
static double m_g_classic(int which, const double *x)
{
    geom g = { 0 };
    double nh, vh;
    g.nl = x[0], g.nv = x[1], g.lv = x[0] * x[1], g.alpha = x[2];
    geom_input(&g, "noh", &nh);
    geom_input(&g, "voh", &vh);
    switch (which) {
    case 0: return facet_oracle_g_implicit(g.nl, g.nv);
    case 1: return facet_oracle_g_neumann(g.nl, g.nv);
    case 2: return facet_oracle_g_cook_torrance(g.nl, g.nv, nh, vh);
    default: return facet_oracle_g_kelemen(g.nl, g.nv, vh);
    }
}
static double m_g_implicit(const double *x) { return m_g_classic(0, x); }
static double m_g_neumann(const double *x) { return m_g_classic(1, x); }
static double m_g_cook_torrance(const double *x) { return m_g_classic(2, x); }
static double m_g_kelemen(const double *x) { return m_g_classic(3, x); }
static double m_fresnel_schlick_f90(const double *x) { return facet_oracle_fresnel_schlick_f90(x[0], 1.0, x[1]); }

#define AX_NL(lo) { "N.L", lo, 1.0 }
#define AX_NV(lo) { "N.V", lo, 1.0 }
#define AX_A { "alpha", 0x1p-10, 1.0 }
#define VIS3 3, { AX_NL(0x1p-8), AX_NV(0x1p-8), AX_A }   /* the fixed-point cos floor, and issue 10's domain */
#define G3 3, { AX_NL(0x1p-12), AX_NV(0x1p-12), AX_A }
#define G1D 2, { AX_NV(0x1p-12), AX_A }
#define FRES 2, { { "f0", 0.02, 0.1 }, { "V.H", 0x1p-10, 1.0 } } /* dielectrics: eta 1.33 .. 1.92 */
#define G1GTR 3, { AX_NV(0x1p-12), AX_A, { "gamma", 0.25, 4.0 } }

static tradeoff trades[] = {
    { "visibility", "smith_vis_hammon", "smith_vis (exact, correlated)", "smith_vis_hammon", "smith_vis",
      m3_smith_vis_hammon, m3_smith_vis, VIS3, 0, 0, { 0 }, 0 },
    { "visibility", "smith_vis_joint_approx (= Hammon's)", "smith_vis (exact, correlated)", "smith_vis_joint_approx",
      "smith_vis", m3_smith_vis_joint_approx, m3_smith_vis, VIS3, 0, 0, { 0 }, 0 },
    { "visibility", "smith_vis_fit (3 lines, fitted)", "smith_vis (exact, correlated)", "smith_vis_fit", "smith_vis",
      m3_smith_vis_fit, m3_smith_vis, VIS3, 0, 0, { 0 }, 0 },
    { "G2", "smith_g2_hammon", "smith_g2 (exact, correlated)", "smith_g2_hammon", "smith_g2",
      m3_smith_g2_hammon, m3_smith_g2, G3, 0, 0, { 0 }, 0 },
    { "G1", "smith_g1_hammon (Schlick-GGX k = a/2)", "smith_g1 (exact)", "smith_g1_hammon", "smith_g1",
      m2_smith_g1_hammon, m2_smith_g1, G1D, 0, 0, { 0 }, 0 },
    { "G1 Beckmann", "smith_g1_beckmann (Walter)", "exact Beckmann G1 (erf)", "smith_g1_beckmann", "",
      m2_smith_g1_beckmann, m2_smith_g1_beckmann_exact, G1D, 0, 0, { 0 }, 0 },
    { "G1 Beckmann", "smith_g1_schlick_beckmann (k = a sqrt(2/pi))", "exact Beckmann G1 (erf)",
      "smith_g1_schlick_beckmann", "", m2_smith_g1_schlick_beckmann, m2_smith_g1_beckmann_exact, G1D, 0, 0, { 0 }, 0 },
    { "G2", "g_implicit (N.L N.V)", "smith_g2 (exact, correlated)", "g_implicit", "smith_g2", m_g_implicit,
      m3_smith_g2, G3, 0, 0, { 0 }, 0 },
    { "G2", "g_neumann (min(N.L, N.V))", "smith_g2 (exact, correlated)", "g_neumann", "smith_g2", m_g_neumann,
      m3_smith_g2, G3, 0, 0, { 0 }, 0 },
    { "G2", "g_cook_torrance (V-groove)", "smith_g2 (exact, correlated)", "g_cook_torrance", "smith_g2",
      m_g_cook_torrance, m3_smith_g2, G3, 0, 0, { 0 }, 0 },
    { "G2", "g_kelemen", "smith_g2 (exact, correlated)", "g_kelemen", "smith_g2", m_g_kelemen, m3_smith_g2, G3, 0, 0,
      { 0 }, 0 },
    { "Fresnel", "fresnel_schlick_f90 (f90 = 1)", "fresnel_cook_torrance (exact dielectric)", "fresnel_schlick_f90",
      "fresnel_cook_torrance", m_fresnel_schlick_f90, m2_fresnel_cook_torrance, FRES, 0, 0, { 0 }, 0 },
    { "G2 correlation", "smith_g2_uncorrelated", "smith_g2 (correlated)", "smith_g2_uncorrelated", "smith_g2",
      m3_smith_g2_uncorrelated, m3_smith_g2, G3, 0, 0, { 0 }, 0 },
    { "Fresnel", "fresnel_schlick", "fresnel_cook_torrance (exact dielectric)", "fresnel_schlick",
      "fresnel_cook_torrance", m2_fresnel_schlick, m2_fresnel_cook_torrance, FRES, 0, 0, { 0 }, 0 },
    { "Fresnel", "fresnel_schlick_sg (spherical Gaussian)", "fresnel_cook_torrance (exact dielectric)",
      "fresnel_schlick_sg", "fresnel_cook_torrance", m2_fresnel_schlick_sg, m2_fresnel_cook_torrance, FRES, 0, 0,
      { 0 }, 0 },
    { "G1 GTR", "smith_g1_gtr (Dimov: closed forms, cubic in gamma)", "GTR G1 by quadrature", "smith_g1_gtr", "",
      m3_smith_g1_gtr, m3_smith_g1_gtr_exact, G1GTR, 0, 0, { 0 }, 0 },
    { "diffuse", "lambert", "diffuse_hammon", "lambert", "diffuse_hammon", m_lambert, m_diffuse_hammon, G3, 0, 0, { 0 }, 0 },
    { "whole BRDF", "brdf_hammon (Hammon Vis)", "D Vis_exact F + diffuse_hammon", "brdf_hammon", "",
      m_brdf_hammon, m_brdf_exact, G3, 0, 0, { 0 }, 0 },
};
#define N_TRADE ((int)(sizeof trades / sizeof trades[0]))

/* point i of n on an axis: even i log-spaced, odd i linear, both lo .. hi */
static double axis_at(const model_axis *ax, int i, int n)
{
    double u = (double)(i / 2) / (double)((n + 1) / 2 - 1);
    if (i & 1)
        return ax->lo + (ax->hi - ax->lo) * u;
    return exp2(log2(ax->lo) + (log2(ax->hi) - log2(ax->lo)) * u);
}

static void sweep_tradeoffs(void)
{
    int t;
    for (t = 0; t < N_TRADE; t++) {
        tradeoff *x = &trades[t];
        int n = x->n_axes == 3 ? (quick ? 24 : 96) : x->n_axes == 2 ? (quick ? 200 : 1000) : 100000;
        if (x->f_exact == m3_smith_g1_gtr_exact) /* a quadrature per point (~0.1 ms) */
            n = quick ? 10 : 24;
        long total = 1, c;
        int d;
        double sum = 0;
        x->max_rel = -1;
        x->n = 0;
        for (d = 0; d < x->n_axes; d++)
            total *= n;
        for (c = 0; c < total; c++) {
            double v[3];
            long r = c;
            double e;
            for (d = 0; d < x->n_axes; d++) {
                v[d] = axis_at(&x->axes[d], (int)(r % n), n);
                r /= n;
            }
            e = bench_rel_err(x->f_approx(v), x->f_exact(v));
            sum += e;
            x->n++;
            if (e > x->max_rel) {
                x->max_rel = e;
                for (d = 0; d < x->n_axes; d++)
                    x->arg[d] = v[d];
            }
        }
        x->mean_rel = sum / (double)x->n;
    }
}

/* best (lowest median) f32 batch row of a kernel, any port */
static const row *best_batch(const char *kernel)
{
    const row *b = NULL;
    int i;
    for (i = 0; i < n_rows; i++)
        if (!strcmp(rows[i].kernel, kernel) && !strcmp(rows[i].format, "f32") &&
            !strcmp(rows[i].path, "batch") && (!b || rows[i].r.thr.median < b->r.thr.median))
            b = &rows[i];
    return b;
}

/* ---- SVG Pareto plot -------------------------------------------------------------- */

/* a Pareto point: cost on this machine and the two errors, kept apart */
typedef struct point {
    double x;       /* est. cycles per sample */
    double yi;      /* implementation error: max rel. vs the oracle of its own formula (value >= 2^-8) */
    double ym;      /* model error: max rel. vs the exact term; 0 exact; < 0 not an approximation of it */
    char label[64];
    int kind;       /* 0 facet, 1 peer */
} point;

#define ERR_FLOOR_ 1e-8

/* one panel of a Pareto figure: log cost across, log error up, points
 * numbered (the table beside the figure names them), the frontier (the
 * least error within each cost) as a step line */
static void svg_pareto_panel(int ox, int W, int H, const char *ylabel, const point *p, int n, int model,
                             double lx0, double lx1)
{
    static const char *col[2] = { "#1f6feb", "#d1242f" };
    const double ly0 = -8, ly1 = 0.5;
    int L = 62, B = 40, T = 22, i, d, order[128], m = 0;
    double best = 1e300;
#define SX(v) (ox + L + (log10(v) - lx0) / (lx1 - lx0) * (W - L - 10))
#define SY(v) (T + (ly1 - log10((v) > ERR_FLOOR_ ? ((v) < 2.5 ? (v) : 2.5) : ERR_FLOOR_)) / (ly1 - ly0) * (H - B - T))
    fprintf(html, "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"#fafafa\" stroke=\"#888\"/>\n", ox + L, T,
            W - L - 10, H - B - T);
    fprintf(html, "<text x=\"%d\" y=\"14\" font-weight=\"bold\">%s</text>", ox + L, ylabel);
    for (d = (int)ceil(lx0); d <= (int)floor(lx1); d++) {
        fprintf(html, "<line x1=\"%.1f\" x2=\"%.1f\" y1=\"%d\" y2=\"%d\" stroke=\"#ddd\"/>", SX(pow(10, d)), SX(pow(10, d)), T, H - B);
        svg_tick_label(html, SX(pow(10, d)), H - B + 14, "middle", pow(10, d), 1);
    }
    for (d = (int)ly0; d <= 0; d++) {
        fprintf(html, "<line x1=\"%d\" x2=\"%d\" y1=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>", ox + L, ox + W - 10,
                SY(pow(10, d)), SY(pow(10, d)));
        if (d == (int)ly0)
            fprintf(html, "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%s</text>", ox + L - 4, SY(pow(10, d)) + 4,
                    model ? "exact" : "<= 10^-8");
        else
            svg_tick_label(html, ox + L - 4, SY(pow(10, d)) + 4, "end", pow(10, d), 1);
    }
    fprintf(html, "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\" font-style=\"italic\">est. core cycles per sample</text>\n",
            ox + (W + L) / 2, H - 6);
    /* the frontier: by cost, each point that lowers the least error so far */
    for (i = 0; i < n && m < 128; i++)
        if (p[i].x > 0 && (model ? p[i].ym : p[i].yi) >= 0)
            order[m++] = i;
    for (i = 1; i < m; i++) { /* insertion sort by cost */
        int k = order[i], j2 = i - 1;
        while (j2 >= 0 && p[order[j2]].x > p[k].x) {
            order[j2 + 1] = order[j2];
            j2--;
        }
        order[j2 + 1] = k;
    }
    fprintf(html, "<polyline fill=\"none\" stroke=\"#2da44e\" stroke-width=\"1.5\" points=\"");
    for (i = 0; i < m; i++) {
        double y = model ? p[order[i]].ym : p[order[i]].yi;
        if (y < best) {
            if (best < 1e300)
                fprintf(html, "%.1f,%.1f ", SX(p[order[i]].x), SY(best));
            best = y;
            fprintf(html, "%.1f,%.1f ", SX(p[order[i]].x), SY(best));
        }
    }
    if (best < 1e300)
        fprintf(html, "%.1f,%.1f", ox + W - 10.0, SY(best));
    fprintf(html, "\"/>\n");
    if (!m)
        fprintf(html, "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\" fill=\"#666\">none: these kernels are different "
                      "models, not approximations of one</text>", ox + (W + L) / 2, (T + H - B) / 2);
    for (i = 0; i < m; i++) {
        const point *q = &p[order[i]];
        double y = model ? q->ym : q->yi;
        fprintf(html, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3.5\" fill=\"%s\"/><text x=\"%.1f\" y=\"%.1f\" "
                      "font-size=\"9\" fill=\"%s\">%d</text>\n",
                SX(q->x), SY(y), col[q->kind], SX(q->x) + 4, SY(y) - 3, col[q->kind], order[i] + 1);
    }
#undef SX
#undef SY
}

/* a Pareto figure: implementation error and model error side by side over
 * the same cost axis, and the numbered table */
static void svg_pareto(const char *title, const point *p, int n)
{
    double x0 = 1e30, x1 = -1e30, lx0, lx1;
    int W = 470, H = 330, i;
    char b[4][48];
    for (i = 0; i < n; i++)
        if (p[i].x > 0) {
            x0 = p[i].x < x0 ? p[i].x : x0;
            x1 = p[i].x > x1 ? p[i].x : x1;
        }
    if (x0 > x1)
        return;
    lx0 = log10(x0) - 0.15;
    lx1 = log10(x1) + 0.15;
    if (lx1 - lx0 < 1)
        lx0 -= (1 - (lx1 - lx0)) / 2, lx1 = lx0 + 1;
    fprintf(html, "<figure><svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" font-family=\"sans-serif\" "
                  "font-size=\"11\">\n", 2 * W, H);
    svg_pareto_panel(0, W, H, "implementation error (vs its own formula)", p, n, 0, lx0, lx1);
    svg_pareto_panel(W, W, H, "model error (vs the exact term)", p, n, 1, lx0, lx1);
    fprintf(html, "</svg><figcaption><b>Pareto: %s.</b> Left: each kernel's arithmetic error against the double "
                  "oracle of its own formula (max relative, over samples whose value is >= 2^-8; above 1, "
                  "or inf, drawn at the top). Right: the "
                  "formula's model error against the exact term (0 drawn as 'exact'; kernels that are a different "
                  "model rather than an approximation are left out). Blue: facet, red: peers; green: the frontier "
                  "(the least error within each cost). Numbers: the table below.</figcaption></figure>\n", title);
    thead(5, "#", "candidate", "est. cycles/sample", "impl. error", "model error");
    for (i = 0; i < n; i++) {
        const char *cells[5];
        cells[0] = fmt(b[0], sizeof b[0], "%d", i + 1);
        cells[1] = p[i].label;
        cells[2] = fmt(b[1], sizeof b[1], "%.2f", p[i].x);
        cells[3] = p[i].yi < 0 ? "-" : g3(b[2], p[i].yi);
        cells[4] = p[i].ym < 0 ? "n/a" : p[i].ym == 0 ? "exact" : g3(b[3], p[i].ym);
        trow(cells);
    }
    tend();
}

/* ---- sections ------------------------------------------------------------------ */

static void section_clock(void)
{
    h2("Clock and method");
    para("Clock: <b>%s</b> (%s). %s Pinned to CPU %d. Throughput: %s samples per pass, "
         "L1-resident structure-of-arrays of valid random geometry from tests/lib/sample.h (per-sample "
         "alpha, f0, albedo), cost = t(2R passes) - t(R passes) over R passes; >= 11 epochs after "
         "warm-up, each the best of 3; reported: min and median, spread = (max - min) / median, "
         "'!' where spread > 5%%. Latency: a dependent chain (the first input of call i+1 is "
         "in[i+1] + out[i] * 0), minus the same chain with no kernel; per call (a call is 8 samples "
         "for AVX2, 4 for SSE2).",
         cyc_source(), cyc_is_cycles() ? "measured core cycles" : "time-stamp counter ticks, NOT core cycles",
         cyc_is_cycles() ? "" : "perf_event_open(PERF_COUNT_HW_CPU_CYCLES) is not available here (a VM without a virtual PMU), so "
         "'est. cycles' = ticks / ticks-per-cycle, the ratio measured with a dependent chain of 1-cycle integer adds "
         "(it assumes the core clock does not change between that calibration and the kernel).",
         cyc_cpu(), quick ? "256" : "1024");
    if (!cyc_is_cycles())
        para("Measured ticks per core cycle: %.4f (core clock about %.2f x the TSC rate).", tpc, 1 / tpc);
}

static void section_kernels(void)
{
    size_t ki;
    h2("Kernels x format x port: error and cost");
    para("Errors: relative to the double oracle at the same inputs (floor 2^-100), max (with the argmax "
         "input) and mean over the error set; 'bound' is the facet.h bound (ok/BAD). Peers: error against "
         "the oracle of the formula they compute. Fixed-point rows (fmt fx): the float inputs rounded to Q15 "
         "(ties up) and clamped to the fx domain outside the timing; error in LSB of the output format "
         "against round-half-up(oracle 2^frac) at those Q15 inputs, the measure of tests/fx/test_fx_accuracy.c "
         "(brdf_hammon where the oracle is >= 16: relative, bound 2^-26); path batch = "
         "facet_KERNEL_fx_batch with facet_set_port(port) active (identical timings across ports mean the "
         "build routes every port to the same fx loop), path call = facet_KERNEL_fx per sample. Throughput in %s per sample (median), est. cycles per "
         "sample, latency in est. cycles per call. mca: llvm-mca cycles per sample for the port's batch "
         "loop (modelled, not measured). size: bytes of the batch function.", cyc_unit());
    thead(13, "kernel", "fmt", "port", "path", "max err", "argmax input", "mean err", "bound",
          "thr (med)", "est. cyc/sample", "latency cyc/call", "mca znver3 / skylake", "size B");
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const facet_kernel *k = facet_kernel_at(ki);
        int i, j;
        for (i = 0; i < n_rows; i++) {
            const row *x = &rows[i];
            char c[13][160], *p;
            const char *cells[13];
            double m1, m2, sz;
            if (strcmp(x->kernel, k->name))
                continue;
            snprintf(c[0], sizeof c[0], "%s", x->kernel);
            snprintf(c[1], sizeof c[1], "%s", x->format);
            snprintf(c[2], sizeof c[2], "%s", x->port);
            snprintf(c[3], sizeof c[3], "%s", x->path);
            if (x->r.err.has_lsb)
                fmt(c[4], sizeof c[4], "%.0f LSB%s", x->r.err.max_lsb,
                    x->r.err.big_rel >= 0 ? fmt(c[12], 64, " (brdf >= 16: %.2g rel)", x->r.err.big_rel) : "");
            else
                g3(c[4], x->r.err.max_rel);
            p = c[5];
            *p = 0;
            for (j = 0; j < x->r.n_inputs; j++)
                p += snprintf(p, 20, "%s%.4g", j ? ", " : "", x->r.err.arg[j]);
            if (x->r.err.has_lsb)
                fmt(c[6], sizeof c[6], "%.2g LSB", x->r.err.mean_lsb);
            else
                g3(c[6], x->r.err.mean_rel);
            if (x->r.bound > 0 && x->r.err.has_lsb)
                fmt(c[7], sizeof c[7], "%.0f LSB%s %s", x->r.bound, x->r.err.big_rel >= 0 ? ", 2^-26 rel" : "",
                    x->r.within ? "ok" : "**BAD**");
            else if (x->r.bound > 0)
                fmt(c[7], sizeof c[7], "%.3g %s", x->r.bound, x->r.within ? "ok" : "**BAD**");
            else
                strcpy(c[7], "-");
            fmt(c[8], sizeof c[8], "%.3f%s", x->r.thr.median, x->r.thr.noisy ? " !" : "");
            fmt(c[9], sizeof c[9], "%.2f", est(x->r.thr.median));
            if (x->r.has_lat)
                fmt(c[10], sizeof c[10], "%.1f%s", est(x->r.lat.median), x->r.lat.noisy ? " !" : "");
            else
                strcpy(c[10], "-");
            m1 = mca_of(x->format, x->port, x->kernel, "znver3");
            m2 = mca_of(x->format, x->port, x->kernel, "skylake");
            if (!strcmp(x->path, "batch") && m1 > 0)
                fmt(c[11], sizeof c[11], "%.2f / %.2f", m1, m2);
            else
                strcpy(c[11], "-");
            sz = size_of(x->format, x->port, x->kernel);
            if (!strcmp(x->path, "batch") && sz > 0)
                fmt(c[12], sizeof c[12], "%.0f", sz);
            else
                strcpy(c[12], "-");
            for (j = 0; j < 13; j++)
                cells[j] = c[j];
            trow(cells);
        }
    }
    tend();
    para("Peers (bench/harness/peers.h): <b>textbook</b> (-O2): powf, D in tan form, Smith "
         "via Lambda with sqrtf, plain divisions. <b>shader</b> (-O3 -fno-math-errno -fno-trapping-math "
         "-ffp-contract=fast, auto-vectorized), built for the width of the facet port it is compared with: "
         "<b>shader_avx2</b> -march=x86-64-v3, <b>shader_avx512</b> -march=x86-64-v4 (each run only where "
         "that port runs; elsewhere one native build): a2 form of D, pow5 by multiplication. "
         "<b>*_fm</b>: the same source and width with -ffast-math. Every peer row (path peer) takes the "
         "same inputs and computes the same formula as the facet kernel: brdf_hammon's peers take (N.L, "
         "N.V, L.V, alpha, f0, albedo), derive N.H and L.H from one rsqrt of 2 + 2 L.V and use Hammon's "
         "Vis, so their error is arithmetic error and their time the same work. The rows of path "
         "peer-vectors are another model, D Vis_exact F + Hammon diffuse from vectors L, V (N = z), "
         "judged against its own oracle.");
}

static void section_tradeoff(void)
{
    int t;
    char b[8][64];
    h2("Tradeoff per term: model error of each approximation vs the exact model");
    para("Model error, not implementation error: the double-precision oracles of both formulas (the "
         "approximation's own formula and the exact reference) on a grid over each row's domain (per axis half "
         "the points log-spaced, half linear; %s), relative error |approx / exact - 1|: max, mean, and the "
         "argmax in the domain's axes. Domains: visibility N.L, N.V in [2^-8, 1]; the other two-cosine rows "
         "[2^-12, 1]; G1 rows N.V in [2^-12, 1]; alpha in [2^-10, 1] everywhere; L.V = N.L N.V where needed "
         "(L and V 90 deg apart in azimuth), f0 = 0.04, albedo = 0.8. The implementation error of each kernel "
         "(vs its own formula) is in the kernels table. Cost: the best port's batch, est. cycles per sample.",
         quick ? "24 points per axis for 3 axes, 200 for 2" : "96 points per axis for 3 axes, 1000 for 2");
    thead(8, "term", "approximation", "exact", "max rel err", "mean rel err", "argmax (domain axes)",
          "cost approx", "cost exact");
    for (t = 0; t < N_TRADE; t++) {
        const tradeoff *x = &trades[t];
        const row *ca = best_batch(x->cheap_kernel), *ce = x->exact_kernel[0] ? best_batch(x->exact_kernel) : NULL;
        const char *cells[8];
        cells[0] = x->term;
        cells[1] = x->approx;
        cells[2] = x->exact;
        cells[3] = g3(b[0], x->max_rel);
        cells[4] = g3(b[1], x->mean_rel);
        {
            char *q = b[2];
            int d;
            *q = 0;
            for (d = 0; d < x->n_axes; d++)
                q += snprintf(q, 20, "%s%s %.3g", d ? ", " : "", x->axes[d].name, x->arg[d]);
            cells[5] = b[2];
        }
        cells[6] = ca ? fmt(b[3], sizeof b[3], "%.2f (%s)", est(ca->r.thr.median), ca->port) : "-";
        if (!strcmp(x->term, "whole BRDF")) {
            const row *p = NULL;
            int i;
            for (i = 0; i < n_rows; i++)
                if (!strcmp(rows[i].path, "peer") && !strcmp(rows[i].kernel, "brdf_hammon") &&
                    (!p || rows[i].r.thr.median < p->r.thr.median))
                    p = &rows[i];
            cells[7] = p ? fmt(b[4], sizeof b[4], "%.2f (peer %s)", est(p->r.thr.median), p->port) : "-";
        } else {
            cells[7] = ce ? fmt(b[4], sizeof b[4], "%.2f (%s)", est(ce->r.thr.median), ce->port) : "-";
        }
        trow(cells);
    }
    tend();
}

/* the model error of kernel kn against its term's exact form: from the
 * tradeoff sweep; 0 for the exact kernels; -1 for kernels that are not an
 * approximation of another (a different model) */
static double model_of(const char *kn)
{
    int t;
    for (t = 0; t < N_TRADE; t++)
        if (!strcmp(trades[t].cheap_kernel, kn))
            return trades[t].max_rel;
    for (t = 0; t < N_TRADE; t++)
        if (!strcmp(trades[t].exact_kernel, kn))
            return 0;
    return -1;
}

/* The terms a user chooses among, each with the kernels that compute it
 * (names not in this build are skipped). */
static const char *const pareto_groups[][10] = {
    /* no exact reference: each variant is its own model (a look, not an
     * approximation): D and diffuse */
    { "D (normal distribution)", "ggx_d", "beckmann_d", "blinn_phong_d", "gtr_d", "ggx_aniso_d", NULL },
    { "G1 (masking)", "smith_g1", "smith_g1_hammon", "smith_g1_gtr", NULL },
    { "G1 for Beckmann's D", "smith_g1_beckmann", "smith_g1_schlick_beckmann", NULL },
    { "G2 (masking-shadowing)", "smith_g2", "smith_g2_hammon", "smith_g2_uncorrelated", "g_implicit", "g_neumann",
      "g_cook_torrance", "g_kelemen", NULL },
    { "visibility (G2 / (4 N.L N.V))", "smith_vis", "smith_vis_hammon", "smith_vis_joint_approx", "smith_vis_fit", NULL },
    { "Fresnel", "fresnel_schlick", "fresnel_cook_torrance", "fresnel_schlick_f90", "fresnel_schlick_sg", NULL },
    { "diffuse", "diffuse_hammon", "lambert", "diffuse_burley", "diffuse_oren_nayar", "diffuse_hammon_hybrid",
      "diffuse_hammon_cheap", NULL },
    { "whole BRDF", "brdf_hammon", NULL },
};
#define N_PARETO_GROUPS ((int)(sizeof pareto_groups / sizeof pareto_groups[0]))
static int group_has_reference(int g)
{
    return strncmp(pareto_groups[g][0], "D ", 2) && strcmp(pareto_groups[g][0], "diffuse");
}

static void section_pareto(void)
{
    static const char *const formats[] = { "f32", "f32_fast", "fx", "fx_fast" };
    int g;
    h2("Pareto: error vs cycles, per term");
    para("Every facet kernel of each term in every format and tier on every port this machine runs (batch path), "
         "and the peers, by cost (est. cycles per sample) and by the two errors, kept apart. Fixed-point "
         "implementation error: against the oracle at the same Q15 inputs (the input rounding is in the "
         "image-space section). (The SVG plots are in index.html.)");
    for (g = 0; g < N_PARETO_GROUPS; g++) {
        point pts[128];
        int n = 0, s2, i, f;
        for (s2 = 1; pareto_groups[g][s2] && n < 128; s2++) {
            const char *kn = pareto_groups[g][s2];
            double model = group_has_reference(g) ? model_of(kn) : -1;
            for (f = 0; f < 4; f++)
                for (i = 0; i < n_rows && n < 128; i++) {
                    const row *x = &rows[i];
                    if (strcmp(x->kernel, kn) || strcmp(x->format, formats[f]) || strcmp(x->path, "batch"))
                        continue;
                    pts[n].x = est(x->r.thr.median);
                    pts[n].yi = x->r.err.max_rel_vis;
                    pts[n].ym = model;
                    pts[n].kind = 0;
                    snprintf(pts[n].label, sizeof pts[n].label, "%s %s %s", kn, x->format, x->port);
                    n++;
                }
            for (i = 0; i < n_rows && n < 128; i++) {
                const row *x = &rows[i];
                if (strcmp(x->kernel, kn) || strcmp(x->path, "peer"))
                    continue;
                pts[n].x = est(x->r.thr.median);
                pts[n].yi = x->r.err.max_rel_vis;
                /* every "peer" row computes the kernel's own formula (the exact-Vis brdf
                 * peers are path "peer-vectors", not plotted) */
                pts[n].ym = model;
                pts[n].kind = 1;
                snprintf(pts[n].label, sizeof pts[n].label, "peer %s (%s)", x->port, kn);
                n++;
            }
        }
        if (n)
            svg_pareto(pareto_groups[g][0], pts, n);
    }
}

/* ---- the chooser: per term and target, the most accurate choice within
 * each cost ------------------------------------------------------------------ */

static double armv(const char *what, const char *kernel, const char *cpu);

typedef struct choice { const char *kernel, *format; double cost, impl, model; } choice;

/* a candidate's implementation error: measured on this machine's port (the
 * Cortex-M builds run the scalar C: fixed point is bit-exact everywhere,
 * the f32 scalar code is the same source) */
static double impl_of(const char *kn, const char *format, const char *port)
{
    const row *x = find_row(kn, format, port, "batch");
    return x ? x->r.err.max_rel_vis : -1;
}

static double total_of(const choice *c) { return (c->model > 0 ? c->model : 0) + c->impl; }

/* the frontier of cands by cost: each candidate more accurate than every
 * cheaper one, as "<= cost: kernel format (error)" */
static void frontier_cell(char *out, size_t cap, choice *c, int n, const char *unit)
{
    double best = 1e300;
    int i, j;
    size_t len = 0;
    for (i = 1; i < n; i++) { /* by cost, then by error */
        choice k = c[i];
        for (j = i - 1; j >= 0 && (c[j].cost > k.cost || (c[j].cost == k.cost && total_of(&c[j]) > total_of(&k))); j--)
            c[j + 1] = c[j];
        c[j + 1] = k;
    }
    out[0] = 0;
    for (i = 0; i < n; i++) {
        double e = total_of(&c[i]);
        char eb[32];
        if (e >= best * 0.999)
            continue;
        best = e;
        len += (size_t)snprintf(out + len, len < cap ? cap - len : 0, "%s<= %.3g %s: <b>%s %s</b> (error %s%s)",
                                len ? "<br>" : "", c[i].cost, unit, c[i].kernel, c[i].format, g3(eb, e),
                                c[i].model > 0 ? ", mostly model" : "");
        if (len >= cap)
            break;
    }
    if (!out[0])
        snprintf(out, cap, "-");
}

static void section_choose(void)
{
    static const char *const fmts[] = { "f32", "f32_fast", "fx", "fx_fast" };
    /* targets: a port of this machine (measured est. cycles), or a Cortex-M
     * core (arm.tsv: TRM-modelled M0 cycles, llvm-mca M4 cycles) */
    static const struct { const char *name, *port, *cpu, *unit; int f32soft, f32fpu; const char *vec, *measure; } tg[] = {
        { "AVX-512 (this machine)", "avx512", NULL, "cyc", 0, 0, NULL, NULL },
        { "AVX2 (this machine)", "avx2", NULL, "cyc", 0, 0, NULL, NULL },
        { "SSE2 (this machine)", "sse2", NULL, "cyc", 0, 0, NULL, NULL },
        { "NEON (aarch64, Cortex-A57 model)", NULL, NULL, "cyc (llvm-mca A57 model)", 0, 0, "neon", "mca-cortex-a57" },
        { "Helium (Cortex-M55)", NULL, NULL, "instr (qemu count)", 0, 0, "helium", "qemu-insn" },
        { "Cortex-M0", NULL, "cortex-m0", "cyc (TRM model)", 1, 0, NULL, NULL },
        { "Cortex-M4", NULL, "cortex-m4", "cyc (llvm-mca)", 1, 0, NULL, NULL },
        { "Cortex-M4 with FPU", NULL, "cortex-m4", "cyc (llvm-mca)", 0, 1, NULL, NULL },
    };
    char why_neon[300], why_helium[300];
    int ok_neon = armvec_status("neon", why_neon, sizeof why_neon);
    int ok_helium = armvec_status("helium", why_helium, sizeof why_helium);
    int g, t;
    h2("Which one to use");
    para("For each term and target: the Pareto frontier of kernel variant x format x tier by cost and by error "
         "against the exact term, read as 'within this cost, the most accurate choice is ...'. Error = model "
         "error (the formula against the exact term, from the tradeoff sweep; 0 for exact kernels, left out for "
         "terms whose variants are different models) + implementation error (max relative against the formula's "
         "own oracle, where the value is >= 2^-8, measured on that port; Cortex-M: the scalar code's). Costs: "
         "this machine's ports in est. core cycles per sample (batch, %s run); NEON (aarch64): cycles per "
         "sample MODELLED by llvm-mca 14 with its Cortex-A57 scheduling model (the model LLVM 14 also uses for "
         "A72, A76 and Neoverse N1) on the executed instruction trace of a 64-sample batch call under "
         "qemu-aarch64 (callees and tails included, branches free); Helium (Cortex-M55, helium objects from "
         "clang 14): instructions executed per sample of a 64-sample batch call, MEASURED under qemu-system-arm "
         "(instructions, not cycles: a 128-bit MVE instruction takes two beats); both from "
         "bench/report/arm_targets.sh, the ports' own tables in every tier they run; implementation error there: "
         "the scalar code's measured here (fixed point is bit-exact on every port; the ports' f32 is held to the "
         "same bounds by the 40-arm and 52-helium suites). Cortex-M in cycles per call, "
         "MODELLED from executed-instruction traces (M0: TRM timings, M4: llvm-mca; section Cortex-M). RISC-V "
         "is not costed here. NEON: %s. Helium: %s. Details: the Pareto figures below, then the long "
         "tables. D and diffuse have no exact reference (each variant is a model of its own, a look rather "
         "than an approximation): there each variant's cheapest format is listed with its cost.",
         quick ? "a quick" : "a full", why_neon, why_helium);
    for (g = 0; g < N_PARETO_GROUPS; g++) {
        int any = 0;
        for (t = 0; t < (int)(sizeof tg / sizeof tg[0]); t++) {
            choice c[64];
            int n = 0, s2, f;
            static char cell[2048];
            const char *cells[3];
            for (s2 = 1; pareto_groups[g][s2]; s2++) {
                const char *kn = pareto_groups[g][s2];
                double model = model_of(kn);
                for (f = 0; f < 4 && n < 64; f++) {
                    double cost = -1, impl;
                    if (tg[t].port) {
                        const row *x = find_row(kn, fmts[f], tg[t].port, "batch");
                        if (x)
                            cost = est(x->r.thr.median);
                        impl = impl_of(kn, fmts[f], tg[t].port);
                    } else if (tg[t].vec) {
                        cost = armvec_of(fmts[f], tg[t].vec, kn, tg[t].measure);
                        impl = impl_of(kn, fmts[f], "scalar");
                    } else {
                        const char *what = f == 0 ? (tg[t].f32fpu ? "f32fpu" : tg[t].f32soft ? "f32soft" : NULL)
                                                  : f == 1 ? NULL : f == 2 ? "fx" : "fxfast";
                        char key[32];
                        if (!what)
                            continue;
                        snprintf(key, sizeof key, "%s-%s", what, !strcmp(tg[t].cpu, "cortex-m0") ? "m0cyc" : "mca");
                        cost = armv(key, kn, tg[t].cpu);
                        impl = impl_of(kn, fmts[f], "scalar");
                    }
                    if (cost <= 0 || impl < 0)
                        continue;
                    c[n].kernel = kn;
                    c[n].format = fmts[f];
                    c[n].cost = cost;
                    c[n].impl = impl;
                    c[n].model = model;
                    n++;
                }
            }
            if (!n && tg[t].vec && !(!strcmp(tg[t].vec, "neon") ? ok_neon : ok_helium)) {
                /* the target could not be costed here: the table says why */
                if (!any) {
                    fprintf(md, "\n### %s\n\n", pareto_groups[g][0]);
                    fprintf(html, "<h3>%s</h3>\n", pareto_groups[g][0]);
                    thead(3, "target", "candidates", "within this cost, the most accurate choice");
                    any = 1;
                }
                cells[0] = tg[t].name;
                cells[1] = "0";
                snprintf(cell, sizeof cell, "not costed: %s", !strcmp(tg[t].vec, "neon") ? why_neon : why_helium);
                cells[2] = cell;
                trow(cells);
                continue;
            }
            if (!n)
                continue;
            if (!any) {
                fprintf(md, "\n### %s\n\n", pareto_groups[g][0]);
                fprintf(html, "<h3>%s</h3>\n", pareto_groups[g][0]);
                thead(3, "target", "candidates", "within this cost, the most accurate choice");
                any = 1;
            }
            {
                int ref = group_has_reference(g), m = 0, i, j;
                choice other[64];
                size_t len;
                /* the frontier over the candidates compared with the term's
                 * reference; the others (a different model, or a term
                 * without a reference) listed by their cheapest format */
                for (i = 0; i < n; i++)
                    if (ref && c[i].model >= 0)
                        c[m++] = c[i];
                    else
                        other[i - m] = c[i];
                frontier_cell(cell, sizeof cell, c, m, tg[t].unit);
                if (!m)
                    cell[0] = 0;
                len = strlen(cell);
                for (i = 0; i < n - m && len + 200 < sizeof cell; i++) {
                    int best = 1;
                    for (j = 0; j < n - m; j++)
                        if (!strcmp(other[j].kernel, other[i].kernel) &&
                            (other[j].cost < other[i].cost || (other[j].cost == other[i].cost && j < i)))
                            best = 0;
                    if (!best)
                        continue;
                    len += (size_t)snprintf(cell + len, sizeof cell - len, "%s%s <b>%s %s</b>: %.3g %s (impl. error %.3g)",
                                            len ? "<br>" : "", ref ? "a different model:" : "", other[i].kernel,
                                            other[i].format, other[i].cost, tg[t].unit, other[i].impl);
                }
            }
            {
                char nb[16];
                cells[0] = tg[t].name;
                cells[1] = fmt(nb, sizeof nb, "%d", n);
                cells[2] = cell;
                trow(cells);
            }
        }
        if (any)
            tend();
    }
}

/* an image-space error as one cell: max / p99 / mean code difference (max dE76) */
static const char *img_cell(char *b, size_t n, const img_err *e)
{
    return fmt(b, n, "%.0f / %.0f / %.3f (%.2f)", e->max_code, e->p99_code, e->mean_code, e->max_de);
}

/* every variant of the menu in image space: implementation and model error */
static void section_image_variants(void)
{
    int nmax = img_variant_count(), n, i, j;
    img_variant *v = calloc((size_t)nmax, sizeof *v);
    pic diff;
    char port[32];
    clock_t ts = clock();
    say("image-space error: the menu's variants ...");
    n = img_variants_run(v, nmax, &diff, port, sizeof port);
    say("image-space error: %d variants in %.1f s CPU", n, (double)(clock() - ts) / CLOCKS_PER_SEC);
    fprintf(md, "\n### The menu's variants in image space\n\n");
    fprintf(html, "<h3>The menu's variants in image space</h3>\n");
    para("The same spheres with a BRDF assembled as D * Vis * F + diffuse from double oracles (GGX D, exact "
         "height-correlated Smith Vis, Schlick F with V.H, Hammon's diffuse), except the part the variant "
         "computes (a G1 gives Vis = G1(N.L) G1(N.V) / (4 N.L N.V), with Beckmann's D for the Beckmann G1s "
         "and GTR's at the same gamma for smith_g1_gtr; a G2 gives Vis = G2 / (4 N.L N.V)). Implementation "
         "error: the kernel's render against the render from its own double oracle at the same float inputs "
         "(f32 and f32_fast: batch on %s, the best port of this CPU; fx and fx_fast where the kernel has them: "
         "the inputs rounded to Q15, so input rounding is included). Model error: the variant's oracle render "
         "against the reference's (G and Vis: the exact height-correlated Smith Vis; Beckmann G1: the exact "
         "Beckmann G1; smith_g1_gtr: the exact GTR G1 by quadrature; Fresnel: the exact dielectric Fresnel from "
         "f0; gtr_d at gamma 2: GGX); '-': no reference (a model of its own) or no such format. Each cell: max "
         "/ p99 / mean code difference (8-bit sRGB, largest channel per pixel, lit pixels) and, in brackets, "
         "the max CIE76 delta E.", port);
    thead(8, "variant", "term", "f32", "f32_fast", "fx (Q15 dots)", "fx_fast (Q15 dots)", "model: against",
          "model error");
    for (i = 0; i < n; i++) {
        char b[6][64];
        const char *cells[8];
        cells[0] = v[i].name;
        cells[1] = v[i].term;
        for (j = 0; j < 4; j++)
            cells[2 + j] = v[i].have[j] ? img_cell(b[j], sizeof b[j], &v[i].impl[j]) : "-";
        cells[6] = v[i].reference[0] ? v[i].reference : "-";
        cells[7] = !v[i].has_model ? "-" : v[i].is_reference ? "0 (the reference)" : img_cell(b[4], sizeof b[4], &v[i].model);
        trow(cells);
    }
    tend();
    if (diff.ax.rows)
        picture(&diff, "image_variants_model.png");
    pic_free(&diff);
    free(v);
}

/* what a viewer sees: brdf_hammon's formats, tiers and ports in 8-bit sRGB */
static void section_image_error(void)
{
    img_err e[16];
    pic ref, diff;
    int n, i;
    say("image-space error: spheres in every format, tier and port ...");
    n = img_error_run(e, 16, &ref, &diff);
    h2("Image-space error: what a pixel shows");
    para("Lit spheres (two materials x six alpha) rendered with each format, tier and port of brdf_hammon and "
         "compared with the same render from the double oracle, as 8-bit sRGB codes (radiance = BRDF N.L E, so "
         "the error is weighted by N.L as a pixel weights it; tone c / (1 + c) per channel so that highlights "
         "are not clipped) and as CIE76 colour differences (D65; delta E of 1 is about the smallest visible). "
         "f32 rows: the kernel's arithmetic only (reference at the same float dots). Fixed-point rows: the dots "
         "rounded to Q15 as a caller must, against the float reference, so input rounding is included. The "
         "model row: the exact-Vis BRDF against brdf_hammon, both as oracles (Hammon's Vis approximation in "
         "codes). Code differences: per pixel the largest of the three channels; p99 over the lit pixels.");
    thead(9, "candidate", "against", "max code diff", "p99 code diff", "mean code diff", "pixels off",
          "mean dE76", "p99 dE76", "max dE76");
    for (i = 0; i < n; i++) {
        char b[8][32];
        const char *cells[9];
        cells[0] = e[i].name;
        cells[1] = e[i].against;
        cells[2] = fmt(b[0], sizeof b[0], "%.0f", e[i].max_code);
        cells[3] = fmt(b[1], sizeof b[1], "%.0f", e[i].p99_code);
        cells[4] = fmt(b[2], sizeof b[2], "%.3f", e[i].mean_code);
        cells[5] = fmt(b[3], sizeof b[3], "%.2f%% of %ld", 100 * e[i].frac_diff, e[i].pixels);
        cells[6] = fmt(b[4], sizeof b[4], "%.3f", e[i].mean_de);
        cells[7] = fmt(b[5], sizeof b[5], "%.2f", e[i].p99_de);
        cells[8] = fmt(b[6], sizeof b[6], "%.2f", e[i].max_de);
        trow(cells);
    }
    tend();
    picture(&ref, "image_reference.png");
    picture(&diff, "image_difference.png");
    pic_free(&ref);
    pic_free(&diff);
    section_image_variants();
}

/* ---- white furnace: the directional albedo of every diffuse model -------- */

typedef struct curve { char label[64]; int colour, dash; int n; double x[32], y[32]; } curve;

/* an SVG line plot with labelled axes and a legend beside it */
static void svg_lines(const char *title, const char *xlabel, const char *ylabel, const curve *c, int nc,
                      double x0, double x1, double y0, double y1)
{
    static const char *col[8] = { "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf" };
    int W = 560, H = 320, L = 56, B = 44, T = 24, R = 16, LW = 260, i, j, n;
    double t[16];
#define PX_(x) (L + ((x) - x0) / (x1 - x0) * (W - L - R))
#define PY_(y) (T + (y1 - (y)) / (y1 - y0) * (H - T - B))
    fprintf(html, "<figure><svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" font-family=\"sans-serif\" "
                  "font-size=\"11\"><rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" stroke=\"#999\"/>",
            W + LW, H, L, T, W - L - R, H - T - B);
    fprintf(html, "<text x=\"%d\" y=\"15\" font-weight=\"bold\">%s</text>", L, title);
    n = ticks(x0, x1, 0, t, 16);
    for (i = 0; i < n; i++) {
        fprintf(html, "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"#333\"/>", PX_(t[i]), H - B, PX_(t[i]), H - B + 4);
        svg_tick_label(html, PX_(t[i]), H - B + 16, "middle", t[i], 0);
    }
    fprintf(html, "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\" font-style=\"italic\">%s</text>", (L + W - R) / 2.0, H - 8, xlabel);
    n = ticks(y0, y1, 0, t, 16);
    for (i = 0; i < n; i++) {
        fprintf(html, "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#ddd\"/>", L, PY_(t[i]), W - R, PY_(t[i]));
        svg_tick_label(html, L - 6, PY_(t[i]) + 4, "end", t[i], 0);
    }
    fprintf(html, "<text transform=\"translate(14,%.1f) rotate(-90)\" text-anchor=\"middle\" font-style=\"italic\">%s</text>",
            (T + H - B) / 2.0, ylabel);
    for (i = 0; i < nc; i++) {
        fprintf(html, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\"%s points=\"", col[c[i].colour % 8],
                c[i].dash == 1 ? " stroke-dasharray=\"6 3\"" : c[i].dash == 2 ? " stroke-dasharray=\"2 2\"" : "");
        for (j = 0; j < c[i].n; j++)
            fprintf(html, "%.1f,%.1f ", PX_(c[i].x[j]), PY_(c[i].y[j]));
        fprintf(html, "\"/>");
        fprintf(html, "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"%s\" stroke-width=\"1.5\"%s/>"
                      "<text x=\"%d\" y=\"%d\">%s</text>",
                W + 4, T + 14 * i + 6, W + 28, T + 14 * i + 6, col[c[i].colour % 8],
                c[i].dash == 1 ? " stroke-dasharray=\"6 3\"" : c[i].dash == 2 ? " stroke-dasharray=\"2 2\"" : "",
                W + 32, T + 14 * i + 10, c[i].label);
    }
#undef PX_
#undef PY_
    fprintf(html, "</svg></figure>\n");
}

/* directional albedo of kernel k at N.V = nv (albedo input 1): the integral
 * of f (N.L) over the hemisphere of L, midpoint rule in (theta_l, phi_l) */
static double furnace(const facet_kernel *k, double nv, double alpha)
{
    const int NT = 48, NP = 96;
    double sv = sqrt(1 - nv * nv), sum = 0, in[FACET_MAX_INPUTS];
    int i, j;
    for (i = 0; i < NT; i++) {
        double th = (i + 0.5) / NT * (PI_REPORT / 2), ct = cos(th), st = sin(th);
        for (j = 0; j < NP; j++) {
            double ph = (j + 0.5) / NP * (2 * PI_REPORT);
            geom g = { 0 };
            g.nl = ct, g.nv = nv, g.lv = st * sv * cos(ph) + ct * nv;
            g.alpha = alpha, g.albedo = 1, g.f0 = 0.04, g.f90 = 1, g.gamma = 2;
            if (!geom_inputs(&g, k->inputs, k->n_inputs, in))
                return -1;
            sum += k->oracle(in) * ct * st;
        }
    }
    return sum * (PI_REPORT / 2 / NT) * (2 * PI_REPORT / NP);
}

static void section_furnace(void)
{
    static const double alphas[3] = { 0.05, 0.3, 1.0 };
    curve c[24];
    int nc = 0, colour = 0, a, i;
    size_t ki;
    char b[6][32];
    h2("White furnace: directional albedo of the diffuse models");
    para("Each diffuse kernel's double oracle with albedo 1, integrated against N.L over the hemisphere of L "
         "(midpoint rule, 48 x 96 directions; its own error shows in Lambert's 1.0002) for each view angle: the "
         "fraction of light a white surface returns. Lambert is 1 everywhere by construction; a model above 1 creates energy, one below loses "
         "it (to what a multiple-scattering term would return). Solid, dashed, dotted: alpha = 0.05, 0.3, 1.");
    thead(6, "model", "alpha", "albedo at N.V = 1", "at N.V = 0.5", "at N.V = 0.1", "min .. max");
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const facet_kernel *k = facet_kernel_at(ki);
        if (strncmp(k->name, "diffuse_", 8) && strcmp(k->name, "lambert"))
            continue;
        int has_alpha = 0;
        for (i = 0; i < k->n_inputs; i++)
            has_alpha |= !strcmp(k->inputs[i], "alpha");
        for (a = 0; a < (has_alpha ? 3 : 1) && nc < 24; a++) {
            curve *cv = &c[nc];
            double lo = 1e9, hi = -1e9;
            const char *cells[6];
            cv->n = 0;
            for (i = 0; i < 19; i++) {
                double nv = cos(i * 5.0 * PI_REPORT / 180), v;
                nv = nv < 0.02 ? 0.02 : nv; /* the last point: 88.9 deg */
                v = furnace(k, nv, alphas[a]);
                if (v < 0)
                    break;
                cv->x[cv->n] = acos(nv) * 180 / PI_REPORT;
                cv->y[cv->n++] = v;
                lo = v < lo ? v : lo;
                hi = v > hi ? v : hi;
            }
            if (!cv->n)
                break;
            if (has_alpha)
                snprintf(cv->label, sizeof cv->label, "%s, alpha %g", k->name, alphas[a]);
            else
                snprintf(cv->label, sizeof cv->label, "%s (any alpha)", k->name);
            cv->colour = colour;
            cv->dash = a;
            cells[0] = k->name;
            cells[1] = has_alpha ? fmt(b[0], sizeof b[0], "%g", alphas[a]) : "any";
            cells[2] = fmt(b[1], sizeof b[1], "%.4f", furnace(k, 1.0, alphas[a]));
            cells[3] = fmt(b[2], sizeof b[2], "%.4f", furnace(k, 0.5, alphas[a]));
            cells[4] = fmt(b[3], sizeof b[3], "%.4f", furnace(k, 0.1, alphas[a]));
            cells[5] = fmt(b[4], sizeof b[4], "%.4f .. %.4f", lo, hi);
            trow(cells);
            nc++;
        }
        colour++;
    }
    tend();
    svg_lines("Directional albedo (white furnace)", "view angle theta_v (deg)", "albedo", c, nc, 0, 90, 0, 1.4);
    fprintf(md, "(The plot is in index.html.)\n\n");
}

static void section_pictures(void)
{
    pic p;
    int w;
    static const char *hm_file[PIC_N_HEATMAPS] = {
        "heat_vis_hammon.png", "heat_g2_uncorrelated.png", "heat_g1_hammon.png",
        "heat_lambert.png", "heat_brdf_hammon_model.png",
    };
    h2("Pictures");
    say("pictures: BRDF slices, spheres, heatmaps ...");
    p = pic_slices();
    picture(&p, "slices.png");
    pic_free(&p);
    p = pic_spheres();
    picture(&p, "spheres.png");
    pic_free(&p);
    for (w = 0; w < PIC_N_HEATMAPS; w++) {
        p = pic_heatmap(w);
        picture(&p, hm_file[w]);
        pic_free(&p);
    }
    p = pic_heatmap_f32();
    picture(&p, "heat_brdf_hammon_f32.png");
    pic_free(&p);
    p = pic_heatmap_fx(0);
    picture(&p, "heat_brdf_hammon_fx.png");
    pic_free(&p);
    p = pic_heatmap_fx(1);
    picture(&p, "heat_brdf_hammon_fx_inputs.png");
    pic_free(&p);
}

typedef struct shade_ctx { rs_gbuf *g; int path; } shade_ctx;

static int shade(rs_gbuf *g, int path)
{
    switch (path) {
    case 0: rs_shade_scalar(g); return 1;
    case 1: return rs_shade_avx2(g);
    case 2: return rs_shade_sse2(g);
    case 3: rs_shade_batch(g); return 1;
    case 4: return rs_shade_neon(g);
    case 5: return rs_shade_fx(g);
    case 6: rs_shade_rgb(g); return 1;
    case 7: rs_shade_material(g); return 1;
    default: rs_shade_pixel(g); return 1;
    }
}

static void shade_work(void *ctx, long reps)
{
    shade_ctx *c = ctx;
    long r;
    for (r = 0; r < reps; r++)
        shade(c->g, c->path);
}

static double raster_avx2_per_eval = -1, raster_batch_per_eval = -1;

static void section_raster(void)
{
    static const char *names[9] = { "scalar inline", "AVX2 inline (8 px)", "SSE2 inline (4 px)",
                                    "batch (deferred, 3 calls per light)", "NEON inline (4 px)", "fixed point",
                                    "RGB batch (deferred, 1 call per light)",
                                    "RGB batch, uniform material per run", "per pixel: shade_hammon_rgb_f32 (N, L, V)" };
    static const char *files[9] = { "raster_scalar.png", "raster_avx2.png", "raster_sse2.png",
                                    "raster_batch.png", "raster_neon.png", "raster_fx.png",
                                    "raster_rgb.png", "raster_material.png", "raster_pixel.png" };
    int W = quick ? 96 : 480, H = quick ? 64 : 320, p;
    rs_gbuf *g;
    unsigned char *ref, *img;
    size_t np;
    char b[10][64];
    pic pp = { 0 };
    say("rasterizer: %dx%d ...", W, H);
    g = rs_render(W, H);
    np = (size_t)W * (size_t)H * 3;
    ref = malloc(np);
    img = malloc(np);
    rs_shade_oracle(g);
    rs_to_srgb(g, ref);
    h2("Software rasterizer");
    para("%dx%d, %ld front-facing triangles rasterized (perspective, z-buffer, perspective-correct "
         "normals and positions), %d shaded pixels, %d lights (directional + point), RGB: %d BRDF "
         "evaluations per pixel. Cost of the shading pass only (dots from the interpolated normal, view "
         "and light vectors, BRDF, accumulation), measured like the kernels (R vs 2R frames, >= 11 epochs). "
         "Difference: 8-bit sRGB against the same frame shaded by the double oracle, over shaded pixels "
         "(max and mean per channel; p99 of each pixel's largest channel difference; CIE76 delta E).",
         W, H, g->triangles, g->n, g->n_lights, 3 * g->n_lights);
    thead(10, "path", "ticks/pixel", "est. cyc/pixel", "est. cyc/BRDF eval", "spread", "max diff", "mean diff",
          "p99 diff", "mean dE76", "max dE76");
    for (p = 0; p < 9; p++) {
        shade_ctx c;
        cyc_stat s;
        long reps;
        int maxd;
        double meand, per_eval;
        const char *cells[10];
        img_err ie;
        c.g = g;
        c.path = p;
        if (!shade(g, p)) {
            cells[0] = names[p];
            cells[1] = cells[2] = cells[3] = cells[4] = cells[5] = cells[6] = cells[7] = cells[8] = cells[9] = "n/a";
            trow(cells);
            continue;
        }
        rs_to_srgb(g, img);
        rs_diff(g, ref, img, &maxd, &meand);
        img_compare_rgb8(&ie, img, ref, g->idx, g->n);
        reps = 1;
        s = cyc_measure(shade_work, &c, reps, (double)g->n, quick ? 11 : 11);
        per_eval = est(s.median) / (3.0 * g->n_lights);
        if (p == 1)
            raster_avx2_per_eval = per_eval;
        if (p == 3)
            raster_batch_per_eval = per_eval;
        cells[0] = names[p];
        cells[1] = fmt(b[0], sizeof b[0], "%.1f", s.median);
        cells[2] = fmt(b[1], sizeof b[1], "%.1f", est(s.median));
        cells[3] = fmt(b[2], sizeof b[2], "%.2f", per_eval);
        cells[4] = fmt(b[3], sizeof b[3], "%.1f%%%s", 100 * s.spread, s.noisy ? " !" : "");
        cells[5] = fmt(b[4], sizeof b[4], "%d", maxd);
        cells[6] = fmt(b[5], sizeof b[5], "%.4f", meand);
        cells[7] = fmt(b[6], sizeof b[6], "%.0f", ie.p99_code);
        cells[8] = fmt(b[7], sizeof b[7], "%.4f", ie.mean_de);
        cells[9] = fmt(b[8], sizeof b[8], "%.2f", ie.max_de);
        trow(cells);
        {
            char path[1024];
            snprintf(path, sizeof path, "%s/%s", outdir, files[p]);
            png_write(path, img, W, H);
        }
    }
    tend();
    pp.w = W;
    pp.h = H;
    pp.rgb = ref;
    snprintf(pp.title, sizeof pp.title, "Rasterizer, oracle-shaded reference");
    snprintf(pp.caption, sizeof pp.caption, "Spheres across alpha (0.02 copper, 0.08 red plastic, 0.2 gold, 0.45 blue plastic, 0.9 clay) on a rippled floor mesh (alpha 0.3); directional light from the upper left and a bluish point light on the right. The facet-shaded frames (raster_*.png) differ from it by at most the 'max diff' above.");
    picture(&pp, "raster_oracle.png");
    if (!shade(g, 1))
        shade(g, 0);
    rs_to_srgb(g, img);
    pp.rgb = img;
    snprintf(pp.title, sizeof pp.title, "Rasterizer, shaded with facet (AVX2 inline where available)");
    snprintf(pp.caption, sizeof pp.caption, "The same frame shaded with facet_brdf_hammon_f32_avx2, 8 pixels per call.");
    picture(&pp, "raster_facet.png");
    free(ref);
    free(img);
    rs_free(g);
}

static double armv(const char *what, const char *kernel, const char *cpu)
{
    const tsv *t = arm_of(what, kernel, cpu);
    return t ? t->v : -1;
}

static const char *armcell(char *b, size_t n, double v)
{
    if (v < 0)
        return "-";
    return fmt(b, n, "%.0f", v);
}

static void section_arm(void)
{
    size_t ki;
    h2("Cortex-M: fixed point vs soft-float f32 (qemu traces; measured counts, modelled cycles)");
    if (!n_arm) {
        para("No Cortex-M figures in this build (arm.tsv empty: bench/cortexm/cortexm.sh needs arm-none-eabi-gcc "
             "with newlib and qemu-system-arm; llvm-mca for the modelled cycles).");
        return;
    }
    para("bench/cortexm/cortexm.sh builds bench/cortexm/cortexm_main.c with arm-none-eabi-gcc -O2 -mthumb -mcpu=CORE "
         "(fixed point: src/fx/fx_prims.c, src/fx/fx_kernels.c; f32: facet/scalar.h with -mfloat-abi=soft, so "
         "every float operation is a libgcc call), runs it under qemu-system-arm -singlestep -d exec "
         "(one log line per executed instruction) and cuts each kernel call out of the trace, from the "
         "kernel's first instruction to its return: callees (reciprocal, square root, libgcc soft-float "
         "helpers) included, argument set-up and the call instruction not. 4 representative inputs "
         "(consistent geometry, alpha 0.012 to 0.6), one call each; figures are the mean per call. "
         "<b>insns</b>: executed instructions, MEASURED (qemu; a count, not cycles). <b>mca</b>: llvm-mca "
         "(LLVM 14) cycles for the core on the executed instruction sequence as straight-line code, "
         "MODELLED: branch targets folded to one label, calls as plain branches, no pipeline refill on "
         "taken branches (1-3 cycles each on M4; <b>taken</b> gives their count per call), zero wait "
         "states; cortex-m7 with IT blocks unpredicated (LLVM's M7 model lacks IT). <b>M0 cyc</b>: the "
         "Cortex-M0 TRM timing table (loads/stores 2, taken branch 3, BL 4, POP with PC 3+N, single-cycle "
         "multiplier, zero wait states) applied to the executed ARMv6-M trace, MODELLED. The M0 build runs "
         "on mps2-an385 (a Cortex-M3 model; the executed path depends only on the ISA), M33 code on the "
         "M4 model (mps2-an386), M7 on mps2-an500.");
    thead(12, "kernel", "fx M0 insns", "fx M0 cyc (TRM)", "fx M4 insns", "fx M4 / M7 / M33 mca",
          "fx M4 taken", "f32 soft M0 insns", "f32 soft M0 cyc (TRM)", "f32 soft M4 insns",
          "f32 soft M4 / M7 / M33 mca", "soft/fx M4 (mca)", "soft/fx M0 (TRM)");
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const char *kn = facet_kernel_at(ki)->name;
        char b[12][96];
        const char *cells[12];
        double fm4 = armv("fx-mca", kn, "cortex-m4"), sm4 = armv("f32soft-mca", kn, "cortex-m4");
        double f0c = armv("fx-m0cyc", kn, "cortex-m0"), s0c = armv("f32soft-m0cyc", kn, "cortex-m0");
        if (armv("fx-insns", kn, "cortex-m4") < 0 && armv("f32soft-insns", kn, "cortex-m4") < 0)
            continue;
        cells[0] = kn;
        cells[1] = armcell(b[1], sizeof b[1], armv("fx-insns", kn, "cortex-m0"));
        cells[2] = armcell(b[2], sizeof b[2], f0c);
        cells[3] = armcell(b[3], sizeof b[3], armv("fx-insns", kn, "cortex-m4"));
        cells[4] = fm4 < 0 ? "-" : fmt(b[4], sizeof b[4], "%.0f / %.0f / %.0f", fm4, armv("fx-mca", kn, "cortex-m7"),
                                       armv("fx-mca", kn, "cortex-m33"));
        cells[5] = armcell(b[5], sizeof b[5], armv("fx-taken", kn, "cortex-m4"));
        cells[6] = armcell(b[6], sizeof b[6], armv("f32soft-insns", kn, "cortex-m0"));
        cells[7] = armcell(b[7], sizeof b[7], s0c);
        cells[8] = armcell(b[8], sizeof b[8], armv("f32soft-insns", kn, "cortex-m4"));
        cells[9] = sm4 < 0 ? "-" : fmt(b[9], sizeof b[9], "%.0f / %.0f / %.0f", sm4,
                                       armv("f32soft-mca", kn, "cortex-m7"), armv("f32soft-mca", kn, "cortex-m33"));
        cells[10] = fm4 > 0 && sm4 > 0 ? fmt(b[10], sizeof b[10], "%.1fx", sm4 / fm4) : "-";
        cells[11] = f0c > 0 && s0c > 0 ? fmt(b[11], sizeof b[11], "%.1fx", s0c / f0c) : "-";
        trow(cells);
    }
    tend();    para("The fast tiers against the precise fixed point and the core's FPU: <b>fx_fast</b> "
         "(facet_KERNEL_fx_fast, src/fx/fx_fast.c) and the precise f32 kernel built for the core's FPU "
         "(<b>f32 FPU</b>: -mfloat-abi=hard, -mfpu=fpv4-sp-d16 on M4, fpv5-d16 on M7), measured the same way.");
    thead(9, "kernel", "fx_fast M0 insns", "fx_fast M0 cyc (TRM)", "fx_fast M4 insns", "fx_fast M4 / M7 / M33 mca",
          "fx M4 insns", "f32 FPU M4 insns", "f32 FPU M4 / M7 mca", "fx/fx_fast M4 (mca)");
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const char *kn = facet_kernel_at(ki)->name;
        char b[9][96];
        const char *cells[9];
        double q4 = armv("fxfast-mca", kn, "cortex-m4"), p4 = armv("fx-mca", kn, "cortex-m4");
        double h4 = armv("f32fpu-mca", kn, "cortex-m4");
        if (armv("fxfast-insns", kn, "cortex-m4") < 0 && armv("f32fpu-insns", kn, "cortex-m4") < 0)
            continue;
        cells[0] = kn;
        cells[1] = armcell(b[1], sizeof b[1], armv("fxfast-insns", kn, "cortex-m0"));
        cells[2] = armcell(b[2], sizeof b[2], armv("fxfast-m0cyc", kn, "cortex-m0"));
        cells[3] = armcell(b[3], sizeof b[3], armv("fxfast-insns", kn, "cortex-m4"));
        cells[4] = q4 < 0 ? "-" : fmt(b[4], sizeof b[4], "%.0f / %.0f / %.0f", q4, armv("fxfast-mca", kn, "cortex-m7"),
                                      armv("fxfast-mca", kn, "cortex-m33"));
        cells[5] = armcell(b[5], sizeof b[5], armv("fx-insns", kn, "cortex-m4"));
        cells[6] = armcell(b[6], sizeof b[6], armv("f32fpu-insns", kn, "cortex-m4"));
        {
            char m7[16];
            cells[7] = h4 < 0 ? "-" : fmt(b[7], sizeof b[7], "%.0f / %s", h4,
                                          armcell(m7, sizeof m7, armv("f32fpu-mca", kn, "cortex-m7")));
        }
        cells[8] = q4 > 0 && p4 > 0 ? fmt(b[8], sizeof b[8], "%.1fx", p4 / q4) : "-";
        trow(cells);
    }
    tend();
}

/* the precision tiers' targets: each tier's brdf_hammon batch against the
 * fast-math shader peer built for the same width, and the fast fixed point
 * on the Cortex-M cores */
static void target_tiers(void)
{
    static const char *const widths[] = { "avx2", "avx512" };
    static const struct { const char *format; double want; } tiers[] = { { "f32_fast", 1.5 }, { "f32", 1.0 } };
    char b[4][400], peer[32];
    const char *cells[4];
    size_t w, t;
    for (w = 0; w < 2; w++)
        for (t = 0; t < 2; t++) {
            const row *x = find_row("brdf_hammon", tiers[t].format, widths[w], "batch"), *p;
            snprintf(peer, sizeof peer, "shader_%s_fm", widths[w]);
            p = find_row("brdf_hammon", "f32", peer, "peer");
            cells[0] = fmt(b[0], sizeof b[0], "%s brdf_hammon %s batch >= %.1fx the fast-math shader peer at the same width",
                           widths[w], tiers[t].format, tiers[t].want);
            if (x && p) {
                double r = p->r.thr.median / x->r.thr.median;
                cells[1] = fmt(b[1], sizeof b[1], "%.2fx (%.2f vs %.2f est. cycles/sample); max err %.3g vs bound %.3g",
                               r, est(x->r.thr.median), est(p->r.thr.median), x->r.err.max_rel, x->r.bound);
                cells[2] = r >= tiers[t].want && x->r.within ? "yes" : "**no**";
                cells[3] = "ratio within one run; the peer (-march of the same width, -ffast-math) computes "
                           "brdf_hammon's own formula from the same dots (bench/harness/peers.h), max error ~0.4 "
                           "at the peak";
            } else {
                cells[1] = "-";
                cells[2] = "n/a";
                cells[3] = "this CPU does not run that width";
            }
            trow(cells);
        }
    {
        double m4 = armv("fxfast-insns", "brdf_hammon", "cortex-m4"), m0 = armv("fxfast-insns", "brdf_hammon", "cortex-m0");
        double fpu = armv("f32fpu-insns", "brdf_hammon", "cortex-m4"), m4mca = armv("fxfast-mca", "brdf_hammon", "cortex-m4");
        cells[0] = "fx_fast brdf_hammon <= 150 executed instructions per call on Cortex-M4, <= 450 on Cortex-M0, "
                   "fewer than the f32 kernel on the M4's FPU";
        if (m4 > 0 && m0 > 0) {
            cells[1] = fmt(b[1], sizeof b[1], "M4 %.0f (llvm-mca %.0f cycles), M0 %.0f, f32 FPU M4 %.0f", m4, m4mca, m0, fpu);
            cells[2] = m4 <= 150 && m0 <= 450 && (fpu < 0 || m4 < fpu) ? "yes" : "**no**";
            cells[3] = "instructions MEASURED under qemu (bench/cortexm); bound: ~26 high-word 32x32 products, "
                       "4 table functions, 9 clz, 6 clamps at 2^-10 (README fixed point, fast tier)";
        } else {
            cells[1] = "-";
            cells[2] = "n/a";
            cells[3] = "no Cortex-M figures in this build";
        }
        trow(cells);
    }
}

static void section_targets(void)
{
    const row *ab = find_row("brdf_hammon", "f32", "avx2", "batch");
    const row *fastest = NULL;
    char b[12][400];
    const char *cells[4];
    int i;
    size_t ki;
    h2("Targets");
    thead(4, "target", "measured / modelled", "met?", "note");
    /* the fastest peer at AVX2's width (built -march=x86-64-v3), or the
     * width-independent textbook peer */
    for (i = 0; i < n_rows; i++)
        if (!strcmp(rows[i].path, "peer") && !strcmp(rows[i].kernel, "brdf_hammon") &&
            (strstr(rows[i].port, "_avx2") || !strstr(rows[i].port, "_avx512")) &&
            (!fastest || rows[i].r.thr.median < fastest->r.thr.median))
            fastest = &rows[i];
    cells[0] = "AVX2 brdf_hammon batch <= 3.0 core cycles/sample";
    if (ab) {
        double c = est(ab->r.thr.median);
        cells[1] = fmt(b[0], sizeof b[0], "%.2f %s", c, cyc_is_cycles() ? "cycles (measured)" : "est. cycles (TSC ticks / measured ratio)");
        cells[2] = c <= 3.0 ? "yes" : "**no**";
    } else {
        cells[1] = "no AVX2 on this machine";
        cells[2] = "n/a";
    }
    cells[3] = "";
    trow(cells);
    cells[0] = "AVX2 brdf_hammon >= 1.8x faster than the fastest peer at the same width, within its bound";
    if (ab && fastest) {
        double r = fastest->r.thr.median / ab->r.thr.median;
        cells[1] = fmt(b[1], sizeof b[1], "%.2fx vs %s (%.2f est. cycles/sample); max err %.3g vs bound %.3g", r,
                       fastest->port, est(fastest->r.thr.median), ab->r.err.max_rel, ab->r.bound);
        cells[2] = r >= 1.8 && ab->r.within ? "yes" : "**no**";
        cells[3] = "ratio within one run; the peer computes brdf_hammon's own formula from the same dots (see peers)";
    } else {
        cells[1] = "-";
        cells[2] = "n/a";
        cells[3] = "";
    }
    trow(cells);
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const char *kn = facet_kernel_at(ki)->name;
        const row *x = find_row(kn, "f32", "avx2", "batch");
        double m = mca_of("f32", "avx2", kn, "znver3");
        if (!x || m <= 0)
            continue;
        cells[0] = fmt(b[2], sizeof b[2], "AVX2 %s within 1.25x of llvm-mca znver3", kn);
        cells[1] = fmt(b[3], sizeof b[3], "%.2f est. cycles vs %.2f modelled (%.2fx); skylake model %.2f",
                       est(x->r.thr.median), m, est(x->r.thr.median) / m, mca_of("f32", "avx2", kn, "skylake"));
        cells[2] = est(x->r.thr.median) <= 1.25 * m ? "yes" : "**no**";
        cells[3] = "this machine is not a Zen 3 (see clock)";
        trow(cells);
    }
    for (ki = 0; ki < facet_kernel_count(); ki++) { /* target: every AVX2 kernel >= 5x its scalar port */
        const char *kn = facet_kernel_at(ki)->name;
        const row *x = find_row(kn, "f32", "avx2", "batch"), *sc = find_row(kn, "f32", "scalar", "batch");
        if (!x || !sc)
            continue;
        cells[0] = fmt(b[2], sizeof b[2], "AVX2 %s >= 5x its scalar port (batch)", kn);
        cells[1] = fmt(b[3], sizeof b[3], "%.1fx (%.2f vs %.2f est. cycles/sample)", sc->r.thr.median / x->r.thr.median,
                       est(sc->r.thr.median), est(x->r.thr.median));
        cells[2] = sc->r.thr.median >= 5.0 * x->r.thr.median ? "yes" : "**no**";
        cells[3] = "ratio within one run";
        trow(cells);
    }
    {
        double fx = armv("fx-mca", "brdf_hammon", "cortex-m4"), sf = armv("f32soft-mca", "brdf_hammon", "cortex-m4");
        double fxi = armv("fx-insns", "brdf_hammon", "cortex-m4"), sfi = armv("f32soft-insns", "brdf_hammon", "cortex-m4");
        double f0 = armv("fx-m0cyc", "brdf_hammon", "cortex-m0"), s0 = armv("f32soft-m0cyc", "brdf_hammon", "cortex-m0");
        cells[0] = "fx brdf_hammon <= 150 cycles/sample on Cortex-M4 (llvm-mca)";
        cells[1] = fx > 0 ? fmt(b[4], sizeof b[4], "%.0f cycles per call, MODELLED (llvm-mca cortex-m4 on the executed "
                                                    "trace, %.0f instructions measured under qemu; + %.0f taken branches "
                                                    "at 1-3 cycles not modelled)", fx, fxi, armv("fx-taken", "brdf_hammon", "cortex-m4"))
                          : "not available";
        cells[2] = fx > 0 ? (fx <= 150 ? "yes" : "**no**") : "n/a";
        cells[3] = "4 representative inputs, mean per call; see the Cortex-M section";
        trow(cells);
        cells[0] = "fx brdf_hammon >= 10x fewer cycles than soft-float f32 on the same core";
        if (fx > 0 && sf > 0) {
            cells[1] = fmt(b[5], sizeof b[5], "Cortex-M4: %.1fx (%.0f vs %.0f cycles, MODELLED by llvm-mca on the traces; "
                                              "executed instructions MEASURED: %.0f vs %.0f, %.1fx)%s",
                           sf / fx, sf, fx, sfi, fxi, sfi / fxi,
                           f0 > 0 && s0 > 0 ? fmt(b[7], sizeof b[7], "; Cortex-M0: %.1fx (%.0f vs %.0f cycles, TRM-table model)",
                                                  s0 / f0, s0, f0) : "");
            cells[2] = sf / fx >= 10 ? "yes" : "**no**";
        } else {
            cells[1] = "not available";
            cells[2] = "n/a";
        }
        cells[3] = "soft-float: facet/scalar.h -mfloat-abi=soft, libgcc helpers included in the trace";
        trow(cells);
    }
    cells[0] = "rasterizer AVX2 shading <= 1.3x the batch benchmark's cycles/sample";
    if (ab && raster_avx2_per_eval > 0) {
        double r = raster_avx2_per_eval / est(ab->r.thr.median);
        cells[1] = fmt(b[6], sizeof b[6], "%.2f est. cycles per BRDF evaluation vs %.2f (%.2fx)", raster_avx2_per_eval,
                       est(ab->r.thr.median), r);
        cells[2] = r <= 1.3 ? "yes" : "**no**";
        cells[3] = "shading cost includes the per-pixel vectors and dots, amortised over 3 channels";
    } else {
        cells[1] = "-";
        cells[2] = "n/a";
        cells[3] = "";
    }
    trow(cells);
    target_tiers();
    tend();
}

/* the core part of report.md (accuracy tables) as HTML: headings, tables,
 * paragraphs; enough for what tests/report/report.sh writes */
static void md_to_html(FILE *in, FILE *out)
{
    char line[8192];
    int in_table = 0, header = 0;
    while (fgets(line, sizeof line, in)) {
        size_t n = strlen(line);
        while (n && (line[n - 1] == '\n' || line[n - 1] == '\r'))
            line[--n] = 0;
        if (line[0] == '|') {
            char *p = line + 1, *q;
            if (strstr(line, "---")) {
                header = 0;
                continue;
            }
            if (!in_table) {
                fputs("<table>", out);
                in_table = 1;
                header = 1;
            }
            fputs("<tr>", out);
            while ((q = strchr(p, '|'))) {
                *q = 0;
                fprintf(out, header ? "<th>%s</th>" : "<td>%s</td>", p);
                p = q + 1;
            }
            fputs("</tr>\n", out);
            continue;
        }
        if (in_table) {
            fputs("</table>\n", out);
            in_table = 0;
        }
        if (!line[0])
            continue;
        if (line[0] == '#') {
            int lv = 0;
            while (line[lv] == '#')
                lv++;
            fprintf(out, "<h%d>%s</h%d>\n", lv, line + lv + 1, lv);
        } else {
            fprintf(out, "<p>%s</p>\n", line);
        }
    }
    if (in_table)
        fputs("</table>\n", out);
}

/* the heading of the bench part, in bench.md and index.html: a quick run
 * says so, since its figures come from a few samples */
#define BENCH_TITLE "Benchmarks (bench/)"
#define BENCH_QUICK_TITLE "Benchmarks (bench/), QUICK RUN"
#define BENCH_QUICK_NOTE "Quick run (<code>facet-bench report --quick</code>): few samples, short passes, " \
    "small pictures; these figures test the machinery and are not for comparison. <code>make report</code> " \
    "measures in full."

static int copy_file(const char *path, FILE *out)
{
    FILE *in = fopen(path, "r");
    int c;
    if (!in)
        return 0;
    while ((c = fgetc(in)) != EOF)
        fputc(c, out);
    fclose(in);
    return 1;
}

/* report.md and index.html are composed here, from accuracy.md (the part
 * tests/report/report.sh writes; absent in a bench-only run) and this run's bench
 * part, so a quick run after a full one replaces the bench part of both
 * rather than adding a second one beside the stale first. */
/* accuracy.md split at its first section: the head (title, machine, date)
 * opens the report, the accuracy tables close it (the long tables last) */
static char *read_all(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    char *b = NULL;
    long len;
    *n = 0;
    if (!f)
        return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (len = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0) {
        b = malloc((size_t)len + 1);
        if (b) {
            *n = fread(b, 1, (size_t)len, f);
            b[*n] = 0;
        }
    }
    fclose(f);
    return b;
}

static size_t accuracy_split(const char *acc)
{
    const char *p = strstr(acc, "\n## ");
    return p ? (size_t)(p - acc) + 1 : strlen(acc);
}

static void md_part_to_html(const char *text, size_t n, FILE *out)
{
    FILE *in = fmemopen((void *)text, n, "r");
    if (!in || !n) {
        if (in)
            fclose(in);
        return;
    }
    md_to_html(in, out);
    fclose(in);
}

static void write_index(void)
{
    char path[1024];
    FILE *out;
    char *acc;
    size_t n, head;
    snprintf(path, sizeof path, "%s/index.html", outdir);
    out = fopen(path, "w");
    if (!out)
        return;
    fprintf(out, "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>facet report%s</title>\n", quick ? " (quick run)" : "");
    fputs("<style>body{font-family:sans-serif;max-width:1200px;margin:2em auto;padding:0 1em;color:#222}"
          "table{border-collapse:collapse;font-size:12px;margin:1em 0}td,th{border:1px solid #ccc;padding:2px 6px;"
          "text-align:left}th{background:#f0f0f0}figure{margin:1em 0}figcaption{font-size:12px;color:#444;"
          "max-width:900px}img{image-rendering:pixelated}</style></head><body>\n", out);
    snprintf(path, sizeof path, "%s/accuracy.md", outdir);
    acc = read_all(path, &n);
    head = acc ? accuracy_split(acc) : 0;
    if (acc)
        md_part_to_html(acc, head, out);
    else
        fputs("<h1>facet report</h1>\n", out);
    fprintf(out, "<h1>%s</h1>\n", quick ? BENCH_QUICK_TITLE : BENCH_TITLE);
    snprintf(path, sizeof path, "%s/bench.html", outdir);
    copy_file(path, out);
    if (acc && head < n) {
        fputs("<h1>Accuracy (tests/report/report.sh)</h1>\n", out);
        md_part_to_html(acc + head, n - head, out);
    }
    free(acc);
    fputs("</body></html>\n", out);
    fclose(out);
}

static void write_report_md(void)
{
    char path[1024];
    FILE *out;
    char *acc;
    size_t n, head;
    snprintf(path, sizeof path, "%s/report.md", outdir);
    out = fopen(path, "w");
    if (!out)
        return;
    snprintf(path, sizeof path, "%s/accuracy.md", outdir);
    acc = read_all(path, &n);
    head = acc ? accuracy_split(acc) : 0;
    if (acc)
        fwrite(acc, 1, head, out);
    else
        fputs("# facet report\n\n(bench part only: no accuracy.md from tests/report/report.sh here)\n", out);
    snprintf(path, sizeof path, "%s/bench.md", outdir);
    copy_file(path, out);
    if (acc && head < n) {
        fputs("\n# Accuracy (tests/report/report.sh)\n\n", out);
        fwrite(acc + head, 1, n - head, out);
    }
    free(acc);
    fclose(out);
}

int facet_bench_report(int argc, char **argv)
{
    bench_opts o;
    char path[1024];
    int i;
    time_t t0 = time(NULL);
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--quick"))
            quick = 1;
        else
            outdir = argv[i];
    }
    if (!outdir) {
        fprintf(stderr, "usage: facet-bench report OUTDIR [--quick]\n");
        return 2;
    }
    cyc_init();
    tpc = cyc_ticks_per_cycle();
    mca = read_tsv("mca.tsv", &n_mca, 1);
    sizes = read_tsv("size.tsv", &n_sizes, 0);
    arm = read_tsv("arm.tsv", &n_arm, 0);
    armvec = read_tsv("arm_vec.tsv", &n_armvec, 1);
    snprintf(path, sizeof path, "%s/bench.md", outdir);
    md = fopen(path, "w");
    snprintf(path, sizeof path, "%s/bench.html", outdir);
    html = fopen(path, "w");
    if (!md || !html) {
        fprintf(stderr, "facet-bench report: cannot write to %s\n", outdir);
        return 1;
    }
    bench_defaults(&o);
    if (quick) {
        o.n_time = 256;
        o.n_err = 4096;
        o.target = 5000;
    } else {
        o.n_err = 1 << 17;
    }
    o.progress = 1;
    o.sampler_batch_only = 1; /* the samplers' table shows the batch rows */
    say("benchmarks: every kernel x format x port x path, and the peers ...");
    bench_run(&o, collect, NULL);
    say("model-error sweep of the approximations ...");
    sweep_tradeoffs();

    fprintf(md, "\n# %s\n\n", quick ? BENCH_QUICK_TITLE : BENCH_TITLE);
    if (quick)
        para(BENCH_QUICK_NOTE);
    /* the summary first, the figures next, the long tables last (the
     * targets need the rasterizer's figures, so they follow it) */
    section_choose();
    section_clock();
    section_pareto();
    section_image_error();
    section_furnace();
    section_tradeoff();
    section_pictures();
    {
        time_t ts = time(NULL);
        say("importance sampling: cost table, picture of sampled directions, chi-square table ...");
        report_samplers(md, html, outdir, quick, find_bench_row, tpc);
        say("importance sampling section done in %ld s", (long)(time(NULL) - ts));
    }
    section_arm();
    section_raster();
    section_targets();
    section_kernels();
    fclose(md);
    fclose(html);
    write_index();
    write_report_md();
    say("bench part done in %ld s: %s/index.html, %s/bench.md", (long)(time(NULL) - t0), outdir, outdir);
    (void)both;
    return 0;
}
