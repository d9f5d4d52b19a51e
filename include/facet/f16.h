/* facet/f16.h - the binary16 (f16) format: API, domain and contracts.
 *
 * Storage: IEEE 754 binary16 bit patterns in uint16_t (facet_f16), in and
 * out.  Not _Float16: C99 and C++ before C++23 have no such type, tcc, pcc
 * and MSVC have none, and where gcc has one its ABI differs by target (an
 * SSE register on x86-64, a general one elsewhere); uint16_t is what image
 * formats, GPU buffers and half-float files store, is the same on every
 * compiler, and carries the bits through untouched.  facet_f32_from_f16 and
 * facet_f16_from_f32 convert (exactly, and rounded to nearest even).
 *
 * Computation: in binary16 lanes (AVX-512 FP16: 32 per zmm register; ARMv8.2
 * FP16 NEON and Helium MVE: 8 per q register; RISC-V Vector with Zvfh: VLEN
 * / 16 per vector register; the scalar port, the
 * specification, emulates binary16 in portable C: facet/f16_scalar.h), except the few operations binary16 cannot hold,
 * which run in f32 lanes from the exact binary16 inputs: ggx_d's
 * d = 1 - N.H^2 + alpha^2 N.H^2 and its quotient, ggx_aniso_d's K and D
 * (ax^2 ay^2 down to 2^-28; D as K^-2), and brdf_hammon's
 * specular term D Vis F (the peak 2 + 2 L.V - (N.L + N.V)^2 cancels; y^5
 * raises a rounding five times; D Vis F spans 2^-18 .. 2^24); the kernel's
 * contract says which.  One tier: binary16's rounding (2^-11) is the cost
 * the format buys, and the reciprocal and rsqrt estimates are used at
 * about that precision (avx512fp16: vrcpph / vrsqrtph as they are, within
 * 2^-11 + 2^-14 by the SDM; neonfp16: 8-bit estimates and one step;
 * rvvfp16: 7-bit estimates and one step).
 *
 * Domain, for every f16 kernel:
 *   alpha   [FACET_F16_ALPHA_MIN, 1] = [2^-7, 1] (perceptual roughness
 *           0.0884, Filament's mobile floor 0.089): alpha^2 >= 2^-14, the
 *           smallest binary16 normal, so D's alpha^2 / d^2 keeps binary16's
 *           precision (below it alpha^2 is subnormal: 2^-15 has 10 bits,
 *           2^-20 5); D <= 1 / (pi alpha^2) = 5215 stays below 65504.
 *   N.L, N.V [FACET_F16_COS_MIN, 1] = [2^-7, 1] (89.55 degrees): N.L N.V >=
 *           2^-14 stays normal, Vis <= 2^12, and N.L + N.V is exact in f32
 *           (18 bits) for the f32 peak.  A rasterizer multiplies by N.L:
 *           the clamp only changes light at N.L < 0.0078.  The same floor
 *           for smith_g1, smith_g1_hammon, smith_g1_schlick_beckmann,
 *           g_implicit and g_neumann, whose f32 forms take N.V (N.L) from 0.
 *   L.V     [-1, 1], and T.H, B.H (ggx_aniso_d); alpha_x, alpha_y as alpha;
 *           f0, f90, albedo, cosines of Fresnel, N.H, L.H, V.H: [0, 1].
 * Outside it: clamped (below the low end, -Inf and NaN to the low end, +Inf
 * to the high end).  NaN rule: a NaN in any input (every NaN class: quiet,
 * signalling, either sign, any payload) gives +0 (bits 0x0000).  Results
 * are never Inf or NaN: values that would exceed 65504 (brdf_hammon at
 * grazing, small alpha) saturate to 65504 (0x7bff).
 *
 * Error: against the double oracle (facet/oracle.h) at the same binary16
 * inputs, after the domain clamp above: |got - want| <= bound * max(|want|,
 * 2^-14) (values below the smallest normal 2^-14 are compared absolutely,
 * bound * 2^-14: binary16's subnormals have 10 bits and fewer), and where
 * want > 65504 the result is 65504.  The bounds FACET_ERR_<NAME>_F16 below
 * are measured (tests/f16/test_f16_accuracy.c enforces them on every port
 * this CPU runs; the table it prints is where they come from); "about
 * 2^-8" (half an 8-bit sRGB code).
 *
 * Speed (build/facet-f16-bench: one run, interleaved, TSC ticks per
 * sample, 1024-sample batches, this shared 2-core Xeon with AVX-512 FP16;
 * f32 and f32_fast on the avx512 port, 16 lanes, f16 on avx512fp16, 32
 * lanes; f16 / f32 precise, the range over 6 runs): noh 2.41-2.59, loh
 * 2.42-2.62, fresnel_schlick 1.70-1.83, ggx_d 0.96-1.01, smith_vis
 * 3.44-3.71, smith_vis_hammon 2.10-2.30, diffuse_hammon 2.03-2.26,
 * brdf_hammon 1.21-1.27, lambert 1.54-1.93 (memory bound).  Per 32
 * samples (llvm-mca-16 -mcpu=sapphirerapids, uops on the 512-bit FP ports
 * p0 and p5; the f32 kernel's per 16 samples in brackets): noh 19 (22),
 * loh 12 (15), fresnel_schlick 15 (14), ggx_d 38 (15 and a vdivps),
 * smith_vis 35 (33 with a vdivps and two vsqrtps), smith_vis_hammon 18
 * (17), diffuse_hammon 55 (53), brdf_hammon 176 (97 with three vdivps and
 * a vsqrtps), lambert 5 (4).  ggx_d and brdf_hammon keep f32 lanes for the
 * part binary16 cannot hold to 2^-8 (measured: binary16-only ggx_d forms
 * reach 4.0e-3 to 4.6e-3), and every f32 operation costs two uops per 32
 * samples, every conversion of 16 lanes two: brdf_hammon's 176 are 114 in
 * f32 lanes (five inputs widened, 25; 33 operations, 66; three estimates,
 * 18; the narrowing, 5) and 62 in binary16 (clamps 12, the diffuse 39,
 * the NaN rule 5, the sum 2, moves).  Against the binary16 shader-style
 * transcription (-ffast-math, 71 uops; the same run measures it at 9.4%
 * Inf and 18% beyond 2^-8 for brdf_hammon, 34% Inf for ggx_d)
 * brdf_hammon runs at 0.40x-0.43x.  Issue 22's targets for brdf_hammon (2.5x f32, 0.6x the
 * transcription: at most about 78 and 118 such uops) are not met: the
 * f32-lane specular term alone is 114.
 * The kernels given an f16 form with issue 22 item 1, one run of the same
 * bench (2026-12-07, f16 / f32 precise): fresnel_schlick_f90 1.92,
 * ggx_aniso_d 0.82 (all of D in f32 lanes, five inputs widened: slower
 * than the f32 kernel; it buys binary16 in and out), smith_g1 3.92,
 * smith_g2 3.71, smith_g2_uncorrelated 3.06, smith_g1_hammon 2.79,
 * smith_g2_hammon 2.03, g_implicit 2.04, g_neumann 2.02, g_cook_torrance
 * 2.20, g_kelemen 2.26, smith_g1_schlick_beckmann 2.63,
 * smith_vis_joint_approx 2.09, diffuse_burley 1.51, diffuse_oren_nayar 2.17,
 * diffuse_hammon_hybrid 2.36, diffuse_hammon_cheap 2.29.
 *
 * The bounds are the largest measured on any port: scalar and avx512fp16
 * over 2,000,000 samples per kernel (test_f16_accuracy 2000000), the
 * latter also with its estimates at their architectural worst
 * (FACET_AVX512FP16_TEST_WORST_ESTIMATES: ggx_d's and smith_vis's bounds
 * are those), neonfp16 over 1,000,000 under qemu-aarch64 (Arm's
 * frecpe/frsqrte are defined bit for bit by the architecture, so the
 * emulator computes what the hardware does); neonfp16's 8-bit estimates
 * plus one step make noh and loh their largest.  heliumfp16 (MVE: no
 * estimate instruction; bit seeds and two Newton steps, facet/heliumfp16.h)
 * over 2,000,000 under qemu-system-arm -M mps3-an547 (Cortex-M55), within
 * every bound (clang 14's objects, 2026-12-07: noh 1.55e-3, loh 9.77e-4,
 * fresnel_schlick 2.13e-3, ggx_d 1.41e-3,
 * smith_vis 1.93e-3, smith_vis_hammon 1.53e-3, diffuse_hammon 3.82e-3,
 * brdf_hammon 3.58e-3, lambert 6.28e-4).  rvvfp16 (RISC-V Vector with Zvfh:
 * vfrec7 / vfrsqrt7 and one Newton step, facet/rvvfp16.h) over 2,000,000
 * under qemu-riscv64 -cpu rv64,v=true,Zfh=true at VLEN 128, 256 and 512 (the
 * same figures at each: a lane's arithmetic does not depend on VLEN), within
 * every bound: noh 1.54e-3, loh 1.08e-3, fresnel_schlick 2.13e-3, ggx_d
 * 1.44e-3, smith_vis 2.11e-3, smith_vis_hammon 1.61e-3, diffuse_hammon
 * 3.82e-3, brdf_hammon 3.58e-3, lambert 6.28e-4, and for the kernels given
 * an f16 form with issue 22 item 1 (VLEN 128): fresnel_schlick_f90 2.15e-3,
 * ggx_aniso_d 5.37e-4, smith_g1 1.86e-3, smith_g2 2.21e-3,
 * smith_g2_uncorrelated 2.80e-3, smith_g1_hammon 1.24e-3, smith_g2_hammon
 * 2.09e-3, g_implicit 4.88e-4, g_neumann 0, g_cook_torrance 1.33e-3,
 * g_kelemen 1.51e-3, smith_g1_schlick_beckmann 1.45e-3,
 * smith_vis_joint_approx 1.52e-3, diffuse_burley 3.09e-3,
 * diffuse_oren_nayar 2.56e-3, diffuse_hammon_hybrid 2.96e-3,
 * diffuse_hammon_cheap 3.08e-3 (the dispatcher refuses it there, qemu-user
 * 7.2 having no riscv_hwprobe: tests/suites/54-rvv.sh runs the table
 * itself, FACET_TEST_F16_FORCE).
 * The kernels given an f16 form
 * with issue 22 item 1 (fresnel_schlick_f90 to diffuse_hammon_cheap below)
 * were measured by the same runs (2026-12-07; neonfp16 over 1,000,000):
 * the worst-estimate avx512fp16 run gives the bounds of ggx_aniso_d,
 * smith_g1, smith_g2, smith_g2_hammon, g_kelemen, smith_g1_schlick_beckmann,
 * diffuse_oren_nayar, diffuse_hammon_hybrid and diffuse_hammon_cheap;
 * neonfp16 those of smith_g2_uncorrelated, smith_g1_hammon, g_cook_torrance
 * and smith_vis_joint_approx; every port has the same maximum for
 * fresnel_schlick_f90, g_implicit (its one rounding: u) and g_neumann (0),
 * and every port but neonfp16 (2.76e-3) for diffuse_burley.  heliumfp16
 * (clang 14's objects): fresnel_schlick_f90 2.15e-3, ggx_aniso_d 5.00e-4,
 * smith_g1 1.84e-3, smith_g2 2.30e-3, smith_g2_uncorrelated 2.80e-3,
 * smith_g1_hammon 1.24e-3, smith_g2_hammon 2.09e-3, g_implicit 4.88e-4,
 * g_neumann 0, g_cook_torrance 1.48e-3, g_kelemen 1.51e-3,
 * smith_g1_schlick_beckmann 1.45e-3, smith_vis_joint_approx 1.53e-3,
 * diffuse_burley 3.09e-3, diffuse_oren_nayar 2.56e-3, diffuse_hammon_hybrid
 * 3.15e-3, diffuse_hammon_cheap 3.08e-3.
 *
 * Speed on the Arm ports (ports/README.md, "Binary16"): f16 against f32
 * 1.7x to 2.3x in instructions, 1.8x to 2.5x in cycles on Helium
 * (Cortex-M55: qemu instructions, llvm-mca-16 cycles; ggx_aniso_d, all
 * f32 lanes, 1.20x) and 2.2x to 3.6x on NEON (llvm-mca's Cortex-A55 model;
 * ggx_aniso_d 2.09x) for the
 * binary16-only kernels; brdf_hammon 1.79x on NEON (target 1.7x: met on the
 * A55 model) but 1.14x / 1.21x on Helium (target missed: its f32-lane part
 * costs what binary16 saves, and on MVE's 8 Q registers the f32 lanes
 * spill).  RISC-V Vector with Zvfh (rvvfp16, facet/rvvfp16.h: qemu
 * instructions per sample, VLEN 128 / 256 / 512): the binary16-only
 * kernels execute 1.6x to 2.4x fewer than the rvv f32 port, brdf_hammon
 * 1.42x / 1.40x / 1.36x (short of the 1.7x asked of NEON and Helium: its
 * f32 lanes are LMUL 2 groups).
 *
 * Ways in: facet_<kernel>_f16 (one sample, the scalar port),
 * facet_<kernel>_f16_batch (any count, any alignment, out may be an input:
 * the best f16 port for this CPU), inline facet_<kernel>_f16_<port>
 * (facet/f16_scalar.h on float-held binary16 values, facet/avx512fp16.h on
 * __m512h, facet/neonfp16.h and facet/heliumfp16.h on float16x8_t,
 * facet/rvvfp16.h on vfloat16m1_t).  Which kernels have an f16 form, and why the others do not:
 * src/core/f16_kernels.def (`facet list --formats`). */
#ifndef FACET_F16_H
#define FACET_F16_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef uint16_t facet_f16; /* an IEEE binary16 bit pattern */

#define FACET_F16_ALPHA_MIN 0.0078125f /* 2^-7 */
#define FACET_F16_COS_MIN 0.0078125f   /* 2^-7 */
#define FACET_F16_MAX 65504.0f         /* the largest binary16, bits 0x7bff */

/* binary16 to float: exact (NaN stays NaN, Inf stays Inf) */
float facet_f32_from_f16(facet_f16 h);
/* float to binary16: rounded to nearest even, as IEEE converts (overflow
 * to Inf, NaN to a quiet NaN): the kernels' inputs may be anything */
facet_f16 facet_f16_from_f32(float x);
void facet_f16_from_f32_batch(facet_f16 *out, const float *in, size_t n);
void facet_f32_from_f16_batch(float *out, const facet_f16 *in, size_t n);

/* The f16 port running the batches: "avx512fp16" where the CPU has
 * AVX-512 FP16 (CPUID.(EAX=7,ECX=0):EDX[23], with AVX-512 BW and VL, and
 * the OS saving ZMM state) and the active port (facet_set_port) is
 * avx512; "neonfp16" on aarch64 where HWCAP has FPHP and ASIMDHP;
 * "heliumfp16" on Armv8.1-M where MVFR1.MVE is 2 (MVE with floating point:
 * Cortex-M55, M85) and the active port is helium; "rvvfp16" on riscv64 Linux
 * where AT_HWCAP has V, the riscv_hwprobe system call reports Zvfh
 * (RISCV_HWPROBE_EXT_ZVFH) and the active port is rvv (refused where the
 * call is absent: a kernel before 6.4, qemu-user 7.2); else "scalar".  facet_f16_port_supported(name): 1 where this CPU
 * runs it; facet_f16_port_refusal(name): why not (NULL where it does, or
 * for an unknown name). */
const char *facet_f16_port_name(void);
int facet_f16_port_supported(const char *name);
const char *facet_f16_port_refusal(const char *name);

/* ---- the kernels ----------------------------------------------------------
 * Formulas as the f32 kernels of facet.h; each bound is the measured
 * maximum, rounded up (test_f16_accuracy prints it). */

/* N.H from the dots, s rsqrt(max(2 + 2 L.V, s^2)), s = N.L + N.V; in
 * [0, 1].  Binary16 throughout: 4 clamps, 6 ops and an rsqrt. */
#define FACET_ERR_NOH_FROM_DOTS_F16 1.75e-3
facet_f16 facet_noh_from_dots_f16(facet_f16 nol, facet_f16 nov, facet_f16 lov);
/* L.H = sqrt((1 + L.V) / 2); binary16 throughout. */
#define FACET_ERR_LOH_FROM_DOTS_F16 1.4e-3
facet_f16 facet_loh_from_dots_f16(facet_f16 lov);
/* Schlick: f0 + (1 - f0) (1 - cos)^5, 1 - cos carried as two binary16
 * values (Fast2Sum); binary16 throughout. */
#define FACET_ERR_FRESNEL_SCHLICK_F16 2.15e-3
facet_f16 facet_fresnel_schlick_f16(facet_f16 f0, facet_f16 cos);
/* GGX D = alpha^2 / (pi (1 - N.H^2 + alpha^2 N.H^2)^2) <= 5215; d and
 * alpha / (sqrt(pi) d) in f32 lanes (2 conversions, 5 operations, a
 * reciprocal estimate), the square in binary16. */
#define FACET_ERR_GGX_D_F16 1.55e-3
facet_f16 facet_ggx_d_f16(facet_f16 noh, facet_f16 alpha);
/* Smith visibility, height-correlated exact form, <= 2^12; binary16
 * throughout (radicands as sums of non-negative terms; 2 square roots and
 * a quotient from the estimates). */
#define FACET_ERR_SMITH_VIS_F16 2.4e-3
facet_f16 facet_smith_vis_f16(facet_f16 nol, facet_f16 nov, facet_f16 alpha);
/* Hammon's visibility 0.5 / lerp(2 N.L N.V, N.L + N.V, alpha) <= 2^12;
 * binary16 throughout. */
#define FACET_ERR_SMITH_VIS_HAMMON_F16 1.8e-3
facet_f16 facet_smith_vis_hammon_f16(facet_f16 nol, facet_f16 nov, facet_f16 alpha);
/* Hammon's diffuse (facet.h); binary16 throughout. */
#define FACET_ERR_DIFFUSE_HAMMON_F16 3.85e-3
facet_f16 facet_diffuse_hammon_f16(facet_f16 nol, facet_f16 nov, facet_f16 lov, facet_f16 alpha,
                                   facet_f16 albedo);
/* The whole Hammon BRDF D Vis_hammon F + diffuse_hammon, saturated at
 * 65504: the specular term D Vis F in f32 lanes (the peak without
 * cancellation, as the f32 kernel; 5 conversions, 33 operations, 3
 * estimates), narrowed once; the diffuse (diffuse_hammon's binary16 body,
 * to the bit) and the sum in binary16. */
#define FACET_ERR_BRDF_HAMMON_F16 3.7e-3
facet_f16 facet_brdf_hammon_f16(facet_f16 nol, facet_f16 nov, facet_f16 lov, facet_f16 alpha,
                                facet_f16 f0, facet_f16 albedo);
/* albedo / pi */
#define FACET_ERR_LAMBERT_F16 6.3e-4
facet_f16 facet_lambert_f16(facet_f16 albedo);

/* ---- the rest of the menu, in src/core/f16_kernels.def order ----------------
 * Each bound is the measured maximum over the ports (below), rounded up. */

/* Schlick with f90: f0 (1 - y^5) + f90 y^5, y = 1 - V.H (f90 < f0 does not
 * cancel); 1 - y^5 = c Q(c) by Horner in positive terms, y^5 as
 * fresnel_schlick's; binary16 throughout. */
#define FACET_ERR_FRESNEL_SCHLICK_F90_F16 2.15e-3
facet_f16 facet_fresnel_schlick_f90_f16(facet_f16 f0, facet_f16 f90, facet_f16 voh);
/* Anisotropic GGX 1 / (pi ax ay k^2), k = (T.H/ax)^2 + (B.H/ay)^2 + N.H^2
 * floored at 1/2 (facet.h), <= 4 / (pi ax ay) < 2^15; T.H, B.H in [-1, 1],
 * alpha_x, alpha_y in [2^-7, 1].  In f32 lanes (5 conversions, 14
 * operations, a reciprocal estimate), narrowed once: ax^2 ay^2 reaches
 * 2^-28, below binary16's normals, and D goes as K^-2 (f16_body.h). */
#define FACET_ERR_GGX_ANISO_D_F16 6.09e-4
facet_f16 facet_ggx_aniso_d_f16(facet_f16 noh, facet_f16 toh, facet_f16 boh, facet_f16 alpha_x,
                                facet_f16 alpha_y);
/* Exact Smith G1 for GGX, 2 N.V / (N.V + sqrt(alpha^2 (1 - N.V^2) + N.V^2)),
 * N.V in [2^-7, 1] as every f16 cosine; binary16 throughout (1 - N.V^2 in
 * one fnma, a root and a quotient from the estimates). */
#define FACET_ERR_SMITH_G1_F16 2.31e-3
facet_f16 facet_smith_g1_f16(facet_f16 nov, facet_f16 alpha);
/* Exact height-correlated Smith G2 (= 4 N.L N.V smith_vis); binary16
 * throughout, two roots and a quotient. */
#define FACET_ERR_SMITH_G2_F16 2.88e-3
facet_f16 facet_smith_g2_f16(facet_f16 nol, facet_f16 nov, facet_f16 alpha);
/* G1(L) G1(V); binary16 throughout, one quotient, each root with one
 * Newton correction (3 operations: the two roots' errors multiply here). */
#define FACET_ERR_SMITH_G2_UNCORRELATED_F16 2.85e-3
facet_f16 facet_smith_g2_uncorrelated_f16(facet_f16 nol, facet_f16 nov, facet_f16 alpha);
/* Hammon's G1 2 N.V / (N.V (2 - alpha) + alpha); binary16 throughout. */
#define FACET_ERR_SMITH_G1_HAMMON_F16 1.61e-3
facet_f16 facet_smith_g1_hammon_f16(facet_f16 nov, facet_f16 alpha);
/* Hammon's G2 2 N.L N.V / lerp(2 N.L N.V, N.L + N.V, alpha) (smith_vis_hammon's
 * divisor); binary16 throughout. */
#define FACET_ERR_SMITH_G2_HAMMON_F16 2.28e-3
facet_f16 facet_smith_g2_hammon_f16(facet_f16 nol, facet_f16 nov, facet_f16 alpha);
/* N.L N.V: one rounding. */
#define FACET_ERR_G_IMPLICIT_F16 4.89e-4
facet_f16 facet_g_implicit_f16(facet_f16 nol, facet_f16 nov);
/* Neumann, min(N.L, N.V): exact, measured 0; the tests enforce 2^-30. */
#define FACET_ERR_G_NEUMANN_F16 9.313e-10 /* 2^-30; exact, measured 0 */
facet_f16 facet_g_neumann_f16(facet_f16 nol, facet_f16 nov);
/* Cook-Torrance min(1, 2 N.H min(N.L, N.V) / V.H), N.H, V.H in [0, 1]
 * (subnormals included; V.H = 0 gives 1); binary16 throughout, N.H and V.H
 * scaled by 2^15 and 2^14 first (exact), one quotient. */
#define FACET_ERR_G_COOK_TORRANCE_F16 1.6e-3
facet_f16 facet_g_cook_torrance_f16(facet_f16 nol, facet_f16 nov, facet_f16 noh, facet_f16 voh);
/* Kelemen min(1, N.L N.V / V.H^2) (V.H = 0 gives 1); binary16 throughout. */
#define FACET_ERR_G_KELEMEN_F16 1.75e-3
facet_f16 facet_g_kelemen_f16(facet_f16 nol, facet_f16 nov, facet_f16 voh);
/* Schlick's G1 for Beckmann N.V / (N.V (1 - k) + k), k = alpha sqrt(2/pi);
 * binary16 throughout. */
#define FACET_ERR_SMITH_G1_SCHLICK_BECKMANN_F16 1.82e-3
facet_f16 facet_smith_g1_schlick_beckmann_f16(facet_f16 nov, facet_f16 alpha);
/* The engines' joint visibility (facet.h; Hammon's, in Karis's form), <= 2^11;
 * binary16 throughout. */
#define FACET_ERR_SMITH_VIS_JOINT_APPROX_F16 1.84e-3
facet_f16 facet_smith_vis_joint_approx_f16(facet_f16 nol, facet_f16 nov, facet_f16 alpha);
/* Burley's diffuse (facet.h), L.H in [0, 1]: each factor as the positive
 * terms (1 - y^5 / 2) + 2 sqrt(alpha) L.H^2 y^5, the root with one Newton
 * correction; binary16 throughout. */
#define FACET_ERR_DIFFUSE_BURLEY_F16 3.09e-3
facet_f16 facet_diffuse_burley_f16(facet_f16 nol, facet_f16 nov, facet_f16 loh, facet_f16 alpha,
                                   facet_f16 albedo);
/* Oren-Nayar (facet.h), its constants rescaled so that binary16 holds them
 * (f16_body.h); binary16 throughout, one quotient. */
#define FACET_ERR_DIFFUSE_OREN_NAYAR_F16 2.83e-3
facet_f16 facet_diffuse_oren_nayar_f16(facet_f16 nol, facet_f16 nov, facet_f16 lov, facet_f16 alpha,
                                       facet_f16 albedo);
/* Hammon's hybrid (facet.h) on diffuse_hammon's binary16 body; each smooth
 * factor as 1/2 + (N / 2) Q(N) (positive terms). */
#define FACET_ERR_DIFFUSE_HAMMON_HYBRID_F16 3.17e-3
facet_f16 facet_diffuse_hammon_hybrid_f16(facet_f16 nol, facet_f16 nov, facet_f16 lov, facet_f16 alpha,
                                          facet_f16 albedo);
/* Hammon's cheap variant (smooth = 1) on diffuse_hammon's binary16 body. */
#define FACET_ERR_DIFFUSE_HAMMON_CHEAP_F16 3.13e-3
facet_f16 facet_diffuse_hammon_cheap_f16(facet_f16 nol, facet_f16 nov, facet_f16 lov, facet_f16 alpha,
                                         facet_f16 albedo);

/* the batches: out[i] = facet_<kernel>_f16(x0[i], ...) */
void facet_noh_from_dots_f16_batch(facet_f16 *out, const facet_f16 *nol, const facet_f16 *nov,
                                   const facet_f16 *lov, size_t n);
void facet_loh_from_dots_f16_batch(facet_f16 *out, const facet_f16 *lov, size_t n);
void facet_fresnel_schlick_f16_batch(facet_f16 *out, const facet_f16 *f0, const facet_f16 *cos, size_t n);
void facet_ggx_d_f16_batch(facet_f16 *out, const facet_f16 *noh, const facet_f16 *alpha, size_t n);
void facet_smith_vis_f16_batch(facet_f16 *out, const facet_f16 *nol, const facet_f16 *nov,
                               const facet_f16 *alpha, size_t n);
void facet_smith_vis_hammon_f16_batch(facet_f16 *out, const facet_f16 *nol, const facet_f16 *nov,
                                      const facet_f16 *alpha, size_t n);
void facet_diffuse_hammon_f16_batch(facet_f16 *out, const facet_f16 *nol, const facet_f16 *nov,
                                    const facet_f16 *lov, const facet_f16 *alpha,
                                    const facet_f16 *albedo, size_t n);
void facet_brdf_hammon_f16_batch(facet_f16 *out, const facet_f16 *nol, const facet_f16 *nov,
                                 const facet_f16 *lov, const facet_f16 *alpha, const facet_f16 *f0,
                                 const facet_f16 *albedo, size_t n);
void facet_lambert_f16_batch(facet_f16 *out, const facet_f16 *albedo, size_t n);
void facet_fresnel_schlick_f90_f16_batch(facet_f16 *out, const facet_f16 *f0, const facet_f16 *f90,
                                         const facet_f16 *voh, size_t n);
void facet_ggx_aniso_d_f16_batch(facet_f16 *out, const facet_f16 *noh, const facet_f16 *toh,
                                 const facet_f16 *boh, const facet_f16 *alpha_x, const facet_f16 *alpha_y,
                                 size_t n);
void facet_smith_g1_f16_batch(facet_f16 *out, const facet_f16 *nov, const facet_f16 *alpha, size_t n);
void facet_smith_g2_f16_batch(facet_f16 *out, const facet_f16 *nol, const facet_f16 *nov,
                              const facet_f16 *alpha, size_t n);
void facet_smith_g2_uncorrelated_f16_batch(facet_f16 *out, const facet_f16 *nol, const facet_f16 *nov,
                                           const facet_f16 *alpha, size_t n);
void facet_smith_g1_hammon_f16_batch(facet_f16 *out, const facet_f16 *nov, const facet_f16 *alpha, size_t n);
void facet_smith_g2_hammon_f16_batch(facet_f16 *out, const facet_f16 *nol, const facet_f16 *nov,
                                     const facet_f16 *alpha, size_t n);
void facet_g_implicit_f16_batch(facet_f16 *out, const facet_f16 *nol, const facet_f16 *nov, size_t n);
void facet_g_neumann_f16_batch(facet_f16 *out, const facet_f16 *nol, const facet_f16 *nov, size_t n);
void facet_g_cook_torrance_f16_batch(facet_f16 *out, const facet_f16 *nol, const facet_f16 *nov,
                                     const facet_f16 *noh, const facet_f16 *voh, size_t n);
void facet_g_kelemen_f16_batch(facet_f16 *out, const facet_f16 *nol, const facet_f16 *nov,
                               const facet_f16 *voh, size_t n);
void facet_smith_g1_schlick_beckmann_f16_batch(facet_f16 *out, const facet_f16 *nov, const facet_f16 *alpha,
                                               size_t n);
void facet_smith_vis_joint_approx_f16_batch(facet_f16 *out, const facet_f16 *nol, const facet_f16 *nov,
                                            const facet_f16 *alpha, size_t n);
void facet_diffuse_burley_f16_batch(facet_f16 *out, const facet_f16 *nol, const facet_f16 *nov,
                                    const facet_f16 *loh, const facet_f16 *alpha, const facet_f16 *albedo,
                                    size_t n);
void facet_diffuse_oren_nayar_f16_batch(facet_f16 *out, const facet_f16 *nol, const facet_f16 *nov,
                                        const facet_f16 *lov, const facet_f16 *alpha, const facet_f16 *albedo,
                                        size_t n);
void facet_diffuse_hammon_hybrid_f16_batch(facet_f16 *out, const facet_f16 *nol, const facet_f16 *nov,
                                           const facet_f16 *lov, const facet_f16 *alpha,
                                           const facet_f16 *albedo, size_t n);
void facet_diffuse_hammon_cheap_f16_batch(facet_f16 *out, const facet_f16 *nol, const facet_f16 *nov,
                                          const facet_f16 *lov, const facet_f16 *alpha,
                                          const facet_f16 *albedo, size_t n);

/* The f16 kernel table, in src/core/f16_kernels.def order (every kernel of
 * facet_kernel_at's list; f16 NULL and why set where it has no f16 form). */
typedef struct facet_f16_kernel {
    const char *name;
    int n_inputs;
    facet_f16 (*f16)(const facet_f16 *in);                         /* NULL: no f16 form */
    void (*f16_batch)(facet_f16 *out, const facet_f16 *const *in, size_t n);
    double err_f16;                                                /* FACET_ERR_<NAME>_F16 */
    const char *why;                                               /* why not, or "" */
} facet_f16_kernel;
size_t facet_f16_kernel_count(void);
const facet_f16_kernel *facet_f16_kernel_at(size_t i);
const facet_f16_kernel *facet_f16_kernel_find(const char *name);

#ifdef __cplusplus
}
#endif

#endif
