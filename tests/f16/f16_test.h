/* f16_test.h - shared by the f16 tests: the f16 ports this build has, the
 * domain clamp of facet/f16.h on doubles, the error measure, and inputs. */
#ifndef FACET_F16_TEST_H
#define FACET_F16_TEST_H

#include <string.h>
#include <math.h>
#include "facet.h"
#include "facet/f16.h"
#include "../lib/sample.h"

/* the f16 tables are reached through the f32 port that carries them
 * (src/core/ports.def's f16 column): scalar, avx512 for avx512fp16, neon
 * for neonfp16, helium for heliumfp16 */
typedef struct { const char *f16, *via; } f16t_port;
static const f16t_port f16t_ports[] = { { "scalar", "scalar" }, { "avx512fp16", "avx512" }, { "neonfp16", "neon" },
                                        { "heliumfp16", "helium" } };
#define F16T_N_PORTS (sizeof f16t_ports / sizeof f16t_ports[0])

/* select port j for the f16 batches; 0 if this build or CPU cannot */
static inline int f16t_use(size_t j)
{
    if (!facet_f16_port_supported(f16t_ports[j].f16))
        return 0;
    if (facet_set_port(f16t_ports[j].via) != 0)
        return 0;
    return !strcmp(facet_f16_port_name(), f16t_ports[j].f16);
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
