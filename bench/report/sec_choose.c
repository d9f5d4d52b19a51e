/* sec_choose.c - which one to use: per term and target, the most accurate choice within
 * each cost. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "kernel_facts.h"
#include "choose.h"
#include "report.h"

static const char *const fmts[] = { "f32", "f32_fast", "fx", "fx_fast" };

/* targets: a port of this machine (measured est. cycles), an Arm vector
 * port (arm_vec.tsv: llvm-mca NEON cycles, Helium instruction counts), or a
 * Cortex-M core (arm.tsv: TRM-modelled M0 cycles, llvm-mca M4 cycles) */
static const choose_target targets[] = {
    { "AVX-512 (this machine)", "avx512", NULL, "cyc", 0, 0, NULL, NULL },
    { "AVX2 (this machine)", "avx2", NULL, "cyc", 0, 0, NULL, NULL },
    { "SSE2 (this machine)", "sse2", NULL, "cyc", 0, 0, NULL, NULL },
    { "NEON (aarch64, Cortex-A57 model)", NULL, NULL, "cyc (llvm-mca A57 model)", 0, 0, "neon", "mca-cortex-a57" },
    { "Helium (Cortex-M55)", NULL, NULL, "instr (qemu count)", 0, 0, "helium", "qemu-insn" },
    { "Cortex-M0", NULL, "cortex-m0", "cyc (TRM model)", 1, 0, NULL, NULL },
    { "Cortex-M4", NULL, "cortex-m4", "cyc (llvm-mca)", 1, 0, NULL, NULL },
    { "Cortex-M4 with FPU", NULL, "cortex-m4", "cyc (llvm-mca)", 0, 1, NULL, NULL },
};

int choose_target_count(void) { return (int)(sizeof targets / sizeof targets[0]); }
const choose_target *choose_target_at(int t) { return &targets[t]; }

/* a candidate's implementation error: measured on this machine's port (the
 * Cortex-M builds run the scalar C: fixed point is bit-exact everywhere,
 * the f32 scalar code is the same source) */
static double impl_of(const report_data *D, const char *kn, const char *format, const char *port)
{
    const bench_row *x = data_row_of(D, kn, format, port, "batch");
    return x ? x->err.max_rel_vis : -1;
}

static double total_of(const choice *c) { return (c->model > 0 ? c->model : 0) + c->impl; }

/* the frontier of cands by cost: each candidate more accurate than every
 * cheaper one, as "<= cost: kernel format (error)" */
static void frontier_cell(char *out, size_t cap, choice *c, int n, const char *unit)
{
    double best = 1e300;
    int i, j;
    size_t len = 0;
    for (i = 1; i < n; i++) { /* by cost, then by error */
        choice k = c[i];
        for (j = i - 1; j >= 0 && (c[j].cost > k.cost || (c[j].cost == k.cost && total_of(&c[j]) > total_of(&k))); j--)
            c[j + 1] = c[j];
        c[j + 1] = k;
    }
    out[0] = 0;
    for (i = 0; i < n; i++) {
        double e = total_of(&c[i]);
        char eb[32];
        if (e >= best * 0.999)
            continue;
        best = e;
        {
            const kf_sim *sim = kf_sim_of(c[i].kernel); /* a diffuse kernel: say which material, and the noise */
            char sb[96] = "";
            if (sim)
                snprintf(sb, sizeof sb, " (+- %.2g), vs the %s microsurface", sim->sig, sim->reference);
            len += (size_t)snprintf(out + len, len < cap ? cap - len : 0, "%s<= %.3g %s: <b>%s %s</b> (error %s%s%s)",
                                    len ? "<br>" : "", c[i].cost, unit, c[i].kernel, c[i].format, report_g3(eb, e), sb,
                                    c[i].model > 0 ? ", mostly model" : "");
        }
        if (len >= cap)
            break;
    }
    if (!out[0])
        snprintf(out, cap, "-");
}

int choose_candidates(const report_data *D, int term, int t, choice *c, int max)
{
    const choose_target *tg = &targets[t];
    const char *names[32];
    int nk = kf_term_kernels(term, names, 32), n = 0, k, f;
    for (k = 0; k < nk; k++) {
        const char *kn = names[k];
        double model = kf_model_of(kn);
        for (f = 0; f < 4 && n < max; f++) {
            double cost = -1, impl;
            if (tg->port) {
                const bench_row *x = data_row_of(D, kn, fmts[f], tg->port, "batch");
                if (x)
                    cost = data_est(D, x->thr.median);
                impl = impl_of(D, kn, fmts[f], tg->port);
            } else if (tg->vec) {
                cost = data_armvec(D, fmts[f], tg->vec, kn, tg->measure);
                impl = impl_of(D, kn, fmts[f], "scalar");
            } else {
                const char *what = f == 0 ? (tg->f32fpu ? "f32fpu" : tg->f32soft ? "f32soft" : NULL)
                                          : f == 1 ? NULL : f == 2 ? "fx" : "fxfast";
                char key[32];
                if (!what)
                    continue;
                snprintf(key, sizeof key, "%s-%s", what, !strcmp(tg->cpu, "cortex-m0") ? "m0cyc" : "mca");
                cost = data_arm(D, key, kn, tg->cpu);
                impl = impl_of(D, kn, fmts[f], "scalar");
            }
            if (cost <= 0 || impl < 0)
                continue;
            c[n].kernel = kn;
            c[n].format = fmts[f];
            c[n].cost = cost;
            c[n].impl = impl;
            c[n].model = model;
            n++;
        }
    }
    return n;
}

void section_choose(report *r)
{
    report_data *D = r->data;
    char why_neon[300], why_helium[300];
    int ok_neon = data_armvec_status(D, "neon", why_neon, sizeof why_neon);
    int ok_helium = data_armvec_status(D, "helium", why_helium, sizeof why_helium);
    int g, t;
    doc_heading(r->doc, 2, "%s", "Which one to use");
    doc_para(r->doc, "For each term and target: the Pareto frontier of kernel variant x format x tier by cost and by error "
         "against the exact term, read as 'within this cost, the most accurate choice is ...'. Error = model "
         "error (the formula against the exact term, from the tradeoff sweep; 0 for exact kernels, left out for "
         "terms whose variants are different models) + implementation error (max relative against the formula's "
         "own oracle, where the value is >= 2^-8, measured on that port; Cortex-M: the scalar code's). Costs: "
         "this machine's ports in est. core cycles per sample (batch, %s run); NEON (aarch64): cycles per "
         "sample MODELLED by llvm-mca 14 with its Cortex-A57 scheduling model (the model LLVM 14 also uses for "
         "A72, A76 and Neoverse N1) on the executed instruction trace of a 64-sample batch call under "
         "qemu-aarch64 (callees and tails included, branches free); Helium (Cortex-M55, helium objects from "
         "clang 14): instructions executed per sample of a 64-sample batch call, MEASURED under qemu-system-arm "
         "(instructions, not cycles: a 128-bit MVE instruction takes two beats); both from "
         "bench/report/arm_targets.sh, the ports' own tables in every tier they run; implementation error there: "
         "the scalar code's measured here (fixed point is bit-exact on every port; the ports' f32 is held to the "
         "same bounds by the 40-arm and 52-helium suites). Cortex-M in cycles per call, "
         "MODELLED from executed-instruction traces (M0: TRM timings, M4: llvm-mca; section Cortex-M). RISC-V "
         "is not costed here. NEON: %s. Helium: %s. Details: the Pareto figures below, then the long "
         "tables. D has no exact reference (each variant is a model of its own, a look rather than an "
         "approximation): there each variant's cheapest format is listed with its cost. Diffuse: the model error "
         "is against the simulated Smith microsurface of the material each kernel approximates (the model-error "
         "section; max relative over its grid, with the simulation's standard error), so the diffuse rows rank by "
         "it as the shadowing rows do.",
         r->quick ? "a quick" : "a full", why_neon, why_helium);
    for (g = 0; g < kf_term_count(); g++) {
        int any = 0;
        for (t = 0; t < choose_target_count(); t++) {
            choice c[64];
            int n;
            static char cell[2048];
            const char *cells[3];
            n = choose_candidates(D, g, t, c, 64);
            if (!n && targets[t].vec && !(!strcmp(targets[t].vec, "neon") ? ok_neon : ok_helium)) {
                /* the target could not be costed here: the table says why */
                if (!any) {
                    doc_heading(r->doc, 3, "%s", kf_term_title(g));
                    doc_table(r->doc, 3, "target", "candidates", "within this cost, the most accurate choice");
                    any = 1;
                }
                cells[0] = targets[t].name;
                cells[1] = "0";
                snprintf(cell, sizeof cell, "not costed: %s", !strcmp(targets[t].vec, "neon") ? why_neon : why_helium);
                cells[2] = cell;
                doc_row(r->doc, cells);
                continue;
            }
            if (!n)
                continue;
            if (!any) {
                doc_heading(r->doc, 3, "%s", kf_term_title(g));
                doc_table(r->doc, 3, "target", "candidates", "within this cost, the most accurate choice");
                any = 1;
            }
            {
                int ref = kf_term_has_reference(g), m = 0, i, j;
                choice other[64];
                size_t len;
                /* the frontier over the candidates compared with the term's
                 * reference; the others (a different model, or a term
                 * without a reference) listed by their cheapest format */
                for (i = 0; i < n; i++)
                    if (ref && c[i].model >= 0)
                        c[m++] = c[i];
                    else
                        other[i - m] = c[i];
                frontier_cell(cell, sizeof cell, c, m, targets[t].unit);
                if (!m)
                    cell[0] = 0;
                len = strlen(cell);
                for (i = 0; i < n - m && len + 200 < sizeof cell; i++) {
                    int best = 1;
                    for (j = 0; j < n - m; j++)
                        if (!strcmp(other[j].kernel, other[i].kernel) &&
                            (other[j].cost < other[i].cost || (other[j].cost == other[i].cost && j < i)))
                            best = 0;
                    if (!best)
                        continue;
                    len += (size_t)snprintf(cell + len, sizeof cell - len, "%s%s <b>%s %s</b>: %.3g %s (impl. error %.3g)",
                                            len ? "<br>" : "", ref ? "a different model:" : "", other[i].kernel,
                                            other[i].format, other[i].cost, targets[t].unit, other[i].impl);
                }
            }
            {
                char nb[16];
                cells[0] = targets[t].name;
                cells[1] = report_fmt(nb, sizeof nb, "%d", n);
                cells[2] = cell;
                doc_row(r->doc, cells);
            }
        }
        if (any)
            doc_table_end(r->doc);
    }
}

/* an image-space error as one cell: max / p99 / mean code difference (max dE76) */
