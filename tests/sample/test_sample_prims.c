/* test_sample_prims.c - the samplers' building blocks and costs.
 *   - sincos_2pi on every 5th u = k 2^-24 in [0, 1) (every 61st under
 *     FACET_TEST_QUICK), every port and tier, against libm in double:
 *     absolute error <= FACET_ERR_SINCOS_2PI_F32, and relative error of the
 *     sine <= 2^-21 for u below 1/64 (the polynomial keeps it relative);
 *     sin^2 + cos^2 - 1 within 2^-22.
 *   - the operation count of every sampler body of the list
 *     (src/core/sample_kernels.def; the "Cost" of facet.h), counted like
 *     tests/f32/test_op_counts.c on the counting op layer
 *     (tests/lib/op_count.h: its rules); each must equal the Cost facet.h
 *     states. */
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <string.h>
#include <stdint.h>
#include "../lib/harness.h"
#include "../lib/op_count.h"

/* the "Cost:" facet.h states for a sampler: the first after " * <name>(";
 * 1 if found, 0 if facet.h has none for it, -1 if facet.h cannot be read
 * (the test runs from the source tree's top) */
static int stated_cost(const char *name, long *ops, long *rsq, long *rcp)
{
    static char text[1 << 18];
    static size_t len;
    static int unreadable;
    char key[64];
    const char *p, *c;
    if (!len && !unreadable) {
        FILE *f = fopen("include/facet.h", "r");
        if (f) {
            len = fread(text, 1, sizeof text - 1, f);
            unreadable = !feof(f); /* larger than the buffer: grow it */
            fclose(f);
        }
        unreadable |= !len;
    }
    if (unreadable)
        return -1;
    snprintf(key, sizeof key, " * %s(", name);
    p = strstr(text, key);
    if (!p || !(c = strstr(p, "Cost: ")))
        return 0;
    *rsq = *rcp = 0;
    *ops = atol(c + 6);
    if ((p = strstr(c, "ops (")) && p - c < 20)
        sscanf(p, "ops (%ld rsqrt, %ld rcp)", rsq, rcp);
    return 1;
}

/* one evaluation of a sampler body at inputs 1/2: a vec sampler writes
 * its outputs through pointers, a ret one returns its value */
#define SP_HALF_1 0.5f
#define SP_HALF_2 SP_HALF_1, 0.5f
#define SP_HALF_3 SP_HALF_2, 0.5f
#define SP_HALF_4 SP_HALF_3, 0.5f
#define SP_HALF_5 SP_HALF_4, 0.5f
#define SP_HALF_6 SP_HALF_5, 0.5f
#define SP_HALF_7 SP_HALF_6, 0.5f
#define SP_HALF_8 SP_HALF_7, 0.5f
#define SP_OUT_1 &o[0]
#define SP_OUT_2 SP_OUT_1, &o[1]
#define SP_OUT_3 SP_OUT_2, &o[2]
#define SP_CALL_vec(name, n_out, n_in) count_##name(SP_OUT_##n_out, SP_HALF_##n_in)
#define SP_CALL_ret(name, n_out, n_in) (void)count_##name(SP_HALF_##n_in)

static void count_one(const char *name)
{
    long o_ = 0, q_ = 0, r_ = 0;
    int got = stated_cost(name, &o_, &q_, &r_);
    printf("%-24s %4ld ops (%ld rsqrt, %ld rcp)\n", name, n_ops, n_rsqrt, n_rcp);
    if (got < 0)
        SKIP("%s: include/facet.h not readable here (run from the source tree's top)", name);
    else if (!got)
        CHECK(0, "%s: its contract in include/facet.h states no Cost", name);
    else
        CHECK(o_ == n_ops && q_ == n_rsqrt && r_ == n_rcp,
              "%s: facet.h says %ld ops (%ld rsqrt, %ld rcp), the body has %ld (%ld, %ld)", name, o_, q_, r_, n_ops,
              n_rsqrt, n_rcp);
}

static void op_counts(void)
{
    float o[FACET_SAMPLER_MAX_OUTPUTS];
#define FACET_SAMPLER(name, NAME, kind, err, n_out, n_in, outputs, inputs) \
    opc_reset();                                                         \
    SP_CALL_##kind(name, n_out, n_in);                                   \
    count_one(#name);
#include "../../src/core/sample_kernels.def"
#undef FACET_SAMPLER
    (void)o;
}

int main(void)
{
    long step = getenv("FACET_TEST_QUICK") ? 61 : 5, n = 0, k;
    size_t pi;
    float *u, *s, *c;
    th_name = "sample_prims";
    op_counts();
    u = malloc(((1L << 24) / step + 1) * sizeof(float));
    s = malloc(((1L << 24) / step + 1) * sizeof(float));
    c = malloc(((1L << 24) / step + 1) * sizeof(float));
    for (k = 0; k < (1L << 24); k += step)
        u[n++] = (float)k * 0x1p-24f;
    for (pi = 0; pi < facet_port_count(); pi++) {
        int sup, tier;
        const char *pn = facet_port_at(pi, &sup, NULL);
        if (!sup)
            continue;
        facet_set_port(pn);
        for (tier = 0; tier < 2; tier++) {
            double worst = 0, worst_rel = 0, worst_len = 0;
            float wu = 0;
            (tier ? facet_sincos_2pi_f32_fast_batch : facet_sincos_2pi_f32_batch)(s, c, u, (size_t)n);
            for (k = 0; k < n; k++) {
                double p = 2 * M_PI * u[k], es = s[k] - sin(p), ec = c[k] - cos(p);
                double e = sqrt(es * es + ec * ec), len = fabs((double)s[k] * s[k] + (double)c[k] * c[k] - 1);
                if (e > worst) {
                    worst = e;
                    wu = u[k];
                }
                if (u[k] > 0 && u[k] < 1.0f / 64 && fabs(es / sin(p)) > worst_rel)
                    worst_rel = fabs(es / sin(p));
                if (len > worst_len)
                    worst_len = len;
            }
            printf("sincos_2pi %-7s %-4s: max error 2^%.2f at u = %.9g, sine relative (u < 1/64) 2^%.2f, "
                   "|sin^2 + cos^2 - 1| 2^%.2f, %ld values\n", pn, tier ? "fast" : "f32", log2(worst), wu,
                   log2(worst_rel), log2(worst_len), n);
            CHECK(worst <= FACET_ERR_SINCOS_2PI_F32, "sincos_2pi on %s: error 2^%.2f", pn, log2(worst));
            CHECK(worst_rel <= 0x1p-21, "sincos_2pi on %s: sine relative error 2^%.2f near 0", pn, log2(worst_rel));
            CHECK(worst_len <= 0x1p-22, "sincos_2pi on %s: sin^2 + cos^2 - 1 = 2^%.2f", pn, log2(worst_len));
        }
    }
    facet_set_port("auto");
    free(u);
    free(s);
    free(c);
    return th_done();
}
