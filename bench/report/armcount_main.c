/* armcount_main.c - every kernel's batch function of one vector port, in
 * each tier the port runs (f32, f32_fast, fx, fx_fast), one call of N
 * samples between two marker calls, for counting executed instructions
 * under qemu (bench/report/arm_targets.sh cuts the trace at the markers).
 * The port's tables are called directly (src/core/port.h), so the dispatcher's
 * pointer load is not counted.  Prints one "FORMAT KERNEL" line per counted
 * call, in call order.  ARMCOUNT_PORT names the port (helium).
 *
 * Binary16 (format f16): the f16 table the port's line of
 * src/core/ports.def names in its f16 column (where its guard holds on
 * this target), found in the port list at run time, so a port that gains
 * an f16 table is counted with no change here; the line
 * "armcount-f16: TABLE" says which ("none": the line runs the scalar f16
 * table, i.e. the port has no f16 code of its own, and nothing is
 * counted).  Inputs: the same values as binary16 bits.
 * ARMCOUNT_F16_ONLY: only the kernels with an f16 form, in f32, f32_fast
 * and f16 (bench/qcount/qcount.sh m55-f16). */
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "facet.h"
#include "facet/fx.h"
#include "../../src/core/port.h"
#include "../../src/core/platform.h"
#include "../../src/core/f16_port.h"
#include "facet/f16.h"

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
static uint16_t hin[D_N][N], hout[N];
static int id;

/* every kernel's inputs' domain classes, by the kernel's place in kernels.def */
enum {
#define FACET_KERNEL(name, ...) K_##name,
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
    K_N
};
#define DOM_(input, domain) D_##domain
static const unsigned char kdom[K_N][6] = {
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    { FACET_MAP_INPUTS(n, DOM_, __VA_ARGS__) },
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
};

/* the port lines compiled for this target and the f16 table each runs */
#define STR_(x) #x
#define STR(x) STR_(x)
static const struct { const char *port; const facet_f16_port *f16; } f16_lines[] = {
#define FACET_PORT(name, guard, cpu, fx, fx_fast, f16, f16_cpu) FACET_PORT_IF(guard, { #name, &facet_f16_port_##f16 },)
#include "../../src/core/ports.def"
#undef FACET_PORT
};

/* binary16 bits of x (|x| in [2^-14, 1] or 0; truncated: any in-domain value will do) */
static uint16_t h_of(float x)
{
    uint32_t b, s;
    int e;
    memcpy(&b, &x, sizeof b);
    s = (b >> 16) & 0x8000u;
    e = (int)((b >> 23) & 255u) - 127 + 15;
    return (uint16_t)(e <= 0 ? s : s | (uint32_t)e << 10 | (b & 0x7fffffu) >> 13);
}

#define CLASS_(input, domain) D_##domain
#define F_ARG_(input, domain) fin[D_##domain]
#define Q_ARG_(input, domain) qin[D_##domain]

#ifdef ARMCOUNT_F16_ONLY
static int has_f16(const char *name)
{
    const facet_f16_kernel *k = facet_f16_kernel_find(name);
    return k && k->f16;
}
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
    {
        const facet_f16_port *h = NULL;
        const uint16_t *hp[6];
        size_t l;
        int q;
        for (l = 0; l < sizeof f16_lines / sizeof f16_lines[0] && !h; l++)
            if (!strcmp(f16_lines[l].port, STR(ARMCOUNT_PORT)))
                h = f16_lines[l].f16;
        if (h == &facet_f16_port_scalar)
            h = NULL;
        printf("armcount-f16: %s\n", h ? h->name : "none");
        for (d = 0; d < D_N; d++)
            for (i = 0; i < N; i++)
                hin[d][i] = h_of(fin[d][i]);
#define HP_(q) hp[q]
#define FACET_F16(name, NAME, n, form, why)                                                    \
        FACET_IF_F16(form, if (h) {                                                           \
            for (q = 0; q < n; q++)                                                           \
                hp[q] = hin[kdom[K_##name][q]];                                               \
            armcount_begin(id); h->name(hout, FACET_EACH_INPUT(n, HP_), N); armcount_end(id++); \
            printf("f16 %s\n", #name);                                                        \
        })
#include "../../src/core/f16_kernels.def"
#undef FACET_F16
    }
    printf("armcount: %g %llu %u\n", (double)out[0], (unsigned long long)qout[0], (unsigned)hout[0]);
    return 0;
}
