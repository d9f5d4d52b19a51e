/* sec_model.c - the model error of each approximation against the exact form of its term
 * (kernel_facts.c runs the sweep), and of each diffuse kernel against the microsurface
 * simulation of its material (bench/microsurface/model_error.tsv, kf_sim_load). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "kernel_facts.h"
#include "report.h"

static void section_model_diffuse(report *r);
static void section_spec_loss(report *r);

void section_model(report *r)
{
    report_data *D = r->data;
    int t;
    char b[8][64];
    doc_heading(r->doc, 2, "%s", "Tradeoff per term: model error of each approximation vs the exact model");
    doc_para(r->doc, "Model error, not implementation error: the double-precision oracles of both formulas (the "
         "approximation's own formula and the exact reference) on a grid over each row's domain (per axis half "
         "the points log-spaced, half linear; %s), relative error |approx / exact - 1|: max, mean, and the "
         "argmax in the domain's axes. Domains: visibility N.L, N.V in [2^-8, 1]; the other two-cosine rows "
         "[2^-12, 1]; G1 rows N.V in [2^-12, 1]; alpha in [2^-10, 1] everywhere; L.V = N.L N.V where needed "
         "(L and V 90 deg apart in azimuth), f0 = 0.04, albedo = 0.8. The implementation error of each kernel "
         "(vs its own formula) is in the kernels table. Cost: the best port's batch, est. cycles per sample.",
         r->quick ? "24 points per axis for 3 axes, 200 for 2" : "96 points per axis for 3 axes, 1000 for 2");
    doc_table(r->doc, 8, "term", "approximation", "exact", "max rel err", "mean rel err", "argmax (domain axes)",
          "cost approx", "cost exact");
    for (t = 0; t < kf_model_count(); t++) {
        const kf_model *x = kf_model_at(t);
        const bench_row *ca = data_best_batch(D, x->kernel), *ce = x->exact_kernel[0] ? data_best_batch(D, x->exact_kernel) : NULL;
        const char *cells[8];
        cells[0] = x->term;
        cells[1] = x->approx;
        cells[2] = x->exact;
        cells[3] = report_g3(b[0], x->max_rel);
        cells[4] = report_g3(b[1], x->mean_rel);
        {
            char *q = b[2];
            int d;
            *q = 0;
            for (d = 0; d < x->n_axes; d++)
                q += snprintf(q, 20, "%s%s %.3g", d ? ", " : "", x->axes[d].name, x->arg[d]);
            cells[5] = b[2];
        }
        cells[6] = ca ? report_fmt(b[3], sizeof b[3], "%.2f (%s)", data_est(D, ca->thr.median), ca->port) : "-";
        if (x->peer_exact) { /* the exact form's cost: its exact-Vis peers' */
            const bench_row *p = data_best_peer(D, x->kernel, "peer-vectors");
            cells[7] = p ? report_fmt(b[4], sizeof b[4], "%.2f (peer %s)", data_est(D, p->thr.median), p->port) : "-";
        } else {
            cells[7] = ce ? report_fmt(b[4], sizeof b[4], "%.2f (%s)", data_est(D, ce->thr.median), ce->port) : "-";
        }
        doc_row(r->doc, cells);
    }
    doc_table_end(r->doc);
    section_model_diffuse(r);
    section_spec_loss(r);
}

/* a simulated figure with its standard error beside it; a maximum inside 3
 * sigma is only a bound */
static const char *sim_fig(char *b, size_t n, double x, double sig)
{
    char g1[32], g2[32];
    if (x < 3 * sig)
        return report_fmt(b, n, "< %s (3 sigma)", report_g3(g1, 3 * sig));
    return report_fmt(b, n, "%s (+- %s)", report_g3(g1, x), report_g3(g2, sig));
}

static void section_model_diffuse(report *r)
{
    report_data *D = r->data;
    const kf_sim *x[32];
    int n = 0, i, a;
    size_t k;
    char b[8][96];
    for (k = 0; k < facet_kernel_count() && n < 32; k++) /* the kernel list's order */
        if ((x[n] = kf_sim_of(facet_kernel_at(k)->name)))
            n++;
    doc_heading(r->doc, 3, "%s", "Diffuse: model error vs the simulated Smith microsurface");
    if (!n) {
        doc_para(r->doc, "%s could not be read: no diffuse kernel is compared here.", KF_SIM_TABLE);
        return;
    }
    doc_para(r->doc, "The diffuse kernels have no closed-form exact term: the reference is a Monte Carlo simulation "
         "of light on the Smith microsurface of GGX itself (bench/microsurface: random walks, the simulation "
         "Hammon fitted his model to), committed as tables (%s and the tables beside it; bench/microsurface/"
         "README.md says how they were made: seed, paths per run, time). Each kernel is compared with the material it "
         "approximates: hammon = Hammon's facets (Schlick F0 0.04 mirror + Fresnel-symmetric Lambertian), its "
         "diffuse part / (1 - F0), for diffuse_hammon and its hybrid and cheap variants and diffuse_burley; lambert "
         "= Lambertian facets, the whole BRDF, for diffuse_oren_nayar (sigma = alpha / 2) and lambert. Relative "
         "error |kernel / reference - 1| of the kernel's double oracle over the tables' grid: alpha in [2^-10, 1] "
         "(12 values), N.L, N.V in [0.02, 1] (10 each), 7 azimuths, facet albedo in {1, 0.75, 0.5, 0.25}. "
         "Beside every figure (+-) the simulation's standard error of it; a maximum inside 3 sigma is given only "
         "as a bound. The maxima fall where the reference is dark (grazing L and V on opposite sides, strong "
         "shadowing and masking); the N.L, N.V >= 0.2 columns leave those out. The chooser and the Pareto "
         "figures rank the diffuse rows by the whole-grid maximum. Hammon's constants refitted to the same "
         "tables: bench/microsurface/hammon_refit.md.", KF_SIM_TABLE);
    doc_table(r->doc, 7, "kernel", "material", "max rel err (+- sigma)", "where (alpha, N.L, N.V, phi, albedo)",
              "mean rel err (noise)", "N.L, N.V >= 0.2: max (+- sigma); mean", "cost (best port)");
    for (i = 0; i < n; i++) {
        const kf_sim *s = x[i];
        const bench_row *c = data_best_batch(D, s->kernel);
        const char *cells[7];
        char g1[32], g2[32];
        cells[0] = s->kernel;
        cells[1] = s->reference;
        cells[2] = sim_fig(b[0], sizeof b[0], s->max, s->sig);
        cells[3] = report_fmt(b[1], sizeof b[1], "%g, %g, %g, %g, %g", s->at[0], s->at[1], s->at[2], s->at[3], s->at[4]);
        cells[4] = report_fmt(b[2], sizeof b[2], "%s (%s)", report_g3(g1, s->mean), report_g3(g2, s->mean_sig));
        sim_fig(b[6], sizeof b[6], s->max2, s->sig2);
        cells[5] = report_fmt(b[3], sizeof b[3], "%s; %s", b[6], report_g3(g1, s->mean2));
        cells[6] = c ? report_fmt(b[4], sizeof b[4], "%.2f (%s)", data_est(D, c->thr.median), c->port) : "-";
        doc_row(r->doc, cells);
    }
    doc_table_end(r->doc);
    doc_para(r->doc, "Per alpha (the whole grid of N.L, N.V, azimuth and albedo): max rel err (+- sigma); mean.");
    {
        const char *head[1 + 32], *cells[1 + 32];
        static char cellbuf[32][96];
        head[0] = "alpha";
        for (i = 0; i < n; i++)
            head[1 + i] = x[i]->kernel;
        doc_table_head(r->doc, 1 + n, head);
        for (a = 0; a < x[0]->n_alpha; a++) {
            char ab[32];
            cells[0] = report_fmt(ab, sizeof ab, "%g", x[0]->alpha[a]);
            for (i = 0; i < n; i++) {
                char f[64], g1[32];
                if (a < x[i]->n_alpha) {
                    sim_fig(f, sizeof f, x[i]->amax[a], x[i]->asig[a]);
                    cells[1 + i] = report_fmt(cellbuf[i], sizeof cellbuf[i], "%s; %s", f, report_g3(g1, x[i]->amean[a]));
                } else {
                    cells[1 + i] = "-";
                }
            }
            doc_row(r->doc, cells);
        }
        doc_table_end(r->doc);
    }
}

/* the committed figure of the energy single-scattering GGX loses
 * (microsurface energy), inline */
#define SPEC_LOSS_SVG "bench/microsurface/spec_loss.svg"
static void section_spec_loss(report *r)
{
    FILE *f = fopen(SPEC_LOSS_SVG, "rb");
    char *svg;
    long n;
    doc_heading(r->doc, 3, "%s", "Multiple-scattering specular: the energy single-scattering GGX loses");
    if (!f) {
        doc_para(r->doc, "%s could not be read.", SPEC_LOSS_SVG);
        return;
    }
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    rewind(f);
    svg = n > 0 ? malloc((size_t)n + 1) : NULL;
    if (svg)
        svg[fread(svg, 1, (size_t)n, f)] = '\0';
    fclose(f);
    doc_para(r->doc, "1 - E(N.V, alpha) of the GGX BRDF D G2 / (4 N.L N.V) with F = 1 (a white conductor) by "
         "quadrature, and the simulated mirror microsurface's multiple-scattering albedo beside it (%s; the "
         "table, and a Kulla-Conty compensation lobe fitted with two rationals and its errors against the "
         "simulation: bench/microsurface/spec_loss.md). No compensation kernel is offered: the fitted lobe restores "
         "the energy but its shape is far from the simulated multiple scattering (spec_loss.md).", SPEC_LOSS_SVG);
    if (svg)
        report_svg_figure(r, svg, "Energy single-scattering GGX loses",
                          "bench/microsurface/spec_loss.svg (microsurface energy): 1 - E by quadrature (lines) and "
                          "the simulated multiple-scattering albedo (dots), the compensation fit dashed, per alpha over N.V.");
}
