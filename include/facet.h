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
 *     (values below the absolute floor of the previous point excepted),
 *     maximum over the test sweep (tests/test_f32_accuracy.c), in units of
 *     2^-k; FACET_ERR_* below are the bounds the tests enforce.  Where a
 *     bound has an absolute floor it is said so.  Cost counts float
 *     operations of the body (clamps included), rsqrt and rcp counted once.
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
 * Error: FACET_ERR_NOH_FROM_DOTS_F32.  Cost: 1 rsqrt + 11 ops. */
float facet_noh_from_dots_f32(float nol, float nov, float lov);

/* L.H = V.H = |L + V| / 2 = sqrt((1 + L.V) / 2), via the same rsqrt.
 * Domain: L.V in [-1, 1]; L.V = -1 gives 0.
 * Error: FACET_ERR_LOH_FROM_DOTS_F32.  Cost: 1 rsqrt + 6 ops. */
float facet_loh_from_dots_f32(float lov);

/* Schlick's Fresnel: F = F0 + (1 - F0) (1 - cos)^5, the power by three
 * multiplies.  Domain: f0, cos in [0, 1].  F(f0, 1) = f0, F(f0, 0) = 1.
 * Error: FACET_ERR_FRESNEL_SCHLICK_F32.  Cost: 9 ops. */
float facet_fresnel_schlick_f32(float f0, float cos_theta);

/* GGX / Trowbridge-Reitz normal distribution:
 *   D = alpha^2 / (pi ((N.H)^2 (alpha^2 - 1) + 1)^2)
 * evaluated as (1/pi) (alpha / d)^2 with d = (1 - N.H)(1 + N.H) + (N.H alpha)^2,
 * which has no cancellation at the peak.  D(1) = 1/(pi alpha^2) (<= 3.3e5),
 * D(0) = alpha^2/pi.  Domain: N.H in [0, 1], alpha in [FACET_ALPHA_MIN, 1].
 * Error: FACET_ERR_GGX_D_F32.  Cost: 1 rcp + 12 ops. */
float facet_ggx_d_f32(float noh, float alpha);

/* Exact Smith masking for GGX:
 *   G1 = 2 N.V / (N.V + sqrt(alpha^2 + (1 - alpha^2) N.V^2)) = 1 / (1 + Lambda)
 * Domain: N.V in [0, 1]; G1(0) = 0, G1(1) = 1.
 * Error: FACET_ERR_SMITH_G1_F32.  Cost: 1 rsqrt + 1 rcp + 13 ops. */
float facet_smith_g1_f32(float nov, float alpha);

/* Exact height-correlated Smith G2 for GGX:
 *   G2 = 2 N.L N.V / (N.V sqrt(alpha^2 + (1-alpha^2) N.L^2)
 *                   + N.L sqrt(alpha^2 + (1-alpha^2) N.V^2))  = 1/(1 + Lambda_L + Lambda_V)
 * Domain: N.L, N.V in [FACET_COS_MIN, 1].
 * Error: FACET_ERR_SMITH_G2_F32.  Cost: 2 rsqrt + 1 rcp + 24 ops. */
float facet_smith_g2_f32(float nol, float nov, float alpha);

/* Uncorrelated Smith G2 = G1(N.L) G1(N.V), with one reciprocal.
 * Domain: as smith_g2.  Error: FACET_ERR_SMITH_G2_UNCORRELATED_F32.
 * Cost: 2 rsqrt + 1 rcp + 27 ops. */
float facet_smith_g2_uncorrelated_f32(float nol, float nov, float alpha);

/* Visibility: correlated G2 / (4 N.L N.V) with the numerator cancelled:
 *   Vis = 0.5 / (N.V sqrt(alpha^2 + (1-alpha^2) N.L^2) + N.L sqrt(...N.V...))
 * Domain: as smith_g2; at the domain corner Vis <= 0.5/(2 alpha_min COS_MIN^2)... in
 * practice <= 2.6e11.  Error: FACET_ERR_SMITH_VIS_F32.
 * Cost: 2 rsqrt + 1 rcp + 21 ops. */
float facet_smith_vis_f32(float nol, float nov, float alpha);

/* Hammon's G1 approximation (= Schlick-GGX with k = alpha/2):
 *   G1 ~ 2 N.V / (N.V (2 - alpha) + alpha)
 * Domain: N.V in [0, 1].  Error: FACET_ERR_SMITH_G1_HAMMON_F32 (vs the same
 * formula in double; its model error vs exact G1 is in the report).
 * Cost: 1 rcp + 11 ops. */
float facet_smith_g1_hammon_f32(float nov, float alpha);

/* Hammon's G2 approximation:
 *   G2 ~ 2 N.L N.V / lerp(2 N.L N.V, N.L + N.V, alpha)
 * the lerp evaluated as (1 - alpha) 2 N.L N.V + alpha (N.L + N.V).
 * Domain: N.L, N.V in [FACET_COS_MIN, 1].  Error: FACET_ERR_SMITH_G2_HAMMON_F32.
 * Cost: 1 rcp + 17 ops. */
float facet_smith_g2_hammon_f32(float nol, float nov, float alpha);

/* Hammon's visibility: G2_hammon / (4 N.L N.V) = 0.5 / lerp(2 N.L N.V, N.L + N.V, alpha).
 * Domain: as smith_g2_hammon; max 0.5/(2 alpha_min COS_MIN) = 2.7e8.
 * Error: FACET_ERR_SMITH_VIS_HAMMON_F32.  Cost: 1 rcp + 15 ops. */
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
 * Error: FACET_ERR_DIFFUSE_HAMMON_F32.  Cost: 1 rsqrt + 1 rcp + 45 ops. */
float facet_diffuse_hammon_f32(float nol, float nov, float lov, float alpha, float albedo);

/* The whole model, per light:
 *   brdf = D(N.H) Vis_hammon(N.L, N.V) F(f0, L.H) + diffuse_hammon
 * (a BRDF value; radiance = brdf * N.L * light).  D is evaluated from the
 * dots without forming N.H (see f32_body.h: the peak for small alpha is
 * ill-conditioned in N.H, so 2 + 2 L.V - (N.L + N.V)^2 is formed exactly);
 * one rsqrt and one reciprocal.
 * Domain: N.L, N.V in [FACET_COS_MIN, 1], L.V in [-1, 1], alpha, f0, albedo.
 * Error: FACET_ERR_BRDF_HAMMON_F32.  Cost: 1 rsqrt + 1 rcp + 95 ops. */
float facet_brdf_hammon_f32(float nol, float nov, float lov, float alpha,
                            float f0, float albedo);

/* brdf_hammon for an RGB f0 and albedo, sharing the geometry:
 * out[c] = facet_brdf_hammon_f32(nol, nov, lov, alpha, f0[c], albedo[c]),
 * to within the same bound. */
void facet_brdf_hammon_rgb_f32(float out[3], float nol, float nov, float lov,
                               float alpha, const float f0[3], const float albedo[3]);

/* Lambert: albedo / pi.  Domain: albedo in [0, 1].
 * Error: FACET_ERR_LAMBERT_F32.  Cost: 3 ops. */
float facet_lambert_f32(float albedo);

/* ---- batch API -------------------------------------------------------------
 * facet_<kernel>_f32_batch(out, in1, ..., n): out[i] = kernel(in1[i], ...)
 * for i < n, structure-of-arrays, inputs in the order above.  Any n (tails
 * are handled), no alignment requirement, out may alias any input.  Runs on
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

/* Ports.  facet_set_port(name) forces one for all batch calls in the process:
 * "scalar", "sse2", "avx2", "avx512", "neon", or "auto" (the automatic choice).  Returns
 * 0 on success, 1 for a name not compiled into this build, 2 for a port this
 * CPU cannot run (the active port is then unchanged).  The environment
 * variable FACET_PORT names the initial choice the same way (an unknown or
 * unsupported name there falls back to auto; facet_port_name() tells).
 * facet_port_at(i, &supported, &lanes) lists the ports compiled in, best
 * first (NULL past the end). */
int facet_set_port(const char *name);
const char *facet_port_name(void);
size_t facet_port_count(void);
const char *facet_port_at(size_t i, int *supported, int *lanes);

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
} facet_kernel;

size_t facet_kernel_count(void);
const facet_kernel *facet_kernel_at(size_t i);
const facet_kernel *facet_kernel_find(const char *name); /* NULL if unknown */

#ifdef __cplusplus
}
#endif

#endif
