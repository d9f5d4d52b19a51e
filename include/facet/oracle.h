/* facet/oracle.h - the double-precision reference of every kernel.
 *
 * The oracle follows the definitional formulas, not the kernels' algebra:
 * L and V are built as unit vectors with the given dots and H = normalize(L+V)
 * (in double-double: the azimuth cancels where L is nearly opposite V at
 * grazing angles), D in its tan form, Smith G through Lambda, pow() for the
 * Fresnel power, -expm1(5 log1p(-x)) for the smooth diffuse's 1 - (1 - x)^5
 * (no cancellation at grazing angles), lerps as (1 - a) x + a y, plain
 * divisions.  The quantities the kernels are most sensitive to are taken
 * from exact geometric identities evaluated in double-double instead of from
 * the rounded vectors: tan^2(theta_h) = |h_t|^2 / h_z^2 with |h|^2 = 2 + 2 L.V
 * and h_z = N.L + N.V, 1 - L.H = (1 - L.H^2) / (1 + L.H) for the Fresnel
 * tail, and t = 1 + L.V itself (never L.V = t - 1 rounded: near L.V = -1 t
 * is tiny, and the diffuse's facing = t/2 is made of it).  It is
 * compiled with -ffp-contract=off, uses libm freely, and shares no code with
 * the kernels.  Its only common ground with them is the contract's domain
 * handling (clamping, and the identity extension for inconsistent dot
 * triples), which is part of what the kernels promise.
 *
 * Accuracy: validated in tests/oracle/test_oracle.c, against quadrature
 * (normalisation of D, Lambda integrated from the slope distribution, the
 * Smith constraint, the 21/(20 pi) smooth-diffuse albedo), by symmetry, and
 * against an independent long-double evaluation at ill-conditioned points:
 * the specular peak, grazing angles, L.V near +-1, and L.V near -1 with
 * cosines down to FACET_COS_MIN (agreement 4e-15 relative); i.e. about 10^8
 * times below the f32 bounds it judges.
 *
 * NaN: the functions below clamp a NaN input to the low end of its domain
 * (they are also the samplers' building blocks); the kernel table's oracle
 * entry (facet_kernel.oracle, which `facet eval --oracle` uses) applies the
 * kernels' NaN rule instead: any NaN input gives 0.
 */
#ifndef FACET_ORACLE_H
#define FACET_ORACLE_H

#ifdef __cplusplus
extern "C" {
#endif

/* The geometry of an (N.L, N.V, L.V) triple after the domain rules.
 * consistent = 1 when unit vectors with these dots exist (then n_h, l_h,
 * l_v and tan2_h come from the vectors), 0 when the identity extension was
 * used.  tan2_h = tan^2 of the angle between N and H.  t = 1 + L.V (after
 * the raise to (N.L + N.V)^2 / 2 for inconsistent triples) to full relative
 * precision: near L.V = -1 it is tiny (down to 2^-39), and 1 + l_v would
 * keep only 2^-53 of it absolutely. */
typedef struct facet_oracle_geom {
    double n_l, n_v, l_v, n_h, l_h, tan2_h;
    int consistent;
    double t;
} facet_oracle_geom;

facet_oracle_geom facet_oracle_geometry(double nol, double nov, double lov);

double facet_oracle_noh_from_dots(double nol, double nov, double lov);
double facet_oracle_loh_from_dots(double lov);
double facet_oracle_fresnel_schlick(double f0, double cos_theta);
/* exact dielectric Fresnel (Snell + the Fresnel equations, unpolarised),
 * eta from f0; fresnel_schlick with f90 */
double facet_oracle_fresnel_cook_torrance(double f0, double voh);
double facet_oracle_fresnel_schlick_f90(double f0, double f90, double voh);
double facet_oracle_fresnel_schlick_sg(double f0, double cos_theta);
double facet_oracle_ggx_d(double noh, double alpha);
/* D from tan^2(theta_h) directly (the accurate form near the peak) */
double facet_oracle_ggx_d_tan2(double tan2_h, double cos_h, double alpha);
double facet_oracle_blinn_phong_d(double noh, double alpha);
double facet_oracle_beckmann_d(double noh, double alpha);
double facet_oracle_ggx_aniso_d(double noh, double toh, double boh, double alpha_x,
                                double alpha_y);
double facet_oracle_gtr_d(double noh, double alpha, double gamma);
double facet_oracle_smith_lambda(double nov, double alpha);
double facet_oracle_smith_g1(double nov, double alpha);
double facet_oracle_smith_g2(double nol, double nov, double alpha);
double facet_oracle_smith_g2_uncorrelated(double nol, double nov, double alpha);
double facet_oracle_smith_vis(double nol, double nov, double alpha);
double facet_oracle_smith_g1_hammon(double nov, double alpha);
/* Dimov's G1 for GTR: the monotone cubic (pchip) in gamma through the closed
 * forms at gamma = 0 .. 4 (the kernel's definition); one closed form; and
 * the exact G1 = 1 / (1 + Lambda) by quadrature (the model reference) */
double facet_oracle_smith_g1_gtr(double nov, double alpha, double gamma);
double facet_oracle_smith_g1_gtr_order(double nov, double alpha, int order);
double facet_oracle_smith_g1_gtr_exact(double nov, double alpha, double gamma);
double facet_oracle_smith_g2_hammon(double nol, double nov, double alpha);
double facet_oracle_smith_vis_hammon(double nol, double nov, double alpha);
/* the rest of the shadowing/visibility menu (facet.h), each from its own
 * formula; and the exact Beckmann Smith G1, 1 / (1 + Lambda) with
 * Lambda = (erf(c) - 1) / 2 + exp(-c^2) / (2 c sqrt(pi)), c = N.V / (alpha
 * sqrt(1 - N.V^2)): the reference Walter's and Schlick's forms approximate */
double facet_oracle_g_implicit(double nol, double nov);
double facet_oracle_g_neumann(double nol, double nov);
double facet_oracle_g_cook_torrance(double nol, double nov, double noh, double voh);
double facet_oracle_g_kelemen(double nol, double nov, double voh);
double facet_oracle_smith_g1_beckmann(double nov, double alpha);
double facet_oracle_smith_g1_beckmann_exact(double nov, double alpha);
double facet_oracle_smith_g1_schlick_beckmann(double nov, double alpha);
double facet_oracle_smith_vis_joint_approx(double nol, double nov, double alpha);
double facet_oracle_smith_vis_fit(double nol, double nov, double alpha);
double facet_oracle_diffuse_hammon(double nol, double nov, double lov, double alpha,
                                   double albedo);
double facet_oracle_diffuse_burley(double nol, double nov, double loh, double alpha,
                                   double albedo);
double facet_oracle_diffuse_oren_nayar(double nol, double nov, double lov, double alpha,
                                       double albedo);
double facet_oracle_diffuse_hammon_hybrid(double nol, double nov, double lov, double alpha,
                                          double albedo);
double facet_oracle_diffuse_hammon_cheap(double nol, double nov, double lov, double alpha,
                                         double albedo);
double facet_oracle_brdf_hammon(double nol, double nov, double lov, double alpha,
                                double f0, double albedo);
double facet_oracle_lambert(double albedo);

/* samplers (facet.h, "GGX and GTR importance sampling"): the same inputs and
 * outputs as facet_<sampler>_f32, in double, from the definitions */
void facet_oracle_ggx_sample_d(double h[3], double u1, double u2, double alpha);
double facet_oracle_ggx_pdf_d(double noh, double alpha);
void facet_oracle_ggx_sample_vndf(double h[3], double vx, double vy, double vz, double u1,
                                  double u2, double alpha);
double facet_oracle_ggx_pdf_vndf(double nov, double noh, double voh, double alpha);
double facet_oracle_ggx_pdf_vndf_reflect(double nov, double noh, double voh, double alpha);
void facet_oracle_reflect(double l[3], double vx, double vy, double vz, double hx, double hy,
                          double hz);
void facet_oracle_ggx_sample_d_aniso(double h[3], double u1, double u2, double alpha_x,
                                     double alpha_y);
double facet_oracle_ggx_pdf_d_aniso(double hx, double hy, double hz, double alpha_x,
                                    double alpha_y);
void facet_oracle_ggx_sample_vndf_aniso(double h[3], double vx, double vy, double vz, double u1,
                                        double u2, double alpha_x, double alpha_y);
double facet_oracle_ggx_pdf_vndf_aniso(double vx, double vy, double vz, double hx, double hy,
                                       double hz, double alpha_x, double alpha_y);
void facet_oracle_gtr_sample_d(double h[3], double u1, double u2, double alpha, double gamma);
double facet_oracle_gtr_pdf_d(double noh, double alpha, double gamma);
void facet_oracle_sincos_2pi(double sc[2], double u);

#ifdef __cplusplus
}
#endif

#endif
