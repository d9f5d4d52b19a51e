/* cortexm_main.c - the Cortex-M harness behind bench/cortexm/cortexm.sh: calls every
 * kernel on a few representative inputs, once each, under qemu-system-arm
 * with an instruction trace (-d exec with one instruction per block), so the
 * script can cut out each call's executed instructions: from the kernel's
 * first instruction to its return, callees and libgcc helpers included, the
 * caller's argument set-up and the call instruction not.
 *   -DBENCH_FX      the fixed-point kernels facet_<kernel>_fx (the src/fx/ sources);
 *                   with -DBENCH_FX_FAST their fast tier facet_<kernel>_fx_fast
 *   otherwise       the f32 scalar kernels of facet/scalar.h built for the
 *                   same core (soft float, or the core's FPU with a
 *                   hard-float build),
 *                   each behind a noinline wrapper bench_f32_<kernel>
 * The inputs are compile-time constants (no float arithmetic outside the
 * kernels); the results go to a volatile sink. */
#include <stdint.h>
#ifdef BENCH_FX
#include "facet/fx.h"
#else
#include "facet/scalar.h"
#endif

#include "../../src/core/kernel_list.h"

/* nol, nov, lov, alpha, f0, albedo, noh, loh: consistent geometry
 * (L.V from N.L, N.V and an azimuth; N.H and L.H from the identities) */
#define N_PTS 4
#define PT0 0.720000f, 0.810000f, 0.752558f, 0.300000f, 0.040000f, 0.800000f, 0.817222f, 0.936098f
#define PT1 0.350000f, 0.920000f, 0.636589f, 0.050000f, 0.950000f, 0.100000f, 0.701971f, 0.904596f
#define PT2 0.930000f, 0.550000f, 0.400266f, 0.600000f, 0.040000f, 0.500000f, 0.884385f, 0.836740f
#define PT3 0.120000f, 0.430000f, 0.921875f, 0.012000f, 0.560000f, 0.300000f, 0.280534f, 0.980274f
/* where each kernel input (src/core/kernels.def's names) is in a point; a
 * one-cosine kernel's cos is L.H (Fresnel) */
#define AT_nol 0
#define AT_nov 1
#define AT_lov 2
#define AT_alpha 3
#define AT_f0 4
#define AT_albedo 5
#define AT_noh 6
#define AT_cos 7
/* the D terms' other inputs reuse slots (their cost does not depend on the
 * values): T.H = L.V's, B.H = f0's, alpha_x = alpha, alpha_y = albedo's,
 * the GTR tail gamma = L.H's (0.84 .. 0.98, a non-integer order) */
#define AT_toh 2
#define AT_boh 4
#define AT_alpha_x 3
#define AT_alpha_y 5
#define AT_gamma 7
/* the menu's other inputs: V.H = L.H (the cos slot), L.H likewise, f90 =
 * albedo's slot */
#define AT_voh 7
#define AT_loh 7
#define AT_f90 5
#define INPUT_(input, domain) p[AT_##input]

volatile uint64_t bench_sink;

#ifdef BENCH_FX
/* Q15, round to nearest, ties up (fx.h), as integer constant expressions */
#define Q(x) ((int32_t)((double)(x) * 32768.0 + 0.5))
#define QP(a, b, c, d, e, f, g, h) { Q(a), Q(b), Q(c), Q(d), Q(e), Q(f), Q(g), Q(h) }
#define QP_(p) QP(p)
static const int32_t in[N_PTS][8] = { QP_(PT0), QP_(PT1), QP_(PT2), QP_(PT3) };
typedef int32_t T;
/* Names generated here from src/core/kernels.def: one call per fixed-point kernel */
#ifdef BENCH_FX_FAST
#define BENCH_TIER_(name) facet_##name##_fx_fast
#define BENCH_IF_TIER_(fx_type, fx_code, ...) FACET_IF_FX(fx_type, __VA_ARGS__)
#else
#define BENCH_TIER_(name) facet_##name##_fx
/* the precise tier: not the kernels with the fast tier only */
#define BENCH_IF_TIER_(fx_type, fx_code, ...) FACET_IF_PRECISE(fx_code, __VA_ARGS__)
#endif
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    BENCH_IF_TIER_(fx_type, fx_code, bench_sink = (uint64_t)BENCH_TIER_(name)(FACET_MAP_INPUTS(n, INPUT_, __VA_ARGS__));)
#else
#define FP(a, b, c, d, e, f, g, h) { a, b, c, d, e, f, g, h }
#define FP_(p) FP(p)
static const float in[N_PTS][8] = { FP_(PT0), FP_(PT1), FP_(PT2), FP_(PT3) };
typedef float T;
/* Names generated here from src/core/kernels.def: a noinline wrapper per kernel,
 * so the trace can cut out its call, and one call per kernel */
#define PARAM_(q) float x##q
#define ARG_(q) x##q
#define FACET_KERNEL(name, NAME, n, ...)                                                     \
    float bench_f32_##name(FACET_EACH_INPUT(n, PARAM_));                                     \
    __attribute__((noinline)) float bench_f32_##name(FACET_EACH_INPUT(n, PARAM_))            \
    {                                                                                        \
        return facet_##name##_f32_scalar(FACET_EACH_INPUT(n, ARG_));                         \
    }
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
static volatile float fsink;
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    fsink = bench_f32_##name(FACET_MAP_INPUTS(n, INPUT_, __VA_ARGS__));
#endif

int main(void)
{
    int i;
    for (i = 0; i < N_PTS; i++) {
        const T *p = in[i];
#include "../../src/core/kernels.def"
    }
    return 0;
}
