/* sec_wcet.c - Execution time on Cortex-M: the per-call ranges of every
 * fixed-point kernel that include/facet/fx.h states (its <wcet-table>
 * block, written by tests/cortexm/wcet.sh --write and held exactly by
 * suite 51-fx-wcet), so the report shows the very figures the test
 * enforces and runs no emulator of its own. */
#include <stdio.h>
#include <string.h>
#include "report.h"

#define WCET_HEADER "include/facet/fx.h"

void section_wcet(report *r)
{
    FILE *f = fopen(WCET_HEADER, "r");
    char line[256];
    int in = 0, rows = 0;
    doc_heading(r->doc, 2, "%s", "Execution time on Cortex-M (fixed point, per call)");
    if (!f) {
        doc_para(r->doc, "No execution-time table: %s cannot be read.", WCET_HEADER);
        return;
    }
    doc_para(r->doc, "Every fixed-point kernel in both tiers, one call, minimum-maximum over the golden vectors "
             "(the edge cases and 256 random inputs of facet vectors, seed 1), built -O2 for Cortex-M0, M4 and M33. "
             "<b>insns</b>: instructions executed under qemu-system-arm, MEASURED (exact, deterministic). "
             "<b>cycles</b>: MODELLED (M0 from its TRM timing table, M4/M33 by llvm-mca on each executed path). "
             "A single figure is constant time: on M4 and M33 the fast kernels' machine code has no conditional "
             "branch (the disassembly check of suite 51-fx-wcet); on M0 (no conditional execution) selects stay "
             "branches and the spread is stated. Budget the maximum. From %s, where suite 51-fx-wcet holds every "
             "row exactly (regenerate: sh tests/cortexm/wcet.sh --write).", WCET_HEADER);
    doc_table(r->doc, 8, "kernel", "tier", "M0 insns", "M0 cycles", "M4 insns", "M4 cycles", "M33 insns", "M33 cycles");
    while (fgets(line, sizeof line, f)) {
        char c[8][48];
        const char *cells[8];
        int i;
        if (strstr(line, "</wcet-table>"))
            break;
        if (strstr(line, "<wcet-table>")) {
            in = 1;
            continue;
        }
        if (!in || sscanf(line, " * %47s %47s %47s %47s %47s %47s %47s %47s", c[0], c[1], c[2], c[3], c[4], c[5],
                          c[6], c[7]) != 8 || !strcmp(c[0], "kernel"))
            continue;
        for (i = 0; i < 8; i++)
            cells[i] = c[i];
        doc_row(r->doc, cells);
        rows++;
    }
    doc_table_end(r->doc);
    fclose(f);
    if (!rows)
        doc_para(r->doc, "The execution-time block of %s has no rows.", WCET_HEADER);
}
