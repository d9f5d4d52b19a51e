/* test_sample_prims.c - the samplers' building blocks and costs.
 *   - sincos_2pi on every 5th u = k 2^-24 in [0, 1) (every 61st under
 *     FACET_TEST_QUICK), every port and tier, against libm in double:
 *     absolute error <= FACET_ERR_SINCOS_2PI_F32, and relative error of the
 *     sine <= 2^-21 for u below 1/64 (the polynomial keeps it relative);
 *     sin^2 + cos^2 - 1 within 2^-22.
 *   - the operation count of every sampler body (the "Cost" of facet.h),
 *     counted like tests/f32/test_op_counts.c by instantiating the bodies on
 *     the counting op layer (tests/lib/op_count.h, its rules there); each
 *     must equal the Cost facet.h states. */
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <string.h>
#include <stdint.h>
#include "../lib/harness.h"
#include "facet.h"

#include "../lib/op_count.h"

#define FACET_V float
#define FACET_OP(op) cnt_##op
#define FACET_K(k) count_##k
#include "facet/detail/f32_body.h"
#include "facet/detail/f32_sample_body.h"
#undef FACET_V
#undef FACET_OP
#undef FACET_K

/* the "Cost:" facet.h states for a sampler: the first after " * <name>(" */
static int stated_cost(const char *name, long *ops, long *rsq, long *rcp)
{
    static char text[1 << 17];
    static size_t len;
    char key[64];
    const char *p, *c;
    if (!len) {
        FILE *f = fopen("include/facet.h", "r");
        if (!f)
            return 0;
        len = fread(text, 1, sizeof text - 1, f);
        fclose(f);
    }
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

#define COUNT(expr, name)                                                          \
    do {                                                                           \
        long o_, q_, r_;                                                           \
        cnt_reset();                                                               \
        expr;                                                                      \
        printf("%-24s %4ld ops (%ld rsqrt, %ld rcp)\n", name, n_ops, n_rsqrt, n_rcp); \
        if (stated_cost(name, &o_, &q_, &r_))                                      \
            CHECK(o_ == n_ops && q_ == n_rsqrt && r_ == n_rcp,                     \
                  "%s: facet.h says %ld ops (%ld rsqrt, %ld rcp), the body has %ld (%ld, %ld)", \
                  name, o_, q_, r_, n_ops, n_rsqrt, n_rcp);                        \
        else                                                                       \
            SKIP("%s: no Cost in include/facet.h (run from the source tree's top)", name); \
    } while (0)

static void op_counts(void)
{
    float h[3];
    COUNT(count_ggx_sample_d(&h[0], &h[1], &h[2], 0.3f, 0.6f, 0.2f), "ggx_sample_d");
    COUNT((void)count_ggx_pdf_d(0.9f, 0.2f), "ggx_pdf_d");
    COUNT(count_ggx_sample_vndf(&h[0], &h[1], &h[2], 0.3f, 0.2f, 0.9f, 0.3f, 0.6f, 0.2f), "ggx_sample_vndf");
    COUNT((void)count_ggx_pdf_vndf(0.9f, 0.95f, 0.8f, 0.2f), "ggx_pdf_vndf");
    COUNT((void)count_ggx_pdf_vndf_reflect(0.9f, 0.95f, 0.8f, 0.2f), "ggx_pdf_vndf_reflect");
    COUNT(count_reflect(&h[0], &h[1], &h[2], 0.3f, 0.2f, 0.9f, 0.1f, 0.1f, 0.99f), "reflect");
    COUNT(count_ggx_sample_d_aniso(&h[0], &h[1], &h[2], 0.3f, 0.6f, 0.2f, 0.4f), "ggx_sample_d_aniso");
    COUNT((void)count_ggx_pdf_d_aniso(0.1f, 0.1f, 0.99f, 0.2f, 0.4f), "ggx_pdf_d_aniso");
    COUNT(count_ggx_sample_vndf_aniso(&h[0], &h[1], &h[2], 0.3f, 0.2f, 0.9f, 0.3f, 0.6f, 0.2f, 0.4f), "ggx_sample_vndf_aniso");
    COUNT((void)count_ggx_pdf_vndf_aniso(0.3f, 0.2f, 0.9f, 0.1f, 0.1f, 0.99f, 0.2f, 0.4f), "ggx_pdf_vndf_aniso");
    COUNT(count_gtr_sample_d(&h[0], &h[1], &h[2], 0.3f, 0.6f, 0.2f, 1.0f), "gtr_sample_d");
    COUNT((void)count_gtr_pdf_d(0.9f, 0.2f, 1.0f), "gtr_pdf_d");
    COUNT(count_sincos_2pi(&h[0], &h[1], 0.3f), "sincos_2pi");
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
