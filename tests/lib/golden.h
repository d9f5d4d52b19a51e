/* golden.h - named points of every kernel: inputs and the value the
 * contract's formula (include/facet.h) gives there, written out in closed
 * form, independently of the oracle's and the kernels' code.  The golden
 * values are kept here, by hand, one place per kernel; the kernel list is
 * not: golden_covers() fails, naming it, for a kernel of the table
 * (facet_kernel_at) without a point here, and for a point naming no kernel.
 *   tests/oracle/test_oracle.c   the oracle at every point, within
 *                                GOLDEN_ORACLE_TOL (relative);
 *   tests/f32/test_f32_bad_input.c  both f32 tiers at every point, within
 *                                their bound, and to the bit where the row
 *                                says exact (a named point of the contract).
 * Inputs are exact in float (dyadic) unless the row is exact, so that the
 * f32 kernels see the very point.  A new kernel adds its rows here. */
#ifndef FACET_TEST_GOLDEN_H
#define FACET_TEST_GOLDEN_H

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "facet/detail/vis_fit.h"
#include "harness.h"

#define GOLDEN_ORACLE_TOL 1e-13

typedef struct {
    const char *kernel;
    double in[FACET_MAX_INPUTS];
    double want;
    int exact; /* facet_<kernel>_f32 gives (float)want to the bit */
} golden_point;

/* pieces of the formulas, at the points below */
#define G_SQ_(x) ((x) * (x))
#define G_P5_(x) ((x) * (x) * (x) * (x) * (x))
/* the geometry of (N.L, N.V, L.V) = (1/2, 3/4, 1/4): N.H, L.H */
#define G_NOH_ (1.25 / sqrt(2.5))
#define G_LOH_ sqrt(0.625)
/* GGX D at N.H = n, alpha = a */
#define G_GGX_D_(n, a) (G_SQ_(a) / (M_PI * G_SQ_(G_SQ_(n) * (G_SQ_(a) - 1) + 1)))
/* GGX's sqrt(alpha^2 + (1 - alpha^2) x^2), and G1 */
#define G_LAM_(x, a) sqrt(G_SQ_(a) + (1 - G_SQ_(a)) * G_SQ_(x))
#define G_G1_(x, a) (2 * (x) / ((x) + G_LAM_(x, a)))
/* Hammon's rough term at facing f, N.H h */
#define G_ROUGH_(f, h) ((f) * (0.9 - 0.4 * (f)) * (0.5 + (h)) / (h))
/* smith_vis_fit's r~ (the constants of facet/detail/vis_fit.h, stored as 2 k) */
#define G_VF_T_(x, a) ((x) * (1 + (a) * ((double)FACET_VIS_FIT_C1 + (double)FACET_VIS_FIT_C2 * (a))))
#define G_VF_R_(x, a)                                                                            \
    (0.5 * fmax((double)FACET_VIS_FIT_K1 * (a),                                                  \
                fmax((double)FACET_VIS_FIT_K2 * (a) + (double)FACET_VIS_FIT_K3 * G_VF_T_(x, a), \
                     (double)FACET_VIS_FIT_K4 * (a) + (double)FACET_VIS_FIT_K5 * G_VF_T_(x, a))))
/* Walter's rational at c */
#define G_WALTER_(c) fmin(1.0, (3.535 * (c) + 2.181 * (c) * (c)) / (1 + 2.276 * (c) + 2.577 * (c) * (c)))
/* Oren-Nayar's A and B at sigma = alpha / 2 */
#define G_ON_A_(a) (1 - 0.5 * G_SQ_((a) / 2) / (G_SQ_((a) / 2) + 0.33))
#define G_ON_B_(a) (0.45 * G_SQ_((a) / 2) / (G_SQ_((a) / 2) + 0.09))
/* Dimov's G^3 at n, alpha a (W = sqrt(n^2 + a^2 s2)) */
#define G_W_(n, a) sqrt(G_SQ_(n) + G_SQ_(a) * (1 - G_SQ_(n)))
#define G_GTR3_(n, a)                                                                              \
    (4 * (1 + G_SQ_(a)) * (n) * G_W_(n, a) /                                                       \
     (G_SQ_(a) * (3 * G_SQ_(a) + 1) * (1 - G_SQ_(n)) + 2 * (1 + G_SQ_(a)) * (n) * ((n) + G_W_(n, a))))

/* The table, built on first use (its values are computed: C99 allows
 * that in an automatic initializer only); *n gets the count */
static inline const golden_point *golden_table(size_t *n)
{
    static golden_point *table;
    static size_t count;
    if (!table) {
        const golden_point t[] = {
            { "noh_from_dots", { 0.5, 0.75, 0.25 }, G_NOH_, 0 },
            { "loh_from_dots", { 0.25 }, G_LOH_, 0 },
            { "loh_from_dots", { -1 }, 0, 0 },
            { "fresnel_schlick", { 0.25, 0.5 }, 0.25 + 0.75 / 32, 0 },
            { "fresnel_schlick", { 0.25, 1 }, 0.25, 0 },
            { "fresnel_cook_torrance", { 0.25, 0.5 }, /* sqrt f0 = 1/2: eta = 3, g = sqrt(8.25) */
              0.5 * G_SQ_((sqrt(8.25) - 0.5) / (sqrt(8.25) + 0.5)) *
                  (1 + G_SQ_(((sqrt(8.25) + 0.5) * 0.5 - 1) / ((sqrt(8.25) - 0.5) * 0.5 + 1))), 0 },
            { "fresnel_cook_torrance", { 0.25, 1 }, 0.25, 0 },
            { "fresnel_schlick_f90", { 0.25, 0.5, 0.5 }, 0.25 + 0.25 / 32, 0 },
            { "fresnel_schlick_sg", { 0.25, 0.5 }, 0.25 + 0.75 * exp2((-5.55473 * 0.5 - 6.98316) * 0.5), 0 },
            { "ggx_d", { 0.5, 0.5 }, G_GGX_D_(0.5, 0.5), 0 },
            { "ggx_d", { 1, 0.5 }, 4 / M_PI, 0 },
            { "blinn_phong_d", { 0.5, 0.5 }, 0.0625 / M_PI, 0 }, /* p = 6: 2^-6 / (pi / 4) */
            { "beckmann_d", { 0.75, 0.5 }, exp(-(0.4375 / 0.5625) / 0.25) / (M_PI * 0.25 * G_SQ_(0.5625)), 0 },
            { "ggx_aniso_d", { 0.75, 0.5, 0.25, 0.5, 0.25 }, 1 / (M_PI * 0.125 * G_SQ_(2.5625)), 0 },
            { "gtr_d", { 0.5, 0.5, 3 }, (0.1 / M_PI) / (0.8125 * 0.8125 * 0.8125), 0 },
            { "gtr_d", { 0.5, 0.5, 1 }, (-0.75 / (M_PI * log(0.25))) / 0.8125, 0 },
            { "smith_g1", { 0.5, 0.5 }, G_G1_(0.5, 0.5), 0 },
            { "smith_g2", { 0.5, 0.75, 0.5 }, 2 * 0.375 / (0.75 * G_LAM_(0.5, 0.5) + 0.5 * G_LAM_(0.75, 0.5)), 0 },
            { "smith_g2_uncorrelated", { 0.5, 0.75, 0.5 }, G_G1_(0.5, 0.5) * G_G1_(0.75, 0.5), 0 },
            { "smith_vis", { 0.5, 0.75, 0.5 }, 0.5 / (0.75 * G_LAM_(0.5, 0.5) + 0.5 * G_LAM_(0.75, 0.5)), 0 },
            { "smith_g1_hammon", { 0.5, 0.5 }, 0.8, 0 },
            { "smith_g1_gtr", { 0.5, 0.5, 2 }, G_G1_(0.5, 0.5), 0 },
            { "smith_g1_gtr", { 0.5, 0.5, 0 }, 1 / 1.5, 0 },
            { "smith_g1_gtr", { 0.5, 0.5, 3 }, G_GTR3_(0.5, 0.5), 0 },
            { "smith_g2_hammon", { 0.5, 0.75, 0.5 }, 0.75, 0 },  /* 0.75 / (0.375 + 0.625) */
            { "smith_vis_hammon", { 0.5, 0.75, 0.5 }, 0.5, 0 }, /* 0.5 / (0.375 + 0.625) */
            { "g_implicit", { 0.5, 0.75 }, 0.375, 0 },
            { "g_implicit", { 1, 1 }, 1, 1 },
            { "g_implicit", { 0, 0.5 }, 0, 1 },
            { "g_neumann", { 0.5, 0.75 }, 0.5, 0 },
            { "g_neumann", { 0.25, 0.75 }, 0.25, 1 },
            { "g_neumann", { 0, 0 }, 0, 1 },
            { "g_cook_torrance", { 0.25, 0.75, 0.5, 0.75 }, 1 / 3.0, 0 },
            { "g_cook_torrance", { 0.5, 0.5, 1, 0 }, 1, 1 },            /* V.H = 0 */
            { "g_cook_torrance", { 0.2, 0.9, 0.5, 0.8 }, 0.25, 1 },     /* 2 0.5 0.2 / 0.8 */
            { "g_kelemen", { 0.5, 0.75, 0.75 }, 0.375 / 0.5625, 0 },
            { "g_kelemen", { 0.5, 0.5, 0 }, 1, 1 }, /* V.H = 0 */
            { "g_kelemen", { 1, 0.5, 1 }, 0.5, 1 },
            { "smith_g1_beckmann", { 0.5, 0.5 }, G_WALTER_(1 / sqrt(0.75)), 0 }, /* c = 0.5 / (0.5 sqrt(0.75)) */
            { "smith_g1_schlick_beckmann", { 0.5, 0.5 },
              0.5 / (0.5 * (1 - 0.5 * sqrt(2 / M_PI)) + 0.5 * sqrt(2 / M_PI)), 0 },
            { "smith_vis_joint_approx", { 0.5, 0.75, 0.5 }, 0.5, 0 }, /* 0.5 / (0.4375 + 0.5625) */
            { "smith_vis_fit", { 0.5, 0.75, 0.5 }, 0.5 / (0.75 * G_VF_R_(0.5, 0.5) + 0.5 * G_VF_R_(0.75, 0.5)), 0 },
            { "diffuse_hammon", { 0.5, 0.75, 0.25, 0.5, 0.5 },
              0.5 * ((0.5 * 1.05 * (1 - G_P5_(0.5)) * (1 - G_P5_(0.25)) + 0.5 * G_ROUGH_(0.625, G_NOH_)) / M_PI +
                     0.5 * 0.1159 * 0.5), 0 },
            { "diffuse_burley", { 0.5, 0.75, 0.75, 0.25, 0.5 }, /* f_d90 = 0.5 + 2 0.5 0.75^2 */
              0.5 / M_PI * (1 + 0.0625 * G_P5_(0.5)) * (1 + 0.0625 * G_P5_(0.25)), 0 },
            { "diffuse_oren_nayar", { 0.5, 0.75, 0.5, 0.5, 0.5 }, /* max(0, L.V - N.L N.V) / max(N.L, N.V) = 1/6 */
              0.5 / M_PI * (G_ON_A_(0.5) + G_ON_B_(0.5) / 6), 0 },
            { "diffuse_hammon_hybrid", { 0.5, 0.75, 0.25, 0.5, 0.5 },
              0.5 * ((0.5 * (1 - G_P5_(0.5) / 2) * (1 - G_P5_(0.25) / 2) + 0.5 * G_ROUGH_(0.625, G_NOH_)) / M_PI +
                     0.5 * 0.1159 * 0.5), 0 },
            { "diffuse_hammon_cheap", { 0.5, 0.75, 0.25, 0.5, 0.5 },
              0.5 * ((0.5 + 0.5 * G_ROUGH_(0.625, G_NOH_)) / M_PI + 0.5 * 0.1159 * 0.5), 0 },
            { "brdf_hammon", { 0.5, 0.75, 0.25, 0.5, 0.25, 0.5 }, /* Vis_hammon = 0.5 here */
              G_GGX_D_(G_NOH_, 0.5) * 0.5 * (0.25 + 0.75 * G_P5_(1 - G_LOH_)) +
                  0.5 * ((0.5 * 1.05 * (1 - G_P5_(0.5)) * (1 - G_P5_(0.25)) + 0.5 * G_ROUGH_(0.625, G_NOH_)) / M_PI +
                         0.5 * 0.1159 * 0.5), 0 },
            { "lambert", { 0.5 }, 0.5 / M_PI, 0 },
        };
        table = malloc(sizeof t);
        if (!table)
            abort();
        memcpy(table, t, sizeof t);
        count = sizeof t / sizeof t[0];
    }
    *n = count;
    return table;
}

/* Every kernel of the table has a point, and every point names a kernel */
static inline void golden_covers(void)
{
    size_t i, j, count;
    const golden_point *g = golden_table(&count);
    for (i = 0; i < facet_kernel_count(); i++) {
        const char *name = facet_kernel_at(i)->name;
        int n = 0;
        for (j = 0; j < count; j++)
            n += !strcmp(g[j].kernel, name);
        CHECK(n > 0, "kernel %s has no golden values (named points) in tests/lib/golden.h", name);
    }
    for (j = 0; j < count; j++)
        CHECK(facet_kernel_find(g[j].kernel) != NULL, "tests/lib/golden.h: a point of '%s', which is no kernel of the table",
              g[j].kernel);
}

#endif
