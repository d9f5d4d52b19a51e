/* sec_pareto.c - per term, every kernel in every format, tier and port by cost and by
 * its two errors: the Pareto figures and their numbered tables. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "kernel_facts.h"
#include "svg.h"
#include "report.h"

/* a Pareto point: cost on this machine and the two errors, kept apart */
typedef struct point {
    double x;       /* est. cycles per sample */
    double yi;      /* implementation error: max rel. vs the oracle of its own formula (value >= 2^-8) */
    double ym;      /* model error: max rel. vs the exact term; 0 exact; < 0 not an approximation of it */
    char label[64];
    int kind;       /* 0 facet, 1 peer */
} point;

/* errors are drawn between 10^-8 (or exact) and 2.5 (above 1, and inf, at the top) */
#define ERR_FLOOR 1e-8
#define ERR_CEIL 2.5
static double err_clamp_to(double v, double ceil_) { return v > ERR_FLOOR ? (v < ceil_ ? v : ceil_) : ERR_FLOOR; }

static const char *const kind_colour[2] = { "#1f6feb", "#d1242f" };
#define FRONTIER_COLOUR "#2da44e"

/* one panel of a Pareto figure: log cost across, log error up, points
 * numbered (the table under the figure names them; hover shows the name),
 * the frontier (the least error within each cost) as a step line */
static void pareto_panel(svg *s, double ox, double W, double H, const char *title, const point *p, int n, int model,
                         const svg_axis *ax)
{
    svg_plot pl;
    int i, order[128], m = 0, nf = 0;
    double best = 1e300, fx[260], fy[260], top = pow(10, 0.5), top_clamp = ERR_CEIL;
    /* model errors above 1 (the diffuse kernels against the simulation):
     * the axis reaches the largest, up to 10^3 */
    for (i = 0; i < n && model; i++)
        while (p[i].ym > top_clamp && top < 1e3)
            top *= 10, top_clamp = 0.8 * top;
    memset(&pl, 0, sizeof pl);
    pl.s = s;
    pl.x = ox + 62;
    pl.y = 22;
    pl.w = W - 62 - 10;
    pl.h = H - 40 - 22 - 14;
    pl.ax = *ax;
    pl.ay.label = model ? "model error (max rel.)" : "implementation error (max rel.)";
    pl.ay.lo = ERR_FLOOR;
    pl.ay.hi = top;
    pl.ay.log = 1;
    pl.ay.lo_text = model ? "exact" : "<= 10^-8";
    pl.label_gap = 50;
    svg_plot_frame(&pl, title);
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
    for (i = 0; i < m; i++) {
        double y = err_clamp_to(model ? p[order[i]].ym : p[order[i]].yi, top_clamp);
        if (y < best) {
            if (best < 1e300)
                fx[nf] = p[order[i]].x, fy[nf++] = best;
            best = y;
            fx[nf] = p[order[i]].x, fy[nf++] = best;
        }
    }
    if (best < 1e300) {
        fx[nf] = pl.ax.hi, fy[nf++] = best;
        svg_plot_line(&pl, nf, fx, fy, FRONTIER_COLOUR, 0, 1.5);
    } else {
        svg_plot_note(&pl, "none: these kernels are different models, not approximations of one");
    }
    for (i = 0; i < m; i++) {
        const point *q = &p[order[i]];
        double y = model ? q->ym : q->yi;
        char num[16], hover[160], eb[32];
        snprintf(num, sizeof num, "%d", order[i] + 1);
        snprintf(hover, sizeof hover, "%d: %s, %.2f est. cycles/sample, %s error %s", order[i] + 1, q->label, q->x,
                 model ? "model" : "implementation", y == 0 ? "exact" : report_g3(eb, y));
        svg_plot_dot(&pl, q->x, err_clamp_to(y, top_clamp), kind_colour[q->kind], num, hover);
    }
}

/* a Pareto figure: implementation error and model error side by side over
 * the same cost axis, a legend, and the numbered table */
static void pareto_figure(const report *r, const char *term, const point *p, int n)
{
    static const svg_key keys[3] = {
        { "facet kernel (format, tier, port)", "#1f6feb", SVG_KEY_DOT, 0 },
        { "peer", "#d1242f", SVG_KEY_DOT, 0 },
        { "frontier: the least error within each cost", FRONTIER_COLOUR, SVG_KEY_LINE, 0 },
    };
    double x0 = 1e30, x1 = -1e30, lx0, lx1;
    int W = 470, H = 344, i;
    char b[4][48], title[160];
    svg s;
    svg_axis ax = { "est. core cycles per sample", 0, 0, 1, 0, NULL };
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
    ax.lo = pow(10, lx0);
    ax.hi = pow(10, lx1);
    svg_begin(&s, 2 * W, H);
    pareto_panel(&s, 0, W, H, "implementation error (vs its own formula)", p, n, 0, &ax);
    pareto_panel(&s, W, W, H, "model error (vs the exact term)", p, n, 1, &ax);
    svg_legend(&s, 62, H - 8, 3, keys, 1);
    snprintf(title, sizeof title, "Pareto: %s", term);
    report_svg_figure(r, svg_end(&s), title,
                      "Left: each kernel's arithmetic error against the double "
                      "oracle of its own formula (max relative, over samples whose value is >= 2^-8; above 1, "
                      "or inf, drawn at the top). Right: the "
                      "formula's model error against the exact term (0 drawn as 'exact'; diffuse: against the simulated "
                      "Smith microsurface of each kernel's material, section Tradeoff; kernels that are a different "
                      "model rather than an approximation are left out). Blue: facet, red: peers; green: the frontier "
                      "(the least error within each cost). Numbers: the table below.");
    doc_table(r->doc, 5, "#", "candidate", "est. cycles/sample", "impl. error", "model error");
    for (i = 0; i < n; i++) {
        const char *cells[5];
        cells[0] = report_fmt(b[0], sizeof b[0], "%d", i + 1);
        cells[1] = p[i].label;
        cells[2] = report_fmt(b[1], sizeof b[1], "%.2f", p[i].x);
        cells[3] = p[i].yi < 0 ? "-" : report_g3(b[2], p[i].yi);
        cells[4] = p[i].ym < 0 ? "n/a" : p[i].ym == 0 ? "exact" : report_g3(b[3], p[i].ym);
        doc_row(r->doc, cells);
    }
    doc_table_end(r->doc);
}

void section_pareto(report *r)
{
    report_data *D = r->data;
    static const char *const formats[] = { "f32", "f32_fast", "fx", "fx_fast", "f16" };
    int g;
    doc_heading(r->doc, 2, "%s", "Pareto: error vs cycles, per term");
    doc_para(r->doc, "Every facet kernel of each term in every format and tier on every port this machine runs (batch path), "
         "and the peers, by cost (est. cycles per sample) and by the two errors, kept apart. Fixed-point "
         "implementation error: against the oracle at the same Q15 inputs (the input rounding is in the "
         "image-space section). Binary16 (f16): the rows of f16 tables that compute in binary16 (avx512fp16 here), "
         "error in facet/f16.h's measure restricted to values >= 2^-8 at the f16 tests' binary16 inputs; the scalar "
         "f16 table, the specification emulated in portable C, is in the kernels table, not plotted. (The SVG plots "
         "are in index.html.)");
    for (g = 0; g < kf_term_count(); g++) {
        const char *names[32];
        int nk = kf_term_kernels(g, names, 32), ref = kf_term_has_reference(g);
        point pts[128];
        int n = 0, s2, i, f;
        for (s2 = 0; s2 < nk && n < 128; s2++) {
            const char *kn = names[s2];
            double model = ref ? kf_model_of(kn) : -1;
            for (f = 0; f < 5; f++)
                for (i = 0; i < D->n_rows && n < 128; i++) {
                    const bench_row *x = &D->rows[i].r;
                    if (strcmp(x->kernel, kn) || strcmp(x->format, formats[f]) || strcmp(x->path, "batch"))
                        continue;
                    if (f == 4 && !strcmp(x->port, "scalar")) /* emulated: not a way to compute */
                        continue;
                    pts[n].x = data_est(D, x->thr.median);
                    pts[n].yi = x->err.max_rel_vis;
                    pts[n].ym = model;
                    pts[n].kind = 0;
                    snprintf(pts[n].label, sizeof pts[n].label, "%s %s %s", kn, x->format, x->port);
                    n++;
                }
            for (i = 0; i < D->n_rows && n < 128; i++) {
                const bench_row *x = &D->rows[i].r;
                if (strcmp(x->kernel, kn) || strcmp(x->path, "peer"))
                    continue;
                pts[n].x = data_est(D, x->thr.median);
                pts[n].yi = x->err.max_rel_vis;
                /* every "peer" row computes the kernel's own formula (the exact-Vis
                 * brdf peers are path "peer-vectors", not plotted) */
                pts[n].ym = model;
                pts[n].kind = 1;
                snprintf(pts[n].label, sizeof pts[n].label, "peer %s (%s)", x->port, kn);
                n++;
            }
        }
        if (n)
            pareto_figure(r, kf_term_title(g), pts, n);
    }
}
