/* sec_speed.c - the speed table of issue 21: per kernel, both f32 tiers'
 * batch on AVX2 and AVX-512 against the same-formula shader peers built for
 * the same width (fast-math and not), from the report run's interleaved
 * speed run (harness/speed.h, recorded in the measured set: data.h), with
 * the targets beside the ratios; then the fast tier against the
 * precise one on the ports this machine cannot time (NEON: llvm-mca's
 * Cortex-A57 model, Helium and RVV: executed instructions; arm_vec.tsv).
 * Each kernel's operation budget is read from its contract (include/facet.h,
 * the Budget line; tests/f32/test_op_counts.c checks those lines). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "facet/f16.h"
#include "report.h"

/* the targets (issue 21): brdf_hammon's, and every kernel whose
 * fast tier is another formulation (its Budget line differs) */
#define T_BRDF_FAST_F32 1.3
#define T_FAST_F32 1.15
#define T_BRDF_F16_F32 2.5  /* issue 22: f16 brdf_hammon against f32 precise, AVX-512 FP16 */
#define T_BRDF_F16_PEER 0.6 /* and against the binary16 transcription */

typedef struct budget {
    int ok, f32, fast; /* total operations of each tier (clamps + NaN + peak + term) */
} budget;

/* the Budget line of kernel kn's contract in include/facet.h (the report
 * runs from the tree's root, as for ports/rtl/cost.tsv) */
static budget budget_of(const char *kn)
{
    static char *text;
    static int tried;
    budget b = { 0, 0, 0 };
    char decl[96];
    const char *p, *q;
    int c[8];
    if (!tried) {
        FILE *f = fopen("include/facet.h", "rb");
        long n;
        tried = 1;
        if (f && fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) > 0 && fseek(f, 0, SEEK_SET) == 0 &&
            (text = malloc((size_t)n + 1)) != NULL) {
            size_t got = fread(text, 1, (size_t)n, f);
            text[got] = 0;
        }
        if (f)
            fclose(f);
    }
    if (!text)
        return b;
    snprintf(decl, sizeof decl, "\nfloat facet_%s_f32(", kn);
    p = strstr(text, decl);
    if (!p)
        return b;
    for (q = p; q > text && strncmp(q, "Budget:", 7); q--)
        if (q < p && !strncmp(q, "\nfloat ", 7)) /* another kernel's declaration: this contract has none */
            return b;
    if (q == text || sscanf(q, "Budget: clamps %d, NaN %d, peak %d, term %d; fast: clamps %d, NaN %d, peak %d, term %d",
                            &c[0], &c[1], &c[2], &c[3], &c[4], &c[5], &c[6], &c[7]) != 8)
        return b;
    b.ok = 1;
    b.f32 = c[0] + c[1] + c[2] + c[3];
    b.fast = c[4] + c[5] + c[6] + c[7];
    return b;
}

/* "1.02x" and, with a target, " (>= 1.3x: met)" */
static const char *ratio_cell(char *b, size_t n, const data_speed *num, const data_speed *den, double target)
{
    double r;
    if (!num || !den || den->min <= 0)
        return "-";
    r = num->min / den->min;
    if (target > 0)
        return report_fmt(b, n, "%.2fx (>= %.2fx: %s)", r, target, r >= target ? "met" : "**missed**");
    return report_fmt(b, n, "%.2fx", r);
}

static const char *ticks_cell(char *b, size_t n, const data_speed *x)
{
    if (!x)
        return "-";
    return report_fmt(b, n, "%.3f (%.3f)", x->min, x->median);
}

static void x86_table(report *r, report_data *D)
{
    static const char *const widths[] = { "avx2", "avx512" };
    size_t ki, w;
    int rows = 0;
    doc_table(r->doc, 13, "kernel", "ops f32 / fast (Budget)", "width", "f32 min (med)", "f32_fast min (med)",
              "fm peer min (med)", "peer min (med)", "f32_fast / f32", "f32 / fm peer", "f32_fast / fm peer",
              "f32 / peer", "f32_fast / peer", "max err f32 / fast / fm peer / peer");
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const char *kn = facet_kernel_at(ki)->name;
        budget bu = budget_of(kn);
        int brdf = !strcmp(kn, "brdf_hammon"), differs = bu.ok && bu.f32 != bu.fast;
        for (w = 0; w < 2; w++) {
            char b[13][160], pn[40], e[4][32];
            const char *cells[13];
            const data_speed *f = data_speed_of(D, kn, widths[w], "f32");
            const data_speed *ff = data_speed_of(D, kn, widths[w], "f32_fast"), *pf, *pk;
            int avx512 = w == 1;
            if (!f || !ff)
                continue;
            snprintf(pn, sizeof pn, "shader_%s_fm", widths[w]);
            pf = data_speed_of(D, kn, pn, "peer");
            snprintf(pn, sizeof pn, "shader_%s", widths[w]);
            pk = data_speed_of(D, kn, pn, "peer");
            cells[0] = kn;
            cells[1] = bu.ok ? report_fmt(b[1], sizeof b[1], "%d / %d%s", bu.f32, bu.fast, differs ? "" : " (equal)") : "-";
            cells[2] = widths[w];
            cells[3] = ticks_cell(b[3], sizeof b[3], f);
            cells[4] = ticks_cell(b[4], sizeof b[4], ff);
            cells[5] = ticks_cell(b[5], sizeof b[5], pf);
            cells[6] = ticks_cell(b[6], sizeof b[6], pk);
            /* ratios of minima: the slower's ticks over the faster's (above 1: the first named is faster) */
            cells[7] = ratio_cell(b[7], sizeof b[7], f, ff, brdf ? T_BRDF_FAST_F32 : differs ? T_FAST_F32 : 0);
            cells[8] = ratio_cell(b[8], sizeof b[8], pf, f, brdf ? (avx512 ? 0.85 : 0.6) : 0);
            cells[9] = ratio_cell(b[9], sizeof b[9], pf, ff, brdf ? (avx512 ? 1.0 : 0.8) : 0);
            cells[10] = ratio_cell(b[10], sizeof b[10], pk, f, 0);
            cells[11] = ratio_cell(b[11], sizeof b[11], pk, ff, 0);
            report_g3(e[0], f->err);
            report_g3(e[1], ff->err);
            report_g3(e[2], pf ? pf->err : -1);
            report_g3(e[3], pk ? pk->err : -1);
            cells[12] = report_fmt(b[12], sizeof b[12], "%s / %s / %s / %s", e[0], e[1], pf ? e[2] : "-", pk ? e[3] : "-");
            doc_row(r->doc, cells);
            rows++;
        }
    }
    doc_table_end(r->doc);
    if (!rows)
        doc_para(r->doc, "No AVX2 or AVX-512 rows: this machine runs neither width (or the measured set has no speed run).");
}

/* binary16 against both f32 tiers at the same width: the f16 entries of the
 * same interleaved rounds (a port whose line runs an f16 table of its own) */
static void f16_table(report *r, report_data *D)
{
    size_t ki;
    int i, rows = 0;
    doc_para(r->doc, "Binary16 (facet/f16.h) in the same rounds: where a port's line of src/core/ports.def runs an f16 "
             "table of its own and this CPU runs it, that table's batch (through the dispatcher with the port "
             "active, set outside the timed call) is one more entry of each kernel's rounds, on the same inputs "
             "rounded to binary16 (2 bytes a value in and out, where f32 moves 4). Ratios of minima: above 1 the "
             "f16 batch is faster. Max err f16: facet/f16.h's measure (relative to max(|value|, 2^-14)) at those "
             "binary16 inputs clamped to the f16 domain, against the bound FACET_ERR_<NAME>_F16. <b>f16 fm "
             "peer</b> = shader_f16_fm: the shader-style transcription in _Float16 (bench/f16/peer_f16_shader.c, "
             "-O3 -march=sapphirerapids -mprefer-vector-width=512 -ffast-math: 32 binary16 lanes, no exact peak, "
             "no NaN rule, no saturation) on the same binary16 inputs, in the same rounds, its error in the same "
             "measure (inf: it returns Inf on some of them; build/facet-f16-bench counts how many). Targets "
             "(issue 22): brdf_hammon f16 >= 2.5x f32 and >= 0.6x the f16 fm peer.");
    doc_table(r->doc, 10, "kernel", "f16 table (width)", "f16 min (med)", "f32 min (med)", "f32_fast min (med)",
              "f16 fm peer min (med)", "f32 / f16", "f32_fast / f16", "f16 fm peer / f16",
              "max err f16 (bound) / f16 fm peer");
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const char *kn = facet_kernel_at(ki)->name;
        const facet_f16_kernel *h = facet_f16_kernel_find(kn);
        for (i = 0; i < D->n_speed; i++) {
            const data_speed *x = &D->speed[i], *f, *ff, *pe;
            char b[10][96], e[32], ep[32];
            const char *cells[10];
            int brdf = !strcmp(kn, "brdf_hammon");
            if (strcmp(x->kernel, kn) || strcmp(x->tier, "f16"))
                continue;
            f = data_speed_of(D, kn, x->width, "f32");
            ff = data_speed_of(D, kn, x->width, "f32_fast");
            pe = data_speed_of(D, kn, "shader_f16_fm", "peer");
            if (pe && strcmp(pe->width, x->width))
                pe = NULL;
            cells[0] = kn;
            cells[1] = report_fmt(b[1], sizeof b[1], "%s (%s)", x->port, x->width);
            cells[2] = ticks_cell(b[2], sizeof b[2], x);
            cells[3] = ticks_cell(b[3], sizeof b[3], f);
            cells[4] = ticks_cell(b[4], sizeof b[4], ff);
            cells[5] = ticks_cell(b[5], sizeof b[5], pe);
            cells[6] = ratio_cell(b[6], sizeof b[6], f, x, brdf ? T_BRDF_F16_F32 : 0);
            cells[7] = ratio_cell(b[7], sizeof b[7], ff, x, 0);
            cells[8] = ratio_cell(b[8], sizeof b[8], pe, x, brdf ? T_BRDF_F16_PEER : 0);
            report_g3(e, x->err);
            report_g3(ep, pe ? pe->err : -1);
            if (h)
                cells[9] = report_fmt(b[9], sizeof b[9], "%s (%.3g) / %s", e, h->err_f16, pe ? ep : "-");
            else
                cells[9] = report_fmt(b[9], sizeof b[9], "%s / %s", e, pe ? ep : "-");
            doc_row(r->doc, cells);
            rows++;
        }
    }
    doc_table_end(r->doc);
    if (!rows)
        doc_para(r->doc, "No f16 entries: no port line this CPU runs has an f16 table of its own (or the measured set "
                 "has none).");
}

/* the fast tier against the precise one on a port this machine cannot time */
static const char *vec_cell(char *b, size_t n, report_data *D, const char *kn, const char *port, const char *measure,
                            double *ratio)
{
    double p = data_armvec(D, "f32", port, kn, measure), f = data_armvec(D, "f32_fast", port, kn, measure);
    *ratio = -1;
    if (p <= 0 || f <= 0)
        return "-";
    *ratio = p / f;
    return report_fmt(b, n, "%.1f / %.1f = %.2fx", p, f, p / f);
}

static void vector_table(report *r, report_data *D)
{
    static const struct { const char *port, *measure; } v[] = {
        { "neon", "mca-cortex-a57" }, { "helium", "qemu-insn" }, { "rvv", "qemu-insn" },
    };
    char why[3][256];
    size_t ki, i;
    int any = 0;
    for (i = 0; i < 3; i++)
        data_armvec_status(D, v[i].port, why[i], sizeof why[i]);
    doc_para(r->doc, "The fast tier against the precise tier on the vector ports this machine cannot time "
             "(bench/report/arm_targets.sh: one 64-sample batch call per kernel and tier from the port's own "
             "table, traced under qemu): <b>NEON</b> (aarch64) in cycles per sample MODELLED by llvm-mca's "
             "Cortex-A57 model on the executed trace; <b>Helium</b> (Cortex-M55, clang 14) and <b>RVV</b> "
             "(RV64GCV at VLEN 128, clang 14) in executed instructions per sample MEASURED under qemu (not "
             "cycles). Cells: f32 / f32_fast = f32 / f32_fast. Target (issue 21): the fast tier no slower than "
             "the precise tier on each port (>= 1.00x). Status: NEON %s; Helium %s; RVV %s.",
             why[0], why[1], why[2]);
    doc_table(r->doc, 6, "kernel", "ops f32 / fast (Budget)", "NEON, A57 model cycles", "Helium, instructions",
              "RVV VLEN 128, instructions", "fast >= precise on each");
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const char *kn = facet_kernel_at(ki)->name;
        budget bu = budget_of(kn);
        char b[6][96];
        const char *cells[6];
        double ratio[3];
        int have = 0, met = 1;
        cells[0] = kn;
        cells[1] = bu.ok ? report_fmt(b[1], sizeof b[1], "%d / %d", bu.f32, bu.fast) : "-";
        for (i = 0; i < 3; i++) {
            cells[2 + i] = vec_cell(b[2 + i], sizeof b[2 + i], D, kn, v[i].port, v[i].measure, &ratio[i]);
            if (ratio[i] > 0) {
                have++;
                if (ratio[i] < 0.995) /* two decimals, as printed */
                    met = 0;
            }
        }
        if (!have)
            continue;
        cells[5] = met ? "met" : "**missed**";
        doc_row(r->doc, cells);
        any = 1;
    }
    doc_table_end(r->doc);
    if (!any)
        doc_para(r->doc, "No vector-port costs in this build (arm_vec.tsv empty: see the status above).");
}

/* binary16 against f32 on the Arm ports and RVV (issue 22): the f16 table
 * of neon (neonfp16, llvm-mca's Cortex-A55 model: the A57 has no FP16),
 * helium (heliumfp16, instructions and llvm-mca-16's Cortex-M55 cycles)
 * and rvv (rvvfp16, instructions under qemu-riscv64 at VLEN 128) */
static const char *f16_cell(char *b, size_t n, report_data *D, const char *kn, const char *port, const char *measure,
                            double *ratio)
{
    double p = data_armvec(D, "f32", port, kn, measure), f = data_armvec(D, "f32_fast", port, kn, measure);
    double h = data_armvec(D, "f16", port, kn, measure);
    *ratio = -1;
    if (p <= 0 || f <= 0 || h <= 0)
        return "-";
    *ratio = p / h;
    return report_fmt(b, n, "%.1f / %.1f / %.1f = %.2fx / %.2fx", p, f, h, p / h, f / h);
}

static void f16_arm_table(report *r, report_data *D)
{
    static const struct { const char *port, *measure; } v[] = {
        { "neon", "mca-cortex-a55" }, { "helium", "qemu-insn" }, { "helium", "mca-cortex-m55" }, { "rvv", "qemu-insn" },
    };
    size_t ki, i;
    int any = 0;
    doc_para(r->doc, "Binary16 (f16) against f32 on the Arm ports and RVV (bench/report/arm_targets.sh, the same "
             "traces): <b>NEON</b> neonfp16 in cycles per sample MODELLED by llvm-mca's Cortex-A55 model (an "
             "ARMv8.2-A core with FP16; the A57 model has none), <b>Helium</b> heliumfp16 in executed instructions "
             "MEASURED under qemu and cycles MODELLED by llvm-mca-16's Cortex-M55 model, <b>RVV</b> rvvfp16 "
             "(Zvfh) in executed instructions MEASURED under qemu-riscv64 at VLEN 128 (an f32-lane op of rvvfp16 "
             "is one LMUL 2 instruction). Cells: f32 / f32_fast / f16 = f16 against f32 / against f32_fast. "
             "Target (issue 22): brdf_hammon f16 >= 1.7x f32 on each.");
    doc_table(r->doc, 6, "kernel", "NEON, A55 model cycles", "Helium, instructions", "Helium, M55 model cycles",
              "RVV VLEN 128, instructions", "brdf_hammon >= 1.7x f32");
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const char *kn = facet_kernel_at(ki)->name;
        char b[6][96];
        const char *cells[6];
        double ratio[4];
        int have = 0, met = 1;
        cells[0] = kn;
        for (i = 0; i < 4; i++) {
            cells[1 + i] = f16_cell(b[1 + i], sizeof b[1 + i], D, kn, v[i].port, v[i].measure, &ratio[i]);
            if (ratio[i] > 0) {
                have++;
                if (ratio[i] < 1.695) /* two decimals, as printed */
                    met = 0;
            }
        }
        if (!have)
            continue;
        cells[5] = strcmp(kn, "brdf_hammon") ? "" : met ? "met" : "**missed**";
        doc_row(r->doc, cells);
        any = 1;
    }
    doc_table_end(r->doc);
    if (!any)
        doc_para(r->doc, "No f16 costs on the Arm ports or RVV in this build (arm_vec.tsv has no f16 rows: see the status "
                 "above).");
}

void section_speed(report *r)
{
    report_data *D = r->data;
    const facet_kernel *k = facet_kernel_find("brdf_hammon");
    size_t bytes = k ? (size_t)D->speed_n * (size_t)(k->n_inputs + 1) * sizeof(float) : 0;
    doc_heading(r->doc, 2, "%s", "Speed: both f32 tiers against the same-formula peers (interleaved rounds)");
    if (!D->n_speed) {
        doc_para(r->doc, "No speed run in this measured set (a set recorded before the speed table existed).");
        vector_table(r, D);
        f16_arm_table(r, D);
        return;
    }
    doc_para(r->doc, "Method (bench/harness/speed_bench.c, the same engine as <code>facet-bench speed</code>; this "
             "report's own run, recorded in measured.tsv): per kernel, every entry (the f32 and f32_fast batch of "
             "each x86 port this CPU runs, called through the port's table; the peers) computes one batch of %ld "
             "samples (the same inputs for every entry, tests/lib/sample.h's generator; for brdf_hammon %zu KiB "
             "of inputs and output per pass: %s); %d interleaved rounds, each timing one pass of every entry "
             "(%s around the call, pinned to one core), so the entries compared meet the same load. Figures: %s "
             "per sample, minimum and median over the rounds (est. cycles: divide by %.3f %s per core cycle). "
             "Ratios are of minima within this run, slower over faster: above 1 the first named is faster "
             "(f32_fast / f32 = f32's ticks over f32_fast's). Peers (bench/harness/peers.h): <b>fm peer</b> = "
             "shader_WIDTH_fm (the shader source with -ffast-math), <b>peer</b> = shader_WIDTH (-O3 "
             "-fno-math-errno -fno-trapping-math -ffp-contract=fast, no fast-math), each built for the width "
             "of the row (-march=x86-64-v3 for avx2, -v4 for avx512) and computing the kernel's own formula "
             "from the same inputs (checked by peer_check). Max err: relative to the oracle over the timed "
             "samples. Targets (issue 21): brdf_hammon f32_fast >= 1.3x f32; f32 >= 0.85x (AVX-512) / 0.6x "
             "(AVX2) and f32_fast >= 1.0x / 0.8x the fm peer; every kernel whose fast tier is another "
             "formulation (its Budget line differs, include/facet.h) f32_fast >= 1.15x f32. Kernels with "
             "equal Budget lines have no target: their contracts' family note says no cheaper formulation "
             "within the fast bound was found, the tiers differ only in the port's estimates.",
             D->speed_n, bytes / 1024, bytes <= 32768 ? "L1-resident" : "not L1-resident (L2), beyond a 32-48 KiB L1",
             D->speed_rounds, D->clock.is_cycles ? "the cycle counter" : "rdtsc", D->clock.unit, D->clock.tpc,
             D->clock.unit);
    x86_table(r, D);
    f16_table(r, D);
    vector_table(r, D);
    f16_arm_table(r, D);
}
