/* facet/fx.h - the fixed-point kernels: integer arithmetic only, bit-exact
 * on every target, for cores without an FPU (Cortex-M0/M3/M4, RV32IMC) and
 * as a golden model for fixed-function hardware.
 *
 * Formats (Qm.n: m integer bits, n fraction bits; raw integer = value 2^n)
 *   Inputs, all kernels: int32_t holding Q15, 1.0 = FACET_FX_ONE = 32768
 *     exactly.  One signed 32-bit container for every input because L.V
 *     needs -1 and +1 exactly and [0, 1] values need 32768, which no 16-bit
 *     type holds on both ends; Q15 because the product of two inputs is a
 *     single 32x32->32 multiply (the only multiply Cortex-M0 has) and a Q15
 *     output feeds straight back in (noh_from_dots -> ggx_d).
 *   Outputs:
 *     [0, 1] kernels (noh, loh, F, G1, G2, ...)  int32_t  Q15 (UQ1.15), 0..32768
 *     ggx_d, ggx_aniso_d, and in the fast tier
 *     blinn_phong_d, beckmann_d, gtr_d           uint32_t UQ19.13  (D <= 2^20/pi = 333772.1,
 *                                                 gtr_d: saturates for gamma > 2.571 near its peak)
 *     smith_vis, smith_vis_hammon                uint32_t UQ16.16  (Vis <= 15894.3)
 *     diffuse_hammon                             uint32_t UQ8.24   (<= 20.65)
 *     brdf_hammon                                uint64_t UQ40.24  (<= 4.38e9)
 *   The maxima are at alpha = FACET_FX_ALPHA_MIN and N.L = N.V =
 *   FACET_FX_COS_MIN; every format holds its kernel's maximum, and every
 *   result is additionally saturated at the format's FACET_FX_MAX_* value.
 *
 * Domain (every int32_t is a valid input; out-of-domain values clamp):
 *   [0, 1] inputs (f0, albedo, cos of one-cosine kernels, noh):  [0, 32768]
 *   alpha:                                    [FACET_FX_ALPHA_MIN, 32768]
 *   nol, nov of the two-cosine kernels:       [FACET_FX_COS_MIN, 32768]
 *   lov:                                      [-32768, 32768]
 *   Inconsistent (N.L, N.V, L.V) triples: 1 + L.V is raised to (N.L+N.V)^2/2
 *   exactly as in facet.h (integer compare, no rounding).
 *   FACET_FX_COS_MIN = 2^-8 (cos 89.78 deg), higher than the f32 floor 2^-20:
 *   it keeps Vis below 2^14 and the BRDF below 2^33, so their formats keep
 *   16 and 24 fraction bits.  A renderer multiplies by N.L (< 0.0039 there).
 *
 * Rounding: one rule everywhere - round to nearest, ties up (toward
 * +infinity).  Quotients and square roots are exact (floor plus remainder)
 * before that rounding; see src/fx/fx_prims.h.  No value is an error marker:
 * every raw output is the rounded (or saturated) function value.
 *
 * NaN: fixed point has none.  Inputs are int32 and every pattern is a value
 * (clamped to the domain); the library has no float-to-fixed conversion, so
 * the f32 NaN rule (facet.h: a NaN input gives 0) has nothing to apply to.
 * The `facet` command's Q15 parser refuses `nan` and `inf` (exit status 2);
 * a caller converting floats itself decides what a NaN becomes.
 *
 * Arithmetic: uint32/uint64 only (no signed overflow), no float, no libgcc
 * helper, no dependence on a hardware divider; 32x32->64 products are one
 * UMULL where the core has it and four 16x16 MULS on ARMv6-M (exact either
 * way).  Shared primitives (src/fx/fx_prims.c): one reciprocal (facet_fx_rcp32:
 * 32-entry 16-bit seed table, 3 Newton steps, exact fix-up), one rsqrt
 * (facet_fx_rsqrt32: 24-entry table, 3 Newton steps) giving an exact integer
 * square root, the exact 2-by-1 division of Moller-Granlund.  Every
 * quotient is exact, so a core with a divide instruction may compute it
 * with that instead (Cortex-M3/M4/M7/M33: two 32-bit UDIV digits; 64-bit
 * hosts: the native division) with the same bits (src/fx/fx_prims.h fxp_div64).
 *
 * Stack (bytes; every call's worst case: its own frame from -fstack-usage
 * plus the deepest chain of its callees in gcc's call graph; the sources
 * have no recursion, no dynamic frame, no indirect call and call nothing
 * outside themselves), arm-none-eabi-gcc 12.2.1 -mthumb on the firmware
 * sources (make fx-sources); the maxima over every precise kernel
 * (facet_*_fx), every fast kernel (facet_*_fx_fast) and every batch and
 * RGB call (both tiers), held exactly by tests/suites/27-stack.sh, which
 * prints each call's figure:
 *                          fx  fx_fast  batch/RGB
 *   cortex-m0 -O2          492      152        724
 *   cortex-m0 -Os          600      120        696
 *   cortex-m4 -O2          240      120        320
 *   cortex-m4 -Os          488       88        640
 *   cortex-m33 -O2         260      136        332
 *   cortex-m33 -Os         488       88        640
 * The deepest call is brdf_hammon's (its RGB batch above all), but the
 * fast tier's on M4/M33, smith_g1_gtr's at -O2 (120 / 136) and
 * brdf_hammon's at -Os (88): the constant-time op layer
 * (src/fx/fx_ops_scalar.h, opaque compare masks) holds more values live
 * (was 88 / 88 / 80 / 80 with data-dependent branches); a kernel's own
 * figure is at most its tier's column.  FACET_FX_STACK_BYTES: no call
 * needs more on any of these builds. */
#define FACET_FX_STACK_BYTES 724
/*
 * Execution time (bytes aside, what a firmware budget needs): executed
 * instructions (insns, MEASURED under qemu-system-arm 7.2, deterministic)
 * and cycles (MODELLED) per call of every kernel, minimum-maximum over its
 * golden vectors (the edge cases of `facet vectors` and 256 of its random
 * vectors, seed 1: tests/cortexm/wcet_main.c), entry to return, callees
 * included, arm-none-eabi-gcc 12.2.1 -mthumb -O2.  Cycles: Cortex-M0 the
 * TRM timings on each executed trace (zero wait states); Cortex-M4 / M33
 * llvm-mca 14 -mcpu=cortex-m4 / cortex-m33 on each distinct executed path
 * as straight-line code (-iterations=1; no fetch, wait-state or branch
 * penalty).  M33 code runs on the M4 model (bench/cortexm/cortexm.sh).
 * Constant time: on Cortex-M4 and M33 the fast kernels' machine code, -O2
 * and -Os, has no conditional branch (the op layer's Thumb-2 forms,
 * src/fx/fx_ops_scalar.h; facet_brdf_hammon_rgb_fx_fast has one, its
 * channel loop's), so every fast row there is one figure.  The precise
 * tier keeps its exact division's and root's fix-up steps (and
 * loh_from_dots returns early at L.V = -1).  On Cortex-M0 (no IT) gcc
 * makes selects, min, max and clamps branches: the spread is each M0 row's
 * (fast tier: loh_from_dots 27-59, its portable clz; the others at most
 * 1.25x, the largest absolute smith_g1_gtr's 3906-4393; brdf_hammon
 * 1001-1032); branch-free compare masks (CMP + SBCS) measured +4.8%
 * instructions over the fast tier for 47 of its 746 conditional branches:
 * not taken.
 * Held exactly by tests/suites/51-fx-wcet.sh (with the disassembly check).
 * Regenerate after a change of the bodies or the op layer with the one
 * command  sh tests/cortexm/wcet.sh --write
 * <wcet-table>
 *   kernel                     tier  M0 insns  cycles     M4 insns  cycles     M33 insns cycles
 *   noh_from_dots              fx    1053-1177 1319-1490  192-240   208-256    190-238   205-253
 *   noh_from_dots              fast  131-150   176-198    71        77         71        75
 *   loh_from_dots              fx    31-452    57-578     25-92     28-103     25-92     28-101
 *   loh_from_dots              fast  27-59     42-84      37        40         36        38
 *   fresnel_schlick            fx    103-106   117-124    21        25         21        25
 *   fresnel_schlick            fast  60-63     70-77      23        27         23        27
 *   fresnel_cook_torrance      fast  626-638   752-764    232       251        239       256
 *   fresnel_schlick_f90        fast  75-78     91-98      30        35         30        35
 *   fresnel_schlick_sg         fast  92-95     115-118    35        40         34        42
 *   ggx_d                      fx    763-804   941-1001   148-181   156-189    148-181   155-188
 *   ggx_d                      fast  213-219   258-270    77        84         78        87
 *   blinn_phong_d              fast  908-940   1031-1058  215       246        224       250
 *   beckmann_d                 fast  626-645   702-731    152       174        157       177
 *   ggx_aniso_d                fx    1205-1268 1455-1544  338-374   353-389    342-377   356-391
 *   ggx_aniso_d                fast  549-579   681-712    157       171        156       169
 *   gtr_d                      fast  1523-1532 1703-1717  295       344        306       357
 *   smith_g1                   fx    1080-1198 1350-1509  207-249   220-263    207-249   217-259
 *   smith_g1                   fast  318-326   388-399    120       130        120       131
 *   smith_g2                   fx    1648-1863 2042-2335  339-374   361-396    332-367   349-384
 *   smith_g2                   fast  607-627   723-745    184       199        189       205
 *   smith_g2_uncorrelated      fx    1680-1873 2086-2349  364-410   387-433    364-410   381-427
 *   smith_g2_uncorrelated      fast  577-599   699-724    179       194        184       198
 *   smith_vis                  fx    1622-1837 2001-2291  321-358   345-382    318-354   339-375
 *   smith_vis                  fast  371-380   450-464    128       139        129       138
 *   smith_g1_hammon            fx    501-539   629-677    59-86     65-92      59-86     64-91
 *   smith_g1_hammon            fast  150-166   183-202    71        78         71        78
 *   smith_g1_gtr               fast  4241-4704 5566-6166  1162      1297       1231      1382
 *   smith_g2_hammon            fx    614-662   779-841    118-142   125-149    118-142   127-151
 *   smith_g2_hammon            fast  233-238   282-296    92        100        92        100
 *   smith_vis_hammon           fx    586-624   732-781    107-131   116-140    107-131   115-139
 *   smith_vis_hammon           fast  140-146   178-186    71        75         73        78
 *   g_implicit                 fx    19-22     25-28      12        13         12        13
 *   g_implicit                 fast  19-22     25-28      13        14         13        14
 *   g_neumann                  fx    16-20     19-27      12        13         12        13
 *   g_neumann                  fast  16-20     19-27      9         10         9         10
 *   g_cook_torrance            fx    536-583   684-744    89-90     92-93      89-90     92-93
 *   g_cook_torrance            fast  156-164   205-215    85        89         85        90
 *   g_kelemen                  fx    533-577   682-742    75-95     79-99      75-95     79-99
 *   g_kelemen                  fast  151-161   196-213    80        85         80        85
 *   smith_g1_beckmann          fx    1312-1785 1588-2173  378-485   404-511    378-490   400-514
 *   smith_g1_beckmann          fast  630-646   748-766    190       209        189       207
 *   smith_g1_schlick_beckmann  fx    579-617   727-782    95-124    103-132    95-124    104-133
 *   smith_g1_schlick_beckmann  fast  223-232   272-281    84        93         83        93
 *   smith_vis_joint_approx     fx    589-627   744-793    108-132   117-141    108-132   116-140
 *   smith_vis_joint_approx     fast  143-149   190-198    72        76         74        79
 *   smith_vis_fit              fx    1701-1783 2091-2200  575-619   605-649    582-626   615-659
 *   smith_vis_fit              fast  318-325   379-388    114       131        114       134
 *   diffuse_hammon             fx    2237-2373 2714-2892  666-716   708-759    669-719   712-762
 *   diffuse_hammon             fast  400-418   479-500    123       137        131       146
 *   diffuse_burley             fast  293-301   338-352    85        98         85        98
 *   diffuse_oren_nayar         fast  427-465   511-563    205       214        205       217
 *   diffuse_hammon_hybrid      fast  448-470   513-538    121       139        121       138
 *   diffuse_hammon_cheap       fast  347-370   413-439    98        109        98        111
 *   brdf_hammon                fx    4813-5050 5841-6180  1309-1531 1401-1634  1311-1533 1405-1640
 *   brdf_hammon                fast  1001-1032 1182-1224  278       311        287       325
 * </wcet-table>
 */
/*
 * How this header is organised: as facet.h, one block per kernel family
 * (the geometry identities, Fresnel, D, shadowing and visibility, diffuse,
 * the whole BRDF), then the shared primitives and the kernel table.  A
 * family block opens with what its kernels share and the bounds of both
 * tiers (FACET_FX_ERR_<NAME>: the precise tier's, in LSB;
 * FACET_FX_FAST_ERR_<NAME>: the fast tier's, in its own measure, below);
 * then, per kernel, its contract for both tiers (formula, domains, output
 * format and maximum, error, cost) and its declarations:
 *   facet_<kernel>_fx(...)                     one sample, precise tier
 *   facet_<kernel>_fx_fast(...)                one sample, fast tier
 *   facet_<kernel>_fx_batch(out, ..., n)       n samples on the active port
 *   facet_<kernel>_fx_fast_batch(out, ..., n)  the same, fast tier
 * A kernel with the fast tier only (src/core/kernels.def fx_code `fast`) has
 * no facet_<kernel>_fx, _fx_batch or FACET_FX_ERR_<NAME> (its fx table
 * entry's fx and fx_batch are NULL; `facet eval --format fx` refuses it).
 *
 * The precise tier (_fx): the error is max |raw - round(oracle 2^frac)| in
 * LSB over tests/fx/test_fx_accuracy.c's sweep, FACET_FX_ERR_* the bound it
 * enforces.  The intermediates and the overflow argument of each step are
 * beside its code (src/fx/fx_body.h, every kernel written once over lanes,
 * branch-free; its pseudo-float src/fx/fx_pfloat.h).  Cost:
 * operations of the scalar specification (mul = 32x32->32, mul64 =
 * 32x32->64, division = one exact 64/32 quotient, sqrt = one exact integer
 * root, fxe = one 32-bit-mantissa float step).  The bodies do not branch on
 * their inputs (the exact division and root keep their fix-up steps, and a
 * compiler may turn a select into a branch): over 48 inputs of every class
 * a call's executed instructions vary by at most 1.37x on Cortex-M4, 1.33x
 * on Cortex-M0, but loh_from_dots (the root of 0 at L.V = -1 returns early).
 *
 * The fast tier (_fx_fast): the same inputs as facet_<kernel>_fx (raw Q15
 * int32, the same domains, every int32 clamped the same way) and the same
 * output containers, fraction bits and saturation values (FACET_FX_*_FRAC,
 * FACET_FX_MAX_*): a caller switches tier by name.
 * Bound, every kernel, every input: |raw - v 2^frac| <= max(1 LSB, 2^-10
 * v 2^frac) (FACET_FX_FAST_TOL_REL = 2^-10), v the exact value at the same
 * raw inputs (the oracle).  The error measure is e = |raw - v 2^frac| /
 * max(1, 2^-10 v 2^frac); FACET_FX_FAST_ERR_<NAME> is its measured maximum
 * over tests/fx/test_fx_fast.c's sweep and a 2e7-tuple run of the same
 * families per kernel (enforced by the test; the tier's bound is 1).  Each
 * contract gives the measured e at its argmax (raw inputs), with its LSB
 * part (the maximum of |raw - v 2^frac| over small values: v 2^frac < 2^10)
 * and its relative part (over large values, as tests/fx/test_fx_fast.c
 * splits them; Q15 outputs never reach 2^15 LSB but at 1: no relative
 * part).
 * Integer only, no divide instruction, no libgcc helper (Cortex-M0/M4,
 * RV32IMC), bit-exact on every target (pinned hashes, tests/lib/fx_hash.h);
 * written once over the lane op layer (src/fx/fx_fast_body.h), so a SIMD port
 * instantiates the same body.  Cost: executed instructions per call on
 * Cortex-M4 / Cortex-M0 (qemu trace, mean of bench/cortexm/cortexm_main.c's 4
 * inputs; arm-none-eabi-gcc 12.2 -O2), the precise tier's in brackets; the
 * M4 figures of the fast tier are its constant-time code's (one figure for
 * every input: the Execution time table above gives min-max per target).
 *
 * Datapath (a specification a fixed-function pipeline can implement):
 *   Inputs are clamped first (compare/select).  Exact stages:
 *     S = NL + NV <= 2^16;  P = (2^16 - S)(2^16 + S) = (4 - s^2) 2^30 and
 *     Q = (2^15 - LOV) 2^16 = (4 - 2t) 2^30, both <= 2^32 - 2^16;
 *     u = min(P, Q) = (4 - 2 t_raised) 2^30 (the facet.h raise as one min);
 *     w = P - u = (2t - s^2) 2^30 (the specular peak's cancellation, exact);
 *     c = ~u = (L.H^2) 2^32 - 1; N A, A S <= 2^31; NL NV, A^2 <= 2^30.
 *   1/x and sqrt: the normalised 32-bit mantissa (one clz, one shift; an
 *     even shift for sqrt) indexes a 129-entry table of 2^35/x on [1, 2)
 *     (resp. 97 entries of 2^20 sqrt on [1/4, 1)) with its top 7 bits; the
 *     next 15 bits interpolate linearly (one multiply of a < 2^13
 *     difference by a 15-bit fraction: < 2^28).  Relative error 2^-16 (1/x),
 *     2^-15 (sqrt: h^2/8 max|f''| at 1/4), no Newton step and no
 *     data-dependent loop.  The diffuse's 1 + y + y^2 + y^3 + y^4 (y = 1 -
 *     x) likewise: 257 entries on x = i/256, 7 interpolation bits, 2^-15.8.
 *   Products: 16 x 16 -> 32 bit where the operands allow (the clamped
 *     Q15 values, table steps: one MULS on Cortex-M0), else
 *     the high word of one 32 x 32 -> 64 product (one UMULL on
 *     Cortex-M3/M4), every operand < 2^32 and every product's high word
 *     kept >= 2^21 (2^18 for e^2 at brdf_hammon's sharpest peaks) so the
 *     truncation stays <= 2^-21 (2^-18).  The sums that need
 *     it (d = 1 - n^2 (1 - a^2), the Smith w = a^2 + (1 - a^2) x^2,
 *     Hammon's m = (1 - a) 2 nl nv + a s, e = w + a^2 s^2, the Smith
 *     denominators) are formed exactly in 64 bits (< 2^63), then their top
 *     32 bits (one clz); brdf_hammon keeps m in Q30 (>= 2^15).
 *   Wide ranges (D up to 2^20/pi, Vis, the Fresnel tail y^5 down to f0 =
 *     0, the specular term up to 2^33) carry an exponent lane: a clz where
 *     the range is wide, sums of counts and constants elsewhere, all below
 *     2^10 (biased, so never negative).  A quotient is one table
 *     reciprocal of the normalised divisor times the normalised dividend,
 *     then one rounded shift by the lane's exponent (saturating).
 *     The G terms (smith_g1, smith_g2, smith_g2_uncorrelated,
 *     smith_g1_hammon, smith_g2_hammon, smith_g1_beckmann,
 *     smith_g1_schlick_beckmann) refine that reciprocal by one Newton step
 *     (2^-30), and the GGX ones take the form G1 = X / (X + Y), X = 2 n (n +
 *     r), Y = a^2 (1 - n^2) (G2 = 1 / (1/G1 + 1/G1 - 1), the uncorrelated
 *     G2 = G1 G1 from the same two ratios), rounded as 1 - Y / (X + Y):
 *     a ratio near 1 by the table alone steps backwards where its chord
 *     slope is off by more than the function's slope (issue 25 item 4).
 *   Monotone: every fast kernel is non-decreasing or non-increasing in each
 *     input in which its function is, along every line of
 *     tests/fx/test_fx_fast.c's monotonicity sweep (every value of the
 *     input on 128 lines of the other input, or 120 lines of three- to
 *     six-input kernels: 69 kernel-input pairs, 315 M steps), and over
 *     every (N.V, alpha) pair in both inputs for smith_g1, smith_g1_hammon,
 *     smith_g1_beckmann and smith_g1_schlick_beckmann (2^31 steps each);
 *     but smith_g1_gtr, whose monotone cubic in gamma meets five closed
 *     forms rounded apart: 1 reversal in N.V and 172 in alpha over the
 *     sweep's 3.9 M steps each (its contract), held to those counts.
 *   Intermediates truncate (floor), but for the few steps the body marks
 *     as rounded (table interpolations, the diffuse sum's terms); the final
 *     rounding is to nearest, ties up; results saturate at the format's
 *     maximum.
 *   Why nothing overflows: each bound above is below 2^32 (64-bit values:
 *     below 2^63), exponent lanes stay in [0, 2^10), and every shift count
 *     is clamped to [0, 31]; the brackets in the body give each one.
 *
 * Batches (both tiers): out[i] = kernel(in1[i], ...), i < n; bit-identical
 * to the scalar kernel on every port, for every int32 input (clamping and
 * saturation included) and every n, alignment and tail.  Dispatched with
 * the f32 batches (facet_port_name(), facet_set_port(), FACET_PORT: one
 * choice for every format): the active port's own fixed-point code where it
 * has some, the scalar loop elsewhere; facet_fx_port_name() names the port
 * whose code runs the precise tier.  Which kernels of which tier a port
 * runs on its vector lanes is its own measured choice (where they beat the
 * scalar loop, which divides and takes roots with one hardware instruction
 * where the core has one), stated with its measurement in its own file
 * (ports/<isa>/fx_<isa>.c, FXV_LANES_FX and FXV_LANES_FX_FAST): avx2 /
 * avx512 (AVX2 lanes), aarch64 neon, helium and rvv.  Everything else, and
 * everything on sse2, armv7 neon and scalar, runs the scalar loop.  A firmware build
 * (`make fx-sources`: src/fx/fx_firmware_batch.c instead of the dispatcher)
 * has no ports: each batch is its own scalar loop, facet_fx_port_name() is
 * "scalar", and --gc-sections keeps only the kernels called.  out may be
 * the very same array as an input (32-bit outputs); no other overlap.
 */
#ifndef FACET_FX_H
#define FACET_FX_H

#include <stddef.h>
#include <stdint.h>
#include "facet/common.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FACET_FX_ONE       32768 /* 1.0 in Q15 */
#define FACET_FX_ALPHA_MIN 32    /* 2^-10 = FACET_ALPHA_MIN */
#define FACET_FX_COS_MIN   128   /* 2^-8, the fixed-point cos floor */

/* output fraction bits and saturation values (raw) */
#define FACET_FX_Q15_FRAC  15
#define FACET_FX_D_FRAC    13
#define FACET_FX_VIS_FRAC  16
#define FACET_FX_BRDF_FRAC 24 /* diffuse_hammon and brdf_hammon */
#define FACET_FX_MAX_Q15   32768u
#define FACET_FX_MAX_D     0xFFFFFFFFu
#define FACET_FX_MAX_VIS   0xFFFFFFFFu
#define FACET_FX_MAX_DIFF  0xFFFFFFFFu
#define FACET_FX_MAX_BRDF  0xFFFFFFFFFFFFFFFFull
#define FACET_FX_FAST_TOL_REL 0.0009765625 /* 2^-10 */

/* ==== Conversions between float and fixed point ===========================
 * For a renderer that holds floats and switches to the fixed-point kernels
 * (or checks them against the f32 ones), inline here, no library code.
 *
 * facet_q15_from_f32(x): x as Q15, floor(x 32768 + 1/2) (nearest, ties up:
 *   the rounding of the CLI and of the golden vectors), after the f32
 *   kernels' input rules: NaN gives 0, x is clamped to [-4, 4] first (+-inf
 *   to the bound), which holds every fixed-point input domain (dots
 *   [-1, 1]; alpha, f0, albedo [0, 1]; GTR's gamma [0, 4]); each kernel then
 *   clamps to its own domain as it does any int32_t.  Result in
 *   [-131072, 131072].  Error: the rounding only, at most 1/2 LSB (2^-16)
 *   (exact arithmetic: the scale is a power of two, floor by truncation and
 *   an exact difference).  Cost: 1 mul, 3 compare/selects, 1 float->int,
 *   1 int->float, 1 sub, 1 compare.  Where the CPU has no FPU, soft float.
 * facet_q15_from_f32_batch(out, x, n): the same over n values.
 * facet_f32_from_q15(q): q / 32768, exact for |q| <= 2^24.
 * facet_f32_from_fx(raw, frac): an output of frac fraction bits
 *   (FACET_FX_Q15_FRAC, _D_FRAC, _VIS_FRAC, _BRDF_FRAC; frac in [0, 63]) as
 *   a float, raw 2^-frac, correctly rounded (one rounding, raw to float:
 *   the scale is a power of two).  Any output container converts to
 *   uint64_t; a Q15 output (int32_t, never negative) too. */
static inline int32_t facet_q15_from_f32(float x)
{
    float v;
    int32_t t;
    if (!(x == x))
        return 0;
    x = x < -4.0f ? -4.0f : x > 4.0f ? 4.0f : x;
    v = x * 32768.0f;                 /* exact: |v| <= 2^17 */
    t = FACET_CAST(int32_t, v);       /* toward zero */
    if (v < FACET_CAST(float, t))     /* floor */
        t--;
    return v - FACET_CAST(float, t) >= 0.5f ? t + 1 : t; /* the fraction, exact */
}
static inline void facet_q15_from_f32_batch(int32_t *out, const float *x, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        out[i] = facet_q15_from_f32(x[i]);
}
static inline float facet_f32_from_q15(int32_t q) { return FACET_CAST(float, q) * (1.0f / 32768.0f); }
static inline float facet_f32_from_fx(uint64_t raw, int frac)
{
    uint64_t one = FACET_CAST(uint64_t, 1) << (FACET_CAST(unsigned, frac) & 63u);
    return FACET_CAST(float, raw) / FACET_CAST(float, one);
}

/* the port whose code runs the precise tier's batches (Batches, above) */
const char *facet_fx_port_name(void); /* "avx2", "neon", "helium" or "scalar" */

/* ==== Geometry: N.H and L.H from the dots ================================= */
#define FACET_FX_ERR_NOH_FROM_DOTS                   1
#define FACET_FX_FAST_ERR_NOH_FROM_DOTS              0.538
#define FACET_FX_ERR_LOH_FROM_DOTS                   1
#define FACET_FX_FAST_ERR_LOH_FROM_DOTS              0.490

/* N.H = (N.L + N.V) / sqrt(2 (1 + L.V)), from the dots; nol, nov [cos floor,
 * 1], lov [-1, 1].  Q15, max 1 (a triple at or past N.H = 1 gives 1).
 * fx: error 0 LSB (correctly rounded).  Cost: 1 sqrt, 1 division, ~8 mul64.
 * fx_fast: N.H = s / sqrt(2t); one sqrt, one 1/x.
 *   Error: FACET_FX_FAST_ERR_NOH_FROM_DOTS; measured e 0.538 (LSB 0.509) at
 *   (137, 879, -15701).  Cost: 71 / 147 (214 / 1109). */
int32_t facet_noh_from_dots_fx(int32_t nol, int32_t nov, int32_t lov);
int32_t facet_noh_from_dots_fx_fast(int32_t nol, int32_t nov, int32_t lov);
void facet_noh_from_dots_fx_batch(int32_t *out, const int32_t *nol, const int32_t *nov,
                                  const int32_t *lov, size_t n);
void facet_noh_from_dots_fx_fast_batch(int32_t *out, const int32_t *nol, const int32_t *nov,
                                  const int32_t *lov, size_t n);

/* L.H = sqrt((1 + L.V) / 2); lov [-1, 1].  Q15, max 1; L.V = -1 gives 0.
 * fx: error 0 LSB (correctly rounded).  Cost: 1 integer sqrt.
 * fx_fast: one sqrt.
 *   Error: FACET_FX_FAST_ERR_LOH_FROM_DOTS; measured e 0.490 (LSB 0.489) at
 *   (-32755).  Cost: 37 / 58 (84 / 411). */
int32_t facet_loh_from_dots_fx(int32_t lov);
int32_t facet_loh_from_dots_fx_fast(int32_t lov);
void facet_loh_from_dots_fx_batch(int32_t *out, const int32_t *lov, size_t n);
void facet_loh_from_dots_fx_fast_batch(int32_t *out, const int32_t *lov, size_t n);

/* ==== Fresnel =================================================================
 * Q15 outputs, max 1 (convex combinations of [0, 1] values).  Both tiers:
 * fresnel_schlick; the fast tier only: the rest of the menu (no precise
 * fixed-point kernel), the formulas of facet.h with the fixed-point domains
 * (f0, f90, voh, cos [0, 1]; every int32 outside clamps), the fast tier's
 * bound and datapath (above); each step's Q format and bound are beside the
 * code in src/fx/fx_fast_body.h.  Errors: the final rounding in each but
 * fresnel_cook_torrance (measured over tests/fx/test_fx_fast.c's full
 * sweep, 0.8 M to 2.3 M tuples per kernel, x86-64). */
#define FACET_FX_ERR_FRESNEL_SCHLICK                 1
#define FACET_FX_FAST_ERR_FRESNEL_SCHLICK            0.501
#define FACET_FX_FAST_ERR_FRESNEL_COOK_TORRANCE      0.634
#define FACET_FX_FAST_ERR_FRESNEL_SCHLICK_F90        0.501
#define FACET_FX_FAST_ERR_FRESNEL_SCHLICK_SG         0.502

/* Schlick: f0 + (1 - f0)(1 - cos)^5; f0, cos [0, 1].  Q15, max 1;
 * F(f0, 1) = f0, F(f0, 0) = 1 exactly (both tiers).
 * fx: error 0 LSB (correctly rounded).  Cost: 2 mul, 3 mul64.
 * fx_fast: 1 mul, 3 high-word products; the error is the final rounding.
 *   Error: FACET_FX_FAST_ERR_FRESNEL_SCHLICK; measured e 0.501 (LSB 0.500)
 *   at (706, 26184).  Cost: 23 / 63 (21 / 106). */
int32_t facet_fresnel_schlick_fx(int32_t f0, int32_t cos_theta);
int32_t facet_fresnel_schlick_fx_fast(int32_t f0, int32_t cos_theta);
void facet_fresnel_schlick_fx_batch(int32_t *out, const int32_t *f0, const int32_t *cos_theta,
                                    size_t n);
void facet_fresnel_schlick_fx_fast_batch(int32_t *out, const int32_t *f0, const int32_t *cos_theta,
                                    size_t n);

/* The exact dielectric Fresnel (facet.h), eta from f0; Q15, F(0, c) = 0,
 * F(1, c) = 1, F(f0, 0) = 1.  Fast tier only.  Two sqrt, three 1/x
 * (tables).  Scaling: the Fresnel equations divided by eta (u = 1/eta = (1 -
 * s)/(1 + s), s = sqrt(f0)): rs = (u c - ct)/(u c + ct), rp = (c - u ct)/(c
 * + u ct), ct = sqrt(v + u^2 c^2), v = 1 - u^2 = 4 s/(1 + s)^2, every term in
 * [0, 1]; s, ct from the sqrt table, 1/(1 + s) from the 1/x table, all
 * Q31/Q30; u = (1 - f0)/(1 + s)^2 with its own exponent (to 2^-14 relative
 * down to u = 2^-17.6 at f0 = 1 - 2^-15), c +- u ct in 64 bits at the scale
 * 2^(ku + 30) [< 2^62]; |rs|, |rp| by one 1/x each, F Q31 [<= 2^31]; f0 = 0
 * and f0 = 1 selected (0, 1).
 * Error: FACET_FX_FAST_ERR_FRESNEL_COOK_TORRANCE; measured e 0.634 (LSB
 * 0.634) at (51, 11657) from every f0 x every 5th V.H (2.1e8 pairs); the
 * test's sweep: 0.610 at (49, 11673).  The extra 0.13 LSB over the final
 * rounding comes from the sqrt and 1/x tables (2^-15, 2^-16) in sqrt(f0),
 * 1/(1 + sqrt(f0)) and the refracted cosine (a Newton step on sqrt(f0)
 * alone measured 0.617: not taken).  Cost: 232 / 620. */
int32_t facet_fresnel_cook_torrance_fx_fast(int32_t f0, int32_t voh);
void facet_fresnel_cook_torrance_fx_fast_batch(int32_t *out, const int32_t *f0, const int32_t *voh, size_t n);

/* f0 (1 - (1 - V.H)^5) + f90 (1 - V.H)^5, Q15.  Fast tier only.  1 mul, 4
 * high-word products: y^5 Q30 as fresnel_schlick's; f0 (1 - y^5) + f90 y^5
 * as two high words Q30 [<= 2^30], rounded once: f0 at V.H = 1, f90 at
 * V.H = 0 exactly.
 * Error: FACET_FX_FAST_ERR_FRESNEL_SCHLICK_F90; measured e 0.500 (LSB
 * 0.500) at (35, 6472, 24521).  Cost: 30 / 78. */
int32_t facet_fresnel_schlick_f90_fx_fast(int32_t f0, int32_t f90, int32_t voh);
void facet_fresnel_schlick_f90_fx_fast_batch(int32_t *out, const int32_t *f0, const int32_t *f90,
                                             const int32_t *voh, size_t n);

/* f0 + (1 - f0) 2^((-5.55473 cos - 6.98316) cos), Q15; F(f0, 0) = 1
 * exactly.  Fast tier only.  1 mul, 4 high-word products, one interpolated
 * table: p = (5.55473 c + 6.98316) c Q28 [< 2^31.65] (the constants Q29);
 * 2^-p = 2^-floor(p) times a 257-entry Q31 table of 2^(-i/256) with 20
 * interpolation bits (2^-20.1).
 * Error: FACET_FX_FAST_ERR_FRESNEL_SCHLICK_SG; measured e 0.501 (LSB
 * 0.500) at (46, 17697).  Cost: 35 / 95. */
int32_t facet_fresnel_schlick_sg_fx_fast(int32_t f0, int32_t cos_theta);
void facet_fresnel_schlick_sg_fx_fast_batch(int32_t *out, const int32_t *f0, const int32_t *cos_theta,
                                            size_t n);

/* ==== D: normal distributions =================================================
 * UQ19.13 outputs: D <= 2^20/pi = 333772.1 at N.H = 1, alpha = 2^-10 (for
 * every D here the peak is ~1/(pi alpha^2) or below, gtr_d's above gamma =
 * 2.571 aside), and the tail that falls below the LSB (2^-13) is an
 * absolute error (D below 2^-14 rounds to 0; the oracle does too).  Both
 * tiers: ggx_d, ggx_aniso_d; the fast tier only (kernels.def fx_code
 * `fast`): blinn_phong_d, beckmann_d, gtr_d, which need a power with a
 * non-integer exponent built from integer operations: the integer log2 and
 * 2^f of src/fx/fx_fast_body.h (gtr_d's contract describes them; their
 * bounds, 2^-25.5 and 2^-22.9, are enforced by tests/fx/test_fx_prims.c). */
#define FACET_FX_ERR_GGX_D                           1
#define FACET_FX_FAST_ERR_GGX_D                      0.514
#define FACET_FX_FAST_ERR_BLINN_PHONG_D              0.51
#define FACET_FX_FAST_ERR_BECKMANN_D                 0.51
#define FACET_FX_ERR_GGX_ANISO_D                     4
#define FACET_FX_FAST_ERR_GGX_ANISO_D                0.52
#define FACET_FX_FAST_ERR_GTR_D                      0.52

/* GGX D = alpha^2 / (pi (1 - N.H^2 (1 - alpha^2))^2); noh [0, 1], alpha
 * [2^-10, 1].  UQ19.13, max 2^20/pi = 333772.1 (N.H = 1, alpha = 2^-10).
 * fx: error FACET_FX_ERR_GGX_D LSB.  Cost: 1 division, 3 fxe, 2 mul64.
 * fx_fast: d = (1 - n)(1 + n) + (n alpha)^2 exact in 64 bits; one 1/x.
 *   Error: FACET_FX_FAST_ERR_GGX_D; measured e 0.514 (LSB 0.510, rel
 *   2^-15.15) at (16701, 16432).  Cost: 77 / 217 (157 / 788). */
uint32_t facet_ggx_d_fx(int32_t noh, int32_t alpha);
uint32_t facet_ggx_d_fx_fast(int32_t noh, int32_t alpha);
void facet_ggx_d_fx_batch(uint32_t *out, const int32_t *noh, const int32_t *alpha, size_t n);
void facet_ggx_d_fx_fast_batch(uint32_t *out, const int32_t *noh, const int32_t *alpha, size_t n);

/* The exponential D terms, the fast tier only (kernels.def fx_code fast).
 * Format argument: each is 2^-y times a prefactor whose maximum over N.H
 * is 1/(pi alpha^2) <= 2^20/pi (Blinn-Phong at N.H = 1; Beckmann at N.H = 1
 * for alpha <= 2^-0.5, else 4 alpha^2 e^(1/alpha^2 - 2)/pi <= 0.47), the
 * peak of ggx_d: UQ19.13 holds it with 13 fraction bits, and the tail that
 * falls below its LSB (2^-13) is an absolute error, as ggx_d's tail (D
 * below 2^-14 rounds to 0; the oracle does too).  What it takes is an
 * exponent good to ~2^-20 absolute wherever D is above the LSB (y < 64):
 * exact products, reciprocals refined to 2^-29.5 (table + one Newton
 * step), -log2 N.H by a series in 1 - N.H near 1 (relative precision kept:
 * p reaches 2^21 there) and by the integer log2 elsewhere, y held in Q24
 * (saturated at 128: D 2^13 < 2^-29 beyond 64), 2^-y by the degree-5 2^f
 * and a final rounded shift (src/fx/fx_fast_body.h has each bound).
 * Blinn-Phong D = N.H^p / (pi alpha^2), p = 2 (1 - alpha^2) / alpha^2;
 * noh [0, 1], alpha [2^-10, 1]; UQ19.13, max 2^20/pi.  N.H = 0 gives 0
 * (alpha < 1); alpha = 1 gives 1/pi everywhere (facet.h).  Intermediates:
 * A^2, 2 (2^15 - A)(2^15 + A) Q30 exact; 1/alpha^2 and p as normalised
 * 32-bit mantissas with clz exponents; -log2 N.H: X = 2^15 - N exact,
 * X (series) in 64 bits (< 2^42) or Q26 (<= 15 2^26) times 2^20, one
 * 64-bit scale, normalised; y Q24 (<= 2^31).
 * Error: FACET_FX_FAST_ERR_BLINN_PHONG_D (measured 0.5009 over every N.H
 * at 560 alphas; 0.5000 in the test; relative 2^-16 above 2^15 LSB;
 * e 0.501, LSB 0.500, rel 2^-16.01 at (31571, 3846)).
 * Cost: 215 / 918 (no precise tier). */
uint32_t facet_blinn_phong_d_fx_fast(int32_t noh, int32_t alpha);
void facet_blinn_phong_d_fx_fast_batch(uint32_t *out, const int32_t *noh, const int32_t *alpha, size_t n);

/* Beckmann D = exp(-tan^2 / alpha^2) / (pi alpha^2 N.H^4) (facet.h) as
 * 2^-z alpha^2 r^2 / pi, r = 1/(N.H alpha)^2, z = log2(e) (1 - N.H)(1 + N.H) r;
 * noh [0, 1], alpha [2^-10, 1]; UQ19.13, max 2^20/pi.  N.H = 0 gives 0.
 * Intermediates: N A, (2^15 - N)(2^15 + N), A^2 Q30 exact; 1/(N.H alpha)
 * refined to 2^-29.5, its square and fourth power as 32-bit mantissas with
 * clz exponents; z Q24 (saturated at 128 where z >= 64: D 2^13 <
 * 2^-29 there, the prefactor being <= 2^21 wherever z >= 64).
 * Error: FACET_FX_FAST_ERR_BECKMANN_D (measured 0.5001 over every N.H at
 * 560 alphas; 0.5000 in the test; relative 2^-16 above 2^15 LSB;
 * e 0.500, LSB 0.500, rel 2^-16.02 at (19614, 22452)).
 * Cost: 152 / 638 (no precise tier). */
uint32_t facet_beckmann_d_fx_fast(int32_t noh, int32_t alpha);
void facet_beckmann_d_fx_fast_batch(uint32_t *out, const int32_t *noh, const int32_t *alpha, size_t n);

/* Anisotropic GGX D = (ax ay)^3 / (pi K^2), K = (T.H ay)^2 + (B.H ax)^2 +
 * (N.H ax ay)^2 (facet.h); noh [0, 1], toh, boh [-1, 1] (Q15 signed, the
 * L.V domain), alpha_x, alpha_y [2^-10, 1].  UQ19.13 as ggx_d: for a unit h
 * D <= 1/(pi ax ay) <= 2^20/pi (N.H = 1, both widths 2^-10), the format
 * argument of ggx_d with alpha^2 replaced by ax ay.  Inputs no unit h has:
 * K floored at (ax ay)^2 / 2 (facet.h), so D <= 4/(pi ax ay), which
 * saturates at FACET_FX_MAX_D where ax ay < 2^-19.4.
 * fx: intermediates P = AX AY Q30, T AY and B AX Q30 (each <= 2^30, exact),
 * K Q90 exact in 96 bits [K <= 3], then one fxe rounding
 * (src/fx/fx_body.h).  Error: FACET_FX_ERR_GGX_ANISO_D LSB: 5 roundings
 * of <= 2^-32 relative (K, P/K, square, times P, times 1/pi) plus the final
 * half LSB, which is more than 1 LSB only where raw > 2^29.7 (ax ay <
 * 2^-17, at or near the peak); measured max 3 LSB (3.09 real) at raw
 * 2^31.5, (129, 32, 1, 33, 32), relative 2^-29.9.  The exact peak (N.H = 1,
 * T.H = B.H = 0) is correctly rounded, as ggx_d's.
 * Cost: 1 division (P / K, or the peak's), 3 fxe mul, ~8 mul64.
 * fx_fast: K in Q61 in 64 bits (the (N.H ax ay)^2 term truncated, <= 2^-20
 * relative), its floor by an exact 64-bit max, normalised by clz; (ax ay)^3
 * from the normalised product; one 1/x.
 *   Error: FACET_FX_FAST_ERR_GGX_ANISO_D; measured e 0.514 (LSB 0.514, rel
 *   2^-15.02, i.e. 2^-15.0 above 2^15 LSB) at (24888, -32706, 7085, 32723,
 *   32705); 0.512 over 3e6 unit half vectors.  Cost: 157 / 569 (352 / 1242). */
uint32_t facet_ggx_aniso_d_fx(int32_t noh, int32_t toh, int32_t boh, int32_t alpha_x, int32_t alpha_y);
uint32_t facet_ggx_aniso_d_fx_fast(int32_t noh, int32_t toh, int32_t boh, int32_t alpha_x, int32_t alpha_y);
void facet_ggx_aniso_d_fx_batch(uint32_t *out, const int32_t *noh, const int32_t *toh,
                                const int32_t *boh, const int32_t *alpha_x, const int32_t *alpha_y,
                                size_t n);
void facet_ggx_aniso_d_fx_fast_batch(uint32_t *out, const int32_t *noh, const int32_t *toh,
                                     const int32_t *boh, const int32_t *alpha_x,
                                     const int32_t *alpha_y, size_t n);

/* GTR D = c / d^gamma (facet.h), the fast tier only (kernels.def fx_code
 * fast); noh [0, 1], alpha [2^-10, 1], gamma [0, 4] (raw Q15 [0, 4 2^15],
 * the GAMMA domain; outside clamps).  Evaluated as
 *   D = 2^Z g(|M|) / (pi g(|L|)),  g(m) = m / (1 - 2^-m),  L = log2 alpha^2,
 *   M = (1 - gamma) L,  Z = -gamma log2 d - max(M, 0) in [-60, 20],
 * d = (1 - n)(1 + n) + (n alpha)^2 exact in 64 bits (as ggx_d), which is
 * c = E(L) / (pi E(M)) of facet.h with its limits (gamma = 1: g(0) = 1/ln 2
 * by a series; alpha = 1 and gamma = 0: 1/pi) and no special case.
 * Integer log2 and 2^f (src/fx/fx_fast_body.h): log2 = clz (the exponent) +
 * a 16-entry reciprocal/log table and a degree-5 series on the mantissa
 * (|error| <= 2^-25.5); 2^f = a degree-5 polynomial on f in [0, 1)
 * (Chebyshev nodes, <= 2^-22.9 relative with its truncations); 2^Z's
 * integer part is the final shift.  Formats: -log2 d, |L|, |M| Q26 [<= 60
 * 2^26 < 2^32]; gamma (-log2 d) Q41 in 64 bits [< 2^47.3]; Z + 64 Q24 [4 ..
 * 84: < 2^31]; g's n Q26, d Q31, their cross products Q57 [< 2^63].
 * Output UQ19.13 as ggx_d.  Range: the peak D(1) = c / alpha^(2 gamma) ~
 * (gamma - 1) / (pi alpha^2) for gamma > 1; it fits 2^19 for every alpha
 * where gamma <= 2.57 (gamma = 2: 2^20/pi as GGX; gamma = 1: 24076.5;
 * gamma < 1 smaller still: c <= 1/pi, d^-gamma <= alpha^-2gamma), and above
 * gamma = 2.571 the peak saturates at FACET_FX_MAX_D for alpha below
 * 2^-9.99 (gamma 2.6) .. 2^-9.53 (gamma = 4, peak 1.0e6), near N.H = 1
 * only.  The tail falls below the LSB (2^-13) as ggx_d's: absolute error.
 * Error: FACET_FX_FAST_ERR_GTR_D (measured max 0.514, relative 2^-15.1
 * above 2^15 LSB: the reciprocal's 2^-16 and the exponent's 2^-24 times ln 2
 * |Z|; e 0.514, LSB 0.510, rel 2^-15.12 at (26315, 315, 31073)).
 * Cost: 295 / 1525 (no precise tier). */
uint32_t facet_gtr_d_fx_fast(int32_t noh, int32_t alpha, int32_t gamma);
void facet_gtr_d_fx_fast_batch(uint32_t *out, const int32_t *noh, const int32_t *alpha,
                               const int32_t *gamma, size_t n);

/* ==== Shadowing and visibility ================================================
 * The formulas of facet.h, the same domains as the f32 kernels with the
 * fixed-point cos floor (N.L, N.V of the 3- and 4-input kernels in [2^-8,
 * 1]; the 2-input ones and N.H, V.H in [0, 1]).  Outputs: the G terms Q15
 * (max 1: every one is capped at 1 or a product or minimum of [0, 1]
 * values); the Vis terms UQ16.16 (smith_vis max 15894.3, smith_vis_hammon
 * and smith_vis_joint_approx 13117, smith_vis_fit 15521, all at N.L = N.V =
 * 2^-8, alpha = 2^-10 [raw < 2^30]).  Both tiers but smith_g1_gtr (the fast
 * tier only).  Each step's Q format and bound: src/fx/fx_body.h and
 * src/fx/fx_fast_body.h.  The rest of the menu (g_implicit ..
 * smith_vis_fit) is correctly rounded in the precise tier (0 LSB measured)
 * but for the two Vis terms (1 LSB: fxe's 32-bit rounding of the
 * denominator); its fast-tier errors are over tests/fx/test_fx_fast.c's
 * sweep, 0.8 M to 2 M tuples per kernel, and its quick variant under
 * FACET_TEST_QUICK. */
#define FACET_FX_ERR_SMITH_G1                        1
#define FACET_FX_FAST_ERR_SMITH_G1                   0.520
#define FACET_FX_ERR_SMITH_G2                        1
#define FACET_FX_FAST_ERR_SMITH_G2                   0.527
#define FACET_FX_ERR_SMITH_G2_UNCORRELATED           1
#define FACET_FX_FAST_ERR_SMITH_G2_UNCORRELATED      0.532
#define FACET_FX_ERR_SMITH_VIS                       1
#define FACET_FX_FAST_ERR_SMITH_VIS                  0.054
#define FACET_FX_ERR_SMITH_G1_HAMMON                 1
#define FACET_FX_FAST_ERR_SMITH_G1_HAMMON            0.500
#define FACET_FX_FAST_ERR_SMITH_G1_GTR               0.51
#define FACET_FX_ERR_SMITH_G2_HAMMON                 1
#define FACET_FX_FAST_ERR_SMITH_G2_HAMMON            0.500
#define FACET_FX_ERR_SMITH_VIS_HAMMON                1
#define FACET_FX_FAST_ERR_SMITH_VIS_HAMMON           0.037
#define FACET_FX_ERR_G_IMPLICIT                      1
#define FACET_FX_FAST_ERR_G_IMPLICIT                 0.500
#define FACET_FX_ERR_G_NEUMANN                       1
#define FACET_FX_FAST_ERR_G_NEUMANN                  0.000
#define FACET_FX_ERR_G_COOK_TORRANCE                 1
#define FACET_FX_FAST_ERR_G_COOK_TORRANCE            0.513
#define FACET_FX_ERR_G_KELEMEN                       1
#define FACET_FX_FAST_ERR_G_KELEMEN                  0.513
#define FACET_FX_ERR_SMITH_G1_BECKMANN               1
#define FACET_FX_FAST_ERR_SMITH_G1_BECKMANN          0.502
#define FACET_FX_ERR_SMITH_G1_SCHLICK_BECKMANN       1
#define FACET_FX_FAST_ERR_SMITH_G1_SCHLICK_BECKMANN  0.500
#define FACET_FX_ERR_SMITH_VIS_JOINT_APPROX          1
#define FACET_FX_FAST_ERR_SMITH_VIS_JOINT_APPROX     0.037
#define FACET_FX_ERR_SMITH_VIS_FIT                   1
#define FACET_FX_FAST_ERR_SMITH_VIS_FIT              0.048

/* Smith G1 (GGX, exact) = 2 n / (n + sqrt(alpha^2 + (1 - alpha^2) n^2));
 * nov [0, 1], alpha [2^-10, 1].  Q15, max 1; G1(0) = 0, G1(1) = 1.
 * fx: error FACET_FX_ERR_SMITH_G1 LSB.  Cost: 1 sqrt, 1 division, 1 fxe, 3 mul.
 * fx_fast: G1 = X / (X + Y), X = 2 n (n + r), Y = a^2 (1 - n^2) (r's
 *   table root; X, Y and their sum exact in 64 bits), rounded as 1 - Y / (X
 *   + Y) by one Newton-refined 1/x; monotone in both inputs (every pair,
 *   the datapath paragraph above).
 *   Error: FACET_FX_FAST_ERR_SMITH_G1; measured e 0.520 (LSB 0.520) at
 *   (117, 8397) (0.536 as 2 n / (n + r) by the table 1/x: r's error now
 *   enters times (r - n) / (n + r)^2).  Cost: 98 / 229 (210 / 1138),
 *   measured before the monotone form
 *   (M4 and M33 now: the Execution time table). */
int32_t facet_smith_g1_fx(int32_t nov, int32_t alpha);
int32_t facet_smith_g1_fx_fast(int32_t nov, int32_t alpha);
void facet_smith_g1_fx_batch(int32_t *out, const int32_t *nov, const int32_t *alpha, size_t n);
void facet_smith_g1_fx_fast_batch(int32_t *out, const int32_t *nov, const int32_t *alpha, size_t n);

/* Smith G2, height-correlated = 2 nl nv / (nv r(nl) + nl r(nv)),
 * r(x) = sqrt(alpha^2 + (1 - alpha^2) x^2); nol, nov [2^-8, 1], alpha
 * [2^-10, 1].  Q15, max 1.
 * fx: error FACET_FX_ERR_SMITH_G2 LSB.  Cost: 2 sqrt, 1 division, 3 fxe, ~8 mul.
 * fx_fast: two sqrt, one Newton-refined 1/x: each cosine's G1 = x / d as
 *   smith_g1, G2 = x_l x_v / (d_l d_v - y_l y_v) (y = d - x: 1 / (1/G1_l +
 *   1/G1_v - 1)), in 64 bits, rounded as 1 - (den - x_l x_v) / den;
 *   monotone in each input (the datapath paragraph).
 *   Error: FACET_FX_FAST_ERR_SMITH_G2; measured e 0.527 (LSB 0.527) at
 *   (131, 16606, 8269) (0.536 before the monotone form).  Cost: 146 / 418
 *   (352 / 1766), measured before the monotone form
 *   (M4 and M33 now: the Execution time table). */
int32_t facet_smith_g2_fx(int32_t nol, int32_t nov, int32_t alpha);
int32_t facet_smith_g2_fx_fast(int32_t nol, int32_t nov, int32_t alpha);
void facet_smith_g2_fx_batch(int32_t *out, const int32_t *nol, const int32_t *nov,
                             const int32_t *alpha, size_t n);
void facet_smith_g2_fx_fast_batch(int32_t *out, const int32_t *nol, const int32_t *nov,
                             const int32_t *alpha, size_t n);

/* G1(N.L) G1(N.V); domains as smith_g2.  Q15, max 1.
 * fx: error FACET_FX_ERR_SMITH_G2_UNCORRELATED LSB.  Cost: 2 sqrt, 1
 * division, 3 fxe, ~8 mul.
 * fx_fast: two sqrt, one Newton-refined 1/x: G = x_l x_v / (d_l d_v)
 *   (each G1 = x / d as smith_g1), rounded as 1 - (d_l d_v - x_l x_v) /
 *   (d_l d_v); monotone in each input.
 *   Error: FACET_FX_FAST_ERR_SMITH_G2_UNCORRELATED; measured e 0.532 (LSB
 *   0.532) at (386, 380, 4236) (0.544 before the monotone form).  Cost:
 *   147 / 420 (378 / 1792), measured before the monotone form
 *   (M4 and M33 now: the Execution time table). */
int32_t facet_smith_g2_uncorrelated_fx(int32_t nol, int32_t nov, int32_t alpha);
int32_t facet_smith_g2_uncorrelated_fx_fast(int32_t nol, int32_t nov, int32_t alpha);
void facet_smith_g2_uncorrelated_fx_batch(int32_t *out, const int32_t *nol, const int32_t *nov,
                                          const int32_t *alpha, size_t n);
void facet_smith_g2_uncorrelated_fx_fast_batch(int32_t *out, const int32_t *nol, const int32_t *nov,
                                          const int32_t *alpha, size_t n);

/* Vis = G2 / (4 nl nv) = 0.5 / (nv r(nl) + nl r(nv)); domains as smith_g2.
 * UQ16.16, max 15894.3 (nl = nv = 2^-8, alpha = 2^-10).
 * fx: error FACET_FX_ERR_SMITH_VIS LSB.  Cost: as smith_g2.
 * fx_fast: two sqrt, one 1/x.
 *   Error: FACET_FX_FAST_ERR_SMITH_VIS; measured e 0.054 (LSB 0.000, rel
 *   2^-14.24) at (32739, 181, 16531).  Cost: 128 / 374 (331 / 1740). */
uint32_t facet_smith_vis_fx(int32_t nol, int32_t nov, int32_t alpha);
uint32_t facet_smith_vis_fx_fast(int32_t nol, int32_t nov, int32_t alpha);
void facet_smith_vis_fx_batch(uint32_t *out, const int32_t *nol, const int32_t *nov,
                              const int32_t *alpha, size_t n);
void facet_smith_vis_fx_fast_batch(uint32_t *out, const int32_t *nol, const int32_t *nov,
                              const int32_t *alpha, size_t n);

/* Hammon's G1 ~ 2 n / (n (2 - alpha) + alpha); nov [0, 1], alpha
 * [2^-10, 1].  Q15, max 1.
 * fx: error FACET_FX_ERR_SMITH_G1_HAMMON LSB (both operands exact:
 * correctly rounded).  Cost: 1 division, 2 mul.
 * fx_fast: the denominator exact; one Newton-refined 1/x (2^-30: the
 *   table's 2^-16 stepped backwards near G1 = 1), monotone in both inputs
 *   (every pair).
 *   Error: FACET_FX_FAST_ERR_SMITH_G1_HAMMON; measured e 0.500 (LSB 0.500)
 *   at (61, 5878) (0.514 by the table 1/x).  Cost: 66 / 115 (68 / 514),
 *   measured before the Newton step (two more high-word products; M4
 *   and M33 now: the Execution time table). */
int32_t facet_smith_g1_hammon_fx(int32_t nov, int32_t alpha);
int32_t facet_smith_g1_hammon_fx_fast(int32_t nov, int32_t alpha);
void facet_smith_g1_hammon_fx_batch(int32_t *out, const int32_t *nov, const int32_t *alpha,
                                    size_t n);
void facet_smith_g1_hammon_fx_fast_batch(int32_t *out, const int32_t *nov, const int32_t *alpha,
                                    size_t n);

/* Smith G1 for GTR (Dimov; facet.h's closed forms at gamma = 0 .. 4 and
 * the monotone cubic in gamma between them), the fast tier only (kernels.def
 * fx_code fast); nov [0, 1], alpha [2^-10, 1], gamma [0, 4] (raw [0, 4
 * 2^15]).  Q15, max 1.  The Q15 output is an absolute measure, so every
 * stage is held to an absolute error: the closed forms divided through by
 * powers of W (W = sqrt(n^2 + alpha^2 s2), the table root and one Heron
 * step) are O(1) functions of nu = n / W in [0, 1] and alpha^2, Q30 values
 * (the undivided ones go as alpha^4 at small N.V); divisions by one
 * refined reciprocal (table + Newton, 2^-29); R(u) = ln(1 + u) / u by a
 * series below u = 1/16 and the integer log2 above; e = 1 / (ln 2 g(|L|))
 * from gtr_d's g.  The five values are non-decreasing in gamma (checked
 * against the oracle on a 401 x 4001 (alpha, N.V) grid), so the
 * Fritsch-Carlson slopes (harmonic means 2 a b / (a + b) = 2 a (b / (a + b)),
 * ends (3 d0 - d1) / 2 floored at 0) and the Hermite sum are formed from
 * differences >= 0: nothing is signed; Q27 .. Q32 stages, each bound
 * beside the code (src/fx/fx_fast_body.h).
 * Not monotone everywhere (the only G term): 1 reversal in N.V and 172
 * in alpha over tests/fx/test_fx_fast.c's monotonicity lines (3.9 M steps
 * each), held to those counts; 0 in gamma.
 * Error: FACET_FX_FAST_ERR_SMITH_G1_GTR LSB (measured 0.5002 in the test,
 * 0.5021 over 3e6 tuples with gamma uniform in [0, 4] and 1 in 7 at an
 * integer order; each closed form alone <= 0.5016; e 0.502, LSB 0.500 at
 * (24, 34, 97874)).  Cost: 1162 / 3790
 * (no precise tier; 14 refined reciprocals, 2 log2, 1 2^f: the widest
 * kernel of the tier). */
int32_t facet_smith_g1_gtr_fx_fast(int32_t nov, int32_t alpha, int32_t gamma);
void facet_smith_g1_gtr_fx_fast_batch(int32_t *out, const int32_t *nov, const int32_t *alpha,
                                      const int32_t *gamma, size_t n);

/* Hammon's G2 ~ 2 nl nv / m, m = (1 - alpha) 2 nl nv + alpha (nl + nv);
 * domains as smith_g2.  Q15, max 1.
 * fx: error FACET_FX_ERR_SMITH_G2_HAMMON LSB.  Cost: 1 division, ~6 mul.
 * fx_fast: m exact in 64 bits; one Newton-refined 1/x; monotone in each
 *   input.
 *   Error: FACET_FX_FAST_ERR_SMITH_G2_HAMMON; measured e 0.500 (LSB 0.500)
 *   at (170, 7132, 26909) (0.514 by the table 1/x).  Cost: 87 / 180 (128 /
 *   648), measured before the Newton step (M4 and M33 now: the
 *   Execution time table). */
int32_t facet_smith_g2_hammon_fx(int32_t nol, int32_t nov, int32_t alpha);
int32_t facet_smith_g2_hammon_fx_fast(int32_t nol, int32_t nov, int32_t alpha);
void facet_smith_g2_hammon_fx_batch(int32_t *out, const int32_t *nol, const int32_t *nov,
                                    const int32_t *alpha, size_t n);
void facet_smith_g2_hammon_fx_fast_batch(int32_t *out, const int32_t *nol, const int32_t *nov,
                                    const int32_t *alpha, size_t n);

/* Hammon's Vis ~ 0.5 / m; domains as smith_g2.  UQ16.16, max 13117.
 * fx: error FACET_FX_ERR_SMITH_VIS_HAMMON LSB.  Cost: 1 division, ~6 mul.
 * fx_fast: one 1/x.
 *   Error: FACET_FX_FAST_ERR_SMITH_VIS_HAMMON; measured e 0.037 (LSB 0.000,
 *   rel 2^-15.38) at (32762, 31510, 9047).  Cost: 71 / 143 (115 / 610). */
uint32_t facet_smith_vis_hammon_fx(int32_t nol, int32_t nov, int32_t alpha);
uint32_t facet_smith_vis_hammon_fx_fast(int32_t nol, int32_t nov, int32_t alpha);
void facet_smith_vis_hammon_fx_batch(uint32_t *out, const int32_t *nol, const int32_t *nov,
                                     const int32_t *alpha, size_t n);
void facet_smith_vis_hammon_fx_fast_batch(uint32_t *out, const int32_t *nol, const int32_t *nov,
                                     const int32_t *alpha, size_t n);

/* N.L N.V; Q15.  Scaling: N.L N.V Q30 exact [<= 2^30], rounded once to Q15.
 * fx: error FACET_FX_ERR_G_IMPLICIT LSB (measured 0).  Cost: 1 mul.
 * fx_fast: Error: FACET_FX_FAST_ERR_G_IMPLICIT; measured e 0.500 (LSB
 * 0.500) at (512, 32). */
int32_t facet_g_implicit_fx(int32_t nol, int32_t nov);
int32_t facet_g_implicit_fx_fast(int32_t nol, int32_t nov);
void facet_g_implicit_fx_batch(int32_t *out, const int32_t *nol, const int32_t *nov, size_t n);
void facet_g_implicit_fx_fast_batch(int32_t *out, const int32_t *nol, const int32_t *nov, size_t n);

/* min(N.L, N.V) (= N.L N.V / max); Q15, exact in both tiers.
 * fx: error FACET_FX_ERR_G_NEUMANN LSB (measured 0).
 * fx_fast: Error: FACET_FX_FAST_ERR_G_NEUMANN (0: exact). */
int32_t facet_g_neumann_fx(int32_t nol, int32_t nov);
int32_t facet_g_neumann_fx_fast(int32_t nol, int32_t nov);
void facet_g_neumann_fx_batch(int32_t *out, const int32_t *nol, const int32_t *nov, size_t n);
void facet_g_neumann_fx_fast_batch(int32_t *out, const int32_t *nol, const int32_t *nov, size_t n);

/* min(1, 2 N.H min(N.L, N.V) / V.H); Q15.  Scaling: g = 2 N.H min(N.L, N.V)
 * Q30 exact [<= 2^31]; 1 where g >= V.H 2^15 (V.H = 0 included), else
 * g / V.H.
 * fx: error FACET_FX_ERR_G_COOK_TORRANCE LSB (measured 0).  Cost: 1 division, 2 mul.
 * fx_fast: Error: FACET_FX_FAST_ERR_G_COOK_TORRANCE; measured e 0.513 (LSB
 * 0.512) on the quick sweep; full: 0.5115 at (8143, 137, 32753, 9181). */
int32_t facet_g_cook_torrance_fx(int32_t nol, int32_t nov, int32_t noh, int32_t voh);
int32_t facet_g_cook_torrance_fx_fast(int32_t nol, int32_t nov, int32_t noh, int32_t voh);
void facet_g_cook_torrance_fx_batch(int32_t *out, const int32_t *nol, const int32_t *nov,
                                    const int32_t *noh, const int32_t *voh, size_t n);
void facet_g_cook_torrance_fx_fast_batch(int32_t *out, const int32_t *nol, const int32_t *nov,
                                         const int32_t *noh, const int32_t *voh, size_t n);

/* min(1, N.L N.V / V.H^2); Q15.  Scaling: N.L N.V and V.H^2 Q30 exact
 * [<= 2^30]; 1 where the first is not below the second, else their
 * quotient.
 * fx: error FACET_FX_ERR_G_KELEMEN LSB (measured 0).  Cost: 1 division, 2 mul.
 * fx_fast: Error: FACET_FX_FAST_ERR_G_KELEMEN; measured e 0.513 (LSB 0.512)
 * at (32748, 128, 11613). */
int32_t facet_g_kelemen_fx(int32_t nol, int32_t nov, int32_t voh);
int32_t facet_g_kelemen_fx_fast(int32_t nol, int32_t nov, int32_t voh);
void facet_g_kelemen_fx_batch(int32_t *out, const int32_t *nol, const int32_t *nov,
                              const int32_t *voh, size_t n);
void facet_g_kelemen_fx_fast_batch(int32_t *out, const int32_t *nol, const int32_t *nov,
                                   const int32_t *voh, size_t n);

/* Walter's Beckmann G1 (facet.h); Q15, G1(0) = 0, G1(1) = 1.  Scaling: the
 * branch c < 1.6 as 25 N^2 2^24 < A^2 (1 - n^2) Q60 exact (fast: from the
 * high words; misjudged only within 2^-20 of c = 1.6, where both pieces are
 * 1); the rational in fxe (fast: in c Q29, c^2 Q29, the sums Q59 in 64 bits
 * [< 2^63]); sqrt(1 - n^2) by the exact root (fast: the table).
 * fx: error FACET_FX_ERR_SMITH_G1_BECKMANN LSB (measured 0).  Cost: 1 sqrt,
 * 1 division, ~8 fxe.
 * fx_fast: both quotients by the Newton-refined 1/x; monotone in both
 * inputs (every pair).  Error: FACET_FX_FAST_ERR_SMITH_G1_BECKMANN;
 * measured e 0.502 (LSB 0.501) at (35, 4266) (0.523 by the table 1/x). */
int32_t facet_smith_g1_beckmann_fx(int32_t nov, int32_t alpha);
int32_t facet_smith_g1_beckmann_fx_fast(int32_t nov, int32_t alpha);
void facet_smith_g1_beckmann_fx_batch(int32_t *out, const int32_t *nov, const int32_t *alpha, size_t n);
void facet_smith_g1_beckmann_fx_fast_batch(int32_t *out, const int32_t *nov, const int32_t *alpha,
                                           size_t n);

/* N.V / (N.V (1 - k) + k), k = alpha sqrt(2/pi); Q15.  Scaling: k = a
 * round(sqrt(2/pi) 2^32); the denominator N (1 - k) + k exact in 64 bits
 * [< 2^63].
 * fx: error FACET_FX_ERR_SMITH_G1_SCHLICK_BECKMANN LSB (measured 0).  Cost:
 * 1 division, 3 mul64.
 * fx_fast: the quotient by the Newton-refined 1/x; monotone in both inputs
 * (every pair).  Error: FACET_FX_FAST_ERR_SMITH_G1_SCHLICK_BECKMANN;
 * measured e 0.500 (LSB 0.500) at (603, 32712) (0.508 by the table 1/x). */
int32_t facet_smith_g1_schlick_beckmann_fx(int32_t nov, int32_t alpha);
int32_t facet_smith_g1_schlick_beckmann_fx_fast(int32_t nov, int32_t alpha);
void facet_smith_g1_schlick_beckmann_fx_batch(int32_t *out, const int32_t *nov, const int32_t *alpha,
                                              size_t n);
void facet_smith_g1_schlick_beckmann_fx_fast_batch(int32_t *out, const int32_t *nov,
                                                   const int32_t *alpha, size_t n);

/* The joint approximation = Hammon's Vis; UQ16.16, max 13117: Hammon's
 * exact m45, the same code as smith_vis_hammon in each tier (the same
 * bits).
 * fx: error FACET_FX_ERR_SMITH_VIS_JOINT_APPROX LSB (measured 1, as
 * smith_vis_hammon).  Cost: as smith_vis_hammon.
 * fx_fast: Error: FACET_FX_FAST_ERR_SMITH_VIS_JOINT_APPROX; measured e
 * 0.037 (LSB 0.000, rel 2^-14.79), as smith_vis_hammon. */
uint32_t facet_smith_vis_joint_approx_fx(int32_t nol, int32_t nov, int32_t alpha);
uint32_t facet_smith_vis_joint_approx_fx_fast(int32_t nol, int32_t nov, int32_t alpha);
void facet_smith_vis_joint_approx_fx_batch(uint32_t *out, const int32_t *nol, const int32_t *nov,
                                           const int32_t *alpha, size_t n);
void facet_smith_vis_joint_approx_fx_fast_batch(uint32_t *out, const int32_t *nol, const int32_t *nov,
                                                const int32_t *alpha, size_t n);

/* The fitted visibility (facet.h); UQ16.16, max 15521.  Scaling: the float
 * constants exact in Q30; sigma exact in Q60 (fast: Q30 stages, every value
 * < 2^32, R >= 2^21); the denominator in fxe (fast: exact in 64 bits
 * [< 2^48]).
 * fx: error FACET_FX_ERR_SMITH_VIS_FIT LSB (measured 1: fxe's 32-bit
 * rounding of the denominator).  Cost: 1 division, ~14 fxe.
 * fx_fast: Error: FACET_FX_FAST_ERR_SMITH_VIS_FIT; measured e 0.048 (LSB
 * 0.000, rel 2^-14.39) at (32751, 32733, 27251). */
uint32_t facet_smith_vis_fit_fx(int32_t nol, int32_t nov, int32_t alpha);
uint32_t facet_smith_vis_fit_fx_fast(int32_t nol, int32_t nov, int32_t alpha);
void facet_smith_vis_fit_fx_batch(uint32_t *out, const int32_t *nol, const int32_t *nov,
                                  const int32_t *alpha, size_t n);
void facet_smith_vis_fit_fx_fast_batch(uint32_t *out, const int32_t *nol, const int32_t *nov,
                                       const int32_t *alpha, size_t n);

/* ==== Diffuse =================================================================
 * UQ8.24 outputs (BRDF values, not yet times N.L).  Both tiers:
 * diffuse_hammon; the fast tier only: the rest of the menu (no precise
 * fixed-point kernel), the formulas of facet.h with the fixed-point domains
 * (nol, nov [2^-8, 1]; lov [-1, 1]; loh, albedo [0, 1]; alpha [2^-10, 1];
 * every int32 outside clamps), the fast tier's bound and datapath; each
 * step's Q format and bound are beside the code in src/fx/fx_fast_body.h.
 * Maxima: diffuse_hammon 20.65, diffuse_burley 6.25/pi = 1.99,
 * diffuse_oren_nayar (A + B 256)/pi <= 27.3 at nl = nv = 2^-8, L.V = 1 [raw
 * < 2^28.8], the two Hammon variants <= diffuse_hammon's 20.65.  Fast-tier
 * errors of the menu: the final rounding (measured over
 * tests/fx/test_fx_fast.c's full sweep, 0.8 M to 2.3 M tuples per kernel,
 * x86-64). */
#define FACET_FX_ERR_DIFFUSE_HAMMON                  1
#define FACET_FX_FAST_ERR_DIFFUSE_HAMMON             0.552
#define FACET_FX_FAST_ERR_DIFFUSE_BURLEY             0.506
#define FACET_FX_FAST_ERR_DIFFUSE_OREN_NAYAR         0.508
#define FACET_FX_FAST_ERR_DIFFUSE_HAMMON_HYBRID      0.512
#define FACET_FX_FAST_ERR_DIFFUSE_HAMMON_CHEAP       0.507

/* Hammon's GGX diffuse (facet.h's formula, 1 + L.V raised to
 * (N.L + N.V)^2 / 2); nol, nov [2^-8, 1], lov [-1, 1], alpha [2^-10, 1],
 * albedo [0, 1].  UQ8.24, max 20.65 (nl = nv = 2^-8, L.V = 1, alpha =
 * albedo = 1).
 * fx: error FACET_FX_ERR_DIFFUSE_HAMMON LSB.  Cost: 1 sqrt, 1 division,
 * ~12 fxe, ~10 mul64.
 * fx_fast: 32-bit stages: P(x) = x (1 + y + ... + y^4), the sum from a
 * table; the bracket in Q25 [< 2^31.02], times albedo / pi; one sqrt, one
 * 1/x.
 *   Error: FACET_FX_FAST_ERR_DIFFUSE_HAMMON; measured e 0.552 (LSB 0.517,
 *   rel 2^-14.55) at (134, 142, -32768, 40, 10500).  Cost: 123 / 414 (686 /
 *   2290). */
uint32_t facet_diffuse_hammon_fx(int32_t nol, int32_t nov, int32_t lov, int32_t alpha,
                                 int32_t albedo);
uint32_t facet_diffuse_hammon_fx_fast(int32_t nol, int32_t nov, int32_t lov, int32_t alpha,
                                      int32_t albedo);
void facet_diffuse_hammon_fx_batch(uint32_t *out, const int32_t *nol, const int32_t *nov,
                                   const int32_t *lov, const int32_t *alpha,
                                   const int32_t *albedo, size_t n);
void facet_diffuse_hammon_fx_fast_batch(uint32_t *out, const int32_t *nol, const int32_t *nov,
                                   const int32_t *lov, const int32_t *alpha,
                                   const int32_t *albedo, size_t n);

/* Burley's diffuse (facet.h); UQ8.24, max 1.99.  Fast tier only.  One sqrt
 * (table).  Scaling: sqrt(alpha) Q19 from the sqrt table; f_d90 Q29 [<= 2.5
 * 2^29]; each factor (1 - y^5) + f_d90 y^5 Q29, their product Q28 [< 2^31],
 * times albedo/pi Q33: Q30.
 * Error: FACET_FX_FAST_ERR_DIFFUSE_BURLEY; measured e 0.505 (LSB 0.505, rel
 * 2^-11.01) at (170, 188, 24325, 13879, 3).  Cost: 85 / 298. */
uint32_t facet_diffuse_burley_fx_fast(int32_t nol, int32_t nov, int32_t loh, int32_t alpha,
                                      int32_t albedo);
void facet_diffuse_burley_fx_fast_batch(uint32_t *out, const int32_t *nol, const int32_t *nov,
                                        const int32_t *loh, const int32_t *alpha, const int32_t *albedo,
                                        size_t n);

/* Oren-Nayar's qualitative diffuse from the dots (facet.h); UQ8.24, max
 * 27.3.  Fast tier only.  Three 1/x (table).  Scaling: sigma^2 = a^2/4 Q32
 * exact; A, B by one table 1/x each (Q31); max(0, L.V - nl nv) Q30 exact, /
 * max(nl, nv) Q22 [<= 256 2^22]; A + B term Q21 [< 2^27.5]; times albedo/pi
 * Q33: Q26.
 * Error: FACET_FX_FAST_ERR_DIFFUSE_OREN_NAYAR; measured e 0.507 (LSB 0.507,
 * rel 2^-11.00) at (2230, 2227, 32768, 22716, 1).  Cost: 205 / 453. */
uint32_t facet_diffuse_oren_nayar_fx_fast(int32_t nol, int32_t nov, int32_t lov, int32_t alpha,
                                          int32_t albedo);
void facet_diffuse_oren_nayar_fx_fast_batch(uint32_t *out, const int32_t *nol, const int32_t *nov,
                                            const int32_t *lov, const int32_t *alpha,
                                            const int32_t *albedo, size_t n);

/* Hammon's hybrid diffuse (facet.h); UQ8.24.  Fast tier only.  One sqrt,
 * one 1/x: diffuse_hammon's rough, multi and final steps (its bounds) with
 * the smooth term (1 - yl^5/2)(1 - yv^5/2) Q30.
 * Error: FACET_FX_FAST_ERR_DIFFUSE_HAMMON_HYBRID; measured e 0.511 (LSB
 * 0.511, rel 2^-10.99) at (28017, 5031, -14686, 32745, 18).  Cost: 121 /
 * 469. */
uint32_t facet_diffuse_hammon_hybrid_fx_fast(int32_t nol, int32_t nov, int32_t lov, int32_t alpha,
                                             int32_t albedo);
void facet_diffuse_hammon_hybrid_fx_fast_batch(uint32_t *out, const int32_t *nol, const int32_t *nov,
                                               const int32_t *lov, const int32_t *alpha,
                                               const int32_t *albedo, size_t n);

/* Hammon's cheaper diffuse (facet.h); UQ8.24.  Fast tier only.  One sqrt,
 * one 1/x: diffuse_hammon's rough, multi and final steps with smooth = 1.
 * Error: FACET_FX_FAST_ERR_DIFFUSE_HAMMON_CHEAP; measured e 0.506 (LSB
 * 0.506, rel 2^-11.01) at (184, 22231, -30411, 32717, 40).  Cost: 98 /
 * 368. */
uint32_t facet_diffuse_hammon_cheap_fx_fast(int32_t nol, int32_t nov, int32_t lov, int32_t alpha,
                                            int32_t albedo);
void facet_diffuse_hammon_cheap_fx_fast_batch(uint32_t *out, const int32_t *nol, const int32_t *nov,
                                              const int32_t *lov, const int32_t *alpha,
                                              const int32_t *albedo, size_t n);

/* ==== The whole BRDF ==========================================================
 * Hammon's model, D Vis_hammon F(f0, L.H) + diffuse from the dots, then its
 * RGB forms (one geometry, three channels) and their batches.  64-bit
 * outputs: a batch's out must not overlap an input. */
#define FACET_FX_ERR_BRDF_HAMMON                     1
#define FACET_FX_FAST_ERR_BRDF_HAMMON                0.646

/* The whole model: D Vis_hammon F(f0, L.H) + diffuse, from the dots (N.H
 * never formed; the peak's cancellation exact); domains as diffuse_hammon,
 * f0 [0, 1].  UQ40.24, max 4.38e9 (D 333772 x Vis 13117 at the grazing
 * peak).
 * fx: error FACET_FX_ERR_BRDF_HAMMON LSB where the value is below 16; above,
 * 2^-26 relative (a double oracle cannot resolve 2^-24 on values up to 4e9;
 * measured 2^-28.3).  Cost: 2 sqrt, 3 division, ~30 fxe.
 * fx_fast: one sqrt, three 1/x, 26 high-word products; spec and diffuse
 * added in Q29 (64 bits) and rounded once.
 *   Error: FACET_FX_FAST_ERR_BRDF_HAMMON; measured e 0.646 (LSB 0.646, rel
 *   2^-13.20 above 2^15 LSB) at (32768, 128, 129, 1000, 32, 0).  Cost: 278
 *   / 1060 (1476 / 4919). */
uint64_t facet_brdf_hammon_fx(int32_t nol, int32_t nov, int32_t lov, int32_t alpha,
                              int32_t f0, int32_t albedo);
uint64_t facet_brdf_hammon_fx_fast(int32_t nol, int32_t nov, int32_t lov, int32_t alpha,
                                   int32_t f0, int32_t albedo);
void facet_brdf_hammon_fx_batch(uint64_t *out, const int32_t *nol, const int32_t *nov,
                                const int32_t *lov, const int32_t *alpha, const int32_t *f0,
                                const int32_t *albedo, size_t n);
void facet_brdf_hammon_fx_fast_batch(uint64_t *out, const int32_t *nol, const int32_t *nov,
                                const int32_t *lov, const int32_t *alpha, const int32_t *f0,
                                const int32_t *albedo, size_t n);

/* brdf_hammon for an RGB f0 and albedo, the geometry (D, Vis, the Fresnel
 * tail, the diffuse shape) computed once: out[c] equals
 * facet_brdf_hammon_fx(nol, nov, lov, alpha, f0[c], albedo[c]) bit for bit
 * (the same operations per channel; tests/fx/test_fx_rgb.c), on every target.
 * Cost: one geometry and three channel tails (`build/facet-bench api`:
 * 0.48x the time of three
 * facet_brdf_hammon_fx calls, 0.63x in fx_fast, on x86-64). */
void facet_brdf_hammon_rgb_fx(uint64_t out[3], int32_t nol, int32_t nov, int32_t lov,
                              int32_t alpha, const int32_t f0[3], const int32_t albedo[3]);
/* batches of it: planar (out[c][i], f0[c][i], albedo[c][i]) and interleaved
 * (out[3i + c], f0[3i + c], albedo[3i + c]); the scalar loop on every port;
 * out must not overlap an input (64-bit outputs).  The fast tier: facet_brdf_hammon_rgb_fx_fast[_batch...] below. */
void facet_brdf_hammon_rgb_fx_batch(uint64_t *const out[3], const int32_t *nol, const int32_t *nov,
                                    const int32_t *lov, const int32_t *alpha,
                                    const int32_t *const f0[3], const int32_t *const albedo[3],
                                    size_t n);
void facet_brdf_hammon_rgb_fx_batch_interleaved(uint64_t *out, const int32_t *nol,
                                                const int32_t *nov, const int32_t *lov,
                                                const int32_t *alpha, const int32_t *f0,
                                                const int32_t *albedo, size_t n);
/* the RGB form and its batches, as facet_brdf_hammon_rgb_fx above: each
 * channel equals facet_brdf_hammon_fx_fast bit for bit */
void facet_brdf_hammon_rgb_fx_fast(uint64_t out[3], int32_t nol, int32_t nov, int32_t lov,
                                   int32_t alpha, const int32_t f0[3], const int32_t albedo[3]);
void facet_brdf_hammon_rgb_fx_fast_batch(uint64_t *const out[3], const int32_t *nol,
                                         const int32_t *nov, const int32_t *lov,
                                         const int32_t *alpha, const int32_t *const f0[3],
                                         const int32_t *const albedo[3], size_t n);
void facet_brdf_hammon_rgb_fx_fast_batch_interleaved(uint64_t *out, const int32_t *nol,
                                                     const int32_t *nov, const int32_t *lov,
                                                     const int32_t *alpha, const int32_t *f0,
                                                     const int32_t *albedo, size_t n);

/* ---- the shared primitives (exposed for the tests) ---------------------- */
/* floor((2^64 - 1) / d) - 2^32, d in [2^31, 2^32) */
uint32_t facet_fx_rcp32(uint32_t d);
/* ~ 2^47 / sqrt(x), x in [2^30, 2^32), relative error <= 2^-29 */
uint32_t facet_fx_rsqrt32(uint32_t x);
/* floor((u1 2^32 + u0) / d), remainder in *r; d in [2^31, 2^32), u1 < d, v = rcp32(d) */
uint32_t facet_fx_div2by1(uint32_t u1, uint32_t u0, uint32_t d, uint32_t v, uint32_t *r);
/* floor(sqrt(x)) */
uint32_t facet_fx_isqrt64(uint64_t x);

/* ---- the fx kernel table (same order and input names as facet_kernel) -- */
#define FACET_FX_MAX_INPUTS 6

typedef struct facet_fx_kernel {
    const char *name;                       /* "ggx_d" */
    int n_inputs;
    const char *inputs[FACET_FX_MAX_INPUTS];
    int32_t lo[FACET_FX_MAX_INPUTS];        /* domain of each input, raw Q15 */
    int32_t hi[FACET_FX_MAX_INPUTS];
    int out_frac;                           /* fraction bits of the output */
    int out_bits;                           /* 32 or 64 (container) */
    const char *out_format;                 /* "Q15", "UQ19.13", ... */
    uint64_t out_max;                       /* saturation value (raw) */
    uint64_t (*fx)(const int32_t *in);      /* the kernel, raw output widened;
                                             * NULL (and fx_batch NULL, err_lsb 0)
                                             * for a kernel with the fast tier only */
    /* batch on the active port: out[i] = kernel(in[0][i], ...), out an
     * array of the output container (out_bits) */
    void (*fx_batch)(void *out, const int32_t *const *in, size_t n);
    double err_lsb;                         /* FACET_FX_ERR_<NAME>: max |error| in LSB */
    /* the fast tier: same inputs, format and saturation */
    uint64_t (*fx_fast)(const int32_t *in);
    void (*fx_fast_batch)(void *out, const int32_t *const *in, size_t n);
    double err_fast;                        /* FACET_FX_FAST_ERR_<NAME>: max of
                                             * |error| / max(1 LSB, 2^-10 |value|) */
} facet_fx_kernel;

size_t facet_fx_kernel_count(void);
const facet_fx_kernel *facet_fx_kernel_at(size_t i);
const facet_fx_kernel *facet_fx_kernel_find(const char *name); /* NULL if unknown */

#ifdef __cplusplus
}
#endif

#endif
