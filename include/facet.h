/* facet.h - BRDF kernels for physically based shading, f32 API.
 *
 * Every kernel is a pure function of its inputs with a contract: formula,
 * domain, behaviour outside the domain, error bound measured against the
 * double-precision oracle (facet/oracle.h), and cost.
 *
 * Conventions for all kernels
 *   - alpha is the GGX width, alpha = perceptual roughness^2.
 *   - Cosines are N.L (nol), N.V (nov), N.H (noh), L.V (lov), ...
 *   - Domain: one-cosine inputs, f0 and albedo in [0, 1]; N.L and N.V of the
 *     two-cosine kernels in [FACET_COS_MIN, 1]; L.V in [-1, 1]; alpha in
 *     [FACET_ALPHA_MIN, 1] (facet/common.h: 2^-20 and 2^-10).
 *   - Outside the domain every input is clamped to the nearest domain value;
 *     NaN and -Inf count as the low end, +Inf as the high end.  So finite or
 *     not, every input gives a finite, non-negative result and nothing traps.
 *   - Denormal inputs are values like any other, except on ports that run
 *     with flush-to-zero (armv7 NEON): there they act as 0 (the tests judge
 *     such a port at the flushed input), and an intermediate below 2^-126
 *     becomes 0, so results below 2^-60 are only good to bound * 2^-60
 *     absolutely (elsewhere: below 2^-100, to bound * 2^-100).
 *   - (N.L, N.V, L.V) triples that no pair of unit vectors can form (e.g.
 *     after rounding the dots of a real pair) are evaluated by the identities
 *     below with 1 + L.V raised to (N.L + N.V)^2 / 2 where it is smaller;
 *     this caps N.H at 1 and is continuous with the geometric definition.
 *   - Error: relative to the oracle evaluated at the same float inputs
 *     (values below the absolute floor stated above compared absolutely),
 *     maximum over the test sweep (tests/test_f32_accuracy.c), in units of
 *     2^-k; FACET_ERR_* below are the bounds the tests enforce.  Where a
 *     bound has an absolute floor it is said so.
 *   - Cost: operations of the kernel body as a port with FMA executes them
 *     (clamp = 2, select = 2, fma = 1), counted by tests/test_op_counts.c;
 *     rsqrt and rcp are listed apart: each is an estimate plus the port's
 *     refinement steps (see the port headers).
 *
 * Names: facet_<kernel>_f32 here (library functions, the scalar port);
 * facet_<kernel>_f32_scalar in facet/scalar.h (the same, static inline).
 */
#ifndef FACET_H
#define FACET_H

#include <stddef.h>
#include "facet/common.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FACET_VERSION "0.1.0"

/* ---- measured bounds (relative error vs oracle), enforced by the tests --- */
#define FACET_ERR_NOH_FROM_DOTS_F32         3.372e-07 /* 2^-21.5 */
#define FACET_ERR_LOH_FROM_DOTS_F32         2.384e-07 /* 2^-22 */
#define FACET_ERR_FRESNEL_SCHLICK_F32       4.769e-07 /* 2^-21 */
#define FACET_ERR_GGX_D_F32                 9.538e-07 /* 2^-20 */
#define FACET_ERR_SMITH_G1_F32              4.769e-07 /* 2^-21 */
#define FACET_ERR_SMITH_G2_F32              4.769e-07 /* 2^-21 */
#define FACET_ERR_SMITH_G2_UNCORRELATED_F32 6.744e-07 /* 2^-20.5 */
#define FACET_ERR_SMITH_VIS_F32             4.769e-07 /* 2^-21 */
#define FACET_ERR_SMITH_G1_HAMMON_F32       3.372e-07 /* 2^-21.5 */
#define FACET_ERR_SMITH_G2_HAMMON_F32       4.769e-07 /* 2^-21 */
#define FACET_ERR_SMITH_VIS_HAMMON_F32      3.372e-07 /* 2^-21.5 */
#define FACET_ERR_DIFFUSE_HAMMON_F32        9.538e-07 /* 2^-20 */
#define FACET_ERR_BRDF_HAMMON_F32           2.698e-06 /* 2^-18.5 */
#define FACET_ERR_LAMBERT_F32               1.686e-07 /* 2^-22.5 */

/* N.H from the dots, without building H:
 *   N.H = (N.L + N.V) / sqrt(2 + 2 L.V)        (|L + V|^2 = 2 + 2 L.V)
 * Domain: N.L, N.V in [FACET_COS_MIN, 1], L.V in [-1, 1]; result in [0, 1].
 * Error: <= FACET_ERR_NOH_FROM_DOTS_F32 (2^-21.5); measured max 2^-22.12 (worst port,
 * 30 M samples) at (0.0587858558, 0.458401412, -0.495318681).
 * Cost: 13 ops (1 rsqrt, 0 rcp). */
float facet_noh_from_dots_f32(float nol, float nov, float lov);

/* L.H = V.H = |L + V| / 2 = sqrt((1 + L.V) / 2), via the same rsqrt.
 * Domain: L.V in [-1, 1]; L.V = -1 gives 0.
 * Error: <= FACET_ERR_LOH_FROM_DOTS_F32 (2^-22); measured max 2^-22.64 (worst port,
 * 30 M samples) at (0.0295905489).
 * Cost: 7 ops (1 rsqrt, 0 rcp). */
float facet_loh_from_dots_f32(float lov);

/* Schlick's Fresnel: F = F0 + (1 - F0) (1 - cos)^5, the power by three
 * multiplies.  Domain: f0, cos in [0, 1].  F(f0, 1) = f0, F(f0, 0) = 1.
 * Error: <= FACET_ERR_FRESNEL_SCHLICK_F32 (2^-21); measured max 2^-21.40 (worst port,
 * 30 M samples) at (2.34035488e-05, 0.494028538).
 * Cost: 13 ops (0 rsqrt, 0 rcp). */
float facet_fresnel_schlick_f32(float f0, float cos_theta);

/* GGX / Trowbridge-Reitz normal distribution:
 *   D = alpha^2 / (pi ((N.H)^2 (alpha^2 - 1) + 1)^2)
 * evaluated as (1/pi) (alpha / d)^2 with d = (1 - N.H)(1 + N.H) + (N.H alpha)^2,
 * which has no cancellation at the peak.  D(1) = 1/(pi alpha^2) (<= 3.3e5),
 * D(0) = alpha^2/pi.  Domain: N.H in [0, 1], alpha in [FACET_ALPHA_MIN, 1].
 * Error: <= FACET_ERR_GGX_D_F32 (2^-20); measured max 2^-20.60 (worst port,
 * 30 M samples) at (0.999949455, 0.254411191).
 * Cost: 12 ops (0 rsqrt, 1 rcp). */
float facet_ggx_d_f32(float noh, float alpha);

/* Exact Smith masking for GGX:
 *   G1 = 2 N.V / (N.V + sqrt(alpha^2 + (1 - alpha^2) N.V^2)) = 1 / (1 + Lambda)
 * Domain: N.V in [0, 1]; G1(0) = 0, G1(1) = 1.
 * Error: <= FACET_ERR_SMITH_G1_F32 (2^-21); measured max 2^-21.66 (worst port,
 * 30 M samples) at (0.000242657741, 0.00600074418).
 * Cost: 15 ops (1 rsqrt, 1 rcp). */
float facet_smith_g1_f32(float nov, float alpha);

/* Exact height-correlated Smith G2 for GGX:
 *   G2 = 2 N.L N.V / (N.V sqrt(alpha^2 + (1-alpha^2) N.L^2)
 *                   + N.L sqrt(alpha^2 + (1-alpha^2) N.V^2))  = 1/(1 + Lambda_L + Lambda_V)
 * Domain: N.L, N.V in [FACET_COS_MIN, 1].
 * Error: <= FACET_ERR_SMITH_G2_F32 (2^-21); measured max 2^-21.40 (worst port,
 * 30 M samples) at (0.492564738, 4.08501137e-06, 0.00407959009).
 * Cost: 26 ops (2 rsqrt, 1 rcp). */
float facet_smith_g2_f32(float nol, float nov, float alpha);

/* Uncorrelated Smith G2 = G1(N.L) G1(N.V), with one reciprocal.
 * Domain: as smith_g2.  Error: <= FACET_ERR_SMITH_G2_UNCORRELATED_F32 (2^-20.5); measured max 2^-20.95 (worst port,
 * 30 M samples) at (1.06287043e-05, 4.67698592e-05, 0.0156806652).
 * Cost: 26 ops (2 rsqrt, 1 rcp). */
float facet_smith_g2_uncorrelated_f32(float nol, float nov, float alpha);

/* Visibility: correlated G2 / (4 N.L N.V) with the numerator cancelled:
 *   Vis = 0.5 / (N.V sqrt(alpha^2 + (1-alpha^2) N.L^2) + N.L sqrt(...N.V...))
 * Domain: as smith_g2; largest at N.L = N.V = FACET_COS_MIN, alpha_min:
 * 0.5 / (2 COS_MIN alpha_min) = 2^28.  Error: <= FACET_ERR_SMITH_VIS_F32 (2^-21); measured max 2^-21.62 (worst port,
 * 30 M samples) at (3.14775752e-06, 0.126348287, 0.00824174657).
 * Cost: 23 ops (2 rsqrt, 1 rcp). */
float facet_smith_vis_f32(float nol, float nov, float alpha);

/* Hammon's G1 approximation (= Schlick-GGX with k = alpha/2):
 *   G1 ~ 2 N.V / (N.V (2 - alpha) + alpha)
 * Domain: N.V in [0, 1].  Error: <= FACET_ERR_SMITH_G1_HAMMON_F32 (2^-21.5); measured max 2^-22.26 (worst port,
 * 30 M samples) at (0.516059339, 0.018353641).
 * Cost: 9 ops (0 rsqrt, 1 rcp). */
float facet_smith_g1_hammon_f32(float nov, float alpha);

/* Hammon's G2 approximation:
 *   G2 ~ 2 N.L N.V / lerp(2 N.L N.V, N.L + N.V, alpha)
 * the lerp evaluated as (1 - alpha) 2 N.L N.V + alpha (N.L + N.V).
 * Domain: N.L, N.V in [FACET_COS_MIN, 1].  Error: <= FACET_ERR_SMITH_G2_HAMMON_F32 (2^-21); measured max 2^-21.83 (worst port,
 * 30 M samples) at (1.45550921e-05, 0.00873631984, 0.00181798683).
 * Cost: 16 ops (0 rsqrt, 1 rcp). */
float facet_smith_g2_hammon_f32(float nol, float nov, float alpha);

/* Hammon's visibility: G2_hammon / (4 N.L N.V) = 0.5 / lerp(2 N.L N.V, N.L + N.V, alpha).
 * Domain: as smith_g2_hammon; max 0.5/(2 alpha_min COS_MIN) = 2.7e8.
 * Error: <= FACET_ERR_SMITH_VIS_HAMMON_F32 (2^-21.5); measured max 2^-22.09 (worst port,
 * 30 M samples) at (0.713193238, 0.713202953, 0.00830200501).
 * Cost: 13 ops (0 rsqrt, 1 rcp). */
float facet_smith_vis_hammon_f32(float nol, float nov, float alpha);

/* ---- shadowing and visibility: the rest of the menu -------------------------
 * Karis's list of G terms (G as in D F G / (4 N.L N.V); the Vis kernels are
 * G / (4 N.L N.V) already), Beckmann's Smith G1 in Walter's and Schlick's
 * approximations, the joint approximation engines ship, and a fitted
 * visibility.  Each is evaluated as stated (implementation error: the
 * bound, vs the oracle of that same formula); where it approximates an
 * exact term, its model error against that term is in the report's
 * model-error table (`make report`) and the README. */
#define FACET_ERR_G_IMPLICIT_F32                         8.429e-08 /* 2^-23.5 */
#define FACET_ERR_G_NEUMANN_F32                          9.313e-10 /* 2^-30; exact, measured 0 */
#define FACET_ERR_G_COOK_TORRANCE_F32                    2.384e-07 /* 2^-22 */
#define FACET_ERR_G_KELEMEN_F32                          3.372e-07 /* 2^-21.5 */
#define FACET_ERR_SMITH_G1_BECKMANN_F32                  6.744e-07 /* 2^-20.5 */
#define FACET_ERR_SMITH_G1_SCHLICK_BECKMANN_F32          3.372e-07 /* 2^-21.5 */
#define FACET_ERR_SMITH_VIS_JOINT_APPROX_F32             3.372e-07 /* 2^-21.5 */
#define FACET_ERR_SMITH_VIS_FIT_F32                      4.769e-07 /* 2^-21 */
#define FACET_ERR_G_IMPLICIT_F32_FAST                    8.429e-08 /* 2^-23.5 */
#define FACET_ERR_G_NEUMANN_F32_FAST                     9.313e-10 /* 2^-30; exact, measured 0 */
#define FACET_ERR_G_COOK_TORRANCE_F32_FAST               1.221e-04 /* 2^-13 */
#define FACET_ERR_G_KELEMEN_F32_FAST                     1.221e-04 /* 2^-13 */
#define FACET_ERR_SMITH_G1_BECKMANN_F32_FAST             1.726e-04 /* 2^-12.5 */
#define FACET_ERR_SMITH_G1_SCHLICK_BECKMANN_F32_FAST     1.221e-04 /* 2^-13 */
#define FACET_ERR_SMITH_VIS_JOINT_APPROX_F32_FAST        1.221e-04 /* 2^-13 */
#define FACET_ERR_SMITH_VIS_FIT_F32_FAST                 1.221e-04 /* 2^-13 */

/* Implicit G = N.L N.V (no roughness: the plain cosine product).
 * Domain: N.L, N.V in [0, 1]; symmetric.  G(1, 1) = 1, G(0, x) = 0.
 * Error: <= FACET_ERR_G_IMPLICIT_F32 (2^-23.5; both tiers: one rounding).
 * Cost: 5 ops (0 rsqrt, 0 rcp). */
float facet_g_implicit_f32(float nol, float nov);

/* Neumann G = N.L N.V / max(N.L, N.V), which is min(N.L, N.V): evaluated
 * so, exact (0 at N.L = N.V = 0, where the quotient form is 0/0).
 * Domain: N.L, N.V in [0, 1]; symmetric.
 * Error: exact, measured 0; the tests enforce FACET_ERR_G_NEUMANN_F32 (2^-30), both tiers.  Cost: 5 ops (0 rsqrt, 0 rcp). */
float facet_g_neumann_f32(float nol, float nov);

/* Cook-Torrance (V-groove) G = min(1, 2 N.H N.V / V.H, 2 N.H N.L / V.H)
 *   = min(1, 2 N.H min(N.L, N.V) / V.H).
 * Domain: N.L, N.V in [FACET_COS_MIN, 1], N.H, V.H in [0, 1]; symmetric in
 * N.L, N.V.  Where 2 N.H min(N.L, N.V) >= V.H the result is 1 exactly
 * (V.H = 0 included); the reciprocal sees V.H >= FACET_COS_MIN only.
 * Error: <= FACET_ERR_G_COOK_TORRANCE_F32 (2^-22).
 * Cost: 19 ops (0 rsqrt, 1 rcp). */
float facet_g_cook_torrance_f32(float nol, float nov, float noh, float voh);

/* Kelemen G = N.L N.V / (V.H)^2 (Kelemen and Szirmay-Kalos: G / (4 N.L N.V)
 * = 1 / (4 (V.H)^2) = 1 / (2 (1 + L.V))), capped at 1: for any real pair
 * of vectors N.L N.V <= (V.H)^2, so the cap acts only on inconsistent
 * triples (V.H = 0 gives 1).  Domain: N.L, N.V in [FACET_COS_MIN, 1], V.H
 * in [0, 1]; symmetric in N.L, N.V.
 * Error: <= FACET_ERR_G_KELEMEN_F32 (2^-21.5).
 * Cost: 12 ops (0 rsqrt, 1 rcp). */
float facet_g_kelemen_f32(float nol, float nov, float voh);

/* Smith G1 for Beckmann, Walter's rational approximation of 1 / (1 + Lambda):
 *   c = N.V / (alpha sqrt(1 - N.V^2)),
 *   G1 = min(1, (3.535 c + 2.181 c^2) / (1 + 2.276 c + 2.577 c^2)) for c < 1.6,
 *   G1 = 1 for c >= 1.6
 * (alpha: the Beckmann width, alpha = roughness^2 as for GGX).  The cap at
 * 1 is facet's: the rational is above 1 by up to 6.1e-5 (at c = 1.589) for c in (1.548,
 * 1.631), and capped the two pieces meet continuously at c = 1.6.
 * Evaluated multiplied through by (alpha sqrt(1 - N.V^2))^2 (no infinity
 * at N.V = 1).  Domain: N.V in [0, 1], alpha in [FACET_ALPHA_MIN, 1];
 * G1(0) = 0, G1(1) = 1.  Model error vs the exact Beckmann G1
 * (1 / (1 + Lambda), Lambda from erf; facet_oracle_smith_g1_beckmann_exact):
 * see the README's model-error table.
 * Error: <= FACET_ERR_SMITH_G1_BECKMANN_F32 (2^-20.5).
 * Cost: 22 ops (1 rsqrt, 1 rcp). */
float facet_smith_g1_beckmann_f32(float nov, float alpha);

/* Schlick's approximation of Beckmann's Smith G1:
 *   G1 = N.V / (N.V (1 - k) + k),  k = alpha sqrt(2/pi).
 * The same function as smith_g1_hammon (Schlick-GGX, k = alpha/2) at
 * alpha' = 2 sqrt(2/pi) alpha = 1.596 alpha (for alpha <= 0.627, where
 * alpha' <= 1).  Domain: N.V in [0, 1], alpha in [FACET_ALPHA_MIN, 1];
 * G1(0) = 0, G1(1) = 1.  Model error vs the exact Beckmann G1: README.
 * Error: <= FACET_ERR_SMITH_G1_SCHLICK_BECKMANN_F32 (2^-21.5).
 * Cost: 9 ops (0 rsqrt, 1 rcp). */
float facet_smith_g1_schlick_beckmann_f32(float nov, float alpha);

/* The joint approximation of correlated Smith visibility (UE4's form):
 *   Vis = 0.5 / (N.L (N.V (1 - a) + a) + N.V (N.L (1 - a) + a))
 * which expands to 0.5 / ((1 - a) 2 N.L N.V + a (N.L + N.V)): the same
 * function as smith_vis_hammon (equal within both bounds), in this form.
 * Domain: as smith_vis_hammon; symmetric.  Model error vs exact smith_vis:
 * Hammon's, up to 29% (README).
 * Error: <= FACET_ERR_SMITH_VIS_JOINT_APPROX_F32 (2^-21.5).
 * Cost: 13 ops (0 rsqrt, 1 rcp). */
float facet_smith_vis_joint_approx_f32(float nol, float nov, float alpha);

/* A fitted visibility at Hammon's cost (one reciprocal, no square root):
 * exact correlated Smith is 0.5 / (N.V r(N.L) + N.L r(N.V)) with
 * r(x) = sqrt(a^2 + (1 - a^2) x^2), the length of (a, x sqrt(1 - a^2));
 * r is replaced by the largest of three lines,
 *   r~(x) = max(k1 a, k2 a + k3 t, k4 a + k5 t),  t = x (1 + a (c1 + c2 a)),
 *   Vis ~ 0.5 / (N.V r~(N.L) + N.L r~(N.V)),
 * with the constants minimax-fitted against the exact r over x in
 * [2^-8, 1], alpha in [2^-10, 1] (bench/fit/fit_vis.c reproduces them; the
 * model error of Vis is bounded by that of r, since Vis~/Vis - 1 lies
 * between the values of r/r~ - 1 at N.L and at N.V).
 * Model error vs exact smith_vis: <= FACET_MODEL_ERR_SMITH_VIS_FIT over
 * N.L, N.V in [2^-8, 1], alpha in [2^-10, 1] (tests/test_vis_fit.c).
 * Domain: as smith_vis; symmetric.
 * Error: <= FACET_ERR_SMITH_VIS_FIT_F32 (2^-21), vs the oracle of this formula.
 * Cost: 24 ops (0 rsqrt, 1 rcp). */
#define FACET_MODEL_ERR_SMITH_VIS_FIT 0.05
float facet_smith_vis_fit_f32(float nol, float nov, float alpha);

/* the fast tier (facet_<kernel>_f32_fast: see "the fast tier" below) and
 * the batches (see "batch API" below) of the kernels above.  Fast-tier
 * bounds (FACET_ERR_*_F32_FAST above): the kernels with a reciprocal
 * 2^-13, smith_g1_beckmann (rsqrt and rcp) 2^-12.5, measured worst on
 * avx512's unrefined estimates (2^-13.96 .. 2^-14.18 on this sweep). */
float facet_g_implicit_f32_fast(float nol, float nov);
float facet_g_neumann_f32_fast(float nol, float nov);
float facet_g_cook_torrance_f32_fast(float nol, float nov, float noh, float voh);
float facet_g_kelemen_f32_fast(float nol, float nov, float voh);
float facet_smith_g1_beckmann_f32_fast(float nov, float alpha);
float facet_smith_g1_schlick_beckmann_f32_fast(float nov, float alpha);
float facet_smith_vis_joint_approx_f32_fast(float nol, float nov, float alpha);
float facet_smith_vis_fit_f32_fast(float nol, float nov, float alpha);
void facet_g_implicit_f32_batch(float *out, const float *nol, const float *nov, size_t n);
void facet_g_neumann_f32_batch(float *out, const float *nol, const float *nov, size_t n);
void facet_g_cook_torrance_f32_batch(float *out, const float *nol, const float *nov,
                                     const float *noh, const float *voh, size_t n);
void facet_g_kelemen_f32_batch(float *out, const float *nol, const float *nov, const float *voh,
                               size_t n);
void facet_smith_g1_beckmann_f32_batch(float *out, const float *nov, const float *alpha, size_t n);
void facet_smith_g1_schlick_beckmann_f32_batch(float *out, const float *nov, const float *alpha,
                                               size_t n);
void facet_smith_vis_joint_approx_f32_batch(float *out, const float *nol, const float *nov,
                                            const float *alpha, size_t n);
void facet_smith_vis_fit_f32_batch(float *out, const float *nol, const float *nov,
                                   const float *alpha, size_t n);
void facet_g_implicit_f32_fast_batch(float *out, const float *nol, const float *nov, size_t n);
void facet_g_neumann_f32_fast_batch(float *out, const float *nol, const float *nov, size_t n);
void facet_g_cook_torrance_f32_fast_batch(float *out, const float *nol, const float *nov,
                                          const float *noh, const float *voh, size_t n);
void facet_g_kelemen_f32_fast_batch(float *out, const float *nol, const float *nov,
                                    const float *voh, size_t n);
void facet_smith_g1_beckmann_f32_fast_batch(float *out, const float *nov, const float *alpha,
                                            size_t n);
void facet_smith_g1_schlick_beckmann_f32_fast_batch(float *out, const float *nov,
                                                    const float *alpha, size_t n);
void facet_smith_vis_joint_approx_f32_fast_batch(float *out, const float *nol, const float *nov,
                                                 const float *alpha, size_t n);
void facet_smith_vis_fit_f32_fast_batch(float *out, const float *nol, const float *nov,
                                        const float *alpha, size_t n);

/* Hammon's GGX diffuse (a BRDF value, not yet times N.L):
 *   facing = 0.5 + 0.5 L.V
 *   rough  = facing (0.9 - 0.4 facing) (0.5 + N.H) / N.H
 *   smooth = 1.05 (1 - (1 - N.L)^5) (1 - (1 - N.V)^5)
 *   single = lerp(smooth, rough, alpha) / pi
 *   multi  = 0.1159 alpha
 *   result = albedo (single + albedo multi)
 * N.H from the identity above; 1 - (1-x)^5 as x (1 + y + y^2 + y^3 + y^4),
 * y = 1 - x, so it keeps its precision at grazing angles.
 * Domain: N.L, N.V in [FACET_COS_MIN, 1], L.V in [-1, 1], alpha, albedo.
 * Error: <= FACET_ERR_DIFFUSE_HAMMON_F32 (2^-20); measured max 2^-20.59 (worst port,
 * 30 M samples) at (0.331329554, 0.331329554, 0.999999702, 0.0131228399, 0.645663142).
 * Cost: 44 ops (1 rsqrt, 1 rcp). */
float facet_diffuse_hammon_f32(float nol, float nov, float lov, float alpha, float albedo);

/* The whole model, per light:
 *   brdf = D(N.H) Vis_hammon(N.L, N.V) F(f0, L.H) + diffuse_hammon
 * (a BRDF value; radiance = brdf * N.L * light).  D is evaluated from the
 * dots without forming N.H (see f32_body.h: the peak for small alpha is
 * ill-conditioned in N.H, so 2 + 2 L.V - (N.L + N.V)^2 is formed exactly);
 * one rsqrt, and three reciprocals: 1/(e m) serves both D and Vis, 1/(1 + L.H)
 * gives 1 - L.H without cancellation for the Fresnel tail, 1/(N.L + N.V)
 * gives 1/N.H for the diffuse.
 * Domain: N.L, N.V in [FACET_COS_MIN, 1], L.V in [-1, 1], alpha, f0, albedo.
 * Error: <= FACET_ERR_BRDF_HAMMON_F32 (2^-18.5); measured max 2^-19.30 (worst port,
 * 30 M samples) at (0.683041394, 0.683041394, -0.0669089183, 0.00208292552, 3.8500432e-11, 4.40309833e-09).
 * Cost: 97 ops (1 rsqrt, 3 rcp). */
float facet_brdf_hammon_f32(float nol, float nov, float lov, float alpha,
                            float f0, float albedo);

/* brdf_hammon for an RGB f0 and albedo, the geometry (D, Vis, 1 - L.H, the
 * diffuse shape) computed once: out[c] equals
 * facet_brdf_hammon_f32(nol, nov, lov, alpha, f0[c], albedo[c]) bit for bit.
 * Every port header has the same as facet_brdf_hammon_rgb_f32_<port>(out[3],
 * ..., const V f0[3], const V albedo[3]) on its vector type. */
void facet_brdf_hammon_rgb_f32(float out[3], float nol, float nov, float lov,
                               float alpha, const float f0[3], const float albedo[3]);

/* Lambert: albedo / pi.  Domain: albedo in [0, 1].
 * Error: <= FACET_ERR_LAMBERT_F32 (2^-22.5); measured max 2^-23.26 (worst port,
 * 30 M samples) at (0.196352884).
 * Cost: 3 ops (0 rsqrt, 0 rcp). */
float facet_lambert_f32(float albedo);

/* ---- batch API -------------------------------------------------------------
 * facet_<kernel>_f32_batch(out, in1, ..., n): out[i] = kernel(in1[i], ...)
 * for i < n, structure-of-arrays, inputs in the order above.  Any n (tails
 * are handled), no alignment requirement.  out may be exactly the same array
 * as any input (out == in: each element is read before it is written); no
 * other overlap (out shifted against an input gives results that depend on
 * the port's vector width).  Runs on
 * the best port for this CPU, chosen once and thread-safely on first use:
 * avx512 > avx2 > sse2 on x86, neon on ARM, else scalar.  Every port meets the
 * bounds above (tests/test_f32_accuracy.c runs each kernel on each port);
 * results may differ between ports by rounding, within those bounds. */
void facet_noh_from_dots_f32_batch(float *out, const float *nol, const float *nov,
                                   const float *lov, size_t n);
void facet_loh_from_dots_f32_batch(float *out, const float *lov, size_t n);
void facet_fresnel_schlick_f32_batch(float *out, const float *f0, const float *cos_theta, size_t n);
void facet_ggx_d_f32_batch(float *out, const float *noh, const float *alpha, size_t n);
void facet_smith_g1_f32_batch(float *out, const float *nov, const float *alpha, size_t n);
void facet_smith_g2_f32_batch(float *out, const float *nol, const float *nov, const float *alpha,
                              size_t n);
void facet_smith_g2_uncorrelated_f32_batch(float *out, const float *nol, const float *nov,
                                           const float *alpha, size_t n);
void facet_smith_vis_f32_batch(float *out, const float *nol, const float *nov, const float *alpha,
                               size_t n);
void facet_smith_g1_hammon_f32_batch(float *out, const float *nov, const float *alpha, size_t n);
void facet_smith_g2_hammon_f32_batch(float *out, const float *nol, const float *nov,
                                     const float *alpha, size_t n);
void facet_smith_vis_hammon_f32_batch(float *out, const float *nol, const float *nov,
                                      const float *alpha, size_t n);
void facet_diffuse_hammon_f32_batch(float *out, const float *nol, const float *nov,
                                    const float *lov, const float *alpha, const float *albedo,
                                    size_t n);
void facet_brdf_hammon_f32_batch(float *out, const float *nol, const float *nov, const float *lov,
                                 const float *alpha, const float *f0, const float *albedo, size_t n);
void facet_lambert_f32_batch(float *out, const float *albedo, size_t n);

/* ---- the fast tier (f32_fast) ------------------------------------------
 * facet_<kernel>_f32_fast, facet_<kernel>_f32_fast_batch and, in each port
 * header, facet_<kernel>_f32_fast_<port>: the same formula, domain,
 * out-of-domain behaviour (finite, >= 0 for every input), symmetry and
 * operation count as the precise kernel above, the same formulation (the
 * specular peak's cancellation is still formed exactly), and each port's
 * cheaper reciprocal and rsqrt: scalar rsqrt with 2 Newton steps (not 3,
 * the reciprocal is the division in both tiers); sse2 rcpps / rsqrtps and
 * avx2 estimates with one Newton step (the precise tier: IEEE division /
 * square root, and one third-order step); avx512 the 14-bit estimates
 * unrefined (the precise tier: one Newton step); neon 2 steps (not 3).  Where an error is raised to the fifth
 * power (brdf_hammon's 1 - L.H) both tiers refine fully.  fresnel_schlick
 * and lambert have no reciprocal: both tiers are the same code.  Bounds:
 * relative error vs the oracle, measured over the precise tier's sweep on
 * every port, also with estimates at the architectural bound (worst:
 * avx512, e.g. smith_g2_uncorrelated 2^-12.43, brdf_hammon 2^-13.00),
 * enforced by the same tests; all <= 2^-12. */
#define FACET_ERR_NOH_FROM_DOTS_F32_FAST          8.632e-05 /* 2^-13.5 */
#define FACET_ERR_LOH_FROM_DOTS_F32_FAST          8.632e-05 /* 2^-13.5 */
#define FACET_ERR_FRESNEL_SCHLICK_F32_FAST        4.769e-07 /* 2^-21 */
#define FACET_ERR_GGX_D_F32_FAST                  1.726e-04 /* 2^-12.5 */
#define FACET_ERR_SMITH_G1_F32_FAST               1.726e-04 /* 2^-12.5 */
#define FACET_ERR_SMITH_G2_F32_FAST               1.726e-04 /* 2^-12.5 */
#define FACET_ERR_SMITH_G2_UNCORRELATED_F32_FAST  2.441e-04 /* 2^-12 */
#define FACET_ERR_SMITH_VIS_F32_FAST              1.726e-04 /* 2^-12.5 */
#define FACET_ERR_SMITH_G1_HAMMON_F32_FAST        8.632e-05 /* 2^-13.5 */
#define FACET_ERR_SMITH_G2_HAMMON_F32_FAST        8.632e-05 /* 2^-13.5 */
#define FACET_ERR_SMITH_VIS_HAMMON_F32_FAST       8.632e-05 /* 2^-13.5 */
#define FACET_ERR_DIFFUSE_HAMMON_F32_FAST         1.726e-04 /* 2^-12.5 */
#define FACET_ERR_BRDF_HAMMON_F32_FAST            1.726e-04 /* 2^-12.5 */
#define FACET_ERR_LAMBERT_F32_FAST                1.686e-07 /* 2^-22.5 */

float facet_noh_from_dots_f32_fast(float nol, float nov, float lov);
float facet_loh_from_dots_f32_fast(float lov);
float facet_fresnel_schlick_f32_fast(float f0, float cos_theta);
float facet_ggx_d_f32_fast(float noh, float alpha);
float facet_smith_g1_f32_fast(float nov, float alpha);
float facet_smith_g2_f32_fast(float nol, float nov, float alpha);
float facet_smith_g2_uncorrelated_f32_fast(float nol, float nov, float alpha);
float facet_smith_vis_f32_fast(float nol, float nov, float alpha);
float facet_smith_g1_hammon_f32_fast(float nov, float alpha);
float facet_smith_g2_hammon_f32_fast(float nol, float nov, float alpha);
float facet_smith_vis_hammon_f32_fast(float nol, float nov, float alpha);
float facet_diffuse_hammon_f32_fast(float nol, float nov, float lov, float alpha, float albedo);
float facet_brdf_hammon_f32_fast(float nol, float nov, float lov, float alpha,
                            float f0, float albedo);
float facet_lambert_f32_fast(float albedo);
void facet_brdf_hammon_rgb_f32_fast(float out[3], float nol, float nov, float lov,
                               float alpha, const float f0[3], const float albedo[3]);
void facet_noh_from_dots_f32_fast_batch(float *out, const float *nol, const float *nov,
                                   const float *lov, size_t n);
void facet_loh_from_dots_f32_fast_batch(float *out, const float *lov, size_t n);
void facet_fresnel_schlick_f32_fast_batch(float *out, const float *f0, const float *cos_theta, size_t n);
void facet_ggx_d_f32_fast_batch(float *out, const float *noh, const float *alpha, size_t n);
void facet_smith_g1_f32_fast_batch(float *out, const float *nov, const float *alpha, size_t n);
void facet_smith_g2_f32_fast_batch(float *out, const float *nol, const float *nov, const float *alpha,
                              size_t n);
void facet_smith_g2_uncorrelated_f32_fast_batch(float *out, const float *nol, const float *nov,
                                           const float *alpha, size_t n);
void facet_smith_vis_f32_fast_batch(float *out, const float *nol, const float *nov, const float *alpha,
                               size_t n);
void facet_smith_g1_hammon_f32_fast_batch(float *out, const float *nov, const float *alpha, size_t n);
void facet_smith_g2_hammon_f32_fast_batch(float *out, const float *nol, const float *nov,
                                     const float *alpha, size_t n);
void facet_smith_vis_hammon_f32_fast_batch(float *out, const float *nol, const float *nov,
                                      const float *alpha, size_t n);
void facet_diffuse_hammon_f32_fast_batch(float *out, const float *nol, const float *nov,
                                    const float *lov, const float *alpha, const float *albedo,
                                    size_t n);
void facet_brdf_hammon_f32_fast_batch(float *out, const float *nol, const float *nov, const float *lov,
                                 const float *alpha, const float *f0, const float *albedo, size_t n);
void facet_lambert_f32_fast_batch(float *out, const float *albedo, size_t n);

/* Ports.  facet_set_port(name) forces one for all batch calls in the process:
 * "scalar", "sse2", "avx2", "avx512", "neon", or "auto" (the automatic choice).  Returns
 * 0 on success, 1 for a name not compiled into this build, 2 for a port this
 * CPU cannot run (the active port is then unchanged).  The environment
 * variable FACET_PORT names the initial choice the same way; an unknown or
 * unsupported name there is not an error for the library: it falls back to
 * auto, and facet_port_name() tells which port runs.  (The facet command is
 * stricter: its f32 eval refuses such a FACET_PORT with exit status 2, and
 * `facet ports` says which case applies.)
 * facet_port_at(i, &supported, &lanes) lists the ports compiled in, best
 * first (NULL past the end). */
int facet_set_port(const char *name);
const char *facet_port_name(void);
size_t facet_port_count(void);
const char *facet_port_at(size_t i, int *supported, int *lanes);
/* 1 if the port is compiled in and this CPU (and OS) runs it: the one answer
 * the library, the bench and the rasterizer all use (CPUID/XCR0, HWCAP). */
int facet_port_supported(const char *name);

/* ---- the kernel table ----------------------------------------------------
 * One entry per kernel, in `facet list` order, for tools that drive every
 * kernel the same way (the facet command, the tests, the benchmarks). */
#define FACET_MAX_INPUTS 6

typedef struct facet_kernel {
    const char *name;                          /* "ggx_d" */
    int n_inputs;
    const char *inputs[FACET_MAX_INPUTS];      /* "noh", "alpha" */
    float (*f32)(const float *in);             /* scalar f32 kernel */
    double (*oracle)(const double *in);        /* double oracle */
    /* batch on the active port: out[i] = kernel(in[0][i], in[1][i], ...) */
    void (*f32_batch)(float *out, const float *const *in, size_t n);
    double err_f32;                            /* FACET_ERR_<NAME>_F32 */
    float (*f32_fast)(const float *in);        /* scalar f32_fast kernel */
    void (*f32_fast_batch)(float *out, const float *const *in, size_t n);
    double err_f32_fast;                       /* FACET_ERR_<NAME>_F32_FAST */
} facet_kernel;

size_t facet_kernel_count(void);
const facet_kernel *facet_kernel_at(size_t i);
const facet_kernel *facet_kernel_find(const char *name); /* NULL if unknown */

/* ---- GGX and GTR importance sampling ----------------------------------------
 * Samplers of half vectors h (the microfacet normal) in the shading frame
 * (N = +z) and their pdfs (per unit solid angle of h), f32 in both tiers,
 * inline in every port header (facet_<sampler>_f32_<port>(V h[3], ...),
 * facet_<pdf>_f32_<port>(...)), scalar and batch here.  Body:
 * include/facet/detail/f32_sample_body.h, with every formula's derivation.
 * No libm: sin/cos(2 pi u) by exact quadrant folding and two polynomials,
 * 2^y and log2 by exponent bits and polynomials (errors stated there).
 *
 * Conventions for all samplers
 *   - u1, u2 are uniform in [0, 1): clamped to [0, 1 - 2^-24], NaN and
 *     -Inf to 0, +Inf to 1 - 2^-24.  u1 picks the polar angle (u1 = 0: the
 *     law's pole), u2 the azimuth phi = 2 pi u2.
 *   - alpha, alpha_x, alpha_y: as the kernels, clamped to
 *     [FACET_ALPHA_MIN, 1] (NaN to FACET_ALPHA_MIN).
 *   - Every sampled h is a unit vector (||h| - 1| <= 2^-22 in both tiers:
 *     the final normalization uses the precise rsqrt in f32_fast too) with
 *     h.z > 0, for every input including NaN and Inf (tests/test_sample_ports.c).
 *   - Error of a sampled vector: the Euclidean distance from the oracle's
 *     vector at the same float inputs (facet/oracle.h; about the angle in
 *     radians) divided by max(1, K / 16), where K is the oracle map's own
 *     sensitivity: the sum over inputs of |h(x + d_i) - h(x)| / 2^-24 with
 *     d_i = 2^-24 for u1, u2 and 2^-24 |x_i| for the others.  That is the
 *     plain distance wherever one input ulp moves h by less than 16 ulps
 *     (all of the D samplers but the last ulps of u1 at small alpha), and
 *     relative to the map's conditioning where it is not (e.g. the VNDF map
 *     near the cap rim).  pdfs: relative error vs the oracle, as the
 *     kernels; ggx_pdf_vndf_aniso forms v.h itself, so its error is
 *     relative to that dot product's conditioning sum |v_i h_i| / |v.h|.
 *     Bounds: maximum over tests/test_sample_accuracy.c's sweep (200 k
 *     samples per sampler aimed at the ends of u, grazing and normal views,
 *     alpha log-uniform) on every port, in the fast tier also with
 *     estimates at the architectural bound; FACET_ERR_<SAMPLER>_F32[_FAST].
 *   - The sampled distributions are checked by chi-square goodness of fit
 *     against the pdfs (tests/test_sample_chi2.c: 10^6 samples, 2-D
 *     histograms in (theta, phi), alpha 0.05 .. 1, views to 89.9 degrees,
 *     p > 0.01 each; moments for alpha down to 0.002), and the VNDF
 *     estimator by a white furnace (tests/test_sample_furnace.c).
 *   - Cost: operations as the kernels' (tests/test_sample_prims.c counts
 *     them; the exponent-bit ops exp2i, getexp, getmant count 1).
 *
 * ggx_sample_d(h, u1, u2, alpha): GGX D importance sampling,
 *   h = normalize(alpha sqrt(u1) cos phi, alpha sqrt(u1) sin phi, sqrt(1 - u1)),
 *   i.e. tan^2 theta_h = alpha^2 u1 / (1 - u1), cos^2 theta_h =
 *   (1 - u1) / (1 + (alpha^2 - 1) u1).  pdf: ggx_pdf_d.
 *   Error <= 2^-22 (f32; measured 2^-22.52, sse2), 2^-13.5 (fast; 2^-14.01, avx512).
 *   Cost: 46 ops (3 rsqrt, 0 rcp).
 * ggx_pdf_d(noh, alpha) = D(h) N.H, D computed by ggx_d's code: the result
 *   is fl(ggx_d(noh, alpha) * noh) to the bit (noh clamped to [0, 1]).
 *   Error <= 2^-20 (f32; measured 2^-20.86, every port), 2^-12.5 (fast; 2^-13.01, avx512).
 *   Cost: 15 ops (0 rsqrt, 1 rcp).
 * ggx_sample_d_aniso(h, u1, u2, alpha_x, alpha_y): the same with
 *   (alpha_x, alpha_y) on the x and y components (the stretched slope law);
 *   ggx_sample_d(.., alpha) = ggx_sample_d_aniso(.., alpha, alpha).
 *   Error <= 2^-21.5 (f32; measured 2^-22.23, sse2), 2^-13.5 (fast; 2^-14.01, avx512).
 *   Cost: 48 ops (3 rsqrt, 0 rcp).
 * ggx_pdf_d_aniso(hx, hy, hz, alpha_x, alpha_y) = D(h) h.z = h.z / (pi ax ay k^2),
 *   k = (hx/ax)^2 + (hy/ay)^2 + hz^2 (h unit; hx, hy clamped to [-1, 1],
 *   hz to [0, 1], k floored at 1/2).
 *   Error <= 2^-20 (f32; measured 2^-20.76, sse2), 2^-13.5 (fast; 2^-14.00, avx512).
 *   Cost: 27 ops (0 rsqrt, 1 rcp).
 *
 * ggx_sample_vndf(h, vx, vy, vz, u1, u2, alpha): visible-normal sampling
 *   for the view v (Heitz 2018, in the spherical-cap form: Vh =
 *   normalize(alpha vx, alpha vy, vz), c uniform on the unit sphere with
 *   c.z > -Vh.z (c.z = (1 - u1)(1 + Vh.z) - Vh.z, azimuth phi measured from
 *   Vh's), h = normalize(alpha (Vh + c).x, alpha (Vh + c).y, (Vh + c).z);
 *   the body shows it has Heitz's law, with 4 rsqrt and 2 rcp instead of 6
 *   rsqrt, and no cancellation where Vh + c is short).
 *   v: only its direction is used; components clamped to [-1, 1] (NaN
 *   -> -1); v below the horizon (vz < 0) is sampled as vz = 0, the grazing
 *   view at its azimuth (the caller's pdf must then use N.V = 0); a
 *   (stretched) v shorter than 2^-50 acts as (0, 0, 1).
 *   Error <= 2^-21.5 (f32; measured 2^-21.97, sse2), 2^-12 (fast; 2^-12.76, avx512).
 *   Cost: 102 ops (4 rsqrt, 2 rcp).
 * ggx_sample_vndf_aniso(h, vx, vy, vz, u1, u2, alpha_x, alpha_y): the same
 *   with (alpha_x, alpha_y).
 *   Error <= 2^-21 (f32; measured 2^-21.39, sse2), 2^-12 (fast; 2^-12.43, avx512).
 *   Cost: 104 ops (4 rsqrt, 2 rcp).
 * ggx_pdf_vndf(nov, noh, voh, alpha) = G1(v) max(0, V.H) D(h) / N.V
 *   = 2 max(0, V.H) D / (N.V + sqrt(alpha^2 + (1 - alpha^2) N.V^2)),
 *   with smith_g1's and ggx_d's own terms; finite at N.V = 0 (2 V.H D /
 *   alpha).  nov, voh clamped to [0, 1], noh as ggx_d.
 *   Error <= 2^-20 (f32; measured 2^-20.60, every port), 2^-12 (fast; 2^-12.43, avx512).
 *   Cost: 29 ops (1 rsqrt, 2 rcp).
 * ggx_pdf_vndf_aniso(vx, vy, vz, hx, hy, hz, alpha_x, alpha_y): the same,
 *   anisotropic: 2 max(0, v.h) D(h) / (vz + sqrt(ax^2 vx^2 + ay^2 vy^2 + vz^2))
 *   (v, h unit; clamped as the samplers; the denominator floored at 2^-20).
 *   Error <= 2^-20 (f32; measured 2^-20.74, sse2), 2^-12.5 (fast; 2^-13.01, avx512).
 *   Cost: 47 ops (1 rsqrt, 1 rcp).
 * reflect(l, vx, vy, vz, hx, hy, hz): l = 2 (v.h) h - v (inputs clamped
 *   to [-1, 1]); the reflected direction of a sampled h.
 *   Error <= 2^-21.5 (both tiers: no rcp or rsqrt; measured 2^-21.88, sse2).
 *   Cost: 22 ops.
 * ggx_pdf_vndf_reflect(nov, noh, voh, alpha): the pdf of that l,
 *   ggx_pdf_vndf / (4 V.H) = D G1(v) / (4 N.V); 0 where V.H <= 0.  The
 *   estimator f N.L / pdf of the GGX specular term is then G2 / G1(v).
 *   Error <= 2^-20 (f32; measured 2^-20.65, sse2), 2^-12 (fast; 2^-12.43, avx512).
 *   Cost: 28 ops (1 rsqrt, 2 rcp).
 *
 * gtr_sample_d(h, u1, u2, alpha, gamma): GTR D (prop. to
 *   1 / (1 + (alpha^2 - 1) cos^2 theta)^gamma) sampling where the inverse CDF
 *   has a closed form: gamma < 1.5 samples gamma = 1 (GTR1, "Berry"),
 *   cos^2 theta = (1 - alpha^(2 (1 - u1))) / (1 - alpha^2) (1 - u1 at
 *   alpha = 1), evaluated without cancellation through (2^y - 1) / y;
 *   otherwise (NaN too) gamma = 2, i.e. ggx_sample_d to the bit.
 *   Error <= 2^-21 (f32; measured 2^-21.59, scalar), 2^-12.5 (fast; 2^-13.29, avx512).
 *   Cost: 136 ops (5 rsqrt, 3 rcp).
 * gtr_pdf_d(noh, alpha, gamma) = D_gtr(h) N.H, D_GTR1 = (alpha^2 - 1) /
 *   (pi ln(alpha^2) (1 + (alpha^2 - 1) N.H^2)) (1/pi at alpha = 1);
 *   gamma as gtr_sample_d (GTR2: ggx_pdf_d).
 *   Error <= 2^-20 (f32; measured 2^-20.80, every port), 2^-12 (fast; 2^-12.80, avx512).
 *   Cost: 74 ops (0 rsqrt, 4 rcp).
 * sincos_2pi(sc, u): sc[0] = sin(2 pi u), sc[1] = cos(2 pi u), u as u1;
 *   the samplers' azimuth, exposed for tests and tools.  The sine keeps
 *   2^-21 relative accuracy near u = 0; sin^2 + cos^2 = 1 within 2^-22.
 *   Error <= 2^-23 (both tiers; measured 2^-23.31, sse2, on every 5th
 *   multiple of 2^-24).
 *   Cost: 27 ops.
 *
 * Batch: SoA outputs first, then the inputs in the order above; any n, no
 * alignment requirement, outputs may alias inputs; runs on the port the
 * kernels run on (facet_set_port, FACET_PORT). */
#define FACET_ERR_GGX_SAMPLE_D_F32               2.384e-07 /* 2^-22, distance */
#define FACET_ERR_GGX_PDF_D_F32                  9.537e-07 /* 2^-20 */
#define FACET_ERR_GGX_SAMPLE_VNDF_F32            3.372e-07 /* 2^-21.5, distance */
#define FACET_ERR_GGX_PDF_VNDF_F32               9.537e-07 /* 2^-20 */
#define FACET_ERR_GGX_PDF_VNDF_REFLECT_F32       9.537e-07 /* 2^-20 */
#define FACET_ERR_REFLECT_F32                    3.372e-07 /* 2^-21.5, distance */
#define FACET_ERR_GGX_SAMPLE_D_ANISO_F32         3.372e-07 /* 2^-21.5, distance */
#define FACET_ERR_GGX_PDF_D_ANISO_F32            9.537e-07 /* 2^-20 */
#define FACET_ERR_GGX_SAMPLE_VNDF_ANISO_F32      4.768e-07 /* 2^-21, distance */
#define FACET_ERR_GGX_PDF_VNDF_ANISO_F32         9.537e-07 /* 2^-20 */
#define FACET_ERR_GTR_SAMPLE_D_F32               4.768e-07 /* 2^-21, distance */
#define FACET_ERR_GTR_PDF_D_F32                  9.537e-07 /* 2^-20 */
#define FACET_ERR_SINCOS_2PI_F32                 1.192e-07 /* 2^-23, distance */

#define FACET_ERR_GGX_SAMPLE_D_F32_FAST          8.632e-05 /* 2^-13.5, distance */
#define FACET_ERR_GGX_PDF_D_F32_FAST             1.726e-04 /* 2^-12.5 */
#define FACET_ERR_GGX_SAMPLE_VNDF_F32_FAST       2.441e-04 /* 2^-12, distance */
#define FACET_ERR_GGX_PDF_VNDF_F32_FAST          2.441e-04 /* 2^-12 */
#define FACET_ERR_GGX_PDF_VNDF_REFLECT_F32_FAST  2.441e-04 /* 2^-12 */
#define FACET_ERR_REFLECT_F32_FAST               3.372e-07 /* 2^-21.5, distance */
#define FACET_ERR_GGX_SAMPLE_D_ANISO_F32_FAST    8.632e-05 /* 2^-13.5, distance */
#define FACET_ERR_GGX_PDF_D_ANISO_F32_FAST       8.632e-05 /* 2^-13.5 */
#define FACET_ERR_GGX_SAMPLE_VNDF_ANISO_F32_FAST 2.441e-04 /* 2^-12, distance */
#define FACET_ERR_GGX_PDF_VNDF_ANISO_F32_FAST    1.726e-04 /* 2^-12.5 */
#define FACET_ERR_GTR_SAMPLE_D_F32_FAST          1.726e-04 /* 2^-12.5, distance */
#define FACET_ERR_GTR_PDF_D_F32_FAST             2.441e-04 /* 2^-12 */
#define FACET_ERR_SINCOS_2PI_F32_FAST            1.192e-07 /* 2^-23, distance */

void facet_ggx_sample_d_f32(float h[3], float u1, float u2, float alpha);
float facet_ggx_pdf_d_f32(float noh, float alpha);
void facet_ggx_sample_vndf_f32(float h[3], float vx, float vy, float vz, float u1, float u2,
                               float alpha);
float facet_ggx_pdf_vndf_f32(float nov, float noh, float voh, float alpha);
float facet_ggx_pdf_vndf_reflect_f32(float nov, float noh, float voh, float alpha);
void facet_reflect_f32(float l[3], float vx, float vy, float vz, float hx, float hy, float hz);
void facet_ggx_sample_d_aniso_f32(float h[3], float u1, float u2, float alpha_x, float alpha_y);
float facet_ggx_pdf_d_aniso_f32(float hx, float hy, float hz, float alpha_x, float alpha_y);
void facet_ggx_sample_vndf_aniso_f32(float h[3], float vx, float vy, float vz, float u1, float u2,
                                     float alpha_x, float alpha_y);
float facet_ggx_pdf_vndf_aniso_f32(float vx, float vy, float vz, float hx, float hy, float hz,
                                   float alpha_x, float alpha_y);
void facet_gtr_sample_d_f32(float h[3], float u1, float u2, float alpha, float gamma);
float facet_gtr_pdf_d_f32(float noh, float alpha, float gamma);
void facet_sincos_2pi_f32(float sc[2], float u);

void facet_ggx_sample_d_f32_fast(float h[3], float u1, float u2, float alpha);
float facet_ggx_pdf_d_f32_fast(float noh, float alpha);
void facet_ggx_sample_vndf_f32_fast(float h[3], float vx, float vy, float vz, float u1, float u2,
                                    float alpha);
float facet_ggx_pdf_vndf_f32_fast(float nov, float noh, float voh, float alpha);
float facet_ggx_pdf_vndf_reflect_f32_fast(float nov, float noh, float voh, float alpha);
void facet_reflect_f32_fast(float l[3], float vx, float vy, float vz, float hx, float hy, float hz);
void facet_ggx_sample_d_aniso_f32_fast(float h[3], float u1, float u2, float alpha_x, float alpha_y);
float facet_ggx_pdf_d_aniso_f32_fast(float hx, float hy, float hz, float alpha_x, float alpha_y);
void facet_ggx_sample_vndf_aniso_f32_fast(float h[3], float vx, float vy, float vz, float u1,
                                          float u2, float alpha_x, float alpha_y);
float facet_ggx_pdf_vndf_aniso_f32_fast(float vx, float vy, float vz, float hx, float hy, float hz,
                                        float alpha_x, float alpha_y);
void facet_gtr_sample_d_f32_fast(float h[3], float u1, float u2, float alpha, float gamma);
float facet_gtr_pdf_d_f32_fast(float noh, float alpha, float gamma);
void facet_sincos_2pi_f32_fast(float sc[2], float u);

/* batch: structure-of-arrays outputs first (hx, hy, hz / lx, ly, lz / out /
 * sin, cos), then the inputs; the _f32_fast_batch twins take the same. */
void facet_ggx_sample_d_f32_batch(float *hx, float *hy, float *hz, const float *u1,
                                  const float *u2, const float *alpha, size_t n);
void facet_ggx_pdf_d_f32_batch(float *out, const float *noh, const float *alpha, size_t n);
void facet_ggx_sample_vndf_f32_batch(float *hx, float *hy, float *hz, const float *vx,
                                     const float *vy, const float *vz, const float *u1,
                                     const float *u2, const float *alpha, size_t n);
void facet_ggx_pdf_vndf_f32_batch(float *out, const float *nov, const float *noh,
                                  const float *voh, const float *alpha, size_t n);
void facet_ggx_pdf_vndf_reflect_f32_batch(float *out, const float *nov, const float *noh,
                                          const float *voh, const float *alpha, size_t n);
void facet_reflect_f32_batch(float *lx, float *ly, float *lz, const float *vx, const float *vy,
                             const float *vz, const float *hx, const float *hy, const float *hz,
                             size_t n);
void facet_ggx_sample_d_aniso_f32_batch(float *hx, float *hy, float *hz, const float *u1,
                                        const float *u2, const float *alpha_x,
                                        const float *alpha_y, size_t n);
void facet_ggx_pdf_d_aniso_f32_batch(float *out, const float *hx, const float *hy,
                                     const float *hz, const float *alpha_x,
                                     const float *alpha_y, size_t n);
void facet_ggx_sample_vndf_aniso_f32_batch(float *hx, float *hy, float *hz, const float *vx,
                                           const float *vy, const float *vz, const float *u1,
                                           const float *u2, const float *alpha_x,
                                           const float *alpha_y, size_t n);
void facet_ggx_pdf_vndf_aniso_f32_batch(float *out, const float *vx, const float *vy,
                                        const float *vz, const float *hx, const float *hy,
                                        const float *hz, const float *alpha_x,
                                        const float *alpha_y, size_t n);
void facet_gtr_sample_d_f32_batch(float *hx, float *hy, float *hz, const float *u1,
                                  const float *u2, const float *alpha, const float *gamma,
                                  size_t n);
void facet_gtr_pdf_d_f32_batch(float *out, const float *noh, const float *alpha,
                               const float *gamma, size_t n);
void facet_sincos_2pi_f32_batch(float *s, float *c, const float *u, size_t n);

void facet_ggx_sample_d_f32_fast_batch(float *hx, float *hy, float *hz, const float *u1,
                                       const float *u2, const float *alpha, size_t n);
void facet_ggx_pdf_d_f32_fast_batch(float *out, const float *noh, const float *alpha, size_t n);
void facet_ggx_sample_vndf_f32_fast_batch(float *hx, float *hy, float *hz, const float *vx,
                                          const float *vy, const float *vz, const float *u1,
                                          const float *u2, const float *alpha, size_t n);
void facet_ggx_pdf_vndf_f32_fast_batch(float *out, const float *nov, const float *noh,
                                       const float *voh, const float *alpha, size_t n);
void facet_ggx_pdf_vndf_reflect_f32_fast_batch(float *out, const float *nov, const float *noh,
                                               const float *voh, const float *alpha, size_t n);
void facet_reflect_f32_fast_batch(float *lx, float *ly, float *lz, const float *vx,
                                  const float *vy, const float *vz, const float *hx,
                                  const float *hy, const float *hz, size_t n);
void facet_ggx_sample_d_aniso_f32_fast_batch(float *hx, float *hy, float *hz, const float *u1,
                                             const float *u2, const float *alpha_x,
                                             const float *alpha_y, size_t n);
void facet_ggx_pdf_d_aniso_f32_fast_batch(float *out, const float *hx, const float *hy,
                                          const float *hz, const float *alpha_x,
                                          const float *alpha_y, size_t n);
void facet_ggx_sample_vndf_aniso_f32_fast_batch(float *hx, float *hy, float *hz,
                                                const float *vx, const float *vy,
                                                const float *vz, const float *u1,
                                                const float *u2, const float *alpha_x,
                                                const float *alpha_y, size_t n);
void facet_ggx_pdf_vndf_aniso_f32_fast_batch(float *out, const float *vx, const float *vy,
                                             const float *vz, const float *hx, const float *hy,
                                             const float *hz, const float *alpha_x,
                                             const float *alpha_y, size_t n);
void facet_gtr_sample_d_f32_fast_batch(float *hx, float *hy, float *hz, const float *u1,
                                       const float *u2, const float *alpha, const float *gamma,
                                       size_t n);
void facet_gtr_pdf_d_f32_fast_batch(float *out, const float *noh, const float *alpha,
                                    const float *gamma, size_t n);
void facet_sincos_2pi_f32_fast_batch(float *s, float *c, const float *u, size_t n);

/* The sampler table, for tools that drive every sampler the same way (the
 * facet command, the tests, the bench): one entry per sampler above. */
#define FACET_SAMPLER_MAX_INPUTS 8
#define FACET_SAMPLER_MAX_OUTPUTS 3

typedef struct facet_sampler {
    const char *name;                                  /* "ggx_sample_vndf" */
    int n_inputs;
    const char *inputs[FACET_SAMPLER_MAX_INPUTS];      /* "vx", ..., "alpha" */
    int n_outputs;
    const char *outputs[FACET_SAMPLER_MAX_OUTPUTS];    /* "hx", "hy", "hz" */
    int err_abs;      /* 1: bound is the Euclidean distance of the outputs; 0: relative */
    /* one sample: out[0 .. n_outputs - 1] from in[0 .. n_inputs - 1] (scalar) */
    void (*f32)(float *out, const float *in);
    void (*oracle)(double *out, const double *in);
    /* batch on the active port: out[o][i] from in[0][i], in[1][i], ... */
    void (*f32_batch)(float *const *out, const float *const *in, size_t n);
    double err_f32;
    void (*f32_fast)(float *out, const float *in);
    void (*f32_fast_batch)(float *const *out, const float *const *in, size_t n);
    double err_f32_fast;
} facet_sampler;

size_t facet_sampler_count(void);
const facet_sampler *facet_sampler_at(size_t i);
const facet_sampler *facet_sampler_find(const char *name); /* NULL if unknown */

#ifdef __cplusplus
}
#endif

#endif
