/* test_f32_bad_input.c - the domain contract of facet.h for every kernel:
 * each bad value in each input position (others random and valid) gives a
 * finite, non-negative result, bit-equal to the kernel evaluated at the
 * documented substitute (NaN, -Inf, below-domain -> the low end; +Inf,
 * above-domain -> the high end).  Also the named special points. */
#include <stdio.h>
#include <stdlib.h>
#include <float.h>
#include "harness.h"
#include "sample.h"
#include "facet/oracle.h"

static int same(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

int main(void)
{
    const float bad[] = { NAN, -NAN, INFINITY, -INFINITY, 0.0f, -0.0f, 1.4e-45f, -1.4e-45f,
                          1e-39f, -1e-30f, -1.0f, -2.0f, 1.0000001f, 2.0f, 1e30f, FLT_MAX, -FLT_MAX };
    const int n_bad = (int)(sizeof bad / sizeof bad[0]);
    smp_rng rng = { 12345 };
    size_t ki;
    th_name = "f32_bad_input";

    for (ki = 0; ki < 2 * facet_kernel_count(); ki++) {
        /* every kernel in both tiers: f32, then f32_fast */
        const facet_kernel *k = facet_kernel_at(ki % facet_kernel_count());
        float (*f)(const float *) = ki < facet_kernel_count() ? k->f32 : k->f32_fast;
        const char *tier = ki < facet_kernel_count() ? "" : " (f32_fast)";
        int pos, b, rep, nan_out = 0, neg_out = 0, mismatch = 0;
        for (rep = 0; rep < 50; rep++)
            for (pos = 0; pos < k->n_inputs; pos++)
                for (b = 0; b < n_bad; b++) {
                    float in[FACET_MAX_INPUTS], ref_in[FACET_MAX_INPUTS], got, want;
                    float lo = smp_domain_lo(k, pos), hi = smp_domain_hi(k, pos), v = bad[b];
                    smp_inputs(&rng, k, in);
                    memcpy(ref_in, in, sizeof in);
                    in[pos] = v;
                    /* the documented substitute */
                    ref_in[pos] = (v != v || v < lo) ? lo : v > hi ? hi : v;
                    got = f(in);
                    want = f(ref_in);
                    if (!(got == got) || got == INFINITY || got == -INFINITY)
                        nan_out++;
                    else if (got < 0.0f || same(got, -0.0f))
                        neg_out++;
                    if (!same(got, want))
                        mismatch++;
                    /* every bad input, also in all positions at once */
                    if (rep == 0 && pos == 0) {
                        int j;
                        for (j = 0; j < k->n_inputs; j++)
                            in[j] = v;
                        got = f(in);
                        if (!(got == got) || got > FLT_MAX || got < 0.0f)
                            nan_out++;
                    }
                }
        CHECK(nan_out == 0, "%s%s: %d bad inputs gave NaN or Inf", k->name, tier, nan_out);
        CHECK(neg_out == 0, "%s%s: %d bad inputs gave a negative result", k->name, tier, neg_out);
        CHECK(mismatch == 0, "%s%s: %d bad inputs differ from the documented clamped value", k->name, tier,
              mismatch);
    }

    /* named points of the contracts */
    {
        float a, d;
        CHECK(facet_loh_from_dots_f32(-1.0f) == 0.0f, "L.V = -1 gives L.H = 0");
        CHECK(facet_loh_from_dots_f32(1.0f) == 1.0f, "L.V = 1 gives L.H = 1");
        CHECK(facet_noh_from_dots_f32(0.0f, 0.0f, -1.0f) == 1.0f,
              "L = -V at the horizon: N.H = 1 (cos floor, t raised)");
        CHECK(facet_noh_from_dots_f32(1.0f, 1.0f, 1.0f) == 1.0f, "L = V = N: N.H = 1");
        CHECK(facet_noh_from_dots_f32(1.0f, 1.0f, -1.0f) == 1.0f, "inconsistent triple: N.H capped at 1");
        for (a = FACET_ALPHA_MIN; a <= 1.0f; a *= 2.0f) {
            CHECK(facet_fresnel_schlick_f32(a, 1.0f) == a, "F(f0, 1) = f0 (f0 = %g)", a);
            CHECK(facet_fresnel_schlick_f32(a, 0.0f) == 1.0f, "F(f0, 0) = 1 (f0 = %g)", a);
            CHECK(facet_smith_g1_f32(1.0f, a) == 1.0f, "G1(1) = 1 (alpha %g)", a);
            CHECK(facet_smith_g1_f32(0.0f, a) == 0.0f, "G1(0) = 0 (alpha %g)", a);
            CHECK(facet_smith_g1_hammon_f32(1.0f, a) == 1.0f, "G1_hammon(1) = 1 (alpha %g)", a);
            CHECK(facet_smith_g2_f32(1.0f, 1.0f, a) == 1.0f, "G2(1, 1) = 1 (alpha %g)", a);
            d = facet_ggx_d_f32(1.0f, a);
            CHECK(fabs(d - 1.0 / (M_PI * a * a)) <= 2e-7 * d, "D(1) = 1/(pi alpha^2) (alpha %g): %.9g", a, d);
        }
        /* the D terms beyond GGX and the spherical-Gaussian Fresnel */
        for (a = FACET_ALPHA_MIN; a <= 1.0f; a *= 2.0f) {
            double pk = 1.0 / (M_PI * a * a), g, gg;
            float n;
            d = facet_blinn_phong_d_f32(1.0f, a);
            CHECK(fabs(d - pk) <= 2e-7 * pk, "blinn_phong_d(1) = 1/(pi alpha^2) (alpha %g): %.9g", a, d);
            d = facet_beckmann_d_f32(1.0f, a);
            CHECK(fabs(d - pk) <= 2e-7 * pk, "beckmann_d(1) = 1/(pi alpha^2) (alpha %g): %.9g", a, d);
            CHECK(facet_beckmann_d_f32(0.0f, a) == 0.0f, "beckmann_d(0) = 0 (alpha %g)", a);
            CHECK(facet_blinn_phong_d_f32(0.0f, a) == (a < 1.0f ? 0.0f : (float)(1.0 / M_PI)),
                  "blinn_phong_d(0) = 0 below alpha = 1, 1/pi at 1 (alpha %g)", a);
            for (n = 0.0f; n <= 1.0f; n += 0.0625f) {
                float st = sqrtf((1.0f - n) * (1.0f + n));
                gg = facet_ggx_d_f32(n, a);
                g = facet_gtr_d_f32(n, a, 2.0f);
                CHECK(fabs(g - gg) <= (FACET_ERR_GTR_D_F32 + FACET_ERR_GGX_D_F32) * gg,
                      "gtr_d(gamma = 2) = ggx_d (N.H %g, alpha %g): %.9g vs %.9g", n, a, g, gg);
                g = facet_gtr_d_f32(n, a, 0.0f);
                CHECK(fabs(g - 1.0 / M_PI) <= FACET_ERR_GTR_D_F32 / M_PI, "gtr_d(gamma = 0) = 1/pi: %.9g", g);
                g = facet_ggx_aniso_d_f32(n, 0.6f * st, -0.8f * st, a, a);
                CHECK(fabs(g - gg) <= 2.0 * (FACET_ERR_GGX_ANISO_D_F32 + FACET_ERR_GGX_D_F32) * gg + 1e-30,
                      "ggx_aniso_d(alpha, alpha) = ggx_d (N.H %g, alpha %g): %.9g vs %.9g", n, a, g, gg);
            }
            CHECK(facet_fresnel_schlick_sg_f32(a, 0.0f) == 1.0f, "F_sg(f0, 0) = 1 (f0 = %g)", a);
            CHECK(facet_smith_g1_gtr_f32(1.0f, a, 1.3f) == 1.0f && facet_smith_g1_gtr_f32(0.0f, a, 3.7f) == 0.0f,
                  "G1_gtr(1) = 1, G1_gtr(0) = 0 (alpha %g)", a);
            for (n = 0.0f; n <= 1.0f; n += 0.0625f) {
                CHECK(same(facet_smith_g1_gtr_f32(n, a, 2.0f), facet_smith_g1_f32(n, a)),
                      "G1_gtr(gamma = 2) is smith_g1 to the bit (N.V %g, alpha %g)", n, a);
                g = facet_smith_g1_gtr_f32(n, a, 0.0f);
                CHECK(fabs(g - 2.0 * n / (1.0 + n)) <= FACET_ERR_SMITH_G1_GTR_F32 * g,
                      "G1_gtr(gamma = 0) = 2n / (1 + n) (N.V %g): %.9g", n, g);
            }
        }
        CHECK(same(facet_gtr_d_f32(0.5f, 0.25f, 1.0f), facet_gtr_d_f32(0.5f, 0.25f, 0.99999994f))
                  || fabs(facet_gtr_d_f32(0.5f, 0.25f, 1.0f) / facet_gtr_d_f32(0.5f, 0.25f, 0.99999994f) - 1.0) < 1e-6,
              "gtr_d is continuous through gamma = 1");
        /* alpha = 0 evaluates at alpha_min */
        CHECK(same(facet_ggx_d_f32(1.0f, 0.0f), facet_ggx_d_f32(1.0f, FACET_ALPHA_MIN)), "D: alpha 0 -> alpha_min");
        CHECK(facet_brdf_hammon_f32(0.0f, 0.0f, -1.0f, 0.0f, 1.0f, 1.0f) < 1e16f,
              "brdf at the all-grazing, alpha 0 corner is finite");
        CHECK(facet_brdf_hammon_f32(1.0f, 1.0f, 1.0f, 1.0f, 0.0f, 0.0f) == 0.0f, "brdf: f0 = albedo = 0 at L = V = N is 0");
        CHECK(facet_lambert_f32(1.0f) == (float)(1.0 / M_PI), "lambert(1) = 1/pi");
        CHECK(facet_diffuse_hammon_f32(0.5f, 0.5f, 0.0f, 0.5f, 0.0f) == 0.0f, "diffuse: albedo 0 gives 0");
    }
    /* the RGB form is the scalar kernel per channel */
    {
        int i, bad_rgb = 0;
        for (i = 0; i < 10000; i++) {
            float nl, nv, lv, a = smp_alpha(&rng), f0[3], alb[3], out[3];
            int c;
            smp_geometry(&rng, &nl, &nv, &lv);
            for (c = 0; c < 3; c++) {
                f0[c] = smp_unit(&rng);
                alb[c] = smp_unit(&rng);
            }
            facet_brdf_hammon_rgb_f32(out, nl, nv, lv, a, f0, alb);
            for (c = 0; c < 3; c++)
                if (!same(out[c], facet_brdf_hammon_f32(nl, nv, lv, a, f0[c], alb[c])))
                    bad_rgb++;
        }
        CHECK(bad_rgb == 0, "brdf_hammon_rgb differs from brdf_hammon in %d channels", bad_rgb);
    }
    return th_done();
}
