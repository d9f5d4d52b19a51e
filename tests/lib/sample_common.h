/* sample_common.h - input generators for the samplers' tests
 * (tests/test_sample_*.c), on top of sample.h's PRNG. */
#ifndef FACET_TEST_SAMPLE_COMMON_H
#define FACET_TEST_SAMPLE_COMMON_H

#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "sample.h"

/* a float uniform in [0, 1) on the 2^-24 grid (what a caller's 24-bit
 * generator gives) */
static float ss_u24(smp_rng *r) { return (float)(smp_next(r) >> 40) * 0x1p-24f; }

/* u for accuracy sweeps: uniform, or near the ends and the fold points */
static float ss_u(smp_rng *r)
{
    static const double pts[] = { 0.0, 0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1.0 };
    double d;
    switch (smp_next(r) % 8) {
    case 0: return 0.0f;
    case 1: return 0x1.fffffep-1f;
    case 2: return (float)smp_log2u(r, -24, -1);
    case 3: return (float)(1.0 - smp_log2u(r, -24, -1));
    case 4:
        d = pts[smp_next(r) % 9] + (smp_u01(r) - 0.5) * smp_log2u(r, -24, -6);
        return (float)fmin(fmax(d, 0.0), 0x1.fffffep-1);
    default: return ss_u24(r);
    }
}

/* a unit vector with z >= 0: uniform, near the pole, or grazing */
static void ss_dir(smp_rng *r, float v[3])
{
    double z, s, p = 2 * M_PI * smp_u01(r);
    switch (smp_next(r) % 6) {
    case 0: z = 1.0 - smp_log2u(r, -40, -2); break;
    case 1: z = smp_log2u(r, -24, -2); break;
    case 2: z = (smp_next(r) & 1) ? 0.0 : 1.0; break;
    default: z = smp_u01(r); break;
    }
    s = sqrt(fmax(0.0, (1.0 - z) * (1.0 + z)));
    v[0] = (float)(s * cos(p));
    v[1] = (float)(s * sin(p));
    v[2] = (float)z;
}

/* one in-domain sample for a sampler, by its input names */
static void ss_inputs(smp_rng *r, const facet_sampler *k, float *in)
{
    float v[3], h[3];
    int i;
    ss_dir(r, v);
    ss_dir(r, h);
    for (i = 0; i < k->n_inputs; i++) {
        const char *n = k->inputs[i];
        if (!strcmp(n, "u1") || !strcmp(n, "u2") || !strcmp(n, "u")) in[i] = ss_u(r);
        else if (!strncmp(n, "alpha", 5)) in[i] = smp_alpha(r);
        else if (!strcmp(n, "gamma")) in[i] = (smp_next(r) & 1) ? 1.0f : 2.0f;
        else if (n[0] == 'v' && n[1] && !n[2]) in[i] = v[n[1] - 'x'];
        else if (n[0] == 'h' && n[1] && !n[2]) in[i] = h[n[1] - 'x'];
        else if (!strcmp(n, "noh")) in[i] = (smp_next(r) & 1) ? smp_unit(r) : (float)(1.0 - smp_log2u(r, -24, -4));
        else in[i] = smp_unit(r);
    }
}

/* The index of the input called name, or -1. */
static inline int ss_input_index(const facet_sampler *k, const char *name)
{
    return smp_name_index(k->inputs, k->n_inputs, name);
}

/* The error measure of the samplers' contracts (facet.h), shared by
 * tests/sample/test_sample_accuracy.c and the bench (bench/harness/bench.c).
 * The conditioning of a sampler at x: K = sum over its inputs of
 * |h(x + d_i) - h(x)| / 2^-24 (oracle), d_i one step of 2^-24 for u1, u2
 * (inward at the ends) and of 2^-24 |x_i| for the other inputs: how far the
 * exact map moves when one input moves by about an ulp.  The error measure
 * of a sampled vector is |h - h_oracle| / max(1, K / 16): the plain distance
 * where the map is well-conditioned (K < 16: everywhere but near the rims),
 * relative to K where it is not (the VNDF map near the cap rim, where
 * Vh + c is short, moves by O(1) for one ulp of u1).  x holds
 * FACET_SAMPLER_MAX_INPUTS values. */
static inline double ss_sampler_cond(const facet_sampler *k, const double *x, const double *h0)
{
    double y[FACET_SAMPLER_MAX_INPUTS], h[FACET_SAMPLER_MAX_OUTPUTS], K = 0;
    int i, o;
    for (i = 0; i < k->n_inputs; i++) {
        double d;
        if (!strcmp(k->inputs[i], "gamma"))
            continue;
        memcpy(y, x, sizeof y);
        if (k->inputs[i][0] == 'u')
            d = x[i] >= 0.5 ? -0x1p-24 : 0x1p-24;
        else
            d = x[i] * 0x1p-24;
        y[i] = x[i] + d;
        k->oracle(h, y);
        for (o = 0; o < k->n_outputs; o++)
            K += fabs(h[o] - h0[o]) / 0x1p-24;
    }
    return K;
}

/* The conditioning of v.h for the pdfs that form it from the vectors:
 * sum |v_i h_i| / |v.h| (1 where all terms have one sign). */
static inline double ss_dot_cond(const facet_sampler *k, const float *const *in, long j)
{
    int v = ss_input_index(k, "vx"), h = ss_input_index(k, "hx"), i;
    double s = 0, a = 0;
    if (v < 0 || h < 0)
        return 1;
    for (i = 0; i < 3; i++) {
        double t = (double)in[v + i][j] * in[h + i][j];
        s += t;
        a += fabs(t);
    }
    return s != 0 ? fmax(1.0, a / fabs(s)) : 1.0;
}

#endif
