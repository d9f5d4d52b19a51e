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
         "build routes every port to the same fx loop), path call = facet_KERNEL_fx per sample. Binary16 rows "
         "(fmt f16, facet/f16.h): port = the f16 table that ran (avx512fp16 where the CPU has AVX-512 FP16; "
         "scalar: the specification, binary16 emulated in portable C), facet_KERNEL_f16_batch on binary16 bit "
         "patterns from the f16 tests' generator (tests/f16/f16_test.h: 1 in 4 cosines and alpha aimed at the "
         "2^-7 floors); error in facet/f16.h's measure (relative to max(|value|, 2^-14), against the oracle at "
         "the same binary16 inputs clamped to the f16 domain, saturated at 65504), bound FACET_ERR_NAME_F16 of "
         "facet/f16.h. Throughput in %s per sample (median), est. cycles per "
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
    doc_para(r->doc, "Peers (bench/harness/peers.h): <b>textbook</b> (-O2): powf, D in tan form, Smith "
         "via Lambda with sqrtf, plain divisions. <b>shader</b> (-O3 -fno-math-errno -fno-trapping-math "
         "-ffp-contract=fast, auto-vectorized), built for the width of the facet port it is compared with: "
         "<b>shader_avx2</b> -march=x86-64-v3, <b>shader_avx512</b> -march=x86-64-v4 (each run only where "
         "that port runs; elsewhere one native build): a2 form of D, pow5 by multiplication. "
         "<b>*_fm</b>: the same source and width with -ffast-math. Every peer row (path peer) takes the "
         "same inputs and computes the same formula as the facet kernel, clamped to the same domain, with "
         "no NaN rule and no cancellation-free rearrangement, so its error is arithmetic error and its time "
         "the same work: brdf_hammon's peers take (N.L, N.V, L.V, alpha, f0, albedo), derive N.H and L.H "
         "from one rsqrt of 2 + 2 L.V and use Hammon's Vis; likewise the terms it is made of (noh_from_dots, "
         "loh_from_dots, ggx_d, smith_vis_hammon, smith_g2_hammon, fresnel_schlick, diffuse_hammon) and "
         "smith_g1, smith_g2, smith_vis (exact, with sqrtf), smith_g1_hammon in every set. The shader sets "
         "also have every other kernel, each as a shader writes its formula: fresnel_cook_torrance (the "
         "Fresnel equations as printed, eta = (1 + sqrt f0) / (1 - sqrt f0), g = sqrt(eta^2 - 1 + c^2); "
         "NaN at f0 = V.H = 0, and cancellation as f0 -> 0), fresnel_schlick_f90 (f0 + (f90 - f0)(1 - c)^5: "
         "cancels where f90 < f0), fresnel_schlick_sg (exp2f), blinn_phong_d (powf(N.H, 2 / a^2 - 2) / (pi "
         "a^2)), beckmann_d (expf((N.H^2 - 1) / (a^2 N.H^2)) / (pi a^2 N.H^4)), ggx_aniso_d (UE4's a2 (a2 / "
         "|(ay T.H, ax B.H, a2 N.H)|^2)^2 / pi, a2 = ax ay), gtr_d (c / powf(1 + (a^2 - 1) N.H^2, gamma), c "
         "from expm1f), smith_g2_uncorrelated (G1 G1 with sqrtf), smith_g1_gtr (Dimov's five closed forms "
         "with logf, log1pf and the pchip interpolation), g_implicit, g_neumann (N.L N.V / max), "
         "g_cook_torrance, g_kelemen, smith_g1_beckmann (Walter's rational), smith_g1_schlick_beckmann, "
         "smith_vis_joint_approx (UE4's form), smith_vis_fit (the fitted constants), diffuse_burley, "
         "diffuse_oren_nayar (A + B max(0, L.V - N.L N.V) / max(N.L, N.V)), diffuse_hammon_hybrid, "
         "diffuse_hammon_cheap, lambert. peer_check (run before every bench run) proves each term is its "
         "kernel's formula: on a well-conditioned set its error against the kernel's oracle is <= 2^-10 "
         "(measured <= 1.4e-5), where another model is off by 3%% or more (a control, the smith_vis_fit "
         "peer judged as smith_vis, must fail). The rows of path "
         "peer-vectors are another model, D Vis_exact F + Hammon diffuse from vectors L, V (N = z), "
         "judged against its own oracle.");
}

