/* sec_targets.c - the targets, each measured or modelled, met or not. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "report.h"

static void target_tiers(report *r, report_data *D)
{
    static const char *const widths[] = { "avx2", "avx512" };
    static const struct { const char *format; double want; } tiers[] = { { "f32_fast", 1.5 }, { "f32", 1.0 } };
    char b[4][400], peer[32];
    const char *cells[4];
    size_t w, t;
    for (w = 0; w < 2; w++)
        for (t = 0; t < 2; t++) {
            const bench_row *x = data_row_of(D, "brdf_hammon", tiers[t].format, widths[w], "batch"), *p;
            snprintf(peer, sizeof peer, "shader_%s_fm", widths[w]);
            p = data_row_of(D, "brdf_hammon", "f32", peer, "peer");
            cells[0] = report_fmt(b[0], sizeof b[0], "%s brdf_hammon %s batch >= %.1fx the fast-math shader peer at the same width",
                           widths[w], tiers[t].format, tiers[t].want);
            if (x && p) {
                double ratio = p->thr.median / x->thr.median;
                cells[1] = report_fmt(b[1], sizeof b[1], "%.2fx (%.2f vs %.2f est. cycles/sample); max err %.3g vs bound %.3g",
                               ratio, data_est(D, x->thr.median), data_est(D, p->thr.median), x->err.max_rel, x->bound);
                cells[2] = ratio >= tiers[t].want && x->within ? "yes" : "**no**";
                cells[3] = "ratio within one run; the peer (-march of the same width, -ffast-math) computes the "
                           "exact-Vis model from vectors, max error ~0.3 at the peak";
            } else {
                cells[1] = "-";
                cells[2] = "n/a";
                cells[3] = "this CPU does not run that width";
            }
            doc_row(r->doc, cells);
        }
    {
        double m4 = data_arm(D, "fxfast-insns", "brdf_hammon", "cortex-m4"), m0 = data_arm(D, "fxfast-insns", "brdf_hammon", "cortex-m0");
        double fpu = data_arm(D, "f32fpu-insns", "brdf_hammon", "cortex-m4"), m4mca = data_arm(D, "fxfast-mca", "brdf_hammon", "cortex-m4");
        cells[0] = "fx_fast brdf_hammon <= 150 executed instructions per call on Cortex-M4, <= 450 on Cortex-M0, "
                   "fewer than the f32 kernel on the M4's FPU";
        if (m4 > 0 && m0 > 0) {
            cells[1] = report_fmt(b[1], sizeof b[1], "M4 %.0f (llvm-mca %.0f cycles), M0 %.0f, f32 FPU M4 %.0f", m4, m4mca, m0, fpu);
            cells[2] = m4 <= 150 && m0 <= 450 && (fpu < 0 || m4 < fpu) ? "yes" : "**no**";
            cells[3] = "instructions MEASURED under qemu (bench/cortexm); bound: ~26 high-word 32x32 products, "
                       "4 table functions, 9 clz, 6 clamps at 2^-10 (README fixed point, fast tier)";
        } else {
            cells[1] = "-";
            cells[2] = "n/a";
            cells[3] = "no Cortex-M figures in this build";
        }
        doc_row(r->doc, cells);
    }
}

void section_targets(report *r)
{
    report_data *D = r->data;
    const bench_row *ab = data_row_of(D, "brdf_hammon", "f32", "avx2", "batch");
    const bench_row *fastest = NULL;
    char b[12][400];
    const char *cells[4];
    int i;
    size_t ki;
    doc_heading(r->doc, 2, "%s", "Targets");
    doc_table(r->doc, 4, "target", "measured / modelled", "met?", "note");
    /* the fastest peer at AVX2's width (built -march=x86-64-v3), or the
     * width-independent textbook peer */
    for (i = 0; i < D->n_rows; i++)
        if (!strcmp(D->rows[i].path, "peer") && !strcmp(D->rows[i].kernel, "brdf_hammon") &&
            (strstr(D->rows[i].port, "_avx2") || !strstr(D->rows[i].port, "_avx512")) &&
            (!fastest || D->rows[i].r.thr.median < fastest->thr.median))
            fastest = &D->rows[i].r;
    cells[0] = "AVX2 brdf_hammon batch <= 3.0 core cycles/sample";
    if (ab) {
        double c = data_est(D, ab->thr.median);
        cells[1] = report_fmt(b[0], sizeof b[0], "%.2f %s", c, D->clock.is_cycles ? "cycles (measured)" : "est. cycles (TSC ticks / measured ratio)");
        cells[2] = c <= 3.0 ? "yes" : "**no**";
    } else {
        cells[1] = "no AVX2 on this machine";
        cells[2] = "n/a";
    }
    cells[3] = "";
    doc_row(r->doc, cells);
    cells[0] = "AVX2 brdf_hammon >= 1.8x faster than the fastest peer at the same width, within its bound";
    if (ab && fastest) {
        double ratio = fastest->thr.median / ab->thr.median;
        cells[1] = report_fmt(b[1], sizeof b[1], "%.2fx vs %s (%.2f est. cycles/sample); max err %.3g vs bound %.3g", ratio,
                       fastest->port, data_est(D, fastest->thr.median), ab->err.max_rel, ab->bound);
        cells[2] = ratio >= 1.8 && ab->within ? "yes" : "**no**";
        cells[3] = "ratio within one run; the peer computes the exact-Vis model from vectors (see peers)";
    } else {
        cells[1] = "-";
        cells[2] = "n/a";
        cells[3] = "";
    }
    doc_row(r->doc, cells);
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const char *kn = facet_kernel_at(ki)->name;
        const bench_row *x = data_row_of(D, kn, "f32", "avx2", "batch");
        double m = data_mca(D, "f32", "avx2", kn, "znver3");
        if (!x || m <= 0)
            continue;
        cells[0] = report_fmt(b[2], sizeof b[2], "AVX2 %s within 1.25x of llvm-mca znver3", kn);
        cells[1] = report_fmt(b[3], sizeof b[3], "%.2f est. cycles vs %.2f modelled (%.2fx); skylake model %.2f",
                       data_est(D, x->thr.median), m, data_est(D, x->thr.median) / m, data_mca(D, "f32", "avx2", kn, "skylake"));
        cells[2] = data_est(D, x->thr.median) <= 1.25 * m ? "yes" : "**no**";
        cells[3] = "this machine is not a Zen 3 (see clock)";
        doc_row(r->doc, cells);
    }
    for (ki = 0; ki < facet_kernel_count(); ki++) { /* target: every AVX2 kernel >= 5x its scalar port */
        const char *kn = facet_kernel_at(ki)->name;
        const bench_row *x = data_row_of(D, kn, "f32", "avx2", "batch"), *sc = data_row_of(D, kn, "f32", "scalar", "batch");
        if (!x || !sc)
            continue;
        cells[0] = report_fmt(b[2], sizeof b[2], "AVX2 %s >= 5x its scalar port (batch)", kn);
        cells[1] = report_fmt(b[3], sizeof b[3], "%.1fx (%.2f vs %.2f est. cycles/sample)", sc->thr.median / x->thr.median,
                       data_est(D, sc->thr.median), data_est(D, x->thr.median));
        cells[2] = sc->thr.median >= 5.0 * x->thr.median ? "yes" : "**no**";
        cells[3] = "ratio within one run";
        doc_row(r->doc, cells);
    }
    {
        double fx = data_arm(D, "fx-mca", "brdf_hammon", "cortex-m4"), sf = data_arm(D, "f32soft-mca", "brdf_hammon", "cortex-m4");
        double fxi = data_arm(D, "fx-insns", "brdf_hammon", "cortex-m4"), sfi = data_arm(D, "f32soft-insns", "brdf_hammon", "cortex-m4");
        double f0 = data_arm(D, "fx-m0cyc", "brdf_hammon", "cortex-m0"), s0 = data_arm(D, "f32soft-m0cyc", "brdf_hammon", "cortex-m0");
        cells[0] = "fx brdf_hammon <= 150 cycles/sample on Cortex-M4 (llvm-mca)";
        cells[1] = fx > 0 ? report_fmt(b[4], sizeof b[4], "%.0f cycles per call, MODELLED (llvm-mca cortex-m4 on the executed "
                                                    "trace, %.0f instructions measured under qemu; + %.0f taken branches "
                                                    "at 1-3 cycles not modelled)", fx, fxi, data_arm(D, "fx-taken", "brdf_hammon", "cortex-m4"))
                          : "not available";
        cells[2] = fx > 0 ? (fx <= 150 ? "yes" : "**no**") : "n/a";
        cells[3] = "4 representative inputs, mean per call; see the Cortex-M section";
        doc_row(r->doc, cells);
        cells[0] = "fx brdf_hammon >= 10x fewer cycles than soft-float f32 on the same core";
        if (fx > 0 && sf > 0) {
            cells[1] = report_fmt(b[5], sizeof b[5], "Cortex-M4: %.1fx (%.0f vs %.0f cycles, MODELLED by llvm-mca on the traces; "
                                              "executed instructions MEASURED: %.0f vs %.0f, %.1fx)%s",
                           sf / fx, sf, fx, sfi, fxi, sfi / fxi,
                           f0 > 0 && s0 > 0 ? report_fmt(b[7], sizeof b[7], "; Cortex-M0: %.1fx (%.0f vs %.0f cycles, TRM-table model)",
                                                  s0 / f0, s0, f0) : "");
            cells[2] = sf / fx >= 10 ? "yes" : "**no**";
        } else {
            cells[1] = "not available";
            cells[2] = "n/a";
        }
        cells[3] = "soft-float: facet/scalar.h -mfloat-abi=soft, libgcc helpers included in the trace";
        doc_row(r->doc, cells);
    }
    cells[0] = "rasterizer AVX2 shading <= 1.3x the batch benchmark's cycles/sample";
    if (ab && r->raster_avx2_per_eval > 0) {
        double ratio = r->raster_avx2_per_eval / data_est(D, ab->thr.median);
        cells[1] = report_fmt(b[6], sizeof b[6], "%.2f est. cycles per BRDF evaluation vs %.2f (%.2fx)", r->raster_avx2_per_eval,
                       data_est(D, ab->thr.median), ratio);
        cells[2] = ratio <= 1.3 ? "yes" : "**no**";
        cells[3] = "shading cost includes the per-pixel vectors and dots, amortised over 3 channels";
    } else {
        cells[1] = "-";
        cells[2] = "n/a";
        cells[3] = "";
    }
    doc_row(r->doc, cells);
    target_tiers(r, D);
    doc_table_end(r->doc);
}

