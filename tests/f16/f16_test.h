/* f16_test.h - shared by the f16 tests: the f16 ports this build has, the
 * domain clamp of facet/f16.h on doubles, the error measure, and inputs.
 *
 * FACET_TEST_F16_FORCE=<table> (read here, by the tests, never by the
 * library): run that f16 table even where the dispatcher refuses it, by
 * calling the table itself (src/core/f16_port.h) instead of the dispatched
 * batches.  For a table whose CPU test cannot see its feature under the
 * emulator that does run it (rvvfp16: qemu-user 7.2 has no riscv_hwprobe,
 * so Zvfh is never detected there, yet -cpu rv64,v=true,Zfh=true executes
 * the binary16 vector instructions); tests/suites/54-rvv.sh sets it.  A
 * name that this build has no table of fails the test (f16t_force_check). */
#ifndef FACET_F16_TEST_H
#define FACET_F16_TEST_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "facet.h"
#include "facet/f16.h"
#include "../lib/harness.h"
#include "../lib/sample.h"
#include "../../src/core/platform.h"
#include "../../src/core/f16_port.h"

/* the f16 tables are reached through the f32 port that carries them
 * (src/core/ports.def's f16 column): scalar, avx512 for avx512fp16, neon
 * for neonfp16, helium for heliumfp16, rvv for rvvfp16 */
typedef struct { const char *f16, *via; } f16t_port;
static const f16t_port f16t_ports[] = { { "scalar", "scalar" }, { "avx512fp16", "avx512" }, { "neonfp16", "neon" },
                                        { "heliumfp16", "helium" }, { "rvvfp16", "rvv" } };
#define F16T_N_PORTS (sizeof f16t_ports / sizeof f16t_ports[0])

/* the f16 table called name in this build (the f16 column of the
 * src/core/ports.def lines whose guard holds), or NULL */
static inline const facet_f16_port *f16t_table(const char *name)
{
    static const facet_f16_port *const t[] = {
#define FACET_PORT(pn, guard, cpu, fx, fx_fast, f16, f16_cpu) FACET_PORT_IF(guard, &facet_f16_port_##f16,)
#include "../../src/core/ports.def"
#undef FACET_PORT
    };
    size_t i;
    for (i = 0; name && i < sizeof t / sizeof t[0]; i++)
        if (!strcmp(t[i]->name, name))
            return t[i];
    return NULL;
}

/* the table FACET_TEST_F16_FORCE names for port j, where the dispatcher
 * refuses it (else NULL: the dispatched batches run it, or nothing does) */
static inline const facet_f16_port *f16t_forced(size_t j)
{
    const char *f = getenv("FACET_TEST_F16_FORCE");
    if (!f || strcmp(f, f16t_ports[j].f16) || facet_f16_port_supported(f))
        return NULL;
    return f16t_table(f);
}

/* a FACET_TEST_F16_FORCE that names no table of this build fails: a run
 * told to exercise a port must not pass without it */
static inline void f16t_force_check(void)
{
    const char *f = getenv("FACET_TEST_F16_FORCE");
    size_t j;
    int known = 0;
    if (!f)
        return;
    for (j = 0; j < F16T_N_PORTS; j++)
        known |= !strcmp(f, f16t_ports[j].f16);
    CHECK(known && f16t_table(f), "FACET_TEST_F16_FORCE=%s: no such f16 table in this build", f);
    if (known && f16t_table(f) && !facet_f16_port_supported(f))
        printf("port %s: forced by FACET_TEST_F16_FORCE (the dispatcher refuses it: %s)\n", f,
               facet_f16_port_refusal(f) ? facet_f16_port_refusal(f) : "?");
}

/* select port j for the f16 batches; 0 if this build or CPU cannot (a
 * forced table: 1, and f16t_batch calls it) */
static inline int f16t_use(size_t j)
{
    if (f16t_forced(j))
        return 1;
    if (!facet_f16_port_supported(f16t_ports[j].f16))
        return 0;
    if (facet_set_port(f16t_ports[j].via) != 0)
        return 0;
    return !strcmp(facet_f16_port_name(), f16t_ports[j].f16);
}

/* kernel h's batch on port j (after f16t_use(j)): the dispatched batch, or
 * the forced table's function of that kernel */
static inline void f16t_batch(const facet_f16_kernel *h, size_t j, facet_f16 *out, const facet_f16 *const *in,
                              size_t n)
{
    const facet_f16_port *t = j < F16T_N_PORTS ? f16t_forced(j) : NULL;
    if (!t) {
        h->f16_batch(out, in, n);
        return;
    }
#define F16T_IN_(q) in[q]
#define FACET_F16(kn, NAME, ar, form, why) \
    FACET_IF_F16(form, if (!strcmp(h->name, #kn)) { t->kn(out, FACET_EACH_INPUT(ar, F16T_IN_), n); return; })
#include "../../src/core/f16_kernels.def"
#undef FACET_F16
#undef F16T_IN_
    CHECK(0, "%s: not in the forced table %s", h->name, t->name);
}

/* the domain of input i (facet/f16.h) */
static inline void f16t_domain(const char *name, double *lo, double *hi)
{
    *hi = 1.0;
    if (!strcmp(name, "lov") || !strcmp(name, "toh") || !strcmp(name, "boh")) *lo = -1.0;
    else if (!strncmp(name, "alpha", 5)) *lo = FACET_F16_ALPHA_MIN; /* alpha, alpha_x, alpha_y */
    else if (!strcmp(name, "nol") || !strcmp(name, "nov")) *lo = FACET_F16_COS_MIN;
    else *lo = 0.0;
}

static inline double f16t_clamp(const char *name, double x)
{
    double lo, hi;
    f16t_domain(name, &lo, &hi);
    return !(x > lo) ? lo : x < hi ? x : hi;
}

/* the error measure of facet/f16.h: relative to max(|want|, 2^-14), and
 * against min(want, 65504) (saturation) */
static inline double f16t_err(double got, double want)
{
    double w = want < FACET_F16_MAX ? want : FACET_F16_MAX;
    double d = fabs(got - w), m = fabs(w) > 0x1p-14 ? fabs(w) : 0x1p-14;
    return d / m;
}

/* one in-domain sample as binary16 bits: the f32 tests' generator (the
 * peak, grazing angles, L.V near +-1, ...) rounded to binary16, and 1 in 4
 * the cosines and alpha aimed at binary16's floors */
static inline void f16t_inputs(smp_rng *r, const facet_kernel *k, facet_f16 *in)
{
    float f[FACET_MAX_INPUTS];
    int i;
    smp_inputs(r, k, f);
    for (i = 0; i < k->n_inputs; i++) {
        const char *n = k->inputs[i];
        if ((smp_next(r) & 3) == 0 && (!strcmp(n, "nol") || !strcmp(n, "nov") || !strncmp(n, "alpha", 5)))
            f[i] = (float)smp_log2u(r, -7.5, -5);
        in[i] = facet_f16_from_f32(f[i]);
    }
}

#endif
