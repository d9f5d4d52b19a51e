/* sec_arm.c - Cortex-M: fixed point against soft-float f32 (bench/cortexm/cortexm.sh
 * left the figures in arm.tsv). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "report.h"

static const char *armcell(char *b, size_t n, double v)
{
    if (v < 0)
        return "-";
    return report_fmt(b, n, "%.0f", v);
}

void section_arm(report *r)
{
    report_data *D = r->data;
    size_t ki;
    doc_heading(r->doc, 2, "%s", "Cortex-M: fixed point vs soft-float f32 (qemu traces; measured counts, modelled cycles)");
    if (!D->n_arm) {
        doc_para(r->doc, "No Cortex-M figures in this build (arm.tsv empty: bench/cortexm/cortexm.sh needs arm-none-eabi-gcc "
             "with newlib and qemu-system-arm; llvm-mca for the modelled cycles).");
        return;
    }
    doc_para(r->doc, "bench/cortexm/cortexm.sh builds bench/cortexm/cortexm_main.c with arm-none-eabi-gcc -O2 -mthumb -mcpu=CORE "
         "(fixed point: src/fx/fx_prims.c, src/fx/fx_kernels.c; f32: facet/scalar.h with -mfloat-abi=soft, so "
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
    doc_table(r->doc, 12, "kernel", "fx M0 insns", "fx M0 cyc (TRM)", "fx M4 insns", "fx M4 / M7 / M33 mca",
          "fx M4 taken", "f32 soft M0 insns", "f32 soft M0 cyc (TRM)", "f32 soft M4 insns",
          "f32 soft M4 / M7 / M33 mca", "soft/fx M4 (mca)", "soft/fx M0 (TRM)");
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const char *kn = facet_kernel_at(ki)->name;
        char b[12][96];
        const char *cells[12];
        double fm4 = data_arm(D, "fx-mca", kn, "cortex-m4"), sm4 = data_arm(D, "f32soft-mca", kn, "cortex-m4");
        double f0c = data_arm(D, "fx-m0cyc", kn, "cortex-m0"), s0c = data_arm(D, "f32soft-m0cyc", kn, "cortex-m0");
        if (data_arm(D, "fx-insns", kn, "cortex-m4") < 0 && data_arm(D, "f32soft-insns", kn, "cortex-m4") < 0)
            continue;
        cells[0] = kn;
        cells[1] = armcell(b[1], sizeof b[1], data_arm(D, "fx-insns", kn, "cortex-m0"));
        cells[2] = armcell(b[2], sizeof b[2], f0c);
        cells[3] = armcell(b[3], sizeof b[3], data_arm(D, "fx-insns", kn, "cortex-m4"));
        cells[4] = fm4 < 0 ? "-" : report_fmt(b[4], sizeof b[4], "%.0f / %.0f / %.0f", fm4, data_arm(D, "fx-mca", kn, "cortex-m7"),
                                       data_arm(D, "fx-mca", kn, "cortex-m33"));
        cells[5] = armcell(b[5], sizeof b[5], data_arm(D, "fx-taken", kn, "cortex-m4"));
        cells[6] = armcell(b[6], sizeof b[6], data_arm(D, "f32soft-insns", kn, "cortex-m0"));
        cells[7] = armcell(b[7], sizeof b[7], s0c);
        cells[8] = armcell(b[8], sizeof b[8], data_arm(D, "f32soft-insns", kn, "cortex-m4"));
        cells[9] = sm4 < 0 ? "-" : report_fmt(b[9], sizeof b[9], "%.0f / %.0f / %.0f", sm4,
                                       data_arm(D, "f32soft-mca", kn, "cortex-m7"), data_arm(D, "f32soft-mca", kn, "cortex-m33"));
        cells[10] = fm4 > 0 && sm4 > 0 ? report_fmt(b[10], sizeof b[10], "%.1fx", sm4 / fm4) : "-";
        cells[11] = f0c > 0 && s0c > 0 ? report_fmt(b[11], sizeof b[11], "%.1fx", s0c / f0c) : "-";
        doc_row(r->doc, cells);
    }
    doc_table_end(r->doc);    doc_para(r->doc, "The fast tiers against the precise fixed point and the core's FPU: <b>fx_fast</b> "
         "(facet_KERNEL_fx_fast, src/fx/fx_fast.c) and the precise f32 kernel built for the core's FPU "
         "(<b>f32 FPU</b>: -mfloat-abi=hard, -mfpu=fpv4-sp-d16 on M4, fpv5-d16 on M7), measured the same way.");
    doc_table(r->doc, 9, "kernel", "fx_fast M0 insns", "fx_fast M0 cyc (TRM)", "fx_fast M4 insns", "fx_fast M4 / M7 / M33 mca",
          "fx M4 insns", "f32 FPU M4 insns", "f32 FPU M4 / M7 mca", "fx/fx_fast M4 (mca)");
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const char *kn = facet_kernel_at(ki)->name;
        char b[9][96];
        const char *cells[9];
        double q4 = data_arm(D, "fxfast-mca", kn, "cortex-m4"), p4 = data_arm(D, "fx-mca", kn, "cortex-m4");
        double h4 = data_arm(D, "f32fpu-mca", kn, "cortex-m4");
        if (data_arm(D, "fxfast-insns", kn, "cortex-m4") < 0 && data_arm(D, "f32fpu-insns", kn, "cortex-m4") < 0)
            continue;
        cells[0] = kn;
        cells[1] = armcell(b[1], sizeof b[1], data_arm(D, "fxfast-insns", kn, "cortex-m0"));
        cells[2] = armcell(b[2], sizeof b[2], data_arm(D, "fxfast-m0cyc", kn, "cortex-m0"));
        cells[3] = armcell(b[3], sizeof b[3], data_arm(D, "fxfast-insns", kn, "cortex-m4"));
        cells[4] = q4 < 0 ? "-" : report_fmt(b[4], sizeof b[4], "%.0f / %.0f / %.0f", q4, data_arm(D, "fxfast-mca", kn, "cortex-m7"),
                                      data_arm(D, "fxfast-mca", kn, "cortex-m33"));
        cells[5] = armcell(b[5], sizeof b[5], data_arm(D, "fx-insns", kn, "cortex-m4"));
        cells[6] = armcell(b[6], sizeof b[6], data_arm(D, "f32fpu-insns", kn, "cortex-m4"));
        {
            char m7[16];
            cells[7] = h4 < 0 ? "-" : report_fmt(b[7], sizeof b[7], "%.0f / %s", h4,
                                          armcell(m7, sizeof m7, data_arm(D, "f32fpu-mca", kn, "cortex-m7")));
        }
        cells[8] = q4 > 0 && p4 > 0 ? report_fmt(b[8], sizeof b[8], "%.1fx", p4 / q4) : "-";
        doc_row(r->doc, cells);
    }
    doc_table_end(r->doc);
}

/* the precision tiers' targets: each tier's brdf_hammon batch against the
 * fast-math shader peer built for the same width, and the fast fixed point
 * on the Cortex-M cores */
