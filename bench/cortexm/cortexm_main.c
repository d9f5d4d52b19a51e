/* cortexm_main.c - the Cortex-M harness behind bench/cortexm/cortexm.sh: calls every
 * kernel on a few representative inputs, once each, under qemu-system-arm
 * with an instruction trace (-d exec with one instruction per block), so the
 * script can cut out each call's executed instructions: from the kernel's
 * first instruction to its return, callees and libgcc helpers included, the
 * caller's argument set-up and the call instruction not.
 *   -DBENCH_FX      the fixed-point kernels facet_<kernel>_fx (src/fx_*.c)
 *   otherwise       the f32 scalar kernels of facet/scalar.h built for the
 *                   same core (soft float where the core or ABI has no FPU),
 *                   each behind a noinline wrapper bench_f32_<kernel>
 * The inputs are compile-time constants (no float arithmetic outside the
 * kernels); the results go to a volatile sink. */
#include <stdint.h>
#ifdef BENCH_FX
#include "facet/fx.h"
#else
#include "facet/scalar.h"
#endif

/* nol, nov, lov, alpha, f0, albedo, noh, loh: consistent geometry
 * (L.V from N.L, N.V and an azimuth; N.H and L.H from the identities) */
#define N_PTS 4
#define P0 0.720000f, 0.810000f, 0.752558f, 0.300000f, 0.040000f, 0.800000f, 0.817222f, 0.936098f
#define P1 0.350000f, 0.920000f, 0.636589f, 0.050000f, 0.950000f, 0.100000f, 0.701971f, 0.904596f
#define P2 0.930000f, 0.550000f, 0.400266f, 0.600000f, 0.040000f, 0.500000f, 0.884385f, 0.836740f
#define P3 0.120000f, 0.430000f, 0.921875f, 0.012000f, 0.560000f, 0.300000f, 0.280534f, 0.980274f

volatile uint64_t bench_sink;

#ifdef BENCH_FX
/* Q15, round to nearest, ties up (fx.h), as integer constant expressions */
#define Q(x) ((int32_t)((double)(x) * 32768.0 + 0.5))
#define QP(a, b, c, d, e, f, g, h) { Q(a), Q(b), Q(c), Q(d), Q(e), Q(f), Q(g), Q(h) }
#define QP_(p) QP(p)
static const int32_t in[N_PTS][8] = { QP_(P0), QP_(P1), QP_(P2), QP_(P3) };
typedef int32_t T;
#define CALL(k, ...) bench_sink = (uint64_t)facet_##k##_fx(__VA_ARGS__)
#else
#define FP(a, b, c, d, e, f, g, h) { a, b, c, d, e, f, g, h }
#define FP_(p) FP(p)
static const float in[N_PTS][8] = { FP_(P0), FP_(P1), FP_(P2), FP_(P3) };
typedef float T;
#define W1(k) __attribute__((noinline)) float bench_f32_##k(float a) { return facet_##k##_f32_scalar(a); }
#define W2(k) __attribute__((noinline)) float bench_f32_##k(float a, float b) { return facet_##k##_f32_scalar(a, b); }
#define W3(k) __attribute__((noinline)) float bench_f32_##k(float a, float b, float c) { return facet_##k##_f32_scalar(a, b, c); }
#define W5(k) __attribute__((noinline)) float bench_f32_##k(float a, float b, float c, float d, float e) { return facet_##k##_f32_scalar(a, b, c, d, e); }
#define W6(k) __attribute__((noinline)) float bench_f32_##k(float a, float b, float c, float d, float e, float f) { return facet_##k##_f32_scalar(a, b, c, d, e, f); }
float bench_f32_noh_from_dots(float, float, float);
float bench_f32_loh_from_dots(float);
float bench_f32_fresnel_schlick(float, float);
float bench_f32_ggx_d(float, float);
float bench_f32_smith_g1(float, float);
float bench_f32_smith_g2(float, float, float);
float bench_f32_smith_g2_uncorrelated(float, float, float);
float bench_f32_smith_vis(float, float, float);
float bench_f32_smith_g1_hammon(float, float);
float bench_f32_smith_g2_hammon(float, float, float);
float bench_f32_smith_vis_hammon(float, float, float);
float bench_f32_diffuse_hammon(float, float, float, float, float);
float bench_f32_brdf_hammon(float, float, float, float, float, float);
float bench_f32_lambert(float);
W3(noh_from_dots) W1(loh_from_dots) W2(fresnel_schlick) W2(ggx_d) W2(smith_g1) W3(smith_g2)
W3(smith_g2_uncorrelated) W3(smith_vis) W2(smith_g1_hammon) W3(smith_g2_hammon)
W3(smith_vis_hammon) W5(diffuse_hammon) W6(brdf_hammon) W1(lambert)
static volatile float fsink;
#define CALL(k, ...) fsink = bench_f32_##k(__VA_ARGS__)
#endif

int main(void)
{
    int i;
    for (i = 0; i < N_PTS; i++) {
        const T *p = in[i];
        CALL(noh_from_dots, p[0], p[1], p[2]);
        CALL(loh_from_dots, p[2]);
        CALL(fresnel_schlick, p[4], p[7]);
        CALL(ggx_d, p[6], p[3]);
        CALL(smith_g1, p[1], p[3]);
        CALL(smith_g2, p[0], p[1], p[3]);
        CALL(smith_g2_uncorrelated, p[0], p[1], p[3]);
        CALL(smith_vis, p[0], p[1], p[3]);
        CALL(smith_g1_hammon, p[1], p[3]);
        CALL(smith_g2_hammon, p[0], p[1], p[3]);
        CALL(smith_vis_hammon, p[0], p[1], p[3]);
        CALL(diffuse_hammon, p[0], p[1], p[2], p[3], p[5]);
        CALL(brdf_hammon, p[0], p[1], p[2], p[3], p[4], p[5]);
#ifndef BENCH_FX
        CALL(lambert, p[5]);
#endif
    }
    return 0;
}
