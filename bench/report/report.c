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
#include "png.h"
#include "raster/raster.h"
#include "facet_bench.h"

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

/* a PNG written to OUTDIR/name and inlined in the HTML */
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

/* ---- modelled cycles and sizes from report.sh --------------------------- */

/* a row of a .tsv: three names and a value (and a source), or with a
 * leading format column (mca.tsv) four names */
typedef struct tsv { char f[32], a[32], b[32], c[32]; double v; char src[64]; } tsv;
static tsv *mca, *sizes, *arm;
static int n_mca, n_sizes, n_arm;

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
/* the diffuse and whole-BRDF rows: L.V = N.L N.V (azimuths 90 deg apart), f0 = 0.04, albedo = 0.8 */
static double m_lambert(const double *x) { (void)x; return facet_oracle_lambert(0.8); }
static double m_diffuse_hammon(const double *x) { return facet_oracle_diffuse_hammon(x[0], x[1], x[0] * x[1], x[2], 0.8); }
static double m_brdf_hammon(const double *x) { return facet_oracle_brdf_hammon(x[0], x[1], x[0] * x[1], x[2], 0.04, 0.8); }
static double m_brdf_exact(const double *x) { return bench_oracle_brdf_exact(x[0], x[1], x[0] * x[1], x[2], 0.04, 0.8); }

#define AX_NL(lo) { "N.L", lo, 1.0 }
#define AX_NV(lo) { "N.V", lo, 1.0 }
#define AX_A { "alpha", 0x1p-10, 1.0 }
#define VIS3 3, { AX_NL(0x1p-8), AX_NV(0x1p-8), AX_A }   /* the fixed-point cos floor, and issue 10's domain */
#define G3 3, { AX_NL(0x1p-12), AX_NV(0x1p-12), AX_A }
#define G1D 2, { AX_NV(0x1p-12), AX_A }

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
    { "G2 correlation", "smith_g2_uncorrelated", "smith_g2 (correlated)", "smith_g2_uncorrelated", "smith_g2",
      m3_smith_g2_uncorrelated, m3_smith_g2, G3, 0, 0, { 0 }, 0 },
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

typedef struct point { double x, y; char label[48]; int kind; } point; /* kind 0 facet, 1 peer, 2 approx */

static void svg_pareto(const char *title, const point *p, int n)
{
    double x0 = 1e30, x1 = -1e30, y0 = 1e30, y1 = -1e30;
    int W = 640, H = 360, L = 70, B = 40, i, d;
    double lx0, lx1, ly0, ly1;
    static const char *col[3] = { "#1f6feb", "#d1242f", "#8250df" };
    for (i = 0; i < n; i++) {
        double y = p[i].y > 1e-9 ? p[i].y : 1e-9;
        if (p[i].x <= 0 || !(p[i].y == p[i].y))
            continue;
        if (p[i].x < x0) x0 = p[i].x;
        if (p[i].x > x1) x1 = p[i].x;
        if (y < y0) y0 = y;
        if (y > y1) y1 = y;
    }
    if (x0 > x1)
        return;
    lx0 = floor(log10(x0 * 0.8));
    lx1 = ceil(log10(x1 * 1.25));
    ly0 = floor(log10(y0)) ;
    ly1 = ceil(log10(y1 > 1 ? y1 : 1)) + (y1 >= 1 ? 0.5 : 0);
    if (lx1 <= lx0) lx1 = lx0 + 1;
    if (ly1 <= ly0) ly1 = ly0 + 1;
    fprintf(html, "<figure><svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" font-family=\"sans-serif\" font-size=\"11\">\n", W, H);
    fprintf(html, "<rect x=\"%d\" y=\"10\" width=\"%d\" height=\"%d\" fill=\"#fafafa\" stroke=\"#888\"/>\n", L, W - L - 10, H - B - 10);
#define SX(v) (L + (log10(v) - lx0) / (lx1 - lx0) * (W - L - 10))
#define SY(v) (10 + (ly1 - log10(v)) / (ly1 - ly0) * (H - B - 10))
    for (d = (int)lx0; d <= (int)lx1; d++)
        fprintf(html, "<line x1=\"%.1f\" x2=\"%.1f\" y1=\"10\" y2=\"%d\" stroke=\"#ddd\"/><text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">1e%d</text>\n",
                SX(pow(10, d)), SX(pow(10, d)), H - B, SX(pow(10, d)), H - B + 14, d);
    for (d = (int)ly0; d <= (int)ly1; d++)
        fprintf(html, "<line x1=\"%d\" x2=\"%d\" y1=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/><text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">1e%d</text>\n",
                L, W - 10, SY(pow(10, d)), SY(pow(10, d)), L - 4, SY(pow(10, d)) + 4, d);
    fprintf(html, "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">est. core cycles per sample (log)</text>\n", (W + L) / 2, H - 6);
    fprintf(html, "<text x=\"14\" y=\"%d\" transform=\"rotate(-90 14 %d)\" text-anchor=\"middle\">max rel. error vs exact model (log)</text>\n", H / 2, H / 2);
    for (i = 0; i < n; i++) {
        double y = p[i].y > 1e-9 ? p[i].y : 1e-9;
        if (p[i].x <= 0 || !(p[i].y == p[i].y))
            continue;
        if (isinf(y))
            y = pow(10, ly1);
        fprintf(html, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"%s\"/><text x=\"%.1f\" y=\"%.1f\" fill=\"%s\">%s</text>\n",
                SX(p[i].x), SY(y), col[p[i].kind], SX(p[i].x) + 6, SY(y) - 4 + 9 * (i % 2), col[p[i].kind], p[i].label);
    }
#undef SX
#undef SY
    fprintf(html, "</svg><figcaption><b>Pareto: %s.</b> Blue: facet exact kernels (error = f32 arithmetic); "
                  "purple: facet approximations (error = model error vs the exact term); red: peers "
                  "(error vs the oracle of the model they compute). Lower left is better.</figcaption></figure>\n", title);
}

/* ---- sections ------------------------------------------------------------------ */

static void section_clock(void)
{
    h2("Clock and method");
    para("Clock: <b>%s</b> (%s). %s Pinned to CPU %d. Throughput: %s samples per pass, "
         "L1-resident structure-of-arrays of valid random geometry from tests/sample.h (per-sample "
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
         "against round-half-up(oracle 2^frac) at those Q15 inputs, the measure of tests/test_fx_accuracy.c "
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
    para("Peers (bench/harness/peers.h): <b>textbook</b> (-O2): H = normalize(L+V), powf, D in tan form, Smith "
         "via Lambda with sqrtf, plain divisions. <b>shader</b> (-O3 -fno-math-errno "
         "-ffp-contract=fast, auto-vectorized), built for the width of the facet port it is compared with: "
         "<b>shader_avx2</b> -march=x86-64-v3, <b>shader_avx512</b> -march=x86-64-v4 (each run only where "
         "that port runs; elsewhere one native build): a2 form of D, exact correlated Vis with two sqrtf, "
         "pow5 by multiplication, Hammon diffuse. <b>*_fm</b>: the same source and width with -ffast-math. "
         "Single-term "
         "peers take the same inputs as the facet kernel. The brdf_hammon peer rows compute "
         "D Vis_exact F + Hammon diffuse from vectors L, V in tangent space (N = z) plus alpha, f0, "
         "albedo; facet's brdf_hammon takes (N.L, N.V, L.V) and uses Hammon's Vis (its model error is in "
         "the tradeoff table), so a caller with vectors pays one extra 3-term dot product for L.V.");
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

static void section_pareto(void)
{
    static const char *groups[4][6] = {
        { "visibility", "smith_vis", "smith_vis_hammon", "smith_vis_joint_approx", "smith_vis_fit", NULL },
        { "G1", "smith_g1", "smith_g1_hammon", "smith_g1_beckmann", "smith_g1_schlick_beckmann", NULL },
        { "G2", "smith_g2", "smith_g2_hammon", "smith_g2_uncorrelated", NULL },
        { "whole BRDF", "brdf_hammon", NULL },
    };
    int g;
    h2("Pareto: error vs cycles, per term");
    fprintf(md, "(The SVG plots are in index.html.)\n\n");
    for (g = 0; g < 4; g++) {
        point pts[64];
        int n = 0, s, i, t;
        for (s = 1; groups[g][s]; s++) {
            const char *kn = groups[g][s];
            double model = 0;
            int approx = 0;
            for (t = 0; t < N_TRADE; t++)
                if (!strcmp(trades[t].cheap_kernel, kn)) {
                    model = trades[t].max_rel;
                    approx = 1;
                }
            for (i = 0; i < n_rows && n < 64; i++) {
                const row *x = &rows[i];
                if (strcmp(x->kernel, kn) || strcmp(x->format, "f32"))
                    continue;
                if (strcmp(x->path, "batch") && strcmp(x->path, "peer"))
                    continue;
                pts[n].x = est(x->r.thr.median);
                if (!strcmp(x->path, "peer")) {
                    pts[n].kind = 1;
                    pts[n].y = x->r.err.max_rel;
                    snprintf(pts[n].label, sizeof pts[n].label, "%s %s", x->port, kn);
                } else {
                    pts[n].kind = approx ? 2 : 0;
                    pts[n].y = approx ? (model > x->r.err.max_rel ? model : x->r.err.max_rel) : x->r.err.max_rel;
                    snprintf(pts[n].label, sizeof pts[n].label, "%s %s", kn, x->port);
                }
                n++;
            }
        }
        svg_pareto(groups[g][0], pts, n);
    }
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
    p = pic_colorbar();
    picture(&p, "colorbar.png");
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
    default: return rs_shade_fx(g);
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
    static const char *names[6] = { "scalar inline", "AVX2 inline (8 px)", "SSE2 inline (4 px)",
                                    "batch (deferred)", "NEON inline (4 px)", "fixed point" };
    static const char *files[6] = { "raster_scalar.png", "raster_avx2.png", "raster_sse2.png",
                                    "raster_batch.png", "raster_neon.png", "raster_fx.png" };
    int W = quick ? 96 : 480, H = quick ? 64 : 320, p;
    rs_gbuf *g;
    unsigned char *ref, *img;
    size_t np;
    char b[8][64];
    pic pp;
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
         "Difference: 8-bit sRGB against the same frame shaded by the double oracle, over shaded pixels.",
         W, H, g->triangles, g->n, g->n_lights, 3 * g->n_lights);
    thead(7, "path", "ticks/pixel", "est. cyc/pixel", "est. cyc/BRDF eval", "spread", "max diff", "mean diff");
    for (p = 0; p < 6; p++) {
        shade_ctx c;
        cyc_stat s;
        long reps;
        int maxd;
        double meand, per_eval;
        const char *cells[7];
        c.g = g;
        c.path = p;
        if (!shade(g, p)) {
            cells[0] = names[p];
            cells[1] = cells[2] = cells[3] = cells[4] = cells[5] = cells[6] = "n/a";
            trow(cells);
            continue;
        }
        rs_to_srgb(g, img);
        rs_diff(g, ref, img, &maxd, &meand);
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
         "(fixed point: src/fx_core.c, src/fx_kernels.c; f32: facet/scalar.h with -mfloat-abi=soft, so "
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
         "(facet_KERNEL_fx_fast, src/fx_fast.c) and the precise f32 kernel built for the core's FPU "
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
                cells[3] = "ratio within one run; the peer (-march of the same width, -ffast-math) computes the "
                           "exact-Vis model from vectors, max error ~0.3 at the peak";
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
        cells[3] = "ratio within one run; the peer computes the exact-Vis model from vectors (see peers)";
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
 * paragraphs; enough for what tests/report.sh writes */
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

static void write_index(void)
{
    char path[1024];
    FILE *out, *in;
    int c;
    snprintf(path, sizeof path, "%s/index.html", outdir);
    out = fopen(path, "w");
    if (!out)
        return;
    fputs("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>facet report</title>\n"
          "<style>body{font-family:sans-serif;max-width:1200px;margin:2em auto;padding:0 1em;color:#222}"
          "table{border-collapse:collapse;font-size:12px;margin:1em 0}td,th{border:1px solid #ccc;padding:2px 6px;"
          "text-align:left}th{background:#f0f0f0}figure{margin:1em 0}figcaption{font-size:12px;color:#444;"
          "max-width:900px}img{image-rendering:pixelated}</style></head><body>\n", out);
    snprintf(path, sizeof path, "%s/report.md", outdir);
    in = fopen(path, "r");
    if (in) {
        md_to_html(in, out);
        fclose(in);
    } else {
        fputs("<h1>facet report</h1>\n", out);
    }
    fputs("<h1>Benchmarks (bench/)</h1>\n", out);
    snprintf(path, sizeof path, "%s/bench.html", outdir);
    in = fopen(path, "r");
    if (in) {
        while ((c = fgetc(in)) != EOF)
            fputc(c, out);
        fclose(in);
    }
    fputs("</body></html>\n", out);
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
    say("benchmarks: every kernel x format x port x path, and the peers ...");
    bench_run(&o, collect, NULL);
    say("model-error sweep of the approximations ...");
    sweep_tradeoffs();

    fprintf(md, "\n# Benchmarks (bench/)\n\n");
    section_clock();
    /* targets need the rasterizer figures: render the later sections to a
     * buffer first?  Simpler: the rasterizer runs before the targets. */
    {
        FILE *m0 = md, *h0 = html;
        char *mb = NULL, *hb = NULL;
        size_t ms = 0, hs = 0;
        md = open_memstream(&mb, &ms);
        html = open_memstream(&hb, &hs);
        section_kernels();
        section_tradeoff();
        section_pareto();
        section_arm();
        section_raster();
        section_pictures();
        fclose(md);
        fclose(html);
        md = m0;
        html = h0;
        section_targets();
        fwrite(mb, 1, ms, md);
        fwrite(hb, 1, hs, html);
        free(mb);
        free(hb);
    }
    fclose(md);
    fclose(html);
    write_index();
    say("bench part done in %ld s: %s/index.html, %s/bench.md", (long)(time(NULL) - t0), outdir, outdir);
    (void)both;
    return 0;
}
