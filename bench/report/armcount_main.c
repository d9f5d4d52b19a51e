/* armcount_main.c - every kernel's batch function of one vector port, in
 * each tier the port runs (f32, f32_fast, fx, fx_fast), one call of N
 * samples between two marker calls, for counting executed instructions
 * under qemu (bench/report/arm_targets.sh cuts the trace at the markers).
 * The port's tables are called directly (src/core/port.h), so the dispatcher's
 * pointer load is not counted.  Prints one "FORMAT KERNEL" line per counted
 * call, in call order.  ARMCOUNT_PORT names the port (helium).
 * ARMCOUNT_F16 (optional) names the port's binary16 table (heliumfp16,
 * neonfp16): then every kernel with an f16 form is also counted as format
 * f16, on the same inputs rounded to binary16 (inside facet/f16.h's
 * domain).  ARMCOUNT_F16_ONLY: only the kernels with an f16 form, in f32,
 * f32_fast and f16 (bench/qcount/qcount.sh m55-f16). */
#include <stdint.h>
#include <stdio.h>
#include "facet.h"
#include "facet/fx.h"
#include "../../src/core/port.h"
#ifdef ARMCOUNT_F16
#include "facet/f16.h"
#include "../../src/core/f16_port.h"
#endif

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

#ifdef ARMCOUNT_F16
#define F16 CAT(facet_f16_port_, ARMCOUNT_F16)
static facet_f16 hin_[D_N][N], hout[N];
static const facet_f16 *hin[6];
/* each kernel's input domains, from kernels.def */
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    static const int dom_##name[] = { FACET_MAP_INPUTS(n, CLASS_, __VA_ARGS__) };
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
#define H_ARG_(q) hin[q]
static int has_f16(const char *name)
{
    const facet_f16_kernel *h = facet_f16_kernel_find(name);
    return h && h->f16;
}
#endif
#ifdef ARMCOUNT_F16_ONLY
#define WANT_(name) has_f16(#name)
#define FX_WANT_ 0
#else
#define WANT_(name) 1
#define FX_WANT_ 1
#endif

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
#ifdef ARMCOUNT_F16
            hin_[d][i] = facet_f16_from_f32(fin[d][i]);
#endif
        }
/* a kernel the port's table leaves NULL runs the tier's scalar loop (the
 * dispatcher's rule, src/core/dispatch.c): that is what the port executes */
#define CALL_(tab, fb, fmt, name, outp, ...) \
    armcount_begin(id); (tab.name ? tab.name : fb.name)(outp, __VA_ARGS__, N); armcount_end(id++); \
    printf("%s %s\n", fmt, #name);
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    if (WANT_(name)) { \
    CALL_(F32, facet_port_scalar_f32, "f32", name, out, FACET_MAP_INPUTS(n, F_ARG_, __VA_ARGS__)) \
    CALL_(F32_FAST, facet_port_scalar_f32_fast, "f32_fast", name, out, FACET_MAP_INPUTS(n, F_ARG_, __VA_ARGS__)) } \
    if (FX_WANT_) { \
    FACET_IF_PRECISE(fx_code, CALL_(FX, facet_fx_port_scalar, "fx", name, (fx_type *)(void *)qout, FACET_MAP_INPUTS(n, Q_ARG_, __VA_ARGS__))) \
    FACET_IF_FX(fx_type, CALL_(FX_FAST, facet_fx_fast_port_scalar, "fx_fast", name, (fx_type *)(void *)qout, FACET_MAP_INPUTS(n, Q_ARG_, __VA_ARGS__))) }
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
#ifdef ARMCOUNT_F16
    /* the binary16 table: its own (no scalar fallback: every f16 kernel has
     * a batch in every f16 table) */
#define FACET_F16(name, NAME, n, form, why)                                   \
    FACET_IF_F16(form, for (i = 0; i < n; i++) hin[i] = hin_[dom_##name[i]]; \
                 armcount_begin(id); F16.name(hout, FACET_EACH_INPUT(n, H_ARG_), N); armcount_end(id++); \
                 printf("f16 %s\n", #name);)
#include "../../src/core/f16_kernels.def"
#undef FACET_F16
#endif
#ifdef ARMCOUNT_F16
    printf("armcount: %g %llu %u\n", (double)out[0], (unsigned long long)qout[0], (unsigned)hout[0]);
#else
    printf("armcount: %g %llu\n", (double)out[0], (unsigned long long)qout[0]);
#endif
    return 0;
}
