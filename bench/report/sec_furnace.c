/* sec_furnace.c - the white furnace: the directional albedo of every diffuse model. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "kernel_facts.h"
#include "geom.h"
#include "svg.h"
#include "report.h"

#define PI_ 3.14159265358979323846

typedef struct curve { char label[64]; int colour, dash; int n; double x[32], y[32]; } curve;

static const char *const curve_colour[8] = { "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b",
                                              "#e377c2", "#17becf" };

/* the curves over the view angle, the legend beside the plot */
static char *furnace_svg(const curve *c, int nc)
{
    int W = 560, H = 320, LW = 260, i, j;
    double top = 1.4;
    svg_key keys[24];
    svg s;
    svg_plot pl;
    svg_begin(&s, W + LW, H);
    memset(&pl, 0, sizeof pl);
    pl.s = &s;
    pl.x = 56;
    pl.y = 24;
    pl.w = W - 56 - 16;
    pl.h = H - 24 - 44;
    pl.ax.label = "view angle theta_v (deg)";
    pl.ax.lo = 0;
    pl.ax.hi = 90;
    pl.ay.label = "albedo";
    pl.ay.lo = 0;
    for (i = 0; i < nc; i++) /* room for every curve, in steps of 0.2 */
        for (j = 0; j < c[i].n; j++)
            if (c[i].y[j] > top)
                top = ceil(c[i].y[j] / 0.2) * 0.2;
    pl.ay.hi = top;
    pl.ay.step = 0.2;
    svg_plot_frame(&pl, "Directional albedo (white furnace)");
    for (i = 0; i < nc && i < 24; i++) {
        svg_plot_line(&pl, c[i].n, c[i].x, c[i].y, curve_colour[c[i].colour % 8], c[i].dash, 1.5);
        keys[i].label = c[i].label;
        keys[i].colour = curve_colour[c[i].colour % 8];
        keys[i].kind = SVG_KEY_LINE;
        keys[i].dash = c[i].dash;
    }
    svg_legend(&s, W + 4, pl.y + 6, nc < 24 ? nc : 24, keys, 0);
    return svg_end(&s);
}

/* directional albedo of kernel k at N.V = nv (albedo input 1): the integral
 * of f (N.L) over the hemisphere of L, midpoint rule in (theta_l, phi_l) */
static double furnace(const facet_kernel *k, double nv, double alpha)
{
    const int NT = 48, NP = 96;
    double sv = sqrt(1 - nv * nv), sum = 0, in[FACET_MAX_INPUTS];
    int i, j;
    for (i = 0; i < NT; i++) {
        double th = (i + 0.5) / NT * (PI_ / 2), ct = cos(th), st = sin(th);
        for (j = 0; j < NP; j++) {
            double ph = (j + 0.5) / NP * (2 * PI_);
            geom g = { 0 };
            g.nl = ct, g.nv = nv, g.lv = st * sv * cos(ph) + ct * nv;
            g.alpha = alpha, g.albedo = 1, g.f0 = 0.04, g.f90 = 1, g.gamma = 2;
            if (!geom_inputs(&g, k->inputs, k->n_inputs, in))
                return -1;
            sum += k->oracle(in) * ct * st;
        }
    }
    return sum * (PI_ / 2 / NT) * (2 * PI_ / NP);
}

void section_furnace(report *r)
{
    static const double alphas[3] = { 0.05, 0.3, 1.0 };
    curve c[24];
    int nc = 0, colour = 0, a, i;
    size_t ki;
    char b[6][32];
    doc_heading(r->doc, 2, "%s", "White furnace: directional albedo of the diffuse models");
    doc_para(r->doc, "Each diffuse kernel's double oracle with albedo 1, integrated against N.L over the hemisphere of L "
         "(midpoint rule, 48 x 96 directions; its own error shows in Lambert's 1.0002) for each view angle: the "
         "fraction of light a white surface returns. Lambert is 1 everywhere by construction; a model above 1 creates energy, one below loses "
         "it (to what a multiple-scattering term would return). Solid, dashed, dotted: alpha = 0.05, 0.3, 1.");
    doc_table(r->doc, 6, "model", "alpha", "albedo at N.V = 1", "at N.V = 0.5", "at N.V = 0.1", "min .. max");
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const facet_kernel *k = facet_kernel_at(ki);
        int has_alpha = 0;
        if (!kf_is_diffuse(k->name))
            continue;
        for (i = 0; i < k->n_inputs; i++)
            has_alpha |= !strcmp(k->inputs[i], "alpha");
        for (a = 0; a < (has_alpha ? 3 : 1) && nc < 24; a++) {
            curve *cv = &c[nc];
            double lo = 1e9, hi = -1e9;
            const char *cells[6];
            cv->n = 0;
            for (i = 0; i < 19; i++) {
                double nv = cos(i * 5.0 * PI_ / 180), v;
                nv = nv < 0.02 ? 0.02 : nv; /* the last point: 88.9 deg */
                v = furnace(k, nv, alphas[a]);
                if (v < 0)
                    break;
                cv->x[cv->n] = acos(nv) * 180 / PI_;
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
            cells[1] = has_alpha ? report_fmt(b[0], sizeof b[0], "%g", alphas[a]) : "any";
            cells[2] = report_fmt(b[1], sizeof b[1], "%.4f", furnace(k, 1.0, alphas[a]));
            cells[3] = report_fmt(b[2], sizeof b[2], "%.4f", furnace(k, 0.5, alphas[a]));
            cells[4] = report_fmt(b[3], sizeof b[3], "%.4f", furnace(k, 0.1, alphas[a]));
            cells[5] = report_fmt(b[4], sizeof b[4], "%.4f .. %.4f", lo, hi);
            doc_row(r->doc, cells);
            nc++;
        }
        colour++;
    }
    doc_table_end(r->doc);
    report_svg_figure(r, furnace_svg(c, nc), NULL, NULL);
    doc_only(r->doc, DOC_MD, "(The plot is in index.html.)\n\n");
}

