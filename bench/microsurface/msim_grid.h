/* msim_grid.h - the reference tables' grid (bench/microsurface/README.md):
 * alpha from 2^-10 to 1, the cosines of L and V, the azimuth between them.
 * The tables hold every (alpha, N.L) run with next-event estimates at every
 * (N.V, phi); phi = 0 puts V on L's side (back-scattering), 180 the mirror
 * side.  N.V = 1 has one azimuth. */
#ifndef MSIM_GRID_H
#define MSIM_GRID_H

#define MSIM_NALPHA 12
#define MSIM_NCOS 10
#define MSIM_NPHI 7
static const double msim_grid_alpha[MSIM_NALPHA] = {
    0x1p-10, 0x1p-6, 0x1p-4, 0.125, 0.1875, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1.0};
static const double msim_grid_cos[MSIM_NCOS] = {1.0, 0.9, 0.75, 0.6, 0.45, 0.3, 0.2, 0.1, 0.05, 0.02};
static const double msim_grid_phi[MSIM_NPHI] = {0.0, 30.0, 60.0, 90.0, 120.0, 150.0, 180.0};

/* the table's materials: name, facet, f0 */
#define MSIM_NMAT 3
static const struct {
    const char *name;
    int facet;
    double f0;
} msim_grid_mat[MSIM_NMAT] = {
    {"hammon", 1, 0.04}, /* Hammon's facet (Schlick-F mirror + symmetric diffuse), f0 0.04 */
    {"lambert", 0, 0.0}, /* Lambertian facets */
    {"mirror", 2, 1.0},  /* white mirror facets (F = 1) */
};

#endif
