/* msim_analyse.c - what the reference tables are for (bench/microsurface/README.md):
 *   error:  the model error of every diffuse kernel (facet's oracle of each,
 *           and the f32 and f32_fast kernels) against the simulation of the
 *           material it approximates -> model_error.tsv, model_error.md
 *   refit:  Hammon's constants refitted to the reference -> hammon_refit.md
 *   energy: single-scattering GGX's energy loss 1 - E(N.V, alpha) and a cheap
 *           compensation term -> spec_loss.tsv, spec_loss.svg, spec_loss.md
 * Every relative error e = kernel / reference - 1 is given with its standard
 * error from the simulation, sigma = (kernel / reference) (se / reference). */
#include "msim_tables.h"
#include "facet.h"
#include "facet/oracle.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

int msim_cmd_error(const char *dir);
int msim_cmd_refit(const char *dir);
int msim_cmd_energy(const char *dir);

/* ---- the references ------------------------------------------------------ */
enum { REF_HAMMON = 0, REF_LAMBERT = 1, NREF = 2 };
static const char *const ref_name[NREF] = {"hammon", "lambert"};
static const char *const ref_desc[NREF] = {
    "Hammon's facets (Schlick F0 0.04 mirror + Fresnel-symmetric diffuse), the diffuse part (paths with a diffuse "
    "event) / (1 - F0)",
    "Lambertian facets, the whole BRDF"};
#define NRHO 4
static const int rho_part[NREF][NRHO] = {{MSIM_D100, MSIM_D075, MSIM_D050, MSIM_D025},
                                         {MSIM_TOTAL, MSIM_D075, MSIM_D050, MSIM_D025}};

static msim_table tab[NREF];
static double f0_hammon;

static int load_refs(const char *dir)
{
    char path[1024];
    int i;
    for (i = 0; i < NREF; i++) {
        snprintf(path, sizeof path, "%s/ref_%s.tsv", dir, ref_name[i]);
        if (msim_table_read(&tab[i], path)) {
            fprintf(stderr, "microsurface: cannot read %s\n", path);
            return -1;
        }
    }
    f0_hammon = msim_grid_mat[0].f0;
    return 0;
}

/* DIR/NAME for writing (NULL and a message when it cannot be) */
static FILE *open_out(const char *dir, const char *name)
{
    char path[1024];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    f = fopen(path, "w");
    if (!f)
        fprintf(stderr, "microsurface: cannot write %s\n", path);
    return f;
}

static void ref_value(int ref, const msim_row *r, int irho, double *v, double *se)
{
    double s = ref == REF_HAMMON ? 1.0 / (1.0 - f0_hammon) : 1.0;
    *v = r->val[rho_part[ref][irho]] * s;
    *se = r->se[rho_part[ref][irho]] * s;
}

/* ---- the kernels --------------------------------------------------------- */
typedef double (*kern_fn)(double nl, double nv, double lv, double a, double rho);

static double k_hammon_o(double l, double v, double lv, double a, double r) { return facet_oracle_diffuse_hammon(l, v, lv, a, r); }
static double k_hybrid_o(double l, double v, double lv, double a, double r) { return facet_oracle_diffuse_hammon_hybrid(l, v, lv, a, r); }
static double k_cheap_o(double l, double v, double lv, double a, double r) { return facet_oracle_diffuse_hammon_cheap(l, v, lv, a, r); }
static double k_burley_o(double l, double v, double lv, double a, double r)
{
    return facet_oracle_diffuse_burley(l, v, facet_oracle_loh_from_dots(lv), a, r);
}
static double k_on_o(double l, double v, double lv, double a, double r) { return facet_oracle_diffuse_oren_nayar(l, v, lv, a, r); }
static double k_lambert_o(double l, double v, double lv, double a, double r)
{
    (void)l, (void)v, (void)lv, (void)a;
    return facet_oracle_lambert(r);
}
/* the f32 kernels at the float-rounded point */
#define F32K(name, call)                                                                         \
    static double name(double l, double v, double lv, double a, double r)                        \
    {                                                                                            \
        float fl = (float)l, fv = (float)v, flv = (float)lv, fa = (float)a, fr = (float)r;       \
        (void)fl, (void)fv, (void)flv, (void)fa;                                                 \
        return (double)(call);                                                                   \
    }
F32K(k_hammon_f, facet_diffuse_hammon_f32(fl, fv, flv, fa, fr))
F32K(k_hybrid_f, facet_diffuse_hammon_hybrid_f32(fl, fv, flv, fa, fr))
F32K(k_cheap_f, facet_diffuse_hammon_cheap_f32(fl, fv, flv, fa, fr))
F32K(k_burley_f, facet_diffuse_burley_f32(fl, fv, facet_loh_from_dots_f32(flv), fa, fr))
F32K(k_on_f, facet_diffuse_oren_nayar_f32(fl, fv, flv, fa, fr))
F32K(k_lambert_f, facet_lambert_f32(fr))
F32K(k_hammon_ff, facet_diffuse_hammon_f32_fast(fl, fv, flv, fa, fr))
F32K(k_hybrid_ff, facet_diffuse_hammon_hybrid_f32_fast(fl, fv, flv, fa, fr))
F32K(k_cheap_ff, facet_diffuse_hammon_cheap_f32_fast(fl, fv, flv, fa, fr))
F32K(k_burley_ff, facet_diffuse_burley_f32_fast(fl, fv, facet_loh_from_dots_f32_fast(flv), fa, fr))
F32K(k_on_ff, facet_diffuse_oren_nayar_f32_fast(fl, fv, flv, fa, fr))
F32K(k_lambert_ff, facet_lambert_f32_fast(fr))

#define NFORM 3
static const char *const form_name[NFORM] = {"oracle", "f32", "f32_fast"};
#define NKERN 6
static const struct {
    const char *name;
    kern_fn fn[NFORM];
    int ref; /* the material it is meant to approximate */
    const char *why;
} kern[NKERN] = {
    {"diffuse_hammon", {k_hammon_o, k_hammon_f, k_hammon_ff}, REF_HAMMON,
     "Hammon fitted it to exactly this simulation (his appendix); exact at alpha = 0"},
    {"diffuse_hammon_hybrid", {k_hybrid_o, k_hybrid_f, k_hybrid_ff}, REF_HAMMON,
     "Hammon's variant of the same fit (Disney's smooth term)"},
    {"diffuse_hammon_cheap", {k_cheap_o, k_cheap_f, k_cheap_ff}, REF_HAMMON,
     "Hammon's variant of the same fit (Lambert's smooth term)"},
    {"diffuse_burley", {k_burley_o, k_burley_f, k_burley_ff}, REF_HAMMON,
     "the diffuse beside a GGX dielectric's specular, with its Fresnel-like grazing darkening and retro-reflection "
     "(Hammon's comparison puts it against this simulation)"},
    {"diffuse_oren_nayar", {k_on_o, k_on_f, k_on_ff}, REF_LAMBERT,
     "Lambertian facets (its derivation), here on GGX-Smith facets with sigma = alpha / 2"},
    {"lambert", {k_lambert_o, k_lambert_f, k_lambert_ff}, REF_LAMBERT, "Lambertian facets; exact at alpha = 0"},
};

/* ---- aggregation --------------------------------------------------------- */
/* two measures: the relative error e = k / r - 1 and the absolute error in
 * units of a Lambertian BRDF of the same albedo, u = |k - r| / (albedo / pi)
 * (what an image shows where the reference is dark) */
typedef struct {
    double max, sig_at_max, sum, sumsig, sumsigned;
    int n;
    double at_a, at_nl, at_nv, at_phi, at_lv, at_rho, at_k, at_ref;
    double umax, usig, usum;
    double u_a, u_nl, u_nv, u_phi, u_rho;
} agg;

static void agg_add(agg *g, double e, double sig, double u, double usig, const msim_row *r, double rho, double kv,
                    double rv)
{
    if (g->n == 0 || fabs(e) > g->max) {
        g->max = fabs(e);
        g->sig_at_max = sig;
        g->at_a = r->alpha;
        g->at_nl = r->nl;
        g->at_nv = r->nv;
        g->at_phi = r->phi;
        g->at_lv = r->lv;
        g->at_rho = rho;
        g->at_k = kv;
        g->at_ref = rv;
    }
    if (g->n == 0 || u > g->umax) {
        g->umax = u;
        g->usig = usig;
        g->u_a = r->alpha;
        g->u_nl = r->nl;
        g->u_nv = r->nv;
        g->u_phi = r->phi;
        g->u_rho = rho;
    }
    g->sum += fabs(e);
    g->sumsig += sig;
    g->sumsigned += e;
    g->usum += u;
    g->n++;
}

#define NA (MSIM_NALPHA + 1) /* the last: all alphas */
#define NR (NRHO + 1)        /* the last: all albedos */
#define ND 2                 /* domains: the whole grid; N.L, N.V >= 0.2 */
#define COS_D1 0.2
static const char *const dom_name[ND] = {"all", "cos>=0.2"};
static agg A[NKERN][NFORM][NREF][ND][NR][NA];

static int alpha_index(double a)
{
    int i;
    for (i = 0; i < MSIM_NALPHA; i++)
        if (msim_grid_alpha[i] == a)
            return i;
    return -1;
}

static void pct(char *buf, size_t n, double x) /* a relative error as a percentage */
{
    if (x >= 0.1)
        snprintf(buf, n, "%.1f%%", 100.0 * x);
    else if (x >= 0.001)
        snprintf(buf, n, "%.2f%%", 100.0 * x);
    else
        snprintf(buf, n, "%.3f%%", 100.0 * x);
}

/* "max (+- sigma)", or a bound when the error is inside 3 sigma */
static void fig(char *buf, size_t n, double x, double sig)
{
    char a[32], b[32], c[32];
    pct(a, sizeof a, x);
    pct(b, sizeof b, sig);
    pct(c, sizeof c, 3.0 * sig);
    if (x < 3.0 * sig)
        snprintf(buf, n, "< %s (3 sigma; %s measured)", c, a);
    else
        snprintf(buf, n, "%s (+- %s)", a, b);
}

/* a Markdown table's rule under a header of 1 + n columns */
static void md_rule(FILE *md, int n)
{
    int i;
    fputs("\n|---|", md);
    for (i = 0; i < n; i++)
        fputs("---|", md);
    fputs("\n", md);
}

/* x[0], x[1], ... separated by ", " */
static void md_list(FILE *md, const char *fmt, const double *x, int n)
{
    int i;
    for (i = 0; i < n; i++) {
        if (i)
            fputs(", ", md);
        fprintf(md, fmt, x[i]);
    }
}

static void agg_point(int k, int fm, int rf, const msim_row *r, int ir, int ai)
{
    double v, se, rho = msim_rho[ir], kv, e, sig, u, usig, lam;
    int d, nd;
    ref_value(rf, r, ir, &v, &se);
    if (!(v > 0.0))
        return;
    kv = kern[k].fn[fm](r->nl, r->nv, r->lv, r->alpha, rho);
    e = kv / v - 1.0;
    sig = kv / v * (se / v);
    lam = rho / PI;
    u = fabs(kv - v) / lam;
    usig = se / lam;
    nd = r->nl >= COS_D1 && r->nv >= COS_D1 ? 2 : 1;
    for (d = 0; d < nd; d++) {
        agg_add(&A[k][fm][rf][d][ir][ai], e, sig, u, usig, r, rho, kv, v);
        agg_add(&A[k][fm][rf][d][ir][NA - 1], e, sig, u, usig, r, rho, kv, v);
        agg_add(&A[k][fm][rf][d][NR - 1][ai], e, sig, u, usig, r, rho, kv, v);
        agg_add(&A[k][fm][rf][d][NR - 1][NA - 1], e, sig, u, usig, r, rho, kv, v);
    }
}

static void md_summary_row(FILE *md, int k, int rf)
{
    const agg *g0 = &A[k][0][rf][0][NR - 1][NA - 1], *g1 = &A[k][0][rf][1][NR - 1][NA - 1];
    char b1[96], b2[32], b3[32], b4[96], b5[32], b6[32], b7[32], b8[32], b9[96];
    fig(b1, sizeof b1, g0->max, g0->sig_at_max);
    pct(b2, sizeof b2, g0->sum / g0->n);
    pct(b3, sizeof b3, g0->sumsig / g0->n);
    fig(b4, sizeof b4, g1->max, g1->sig_at_max);
    pct(b5, sizeof b5, g1->sum / g1->n);
    pct(b6, sizeof b6, g0->usum / g0->n);
    pct(b7, sizeof b7, A[k][1][rf][0][NR - 1][NA - 1].max);
    pct(b8, sizeof b8, A[k][2][rf][0][NR - 1][NA - 1].max);
    fig(b9, sizeof b9, g0->umax, g0->usig);
    fprintf(md, "| %s%s%s | %s%s | %s at %g, %g, %g, %g, %g | %s (%s) | %s at %g, %g, %g, %g, %g | %s | %s at %g, %g, %g, %g, %g; mean %s | %s | %s |\n",
            kern[k].ref == rf ? "**" : "", kern[k].name, kern[k].ref == rf ? "**" : "", ref_name[rf],
            kern[k].ref == rf ? " (its material)" : "", b1, g0->at_a, g0->at_nl, g0->at_nv, g0->at_phi, g0->at_rho,
            b2, b3, b4, g1->at_a, g1->at_nl, g1->at_nv, g1->at_phi, g1->at_rho, b5, b9, g0->u_a, g0->u_nl, g0->u_nv,
            g0->u_phi, g0->u_rho, b6, b7, b8);
}

static void md_per_alpha(FILE *md, int d)
{
    int ia, k;
    fprintf(md, "\n## Per alpha, against the kernel's own material, %s (oracle; every albedo)\n\n",
            d ? "N.L and N.V >= 0.2" : "the whole grid");
    fprintf(md, "Each cell: max abs e (sigma) at (N.L, N.V, phi, albedo); mean abs e.\n\n| alpha |");
    for (k = 0; k < NKERN; k++)
        fprintf(md, " %s |", kern[k].name);
    md_rule(md, NKERN);
    for (ia = 0; ia < MSIM_NALPHA; ia++) {
        fprintf(md, "| %g |", msim_grid_alpha[ia]);
        for (k = 0; k < NKERN; k++) {
            const agg *g = &A[k][0][kern[k].ref][d][NR - 1][ia];
            char b1[96], b2[32];
            fig(b1, sizeof b1, g->max, g->sig_at_max);
            pct(b2, sizeof b2, g->sum / g->n);
            fprintf(md, " %s at (%g, %g, %g, %g); mean %s |", b1, g->at_nl, g->at_nv, g->at_phi, g->at_rho, b2);
        }
        fprintf(md, "\n");
    }
}

int msim_cmd_error(const char *dir)
{
    int k, fm, rf, ir, i, ia, d;
    FILE *t, *md;
    if (load_refs(dir))
        return 2;
    memset(A, 0, sizeof A);
    for (rf = 0; rf < NREF; rf++)
        for (i = 0; i < tab[rf].n; i++) {
            const msim_row *r = &tab[rf].row[i];
            int ai = alpha_index(r->alpha);
            if (ai < 0)
                continue;
            for (ir = 0; ir < NRHO; ir++)
                for (k = 0; k < NKERN; k++)
                    for (fm = 0; fm < NFORM; fm++)
                        agg_point(k, fm, rf, r, ir, ai);
        }
    t = open_out(dir, "model_error.tsv");
    md = open_out(dir, "model_error.md");
    if (!t || !md)
        return 2;
    fprintf(t, "# model error of facet's diffuse kernels against the microsurface simulation "
               "(bench/microsurface/README.md, \"model_error.tsv\"); made by microsurface error\n");
    fprintf(t, "kernel\tform\treference\tprimary\tdomain\talbedo\talpha\tpoints\tmax_abs_rel_err\tsigma_at_max\t"
               "at_alpha\tat_nl\tat_nv\tat_phi\tat_lv\tat_albedo\tkernel_at_max\tref_at_max\t"
               "mean_abs_rel_err\tmean_sigma\tmean_rel_err\tmax_lambert_units\tsigma_lu\tlu_at_alpha\tlu_at_nl\t"
               "lu_at_nv\tlu_at_phi\tlu_at_albedo\tmean_lambert_units\n");
    for (k = 0; k < NKERN; k++)
        for (fm = 0; fm < NFORM; fm++)
            for (rf = 0; rf < NREF; rf++)
                for (d = 0; d < ND; d++)
                    for (ir = 0; ir < NR; ir++)
                        for (ia = 0; ia < NA; ia++) {
                            const agg *g = &A[k][fm][rf][d][ir][ia];
                            char as[32], rs[32];
                            if (!g->n)
                                continue;
                            if (ia == NA - 1)
                                snprintf(as, sizeof as, "all");
                            else
                                snprintf(as, sizeof as, "%.17g", msim_grid_alpha[ia]);
                            if (ir == NR - 1)
                                snprintf(rs, sizeof rs, "all");
                            else
                                snprintf(rs, sizeof rs, "%g", msim_rho[ir]);
                            fprintf(t, "%s\t%s\t%s\t%d\t%s\t%s\t%s\t%d\t%.4e\t%.2e\t%.17g\t%.17g\t%.17g\t%g\t%.6f\t%g\t"
                                       "%.6e\t%.6e\t%.4e\t%.2e\t%.4e\t%.4e\t%.2e\t%.17g\t%.17g\t%.17g\t%g\t%g\t%.4e\n",
                                    kern[k].name, form_name[fm], ref_name[rf], kern[k].ref == rf, dom_name[d], rs, as,
                                    g->n, g->max, g->sig_at_max, g->at_a, g->at_nl, g->at_nv, g->at_phi, g->at_lv,
                                    g->at_rho, g->at_k, g->at_ref, g->sum / g->n, g->sumsig / g->n, g->sumsigned / g->n,
                                    g->umax, g->usig, g->u_a, g->u_nl, g->u_nv, g->u_phi, g->u_rho, g->usum / g->n);
                        }
    fclose(t);

    /* the Markdown the lead pastes into the contracts and the report */
    fprintf(md, "# Model error of the diffuse kernels against the microsurface simulation\n\n");
    fprintf(md, "Made by `build/microsurface/microsurface error --dir bench/microsurface` from the reference "
                "tables (`ref_hammon.tsv`, `ref_lambert.tsv`; README.md says how they were made). Relative "
                "error e = kernel / reference - 1 over the tables' grid: alpha in {");
    md_list(md, "%g", msim_grid_alpha, MSIM_NALPHA);
    fprintf(md, "}, N.L and N.V in {");
    md_list(md, "%g", msim_grid_cos, MSIM_NCOS);
    fprintf(md, "}, the azimuth phi between L and V in {0, 30, ..., 180} degrees (0: V on L's side), and the "
                "facet albedo in {1, 0.75, 0.5, 0.25} (the kernel's albedo input). Beside every figure: the "
                "simulation's standard error of that relative error (sigma); a maximum inside 3 sigma is given "
                "as a bound, not as a figure. Means are of |e|, with the mean sigma as their noise. The largest "
                "relative errors fall where the reference is dark (grazing L and V on opposite sides, where "
                "rough surfaces shadow and mask what a smooth model lights), so the tables give them also over "
                "N.L, N.V >= 0.2, and as an absolute error in units of a Lambertian of the same albedo, "
                "u = |kernel - reference| / (albedo / pi).\n\n");
    fprintf(md, "References (the material each kernel is meant to approximate):\n\n");
    for (rf = 0; rf < NREF; rf++)
        fprintf(md, "- **%s**: %s.\n", ref_name[rf], ref_desc[rf]);
    fprintf(md, "\nWhy each kernel's material: ");
    for (k = 0; k < NKERN; k++)
        fprintf(md, "%s: %s. ", kern[k].name, kern[k].why);
    fprintf(md, "\n\n## Summary (every alpha and albedo; oracle, the f32 kernels' maxima beside)\n\n");
    fprintf(md, "Where: alpha, N.L, N.V, phi, albedo.\n\n");
    fprintf(md, "| kernel | against | max abs e (sigma), where | mean abs e (noise) | N.L, N.V >= 0.2: max abs e, where | "
                "mean | max u (sigma), where; mean u | f32 max abs e | f32_fast max abs e |\n"
                "|---|---|---|---|---|---|---|---|---|\n");
    for (k = 0; k < NKERN; k++)
        md_summary_row(md, k, kern[k].ref);
    for (k = 0; k < NKERN; k++)
        for (rf = 0; rf < NREF; rf++)
            if (rf != kern[k].ref)
                md_summary_row(md, k, rf);
    md_per_alpha(md, 0);
    md_per_alpha(md, 1);
    fprintf(md, "\n## Contract lines (paste beside each kernel in include/facet.h)\n\n```\n");
    for (k = 0; k < NKERN; k++) {
        const agg *g = &A[k][0][kern[k].ref][0][NR - 1][NA - 1], *g1 = &A[k][0][kern[k].ref][1][NR - 1][NA - 1];
        char b1[96], b2[32], b3[32], b4[96], b5[32], b6[96];
        fig(b1, sizeof b1, g->max, g->sig_at_max);
        pct(b2, sizeof b2, g->sum / g->n);
        pct(b3, sizeof b3, g->sumsig / g->n);
        fig(b4, sizeof b4, g1->max, g1->sig_at_max);
        pct(b5, sizeof b5, g1->sum / g1->n);
        fig(b6, sizeof b6, g->umax, g->usig);
        fprintf(md, "%s:\n * Model error (against the Smith-GGX microsurface simulation of %s,\n"
                    " * bench/microsurface; alpha in [2^-10, 1], albedo in [0.25, 1]): relative,\n"
                    " * N.L, N.V in [0.02, 1]: max %s at alpha %g, N.L %g, N.V %g,\n"
                    " * phi %g, albedo %g, mean %s (noise %s); N.L, N.V in [0.2, 1]: max %s,\n"
                    " * mean %s; absolute, in units of albedo / pi: max %s.\n",
                kern[k].name, ref_name[kern[k].ref], b1, g->at_a, g->at_nl, g->at_nv, g->at_phi, g->at_rho, b2, b3, b4,
                b5, b6);
    }
    fprintf(md, "```\n");
    fclose(md);
    for (rf = 0; rf < NREF; rf++)
        msim_table_free(&tab[rf]);
    printf("microsurface error: wrote %s/model_error.tsv and model_error.md\n", dir);
    return 0;
}

/* ---- Hammon's fit, refitted ---------------------------------------------- */
#define NP 5 /* rough a, b (facing (a - b facing)), c (c + N.H), smooth s, multi m */
static const double hammon_pub[NP] = {0.9, 0.4, 0.5, 1.05, 0.1159};
static const char *const pname[NP] = {"p0 = 0.9 (rough: facing (0.9 - 0.4 facing))", "p1 = 0.4",
                                      "p2 = 0.5 (rough: (0.5 + N.H) / N.H)", "p3 = 1.05 (smooth)",
                                      "p4 = 0.1159 (multi)"};

static double hammon_model(const double *p, double nl, double nv, double lv, double a, double rho)
{
    double facing = 0.5 + 0.5 * lv, noh = facet_oracle_noh_from_dots(nl, nv, lv);
    double rough = facing * (p[0] - p[1] * facing) * (p[2] + noh) / noh;
    double sl = 1.0 - pow(1.0 - nl, 5.0), sv = 1.0 - pow(1.0 - nv, 5.0);
    double smooth = p[3] * sl * sv, single = ((1.0 - a) * smooth + a * rough) / PI;
    return rho * (single + rho * p[4] * a);
}

/* the points the fit sees: every table row of Hammon's material, each albedo */
typedef struct {
    double nl, nv, lv, phi, a, rho, ref, se;
    double facing, inv_nh, ss; /* precomputed: 0.5 + 0.5 L.V, 1 / N.H, the smooth shape */
} fpt;
static fpt *pts;
static int npts;

/* hammon_model from the precomputed parts (the same value) */
static double model_pt(const double *p, const fpt *q)
{
    double rough = q->facing * (p[0] - p[1] * q->facing) * (p[2] * q->inv_nh + 1.0);
    double single = ((1.0 - q->a) * p[3] * q->ss + q->a * rough) / PI;
    return q->rho * (single + q->rho * p[4] * q->a);
}

/* max and mean |e| over the whole grid ([0], [1]) and over N.L, N.V >= 0.2 ([2], [3]) */
static void fit_errors(const double *p, double *err)
{
    int i, n1 = 0;
    double m = 0, s = 0, m1 = 0, s1 = 0;
    for (i = 0; i < npts; i++) {
        double e = fabs(model_pt(p, &pts[i]) / pts[i].ref - 1.0);
        if (e > m)
            m = e;
        s += e;
        if (pts[i].nl >= COS_D1 && pts[i].nv >= COS_D1) {
            if (e > m1)
                m1 = e;
            s1 += e;
            n1++;
        }
    }
    err[0] = m;
    err[1] = s / npts;
    err[2] = m1;
    err[3] = s1 / n1;
}

#define NFIT 3
static const char *const fit_name[NFIT] = {"min max", "min mean", "min max, N.L, N.V >= 0.2"};
static const int fit_obj[NFIT] = {0, 1, 2}; /* which of fit_errors' figures each minimises */
static int fit_mode;
static double objective(const double *p)
{
    double err[4];
    fit_errors(p, err);
    return err[fit_obj[fit_mode]];
}

/* Nelder-Mead over n <= 8 parameters of f, restarted from its best point
 * with a halved step until it stops improving (deterministic) */
static void nelder_mead(double (*f)(const double *), double *p, int np, double scale)
{
    int restart;
    double best = f(p);
    for (restart = 0; restart < 30; restart++) {
        double x[9][8], fx[9], prev = best;
        int i, j, it;
        for (i = 0; i <= np; i++) {
            memcpy(x[i], p, sizeof x[i]);
            if (i)
                x[i][i - 1] += scale * (fabs(p[i - 1]) > 1e-3 ? p[i - 1] : 0.1);
            fx[i] = f(x[i]);
        }
        for (it = 0; it < 5000; it++) {
            int hi = 0, lo = 0, nh;
            double c[8] = {0}, xr[8], fr;
            for (i = 0; i <= np; i++) {
                if (fx[i] > fx[hi])
                    hi = i;
                if (fx[i] < fx[lo])
                    lo = i;
            }
            if (fx[hi] - fx[lo] <= 1e-12 * fx[lo])
                break;
            nh = lo; /* the second highest */
            for (i = 0; i <= np; i++)
                if (i != hi && fx[i] > fx[nh])
                    nh = i;
            for (i = 0; i <= np; i++)
                if (i != hi)
                    for (j = 0; j < np; j++)
                        c[j] += x[i][j] / np;
            for (j = 0; j < np; j++)
                xr[j] = c[j] + (c[j] - x[hi][j]);
            fr = f(xr);
            if (fr < fx[lo]) {
                double xe[8], fe;
                for (j = 0; j < np; j++)
                    xe[j] = c[j] + 2.0 * (c[j] - x[hi][j]);
                fe = f(xe);
                if (fe < fr) {
                    memcpy(x[hi], xe, sizeof xe);
                    fx[hi] = fe;
                } else {
                    memcpy(x[hi], xr, sizeof xr);
                    fx[hi] = fr;
                }
            } else if (fr < fx[nh]) {
                memcpy(x[hi], xr, sizeof xr);
                fx[hi] = fr;
            } else {
                double xc[8], fc;
                for (j = 0; j < np; j++)
                    xc[j] = c[j] + 0.5 * (x[hi][j] - c[j]);
                fc = f(xc);
                if (fc < fx[hi]) {
                    memcpy(x[hi], xc, sizeof xc);
                    fx[hi] = fc;
                } else {
                    for (i = 0; i <= np; i++)
                        if (i != lo) {
                            for (j = 0; j < np; j++)
                                x[i][j] = x[lo][j] + 0.5 * (x[i][j] - x[lo][j]);
                            fx[i] = f(x[i]);
                        }
                }
            }
        }
        for (i = 0; i <= np; i++)
            if (fx[i] < best) {
                best = fx[i];
                memcpy(p, x[i], np * sizeof *p);
            }
        if (prev - best <= 1e-9 * best)
            break;
        scale *= 0.5;
    }
}

/* the model's errors per alpha (and over N.L, N.V >= 0.2), with the
 * simulation's noise at the maximum */
static void per_alpha(FILE *md, const double *p, const char *label)
{
    int ia, i, d;
    fprintf(md, "\n%s, per alpha:\n\n| alpha | max abs e (sigma) | at (N.L, N.V, phi, albedo) | mean abs e | "
                "N.L, N.V >= 0.2: max abs e | mean abs e |\n|---|---|---|---|---|---|\n",
            label);
    for (ia = 0; ia <= MSIM_NALPHA; ia++) {
        double mx[2] = {-1, -1}, sig[2] = {0, 0}, s[2] = {0, 0}, at[4] = {0};
        int n[2] = {0, 0};
        char b[2][96], m[2][32];
        for (i = 0; i < npts; i++) {
            double kv, e;
            if (ia < MSIM_NALPHA && pts[i].a != msim_grid_alpha[ia])
                continue;
            kv = model_pt(p, &pts[i]);
            e = fabs(kv / pts[i].ref - 1.0);
            for (d = 0; d < 2; d++) {
                if (d && !(pts[i].nl >= COS_D1 && pts[i].nv >= COS_D1))
                    continue;
                if (e > mx[d]) {
                    mx[d] = e;
                    sig[d] = kv / pts[i].ref * pts[i].se / pts[i].ref;
                    if (!d) {
                        at[0] = pts[i].nl;
                        at[1] = pts[i].nv;
                        at[2] = pts[i].phi;
                        at[3] = pts[i].rho;
                    }
                }
                s[d] += e;
                n[d]++;
            }
        }
        for (d = 0; d < 2; d++) {
            fig(b[d], sizeof b[d], mx[d], sig[d]);
            pct(m[d], sizeof m[d], s[d] / n[d]);
        }
        if (ia < MSIM_NALPHA)
            fprintf(md, "| %g ", msim_grid_alpha[ia]);
        else
            fprintf(md, "| all ");
        fprintf(md, "| %s | %g, %g, %g, %g | %s | %s | %s |\n", b[0], at[0], at[1], at[2], at[3], m[0], b[1], m[1]);
    }
}

int msim_cmd_refit(const char *dir)
{
    FILE *md;
    int i, ir, j;
    double pf[NFIT][NP], e[NFIT + 1][4];
    if (load_refs(dir))
        return 2;
    pts = calloc((size_t)tab[REF_HAMMON].n * NRHO, sizeof *pts);
    npts = 0;
    for (i = 0; i < tab[REF_HAMMON].n; i++)
        for (ir = 0; ir < NRHO; ir++) {
            const msim_row *r = &tab[REF_HAMMON].row[i];
            fpt *q = &pts[npts];
            ref_value(REF_HAMMON, r, ir, &q->ref, &q->se);
            if (!(q->ref > 0.0))
                continue;
            q->nl = r->nl;
            q->nv = r->nv;
            q->lv = r->lv;
            q->phi = r->phi;
            q->a = r->alpha;
            q->rho = msim_rho[ir];
            q->facing = 0.5 + 0.5 * r->lv;
            q->inv_nh = 1.0 / facet_oracle_noh_from_dots(r->nl, r->nv, r->lv);
            q->ss = (1.0 - pow(1.0 - r->nl, 5.0)) * (1.0 - pow(1.0 - r->nv, 5.0));
            npts++;
        }
    /* the parametrised model with Hammon's constants is facet's oracle of diffuse_hammon */
    for (i = 0; i < npts; i++) {
        double a = model_pt(hammon_pub, &pts[i]);
        double b = hammon_model(hammon_pub, pts[i].nl, pts[i].nv, pts[i].lv, pts[i].a, pts[i].rho);
        double c = facet_oracle_diffuse_hammon(pts[i].nl, pts[i].nv, pts[i].lv, pts[i].a, pts[i].rho);
        if (fabs(a - c) > 1e-12 * c || fabs(b - c) > 1e-12 * c) {
            fprintf(stderr, "microsurface refit: the model (%.17g, %.17g) is not the oracle (%.17g) at point %d\n", a,
                    b, c, i);
            return 2;
        }
    }
    for (j = 0; j < NFIT; j++) {
        memcpy(pf[j], hammon_pub, sizeof pf[j]);
        fit_mode = j;
        nelder_mead(objective, pf[j], NP, 0.2);
        fit_errors(pf[j], e[j + 1]);
    }
    fit_errors(hammon_pub, e[0]);
    md = open_out(dir, "hammon_refit.md");
    if (!md)
        return 2;
    fprintf(md, "# Hammon's diffuse fit, refitted to the microsurface reference\n\n");
    fprintf(md, "Made by `build/microsurface/microsurface refit --dir bench/microsurface` from `ref_hammon.tsv` "
                "(the diffuse part of Hammon's material / (1 - F0), README.md). The model is diffuse_hammon's "
                "formula with its five constants free:\n\n"
                "    facing = 0.5 + 0.5 L.V\n    rough  = facing (p0 - p1 facing) (p2 + N.H) / N.H\n"
                "    smooth = p3 (1 - (1 - N.L)^5) (1 - (1 - N.V)^5)\n    single = lerp(smooth, rough, alpha) / pi\n"
                "    result = albedo (single + albedo p4 alpha)\n\n"
                "(the same operations as the kernel: a refit changes constants only; with Hammon's constants it "
                "equals facet_oracle_diffuse_hammon at every point, checked). Fitted over the tables' grid and "
                "albedo in {1, 0.75, 0.5, 0.25} (%d points) by Nelder-Mead from Hammon's constants, minimising "
                "the maximum relative error, the mean, and the maximum over N.L, N.V >= 0.2.\n\n",
            npts);
    fprintf(md, "| constant | Hammon |");
    for (j = 0; j < NFIT; j++)
        fprintf(md, " refit (%s) |", fit_name[j]);
    md_rule(md, NFIT + 1);
    for (i = 0; i < NP; i++) {
        fprintf(md, "| %s | %.4g |", pname[i], hammon_pub[i]);
        for (j = 0; j < NFIT; j++)
            fprintf(md, " %.4f |", pf[j][i]);
        fprintf(md, "\n");
    }
    {
        static const char *const row[4] = {"max abs e", "mean abs e", "N.L, N.V >= 0.2: max abs e",
                                           "N.L, N.V >= 0.2: mean abs e"};
        int r;
        for (r = 0; r < 4; r++) {
            fprintf(md, "| **%s** |", row[r]);
            for (j = 0; j <= NFIT; j++) {
                char b[32];
                pct(b, sizeof b, e[j][r]);
                fprintf(md, " %s |", b);
            }
            fprintf(md, "\n");
        }
    }
    per_alpha(md, hammon_pub, "Hammon's constants (diffuse_hammon)");
    for (j = 0; j < NFIT; j++) {
        char label[96];
        snprintf(label, sizeof label, "Refit (%s)", fit_name[j]);
        per_alpha(md, pf[j], label);
    }
    fclose(md);
    printf("microsurface refit: max / mean / max (cos >= 0.2) / mean (cos >= 0.2): Hammon %.4f %.4f %.4f %.4f\n",
           e[0][0], e[0][1], e[0][2], e[0][3]);
    for (j = 0; j < NFIT; j++) {
        printf("  refit (%s): %.4f %.4f %.4f %.4f, constants", fit_name[j], e[j + 1][0], e[j + 1][1], e[j + 1][2],
               e[j + 1][3]);
        for (i = 0; i < NP; i++)
            printf(" %.5f", pf[j][i]);
        printf("\n");
    }
    free(pts);
    for (i = 0; i < NREF; i++)
        msim_table_free(&tab[i]);
    return 0;
}

/* ---- single-scattering GGX's energy loss --------------------------------- */
/* E(mu, alpha): the directional albedo of D G2 / (4 N.L N.V) (F = 1,
 * height-correlated G2), by quadrature over the half vector in GGX's own
 * measure: with tan^2 theta_h = alpha^2 u / (1 - u), D(h) h_z dw_h = du dphi / (2 pi),
 * and dw_o = 4 (o.h) dw_h, so E = int G2 (i.h) / (mu h_z) du dphi / (2 pi) over
 * the h that reflect i above the horizon.  (i.h) / h_z grows like
 * (1 - u)^-1/2 (tan theta_h) near u = 1, so u in [1/2, 1] is integrated in
 * s = sqrt(1 - u) (du = 2 s ds), u in [0, 1/2] in u; midpoint rules, nu
 * nodes in u and nphi in phi over [0, pi] (twice by symmetry).  At nu =
 * 2048 it agrees with 4096 to 1e-6 over the tables' grid; 1 - E(1, 1) =
 * ln 2 in closed form (D = 1 / pi), which msim_cmd_energy checks. */
static double e_single(double mu, double alpha, int nu, int nphi)
{
    double sx = sqrt(fmax(0.0, 1.0 - mu * mu)), sum = 0.0, s1 = sqrt(0.5);
    int i, j, half = nu / 2;
    for (i = 0; i < nu; i++) {
        double u, w, t2, hz, hs;
        if (i < half) {
            u = 0.5 * (i + 0.5) / half;
            w = 0.5 / half;
        } else {
            double s = s1 * (i - half + 0.5) / half;
            u = 1.0 - s * s;
            w = 2.0 * s * s1 / half;
        }
        t2 = alpha * alpha * u / (1.0 - u);
        hz = 1.0 / sqrt(1.0 + t2);
        hs = sqrt(t2) * hz;
        for (j = 0; j < nphi; j++) {
            double ph = PI * (j + 0.5) / nphi, hx = hs * cos(ph);
            double ih = sx * hx + mu * hz, oz;
            if (ih <= 0.0)
                continue;
            oz = 2.0 * ih * hz - mu; /* (2 (i.h) h - i)_z */
            if (oz <= 0.0)
                continue;
            sum += w * facet_oracle_smith_g2(mu, oz, alpha) * ih / (mu * hz);
        }
    }
    return sum / nphi;
}

/* The compensation's pieces (README.md, "spec_loss"): the lost energy
 *   loss(mu, a) = a mu (c0 + a (c1 + c5 mu + c6 a)) / (mu (mu + c3 a) + a^2 (c4 + c2 mu))
 * and its cosine-weighted hemispherical mean, 2 int loss mu dmu, as
 *   avg(a) = a (q0 + a (q1 + q2 a)) / (1 + q3 a)
 * (the fitted loss falls like a / mu away from grazing at small a, so its
 * mean is linear in a there) */
#define NC 7
#define NQ 4
static double loss_fit(const double *c, double mu, double a)
{
    double n = a * mu * (c[0] + a * (c[1] + c[5] * mu + c[6] * a));
    double d = mu * (mu + c[3] * a) + a * a * (c[4] + c[2] * mu);
    return n / d;
}
static double avg_fit(const double *q, double a)
{
    return a * (q[0] + a * (q[1] + q[2] * a)) / (1.0 + q[3] * a);
}
/* 2 int_0^1 loss(mu) mu dmu of the fitted loss (Simpson, 2000 intervals) */
static double avg_of_fit(const double *c, double a)
{
    int i, n = 2000;
    double s = 0.0;
    for (i = 0; i <= n; i++) {
        double mu = (double)i / n, w = (i == 0 || i == n) ? 1.0 : (i & 1) ? 4.0 : 2.0;
        s += w * (mu > 0.0 ? loss_fit(c, mu, a) * mu : 0.0);
    }
    return 2.0 * s / (3.0 * n);
}

#define EFA 24 /* the fit's grid: alpha 2^-10 and i / 23; mu from 0.02 to 1 */
#define EFM 24
static double efa[EFA], efm[EFM], eloss[EFA][EFM], eavg[EFA];
static double obj_loss(const double *c)
{
    double m = 0.0;
    int i, j;
    for (i = 0; i < EFA; i++)
        for (j = 0; j < EFM; j++) {
            double e = fabs(loss_fit(c, efm[j], efa[i]) - eloss[i][j]);
            if (!(e <= m)) /* NaN counts as worst */
                m = isnan(e) ? 1e30 : e;
        }
    return m;
}
static double obj_avg(const double *q)
{
    double m = 0.0;
    int i;
    for (i = 1; i < EFA; i++) {
        double e = fabs(avg_fit(q, efa[i]) / eavg[i] - 1.0);
        if (!(e <= m))
            m = isnan(e) ? 1e30 : e;
    }
    return m;
}

/* the compensation lobe (Kulla and Conty 2017's form with the fits):
 * loss(N.L) loss(N.V) / (pi avg) */
static double ms_lobe(const double *c, const double *q, double nl, double nv, double a)
{
    double g = avg_fit(q, a);
    return g > 0.0 ? loss_fit(c, nl, a) * loss_fit(c, nv, a) / (PI * g) : 0.0;
}

/* albedo_<mat>.tsv rows: alpha, nl and per part mean, se */
typedef struct {
    double a, nl, v[MSIM_NACC], se[MSIM_NACC];
} alb_row;
static int read_albedo(const char *path, alb_row *rows, int max)
{
    FILE *f = fopen(path, "r");
    static char line[1 << 14];
    int n = 0;
    if (!f)
        return -1;
    while (fgets(line, sizeof line, f) && n < max) {
        char *p = line, *e;
        int c;
        if (line[0] == '#' || !strncmp(line, "alpha", 5))
            continue;
        rows[n].a = strtod(p, &e);
        rows[n].nl = strtod(e, &e);
        strtod(e, &e); /* paths, events per path, cut */
        strtod(e, &e);
        strtod(e, &e);
        for (c = 0; c < MSIM_NACC; c++) {
            rows[n].v[c] = strtod(e, &e);
            rows[n].se[c] = strtod(e, &e);
        }
        n++;
    }
    fclose(f);
    return n;
}

static void svg_plot(const char *path, const double *c, const alb_row *alb, int nalb)
{
    static const double as[5] = {0.125, 0.25, 0.5, 0.75, 1.0};
    static const char *const col[5] = {"#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#444444"};
    FILE *f = fopen(path, "w");
    int W = 640, H = 420, x0 = 60, y0 = 370, pw = 540, ph = 330, i, k;
    if (!f)
        return;
    fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" font-family=\"sans-serif\" "
               "font-size=\"12\">\n<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n", W, H, W, H);
    fprintf(f, "<text x=\"%d\" y=\"20\" font-size=\"14\">Energy single-scattering GGX loses, 1 - E(N.V, alpha) "
               "(F = 1, height-correlated Smith)</text>\n", x0);
    for (i = 0; i <= 10; i++) { /* axes: N.V 0..1, loss 0..0.7 */
        double x = x0 + pw * i / 10.0, y = y0 - ph * i / 10.0;
        fprintf(f, "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"#ddd\"/>\n", x, y0, x, y0 - ph);
        fprintf(f, "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%.1f</text>\n", x, y0 + 15, i / 10.0);
        if (i <= 7) {
            y = y0 - ph * i / 7.0;
            fprintf(f, "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#ddd\"/>\n", x0, y, x0 + pw, y);
            fprintf(f, "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%.1f</text>\n", x0 - 5, y + 4, i / 10.0);
        }
    }
    fprintf(f, "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">N.V</text>\n", x0 + pw / 2, y0 + 32);
    fprintf(f, "<text x=\"15\" y=\"%d\" transform=\"rotate(-90 15 %d)\" text-anchor=\"middle\">1 - E</text>\n",
            y0 - ph / 2, y0 - ph / 2);
    for (k = 0; k < 5; k++) {
        fprintf(f, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"2\" points=\"", col[k]);
        for (i = 0; i <= 60; i++) {
            double mu = 0.01 + 0.99 * i / 60.0, l = 1.0 - e_single(mu, as[k], 256, 128);
            fprintf(f, "%.1f,%.1f ", x0 + pw * mu, y0 - ph * l / 0.7);
        }
        fprintf(f, "\"/>\n<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\" stroke-dasharray=\"5,4\" points=\"", col[k]);
        for (i = 0; i <= 60; i++) {
            double mu = 0.01 + 0.99 * i / 60.0, l = loss_fit(c, mu, as[k]);
            fprintf(f, "%.1f,%.1f ", x0 + pw * mu, y0 - ph * l / 0.7);
        }
        fprintf(f, "\"/>\n");
        for (i = 0; i < nalb; i++)
            if (alb[i].a == as[k])
                fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3\" fill=\"%s\"/>\n", x0 + pw * alb[i].nl,
                        y0 - ph * alb[i].v[MSIM_MULTI] / 0.7, col[k]);
        fprintf(f, "<text x=\"%d\" y=\"%d\" fill=\"%s\">alpha %g</text>\n", x0 + 10, 40 + 15 * k, col[k], as[k]);
    }
    fprintf(f, "<text x=\"%d\" y=\"%d\">lines: quadrature; dashed: the fit; dots: the simulation's multiple "
               "scattering (white mirror facets)</text>\n", x0 + 110, 40);
    fprintf(f, "</svg>\n");
    fclose(f);
}

int msim_cmd_energy(const char *dir)
{
    static alb_row alb[MSIM_NALPHA * MSIM_NCOS + 8];
    char path[1024];
    double c[NC] = {0.15521, -0.08412, 2.01648, -0.06236, 0.44257, 1.04005, 1.31160}, q[NQ] = {0.3, 1.0, 0.0, 1.0};
    static double equad[MSIM_NALPHA * MSIM_NCOS + 8];
    double zmax = 0.0, dmax = 0.0, emax = 0.0, e_at[2] = {0, 0}, ln2;
    int nalb, i, j, ia;
    msim_table mir;
    FILE *t, *md;
    snprintf(path, sizeof path, "%s/albedo_mirror.tsv", dir);
    nalb = read_albedo(path, alb, MSIM_NALPHA * MSIM_NCOS + 8);
    snprintf(path, sizeof path, "%s/ref_mirror.tsv", dir);
    if (nalb <= 0 || msim_table_read(&mir, path)) {
        fprintf(stderr, "microsurface energy: cannot read %s/albedo_mirror.tsv or ref_mirror.tsv\n", dir);
        return 2;
    }
    ln2 = 1.0 - e_single(1.0, 1.0, 2048, 1024);
    if (fabs(ln2 - log(2.0)) > 1e-6) {
        fprintf(stderr, "microsurface energy: quadrature 1 - E(1, 1) = %.6f, want ln 2\n", ln2);
        return 2;
    }
    /* the fit: loss on a 24 x 24 grid by quadrature, then its hemispherical mean */
    for (i = 0; i < EFA; i++)
        efa[i] = i == 0 ? 0x1p-10 : (double)i / (EFA - 1);
    for (j = 0; j < EFM; j++)
        efm[j] = 0.02 + 0.98 * pow((double)j / (EFM - 1), 1.5);
    for (i = 0; i < EFA; i++)
        for (j = 0; j < EFM; j++)
            eloss[i][j] = 1.0 - e_single(efm[j], efa[i], 1024, 512);
    nelder_mead(obj_loss, c, NC, 0.5);
    nelder_mead(obj_loss, c, NC, 0.1);
    for (i = 0; i < EFA; i++)
        eavg[i] = avg_of_fit(c, efa[i]);
    nelder_mead(obj_avg, q, NQ, 0.5);
    nelder_mead(obj_avg, q, NQ, 0.1);

    t = open_out(dir, "spec_loss.tsv");
    md = open_out(dir, "spec_loss.md");
    if (!t || !md)
        return 2;
    fprintf(t, "# the energy single-scattering GGX loses, 1 - E(N.V, alpha) (F = 1, height-correlated Smith): by "
               "quadrature (e_single in msim_analyse.c) and by the simulation of white mirror facets (albedo_mirror.tsv: "
               "single = E, multi = the energy multiple scattering returns); fit = the compensation's loss(N.V, alpha); "
               "made by microsurface energy\n");
    fprintf(t, "alpha\tnv\tE_quadrature\tloss_quadrature\tsim_single\tse_single\tsim_multi\tse_multi\tsim_total\tse_total\t"
               "loss_fit\n");
    for (i = 0; i < nalb; i++) {
        double e = e_single(alb[i].nl, alb[i].a, 2048, 1024), z, lf = loss_fit(c, alb[i].nl, alb[i].a);
        equad[i] = e;
        /* where the loss is below ~1e-4 the paths that carry it are too rare for
         * the simulation's standard error to see (a few in 2e6) */
        z = fabs(alb[i].v[MSIM_SINGLE] - e) / (alb[i].se[MSIM_SINGLE] + 1e-12);
        if (1.0 - e >= 1e-4 && z > zmax)
            zmax = z;
        if (fabs(alb[i].v[MSIM_SINGLE] - e) > dmax)
            dmax = fabs(alb[i].v[MSIM_SINGLE] - e);
        if (fabs(lf - (1.0 - e)) > emax) {
            emax = fabs(lf - (1.0 - e));
            e_at[0] = alb[i].a;
            e_at[1] = alb[i].nl;
        }
        fprintf(t, "%.17g\t%.17g\t%.7f\t%.7f\t%.7f\t%.2e\t%.7f\t%.2e\t%.7f\t%.2e\t%.7f\n", alb[i].a, alb[i].nl, e, 1.0 - e,
                alb[i].v[MSIM_SINGLE], alb[i].se[MSIM_SINGLE], alb[i].v[MSIM_MULTI], alb[i].se[MSIM_MULTI],
                alb[i].v[MSIM_TOTAL], alb[i].se[MSIM_TOTAL], lf);
    }
    fclose(t);
    snprintf(path, sizeof path, "%s/spec_loss.svg", dir);
    svg_plot(path, c, alb, nalb);

    fprintf(md, "# Multiple-scattering specular: the energy single-scattering GGX loses\n\n");
    fprintf(md, "Made by `build/microsurface/microsurface energy --dir bench/microsurface`. E(N.V, alpha) is the "
                "directional albedo of D G2 / (4 N.L N.V) with F = 1 and height-correlated Smith G2, by quadrature "
                "over the half vector (checked: 1 - E(1, 1) = ln 2 in closed form, quadrature %.6f); the "
                "simulation of white mirror facets (`albedo_mirror.tsv`) gives the same E as its single-bounce "
                "albedo (largest difference %.1f standard errors over the tables' %d points where 1 - E >= 1e-4; "
                "%.1e absolute anywhere) and 1 - E as the "
                "energy its multiple bounces return, so a white GGX conductor loses exactly 1 - E to single "
                "scattering. Figure: `spec_loss.svg`; all figures: `spec_loss.tsv`.\n\n", ln2, zmax, nalb, dmax);
    fprintf(md, "## 1 - E (quadrature), with the simulation's multiple-scattering albedo beside (+- its standard error)\n\n| alpha |");
    for (j = 0; j < MSIM_NCOS; j++)
        fprintf(md, " N.V %g |", msim_grid_cos[j]);
    md_rule(md, MSIM_NCOS);
    for (ia = 0; ia < MSIM_NALPHA; ia++) {
        fprintf(md, "| %g |", msim_grid_alpha[ia]);
        for (j = 0; j < MSIM_NCOS; j++)
            for (i = 0; i < nalb; i++)
                if (alb[i].a == msim_grid_alpha[ia] && alb[i].nl == msim_grid_cos[j])
                    fprintf(md, " %.4f (sim %.4f +- %.4f) |", 1.0 - equad[i],
                            alb[i].v[MSIM_MULTI], alb[i].se[MSIM_MULTI]);
        fprintf(md, "\n");
    }
    /* the compensation: energy and lobe against the simulation, per alpha */
    {
        int d;
        fprintf(md, "\n## A cheap compensation term\n\nFitted here (Nelder-Mead, minimising the largest absolute "
                    "error of the loss over a 24 x 24 grid of alpha in [2^-10, 1] and N.V in [0.02, 1], then the "
                    "largest relative error of its mean over alpha):\n\n```\n"
                    "loss(x, a) = a x (c0 + a (c1 + c5 x + c6 a)) / (x (x + c3 a) + a^2 (c4 + c2 x))   ~ 1 - E(x, a)\n"
                    "avg(a)     = a (q0 + a (q1 + q2 a)) / (1 + q3 a)                             ~ 2 int loss(x, a) x dx\n"
                    "f_ms(N.L, N.V, a) = loss(N.L, a) loss(N.V, a) / (pi avg(a))\n```\n\n"
                    "the lobe of Kulla and Conty (2017) with both of its tables replaced by the two rationals: its "
                    "own directional albedo is loss(N.L) times (the mean of loss) / avg, so added to the "
                    "single-scattering GGX BRDF of a white conductor it returns the lost energy up to the fits' "
                    "errors. Constants: c = {");
        md_list(md, "%.6g", c, NC);
        fprintf(md, "}, q = {");
        md_list(md, "%.6g", q, NQ);
        fprintf(md, "}. Cost: the two losses and avg share one reciprocal (of the product of their three "
                    "denominators): about 30 operations and 1 reciprocal.\n\n");
        fprintf(md, "- loss vs 1 - E (absolute): max %.4f at alpha %g, N.V %g over the tables' grid (%.4f over the "
                    "fit's own grid).\n", emax, e_at[0], e_at[1], obj_loss(c));
        fprintf(md, "- avg vs the mean of loss (relative): max %.4f.\n\n", obj_avg(q));
        fprintf(md, "Per alpha: the white furnace with the compensation (E + the lobe's albedo, F = 1; max "
                    "|1 - total| over N.V), and the lobe against the simulated multiple-scattering BRDF "
                    "(`ref_mirror.tsv`, part multi; relative e with sigma, and absolute u in units of 1 / pi):\n\n"
                    "| alpha | white furnace max abs error | lobe max abs e (sigma) at (N.L, N.V, phi) | mean abs e | "
                    "N.L, N.V >= 0.2: max abs e | mean | max u (sigma) |\n|---|---|---|---|---|---|---|\n");
        for (ia = 0; ia <= MSIM_NALPHA; ia++) {
            double fw = 0.0, lmax[2] = {0, 0}, lsig[2] = {0, 0}, lsum[2] = {0, 0}, lat[3] = {0, 0, 0}, umax = 0, usig = 0;
            int ln[2] = {0, 0};
            char b1[96], b2[96], b3[32], b4[32], b5[96];
            for (i = 0; i < nalb; i++) {
                double a = alb[i].a, mu = alb[i].nl, tot;
                if (ia < MSIM_NALPHA && a != msim_grid_alpha[ia])
                    continue;
                tot = equad[i] + loss_fit(c, mu, a) * avg_of_fit(c, a) / fmax(avg_fit(q, a), 1e-300);
                if (fabs(tot - 1.0) > fw)
                    fw = fabs(tot - 1.0);
            }
            for (i = 0; i < mir.n; i++) {
                const msim_row *r = &mir.row[i];
                double v = r->val[MSIM_MULTI], se = r->se[MSIM_MULTI], k, e, sg, u;
                if (!(v > 0.0) || (ia < MSIM_NALPHA && r->alpha != msim_grid_alpha[ia]))
                    continue;
                k = ms_lobe(c, q, r->nl, r->nv, r->alpha);
                e = fabs(k / v - 1.0);
                sg = k / v * se / v;
                u = fabs(k - v) * PI;
                if (u > umax) {
                    umax = u;
                    usig = se * PI;
                }
                for (d = 0; d < 2; d++) {
                    if (d && !(r->nl >= COS_D1 && r->nv >= COS_D1))
                        continue;
                    if (e > lmax[d]) {
                        lmax[d] = e;
                        lsig[d] = sg;
                        if (!d) {
                            lat[0] = r->nl;
                            lat[1] = r->nv;
                            lat[2] = r->phi;
                        }
                    }
                    lsum[d] += e;
                    ln[d]++;
                }
            }
            fig(b1, sizeof b1, lmax[0], lsig[0]);
            fig(b2, sizeof b2, lmax[1], lsig[1]);
            pct(b3, sizeof b3, lsum[0] / (ln[0] ? ln[0] : 1));
            pct(b4, sizeof b4, lsum[1] / (ln[1] ? ln[1] : 1));
            fig(b5, sizeof b5, umax, usig);
            if (ia < MSIM_NALPHA)
                fprintf(md, "| %g ", msim_grid_alpha[ia]);
            else
                fprintf(md, "| all ");
            fprintf(md, "| %.4f | %s at (%g, %g, %g) | %s | %s | %s | %s |\n", fw, b1, lat[0], lat[1], lat[2], b3, b2, b4, b5);
        }
    }
    fclose(md);
    msim_table_free(&mir);
    printf("microsurface energy: wrote %s/spec_loss.tsv, spec_loss.md, spec_loss.svg; loss fit max %.4f, avg fit %.4f\n",
           dir, obj_loss(c), obj_avg(q));
    return 0;
}
