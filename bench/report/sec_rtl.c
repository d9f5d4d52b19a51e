/* sec_rtl.c - Hardware: the RTL port's cost per module (ports/rtl/cost.tsv,
 * committed; `make rtl` remakes it with Yosys and nextpnr-ice40, so the
 * report runs no synthesis). */
#include <stdio.h>
#include <string.h>
#include "report.h"

/* a figure, or "-" where the row has none */
static const char *num(char *b, size_t n, double v, const char *fmt)
{
    if (v < 0)
        return "-";
    return report_fmt(b, n, fmt, v);
}

void section_rtl(report *r)
{
    report_data *D = r->data;
    int i, none = 0, unmeasured = 0;
    doc_heading(r->doc, 2, "%s", "Hardware: the fast fixed-point kernels as pipelined RTL (ports/rtl)");
    if (!D->n_rtl) {
        doc_para(r->doc, "No RTL cost figures: %s cannot be read (make rtl writes it; ports/rtl/README.md).", D->rtl_path);
        return;
    }
    doc_para(r->doc, "One Verilog-2005 module per kernel, fully pipelined (one sample per clock, the stated latency in "
             "clocks), bit-exact with facet_&lt;kernel&gt;_fx_fast: Verilator linked with libfacet compares every output "
             "of every module on the golden vectors and on random inputs of every int32 pattern class, Icarus Verilog "
             "runs the golden vectors (suite 57-rtl; make rtl for the long run). Figures from %s (made by make rtl, "
             "ports/rtl/cost.sh). <b>cells</b>, <b>gate eq.</b>: Yosys generic synthesis, abc -g cmos (NAND, NOR, "
             "AOI/OAI, MUX, XOR, NOT, D flip-flops), gate equivalents = Yosys's CMOS transistor estimate / 4 (NAND2 = "
             "1, D flip-flop = 4), MODELLED (no process, no wires). <b>depth</b>: the deepest stage, the longest path "
             "in cells between flip-flops. <b>iCE40</b>: Yosys synth_ice40 of the module (products on SB_MAC16 for the "
             "UP5K; all in LUTs for the HX8K), nextpnr-ice40 (seed 1) place and route inside an I/O wrapper: LUT4, DSP "
             "and EBR of the module, logic cells of the placed design (wrapper included), and the maximum clock from "
             "the router's timing report, MEASURED by the tool's static timing (not on a board). A module that fits "
             "neither an UP5K (5280 LCs, 8 DSPs) nor an HX8K (7680 LCs) shows device none and what it needs.",
             D->rtl_path);
    doc_table(r->doc, 12, "module", "latency (clk)", "cells", "gate eq.", "depth", "device", "LUT4", "DSP", "EBR",
              "LCs placed", "Fmax MHz", "LUT4, no DSP");
    for (i = 0; i < D->n_rtl; i++) {
        const data_rtl *x = &D->rtl[i];
        char b[12][32];
        const char *cells[12];
        cells[0] = x->module;
        cells[1] = num(b[1], sizeof b[1], x->latency, "%.0f");
        cells[2] = num(b[2], sizeof b[2], x->cells, "%.0f");
        cells[3] = num(b[3], sizeof b[3], x->gate_eq, "%.0f");
        cells[4] = num(b[4], sizeof b[4], x->depth, "%.0f");
        cells[5] = x->device;
        cells[6] = num(b[6], sizeof b[6], x->luts, "%.0f");
        cells[7] = num(b[7], sizeof b[7], x->dsps, "%.0f");
        cells[8] = num(b[8], sizeof b[8], x->ebr, "%.0f");
        cells[9] = num(b[9], sizeof b[9], x->lcs, "%.0f");
        cells[10] = num(b[10], sizeof b[10], x->fmax_mhz, "%.1f");
        cells[11] = num(b[11], sizeof b[11], x->luts_no_dsp, "%.0f");
        none += !strcmp(x->device, "none");
        unmeasured += !strcmp(x->device, "-");
        doc_row(r->doc, cells);
    }
    {
        const char *anchor[12] = { "anchor: log-domain Phong shading engine (Lai, Yu, Chen, ISCAS 2002)", "", "",
                                   "12,061 gates", "", "ASIC (2002)", "", "", "", "", "450", "" };
        doc_row(r->doc, anchor);
    }
    doc_table_end(r->doc);
    doc_para(r->doc, "%d of %d modules fit no iCE40 as one pipelined module: their LUT4 and DSP columns are what they need "
             "with the 16x16 products on DSP blocks, and the last column (where it was run) with every product in LUTs. "
             "The anchor is a published hardware shading unit: its gate count and clock are those of its own 2002 "
             "ASIC process and library, and it evaluates a multiplier-free log-domain Phong model; the figures here "
             "are a generic CMOS estimate and a small FPGA evaluating facet's kernels at the precision their contracts "
             "state. Comparisons across the two are rough. ports/rtl/README.md has the cells by type.",
             none, D->n_rtl);
    if (unmeasured)
        doc_para(r->doc, "%d modules were not measured by the last cost run (device -): make rtl measures every module.",
                 unmeasured);
}
