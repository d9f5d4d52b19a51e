/* kernel_facts.h - what the report knows of each kernel that the kernel
 * list (src/core/kernels.def) does not say: the term it computes (the
 * chooser's and the Pareto plots' groups), whether it is that term's exact
 * form, an approximation of it (with the two double oracles and the domain
 * of the model-error sweep) or a model of its own, and the variants the
 * image-space section draws.  One table, kernel_facts.c, one entry per
 * kernel of the list; kf_check() fails on a kernel without an entry and on
 * an entry for a kernel the list lacks, and the report refuses to run then.
 * Every list the report shows is the kernel list (facet_kernel_at order)
 * read through this table. */
#ifndef FACET_REPORT_KERNEL_FACTS_H
#define FACET_REPORT_KERNEL_FACTS_H

#include <stdio.h>

/* ---- terms ------------------------------------------------------------------- */

/* the terms a user chooses among, in the report's order */
int kf_term_count(void);
const char *kf_term_title(int t);
/* 0 for the terms without an exact reference (D: each variant a model of
 * its own; diffuse's reference is the microsurface simulation) */
int kf_term_has_reference(int t);
/* the kernels of term t, in the kernel list's order (names[] at most max);
 * returns the count */
int kf_term_kernels(int t, const char **names, int max);
/* 1 if kernel computes a diffuse term (the white furnace) */
int kf_is_diffuse(const char *kernel);

/* ---- model error --------------------------------------------------------------- */

typedef struct kf_axis {
    const char *name;
    double lo, hi;
} kf_axis;

/* one approximation against the exact form of its term, and the sweep's
 * result */
typedef struct kf_model {
    const char *term;         /* "visibility", "G2", ... (the table's column) */
    const char *approx, *exact; /* labels */
    const char *kernel;       /* the approximating kernel */
    const char *exact_kernel; /* the exact form's kernel ("": none in the list) */
    int peer_exact;           /* the exact form is computed by the kernel's
                               * peer-vectors rows (the exact-Vis BRDF peers) */
    int n_axes;
    const kf_axis *axes;
    double max_rel, mean_rel, arg[3];
    long n;
} kf_model;

/* the sweep: each approximation's relative model error on a grid over its
 * domain (fewer points when quick) */
void kf_model_sweep(int quick);
int kf_model_count(void);
const kf_model *kf_model_at(int i);
/* the model error of kernel against its term's exact form: the sweep's
 * max; for a diffuse kernel the max over the microsurface simulation's grid
 * (kf_sim_load; -1 before it or without its row); 0 for an exact form; -1
 * for a model of its own */
double kf_model_of(const char *kernel);
/* ---- the microsurface simulation (bench/microsurface/model_error.tsv) ------- */

/* a diffuse kernel's model error against the simulated Smith microsurface of
 * the material it approximates (facet's double oracle of the kernel; every
 * facet albedo of the tables): relative |kernel / reference - 1|, each
 * figure with the simulation's standard error of it */
#define KF_SIM_MAX_ALPHA 16
typedef struct kf_sim {
    const char *kernel;
    char reference[16];       /* the material: "hammon", "lambert" */
    double max, sig, at[5];   /* the whole grid: max, its sigma, where (alpha, N.L, N.V, phi, albedo) */
    double mean, mean_sig;    /* mean |e| and the mean sigma */
    double max2, sig2, mean2; /* N.L, N.V >= 0.2 */
    int n_alpha;              /* per alpha, the whole grid */
    double alpha[KF_SIM_MAX_ALPHA], amax[KF_SIM_MAX_ALPHA], asig[KF_SIM_MAX_ALPHA], amean[KF_SIM_MAX_ALPHA];
} kf_sim;

/* the committed table, from the tree's top (where the report runs) */
#define KF_SIM_TABLE "bench/microsurface/model_error.tsv"
/* reads the table (microsurface error's output); returns the number of
 * kernels it gives, -1 when it cannot be read */
int kf_sim_load(const char *path);
/* NULL before kf_sim_load or for a kernel the table lacks */
const kf_sim *kf_sim_of(const char *kernel);


/* ---- image space (image_error.c) ------------------------------------------------- */

enum { KF_ROLE_D, KF_ROLE_VIS, KF_ROLE_G2, KF_ROLE_G1, KF_ROLE_F, KF_ROLE_DIFFUSE };
enum { KF_REF_NONE, KF_REF_GGX_D, KF_REF_VIS, KF_REF_G1_BECKMANN, KF_REF_G1_GTR, KF_REF_FRESNEL };

/* a variant drawn in image space: the kernel in a role of D * Vis * F +
 * diffuse, at a gamma (0: the scene's 2), against a reference render */
typedef struct kf_variant {
    const char *kernel;
    char name[48];        /* "gtr_d (gamma 1.5)" */
    const char *role_name; /* "D", "Vis", "G2", "G1", "F", "diffuse" */
    int role;             /* KF_ROLE_* */
    double gamma;
    int ref;              /* KF_REF_* */
    const char *ref_name; /* "" for KF_REF_NONE */
    int is_reference;     /* the variant renders the reference itself */
} kf_variant;

int kf_variant_count(void);
const kf_variant *kf_variant_at(int i);

/* ---- the check ------------------------------------------------------------------ */

/* Checks the table against a list of kernel names (NULL: the library's
 * kernel list): an entry for each, none for a kernel not in it, and each
 * entry whole.  Prints each fault to err; returns the count (0: sound). */
int kf_check(const char *const *names, int n, FILE *err);
/* the table, one line per kernel and per image-space variant (the check's
 * and the tests' view of it) */
void kf_print(FILE *f);

#endif
