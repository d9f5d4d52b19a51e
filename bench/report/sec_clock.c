/* sec_clock.c - the clock and the method of the measurements. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "report.h"

void section_clock(report *r)
{
    report_data *D = r->data;
    doc_heading(r->doc, 2, "%s", "Clock and method");
    doc_para(r->doc, "Clock: <b>%s</b> (%s). %s Pinned to CPU %d. Throughput: %s samples per pass, "
         "L1-resident structure-of-arrays of valid random geometry from tests/lib/sample.h (per-sample "
         "alpha, f0, albedo), cost = t(2R passes) - t(R passes) over R passes; >= 11 epochs after "
         "warm-up, each the best of 3; reported: min and median, spread = (max - min) / median, "
         "'!' where spread > 5%%. Latency: a dependent chain (the first input of call i+1 is "
         "in[i+1] + out[i] * 0), minus the same chain with no kernel; per call (a call is 8 samples "
         "for AVX2, 4 for SSE2).",
         D->clock.source, D->clock.is_cycles ? "measured core cycles" : "time-stamp counter ticks, NOT core cycles",
         D->clock.is_cycles ? "" : "perf_event_open(PERF_COUNT_HW_CPU_CYCLES) is not available here (a VM without a virtual PMU), so "
         "'est. cycles' = ticks / ticks-per-cycle, the ratio measured with a dependent chain of 1-cycle integer adds "
         "(it assumes the core clock does not change between that calibration and the kernel).",
         D->clock.cpu, r->quick ? "256" : "1024");
    if (!D->clock.is_cycles)
        doc_para(r->doc, "Measured ticks per core cycle: %.4f (core clock about %.2f x the TSC rate).", D->clock.tpc, 1 / D->clock.tpc);
}

