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
 *     -Inf counts as the low end, +Inf as the high end.
 *   - NaN: a NaN in any input of a sample (quiet or signalling, either
 *     sign, any payload) gives +0 for that sample, in both tiers, on every
 *     port and in the batch, RGB and vector entry points alike: a value that
 *     cannot light a pixel (the grazing-angle maximum it used to give
 *     could).  Cost: one ordered compare and mask per two inputs
 *     (keep_ord, 2 ops in "Cost:").  So finite or not, every input gives a
 *     finite, non-negative result, never NaN, and nothing traps.  The
 *     importance samplers below keep their own rules (NaN to a documented
 *     substitute); fixed point (facet/fx.h) has integer inputs and no NaN.
 *   - Denormal inputs are values like any other, except on ports that run
 *     with flush-to-zero (armv7 NEON, Helium): there they act as 0 in
 *     arithmetic, while a compare may see their value (qemu's armv7 NEON
 *     does; the tests judge such a port at the flushed input, or at the
 *     unflushed one where a select differs), and an intermediate below 2^-126
 *     becomes 0, so results below 2^-60 are only good to bound * 2^-60
 *     absolutely (elsewhere: below 2^-100, to bound * 2^-100).
 *   - (N.L, N.V, L.V) triples that no pair of unit vectors can form (e.g.
 *     after rounding the dots of a real pair) are evaluated by the identities
 *     below with 1 + L.V raised to (N.L + N.V)^2 / 2 where it is smaller;
 *     this caps N.H at 1 and is continuous with the geometric definition.
 *   - Error: relative to the oracle evaluated at the same float inputs
 *     (values below the absolute floor stated above compared absolutely),
 *     maximum over the test sweep (tests/f32/test_f32_accuracy.c), in units of
 *     2^-k; FACET_ERR_* below are the bounds the tests enforce.  Where a
 *     bound has an absolute floor it is said so.
 *   - Cost: operations of the kernel body as a port with FMA executes them
 *     (clamp = 2, select = 2, keep_ord = 2, keep_ord4 = 3, fma = 1), counted
 *     by tests/f32/test_op_counts.c (tests/lib/op_count.h: the rules);
 *     rsqrt and rcp are listed apart: each is an estimate plus the port's
 *     refinement steps (see the port headers); a quotient a / b or a root
 *     sqrt(x) counts 1 op (the multiply by the estimate) plus a rcp or rsqrt
 *     (on sse2, avx2 and avx512 it is one vdivps / vsqrtps instead).
 *   - Budget: the same operations by what they are for, in both tiers:
 *     clamps (the domain rule), NaN (the NaN rule), peak (brdf_hammon's
 *     exact 2 + 2 L.V - (N.L + N.V)^2 and 1 - L.H), term (the formula
 *     itself); `test_op_counts --tsv FILE` adds each port's refinement
 *     operations and the fast-math shader peer's count.
 *
 * Names: facet_<kernel>_f32 here (library functions: one sample, the
 * active port's per-sample entry, chosen once with the batches' port: the
 * scalar body compiled with that port's flags, on x86 with FMA the
 * hardware's rcp / rsqrt estimates and square root); facet_<kernel>_f32_scalar
 * in facet/scalar.h (the same body, static inline, under your own flags).
 */
#ifndef FACET_H
#define FACET_H

#include <stddef.h>
#include "facet/common.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FACET_VERSION "0.1.0"

/* ---- how this header is organised ---------------------------------------
 * One block per kernel family: the geometry identities, Fresnel, D,
 * shadowing and visibility, diffuse, the whole BRDF; then the ports, the
 * kernel table and the importance samplers.  A family block opens with what
 * its kernels share and the bounds of both tiers (FACET_ERR_<NAME>_F32 and
 * FACET_ERR_<NAME>_F32_FAST: relative error vs the oracle, enforced by the
 * tests); then, per kernel, its contract (formula, domain, behaviour outside
 * it, model error where it approximates an exact term, the error of both
 * tiers, cost) and its four declarations:
 *   facet_<kernel>_f32(...)                    one sample, precise tier
 *   facet_<kernel>_f32_fast(...)               one sample, fast tier
 *   facet_<kernel>_f32_batch(out, ..., n)      n samples on the active port
 *   facet_<kernel>_f32_fast_batch(out, ..., n) the same, fast tier
 *
 * The two tiers.  facet_<kernel>_f32_fast, facet_<kernel>_f32_fast_batch
 * and, in each port header, facet_<kernel>_f32_fast_<port>: the same
 * formula, domain, out-of-domain behaviour (finite, >= 0 for every input)
 * and symmetry as the precise kernel (the specular peak's cancellation is
 * still formed exactly); where its Budget line differs from the precise
 * tier's (brdf_hammon, diffuse_hammon and its hybrid and cheap variants) a
 * cheaper formulation of the same terms, stated in the contract; where the
 * two Budget lines are equal no cheaper formulation within the fast bound
 * was found, and the tiers differ only in the port's estimates: each
 * port's cheaper reciprocal and rsqrt: scalar rsqrt with 2 Newton steps
 * (not 3, the reciprocal is the division in both tiers); sse2 rcpps /
 * rsqrtps and avx2 estimates with one Newton step (the precise tier: IEEE
 * division / square root, and one third-order step); avx512 the 14-bit
 * estimates unrefined (the precise tier: one Newton step); neon 2 steps
 * (not 3); helium (a bit-level seed: MVE has no estimate) 2 steps (not 3);
 * rvv (vfrec7 / vfrsqrt7) 1 step (not 2).  A quotient a / b or a root is
 * the port's div / sqrt: vdivps / vsqrtps in both tiers on sse2, avx2 and
 * avx512 (the divide unit runs beside the FMA pipes, cheaper than an
 * estimate and its steps there; so a kernel whose only estimate is a
 * quotient is the same code in both tiers on those ports; avx512's fast
 * root is x times the raw rsqrt14), a times the tier's reciprocal or rsqrt
 * elsewhere.  Where an error is raised to the
 * fifth power (brdf_hammon's 1 - L.H) both tiers refine fully; a kernel
 * with no reciprocal or rsqrt is the same code in both tiers.  Fast-tier
 * bounds: relative error vs the oracle, measured over the precise tier's
 * sweep on every port, also with estimates at the architectural bound
 * (tests/suites/15-worst-estimates.sh; the worst port is avx512), enforced
 * by the same tests; all <= 2^-12.
 *
 * Batch API.  facet_<kernel>_f32_batch(out, in1, ..., n): out[i] =
 * kernel(in1[i], ...) for i < n, structure-of-arrays, inputs in the order of
 * the one-sample call.  Any n (tails are handled), no alignment requirement.
 * out may be exactly the same array as any input (out == in: each element is
 * read before it is written); no other overlap (out shifted against an input
 * gives results that depend on the port's vector width).  Runs on the best
 * port for this CPU, chosen once and thread-safely on first use: avx512 >
 * avx2 > sse2 on x86, neon on ARM, helium on Armv8.1-M with MVE, rvv on
 * riscv64 with V, else scalar ("Ports" below).  Every port meets the bounds
 * (tests/f32/test_f32_accuracy.c runs each kernel on each port); results may
 * differ between ports by rounding, within those bounds. */

/* ==== Geometry: N.H and L.H from the dots ===================================
 * The shader identities that give N.H and L.H from N.L, N.V and L.V without
 * building H (|L + V|^2 = 2 + 2 L.V); exact identities, no model error. */
#define FACET_ERR_NOH_FROM_DOTS_F32                   3.372e-07 /* 2^-21.5 */
#define FACET_ERR_NOH_FROM_DOTS_F32_FAST              8.632e-05 /* 2^-13.5 */
#define FACET_ERR_LOH_FROM_DOTS_F32                   2.384e-07 /* 2^-22 */
#define FACET_ERR_LOH_FROM_DOTS_F32_FAST              8.632e-05 /* 2^-13.5 */

/* N.H from the dots, without building H:
 *   N.H = (N.L + N.V) / sqrt(2 + 2 L.V)        (|L + V|^2 = 2 + 2 L.V)
 * Domain: N.L, N.V in [FACET_COS_MIN, 1], L.V in [-1, 1]; result in [0, 1].
 * Error: <= FACET_ERR_NOH_FROM_DOTS_F32 (2^-21.5); measured max 2^-22.12 (worst port,
 * 30 M samples) at (0.0587858558, 0.458401412, -0.495318681).
 * f32_fast: <= FACET_ERR_NOH_FROM_DOTS_F32_FAST (2^-13.5).
 * Budget: clamps 6, NaN 3, peak 0, term 7; fast: clamps 6, NaN 3, peak 0, term 7.
 * Cost: 16 ops (1 rsqrt, 0 rcp). */
float facet_noh_from_dots_f32(float nol, float nov, float lov);
float facet_noh_from_dots_f32_fast(float nol, float nov, float lov);
void facet_noh_from_dots_f32_batch(float *out, const float *nol, const float *nov,
                                   const float *lov, size_t n);
void facet_noh_from_dots_f32_fast_batch(float *out, const float *nol, const float *nov,
                                   const float *lov, size_t n);

/* L.H = V.H = |L + V| / 2 = sqrt((1 + L.V) / 2), via the same rsqrt.
 * Domain: L.V in [-1, 1]; L.V = -1 gives 0.
 * Error: <= FACET_ERR_LOH_FROM_DOTS_F32 (2^-22); measured max 2^-22.64 (worst port,
 * 30 M samples) at (0.0295905489).
 * f32_fast: <= FACET_ERR_LOH_FROM_DOTS_F32_FAST (2^-13.5).
 * Budget: clamps 2, NaN 2, peak 0, term 5; fast: clamps 2, NaN 2, peak 0, term 5.
 * Cost: 9 ops (1 rsqrt, 0 rcp). */
float facet_loh_from_dots_f32(float lov);
float facet_loh_from_dots_f32_fast(float lov);
void facet_loh_from_dots_f32_batch(float *out, const float *lov, size_t n);
void facet_loh_from_dots_f32_fast_batch(float *out, const float *lov, size_t n);

/* ==== Fresnel =================================================================
 * c = V.H (= L.H).  fresnel_cook_torrance is the exact dielectric Fresnel,
 * the reference of the others' model error (relative; fresnel_schlick's is
 * stated in fresnel_cook_torrance's contract, fresnel_schlick_sg's, against
 * fresnel_schlick, in its own).  Every Fresnel kernel is the same code in
 * both tiers: three have no reciprocal or rsqrt, and fresnel_cook_torrance
 * refines its estimates fully (its F goes as the fourth power of a rooted
 * term). */
#define FACET_ERR_FRESNEL_SCHLICK_F32                 4.769e-07 /* 2^-21 */
#define FACET_ERR_FRESNEL_SCHLICK_F32_FAST            4.769e-07 /* 2^-21 */
#define FACET_ERR_FRESNEL_COOK_TORRANCE_F32           1.907e-06 /* 2^-19 */
#define FACET_ERR_FRESNEL_COOK_TORRANCE_F32_FAST      1.907e-06 /* 2^-19 */
#define FACET_ERR_FRESNEL_SCHLICK_F90_F32             4.769e-07 /* 2^-21 */
#define FACET_ERR_FRESNEL_SCHLICK_F90_F32_FAST        4.769e-07 /* 2^-21 */
#define FACET_ERR_FRESNEL_SCHLICK_SG_F32              1.349e-06 /* 2^-19.5 */
#define FACET_ERR_FRESNEL_SCHLICK_SG_F32_FAST         1.349e-06 /* 2^-19.5 */

/* Schlick's Fresnel: F = F0 + (1 - F0) (1 - cos)^5, the power by three
 * multiplies.  Domain: f0, cos in [0, 1].  F(f0, 1) = f0, F(f0, 0) = 1.
 * Error: <= FACET_ERR_FRESNEL_SCHLICK_F32 (2^-21); measured max 2^-21.40 (worst port,
 * 30 M samples) at (2.34035488e-05, 0.494028538).
 * f32_fast: the same code (no reciprocal),
 * FACET_ERR_FRESNEL_SCHLICK_F32_FAST (2^-21).
 * Budget: clamps 4, NaN 2, peak 0, term 9; fast: clamps 4, NaN 2, peak 0, term 9.
 * Cost: 15 ops (0 rsqrt, 0 rcp). */
float facet_fresnel_schlick_f32(float f0, float cos_theta);
float facet_fresnel_schlick_f32_fast(float f0, float cos_theta);
void facet_fresnel_schlick_f32_batch(float *out, const float *f0, const float *cos_theta, size_t n);
void facet_fresnel_schlick_f32_fast_batch(float *out, const float *f0, const float *cos_theta, size_t n);

/* Exact Fresnel reflectance of a dielectric (unpolarised), the reference the
 * Schlick forms approximate: with eta = (1 + sqrt f0) / (1 - sqrt f0) (so
 * that f0 = ((eta - 1)/(eta + 1))^2) and g = sqrt(eta^2 - 1 + V.H^2),
 *   F = (1/2) ((g - c)/(g + c))^2 (1 + (((g + c) c - 1)/((g - c) c + 1))^2),  c = V.H
 * (Cook and Torrance's form of the Fresnel equations), evaluated scaled by
 * 1 - f0 so that eta -> infinity costs nothing (f32_body.h derives it): two
 * rsqrt (sqrt f0 and g), one reciprocal, no cancellation.
 * Domain: f0, voh in [0, 1].  F(f0, 1) = f0; F(f0, 0) = 1 for f0 > 0;
 * f0 = 0 (eta = 1, no interface) gives 0 for every V.H; f0 = 1 (eta
 * infinite, a perfect mirror) gives 1 for every V.H.  Near f0 = 1 the
 * function is steep at grazing: F dips to about 1/2 at the Brewster angle,
 * cos = 1/sqrt(eta^2 + 1) ~ (1 - f0) / 4, and returns to 1 at V.H = 0.
 * Model error of fresnel_schlick against it (relative, tests/oracle/test_oracle.c,
 * 401 f0 log-spaced x 2001 V.H): f0 in [0.02, 0.1] (dielectrics, eta 1.33
 * to 1.92) max 0.236 at (f0 0.031, V.H 0.587), where Schlick is too low,
 * mean 0.094; f0 in [0.02, 0.999] max 0.999 at (0.98, V.H 0.005), the
 * Brewster dip Schlick does not have, mean 0.105.
 * The precision is that of F ~ P^-4 (an error of P counts four times), so
 * both tiers are the same code with fully refined estimates.
 * Error: <= FACET_ERR_FRESNEL_COOK_TORRANCE_F32 (2^-19), both tiers; measured max
 * 2^-19.71 (worst port, 3 M samples) at (6.10115691e-08, 0.528173864).
 * f32_fast: the same code, fully refined:
 * FACET_ERR_FRESNEL_COOK_TORRANCE_F32_FAST (2^-19).
 * Budget: clamps 4, NaN 2, peak 0, term 37; fast: clamps 4, NaN 2, peak 0, term 37.
 * Cost: 43 ops (2 rsqrt, 1 rcp). */
float facet_fresnel_cook_torrance_f32(float f0, float voh);
float facet_fresnel_cook_torrance_f32_fast(float f0, float voh);
void facet_fresnel_cook_torrance_f32_batch(float *out, const float *f0, const float *voh, size_t n);
void facet_fresnel_cook_torrance_f32_fast_batch(float *out, const float *f0, const float *voh,
                                                size_t n);

/* Schlick's Fresnel with a free grazing value (f90; fresnel_schlick is
 * f90 = 1):  F = f0 + (f90 - f0)(1 - V.H)^5, evaluated as the convex
 * combination f0 (1 - (1 - c)^5) + f90 (1 - c)^5 (no cancellation, also
 * for f90 < f0).  Domain: f0, f90, voh in [0, 1].  F(f0, f90, 1) = f0,
 * F(f0, f90, 0) = f90 exactly.
 * No reciprocal or rsqrt: both tiers are the same code.
 * Error: <= FACET_ERR_FRESNEL_SCHLICK_F90_F32 (2^-21); measured max 2^-21.54 (worst port,
 * 3 M samples) at (2.63928523e-08, 0.999971151, 0.499411613).
 * f32_fast: FACET_ERR_FRESNEL_SCHLICK_F90_F32_FAST (2^-21).
 * Budget: clamps 6, NaN 3, peak 0, term 15; fast: clamps 6, NaN 3, peak 0, term 15.
 * Cost: 24 ops (0 rsqrt, 0 rcp). */
float facet_fresnel_schlick_f90_f32(float f0, float f90, float voh);
float facet_fresnel_schlick_f90_f32_fast(float f0, float f90, float voh);
void facet_fresnel_schlick_f90_f32_batch(float *out, const float *f0, const float *f90,
                                         const float *voh, size_t n);
void facet_fresnel_schlick_f90_f32_fast_batch(float *out, const float *f0, const float *f90,
                                              const float *voh, size_t n);

/* Schlick's Fresnel with the spherical-Gaussian power (Karis):
 *   F = F0 + (1 - F0) 2^((-5.55473 cos - 6.98316) cos)
 * 2^y from the exponent bits and a polynomial (no libm).  F(f0, 0) = 1;
 * F(f0, 1) = f0 + (1 - f0) 2^-12.54 (not f0: the Gaussian does not reach 0).
 * Domain: f0, cos in [0, 1].
 * Model error against fresnel_schlick (its reference; Schlick's own error
 * against the exact Fresnel is that kernel's): |F_sg - F_schlick| =
 * (1 - f0) |2^y - (1 - cos)^5|, max 0.00377 (1 - f0) at cos = 0.0554,
 * mean 0.00195 (1 - f0) over cos uniform in [0, 1]; relative to Schlick's F
 * at f0 = 0.04 up to 6.9% (cos = 0.633).
 * Both tiers are the same code (no reciprocal).  The error is the tail's:
 * y's two roundings times |y| ln 2 <= 8.7, and the constants rounded to float.
 * Error: <= FACET_ERR_FRESNEL_SCHLICK_SG_F32 (2^-19.5); measured max 2^-20.03 (sse2 and
 * scalar, no FMA; 2^-20.45 with FMA), 300 k samples, at (4.17905432e-10, 0.999937892).
 * f32_fast: FACET_ERR_FRESNEL_SCHLICK_SG_F32_FAST (2^-19.5).
 * Budget: clamps 4, NaN 2, peak 0, term 17; fast: clamps 4, NaN 2, peak 0, term 17.
 * Cost: 23 ops (0 rsqrt, 0 rcp). */
float facet_fresnel_schlick_sg_f32(float f0, float cos_theta);
float facet_fresnel_schlick_sg_f32_fast(float f0, float cos_theta);
void facet_fresnel_schlick_sg_f32_batch(float *out, const float *f0, const float *cos_theta,
                                        size_t n);
void facet_fresnel_schlick_sg_f32_fast_batch(float *out, const float *f0,
                                             const float *cos_theta, size_t n);

/* ==== D: normal distributions =================================================
 * Every D is a normal distribution: the integral of D(m) (N.M) over the
 * hemisphere is 1 (checked by quadrature in tests/oracle/test_oracle.c for
 * alpha 2^-10 .. 1).  alpha is GGX's width (perceptual roughness^2) in every
 * one; no model error: each is the exact term, and the variants are
 * different looks, not approximations of one another.
 * No libm: the powers and exponentials are 2^y and log2 from the exponent
 * bits and polynomials (include/facet/detail/f32_body.h, "2^y and log2":
 * x_exp2, x_log2_x, x_exp2m1r).  The exponential terms carry what any float
 * exponent carries: a rounding r of the exponent y costs |y| ln 2 r of D,
 * and |y| reaches about 120 before D falls below the comparison floor
 * 2^-100; that, not the polynomials (below 2^-26), sets their bounds.  The
 * f32_fast tier keeps the precise reciprocals wherever the result is raised
 * to a power (facet/detail/f32_body.h, RCP_EXP_), so blinn_phong_d and
 * beckmann_d are the same code in both tiers. */
#define FACET_ERR_GGX_D_F32                           9.538e-07 /* 2^-20 */
#define FACET_ERR_GGX_D_F32_FAST                      1.726e-04 /* 2^-12.5 */
#define FACET_ERR_BLINN_PHONG_D_F32                   3.052e-05 /* 2^-15 */
#define FACET_ERR_BLINN_PHONG_D_F32_FAST              3.052e-05 /* 2^-15 */
#define FACET_ERR_BECKMANN_D_F32                      3.052e-05 /* 2^-15 */
#define FACET_ERR_BECKMANN_D_F32_FAST                 3.052e-05 /* 2^-15 */
#define FACET_ERR_GGX_ANISO_D_F32                     6.744e-07 /* 2^-20.5 */
#define FACET_ERR_GGX_ANISO_D_F32_FAST                8.632e-05 /* 2^-13.5 */
#define FACET_ERR_GTR_D_F32                           1.079e-05 /* 2^-16.5 */
#define FACET_ERR_GTR_D_F32_FAST                      1.726e-04 /* 2^-12.5 */

/* GGX / Trowbridge-Reitz normal distribution:
 *   D = alpha^2 / (pi ((N.H)^2 (alpha^2 - 1) + 1)^2)
 * evaluated as (1/pi) (alpha / d)^2 with d = (1 - N.H)(1 + N.H) + (N.H alpha)^2,
 * which has no cancellation at the peak.  D(1) = 1/(pi alpha^2) (<= 3.3e5),
 * D(0) = alpha^2/pi.  Domain: N.H in [0, 1], alpha in [FACET_ALPHA_MIN, 1].
 * Error: <= FACET_ERR_GGX_D_F32 (2^-20); measured max 2^-20.60 (worst port,
 * 30 M samples) at (0.999949455, 0.254411191).
 * f32_fast: <= FACET_ERR_GGX_D_F32_FAST (2^-12.5).
 * Budget: clamps 4, NaN 2, peak 0, term 8; fast: clamps 4, NaN 2, peak 0, term 8.
 * Cost: 14 ops (0 rsqrt, 1 rcp). */
float facet_ggx_d_f32(float noh, float alpha);
float facet_ggx_d_f32_fast(float noh, float alpha);
void facet_ggx_d_f32_batch(float *out, const float *noh, const float *alpha, size_t n);
void facet_ggx_d_f32_fast_batch(float *out, const float *noh, const float *alpha, size_t n);

/* Normalised Blinn-Phong, alpha-parametrised (Karis):
 *   D = N.H^p / (pi alpha^2),  p = 2 / alpha^2 - 2
 * ((p + 2) / (2 pi) N.H^p; p from 0 at alpha = 1 to 2^21 - 2 at alpha_min).
 * Evaluated as 2^(p log2 N.H) with p = 2 (1 - alpha)(1 + alpha) / alpha^2.
 * Domain: N.H in [0, 1], alpha in [FACET_ALPHA_MIN, 1].  D(1) = 1/(pi alpha^2);
 * D(0) = 0 for alpha < 1, 1/pi at alpha = 1 (p = 0).
 * Error: <= FACET_ERR_BLINN_PHONG_D_F32 (2^-15); measured max 2^-15.42 (every port,
 * 300 k samples) at (0.776722491, 0.0863524303), where D = 2.6e-28: the exponent
 * p log2 N.H = -88.6 and its few roundings.
 * f32_fast: the precise code (every reciprocal is raised to a power),
 * FACET_ERR_BLINN_PHONG_D_F32_FAST (2^-15).
 * Budget: clamps 4, NaN 2, peak 0, term 52; fast: clamps 4, NaN 2, peak 0, term 52.
 * Cost: 58 ops (0 rsqrt, 2 rcp). */
float facet_blinn_phong_d_f32(float noh, float alpha);
float facet_blinn_phong_d_f32_fast(float noh, float alpha);
void facet_blinn_phong_d_f32_batch(float *out, const float *noh, const float *alpha, size_t n);
void facet_blinn_phong_d_f32_fast_batch(float *out, const float *noh, const float *alpha, size_t n);

/* Beckmann:
 *   D = exp(-tan^2(theta_h) / alpha^2) / (pi alpha^2 N.H^4),
 *   tan^2(theta_h) = (1 - N.H^2) / N.H^2
 * evaluated as (1/pi) (alpha r)^2 2^y, r = 1 / (N.H alpha)^2,
 * y = -log2(e) (1 - N.H)(1 + N.H) r (no cancellation at the peak).  Where
 * y < -160 the result is 0 (the true D is below 2^-136 there), which also
 * covers N.H -> 0.  Domain: N.H in [0, 1], alpha in [FACET_ALPHA_MIN, 1].
 * D(1) = 1/(pi alpha^2), D(0) = 0.
 * Error: <= FACET_ERR_BECKMANN_D_F32 (2^-15); measured max 2^-15.59 (every port,
 * 300 k samples) at (0.997685969, 0.00783577561), where D = 7.4e-30 (y = -109).
 * f32_fast: the precise code (every reciprocal is raised to a power),
 * FACET_ERR_BECKMANN_D_F32_FAST (2^-15).
 * Budget: clamps 4, NaN 2, peak 0, term 30; fast: clamps 4, NaN 2, peak 0, term 30.
 * Cost: 36 ops (0 rsqrt, 1 rcp). */
float facet_beckmann_d_f32(float noh, float alpha);
float facet_beckmann_d_f32_fast(float noh, float alpha);
void facet_beckmann_d_f32_batch(float *out, const float *noh, const float *alpha, size_t n);
void facet_beckmann_d_f32_fast_batch(float *out, const float *noh, const float *alpha, size_t n);

/* Anisotropic GGX with widths alpha_x (along the tangent T) and alpha_y
 * (along the bitangent B); toh = T.H, boh = B.H, noh = N.H, the components
 * of a unit h in the tangent frame:
 *   D = 1 / (pi ax ay ((T.H/ax)^2 + (B.H/ay)^2 + N.H^2)^2)
 * evaluated as ax^3 ay^3 / (pi K^2), K = T.H^2 ay^2 + B.H^2 ax^2 +
 * N.H^2 ax^2 ay^2 (all terms >= 0: no cancellation at the peak).
 * ggx_aniso_d(n, t, b, a, a) = ggx_d(n, a) for a unit h (t^2 + b^2 = 1 - n^2).
 * Domain: N.H in [0, 1], T.H and B.H in [-1, 1] (clamped like L.V: NaN and
 * -Inf to -1), alpha_x, alpha_y in [FACET_ALPHA_MIN, 1].  Inputs no unit h
 * has: K is floored at ax^2 ay^2 / 2 (the bracket at 1/2), so D <= 4 / (pi ax ay).
 * Error: <= FACET_ERR_GGX_ANISO_D_F32 (2^-20.5); measured max 2^-20.78 (every port,
 * 300 k samples) at (0.998403668, 0.0521120951, -0.0217817482, 0.621842802, 0.203452751).
 * f32_fast: <= FACET_ERR_GGX_ANISO_D_F32_FAST (2^-13.5); measured 2^-14.18
 * (avx512).
 * Budget: clamps 10, NaN 5, peak 0, term 16; fast: clamps 10, NaN 5, peak 0, term 16.
 * Cost: 31 ops (0 rsqrt, 1 rcp). */
float facet_ggx_aniso_d_f32(float noh, float toh, float boh, float alpha_x, float alpha_y);
float facet_ggx_aniso_d_f32_fast(float noh, float toh, float boh, float alpha_x, float alpha_y);
void facet_ggx_aniso_d_f32_batch(float *out, const float *noh, const float *toh, const float *boh,
                                 const float *alpha_x, const float *alpha_y, size_t n);
void facet_ggx_aniso_d_f32_fast_batch(float *out, const float *noh, const float *toh,
                                      const float *boh, const float *alpha_x,
                                      const float *alpha_y, size_t n);

/* Generalized Trowbridge-Reitz (GTR, Burley 2012; Dimov 2015) with tail
 * exponent gamma:
 *   D = c / (1 + (alpha^2 - 1) N.H^2)^gamma,
 *   c = (gamma - 1)(alpha^2 - 1) / (pi (1 - alpha^(2 (1 - gamma))))
 * with its limits: gamma = 1 (GTR1, "Berry"): c = (alpha^2 - 1) / (pi ln alpha^2);
 * alpha = 1: c = 1/pi.  gamma = 2 is GGX: c = alpha^2 / pi, gtr_d(n, a, 2)
 * equals ggx_d(n, a) to within both bounds; gamma = 0 is D = 1/pi.
 * Evaluated without a special case: with L = log2 alpha^2 and
 * E(y) = (2^y - 1) / y, c = E(L) / (pi E((1 - gamma) L)), and
 * d^-gamma = 2^(-gamma log2 d), d = (1 - N.H)(1 + N.H) + (N.H alpha)^2.
 * Domain: N.H in [0, 1], alpha in [FACET_ALPHA_MIN, 1], gamma in [0, 4]
 * (Dimov's range; gamma clamped, NaN and -Inf to 0, +Inf to 4).
 * D(1) = c / alpha^(2 gamma) (up to 1.3e6 at gamma = 4, alpha_min).
 * Error: <= FACET_ERR_GTR_D_F32 (2^-16.5); measured max 2^-16.94 (every port,
 * 300 k samples) at (0.999999762, 0.00208001724, 3.75617146): at the peak of a
 * heavy tail, 2^(-gamma log2 d) with -gamma log2 d = 66.7 (its rounding and
 * log2's) against c = 2^-60.
 * f32_fast: <= FACET_ERR_GTR_D_F32_FAST (2^-12.5); measured 2^-13.63
 * (avx512; 2^-12.95 with estimates at the architectural bound).
 * Budget: clamps 6, NaN 3, peak 0, term 126; fast: clamps 6, NaN 3, peak 0, term 126.
 * Cost: 135 ops (0 rsqrt, 5 rcp). */
float facet_gtr_d_f32(float noh, float alpha, float gamma);
float facet_gtr_d_f32_fast(float noh, float alpha, float gamma);
void facet_gtr_d_f32_batch(float *out, const float *noh, const float *alpha, const float *gamma,
                           size_t n);
void facet_gtr_d_f32_fast_batch(float *out, const float *noh, const float *alpha,
                                const float *gamma, size_t n);

/* ==== Shadowing and visibility ===============================================
 * G terms are G of D F G / (4 N.L N.V); the Vis kernels are G / (4 N.L N.V)
 * already (the 4 N.L N.V cancelled).  Exact Smith for GGX (smith_g1,
 * smith_g2, smith_g2_uncorrelated, smith_vis) and for GTR (smith_g1_gtr, up
 * to its interpolation in gamma), Hammon's approximations, and the rest of
 * Karis's menu: the classic G terms, Beckmann's Smith G1 in Walter's and
 * Schlick's approximations, the joint approximation engines ship, and a
 * fitted visibility.  Each is evaluated as stated (implementation error:
 * the bound, vs the oracle of that same formula); where it approximates an
 * exact term, its model error against that term is in its contract and in
 * the report's model-error table (`make report`).  Fast-tier bounds of the
 * menu: the kernels with a reciprocal 2^-13, smith_g1_beckmann (rsqrt and
 * rcp) 2^-12.5, measured worst on avx512's unrefined estimates (2^-13.96 ..
 * 2^-14.18 on this sweep). */
#define FACET_ERR_SMITH_G1_F32                        4.769e-07 /* 2^-21 */
#define FACET_ERR_SMITH_G1_F32_FAST                   1.726e-04 /* 2^-12.5 */
#define FACET_ERR_SMITH_G2_F32                        4.769e-07 /* 2^-21 */
#define FACET_ERR_SMITH_G2_F32_FAST                   1.726e-04 /* 2^-12.5 */
#define FACET_ERR_SMITH_G2_UNCORRELATED_F32           6.744e-07 /* 2^-20.5 */
#define FACET_ERR_SMITH_G2_UNCORRELATED_F32_FAST      2.441e-04 /* 2^-12 */
#define FACET_ERR_SMITH_VIS_F32                       4.769e-07 /* 2^-21 */
#define FACET_ERR_SMITH_VIS_F32_FAST                  1.726e-04 /* 2^-12.5 */
#define FACET_ERR_SMITH_G1_HAMMON_F32                 3.372e-07 /* 2^-21.5 */
#define FACET_ERR_SMITH_G1_HAMMON_F32_FAST            8.632e-05 /* 2^-13.5 */
#define FACET_ERR_SMITH_G1_GTR_F32                    9.538e-07 /* 2^-20 */
#define FACET_ERR_SMITH_G1_GTR_F32_FAST               1.221e-04 /* 2^-13 */
#define FACET_ERR_SMITH_G2_HAMMON_F32                 4.769e-07 /* 2^-21 */
#define FACET_ERR_SMITH_G2_HAMMON_F32_FAST            8.632e-05 /* 2^-13.5 */
#define FACET_ERR_SMITH_VIS_HAMMON_F32                3.372e-07 /* 2^-21.5 */
#define FACET_ERR_SMITH_VIS_HAMMON_F32_FAST           8.632e-05 /* 2^-13.5 */
#define FACET_ERR_G_IMPLICIT_F32                      8.429e-08 /* 2^-23.5 */
#define FACET_ERR_G_IMPLICIT_F32_FAST                 8.429e-08 /* 2^-23.5 */
#define FACET_ERR_G_NEUMANN_F32                       9.313e-10 /* 2^-30; exact, measured 0 */
#define FACET_ERR_G_NEUMANN_F32_FAST                  9.313e-10 /* 2^-30; exact, measured 0 */
#define FACET_ERR_G_COOK_TORRANCE_F32                 2.384e-07 /* 2^-22 */
#define FACET_ERR_G_COOK_TORRANCE_F32_FAST            1.221e-04 /* 2^-13 */
#define FACET_ERR_G_KELEMEN_F32                       3.372e-07 /* 2^-21.5 */
#define FACET_ERR_G_KELEMEN_F32_FAST                  1.221e-04 /* 2^-13 */
#define FACET_ERR_SMITH_G1_BECKMANN_F32               6.744e-07 /* 2^-20.5 */
#define FACET_ERR_SMITH_G1_BECKMANN_F32_FAST          1.726e-04 /* 2^-12.5 */
#define FACET_ERR_SMITH_G1_SCHLICK_BECKMANN_F32       3.372e-07 /* 2^-21.5 */
#define FACET_ERR_SMITH_G1_SCHLICK_BECKMANN_F32_FAST  1.221e-04 /* 2^-13 */
#define FACET_ERR_SMITH_VIS_JOINT_APPROX_F32          3.372e-07 /* 2^-21.5 */
#define FACET_ERR_SMITH_VIS_JOINT_APPROX_F32_FAST     1.221e-04 /* 2^-13 */
#define FACET_ERR_SMITH_VIS_FIT_F32                   4.769e-07 /* 2^-21 */
#define FACET_ERR_SMITH_VIS_FIT_F32_FAST              1.221e-04 /* 2^-13 */
#define FACET_MODEL_ERR_SMITH_VIS_FIT 0.05

/* Exact Smith masking for GGX:
 *   G1 = 2 N.V / (N.V + sqrt(alpha^2 + (1 - alpha^2) N.V^2)) = 1 / (1 + Lambda)
 * Domain: N.V in [0, 1]; G1(0) = 0, G1(1) = 1.
 * Error: <= FACET_ERR_SMITH_G1_F32 (2^-21); measured max 2^-21.66 (worst port,
 * 30 M samples) at (0.000242657741, 0.00600074418).
 * f32_fast: <= FACET_ERR_SMITH_G1_F32_FAST (2^-12.5).
 * Budget: clamps 4, NaN 2, peak 0, term 11; fast: clamps 4, NaN 2, peak 0, term 11.
 * Cost: 17 ops (1 rsqrt, 1 rcp). */
float facet_smith_g1_f32(float nov, float alpha);
float facet_smith_g1_f32_fast(float nov, float alpha);
void facet_smith_g1_f32_batch(float *out, const float *nov, const float *alpha, size_t n);
void facet_smith_g1_f32_fast_batch(float *out, const float *nov, const float *alpha, size_t n);

/* Exact height-correlated Smith G2 for GGX:
 *   G2 = 2 N.L N.V / (N.V sqrt(alpha^2 + (1-alpha^2) N.L^2)
 *                   + N.L sqrt(alpha^2 + (1-alpha^2) N.V^2))  = 1/(1 + Lambda_L + Lambda_V)
 * Domain: N.L, N.V in [FACET_COS_MIN, 1].
 * Error: <= FACET_ERR_SMITH_G2_F32 (2^-21); measured max 2^-21.40 (worst port,
 * 30 M samples) at (0.492564738, 4.08501137e-06, 0.00407959009).
 * f32_fast: <= FACET_ERR_SMITH_G2_F32_FAST (2^-12.5).
 * Budget: clamps 6, NaN 3, peak 0, term 20; fast: clamps 6, NaN 3, peak 0, term 20.
 * Cost: 29 ops (2 rsqrt, 1 rcp). */
float facet_smith_g2_f32(float nol, float nov, float alpha);
float facet_smith_g2_f32_fast(float nol, float nov, float alpha);
void facet_smith_g2_f32_batch(float *out, const float *nol, const float *nov, const float *alpha,
                              size_t n);
void facet_smith_g2_f32_fast_batch(float *out, const float *nol, const float *nov, const float *alpha,
                              size_t n);

/* Uncorrelated Smith G2 = G1(N.L) G1(N.V), with one reciprocal.
 * Domain: as smith_g2.  Error: <= FACET_ERR_SMITH_G2_UNCORRELATED_F32 (2^-20.5); measured max 2^-20.95 (worst port,
 * 30 M samples) at (1.06287043e-05, 4.67698592e-05, 0.0156806652).
 * f32_fast: <= FACET_ERR_SMITH_G2_UNCORRELATED_F32_FAST (2^-12); measured
 * worst 2^-12.43 (avx512).
 * Budget: clamps 6, NaN 3, peak 0, term 20; fast: clamps 6, NaN 3, peak 0, term 20.
 * Cost: 29 ops (2 rsqrt, 1 rcp). */
float facet_smith_g2_uncorrelated_f32(float nol, float nov, float alpha);
float facet_smith_g2_uncorrelated_f32_fast(float nol, float nov, float alpha);
void facet_smith_g2_uncorrelated_f32_batch(float *out, const float *nol, const float *nov,
                                           const float *alpha, size_t n);
void facet_smith_g2_uncorrelated_f32_fast_batch(float *out, const float *nol, const float *nov,
                                           const float *alpha, size_t n);

/* Visibility: correlated G2 / (4 N.L N.V) with the numerator cancelled:
 *   Vis = 0.5 / (N.V sqrt(alpha^2 + (1-alpha^2) N.L^2) + N.L sqrt(...N.V...))
 * Domain: as smith_g2; largest at N.L = N.V = FACET_COS_MIN, alpha_min:
 * 0.5 / (2 COS_MIN alpha_min) = 2^28.  Error: <= FACET_ERR_SMITH_VIS_F32 (2^-21); measured max 2^-21.62 (worst port,
 * 30 M samples) at (3.14775752e-06, 0.126348287, 0.00824174657).
 * f32_fast: <= FACET_ERR_SMITH_VIS_F32_FAST (2^-12.5).
 * Budget: clamps 6, NaN 3, peak 0, term 17; fast: clamps 6, NaN 3, peak 0, term 17.
 * Cost: 26 ops (2 rsqrt, 1 rcp). */
float facet_smith_vis_f32(float nol, float nov, float alpha);
float facet_smith_vis_f32_fast(float nol, float nov, float alpha);
void facet_smith_vis_f32_batch(float *out, const float *nol, const float *nov, const float *alpha,
                               size_t n);
void facet_smith_vis_f32_fast_batch(float *out, const float *nol, const float *nov, const float *alpha,
                               size_t n);

/* Hammon's G1 approximation (= Schlick-GGX with k = alpha/2):
 *   G1 ~ 2 N.V / (N.V (2 - alpha) + alpha)
 * Domain: N.V in [0, 1].  Error: <= FACET_ERR_SMITH_G1_HAMMON_F32 (2^-21.5); measured max 2^-22.26 (worst port,
 * 30 M samples) at (0.516059339, 0.018353641).
 * f32_fast: <= FACET_ERR_SMITH_G1_HAMMON_F32_FAST (2^-13.5).
 * Budget: clamps 4, NaN 2, peak 0, term 5; fast: clamps 4, NaN 2, peak 0, term 5.
 * Cost: 11 ops (0 rsqrt, 1 rcp). */
float facet_smith_g1_hammon_f32(float nov, float alpha);
float facet_smith_g1_hammon_f32_fast(float nov, float alpha);
void facet_smith_g1_hammon_f32_batch(float *out, const float *nov, const float *alpha, size_t n);
void facet_smith_g1_hammon_f32_fast_batch(float *out, const float *nov, const float *alpha, size_t n);

/* Smith G1 for the GTR distribution (gtr_d), Dimov 2015: the exact
 * G1 = 1 / (1 + Lambda) has closed forms at gamma = 0, 1, 2, 3, 4, here in
 * N.V (n) with s2 = 1 - n^2 and W = sqrt(n^2 + alpha^2 s2):
 *   G^0 = 2n / (1 + n)
 *   G^1 = n / (n + e s2 (W + n (1 - R(u))) / ((W + 1)(n + W))),
 *         e = (alpha^2 - 1) / ln alpha^2, R(u) = ln(1 + u) / u,
 *         u = (1 - alpha^2) s2 / ((W + 1)(n + W))
 *   G^2 = 2n / (n + W)                           (= smith_g1, GGX)
 *   G^3 = 4 (1 + alpha^2) n W / (alpha^2 (3 alpha^2 + 1) s2 + 2 (1 + alpha^2) n (n + W))
 *   G^4 = 2 K n W^3 / (K n (W^3 + n^3) + 3 alpha^2 (alpha^2 P5 s2^2 + 4 n^2 s2 P2)),
 *         K = 8 (alpha^4 + alpha^2 + 1), P5 = 5 alpha^4 + 2 alpha^2 + 1,
 *         P2 = 2 alpha^4 + alpha^2 + 1
 * (Dimov's mu-forms multiplied through by sin theta_v; his G^1 divided by
 * ln alpha^2, so alpha = 1 is no 0/0; each checked against the exact G1 by
 * quadrature to 2e-11, tests/oracle/test_oracle.c), and between the orders the
 * monotone cubic Hermite interpolant in gamma (Fritsch-Carlson, MATLAB's
 * pchip) through the five values.  Dimov interpolates "by a spline"
 * without naming it; the natural cubic spline overshoots to G1 = -0.099
 * (N.V = 0.0017, alpha = 2^-10, gamma = 0.56), pchip stays between
 * neighbouring values.  At the integer orders the result is the closed form.
 * Domain: N.V in [0, 1], alpha in [FACET_ALPHA_MIN, 1], gamma in [0, 4] (as
 * gtr_d).  G1(0) = 0, G1(1) = 1; result in [0, 1].
 * Model error (against the exact G1 of gtr_d by quadrature,
 * facet_oracle_smith_g1_gtr_exact): exact at gamma = 0 .. 4; between them
 * max 0.338 absolute at (N.V 0.018, alpha 2^-10, gamma 1.4), where the exact
 * G1 moves steeply with gamma just above 1; mean 0.0077 (0.015 relative)
 * over N.V in [2^-10, 1], alpha in [2^-10, 1], gamma in [0.1, 3.9]; for
 * alpha >= 0.1 max 0.036 (N.V 0.275, alpha 0.1, gamma 0.5), mean 0.0014.
 * (Dimov reports about 0.1% against Monte Carlo for his alpha range.)
 * The f32_fast tier keeps the precise rsqrt for W (cubed in G^4) and the
 * precise reciprocals (the interpolation's slopes are differences of the
 * five values, which amplify their errors); only 2^y's differs.
 * Error (against the interpolation of the closed forms in double,
 * facet_oracle_smith_g1_gtr): <= FACET_ERR_SMITH_G1_GTR_F32 (2^-20); measured
 * max 2^-20.89 (sse2, 300 k samples) at (0.00778461341, 0.126742497, 3.8678031);
 * f32_fast 2^-14.27 (avx512; 2^-14.01 with estimates at the bound).
 * f32_fast: <= FACET_ERR_SMITH_G1_GTR_F32_FAST (2^-13).
 * Budget: clamps 8, NaN 3, peak 0, term 263; fast: clamps 8, NaN 3, peak 0, term 263.
 * Cost: 274 ops (1 rsqrt, 15 rcp). */
float facet_smith_g1_gtr_f32(float nov, float alpha, float gamma);
float facet_smith_g1_gtr_f32_fast(float nov, float alpha, float gamma);
void facet_smith_g1_gtr_f32_batch(float *out, const float *nov, const float *alpha,
                                  const float *gamma, size_t n);
void facet_smith_g1_gtr_f32_fast_batch(float *out, const float *nov, const float *alpha,
                                       const float *gamma, size_t n);

/* Hammon's G2 approximation:
 *   G2 ~ 2 N.L N.V / lerp(2 N.L N.V, N.L + N.V, alpha)
 * the lerp evaluated as (1 - alpha) 2 N.L N.V + alpha (N.L + N.V).
 * Domain: N.L, N.V in [FACET_COS_MIN, 1].  Error: <= FACET_ERR_SMITH_G2_HAMMON_F32 (2^-21); measured max 2^-21.83 (worst port,
 * 30 M samples) at (1.45550921e-05, 0.00873631984, 0.00181798683).
 * f32_fast: <= FACET_ERR_SMITH_G2_HAMMON_F32_FAST (2^-13.5).
 * Budget: clamps 6, NaN 3, peak 0, term 10; fast: clamps 6, NaN 3, peak 0, term 10.
 * Cost: 19 ops (0 rsqrt, 1 rcp). */
float facet_smith_g2_hammon_f32(float nol, float nov, float alpha);
float facet_smith_g2_hammon_f32_fast(float nol, float nov, float alpha);
void facet_smith_g2_hammon_f32_batch(float *out, const float *nol, const float *nov,
                                     const float *alpha, size_t n);
void facet_smith_g2_hammon_f32_fast_batch(float *out, const float *nol, const float *nov,
                                     const float *alpha, size_t n);

/* Hammon's visibility: G2_hammon / (4 N.L N.V) = 0.5 / lerp(2 N.L N.V, N.L + N.V, alpha).
 * Domain: as smith_g2_hammon; max 0.5/(2 alpha_min COS_MIN) = 2.7e8.
 * Error: <= FACET_ERR_SMITH_VIS_HAMMON_F32 (2^-21.5); measured max 2^-22.09 (worst port,
 * 30 M samples) at (0.713193238, 0.713202953, 0.00830200501).
 * f32_fast: <= FACET_ERR_SMITH_VIS_HAMMON_F32_FAST (2^-13.5).
 * Budget: clamps 6, NaN 3, peak 0, term 7; fast: clamps 6, NaN 3, peak 0, term 7.
 * Cost: 16 ops (0 rsqrt, 1 rcp). */
float facet_smith_vis_hammon_f32(float nol, float nov, float alpha);
float facet_smith_vis_hammon_f32_fast(float nol, float nov, float alpha);
void facet_smith_vis_hammon_f32_batch(float *out, const float *nol, const float *nov,
                                      const float *alpha, size_t n);
void facet_smith_vis_hammon_f32_fast_batch(float *out, const float *nol, const float *nov,
                                      const float *alpha, size_t n);

/* Implicit G = N.L N.V (no roughness: the plain cosine product).
 * Domain: N.L, N.V in [0, 1]; symmetric.  G(1, 1) = 1, G(0, x) = 0.
 * Error: <= FACET_ERR_G_IMPLICIT_F32 (2^-23.5; both tiers: one rounding).
 * f32_fast: the same rounding, FACET_ERR_G_IMPLICIT_F32_FAST (2^-23.5).
 * Budget: clamps 4, NaN 2, peak 0, term 1; fast: clamps 4, NaN 2, peak 0, term 1.
 * Cost: 7 ops (0 rsqrt, 0 rcp). */
float facet_g_implicit_f32(float nol, float nov);
float facet_g_implicit_f32_fast(float nol, float nov);
void facet_g_implicit_f32_batch(float *out, const float *nol, const float *nov, size_t n);
void facet_g_implicit_f32_fast_batch(float *out, const float *nol, const float *nov, size_t n);

/* Neumann G = N.L N.V / max(N.L, N.V), which is min(N.L, N.V): evaluated
 * so, exact (0 at N.L = N.V = 0, where the quotient form is 0/0).
 * Domain: N.L, N.V in [0, 1]; symmetric.
 * Error: exact, measured 0; the tests enforce FACET_ERR_G_NEUMANN_F32 (2^-30), both tiers.
 * f32_fast: the same, FACET_ERR_G_NEUMANN_F32_FAST (2^-30).
 * Budget: clamps 4, NaN 2, peak 0, term 1; fast: clamps 4, NaN 2, peak 0, term 1.
 * Cost: 7 ops (0 rsqrt, 0 rcp). */
float facet_g_neumann_f32(float nol, float nov);
float facet_g_neumann_f32_fast(float nol, float nov);
void facet_g_neumann_f32_batch(float *out, const float *nol, const float *nov, size_t n);
void facet_g_neumann_f32_fast_batch(float *out, const float *nol, const float *nov, size_t n);

/* Cook-Torrance (V-groove) G = min(1, 2 N.H N.V / V.H, 2 N.H N.L / V.H)
 *   = min(1, 2 N.H min(N.L, N.V) / V.H).
 * Domain: N.L, N.V in [FACET_COS_MIN, 1], N.H, V.H in [0, 1]; symmetric in
 * N.L, N.V.  Where 2 N.H min(N.L, N.V) >= V.H the result is 1 exactly
 * (V.H = 0 included); the reciprocal sees V.H >= FACET_COS_MIN only.
 * Error: <= FACET_ERR_G_COOK_TORRANCE_F32 (2^-22).
 * f32_fast: <= FACET_ERR_G_COOK_TORRANCE_F32_FAST (2^-13).
 * Budget: clamps 8, NaN 3, peak 0, term 12; fast: clamps 8, NaN 3, peak 0, term 12.
 * Cost: 23 ops (0 rsqrt, 1 rcp). */
float facet_g_cook_torrance_f32(float nol, float nov, float noh, float voh);
float facet_g_cook_torrance_f32_fast(float nol, float nov, float noh, float voh);
void facet_g_cook_torrance_f32_batch(float *out, const float *nol, const float *nov,
                                     const float *noh, const float *voh, size_t n);
void facet_g_cook_torrance_f32_fast_batch(float *out, const float *nol, const float *nov,
                                          const float *noh, const float *voh, size_t n);

/* Kelemen G = N.L N.V / (V.H)^2 (Kelemen and Szirmay-Kalos: G / (4 N.L N.V)
 * = 1 / (4 (V.H)^2) = 1 / (2 (1 + L.V))), capped at 1: for any real pair
 * of vectors N.L N.V <= (V.H)^2, so the cap acts only on inconsistent
 * triples (V.H = 0 gives 1).  Domain: N.L, N.V in [FACET_COS_MIN, 1], V.H
 * in [0, 1]; symmetric in N.L, N.V.
 * Error: <= FACET_ERR_G_KELEMEN_F32 (2^-21.5).
 * f32_fast: <= FACET_ERR_G_KELEMEN_F32_FAST (2^-13).
 * Budget: clamps 6, NaN 3, peak 0, term 6; fast: clamps 6, NaN 3, peak 0, term 6.
 * Cost: 15 ops (0 rsqrt, 1 rcp). */
float facet_g_kelemen_f32(float nol, float nov, float voh);
float facet_g_kelemen_f32_fast(float nol, float nov, float voh);
void facet_g_kelemen_f32_batch(float *out, const float *nol, const float *nov, const float *voh,
                               size_t n);
void facet_g_kelemen_f32_fast_batch(float *out, const float *nol, const float *nov,
                                    const float *voh, size_t n);

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
 * max 0.00313 relative over N.V = i/2000 (i = 1 .. 2000) x 40 alphas
 * log-spaced in [2^-10, 1] (tests/f32/test_vis_fit.c, enforced < 0.01).
 * Error: <= FACET_ERR_SMITH_G1_BECKMANN_F32 (2^-20.5).
 * f32_fast: <= FACET_ERR_SMITH_G1_BECKMANN_F32_FAST (2^-12.5).
 * Budget: clamps 4, NaN 2, peak 0, term 18; fast: clamps 4, NaN 2, peak 0, term 18.
 * Cost: 24 ops (1 rsqrt, 1 rcp). */
float facet_smith_g1_beckmann_f32(float nov, float alpha);
float facet_smith_g1_beckmann_f32_fast(float nov, float alpha);
void facet_smith_g1_beckmann_f32_batch(float *out, const float *nov, const float *alpha, size_t n);
void facet_smith_g1_beckmann_f32_fast_batch(float *out, const float *nov, const float *alpha,
                                            size_t n);

/* Schlick's approximation of Beckmann's Smith G1:
 *   G1 = N.V / (N.V (1 - k) + k),  k = alpha sqrt(2/pi).
 * The same function as smith_g1_hammon (Schlick-GGX, k = alpha/2) at
 * alpha' = 2 sqrt(2/pi) alpha = 1.596 alpha (for alpha <= 0.627, where
 * alpha' <= 1).  Domain: N.V in [0, 1], alpha in [FACET_ALPHA_MIN, 1];
 * G1(0) = 0, G1(1) = 1.  Model error vs the exact Beckmann G1: max 0.646
 * relative (at grazing N.V) on smith_g1_beckmann's grid.
 * Error: <= FACET_ERR_SMITH_G1_SCHLICK_BECKMANN_F32 (2^-21.5).
 * f32_fast: <= FACET_ERR_SMITH_G1_SCHLICK_BECKMANN_F32_FAST (2^-13).
 * Budget: clamps 4, NaN 2, peak 0, term 5; fast: clamps 4, NaN 2, peak 0, term 5.
 * Cost: 11 ops (0 rsqrt, 1 rcp). */
float facet_smith_g1_schlick_beckmann_f32(float nov, float alpha);
float facet_smith_g1_schlick_beckmann_f32_fast(float nov, float alpha);
void facet_smith_g1_schlick_beckmann_f32_batch(float *out, const float *nov, const float *alpha,
                                               size_t n);
void facet_smith_g1_schlick_beckmann_f32_fast_batch(float *out, const float *nov,
                                                    const float *alpha, size_t n);

/* The joint approximation of correlated Smith visibility (UE4's form):
 *   Vis = 0.5 / (N.L (N.V (1 - a) + a) + N.V (N.L (1 - a) + a))
 * which expands to 0.5 / ((1 - a) 2 N.L N.V + a (N.L + N.V)): the same
 * function as smith_vis_hammon (equal within both bounds), in this form.
 * Domain: as smith_vis_hammon; symmetric.  Model error vs exact smith_vis:
 * Hammon's, max 0.291 at N.L = N.V = 0.0043, alpha = 0.0042 over N.L, N.V in
 * [2^-8, 1], alpha in [2^-10, 1] (tests/f32/test_vis_fit.c).
 * Error: <= FACET_ERR_SMITH_VIS_JOINT_APPROX_F32 (2^-21.5).
 * f32_fast: <= FACET_ERR_SMITH_VIS_JOINT_APPROX_F32_FAST (2^-13).
 * Budget: clamps 6, NaN 3, peak 0, term 7; fast: clamps 6, NaN 3, peak 0, term 7.
 * Cost: 16 ops (0 rsqrt, 1 rcp). */
float facet_smith_vis_joint_approx_f32(float nol, float nov, float alpha);
float facet_smith_vis_joint_approx_f32_fast(float nol, float nov, float alpha);
void facet_smith_vis_joint_approx_f32_batch(float *out, const float *nol, const float *nov,
                                            const float *alpha, size_t n);
void facet_smith_vis_joint_approx_f32_fast_batch(float *out, const float *nol, const float *nov,
                                                 const float *alpha, size_t n);

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
 * N.L, N.V in [2^-8, 1], alpha in [2^-10, 1] (tests/f32/test_vis_fit.c);
 * measured 0.0315 at N.L = N.V = 0.35, alpha = 0.69.  Below N.L = 2^-8 (to
 * the f32 floor 2^-20) it stays within 0.031 (r~ tends to k1 a / 2 there).
 * Domain: as smith_vis; symmetric.
 * Error: <= FACET_ERR_SMITH_VIS_FIT_F32 (2^-21), vs the oracle of this formula.
 * f32_fast: <= FACET_ERR_SMITH_VIS_FIT_F32_FAST (2^-13).
 * Budget: clamps 6, NaN 3, peak 0, term 19; fast: clamps 6, NaN 3, peak 0, term 19.
 * Cost: 28 ops (0 rsqrt, 1 rcp). */
float facet_smith_vis_fit_f32(float nol, float nov, float alpha);
float facet_smith_vis_fit_f32_fast(float nol, float nov, float alpha);
void facet_smith_vis_fit_f32_batch(float *out, const float *nol, const float *nov,
                                   const float *alpha, size_t n);
void facet_smith_vis_fit_f32_fast_batch(float *out, const float *nol, const float *nov,
                                        const float *alpha, size_t n);

/* ==== Diffuse =================================================================
 * BRDF values (not yet times N.L).  Lambert, Hammon's GGX diffuse and its
 * hybrid and cheaper variants, Burley's and Oren-Nayar's.  None has a
 * closed-form exact term: each model error is stated against a Monte Carlo
 * simulation of the Smith microsurface of GGX (bench/microsurface: random
 * walks, as Hammon fitted his model; committed tables, seed and paths in
 * its README) made of the material the kernel approximates: "hammon",
 * Hammon's facets (a Schlick F0 = 0.04 mirror mixed with a
 * Fresnel-symmetric Lambertian; the diffuse part / (1 - F0)), for
 * diffuse_hammon, its hybrid and cheap variants and diffuse_burley;
 * "lambert", Lambertian facets, for diffuse_oren_nayar and lambert.
 * Relative error |kernel / reference - 1| of the kernel's formula (its
 * double oracle) over the tables' grid: alpha 2^-10 .. 1 (12 values), N.L
 * and N.V 0.02 .. 1 (10 each), 7 azimuths, the albedo input = the facets'
 * albedo in {0.25, 0.5, 0.75, 1}.  Beside each figure (+-) the
 * simulation's standard error of it; a maximum inside 3 sigma is only a
 * bound.  The maxima fall where the reference is dark (grazing L and V on
 * opposite sides: strong shadowing and masking), hence also N.L, N.V >= 0.2.
 * Per alpha: bench/microsurface/model_error.md and the report.
 * tests/docs/test_docs.c holds each contract's lines to what the tables
 * give.  Directional albedo (albedo = 1, by quadrature over N.V in {1,
 * 0.5, 0.1, 0.01} and alpha in {2^-10, 1/4, 1/2, 1},
 * tests/oracle/test_oracle.c): Lambert 1 exactly, diffuse_hammon 0.050 ..
 * 1.162, the others in their contracts.  Fast tier, measured (3 M samples, avx512, the worst port) and
 * with estimates at the architectural bound (tests/suites/15-worst-estimates.sh,
 * 30 k samples): in each contract. */
#define FACET_ERR_DIFFUSE_HAMMON_F32                  9.538e-07 /* 2^-20 */
#define FACET_ERR_DIFFUSE_HAMMON_F32_FAST             1.726e-04 /* 2^-12.5 */
#define FACET_ERR_DIFFUSE_BURLEY_F32                  6.744e-07 /* 2^-20.5 */
#define FACET_ERR_DIFFUSE_BURLEY_F32_FAST             1.726e-04 /* 2^-12.5 */
#define FACET_ERR_DIFFUSE_OREN_NAYAR_F32              6.744e-07 /* 2^-20.5 */
#define FACET_ERR_DIFFUSE_OREN_NAYAR_F32_FAST         1.726e-04 /* 2^-12.5 */
#define FACET_ERR_DIFFUSE_HAMMON_HYBRID_F32           6.744e-07 /* 2^-20.5 */
#define FACET_ERR_DIFFUSE_HAMMON_HYBRID_F32_FAST      1.726e-04 /* 2^-12.5 */
#define FACET_ERR_DIFFUSE_HAMMON_CHEAP_F32            6.744e-07 /* 2^-20.5 */
#define FACET_ERR_DIFFUSE_HAMMON_CHEAP_F32_FAST       1.726e-04 /* 2^-12.5 */
#define FACET_ERR_LAMBERT_F32                         1.686e-07 /* 2^-22.5 */
#define FACET_ERR_LAMBERT_F32_FAST                    1.686e-07 /* 2^-22.5 */

/* Hammon's GGX diffuse (a BRDF value, not yet times N.L):
 *   facing = 0.5 + 0.5 L.V
 *   rough  = facing (0.9 - 0.4 facing) (0.5 + N.H) / N.H
 *   smooth = 1.05 (1 - (1 - N.L)^5) (1 - (1 - N.V)^5)
 *   single = lerp(smooth, rough, alpha) / pi
 *   multi  = 0.1159 alpha
 *   result = albedo (single + albedo multi)
 * 0.5 / N.H from the identity above as L.H / (N.L + N.V), L.H = sqrt(t/2)
 * (t/2 = (1 + L.V)/2 formed directly, raised to ((N.L + N.V)/2)^2)
 * (one root, one quotient: the port's sqrt and div); 1 - (1-x)^5 as
 * x (1 + y + y^2 + y^3 + y^4), y = 1 - x, so it keeps its precision at
 * grazing angles; 1/pi folded into the constants.
 * Domain: N.L, N.V in [FACET_COS_MIN, 1], L.V in [-1, 1], alpha, albedo.
 * Model error (against the Smith-GGX microsurface simulation of hammon,
 * bench/microsurface; alpha in [2^-10, 1], albedo in [0.25, 1]): relative,
 * N.L, N.V in [0.02, 1]: max 172.0% (+- 0.60%) at alpha 0.375, N.L 0.2, N.V 0.2,
 * phi 180, albedo 0.25, mean 22.4% (noise 0.095%); N.L, N.V in [0.2, 1]: max 172.0% (+- 0.60%),
 * mean 12.5%; absolute, in units of albedo / pi: max 791.1% (+- 1.62%).
 * Its five constants refitted to the same tables with the same operations
 * (bench/microsurface/hammon_refit.md): none lowers both the max and the
 * mean, so no refitted variant is offered.
 * Error: <= FACET_ERR_DIFFUSE_HAMMON_F32 (2^-20); measured max 2^-20.59 (worst port,
 * 30 M samples) at (0.331329554, 0.331329554, 0.999999702, 0.0131228399, 0.645663142)
 * before L.H = sqrt(t/2) was formed directly (2026-12-07); since, 2^-20.77
 * (sse2 and scalar, 3 M samples) at (0.478820592, 0.478820592, -0.541461647,
 * 0.00103950372, 1).
 * f32_fast: <= FACET_ERR_DIFFUSE_HAMMON_F32_FAST (2^-12.5); a cheaper
 * formulation: 0.5 / N.H without its floor at 1/2 (a rounding's worth);
 * measured 2^-14.06 (avx512, 3 M samples), 2^-14.01 with estimates at the
 * architectural bound (avx512).  No cheaper one within the bound was
 * found: the smooth term's two quartics are the formula itself (a cubic in
 * their place is 2^-7 off), and 0.5 / N.H needs its root and quotient to
 * about 2^-13; so the tiers differ by 1 of 46 operations and the port's
 * estimates (on x86: the avx512 root as x rsqrt14, the quotient vdivps in
 * both), measured 1.02-1.07x (bench/README.md), not 1.15x.  The same holds
 * for the hybrid and cheap variants below.
 * Budget: clamps 10, NaN 5, peak 0, term 31; fast: clamps 10, NaN 5, peak 0, term 30.
 * Cost: 46 ops (1 rsqrt, 1 rcp). */
float facet_diffuse_hammon_f32(float nol, float nov, float lov, float alpha, float albedo);
float facet_diffuse_hammon_f32_fast(float nol, float nov, float lov, float alpha, float albedo);
void facet_diffuse_hammon_f32_batch(float *out, const float *nol, const float *nov,
                                    const float *lov, const float *alpha, const float *albedo,
                                    size_t n);
void facet_diffuse_hammon_f32_fast_batch(float *out, const float *nol, const float *nov,
                                    const float *lov, const float *alpha, const float *albedo,
                                    size_t n);

/* Burley's diffuse ("Disney", 2012), a BRDF value:
 *   f_d90  = 0.5 + 2 r L.H^2,  r = sqrt(alpha), Disney's roughness (the
 *            slider whose square is the GGX alpha; some engines put alpha
 *            itself here: that is this kernel at alpha^2)
 *   result = albedo / pi (1 + (f_d90 - 1)(1 - N.L)^5)(1 + (f_d90 - 1)(1 - N.V)^5)
 * L.H is an input (loh_from_dots gives it from L.V).  Each factor is in
 * [1/2, 5/2]: no cancellation.  Not energy conserving: directional albedo
 * (albedo = 1; tests/oracle/test_oracle.c, N.V in {1, 0.5, 0.1, 0.01}, alpha in
 * {2^-10, 1/4, 1/2, 1}) from 0.542 (N.V = 0.01, alpha = 2^-10) to 1.538
 * (N.V = 0.01, alpha = 1); at N.V = 1 exactly 1 - 1/42 + 5 sqrt(alpha)/84.
 * Domain: N.L, N.V in [FACET_COS_MIN, 1], L.H, alpha, albedo.
 * Model error (against the Smith-GGX microsurface simulation of hammon,
 * bench/microsurface; alpha in [2^-10, 1], albedo in [0.25, 1]): relative,
 * N.L, N.V in [0.02, 1]: max 6021.2% (+- 70.5%) at alpha 0.015625, N.L 0.02, N.V 0.02,
 * phi 180, albedo 0.25, mean 78.2% (noise 0.30%); N.L, N.V in [0.2, 1]: max 477.9% (+- 1.36%),
 * mean 32.0%; absolute, in units of albedo / pi: max 1237.1% (+- 1.81%).
 * Error: <= FACET_ERR_DIFFUSE_BURLEY_F32 (2^-20.5); measured max 2^-21.09 (worst port,
 * 3 M samples) at (0.00749915093, 0.00748796575, 0.00142297987, 0.191616133, 0.978153765).
 * f32_fast: <= FACET_ERR_DIFFUSE_BURLEY_F32_FAST (2^-12.5); measured
 * 2^-13.55 (avx512, 3 M samples).
 * Budget: clamps 10, NaN 5, peak 0, term 23; fast: clamps 10, NaN 5, peak 0, term 23.
 * Cost: 38 ops (1 rsqrt, 0 rcp). */
float facet_diffuse_burley_f32(float nol, float nov, float loh, float alpha, float albedo);
float facet_diffuse_burley_f32_fast(float nol, float nov, float loh, float alpha, float albedo);
void facet_diffuse_burley_f32_batch(float *out, const float *nol, const float *nov,
                                    const float *loh, const float *alpha, const float *albedo,
                                    size_t n);
void facet_diffuse_burley_f32_fast_batch(float *out, const float *nol, const float *nov,
                                         const float *loh, const float *alpha,
                                         const float *albedo, size_t n);

/* Oren-Nayar's qualitative diffuse with sigma = alpha / 2 (radians; the
 * mapping of Hammon's comparison), a BRDF value:
 *   A = 1 - 0.5 sigma^2 / (sigma^2 + 0.33),  B = 0.45 sigma^2 / (sigma^2 + 0.09)
 *   result = albedo / pi (A + B max(0, cos(phi_l - phi_v)) sin(theta_max) tan(theta_min))
 * without any angle: cos(phi_l - phi_v) sin(theta_l) sin(theta_v) =
 * L.V - N.L N.V and tan(theta_min) / sin(theta_min) = 1 / max(N.L, N.V), so
 *   result = albedo / pi (A + B max(0, L.V - N.L N.V) / max(N.L, N.V)),
 * one reciprocal for the whole (f32_body.h).  Inconsistent triples follow
 * that identity as it stands.  Largest at N.L = N.V = FACET_COS_MIN, L.V =
 * 1: (A + B 2^20) / pi (B <= 0.331).  Directional albedo (albedo = 1,
 * as diffuse_burley's): A(alpha) at N.V = 1 (0.785 at alpha = 1: the
 * qualitative model has no interreflection), 0.785 to 1.012 over that grid.
 * Domain: N.L, N.V in [FACET_COS_MIN, 1], L.V in [-1, 1], alpha, albedo.
 * Model error (against the Smith-GGX microsurface simulation of lambert,
 * bench/microsurface; alpha in [2^-10, 1], albedo in [0.25, 1]): relative,
 * N.L, N.V in [0.02, 1]: max 1555.4% (+- 11.1%) at alpha 0.125, N.L 0.02, N.V 0.02,
 * phi 180, albedo 0.25, mean 35.2% (noise 0.12%); N.L, N.V in [0.2, 1]: max 476.0% (+- 1.25%),
 * mean 18.1%; absolute, in units of albedo / pi: max 697.6% (+- 1.38%).
 * Error: <= FACET_ERR_DIFFUSE_OREN_NAYAR_F32 (2^-20.5); measured max 2^-21.19 (worst port,
 * 3 M samples) at (0.0482582487, 0.0482582487, 1, 0.223686263, 2.82182633e-08).
 * f32_fast: <= FACET_ERR_DIFFUSE_OREN_NAYAR_F32_FAST (2^-12.5); measured
 * 2^-14.17 (avx512, 3 M samples).
 * Budget: clamps 10, NaN 5, peak 0, term 18; fast: clamps 10, NaN 5, peak 0, term 18.
 * Cost: 33 ops (0 rsqrt, 1 rcp). */
float facet_diffuse_oren_nayar_f32(float nol, float nov, float lov, float alpha, float albedo);
float facet_diffuse_oren_nayar_f32_fast(float nol, float nov, float lov, float alpha, float albedo);
void facet_diffuse_oren_nayar_f32_batch(float *out, const float *nol, const float *nov,
                                        const float *lov, const float *alpha, const float *albedo,
                                        size_t n);
void facet_diffuse_oren_nayar_f32_fast_batch(float *out, const float *nol, const float *nov,
                                             const float *lov, const float *alpha,
                                             const float *albedo, size_t n);

/* Hammon's hybrid diffuse: diffuse_hammon with the smooth term taken from
 * Disney's at f_d90 = 1/2,
 *   smooth = (1 - (1 - N.L)^5 / 2)(1 - (1 - N.V)^5 / 2)
 * (so at alpha = 0 it equals diffuse_burley at roughness 0); rough, single
 * (lerp by alpha) and multi (0.1159 alpha) as diffuse_hammon.
 * Directional albedo (albedo = 1, as diffuse_burley's): 0.513 (N.V = 0.01,
 * alpha = 2^-10) to 1.162 (N.V = 0.01, alpha = 1); its smooth part
 * integrates to (1 - (1 - N.V)^5 / 2)(1 - 1/42).
 * Domain: as diffuse_hammon.
 * Model error (against the Smith-GGX microsurface simulation of hammon,
 * bench/microsurface; alpha in [2^-10, 1], albedo in [0.25, 1]): relative,
 * N.L, N.V in [0.02, 1]: max 5952.7% (+- 69.7%) at alpha 0.015625, N.L 0.02, N.V 0.02,
 * phi 180, albedo 0.25, mean 51.8% (noise 0.25%); N.L, N.V in [0.2, 1]: max 280.8% (+- 0.84%),
 * mean 15.6%; absolute, in units of albedo / pi: max 773.9% (+- 1.68%).
 * Error: <= FACET_ERR_DIFFUSE_HAMMON_HYBRID_F32 (2^-20.5); measured max 2^-20.80 (every port,
 * 3 M samples) at (0.0105562946, 0.0105562946, -0.999777138, 0.00521175098, 0.465762138).
 * f32_fast: <= FACET_ERR_DIFFUSE_HAMMON_HYBRID_F32_FAST (2^-12.5); measured
 * 2^-14.06 (avx512, 3 M samples), 2^-14.01 with estimates at the
 * architectural bound (avx512).
 * Budget: clamps 10, NaN 5, peak 0, term 36; fast: clamps 10, NaN 5, peak 0, term 35.
 * Cost: 51 ops (1 rsqrt, 1 rcp). */
float facet_diffuse_hammon_hybrid_f32(float nol, float nov, float lov, float alpha,
                                      float albedo);
float facet_diffuse_hammon_hybrid_f32_fast(float nol, float nov, float lov, float alpha,
                                           float albedo);
void facet_diffuse_hammon_hybrid_f32_batch(float *out, const float *nol, const float *nov,
                                           const float *lov, const float *alpha,
                                           const float *albedo, size_t n);
void facet_diffuse_hammon_hybrid_f32_fast_batch(float *out, const float *nol, const float *nov,
                                                const float *lov, const float *alpha,
                                                const float *albedo, size_t n);

/* Hammon's cheaper diffuse: diffuse_hammon with smooth = 1 (Lambert):
 *   result = albedo (((1 - alpha) + alpha rough) / pi + albedo 0.1159 alpha).
 * Directional albedo (albedo = 1, as diffuse_burley's): 1.000 (alpha =
 * 2^-10) to 1.162 (N.V = 0.01, alpha = 1).
 * Domain: as diffuse_hammon.
 * Model error (against the Smith-GGX microsurface simulation of hammon,
 * bench/microsurface; alpha in [2^-10, 1], albedo in [0.25, 1]): relative,
 * N.L, N.V in [0.02, 1]: max 19984.4% (+- 231.4%) at alpha 0.015625, N.L 0.02, N.V 0.02,
 * phi 180, albedo 0.25, mean 115.0% (noise 0.56%); N.L, N.V in [0.2, 1]: max 426.6% (+- 1.17%),
 * mean 21.2%; absolute, in units of albedo / pi: max 738.9% (+- 1.68%).
 * Error: <= FACET_ERR_DIFFUSE_HAMMON_CHEAP_F32 (2^-20.5); measured max 2^-21.09 (sse2 and
 * scalar, 3 M samples) at (0.0100785885, 0.000585997652, 0.977368951, 0.722906172, 0.763459802).
 * f32_fast: <= FACET_ERR_DIFFUSE_HAMMON_CHEAP_F32_FAST (2^-12.5); measured
 * 2^-14.09 (avx512, 3 M samples), 2^-14.01 with estimates at the
 * architectural bound (avx512).
 * Budget: clamps 10, NaN 5, peak 0, term 19; fast: clamps 10, NaN 5, peak 0, term 18.
 * Cost: 34 ops (1 rsqrt, 1 rcp). */
float facet_diffuse_hammon_cheap_f32(float nol, float nov, float lov, float alpha,
                                     float albedo);
float facet_diffuse_hammon_cheap_f32_fast(float nol, float nov, float lov, float alpha,
                                          float albedo);
void facet_diffuse_hammon_cheap_f32_batch(float *out, const float *nol, const float *nov,
                                          const float *lov, const float *alpha,
                                          const float *albedo, size_t n);
void facet_diffuse_hammon_cheap_f32_fast_batch(float *out, const float *nol, const float *nov,
                                               const float *lov, const float *alpha,
                                               const float *albedo, size_t n);

/* Lambert: albedo / pi.  Domain: albedo in [0, 1].
 * Model error (against the Smith-GGX microsurface simulation of lambert,
 * bench/microsurface; alpha in [2^-10, 1], albedo in [0.25, 1]): relative,
 * N.L, N.V in [0.02, 1]: max 1565.2% (+- 11.1%) at alpha 0.125, N.L 0.02, N.V 0.02,
 * phi 180, albedo 0.25, mean 45.8% (noise 0.13%); N.L, N.V in [0.2, 1]: max 605.2% (+- 1.47%),
 * mean 26.1%; absolute, in units of albedo / pi: max 1641.2% (+- 1.68%).
 * Error: <= FACET_ERR_LAMBERT_F32 (2^-22.5); measured max 2^-23.26 (worst port,
 * 30 M samples) at (0.196352884).
 * f32_fast: the same code (no reciprocal), FACET_ERR_LAMBERT_F32_FAST
 * (2^-22.5).
 * Budget: clamps 2, NaN 2, peak 0, term 1; fast: clamps 2, NaN 2, peak 0, term 1.
 * Cost: 5 ops (0 rsqrt, 0 rcp). */
float facet_lambert_f32(float albedo);
float facet_lambert_f32_fast(float albedo);
void facet_lambert_f32_batch(float *out, const float *albedo, size_t n);
void facet_lambert_f32_fast_batch(float *out, const float *albedo, size_t n);

/* ==== The whole BRDF ==========================================================
 * Hammon's model, per light: GGX D, Hammon's visibility, Schlick's Fresnel
 * and Hammon's diffuse from the three dots; then its RGB forms (one
 * geometry, three channels), the batches over uniform materials, and the
 * vector entry that takes N, L, V. */
#define FACET_ERR_BRDF_HAMMON_F32                     2.698e-06 /* 2^-18.5 */
#define FACET_ERR_BRDF_HAMMON_F32_FAST                1.726e-04 /* 2^-12.5 */

/* The whole model, per light:
 *   brdf = D(N.H) Vis_hammon(N.L, N.V) F(f0, L.H) + diffuse_hammon
 * (a BRDF value; radiance = brdf * N.L * light).  D is evaluated from the
 * dots without forming N.H (see f32_body.h: the peak for small alpha is
 * ill-conditioned in N.H, so 2 + 2 L.V - (N.L + N.V)^2 is formed exactly,
 * in quarter units: (1 + L.V)/2 and N.L + N.V as unevaluated sums
 * (Fast2Sum) and ((1 + L.V)/2)_hi - ((N.L + N.V)/2)^2 exact before its one
 * rounding, the port's sqr_sub: an fnma, or the exact error of the square
 * without FMA); one square root and three quotients: alpha t / (e m) serves
 * both D and Vis, (1 - t/2) / (1 + L.H) gives 1 - L.H without cancellation
 * for the Fresnel tail, L.H / (N.L + N.V) gives 0.5 / N.H for the diffuse
 * (L.H = sqrt(t/2)); the 1/pi folded into the constants; no intermediate
 * subnormal for an input in the domain ((1 - L.H)^5 and D Vis carried
 * scaled by 2^80 and 2^-80: a subnormal costs Intel cores a microcode
 * assist per instruction).  Quotients and the root are the port's
 * div and sqrt: vdivps / vsqrtps on sse2, avx2 and avx512 (the divide unit
 * runs beside the FMA pipes), a times the reciprocal estimate and its steps
 * elsewhere.  The fast tier is the same formulation with 0.5 / N.H
 * without its floor at 0.5 (a rounding's worth) and the quotients of
 * D Vis and of 0.5 / N.H at the tier's estimate, 1 - L.H at the precise
 * one (F takes its fifth power); on avx512 the root is x times the raw
 * 14-bit rsqrt.  No cheaper formulation within 2^-12 was found: of its 77
 * operations 12 are clamps, 5 the NaN rule and 22 the exact peak (what
 * keeps alpha = 2^-10 at the peak inside the bound; the fast-math shader
 * peer, without it, is off by 0.4 to 0.66 there), and the terms' 38 are
 * the formula's own (bench/README.md, the operation budget).
 * Domain: N.L, N.V in [FACET_COS_MIN, 1], L.V in [-1, 1], alpha, f0, albedo.
 * Error: <= FACET_ERR_BRDF_HAMMON_F32 (2^-18.5); measured max 2^-19.78 (scalar and sse2;
 * 2^-19.92 avx2 and avx512; 300 k samples) at (0.129665449, 0.706130326, 0.417927355, 0.390637547,
 * 2.52674479e-11, 0).
 * f32_fast: <= FACET_ERR_BRDF_HAMMON_F32_FAST (2^-12.5); the Fresnel tail's
 * 1 - L.H, raised to the fifth power, is refined fully in both tiers;
 * measured worst 2^-12.99 (avx512, 300 k samples), 2^-12.69 with estimates
 * at the architectural bound (avx512, 30 k samples).
 * Budget: clamps 12, NaN 5, peak 22, term 39; fast: clamps 12, NaN 5, peak 22, term 38.
 * Cost: 78 ops (1 rsqrt, 3 rcp). */
float facet_brdf_hammon_f32(float nol, float nov, float lov, float alpha,
                            float f0, float albedo);
float facet_brdf_hammon_f32_fast(float nol, float nov, float lov, float alpha,
                            float f0, float albedo);
void facet_brdf_hammon_f32_batch(float *out, const float *nol, const float *nov, const float *lov,
                                 const float *alpha, const float *f0, const float *albedo, size_t n);
void facet_brdf_hammon_f32_fast_batch(float *out, const float *nol, const float *nov, const float *lov,
                                 const float *alpha, const float *f0, const float *albedo, size_t n);

/* brdf_hammon for an RGB f0 and albedo, the geometry (D, Vis, 1 - L.H, the
 * diffuse shape) computed once: out[c] equals
 * facet_brdf_hammon_f32(nol, nov, lov, alpha, f0[c], albedo[c]) bit for bit
 * (_f32_fast: facet_brdf_hammon_f32_fast's).  Every port header has the same
 * on its vector type V, one pointer per output channel and one argument per
 * input channel (sizeless vector types such as RVV's cannot be array
 * elements):
 *   facet_brdf_hammon_rgb_f32_<port>(V *out_r, V *out_g, V *out_b, V nol,
 *       V nov, V lov, V alpha, V f0_r, V f0_g, V f0_b, V albedo_r,
 *       V albedo_g, V albedo_b)
 * and facet_brdf_hammon_rgb_f32_fast_<port>(...) likewise. */
void facet_brdf_hammon_rgb_f32(float out[3], float nol, float nov, float lov,
                               float alpha, const float f0[3], const float albedo[3]);
void facet_brdf_hammon_rgb_f32_fast(float out[3], float nol, float nov, float lov,
                               float alpha, const float f0[3], const float albedo[3]);

/* ---- RGB batches, uniform materials, the vector entry ----------------------
 * A material whose parameters are the same for many samples, passed once:
 *   alpha     GGX width (perceptual roughness^2), clamped as the kernels
 *   f0        specular reflectance at normal incidence, linear RGB
 *   albedo    diffuse albedo, linear RGB
 * Distinct struct types, with named fields, so that f0 and albedo, or the
 * directions below, cannot be swapped by position in a call. */
typedef struct facet_material_f32 {
    float alpha;
    float f0[3];
    float albedo[3];
} facet_material_f32;

/* brdf_hammon for RGB f0 and albedo over n samples, the geometry (D, Vis,
 * 1 - L.H, the diffuse shape) computed once per sample: channel c of
 * sample i equals facet_brdf_hammon_f32_batch's result for (nol[i], nov[i],
 * lov[i], alpha[i], f0 of channel c, albedo of channel c) on the same port,
 * bit for bit (so the bounds, the domain and the NaN rule are brdf_hammon's:
 * a NaN in the geometry zeroes the sample's three channels, one in a
 * channel's f0 or albedo that channel).  Runs on the active port, any n,
 * any alignment; an output may be the very same array (same layout) as an
 * input, no other overlap.  Cost per sample: one brdf_hammon geometry and
 * three channel tails (measured by `build/facet-bench api`:
 * 0.48x to 0.64x the time of three brdf_hammon batches
 * on every port; the material forms 6-11% faster than planar arrays of the
 * same values; the interleaved forms gather through the stack, 1.9x to
 * 2.6x slower than planar on the vector ports).
 *   _batch:               planar: out[c][i], f0[c][i], albedo[c][i]
 *   _batch_interleaved:   out[3i + c], f0[3i + c], albedo[3i + c]
 *   _batch_material:      one uniform material m for all n samples, planar
 *                         out[c][i]; measured at least as fast as _batch
 *   _batch_material_interleaved: the same, out[3i + c]
 *   _batch_textured:      a textured material: m's alpha and f0 uniform,
 *                         albedo[c][i] per sample (m->albedo unused), planar
 *   _batch_textured_rough: the same with alpha[i] per sample (a roughness
 *                         texture; m->alpha unused too); both measured
 *                         within 3% of _batch_material and 2-6% faster
 *                         than _batch with the same values in arrays
 *                         (facet-bench api, every x86 port)
 * and the same for the fast tier (_f32_fast_batch...). */
void facet_brdf_hammon_rgb_f32_batch(float *const out[3], const float *nol, const float *nov,
                                     const float *lov, const float *alpha,
                                     const float *const f0[3], const float *const albedo[3],
                                     size_t n);
void facet_brdf_hammon_rgb_f32_batch_interleaved(float *out, const float *nol, const float *nov,
                                                 const float *lov, const float *alpha,
                                                 const float *f0, const float *albedo, size_t n);
void facet_brdf_hammon_rgb_f32_batch_material(float *const out[3], const float *nol,
                                              const float *nov, const float *lov,
                                              const facet_material_f32 *m, size_t n);
void facet_brdf_hammon_rgb_f32_batch_material_interleaved(float *out, const float *nol,
                                                          const float *nov, const float *lov,
                                                          const facet_material_f32 *m, size_t n);
void facet_brdf_hammon_rgb_f32_batch_textured(float *const out[3], const float *nol,
                                              const float *nov, const float *lov,
                                              const facet_material_f32 *m,
                                              const float *const albedo[3], size_t n);
void facet_brdf_hammon_rgb_f32_batch_textured_rough(float *const out[3], const float *nol,
                                                    const float *nov, const float *lov,
                                                    const float *alpha, const facet_material_f32 *m,
                                                    const float *const albedo[3], size_t n);
void facet_brdf_hammon_rgb_f32_fast_batch(float *const out[3], const float *nol, const float *nov,
                                          const float *lov, const float *alpha,
                                          const float *const f0[3], const float *const albedo[3],
                                          size_t n);
void facet_brdf_hammon_rgb_f32_fast_batch_interleaved(float *out, const float *nol,
                                                      const float *nov, const float *lov,
                                                      const float *alpha, const float *f0,
                                                      const float *albedo, size_t n);
void facet_brdf_hammon_rgb_f32_fast_batch_material(float *const out[3], const float *nol,
                                                   const float *nov, const float *lov,
                                                   const facet_material_f32 *m, size_t n);
void facet_brdf_hammon_rgb_f32_fast_batch_material_interleaved(float *out, const float *nol,
                                                               const float *nov, const float *lov,
                                                               const facet_material_f32 *m,
                                                               size_t n);
void facet_brdf_hammon_rgb_f32_fast_batch_textured(float *const out[3], const float *nol,
                                                   const float *nov, const float *lov,
                                                   const facet_material_f32 *m,
                                                   const float *const albedo[3], size_t n);
void facet_brdf_hammon_rgb_f32_fast_batch_textured_rough(float *const out[3], const float *nol,
                                                         const float *nov, const float *lov,
                                                         const float *alpha,
                                                         const facet_material_f32 *m,
                                                         const float *const albedo[3], size_t n);

/* The vector entry, for per-pixel shaders: unit vectors in one struct with
 * named fields (n: the shading normal, l: towards the light, v: towards the
 * viewer), so that they cannot be passed in the wrong order by position. */
typedef struct facet_vec3_f32 {
    float x, y, z;
} facet_vec3_f32;

typedef struct facet_dirs_f32 {
    facet_vec3_f32 n, l, v;
} facet_dirs_f32;

/* out[c] = brdf_hammon(N.L, N.V, L.V, m->alpha, m->f0[c], m->albedo[c]) * N.L,
 * the radiance factor of one light per unit of its irradiance (multiply by
 * the light's colour).  The dots are formed here (plain float products and
 * sums), then facet_brdf_hammon_rgb_f32.
 * Below-horizon rule: the light below the shading horizon, N.L <= 0, gives
 * exactly 0 in every channel; the view below it, N.V <= 0 (interpolated or
 * normal-mapped normals at silhouettes), is evaluated at N.V =
 * FACET_COS_MIN, the kernel's clamp, so silhouettes do not turn black.
 * NaN in any component of n, l, v or in the material: 0 in the affected
 * channels (the kernels' NaN rule; a NaN direction gives NaN dots).  N.L
 * above 1 (vectors not quite unit) counts as 1 in the factor.
 * Error: the kernel's bound at the dots as formed (2^-18.5; the dots' own
 * rounding is the caller's geometry), plus one rounding for the factor.
 * Cost: 15 scalar ops for the three dots, 2 compares and 3 multiplies for
 * the factor, then facet_brdf_hammon_rgb_f32 (the active port's per-sample
 * entry: measured within noise of that call alone, `build/facet-bench api`). */
void facet_shade_hammon_rgb_f32(float out[3], const facet_dirs_f32 *dirs,
                                const facet_material_f32 *m);
/* the same on facet_brdf_hammon_rgb_f32_fast */
void facet_shade_hammon_rgb_f32_fast(float out[3], const facet_dirs_f32 *dirs,
                                     const facet_material_f32 *m);

/* ---- ports -----------------------------------------------------------------
 * facet_set_port(name) forces one for all batch calls in the process:
 * "scalar", "sse2", "avx2", "avx512", "neon", "helium", "rvv" (those compiled
 * into this build: facet_port_at), or "auto" (the automatic choice).  Returns
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

/* ==== GGX and GTR importance sampling ========================================
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
 *     h.z > 0, for every input including NaN and Inf (tests/sample/test_sample_ports.c).
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
 *     Bounds: maximum over tests/sample/test_sample_accuracy.c's sweep (200 k
 *     samples per sampler aimed at the ends of u, grazing and normal views,
 *     alpha log-uniform) on every port, in the fast tier also with
 *     estimates at the architectural bound; FACET_ERR_<SAMPLER>_F32[_FAST].
 *   - The sampled distributions are checked by chi-square goodness of fit
 *     against the pdfs (tests/sample/test_sample_chi2.c: 10^6 samples, 2-D
 *     histograms in (theta, phi), alpha 0.05 .. 1, views to 89.9 degrees,
 *     p > 0.01 each; moments for alpha down to 0.002), and the VNDF
 *     estimator by a white furnace (tests/sample/test_sample_furnace.c).
 *   - Cost: operations as the kernels' (tests/sample/test_sample_prims.c counts
 *     them; the exponent-bit ops exp2i, getexp, getmant count 1).
 *   - Batch: SoA outputs first (hx, hy, hz / lx, ly, lz / out / sin, cos),
 *     then the inputs in the order of the one-sample call; any n, no
 *     alignment requirement, outputs may alias inputs; runs on the port the
 *     kernels run on (facet_set_port, FACET_PORT).
 *   - Declarations: as the kernels', per sampler or pdf facet_<name>_f32,
 *     facet_<name>_f32_fast, facet_<name>_f32_batch and
 *     facet_<name>_f32_fast_batch; below, one block per kind of sampling,
 *     each with its bounds (FACET_ERR_<NAME>_F32[_FAST]), contracts and
 *     declarations. */

/* ---- sampling D: GGX, isotropic and anisotropic --------------------------
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
 *   Cost: 27 ops (0 rsqrt, 1 rcp). */
#define FACET_ERR_GGX_SAMPLE_D_F32                    2.384e-07 /* 2^-22, distance */
#define FACET_ERR_GGX_SAMPLE_D_F32_FAST               8.632e-05 /* 2^-13.5, distance */
#define FACET_ERR_GGX_PDF_D_F32                       9.537e-07 /* 2^-20 */
#define FACET_ERR_GGX_PDF_D_F32_FAST                  1.726e-04 /* 2^-12.5 */
#define FACET_ERR_GGX_SAMPLE_D_ANISO_F32              3.372e-07 /* 2^-21.5, distance */
#define FACET_ERR_GGX_SAMPLE_D_ANISO_F32_FAST         8.632e-05 /* 2^-13.5, distance */
#define FACET_ERR_GGX_PDF_D_ANISO_F32                 9.537e-07 /* 2^-20 */
#define FACET_ERR_GGX_PDF_D_ANISO_F32_FAST            8.632e-05 /* 2^-13.5 */
void facet_ggx_sample_d_f32(float h[3], float u1, float u2, float alpha);
void facet_ggx_sample_d_f32_fast(float h[3], float u1, float u2, float alpha);
void facet_ggx_sample_d_f32_batch(float *hx, float *hy, float *hz, const float *u1,
                                  const float *u2, const float *alpha, size_t n);
void facet_ggx_sample_d_f32_fast_batch(float *hx, float *hy, float *hz, const float *u1,
                                       const float *u2, const float *alpha, size_t n);
float facet_ggx_pdf_d_f32(float noh, float alpha);
float facet_ggx_pdf_d_f32_fast(float noh, float alpha);
void facet_ggx_pdf_d_f32_batch(float *out, const float *noh, const float *alpha, size_t n);
void facet_ggx_pdf_d_f32_fast_batch(float *out, const float *noh, const float *alpha, size_t n);
void facet_ggx_sample_d_aniso_f32(float h[3], float u1, float u2, float alpha_x, float alpha_y);
void facet_ggx_sample_d_aniso_f32_fast(float h[3], float u1, float u2, float alpha_x, float alpha_y);
void facet_ggx_sample_d_aniso_f32_batch(float *hx, float *hy, float *hz, const float *u1,
                                        const float *u2, const float *alpha_x,
                                        const float *alpha_y, size_t n);
void facet_ggx_sample_d_aniso_f32_fast_batch(float *hx, float *hy, float *hz, const float *u1,
                                             const float *u2, const float *alpha_x,
                                             const float *alpha_y, size_t n);
float facet_ggx_pdf_d_aniso_f32(float hx, float hy, float hz, float alpha_x, float alpha_y);
float facet_ggx_pdf_d_aniso_f32_fast(float hx, float hy, float hz, float alpha_x, float alpha_y);
void facet_ggx_pdf_d_aniso_f32_batch(float *out, const float *hx, const float *hy,
                                     const float *hz, const float *alpha_x,
                                     const float *alpha_y, size_t n);
void facet_ggx_pdf_d_aniso_f32_fast_batch(float *out, const float *hx, const float *hy,
                                          const float *hz, const float *alpha_x,
                                          const float *alpha_y, size_t n);

/* ---- sampling the visible normals (VNDF), and the reflected direction -----
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
 *   Cost: 28 ops (1 rsqrt, 2 rcp). */
#define FACET_ERR_GGX_SAMPLE_VNDF_F32                 3.372e-07 /* 2^-21.5, distance */
#define FACET_ERR_GGX_SAMPLE_VNDF_F32_FAST            2.441e-04 /* 2^-12, distance */
#define FACET_ERR_GGX_SAMPLE_VNDF_ANISO_F32           4.768e-07 /* 2^-21, distance */
#define FACET_ERR_GGX_SAMPLE_VNDF_ANISO_F32_FAST      2.441e-04 /* 2^-12, distance */
#define FACET_ERR_GGX_PDF_VNDF_F32                    9.537e-07 /* 2^-20 */
#define FACET_ERR_GGX_PDF_VNDF_F32_FAST               2.441e-04 /* 2^-12 */
#define FACET_ERR_GGX_PDF_VNDF_ANISO_F32              9.537e-07 /* 2^-20 */
#define FACET_ERR_GGX_PDF_VNDF_ANISO_F32_FAST         1.726e-04 /* 2^-12.5 */
#define FACET_ERR_REFLECT_F32                         3.372e-07 /* 2^-21.5, distance */
#define FACET_ERR_REFLECT_F32_FAST                    3.372e-07 /* 2^-21.5, distance */
#define FACET_ERR_GGX_PDF_VNDF_REFLECT_F32            9.537e-07 /* 2^-20 */
#define FACET_ERR_GGX_PDF_VNDF_REFLECT_F32_FAST       2.441e-04 /* 2^-12 */
void facet_ggx_sample_vndf_f32(float h[3], float vx, float vy, float vz, float u1, float u2,
                               float alpha);
void facet_ggx_sample_vndf_f32_fast(float h[3], float vx, float vy, float vz, float u1, float u2,
                                    float alpha);
void facet_ggx_sample_vndf_f32_batch(float *hx, float *hy, float *hz, const float *vx,
                                     const float *vy, const float *vz, const float *u1,
                                     const float *u2, const float *alpha, size_t n);
void facet_ggx_sample_vndf_f32_fast_batch(float *hx, float *hy, float *hz, const float *vx,
                                          const float *vy, const float *vz, const float *u1,
                                          const float *u2, const float *alpha, size_t n);
void facet_ggx_sample_vndf_aniso_f32(float h[3], float vx, float vy, float vz, float u1, float u2,
                                     float alpha_x, float alpha_y);
void facet_ggx_sample_vndf_aniso_f32_fast(float h[3], float vx, float vy, float vz, float u1,
                                          float u2, float alpha_x, float alpha_y);
void facet_ggx_sample_vndf_aniso_f32_batch(float *hx, float *hy, float *hz, const float *vx,
                                           const float *vy, const float *vz, const float *u1,
                                           const float *u2, const float *alpha_x,
                                           const float *alpha_y, size_t n);
void facet_ggx_sample_vndf_aniso_f32_fast_batch(float *hx, float *hy, float *hz,
                                                const float *vx, const float *vy,
                                                const float *vz, const float *u1,
                                                const float *u2, const float *alpha_x,
                                                const float *alpha_y, size_t n);
float facet_ggx_pdf_vndf_f32(float nov, float noh, float voh, float alpha);
float facet_ggx_pdf_vndf_f32_fast(float nov, float noh, float voh, float alpha);
void facet_ggx_pdf_vndf_f32_batch(float *out, const float *nov, const float *noh,
                                  const float *voh, const float *alpha, size_t n);
void facet_ggx_pdf_vndf_f32_fast_batch(float *out, const float *nov, const float *noh,
                                       const float *voh, const float *alpha, size_t n);
float facet_ggx_pdf_vndf_aniso_f32(float vx, float vy, float vz, float hx, float hy, float hz,
                                   float alpha_x, float alpha_y);
float facet_ggx_pdf_vndf_aniso_f32_fast(float vx, float vy, float vz, float hx, float hy, float hz,
                                        float alpha_x, float alpha_y);
void facet_ggx_pdf_vndf_aniso_f32_batch(float *out, const float *vx, const float *vy,
                                        const float *vz, const float *hx, const float *hy,
                                        const float *hz, const float *alpha_x,
                                        const float *alpha_y, size_t n);
void facet_ggx_pdf_vndf_aniso_f32_fast_batch(float *out, const float *vx, const float *vy,
                                             const float *vz, const float *hx, const float *hy,
                                             const float *hz, const float *alpha_x,
                                             const float *alpha_y, size_t n);
void facet_reflect_f32(float l[3], float vx, float vy, float vz, float hx, float hy, float hz);
void facet_reflect_f32_fast(float l[3], float vx, float vy, float vz, float hx, float hy, float hz);
void facet_reflect_f32_batch(float *lx, float *ly, float *lz, const float *vx, const float *vy,
                             const float *vz, const float *hx, const float *hy, const float *hz,
                             size_t n);
void facet_reflect_f32_fast_batch(float *lx, float *ly, float *lz, const float *vx,
                                  const float *vy, const float *vz, const float *hx,
                                  const float *hy, const float *hz, size_t n);
float facet_ggx_pdf_vndf_reflect_f32(float nov, float noh, float voh, float alpha);
float facet_ggx_pdf_vndf_reflect_f32_fast(float nov, float noh, float voh, float alpha);
void facet_ggx_pdf_vndf_reflect_f32_batch(float *out, const float *nov, const float *noh,
                                          const float *voh, const float *alpha, size_t n);
void facet_ggx_pdf_vndf_reflect_f32_fast_batch(float *out, const float *nov, const float *noh,
                                               const float *voh, const float *alpha, size_t n);

/* ---- sampling GTR D ----------------------------------------------------------
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
 *   Cost: 74 ops (0 rsqrt, 4 rcp). */
#define FACET_ERR_GTR_SAMPLE_D_F32                    4.768e-07 /* 2^-21, distance */
#define FACET_ERR_GTR_SAMPLE_D_F32_FAST               1.726e-04 /* 2^-12.5, distance */
#define FACET_ERR_GTR_PDF_D_F32                       9.537e-07 /* 2^-20 */
#define FACET_ERR_GTR_PDF_D_F32_FAST                  2.441e-04 /* 2^-12 */
void facet_gtr_sample_d_f32(float h[3], float u1, float u2, float alpha, float gamma);
void facet_gtr_sample_d_f32_fast(float h[3], float u1, float u2, float alpha, float gamma);
void facet_gtr_sample_d_f32_batch(float *hx, float *hy, float *hz, const float *u1,
                                  const float *u2, const float *alpha, const float *gamma,
                                  size_t n);
void facet_gtr_sample_d_f32_fast_batch(float *hx, float *hy, float *hz, const float *u1,
                                       const float *u2, const float *alpha, const float *gamma,
                                       size_t n);
float facet_gtr_pdf_d_f32(float noh, float alpha, float gamma);
float facet_gtr_pdf_d_f32_fast(float noh, float alpha, float gamma);
void facet_gtr_pdf_d_f32_batch(float *out, const float *noh, const float *alpha,
                               const float *gamma, size_t n);
void facet_gtr_pdf_d_f32_fast_batch(float *out, const float *noh, const float *alpha,
                                    const float *gamma, size_t n);

/* ---- the azimuth -------------------------------------------------------------
 * sincos_2pi(sc, u): sc[0] = sin(2 pi u), sc[1] = cos(2 pi u), u as u1;
 *   the samplers' azimuth, exposed for tests and tools.  The sine keeps
 *   2^-21 relative accuracy near u = 0; sin^2 + cos^2 = 1 within 2^-22.
 *   Error <= 2^-23 (both tiers; measured 2^-23.31, sse2, on every 5th
 *   multiple of 2^-24).
 *   Cost: 27 ops. */
#define FACET_ERR_SINCOS_2PI_F32                      1.192e-07 /* 2^-23, distance */
#define FACET_ERR_SINCOS_2PI_F32_FAST                 1.192e-07 /* 2^-23, distance */
void facet_sincos_2pi_f32(float sc[2], float u);
void facet_sincos_2pi_f32_fast(float sc[2], float u);
void facet_sincos_2pi_f32_batch(float *s, float *c, const float *u, size_t n);
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
