/* samplers.c - the importance-sampling section of the report (called by
 * report.c): the samplers' cost per port and tier beside the textbook peer
 * (rows of the bench run, harness/bench.c), a picture of sampled directions
 * against the pdf (SVG: OUTDIR/sampling.svg, inlined in the HTML), and the
 * chi-square table that tests/sample/test_sample_chi2.c printed into
 * OUTDIR/sample_chi2.txt (bench/report/sample_chi2.sh). */
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
#include "harness/cycles.h"
#include "samplers.h"

static const double PI_ = 3.14159265358979323846;

/* ---- cost table ------------------------------------------------------------ */

static void cell_row(FILE *md, FILE *html, int n, char c[][64])
{
    int i;
    fprintf(html, "<tr>");
    for (i = 0; i < n; i++) {
        fprintf(md, "| %s ", c[i]);
        fprintf(html, "<td>%s</td>", c[i]);
    }
    fprintf(md, "|\n");
    fprintf(html, "</tr>\n");
}

static void cost_table(FILE *md, FILE *html, const report_data *d)
{
    const char *ports[8];
    int np = 0, i, t;
    size_t p, si;
    char c[24][64];
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
    fprintf(html, "<table><tr>");
    for (i = 0; i < 4 + 2 * np; i++) {
        fprintf(md, "| %s ", c[i]);
        fprintf(html, "<th>%s</th>", c[i]);
    }
    fprintf(md, "|\n");
    for (i = 0; i < 4 + 2 * np; i++)
        fprintf(md, "|---");
    fprintf(md, "|\n");
    fprintf(html, "</tr>\n");
    for (si = 0; si < facet_sampler_count(); si++) {
        const char *kn = facet_sampler_at(si)->name;
        const bench_row *peer = data_row_of(d, kn, "f32", "textbook", "peer"), *best = NULL, *last = NULL;
        int any = 0;
        snprintf(c[0], sizeof c[0], "%s", kn);
        for (t = 0; t < 2; t++)
            for (i = 0; i < np; i++) {
                const bench_row *r = data_row_of(d, kn, t ? "f32_fast" : "f32", ports[i], "batch");
                if (r) {
                    snprintf(c[1 + t * np + i], sizeof c[0], "%.2f%s (%.1f)%s", r->thr.median,
                             r->thr.noisy ? "!" : "", data_est(d, r->thr.median), r->within ? "" : " **BAD**");
                    any = 1;
                } else {
                    snprintf(c[1 + t * np + i], sizeof c[0], "-");
                }
                if (!t && i == 0)
                    best = r;
                if (!t && i == np - 1)
                    last = r;
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
        cell_row(md, html, 4 + 2 * np, c);
    }
    fprintf(md, "\n");
    fprintf(html, "</table>\n");
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

static double nice_step(double range, int want)
{
    double raw = range / want, e = pow(10, floor(log10(raw))), m = raw / e;
    return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * e;
}

/* one panel at (x0, y0), plot area w x h: n samples of the panel's
 * sampler (f32 batch, the active port) binned in theta_h, and the pdf's
 * marginal density as a curve */
static void draw_panel(FILE *f, const panel *pn, long n, int x0, int y0, int w, int h)
{
    float *u1 = malloc(n * sizeof(float)), *u2 = malloc(n * sizeof(float)), *al = malloc(n * sizeof(float));
    float *vx = malloc(n * sizeof(float)), *vy = malloc(n * sizeof(float)), *vz = malloc(n * sizeof(float));
    float *hx = malloc(n * sizeof(float)), *hy = malloc(n * sizeof(float)), *hz = malloc(n * sizeof(float));
    long cnt[NBINS] = { 0 }, j, over = 0;
    double curve[NCURVE + 1], xmax, ymax = 0, bw, step;
    float v[3];
    uint64_t s = 0x51ce5eedull + (uint64_t)(pn->alpha * 1000) * 7919u + (uint64_t)pn->view * 131u + (uint64_t)pn->vndf;
    int i;
    double t = pn->view * PI_ / 180;
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
        curve[i] = marginal(pn, v, xmax * i / NCURVE * PI_ / 180);
        if (curve[i] > ymax)
            ymax = curve[i];
    }
    for (i = 0; i < NBINS; i++)
        if (cnt[i] / (n * bw) > ymax)
            ymax = cnt[i] / (n * bw);
    step = nice_step(ymax, 4);
    ymax = ceil(ymax * 1.05 / step) * step;
#define PX(x) (x0 + (x) / xmax * w)
#define PY(y) (y0 + h - (y) / ymax * h)
    fprintf(f, "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"#fafafa\" stroke=\"#888\"/>\n", x0, y0, w, h);
    for (i = 0; i < NBINS; i++) {
        double y = cnt[i] / (n * bw);
        fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"#9ab\"/>\n", PX(i * bw),
                PY(y), PX((i + 1) * bw) - PX(i * bw) - 0.3, y / ymax * h);
    }
    fprintf(f, "<polyline fill=\"none\" stroke=\"#d1242f\" stroke-width=\"1.5\" points=\"");
    for (i = 0; i <= NCURVE; i++)
        fprintf(f, "%.1f,%.1f ", PX(xmax * i / NCURVE), PY(curve[i]));
    fprintf(f, "\"/>\n");
    {
        double xs = xmax <= 30 ? 5 : xmax <= 60 ? 10 : 15, x, y;
        for (x = 0; x <= xmax + 1e-9; x += xs)
            fprintf(f, "<line x1=\"%.1f\" x2=\"%.1f\" y1=\"%d\" y2=\"%d\" stroke=\"#555\"/>"
                       "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%g</text>\n",
                    PX(x), PX(x), y0 + h, y0 + h + 4, PX(x), y0 + h + 15, x);
        for (y = 0; y <= ymax + 1e-12; y += step)
            fprintf(f, "<line x1=\"%d\" x2=\"%d\" y1=\"%.1f\" y2=\"%.1f\" stroke=\"#555\"/>"
                       "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%g</text>\n",
                    x0 - 4, x0, PY(y), PY(y), x0 - 6, PY(y) + 4, y);
    }
#undef PX
#undef PY
    fprintf(f, "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">theta_h (degrees)</text>\n", x0 + w / 2, y0 + h + 29);
    fprintf(f, "<text x=\"%d\" y=\"%d\" transform=\"rotate(-90 %d %d)\" text-anchor=\"middle\">density per degree</text>\n",
            x0 - 50, y0 + h / 2, x0 - 50, y0 + h / 2);
    if (pn->vndf)
        fprintf(f, "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\" font-weight=\"bold\">ggx_sample_vndf, alpha %g, view %g deg</text>\n",
                x0 + w / 2, y0 - 6, pn->alpha, pn->view);
    else
        fprintf(f, "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\" font-weight=\"bold\">ggx_sample_d, alpha %g</text>\n",
                x0 + w / 2, y0 - 6, pn->alpha);
    if (over)
        fprintf(f, "<text x=\"%d\" y=\"%d\" text-anchor=\"end\" fill=\"#555\">%.2f%% beyond %g deg</text>\n",
                x0 + w - 4, y0 + 14, 100.0 * over / n, xmax);
    free(u1); free(u2); free(al); free(vx); free(vy); free(vz); free(hx); free(hy); free(hz);
}

/* writes the SVG to OUTDIR/sampling.svg and returns it as a malloc'd string
 * (for inlining), or NULL */
static char *sampling_svg(const char *outdir, long n)
{
    static const panel panels[6] = {
        { 0, 0.1, 0 }, { 0, 0.5, 0 }, { 0, 1.0, 0 }, { 1, 0.5, 0 }, { 1, 0.5, 60 }, { 1, 0.5, 89 },
    };
    char *buf = NULL, path[1024];
    size_t sz = 0;
    FILE *f = open_memstream(&buf, &sz);
    int i, W = 1090, H = 610, PW = 250, PH = 200;
    if (!f)
        return NULL;
    fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" font-family=\"sans-serif\" font-size=\"11\">\n", W, H);
    fprintf(f, "<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n", W, H);
    /* legend */
    fprintf(f, "<rect x=\"70\" y=\"8\" width=\"14\" height=\"10\" fill=\"#9ab\"/><text x=\"90\" y=\"17\">histogram of %ld samples "
               "(facet_ggx_sample_d_f32_batch / facet_ggx_sample_vndf_f32_batch, port %s, u on the 2^-24 grid)</text>\n",
            n, facet_port_name());
    fprintf(f, "<line x1=\"70\" x2=\"84\" y1=\"32\" y2=\"32\" stroke=\"#d1242f\" stroke-width=\"2\"/><text x=\"90\" y=\"36\">"
               "pdf: the oracle's ggx_pdf_d / ggx_pdf_vndf (per solid angle), integrated over phi_h, times sin theta_h</text>\n");
    for (i = 0; i < 6; i++)
        draw_panel(f, &panels[i], n, 75 + (i % 3) * (PW + 105), 75 + (i / 3) * (PH + 75), PW, PH);
    fprintf(f, "</svg>\n");
    fclose(f);
    snprintf(path, sizeof path, "%s/sampling.svg", outdir);
    f = fopen(path, "w");
    if (f) {
        fputs(buf, f);
        fclose(f);
    }
    return buf;
}

/* ---- the chi-square table ------------------------------------------------------- */

static void md_row_to_html(FILE *html, const char *line, int header)
{
    const char *p = line + 1, *q;
    fprintf(html, "<tr>");
    while ((q = strchr(p, '|'))) {
        fprintf(html, header ? "<th>%.*s</th>" : "<td>%.*s</td>", (int)(q - p), p);
        p = q + 1;
    }
    fprintf(html, "</tr>\n");
}

static void chi2_table(FILE *md, FILE *html, const char *outdir)
{
    char path[1024], line[1024];
    FILE *f;
    int part = 0, open = 0, first = 1;
    snprintf(path, sizeof path, "%s/sample_chi2.txt", outdir);
    f = fopen(path, "r");
    if (!f) {
        fprintf(md, "No chi-square results (%s missing: run bench/report/sample_chi2.sh).\n\n", path);
        fprintf(html, "<p>No chi-square results (%s missing).</p>\n", path);
        return;
    }
    while (fgets(line, sizeof line, f)) {
        size_t n = strlen(line);
        while (n && (line[n - 1] == '\n' || line[n - 1] == '\r'))
            line[--n] = 0;
        if (line[0] == '|') {
            if (!open) {
                fprintf(html, "<table>");
                if (part == 1) { /* the moment rows have no header of their own */
                    const char *hd = "| sampler | alpha_x | alpha_y | view (deg) | 1 - N.H: sample mean vs pdf's, "
                                     "variance vs pdf's (z-scores) |";
                    fprintf(md, "%s\n|---|---|---|---|---|\n", hd);
                    md_row_to_html(html, hd, 1);
                }
                open = 1;
                first = part == 0;
            }
            fprintf(md, "%s\n", line);
            if (strstr(line, "|---"))
                continue;
            md_row_to_html(html, line, first);
            first = 0;
            continue;
        }
        if (open) {
            fprintf(md, "\n");
            fprintf(html, "</table>\n");
            open = 0;
        }
        if (!line[0])
            continue;
        if (!strncmp(line, "moments", 7))
            part = 1;
        fprintf(md, "%s\n\n", line);
        fprintf(html, "<p>%s</p>\n", line);
    }
    if (open) {
        fprintf(md, "\n");
        fprintf(html, "</table>\n");
    }
    fclose(f);
}

void report_samplers(FILE *md, FILE *html, const report_data *d)
{
    const char *outdir = d->outdir;
    int quick = d->quick;
    char *svg;
    long n = quick ? 100000 : 1000000;
    fprintf(md, "\n## Importance sampling\n\n");
    fprintf(html, "<h2>Importance sampling</h2>\n");
    fprintf(md, "Cost of each sampler and pdf (facet.h, \"GGX and GTR importance sampling\"): %s per sample "
                "(median; '!' where the spread exceeds 5%%) and, in parentheses, est. core cycles (see the clock "
                "section), through the batch API (facet_<sampler>_f32_batch and _f32_fast_batch) with "
                "facet_set_port(port) active, in structure-of-arrays over the in-domain inputs of "
                "tests/sample/test_sample_accuracy.c (gtr_sample_d with gamma = 1), beside the textbook peer "
                "(tests/lib/sample_peer.h: the direct formulas with libm, in float, -O2, one sample at a time; "
                "no peer for the anisotropic forms, reflect and pdf_vndf_reflect). Measured in the same run as "
                "the kernels' rows; compare ratios only. Every facet row is within its facet.h bound in the "
                "samplers' error measure (`facet-bench bench SAMPLER` shows the errors).\n\n", d->clock.unit);
    fprintf(html, "<p>Cost of each sampler and pdf (facet.h, \"GGX and GTR importance sampling\"): %s per sample "
                  "(median; '!' where the spread exceeds 5%%) and, in parentheses, est. core cycles, through the "
                  "batch API with facet_set_port(port) active, beside the textbook peer (tests/lib/sample_peer.h: the "
                  "direct formulas with libm, -O2); gtr_sample_d timed with gamma = 1. Same run as the kernels' "
                  "rows; compare ratios only. <code>facet-bench bench SAMPLER</code> shows the errors.</p>\n",
            d->clock.unit);
    cost_table(md, html, d);
    svg = sampling_svg(outdir, n);
    fprintf(html, "<figure>%s<figcaption><b>Sampled half vectors against the pdf.</b> Histograms of theta_h "
                  "(the angle of h from N) of %ld samples per panel from the f32 batch samplers on port %s, "
                  "against the marginal density of the pdf (the oracle's, integrated over the azimuth). Top: D "
                  "sampling at three widths; bottom: visible normals at alpha 0.5 for views at 0, 60 and 89 "
                  "degrees from N. File: sampling.svg. The goodness of fit is tested below.</figcaption></figure>\n",
            svg ? svg : "", n, facet_port_name());
    fprintf(md, "![Sampled half vectors against the pdf](sampling.svg)\n\n*Sampled half vectors against the pdf.* "
                "Histograms of theta_h (the angle of h from N) of %ld samples per panel from the f32 batch samplers "
                "on port %s, against the marginal density of the pdf (the oracle's, integrated over the azimuth). "
                "Top: D sampling at alpha 0.1, 0.5, 1; bottom: visible normals at alpha 0.5 for views at 0, 60 and "
                "89 degrees from N.\n\n", n, facet_port_name());
    free(svg);
    fprintf(md, "### Chi-square goodness of fit (tests/sample/test_sample_chi2.c)\n\n");
    fprintf(html, "<h3>Chi-square goodness of fit (tests/sample/test_sample_chi2.c)</h3>\n");
    fprintf(md, "Each sampler against its pdf: 16 x 16 bins in (q, phi_h), q the GGX CDF of theta_h, bins "
                "expecting fewer than 5 pooled; Pearson chi-square, pass p > 0.01; integral - 1: the pdf's "
                "quadrature over the hemisphere. The test's own output, run for this report.\n\n");
    fprintf(html, "<p>Each sampler against its pdf: 16 x 16 bins in (q, phi_h), q the GGX CDF of theta_h, bins "
                  "expecting fewer than 5 pooled; Pearson chi-square, pass p &gt; 0.01; integral - 1: the pdf's "
                  "quadrature over the hemisphere. The test's own output, run for this report.</p>\n");
    chi2_table(md, html, outdir);
}
