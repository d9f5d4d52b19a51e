/* sec_samplers.c - importance sampling: the samplers' cost per port and
 * tier beside the textbook peer (rows of the bench run), a picture of
 * sampled directions against the pdf (OUTDIR/sampling.svg, inlined in the
 * HTML), and the chi-square table that tests/sample/test_sample_chi2.c
 * printed into OUTDIR/sample_chi2.txt (bench/report/sample_chi2.sh). */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "facet/oracle.h"
#include "report.h"
#include "svg.h"

static const double PI_ = 3.14159265358979323846;
#define HIST_COLOUR "#9ab"
#define PDF_COLOUR "#d1242f"

/* ---- cost table ------------------------------------------------------------ */

static void cost_table(const report *r)
{
    const report_data *d = r->data;
    const char *ports[8], *head[24];
    int np = 0, i, t;
    size_t p, si;
    char c[24][64];
    const char *cells[24];
    for (p = 0; p < facet_port_count() && np < 8; p++) {
        int sup = 0;
        const char *pn = facet_port_at(p, &sup, NULL);
        if (sup)
            ports[np++] = pn;
    }
    /* header: sampler, f32 per port, f32_fast per port, textbook, the
     * peer's time over the first (widest) port's and over the last's (scalar) */
    snprintf(c[0], sizeof c[0], "sampler");
    for (t = 0; t < 2; t++)
        for (i = 0; i < np; i++)
            snprintf(c[1 + t * np + i], sizeof c[0], "%s %s", t ? "f32_fast" : "f32", ports[i]);
    snprintf(c[1 + 2 * np], sizeof c[0], "textbook peer");
    snprintf(c[2 + 2 * np], sizeof c[0], "peer / %s f32", np ? ports[0] : "-");
    snprintf(c[3 + 2 * np], sizeof c[0], "peer / %s f32", np ? ports[np - 1] : "-");
    for (i = 0; i < 4 + 2 * np; i++)
        head[i] = c[i], cells[i] = c[i];
    doc_table_head(r->doc, 4 + 2 * np, head);
    for (si = 0; si < facet_sampler_count(); si++) {
        const char *kn = facet_sampler_at(si)->name;
        const bench_row *peer = data_row_of(d, kn, "f32", "textbook", "peer"), *best = NULL, *last = NULL;
        int any = 0;
        snprintf(c[0], sizeof c[0], "%s", kn);
        for (t = 0; t < 2; t++)
            for (i = 0; i < np; i++) {
                const bench_row *x = data_row_of(d, kn, t ? "f32_fast" : "f32", ports[i], "batch");
                if (x) {
                    snprintf(c[1 + t * np + i], sizeof c[0], "%.2f%s (%.1f)%s", x->thr.median,
                             x->thr.noisy ? "!" : "", data_est(d, x->thr.median), x->within ? "" : " **BAD**");
                    any = 1;
                } else {
                    snprintf(c[1 + t * np + i], sizeof c[0], "-");
                }
                if (!t && i == 0)
                    best = x;
                if (!t && i == np - 1)
                    last = x;
            }
        if (!any)
            continue;
        if (peer)
            snprintf(c[1 + 2 * np], sizeof c[0], "%.2f%s (%.1f)", peer->thr.median, peer->thr.noisy ? "!" : "",
                     data_est(d, peer->thr.median));
        else
            snprintf(c[1 + 2 * np], sizeof c[0], "-");
        if (peer && best && best->thr.median > 0)
            snprintf(c[2 + 2 * np], sizeof c[0], "%.1fx", peer->thr.median / best->thr.median);
        else
            snprintf(c[2 + 2 * np], sizeof c[0], "-");
        if (peer && last && last->thr.median > 0)
            snprintf(c[3 + 2 * np], sizeof c[0], "%.2fx", peer->thr.median / last->thr.median);
        else
            snprintf(c[3 + 2 * np], sizeof c[0], "-");
        doc_row(r->doc, cells);
    }
    doc_table_end(r->doc);
}

/* ---- picture: histograms of theta_h against the pdf -------------------------- */

typedef struct panel {
    int vndf;            /* 0: ggx_sample_d, 1: ggx_sample_vndf */
    double alpha, view;  /* view: degrees from N */
} panel;

#define NBINS 45
#define NCURVE 180

static uint64_t rng_next(uint64_t *s) /* splitmix64 */
{
    uint64_t z = (*s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/* the marginal density of theta_h per degree: sin(theta) times the pdf
 * (per solid angle) integrated over phi (midpoint rule, 512 points) */
static double marginal(const panel *pn, const float v[3], double th)
{
    double s = sin(th), c = cos(th), sum = 0;
    int k;
    const int NP = 512;
    for (k = 0; k < NP; k++) {
        double f = 2 * PI_ * (k + 0.5) / NP, h[3] = { s * cos(f), s * sin(f), c };
        if (pn->vndf)
            sum += facet_oracle_ggx_pdf_vndf(v[2], c, v[0] * h[0] + v[1] * h[1] + v[2] * h[2], pn->alpha);
        else
            sum += facet_oracle_ggx_pdf_d(c, pn->alpha);
    }
    return sum * 2 * PI_ / NP * s * PI_ / 180;
}

/* one panel, plot area (x0, y0) w x h: n samples of the panel's sampler
 * (f32 batch, the active port) binned in theta_h, and the pdf's marginal
 * density as a curve */
static void draw_panel(svg *sv, const panel *pn, long n, int x0, int y0, int w, int h)
{
    float *u1 = malloc(n * sizeof(float)), *u2 = malloc(n * sizeof(float)), *al = malloc(n * sizeof(float));
    float *vx = malloc(n * sizeof(float)), *vy = malloc(n * sizeof(float)), *vz = malloc(n * sizeof(float));
    float *hx = malloc(n * sizeof(float)), *hy = malloc(n * sizeof(float)), *hz = malloc(n * sizeof(float));
    long cnt[NBINS] = { 0 }, j, over = 0;
    double curve[NCURVE + 1], cx[NCURVE + 1], xmax, ymax = 0, bw, step;
    float v[3];
    uint64_t s = 0x51ce5eedull + (uint64_t)(pn->alpha * 1000) * 7919u + (uint64_t)pn->view * 131u + (uint64_t)pn->vndf;
    int i;
    double t = pn->view * PI_ / 180;
    char title[96];
    svg_plot pl;
    v[0] = (float)(sin(t) * cos(0.7));
    v[1] = (float)(sin(t) * sin(0.7));
    v[2] = (float)cos(t);
    for (j = 0; j < n; j++) {
        u1[j] = (float)(rng_next(&s) >> 40) * 0x1p-24f;
        u2[j] = (float)(rng_next(&s) >> 40) * 0x1p-24f;
        al[j] = (float)pn->alpha;
        vx[j] = v[0];
        vy[j] = v[1];
        vz[j] = v[2];
    }
    if (pn->vndf)
        facet_ggx_sample_vndf_f32_batch(hx, hy, hz, vx, vy, vz, u1, u2, al, (size_t)n);
    else
        facet_ggx_sample_d_f32_batch(hx, hy, hz, u1, u2, al, (size_t)n);
    /* x range: the 99.5% point of theta_h (from the pdf), up to 90 degrees */
    {
        double acc = 0, prev = marginal(pn, v, 0);
        xmax = 90;
        for (i = 1; i <= 900; i++) {
            double y = marginal(pn, v, i * 0.1 * PI_ / 180);
            acc += 0.05 * (prev + y);
            prev = y;
            if (acc >= 0.995) {
                xmax = ceil(i * 0.1 / 10) * 10;
                break;
            }
        }
    }
    bw = xmax / NBINS;
    for (j = 0; j < n; j++) {
        double th = atan2(sqrt((double)hx[j] * hx[j] + (double)hy[j] * hy[j]), hz[j]) * 180 / PI_;
        int b = (int)(th / bw);
        if (b >= NBINS)
            over++;
        else if (b >= 0)
            cnt[b]++;
    }
    for (i = 0; i <= NCURVE; i++) {
        cx[i] = xmax * i / NCURVE;
        curve[i] = marginal(pn, v, cx[i] * PI_ / 180);
        if (curve[i] > ymax)
            ymax = curve[i];
    }
    for (i = 0; i < NBINS; i++)
        if (cnt[i] / (n * bw) > ymax)
            ymax = cnt[i] / (n * bw);
    step = svg_step(0, ymax * 1.05);
    ymax = ceil(ymax * 1.05 / step) * step;
    memset(&pl, 0, sizeof pl);
    pl.s = sv;
    pl.x = x0, pl.y = y0, pl.w = w, pl.h = h;
    pl.ax.label = "theta_h (degrees)";
    pl.ax.hi = xmax;
    pl.ay.label = "density per degree";
    pl.ay.hi = ymax;
    pl.ay.step = step;
    pl.label_gap = 50;
    if (pn->vndf)
        snprintf(title, sizeof title, "ggx_sample_vndf, alpha %g, view %g deg", pn->alpha, pn->view);
    else
        snprintf(title, sizeof title, "ggx_sample_d, alpha %g", pn->alpha);
    svg_plot_frame(&pl, title);
    for (i = 0; i < NBINS; i++)
        svg_plot_bar(&pl, i * bw, (i + 1) * bw, cnt[i] / (n * bw), HIST_COLOUR);
    svg_plot_line(&pl, NCURVE + 1, cx, curve, PDF_COLOUR, 0, 1.5);
    if (over)
        svg_text(sv, x0 + w - 4, y0 + 14, "end", " fill=\"#555\"", "%.2f%% beyond %g deg", 100.0 * over / n, xmax);
    free(u1); free(u2); free(al); free(vx); free(vy); free(vz); free(hx); free(hy); free(hz);
}

/* writes the SVG to OUTDIR/sampling.svg and returns it (malloc'd) for
 * inlining */
static char *sampling_svg(const char *outdir, long n)
{
    static const panel panels[6] = {
        { 0, 0.1, 0 }, { 0, 0.5, 0 }, { 0, 1.0, 0 }, { 1, 0.5, 0 }, { 1, 0.5, 60 }, { 1, 0.5, 89 },
    };
    char *buf, path[1024], hist[200];
    int i, W = 1090, H = 610, PW = 250, PH = 200;
    svg s;
    svg_key keys[2] = {
        { NULL, HIST_COLOUR, SVG_KEY_BOX, 0 },
        { "pdf: the oracle's ggx_pdf_d / ggx_pdf_vndf (per solid angle), integrated over phi_h, times sin theta_h",
          PDF_COLOUR, SVG_KEY_LINE, 0 },
    };
    FILE *f;
    snprintf(hist, sizeof hist, "histogram of %ld samples (facet_ggx_sample_d_f32_batch / "
                                "facet_ggx_sample_vndf_f32_batch, port %s, u on the 2^-24 grid)", n, facet_port_name());
    keys[0].label = hist;
    svg_begin(&s, W, H);
    svg_raw(&s, "<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n", W, H);
    svg_legend(&s, 70, 13, 2, keys, 0);
    for (i = 0; i < 6; i++)
        draw_panel(&s, &panels[i], n, 75 + (i % 3) * (PW + 105), 75 + (i / 3) * (PH + 75), PW, PH);
    buf = svg_end(&s);
    snprintf(path, sizeof path, "%s/sampling.svg", outdir);
    f = fopen(path, "w");
    if (f) {
        fputs(buf, f);
        fputc('\n', f);
        fclose(f);
    }
    return buf;
}

/* ---- the chi-square table ------------------------------------------------------- */

/* appends to a growing text */
static void add(char **t, size_t *len, size_t *cap, const char *s)
{
    size_t n = strlen(s);
    if (*len + n + 1 > *cap) {
        *cap = (*len + n + 1) * 2;
        *t = realloc(*t, *cap);
        if (!*t) {
            fprintf(stderr, "facet-bench report: out of memory\n");
            exit(1);
        }
    }
    memcpy(*t + *len, s, n + 1);
    *len += n;
}

/* The test's output as Markdown: its lines as paragraphs, its tables as
 * they are, and a header for the moment rows (they have none of their
 * own) */
static void chi2_table(const report *r)
{
    char path[1024], line[1024], *t = NULL;
    size_t len = 0, cap = 0;
    FILE *f;
    int part = 0, open = 0;
    snprintf(path, sizeof path, "%s/sample_chi2.txt", r->outdir);
    f = fopen(path, "r");
    if (!f) {
        doc_para(r->doc, "No chi-square results (sample_chi2.txt missing: run bench/report/sample_chi2.sh).");
        return;
    }
    add(&t, &len, &cap, "");
    while (fgets(line, sizeof line, f)) {
        size_t n = strlen(line);
        while (n && (line[n - 1] == '\n' || line[n - 1] == '\r'))
            line[--n] = 0;
        if (line[0] == '|') {
            if (!open && part == 1)
                add(&t, &len, &cap, "| sampler | alpha_x | alpha_y | view (deg) | 1 - N.H: sample mean vs pdf's, "
                                    "variance vs pdf's (z-scores) |\n|---|---|---|---|---|\n");
            open = 1;
            add(&t, &len, &cap, line);
            add(&t, &len, &cap, "\n");
            continue;
        }
        if (open) {
            add(&t, &len, &cap, "\n");
            open = 0;
        }
        if (!line[0])
            continue;
        if (!strncmp(line, "moments", 7))
            part = 1;
        add(&t, &len, &cap, line);
        add(&t, &len, &cap, "\n\n");
    }
    if (open)
        add(&t, &len, &cap, "\n");
    fclose(f);
    doc_markdown(r->doc, t, len);
    free(t);
}

void section_samplers(report *r)
{
    char *markup;
    long n = r->quick ? 100000 : 1000000;
    const char *unit = r->data->clock.unit;
    report_say("importance sampling: cost table, picture of sampled directions, chi-square table ...");
    doc_heading(r->doc, 2, "Importance sampling");
    doc_para(r->doc, "Cost of each sampler and pdf (facet.h, \"GGX and GTR importance sampling\"): %s per sample "
                     "(median; '!' where the spread exceeds 5%%) and, in parentheses, est. core cycles (see the clock "
                     "section), through the batch API (facet_&lt;sampler&gt;_f32_batch and _f32_fast_batch) with "
                     "facet_set_port(port) active, in structure-of-arrays over the in-domain inputs of "
                     "tests/sample/test_sample_accuracy.c (gtr_sample_d with gamma = 1), beside the textbook peer "
                     "(tests/lib/sample_peer.h: the direct formulas with libm, in float, -O2, one sample at a time; "
                     "no peer for the anisotropic forms, reflect and pdf_vndf_reflect). Measured in the same run as "
                     "the kernels' rows; compare ratios only. Every facet row is within its facet.h bound in the "
                     "samplers' error measure (<code>facet-bench bench SAMPLER</code> shows the errors).", unit);
    cost_table(r);
    markup = sampling_svg(r->outdir, n);
    {
        char caption[800];
        doc_fig f;
        snprintf(caption, sizeof caption,
                 "Histograms of theta_h (the angle of h from N) of %ld samples per panel from the f32 batch samplers "
                 "on port %s, against the marginal density of the pdf (the oracle's, integrated over the azimuth). "
                 "Top: D sampling at alpha 0.1, 0.5, 1; bottom: visible normals at alpha 0.5 for views at 0, 60 and "
                 "89 degrees from N. File: sampling.svg. The goodness of fit is tested below.", n, facet_port_name());
        memset(&f, 0, sizeof f);
        f.title = "Sampled half vectors against the pdf";
        f.caption = caption;
        f.svg = markup;
        f.file = "sampling.svg";
        doc_figure(r->doc, &f);
    }
    free(markup);
    doc_heading(r->doc, 3, "Chi-square goodness of fit (tests/sample/test_sample_chi2.c)");
    doc_para(r->doc, "Each sampler against its pdf: 16 x 16 bins in (q, phi_h), q the GGX CDF of theta_h, bins "
                     "expecting fewer than 5 pooled; Pearson chi-square, pass p > 0.01; integral - 1: the pdf's "
                     "quadrature over the hemisphere. The test's own output, run for this report.");
    chi2_table(r);
}
