/* test_sample_accuracy.c - every sampler and pdf (facet.h, "GGX and GTR
 * importance sampling") against the oracle at the same float inputs, on
 * every port this CPU runs, both tiers: sampled vectors by Euclidean
 * distance, pdfs by relative error.  Also: every sampled h is unit with
 * h.z > 0; the scalar entry points equal the scalar port's batch; pdf_d is
 * ggx_d * N.H to the bit; gtr with gamma = 2 is ggx_sample_d to the bit;
 * pdf_vndf agrees with G1 D V.H / N.V from facet's smith_g1 and ggx_d.
 * Prints the measured table.  FACET_TEST_QUICK=1 cuts the sample count. */
#include <stdio.h>
#include <stdlib.h>
#include <float.h>
#include "../lib/harness.h"
#include "../lib/sample_common.h"
#include "facet/oracle.h"

#define NOUT FACET_SAMPLER_MAX_OUTPUTS
#define NIN FACET_SAMPLER_MAX_INPUTS

static int is_sampler(const facet_sampler *k) { return strstr(k->name, "sample") != NULL; }

static int same(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : getenv("FACET_TEST_QUICK") ? 20000 : 200000;
    size_t ki, pi, n_ports = facet_port_count();
    th_name = "sample_accuracy";
    printf("%-24s %-7s %-5s %10s %8s  %s\n", "sampler", "port", "kind", "max err", "log2",
           "argmax (inputs) -> got / oracle");
    for (ki = 0; ki < facet_sampler_count(); ki++) {
        const facet_sampler *k = facet_sampler_at(ki);
        float *in[NIN], *out[NOUT];
        double *want[NOUT], *cond;
        smp_rng rng;
        long j;
        int i, tier;
        rng.s = 0x5a3b1e00u + ki;
        for (i = 0; i < k->n_inputs; i++)
            in[i] = malloc(n * sizeof(float));
        for (i = 0; i < k->n_outputs; i++) {
            out[i] = malloc(n * sizeof(float));
            want[i] = malloc(n * sizeof(double));
        }
        cond = malloc(n * sizeof(double));
        for (j = 0; j < n; j++) {
            float x[NIN];
            double xd[NIN], o[NOUT];
            ss_inputs(&rng, k, x);
            for (i = 0; i < k->n_inputs; i++) {
                in[i][j] = x[i];
                xd[i] = x[i];
            }
            k->oracle(o, xd);
            for (i = 0; i < k->n_outputs; i++)
                want[i][j] = o[i];
            cond[j] = k->err_abs ? fmax(1.0, ss_sampler_cond(k, xd, o) / 16) : 1.0;
        }
        if (!k->err_abs)
            for (j = 0; j < n; j++)
                cond[j] = ss_dot_cond(k, (const float *const *)in, j);
        for (tier = 0; tier < 2; tier++) {
            double bound = tier ? k->err_f32_fast : k->err_f32;
            for (pi = 0; pi < n_ports; pi++) {
                int sup, ftz;
                const char *pn = facet_port_at(pi, &sup, NULL);
                double worst = 0, wg[NOUT] = { 0 }, ww[NOUT] = { 0 }, max_len = 0;
                long wj = 0, bad_unit = 0, bad_z = 0;
                if (!sup)
                    continue;
                CHECK(facet_set_port(pn) == 0, "cannot select port %s", pn);
                ftz = smp_port_flushes_denormals();
                (tier ? k->f32_fast_batch : k->f32_batch)(out, (const float *const *)in, (size_t)n);
                for (j = 0; j < n; j++) {
                    double e = 0;
                    if (k->err_abs) {
                        double l2 = 0;
                        for (i = 0; i < k->n_outputs; i++) {
                            double d = out[i][j] - want[i][j];
                            e += d * d;
                            l2 += (double)out[i][j] * out[i][j];
                        }
                        e = sqrt(e) / cond[j];
                        if (is_sampler(k)) {
                            if (fabs(sqrt(l2) - 1) > max_len)
                                max_len = fabs(sqrt(l2) - 1);
                            if (fabs(sqrt(l2) - 1) > 0x1p-22)
                                bad_unit++;
                            if (!(out[2][j] > 0))
                                bad_z++;
                        }
                    } else {
                        double w = want[0][j], g = out[0][j];
                        double fl = ftz ? SMP_ERR_FLOOR_FTZ : SMP_ERR_FLOOR;
                        e = (fabs(w) < fl ? fabs(g - w) / fl : fabs(g - w) / fabs(w)) / cond[j];
                        if (!(g == g))
                            e = INFINITY;
                    }
                    if (!(e <= worst)) {
                        worst = e;
                        wj = j;
                        for (i = 0; i < k->n_outputs; i++) {
                            wg[i] = out[i][j];
                            ww[i] = want[i][j];
                        }
                    }
                }
                printf("%-24s %-7s %-5s %10.3g %8.2f  (", tier ? "" : k->name, pn,
                       tier ? "fast" : "f32", worst, worst > 0 ? log2(worst) : -999.0);
                for (i = 0; i < k->n_inputs; i++)
                    printf("%s%.9g", i ? ", " : "", in[i][wj]);
                printf(") cond %.3g ->", cond[wj]);
                for (i = 0; i < k->n_outputs; i++)
                    printf(" %.9g/%.12g", wg[i], ww[i]);
                printf("\n");
                CHECK(worst <= bound, "%s%s on %s: max error %.3g (2^%.2f) exceeds the bound 2^%.2f",
                      k->name, tier ? " (fast)" : "", pn, worst, log2(worst), log2(bound));
                CHECK(bad_unit == 0 && bad_z == 0, "%s%s on %s: %ld not unit (max ||h| - 1| %.3g), %ld with h.z <= 0",
                      k->name, tier ? " (fast)" : "", pn, bad_unit, max_len, bad_z);
            }
        }
        for (i = 0; i < k->n_inputs; i++)
            free(in[i]);
        for (i = 0; i < k->n_outputs; i++) {
            free(out[i]);
            free(want[i]);
        }
        free(cond);
    }
    /* shared terms to the bit, every port: pdf_d = fl(ggx_d(noh) noh);
     * gtr_sample_d with gamma = 2 is ggx_sample_d; the scalar entry points
     * are the scalar port's batch */
    for (pi = 0; pi < n_ports; pi++) {
        int sup, tier;
        const char *pn = facet_port_at(pi, &sup, NULL);
        enum { M = 4099 };
        static float noh[M], al[M], u1[M], u2[M], g2[M], d[M], p[M], h[3][M], q[3][M];
        long bad_pdf = 0, bad_gtr = 0, bad_scalar = 0;
        smp_rng rng = { 99 };
        int j;
        if (!sup)
            continue;
        facet_set_port(pn);
        for (j = 0; j < M; j++) {
            noh[j] = (j & 1) ? smp_unit(&rng) : (float)(1.0 - smp_log2u(&rng, -24, -4));
            al[j] = smp_alpha(&rng);
            u1[j] = ss_u(&rng);
            u2[j] = ss_u(&rng);
            g2[j] = 2.0f;
        }
        for (tier = 0; tier < 2; tier++) {
            (tier ? facet_ggx_d_f32_fast_batch : facet_ggx_d_f32_batch)(d, noh, al, M);
            (tier ? facet_ggx_pdf_d_f32_fast_batch : facet_ggx_pdf_d_f32_batch)(p, noh, al, M);
            (tier ? facet_ggx_sample_d_f32_fast_batch : facet_ggx_sample_d_f32_batch)(h[0], h[1], h[2], u1, u2, al, M);
            (tier ? facet_gtr_sample_d_f32_fast_batch : facet_gtr_sample_d_f32_batch)(q[0], q[1], q[2], u1, u2, al, g2, M);
            for (j = 0; j < M; j++) {
                float c = noh[j] < 0 ? 0 : noh[j] > 1 ? 1 : noh[j];
                bad_pdf += !same(p[j], d[j] * c);
                bad_gtr += !same(h[0][j], q[0][j]) || !same(h[1][j], q[1][j]) || !same(h[2][j], q[2][j]);
                if (!strcmp(pn, "scalar")) {
                    float s[3];
                    (tier ? facet_ggx_sample_d_f32_fast : facet_ggx_sample_d_f32)(s, u1[j], u2[j], al[j]);
                    bad_scalar += !same(s[0], h[0][j]) || !same(s[1], h[1][j]) || !same(s[2], h[2][j]);
                    bad_scalar += !same((tier ? facet_ggx_pdf_d_f32_fast : facet_ggx_pdf_d_f32)(noh[j], al[j]), p[j]);
                }
            }
            CHECK(bad_pdf == 0, "%s%s: ggx_pdf_d != ggx_d * noh in %ld cases", pn, tier ? " fast" : "", bad_pdf);
            CHECK(bad_gtr == 0, "%s%s: gtr_sample_d(gamma 2) != ggx_sample_d in %ld cases", pn, tier ? " fast" : "", bad_gtr);
            CHECK(bad_scalar == 0, "%s%s: scalar entry points != scalar batch in %ld cases", pn, tier ? " fast" : "", bad_scalar);
        }
    }
    /* pdf_vndf = G1 D V.H / N.V from facet's own smith_g1 and ggx_d, within
     * the sum of the three bounds, every port and tier (N.V >= 2^-20: below
     * that G1 / N.V is formed from G1's rounding, the pdf from the limit) */
    for (pi = 0; pi < n_ports; pi++) {
        int sup, tier;
        const char *pn = facet_port_at(pi, &sup, NULL);
        enum { M = 20000 };
        static float nv[M], nh[M], vh[M], al[M], p[M], g1[M], d[M];
        smp_rng rng = { 31337 };
        int j;
        if (!sup)
            continue;
        facet_set_port(pn);
        for (j = 0; j < M; j++) {
            nv[j] = (float)((j & 3) ? smp_u01(&rng) : smp_log2u(&rng, -20, 0));
            nh[j] = (j & 1) ? smp_unit(&rng) : (float)(1.0 - smp_log2u(&rng, -24, -4));
            vh[j] = (float)smp_u01(&rng);
            al[j] = smp_alpha(&rng);
        }
        for (tier = 0; tier < 2; tier++) {
            double worst = 0, bound = tier ? FACET_ERR_GGX_PDF_VNDF_F32_FAST + FACET_ERR_SMITH_G1_F32_FAST + FACET_ERR_GGX_D_F32_FAST
                                           : FACET_ERR_GGX_PDF_VNDF_F32 + FACET_ERR_SMITH_G1_F32 + FACET_ERR_GGX_D_F32;
            (tier ? facet_ggx_pdf_vndf_f32_fast_batch : facet_ggx_pdf_vndf_f32_batch)(p, nv, nh, vh, al, M);
            (tier ? facet_smith_g1_f32_fast_batch : facet_smith_g1_f32_batch)(g1, nv, al, M);
            (tier ? facet_ggx_d_f32_fast_batch : facet_ggx_d_f32_batch)(d, nh, al, M);
            for (j = 0; j < M; j++) {
                double want = (double)g1[j] * d[j] * vh[j] / nv[j];
                double e = want > 0 ? fabs(p[j] - want) / want : fabs(p[j]);
                if (e > worst)
                    worst = e;
            }
            printf("pdf_vndf vs smith_g1 * ggx_d * voh / nov on %-7s %-4s: max relative difference 2^%.2f\n", pn,
                   tier ? "fast" : "f32", log2(worst));
            CHECK(worst <= bound, "%s%s: pdf_vndf differs from G1 D V.H / N.V by 2^%.2f (bound 2^%.2f)", pn,
                  tier ? " fast" : "", log2(worst), log2(bound));
        }
    }
    (void)smp_inputs;
    facet_set_port("auto");
    return th_done();
}
