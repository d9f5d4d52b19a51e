/* kernel_facts.c - see kernel_facts.h.  The table (facts[], below the
 * oracles its sweep uses) has one entry per kernel of src/core/kernels.def,
 * in that order; a kernel added to the list without an entry here stops
 * the report (kf_check) and fails tests/suites/60-bench.sh. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "facet/oracle.h"
#include "harness/bench.h"
#include "geom.h"
#include "kernel_facts.h"

/* ---- the double oracles of the model-error sweep ---------------------------
 * An approximation's entry names two oracles as functions of its axes'
 * values x[] (the M2 / M3 wrappers adapt a facet_oracle_* of 2 or 3
 * inputs taken in axis order) and up to three axes (name, low end, high
 * end; the sweep takes half its points log-spaced and half linear on each
 * axis, so both the grazing ends and the middle are dense). */
#define M2(fn) static double m2_##fn(const double *x) { return facet_oracle_##fn(x[0], x[1]); }
#define M3(fn) static double m3_##fn(const double *x) { return facet_oracle_##fn(x[0], x[1], x[2]); }
M3(smith_vis) M3(smith_vis_hammon) M3(smith_vis_joint_approx) M3(smith_vis_fit)
M3(smith_g2) M3(smith_g2_hammon) M3(smith_g2_uncorrelated)
M2(smith_g1) M2(smith_g1_hammon) M2(smith_g1_beckmann) M2(smith_g1_beckmann_exact) M2(smith_g1_schlick_beckmann)
M2(fresnel_schlick) M2(fresnel_schlick_sg) M2(fresnel_cook_torrance)
M3(smith_g1_gtr) M3(smith_g1_gtr_exact)
/* the diffuse and whole-BRDF rows: L.V = N.L N.V (azimuths 90 deg apart), f0 = 0.04, albedo = 0.8 */
static double m_brdf_hammon(const double *x) { return facet_oracle_brdf_hammon(x[0], x[1], x[0] * x[1], x[2], 0.04, 0.8); }
static double m_brdf_exact(const double *x) { return bench_oracle_brdf_exact(x[0], x[1], x[0] * x[1], x[2], 0.04, 0.8); }

/* the classic G terms (no alpha) and Schlick with f90 = 1, on the same
 * geometry: L.V = N.L N.V, N.H and V.H from the identities (geom.c) */
static double m_g_classic(int which, const double *x)
{
    geom g = { 0 };
    double nh, vh;
    g.nl = x[0], g.nv = x[1], g.lv = x[0] * x[1], g.alpha = x[2];
    geom_input(&g, "noh", &nh);
    geom_input(&g, "voh", &vh);
    switch (which) {
    case 0: return facet_oracle_g_implicit(g.nl, g.nv);
    case 1: return facet_oracle_g_neumann(g.nl, g.nv);
    case 2: return facet_oracle_g_cook_torrance(g.nl, g.nv, nh, vh);
    default: return facet_oracle_g_kelemen(g.nl, g.nv, vh);
    }
}
static double m_g_implicit(const double *x) { return m_g_classic(0, x); }
static double m_g_neumann(const double *x) { return m_g_classic(1, x); }
static double m_g_cook_torrance(const double *x) { return m_g_classic(2, x); }
static double m_g_kelemen(const double *x) { return m_g_classic(3, x); }
static double m_fresnel_schlick_f90(const double *x) { return facet_oracle_fresnel_schlick_f90(x[0], 1.0, x[1]); }

#define AX_NL(lo) { "N.L", lo, 1.0 }
#define AX_NV(lo) { "N.V", lo, 1.0 }
#define AX_A { "alpha", 0x1p-10, 1.0 }
#define VIS3 3, { AX_NL(0x1p-8), AX_NV(0x1p-8), AX_A }   /* the fixed-point cos floor, and issue 10's domain */
#define G3 3, { AX_NL(0x1p-12), AX_NV(0x1p-12), AX_A }
#define G1D 2, { AX_NV(0x1p-12), AX_A }
#define FRES 2, { { "f0", 0.02, 0.1 }, { "V.H", 0x1p-10, 1.0 } } /* dielectrics: eta 1.33 .. 1.92 */
#define G1GTR 3, { AX_NV(0x1p-12), AX_A, { "gamma", 0.25, 4.0 } }


/* ---- the table ------------------------------------------------------------- */

enum { T_NONE = -1, T_D, T_G1, T_G1_BECKMANN, T_G2, T_VIS, T_F, T_DIFFUSE, T_BRDF, N_TERMS };
static const struct {
    const char *title;
    int has_reference;
} terms[N_TERMS] = {
    /* D has no exact reference: each variant is its own model (a look, not
     * an approximation); diffuse's is the simulated Smith microsurface of
     * the material each kernel approximates (bench/microsurface) */
    { "D (normal distribution)", 0 },
    { "G1 (masking)", 1 },
    { "G1 for Beckmann's D", 1 },
    { "G2 (masking-shadowing)", 1 },
    { "visibility (G2 / (4 N.L N.V))", 1 },
    { "Fresnel", 1 },
    { "diffuse", 1 },
    { "whole BRDF", 1 },
};
/* the image-space role of each term's kernels (T_BRDF: its own section) */
static const int term_role[N_TERMS] = { KF_ROLE_D, KF_ROLE_G1, KF_ROLE_G1, KF_ROLE_G2, KF_ROLE_VIS, KF_ROLE_F,
                                        KF_ROLE_DIFFUSE, -1 };
static const char *const role_name[] = { "D", "Vis", "G2", "G1", "F", "diffuse" };
static const char *const ref_name[] = { "", "GGX D", "exact height-correlated Smith Vis",
                                        "exact Beckmann G1 (separable)", "exact GTR G1 (separable)",
                                        "exact dielectric Fresnel" };

/* against the exact form of the kernel's term; SIM: against the microsurface
 * simulation of its material (bench/microsurface/model_error.tsv, kf_sim_load) */
enum { OWN, EXACT, APPROX, SIM };

typedef struct fact {
    const char *kernel;
    int term;  /* T_*: the chooser's and the Pareto plots' group */
    int model; /* OWN: a model of its own; EXACT: the term's exact form; APPROX: */
    struct {   /* ... an approximation of it: the model-error sweep's row */
        const char *term, *approx, *exact, *exact_kernel; /* labels; the exact form's kernel or "" */
        double (*f_approx)(const double *x), (*f_exact)(const double *x);
        int n_axes;
        kf_axis axes[3];
    } sweep;
    int peer_exact;   /* its exact form is its peer-vectors rows' (the exact-Vis BRDF peers) */
    const char *note; /* the image-space variants' name note, or NULL */
    int n_variants;   /* drawn in image space (bench/report/image_error.c) */
    struct {
        double gamma; /* 0: the scene's 2 */
        int ref;      /* KF_REF_*: the reference its model error is measured against */
        int is_reference; /* it renders that reference itself */
    } variants[4];
} fact;

/* the exact forms the approximations are measured against */
#define X_VIS "smith_vis (exact, correlated)", "smith_vis"
#define X_G2 "smith_g2 (exact, correlated)", "smith_g2"
#define X_F "fresnel_cook_torrance (exact dielectric)", "fresnel_cook_torrance"
#define NO_SWEEP { 0 }
#define DRAWN(ref) 1, { { 0, ref, 0 } }
#define NOT_DRAWN 0, { { 0, 0, 0 } }

static const fact facts[] = {
    { "noh_from_dots", T_NONE, OWN, NO_SWEEP, 0, NULL, NOT_DRAWN },
    { "loh_from_dots", T_NONE, OWN, NO_SWEEP, 0, NULL, NOT_DRAWN },
    { "fresnel_schlick", T_F, APPROX,
      { "Fresnel", "fresnel_schlick", X_F, m2_fresnel_schlick, m2_fresnel_cook_torrance, FRES },
      0, NULL, DRAWN(KF_REF_FRESNEL) },
    { "fresnel_cook_torrance", T_F, EXACT, NO_SWEEP, 0, NULL, 1, { { 0, KF_REF_FRESNEL, 1 } } },
    { "fresnel_schlick_f90", T_F, APPROX,
      { "Fresnel", "fresnel_schlick_f90 (f90 = 1)", X_F, m_fresnel_schlick_f90, m2_fresnel_cook_torrance, FRES },
      0, "f90 = 1", DRAWN(KF_REF_FRESNEL) },
    { "fresnel_schlick_sg", T_F, APPROX,
      { "Fresnel", "fresnel_schlick_sg (spherical Gaussian)", X_F, m2_fresnel_schlick_sg, m2_fresnel_cook_torrance,
        FRES },
      0, NULL, DRAWN(KF_REF_FRESNEL) },
    { "ggx_d", T_D, OWN, NO_SWEEP, 0, NULL, DRAWN(KF_REF_NONE) },
    { "blinn_phong_d", T_D, OWN, NO_SWEEP, 0, NULL, DRAWN(KF_REF_NONE) },
    { "beckmann_d", T_D, OWN, NO_SWEEP, 0, NULL, DRAWN(KF_REF_NONE) },
    { "ggx_aniso_d", T_D, OWN, NO_SWEEP, 0, "alpha_y = alpha/2", DRAWN(KF_REF_NONE) },
    /* at gamma 2 GTR is GGX */
    { "gtr_d", T_D, OWN, NO_SWEEP, 0, NULL,
      4, { { 1, KF_REF_NONE, 0 }, { 1.5, KF_REF_NONE, 0 }, { 2, KF_REF_GGX_D, 0 }, { 3, KF_REF_NONE, 0 } } },
    { "smith_g1", T_G1, EXACT, NO_SWEEP, 0, NULL, DRAWN(KF_REF_VIS) },
    { "smith_g2", T_G2, EXACT, NO_SWEEP, 0, NULL, 1, { { 0, KF_REF_VIS, 1 } } },
    { "smith_g2_uncorrelated", T_G2, APPROX,
      { "G2 correlation", "smith_g2_uncorrelated", "smith_g2 (correlated)", "smith_g2", m3_smith_g2_uncorrelated,
        m3_smith_g2, G3 },
      0, NULL, DRAWN(KF_REF_VIS) },
    { "smith_vis", T_VIS, EXACT, NO_SWEEP, 0, NULL, 1, { { 0, KF_REF_VIS, 1 } } },
    { "smith_g1_hammon", T_G1, APPROX,
      { "G1", "smith_g1_hammon (Schlick-GGX k = a/2)", "smith_g1 (exact)", "smith_g1", m2_smith_g1_hammon,
        m2_smith_g1, G1D },
      0, NULL, DRAWN(KF_REF_VIS) },
    /* the exact GTR G1 (a quadrature) is drawn at one gamma */
    { "smith_g1_gtr", T_G1, APPROX,
      { "G1 GTR", "smith_g1_gtr (Dimov: closed forms, cubic in gamma)", "GTR G1 by quadrature", "", m3_smith_g1_gtr,
        m3_smith_g1_gtr_exact, G1GTR },
      0, NULL, 2, { { 1.5, KF_REF_G1_GTR, 0 }, { 3, KF_REF_NONE, 0 } } },
    { "smith_g2_hammon", T_G2, APPROX, { "G2", "smith_g2_hammon", X_G2, m3_smith_g2_hammon, m3_smith_g2, G3 },
      0, NULL, DRAWN(KF_REF_VIS) },
    { "smith_vis_hammon", T_VIS, APPROX,
      { "visibility", "smith_vis_hammon", X_VIS, m3_smith_vis_hammon, m3_smith_vis, VIS3 },
      0, NULL, DRAWN(KF_REF_VIS) },
    { "g_implicit", T_G2, APPROX, { "G2", "g_implicit (N.L N.V)", X_G2, m_g_implicit, m3_smith_g2, G3 },
      0, NULL, DRAWN(KF_REF_VIS) },
    { "g_neumann", T_G2, APPROX, { "G2", "g_neumann (min(N.L, N.V))", X_G2, m_g_neumann, m3_smith_g2, G3 },
      0, NULL, DRAWN(KF_REF_VIS) },
    { "g_cook_torrance", T_G2, APPROX,
      { "G2", "g_cook_torrance (V-groove)", X_G2, m_g_cook_torrance, m3_smith_g2, G3 },
      0, NULL, DRAWN(KF_REF_VIS) },
    { "g_kelemen", T_G2, APPROX, { "G2", "g_kelemen", X_G2, m_g_kelemen, m3_smith_g2, G3 },
      0, NULL, DRAWN(KF_REF_VIS) },
    { "smith_g1_beckmann", T_G1_BECKMANN, APPROX,
      { "G1 Beckmann", "smith_g1_beckmann (Walter)", "exact Beckmann G1 (erf)", "", m2_smith_g1_beckmann,
        m2_smith_g1_beckmann_exact, G1D },
      0, NULL, DRAWN(KF_REF_G1_BECKMANN) },
    { "smith_g1_schlick_beckmann", T_G1_BECKMANN, APPROX,
      { "G1 Beckmann", "smith_g1_schlick_beckmann (k = a sqrt(2/pi))", "exact Beckmann G1 (erf)", "",
        m2_smith_g1_schlick_beckmann, m2_smith_g1_beckmann_exact, G1D },
      0, NULL, DRAWN(KF_REF_G1_BECKMANN) },
    { "smith_vis_joint_approx", T_VIS, APPROX,
      { "visibility", "smith_vis_joint_approx (= Hammon's)", X_VIS, m3_smith_vis_joint_approx, m3_smith_vis, VIS3 },
      0, NULL, DRAWN(KF_REF_VIS) },
    { "smith_vis_fit", T_VIS, APPROX,
      { "visibility", "smith_vis_fit (3 lines, fitted)", X_VIS, m3_smith_vis_fit, m3_smith_vis, VIS3 },
      0, NULL, DRAWN(KF_REF_VIS) },
    { "diffuse_hammon", T_DIFFUSE, SIM, NO_SWEEP, 0, NULL, DRAWN(KF_REF_NONE) },
    { "diffuse_burley", T_DIFFUSE, SIM, NO_SWEEP, 0, NULL, DRAWN(KF_REF_NONE) },
    { "diffuse_oren_nayar", T_DIFFUSE, SIM, NO_SWEEP, 0, NULL, DRAWN(KF_REF_NONE) },
    { "diffuse_hammon_hybrid", T_DIFFUSE, SIM, NO_SWEEP, 0, NULL, DRAWN(KF_REF_NONE) },
    { "diffuse_hammon_cheap", T_DIFFUSE, SIM, NO_SWEEP, 0, NULL, DRAWN(KF_REF_NONE) },
    { "brdf_hammon", T_BRDF, APPROX,
      { "whole BRDF", "brdf_hammon (Hammon Vis)", "D Vis_exact F + diffuse_hammon", "", m_brdf_hammon, m_brdf_exact,
        G3 },
      1, NULL, NOT_DRAWN },
    { "lambert", T_DIFFUSE, SIM, NO_SWEEP, 0, NULL, DRAWN(KF_REF_NONE) },
};
#define N_FACTS ((int)(sizeof facts / sizeof facts[0]))

static const fact *find(const char *kernel)
{
    int i;
    for (i = 0; i < N_FACTS; i++)
        if (!strcmp(facts[i].kernel, kernel))
            return &facts[i];
    return NULL;
}

/* ---- the check ---------------------------------------------------------------- */

static int in_list(const char *name, const char *const *names, int n)
{
    int i;
    if (!names)
        return facet_kernel_find(name) != NULL;
    for (i = 0; i < n; i++)
        if (!strcmp(names[i], name))
            return 1;
    return 0;
}

int kf_check(const char *const *names, int n, FILE *err)
{
    int bad = 0, i, j;
    const char *here = "bench/report/kernel_facts.c";
    if (!names)
        n = (int)facet_kernel_count();
    for (i = 0; i < n; i++) {
        const char *kn = names ? names[i] : facet_kernel_at((size_t)i)->name;
        if (!find(kn)) {
            fprintf(err, "%s: no entry for kernel %s (its term, its exact reference or model, its image-space variants)\n",
                    here, kn);
            bad++;
        }
    }
    for (i = 0; i < N_FACTS; i++) {
        const fact *f = &facts[i];
        const fact *x = f->sweep.exact_kernel && f->sweep.exact_kernel[0] ? find(f->sweep.exact_kernel) : NULL;
        if (!in_list(f->kernel, names, n)) {
            fprintf(err, "%s: an entry for %s, which the kernel list lacks\n", here, f->kernel);
            bad++;
        }
        for (j = 0; j < i; j++)
            if (!strcmp(facts[j].kernel, f->kernel)) {
                fprintf(err, "%s: two entries for %s\n", here, f->kernel);
                bad++;
            }
        if (f->model == SIM && f->term != T_DIFFUSE) {
            fprintf(err, "%s: %s: only diffuse kernels are measured against the microsurface simulation\n", here,
                    f->kernel);
            bad++;
        }
        if (f->term < T_NONE || f->term >= N_TERMS || (f->term == T_NONE && f->model != OWN)) {
            fprintf(err, "%s: %s: no term, or a term outside the list\n", here, f->kernel);
            bad++;
        }
        if (f->model == APPROX && (!f->sweep.term || !f->sweep.approx || !f->sweep.exact || !f->sweep.exact_kernel ||
                                   !f->sweep.f_approx || !f->sweep.f_exact || f->sweep.n_axes < 1 ||
                                   f->sweep.n_axes > 3)) {
            fprintf(err, "%s: %s approximates its term but its sweep is incomplete\n", here, f->kernel);
            bad++;
        }
        if (f->model != APPROX && (f->sweep.term || f->sweep.f_approx)) {
            fprintf(err, "%s: %s has a sweep but is not an approximation\n", here, f->kernel);
            bad++;
        }
        if (f->model == APPROX && f->sweep.exact_kernel && f->sweep.exact_kernel[0] &&
            (!x || x->model != EXACT || x->term != f->term)) {
            fprintf(err, "%s: %s is measured against %s, which is not the exact form of its term\n", here, f->kernel,
                    f->sweep.exact_kernel);
            bad++;
        }
        if ((f->term == T_NONE || term_role[f->term] < 0) ? f->n_variants != 0 : f->n_variants < 1) {
            fprintf(err, "%s: %s: image-space variants %s\n", here, f->kernel,
                    f->n_variants ? "for a kernel its section does not draw" : "missing");
            bad++;
        }
        for (j = 0; j < f->n_variants && j < 4; j++)
            if (f->variants[j].ref < KF_REF_NONE || f->variants[j].ref > KF_REF_FRESNEL ||
                (f->variants[j].is_reference && f->variants[j].ref == KF_REF_NONE)) {
                fprintf(err, "%s: %s: variant %d has no valid reference\n", here, f->kernel, j);
                bad++;
            }
    }
    return bad;
}

/* ---- terms ------------------------------------------------------------------- */

int kf_term_count(void) { return N_TERMS; }
const char *kf_term_title(int t) { return terms[t].title; }
int kf_term_has_reference(int t) { return terms[t].has_reference; }

int kf_term_kernels(int t, const char **names, int max)
{
    size_t k;
    int n = 0;
    for (k = 0; k < facet_kernel_count() && n < max; k++) {
        const fact *f = find(facet_kernel_at(k)->name);
        if (f && f->term == t)
            names[n++] = f->kernel;
    }
    return n;
}

int kf_is_diffuse(const char *kernel)
{
    const fact *f = find(kernel);
    return f && f->term == T_DIFFUSE;
}

/* ---- model error ---------------------------------------------------------------- */

/* the approximations in the report's order (by term, then the kernel
 * list's order), with the sweep's results */
static kf_model models[N_FACTS];
static const fact *model_fact[N_FACTS];
static int n_models = -1;

static void list_models(void)
{
    int t;
    size_t k;
    if (n_models >= 0)
        return;
    n_models = 0;
    for (t = 0; t < N_TERMS; t++)
        for (k = 0; k < facet_kernel_count(); k++) {
            const fact *f = find(facet_kernel_at(k)->name);
            kf_model *m = &models[n_models];
            if (!f || f->term != t || f->model != APPROX)
                continue;
            memset(m, 0, sizeof *m);
            m->term = f->sweep.term;
            m->approx = f->sweep.approx;
            m->exact = f->sweep.exact;
            m->kernel = f->kernel;
            m->exact_kernel = f->sweep.exact_kernel;
            m->peer_exact = f->peer_exact;
            m->n_axes = f->sweep.n_axes;
            m->axes = f->sweep.axes;
            m->max_rel = -1;
            model_fact[n_models++] = f;
        }
}

int kf_model_count(void)
{
    list_models();
    return n_models;
}

const kf_model *kf_model_at(int i)
{
    list_models();
    return &models[i];
}

double kf_model_of(const char *kernel)
{
    const fact *f = find(kernel);
    int i;
    if (!f || f->model == OWN)
        return -1;
    if (f->model == EXACT)
        return 0;
    if (f->model == SIM) {
        const kf_sim *x = kf_sim_of(kernel);
        return x ? x->max : -1;
    }
    list_models();
    for (i = 0; i < n_models; i++)
        if (model_fact[i] == f)
            return models[i].max_rel;
    return -1;
}

/* ---- the microsurface simulation's figures (bench/microsurface/model_error.tsv) --------- */

static kf_sim sims[N_FACTS];
static int n_sims;

const kf_sim *kf_sim_of(const char *kernel)
{
    int i;
    for (i = 0; i < n_sims; i++)
        if (!strcmp(sims[i].kernel, kernel))
            return &sims[i];
    return NULL;
}

/* tab-separated fields of line into f[] (at most max), in place */
static int split_tabs(char *line, char **f, int max)
{
    int n = 0;
    char *p = line;
    while (n < max) {
        f[n++] = p;
        p = strchr(p, '\t');
        if (!p)
            break;
        *p++ = '\0';
    }
    return n;
}

/* the rows of the oracle form against each kernel's own material, every
 * albedo: the whole grid (every alpha, and per alpha) and N.L, N.V >= 0.2 */
int kf_sim_load(const char *path)
{
    FILE *in = fopen(path, "r");
    char line[4096], *f[40];
    int col[40], nc = 0, i;
    enum { C_KERNEL, C_FORM, C_REF, C_PRIMARY, C_DOMAIN, C_ALBEDO, C_ALPHA, C_MAX, C_SIG, C_AA, C_ANL, C_ANV, C_APHI,
           C_ARHO, C_MEAN, C_MSIG, NCOL };
    static const char *const want[NCOL] = { "kernel", "form", "reference", "primary", "domain", "albedo", "alpha",
                                            "max_abs_rel_err", "sigma_at_max", "at_alpha", "at_nl", "at_nv", "at_phi",
                                            "at_albedo", "mean_abs_rel_err", "mean_sigma" };
    n_sims = 0;
    if (!in)
        return -1;
    for (i = 0; i < NCOL; i++)
        col[i] = -1;
    while (fgets(line, sizeof line, in)) {
        int n;
        const fact *fk;
        kf_sim *x;
        line[strcspn(line, "\r\n")] = '\0';
        if (line[0] == '#' || !line[0])
            continue;
        n = split_tabs(line, f, 40);
        if (!nc) { /* the header */
            for (i = 0; i < NCOL; i++) {
                int j;
                for (j = 0; j < n; j++)
                    if (!strcmp(f[j], want[i]))
                        col[i] = j;
                if (col[i] < 0) {
                    fclose(in);
                    return -1;
                }
            }
            nc = n;
            continue;
        }
        if (n != nc || strcmp(f[col[C_FORM]], "oracle") || strcmp(f[col[C_PRIMARY]], "1") ||
            strcmp(f[col[C_ALBEDO]], "all") || !(fk = find(f[col[C_KERNEL]])) || fk->model != SIM)
            continue;
        x = (kf_sim *)kf_sim_of(fk->kernel);
        if (!x) {
            if (n_sims >= N_FACTS)
                continue;
            x = &sims[n_sims++];
            memset(x, 0, sizeof *x);
            x->kernel = fk->kernel;
            snprintf(x->reference, sizeof x->reference, "%s", f[col[C_REF]]);
            x->max = x->max2 = -1;
        }
        if (!strcmp(f[col[C_DOMAIN]], "all") && !strcmp(f[col[C_ALPHA]], "all")) {
            x->max = atof(f[col[C_MAX]]);
            x->sig = atof(f[col[C_SIG]]);
            x->at[0] = atof(f[col[C_AA]]);
            x->at[1] = atof(f[col[C_ANL]]);
            x->at[2] = atof(f[col[C_ANV]]);
            x->at[3] = atof(f[col[C_APHI]]);
            x->at[4] = atof(f[col[C_ARHO]]);
            x->mean = atof(f[col[C_MEAN]]);
            x->mean_sig = atof(f[col[C_MSIG]]);
        } else if (strcmp(f[col[C_DOMAIN]], "all") && !strcmp(f[col[C_ALPHA]], "all")) {
            x->max2 = atof(f[col[C_MAX]]);
            x->sig2 = atof(f[col[C_SIG]]);
            x->mean2 = atof(f[col[C_MEAN]]);
        } else if (!strcmp(f[col[C_DOMAIN]], "all") && x->n_alpha < KF_SIM_MAX_ALPHA) {
            x->alpha[x->n_alpha] = atof(f[col[C_ALPHA]]);
            x->amax[x->n_alpha] = atof(f[col[C_MAX]]);
            x->asig[x->n_alpha] = atof(f[col[C_SIG]]);
            x->amean[x->n_alpha] = atof(f[col[C_MEAN]]);
            x->n_alpha++;
        }
    }
    fclose(in);
    /* a kernel without its whole-grid row is not compared */
    for (i = 0; i < n_sims; i++)
        if (sims[i].max < 0)
            sims[i] = sims[--n_sims], i--;
    return n_sims;
}

/* point i of n on an axis: even i log-spaced, odd i linear, both lo .. hi */
static double axis_at(const kf_axis *ax, int i, int n)
{
    double u = (double)(i / 2) / (double)((n + 1) / 2 - 1);
    if (i & 1)
        return ax->lo + (ax->hi - ax->lo) * u;
    return exp2(log2(ax->lo) + (log2(ax->hi) - log2(ax->lo)) * u);
}

void kf_model_sweep(int quick)
{
    int t;
    list_models();
    for (t = 0; t < n_models; t++) {
        const fact *f = model_fact[t];
        kf_model *x = &models[t];
        int na = f->sweep.n_axes, d;
        int n = na == 3 ? (quick ? 24 : 96) : na == 2 ? (quick ? 200 : 1000) : 100000;
        long total = 1, c;
        double sum = 0;
        if (f->sweep.f_exact == m3_smith_g1_gtr_exact) /* a quadrature per point (~0.1 ms) */
            n = quick ? 10 : 24;
        x->max_rel = -1;
        x->n = 0;
        for (d = 0; d < na; d++)
            total *= n;
        for (c = 0; c < total; c++) {
            double v[3], e;
            long r = c;
            for (d = 0; d < na; d++) {
                v[d] = axis_at(&f->sweep.axes[d], (int)(r % n), n);
                r /= n;
            }
            e = bench_rel_err(f->sweep.f_approx(v), f->sweep.f_exact(v));
            sum += e;
            x->n++;
            if (e > x->max_rel) {
                x->max_rel = e;
                for (d = 0; d < na; d++)
                    x->arg[d] = v[d];
            }
        }
        x->mean_rel = sum / (double)x->n;
    }
}

/* ---- image space ----------------------------------------------------------------- */

static kf_variant variants[4 * N_FACTS];
static int n_variants = -1;

static void list_variants(void)
{
    int t, j;
    size_t k;
    if (n_variants >= 0)
        return;
    n_variants = 0;
    for (t = 0; t < N_TERMS; t++)
        for (k = 0; k < facet_kernel_count(); k++) {
            const fact *f = find(facet_kernel_at(k)->name);
            if (!f || f->term != t || term_role[t] < 0)
                continue;
            for (j = 0; j < f->n_variants && j < 4; j++) {
                kf_variant *v = &variants[n_variants++];
                memset(v, 0, sizeof *v);
                v->kernel = f->kernel;
                if (f->variants[j].gamma > 0)
                    snprintf(v->name, sizeof v->name, "%s (gamma %g)", f->kernel, f->variants[j].gamma);
                else if (f->note)
                    snprintf(v->name, sizeof v->name, "%s (%s)", f->kernel, f->note);
                else
                    snprintf(v->name, sizeof v->name, "%s", f->kernel);
                v->role = term_role[t];
                v->role_name = role_name[v->role];
                v->gamma = f->variants[j].gamma;
                v->ref = f->variants[j].ref;
                v->ref_name = ref_name[v->ref];
                v->is_reference = f->variants[j].is_reference;
            }
        }
}

int kf_variant_count(void)
{
    list_variants();
    return n_variants;
}

const kf_variant *kf_variant_at(int i)
{
    list_variants();
    return &variants[i];
}

/* ---- the table, printed ----------------------------------------------------------- */

void kf_print(FILE *out)
{
    static const char *const model[] = { "own model", "exact", "approximation", "vs the microsurface simulation" };
    int i;
    fprintf(out, "# bench/report/kernel_facts.c: kernel TAB term TAB against its term's exact form TAB what\n");
    for (i = 0; i < N_FACTS; i++) {
        const fact *f = &facts[i];
        fprintf(out, "kernel\t%s\t%s\t%s\t%s\n", f->kernel, f->term == T_NONE ? "-" : terms[f->term].title,
                model[f->model], f->model == APPROX ? f->sweep.exact : "-");
    }
    fprintf(out, "# variant TAB kernel TAB name TAB role TAB reference (image space)\n");
    for (i = 0; i < kf_variant_count(); i++) {
        const kf_variant *v = kf_variant_at(i);
        fprintf(out, "variant\t%s\t%s\t%s\t%s\n", v->kernel, v->name, v->role_name, v->ref != KF_REF_NONE ? v->ref_name : "-");
    }
}
