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

#endif
