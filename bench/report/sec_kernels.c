/* sec_kernels.c - every kernel x format x port x path: its error and its cost, the long table. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "report.h"

void section_kernels(report *r)
{
    report_data *D = r->data;
    size_t ki;
    doc_heading(r->doc, 2, "%s", "Kernels x format x port: error and cost");
    doc_para(r->doc, "Errors: relative to the double oracle at the same inputs (floor 2^-100), max (with the argmax "
         "input) and mean over the error set; 'bound' is the facet.h bound (ok/BAD). Peers: error against "
         "the oracle of the formula they compute. Fixed-point rows (fmt fx): the float inputs rounded to Q15 "
         "(ties up) and clamped to the fx domain outside the timing; error in LSB of the output format "
         "against round-half-up(oracle 2^frac) at those Q15 inputs, the measure of tests/fx/test_fx_accuracy.c "
         "(brdf_hammon where the oracle is >= 16: relative, bound 2^-26); path batch = "
         "facet_KERNEL_fx_batch with facet_set_port(port) active (identical timings across ports mean the "
         "build routes every port to the same fx loop), path call = facet_KERNEL_fx per sample. Throughput in %s per sample (median), est. cycles per "
         "sample, latency in est. cycles per call. mca: llvm-mca cycles per sample for the port's batch "
         "loop (modelled, not measured). size: bytes of the batch function.", D->clock.unit);
    doc_table(r->doc, 13, "kernel", "fmt", "port", "path", "max err", "argmax input", "mean err", "bound",
          "thr (med)", "est. cyc/sample", "latency cyc/call", "mca znver3 / skylake", "size B");
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const facet_kernel *k = facet_kernel_at(ki);
        int i, j;
        for (i = 0; i < D->n_rows; i++) {
            const bench_row *x = &D->rows[i].r;
            char c[13][160], *p;
            const char *cells[13];
            double m1, m2, sz;
            if (strcmp(x->kernel, k->name))
                continue;
            snprintf(c[0], sizeof c[0], "%s", x->kernel);
            snprintf(c[1], sizeof c[1], "%s", x->format);
            snprintf(c[2], sizeof c[2], "%s", x->port);
            snprintf(c[3], sizeof c[3], "%s", x->path);
            if (x->err.has_lsb)
                report_fmt(c[4], sizeof c[4], "%.0f LSB%s", x->err.max_lsb,
                    x->err.big_rel >= 0 ? report_fmt(c[12], 64, " (brdf >= 16: %.2g rel)", x->err.big_rel) : "");
            else
                report_g3(c[4], x->err.max_rel);
            p = c[5];
            *p = 0;
            for (j = 0; j < x->n_inputs; j++)
                p += snprintf(p, 20, "%s%.4g", j ? ", " : "", x->err.arg[j]);
            if (x->err.has_lsb)
                report_fmt(c[6], sizeof c[6], "%.2g LSB", x->err.mean_lsb);
            else
                report_g3(c[6], x->err.mean_rel);
            if (x->bound > 0 && x->err.has_lsb)
                report_fmt(c[7], sizeof c[7], "%.0f LSB%s %s", x->bound, x->err.big_rel >= 0 ? ", 2^-26 rel" : "",
                    x->within ? "ok" : "**BAD**");
            else if (x->bound > 0)
                report_fmt(c[7], sizeof c[7], "%.3g %s", x->bound, x->within ? "ok" : "**BAD**");
            else
                strcpy(c[7], "-");
            report_fmt(c[8], sizeof c[8], "%.3f%s", x->thr.median, x->thr.noisy ? " !" : "");
            report_fmt(c[9], sizeof c[9], "%.2f", data_est(D, x->thr.median));
            if (x->has_lat)
                report_fmt(c[10], sizeof c[10], "%.1f%s", data_est(D, x->lat.median), x->lat.noisy ? " !" : "");
            else
                strcpy(c[10], "-");
            m1 = data_mca(D, x->format, x->port, x->kernel, "znver3");
            m2 = data_mca(D, x->format, x->port, x->kernel, "skylake");
            if (!strcmp(x->path, "batch") && m1 > 0)
                report_fmt(c[11], sizeof c[11], "%.2f / %.2f", m1, m2);
            else
                strcpy(c[11], "-");
            sz = data_size(D, x->format, x->port, x->kernel);
            if (!strcmp(x->path, "batch") && sz > 0)
                report_fmt(c[12], sizeof c[12], "%.0f", sz);
            else
                strcpy(c[12], "-");
            for (j = 0; j < 13; j++)
                cells[j] = c[j];
            doc_row(r->doc, cells);
        }
    }
    doc_table_end(r->doc);
    doc_para(r->doc, "Peers (bench/harness/peers.h): <b>textbook</b> (-O2): H = normalize(L+V), powf, D in tan form, Smith "
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

