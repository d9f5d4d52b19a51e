/* sec_model.c - the model error of each approximation against the exact form of its term
 * (kernel_facts.c runs the sweep). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "kernel_facts.h"
#include "report.h"

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
        if (x->peer_exact) { /* the exact form's cost: its peers' */
            const bench_row *p = data_best_peer(D, x->kernel);
            cells[7] = p ? report_fmt(b[4], sizeof b[4], "%.2f (peer %s)", data_est(D, p->thr.median), p->port) : "-";
        } else {
            cells[7] = ce ? report_fmt(b[4], sizeof b[4], "%.2f (%s)", data_est(D, ce->thr.median), ce->port) : "-";
        }
        doc_row(r->doc, cells);
    }
    doc_table_end(r->doc);
}
