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

#ifdef __cplusplus
}
#endif

#endif
