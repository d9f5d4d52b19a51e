/* geom.h - one shading geometry, and the value each named kernel input
 * takes there: how the report drives every kernel of the list (whatever
 * its inputs) from the same configurations of N, L, V and material. */
#ifndef FACET_BENCH_GEOM_H
#define FACET_BENCH_GEOM_H

typedef struct geom {
    double nl, nv, lv;  /* N.L, N.V, L.V */
    double alpha;       /* GGX-style roughness (alpha_x = alpha_y = alpha) */
    double f0, f90, albedo, gamma;
} geom;

/* The value of input `name` (as facet_kernel.inputs names it) at g: nol,
 * nov, lov, noh, loh / voh / cos (the half-vector cosine: L.H = V.H),
 * toh / boh (the tangent-frame components of H for an azimuth of 0: T.H =
 * sin theta_h, B.H = 0), alpha, alpha_x, alpha_y, f0, f90, albedo, gamma.
 * Returns 0 for a name it does not know (the caller skips that kernel). */
int geom_input(const geom *g, const char *name, double *v);

/* Fills in[] for a kernel's input names; 0 if any is unknown. */
int geom_inputs(const geom *g, const char *const *names, int n, double *in);

#endif
