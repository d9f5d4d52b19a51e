/* armcount_main.c - every kernel's batch function of one vector port, in
 * each tier the port runs (f32, f32_fast, fx, fx_fast), one call of N
 * samples between two marker calls, for counting executed instructions
 * under qemu (bench/report/arm_targets.sh cuts the trace at the markers).
 * The port's tables are called directly (src/core/port.h), so the dispatcher's
 * pointer load is not counted.  Prints one "FORMAT KERNEL" line per counted
 * call, in call order.  ARMCOUNT_PORT names the port (helium). */
#include <stdint.h>
#include <stdio.h>
#include "facet.h"
#include "facet/fx.h"
#include "../../src/core/port.h"

#ifndef N
#define N 64
#endif
#define CAT_(a, b) a##b
#define CAT(a, b) CAT_(a, b)
#define F32 CAT(CAT(facet_port_, ARMCOUNT_PORT), _f32)
#define F32_FAST CAT(CAT(facet_port_, ARMCOUNT_PORT), _f32_fast)
#define FX CAT(facet_fx_port_, ARMCOUNT_PORT)
#define FX_FAST CAT(facet_fx_fast_port_, ARMCOUNT_PORT)

__attribute__((noinline)) void armcount_begin(int id);
__attribute__((noinline)) void armcount_end(int id);
__attribute__((noinline)) void armcount_begin(int id) { __asm__ volatile("" : : "r"(id) : "memory"); }
__attribute__((noinline)) void armcount_end(int id) { __asm__ volatile("" : : "r"(id) : "memory"); }

/* in-domain inputs per domain class (kernel_list.h): UNIT, COS, ALPHA,
 * LOV, GAMMA, float and the same values in Q15 */
enum { D_UNIT, D_COS, D_ALPHA, D_LOV, D_GAMMA, D_N };
static float fin[D_N][N], out[N];
static int32_t qin[D_N][N];
static uint64_t qout[N];
static int id;

#define CLASS_(input, domain) D_##domain
#define F_ARG_(input, domain) fin[D_##domain]
#define Q_ARG_(input, domain) qin[D_##domain]

int main(void)
{
    uint32_t s = 12345;
    int i, d;
    for (d = 0; d < D_N; d++)
        for (i = 0; i < N; i++) {
            float u;
            s = s * 1664525u + 1013904223u;
            u = (float)(s >> 8) / 16777216.0f;
            fin[d][i] = d == D_LOV ? 2.0f * u - 1.0f : d == D_GAMMA ? 0.5f + 3.0f * u
                      : d == D_ALPHA ? 0.02f + 0.98f * u : 0.05f + 0.95f * u;
            qin[d][i] = (int32_t)(fin[d][i] * 32768.0f);
        }
/* a kernel the port's table leaves NULL runs the tier's scalar loop (the
 * dispatcher's rule, src/core/dispatch.c): that is what the port executes */
#define CALL_(tab, fb, fmt, name, outp, ...) \
    armcount_begin(id); (tab.name ? tab.name : fb.name)(outp, __VA_ARGS__, N); armcount_end(id++); \
    printf("%s %s\n", fmt, #name);
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    CALL_(F32, facet_port_scalar_f32, "f32", name, out, FACET_MAP_INPUTS(n, F_ARG_, __VA_ARGS__)) \
    CALL_(F32_FAST, facet_port_scalar_f32_fast, "f32_fast", name, out, FACET_MAP_INPUTS(n, F_ARG_, __VA_ARGS__)) \
    FACET_IF_PRECISE(fx_code, CALL_(FX, facet_fx_port_scalar, "fx", name, (fx_type *)(void *)qout, FACET_MAP_INPUTS(n, Q_ARG_, __VA_ARGS__))) \
    FACET_IF_FX(fx_type, CALL_(FX_FAST, facet_fx_fast_port_scalar, "fx_fast", name, (fx_type *)(void *)qout, FACET_MAP_INPUTS(n, Q_ARG_, __VA_ARGS__)))
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
    printf("armcount: %g %llu\n", (double)out[0], (unsigned long long)qout[0]);
    return 0;
}
