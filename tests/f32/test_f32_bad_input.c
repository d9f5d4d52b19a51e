/* test_f32_bad_input.c - the domain contract of facet.h for every kernel:
 * each bad value in each input position (others random and valid) gives a
 * finite, non-negative result, bit-equal to the kernel evaluated at the
 * documented substitute (-Inf, below-domain -> the low end; +Inf,
 * above-domain -> the high end), and every NaN class (quiet, signalling,
 * either sign, payloads) in each input position gives +0 (the NaN rule).
 * Also the named special points, and both tiers of every kernel at its
 * golden values (tests/lib/golden.h): within the bound, to the bit where
 * the point is a named point of the contract.  The per-sample calls run
 * the active port's per-sample entries (src/f32/f32_one_body.h): all of it
 * on every port this CPU runs, selected with facet_set_port. */
#include <stdio.h>
#include <stdlib.h>
#include <float.h>
#include <stdint.h>
#include <string.h>
#include "../lib/harness.h"
#include "../lib/sample.h"
#include "../lib/golden.h"
#include "facet/oracle.h"

static int same(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

/* every NaN class: quiet and signalling, both signs, small and full payloads */
static const uint32_t nan_bits[] = { 0x7fc00000u, 0xffc00000u, 0x7f800001u, 0xff800001u, 0x7fa00000u,
                                     0x7fc12345u, 0x7fbfffffu, 0x7fffffffu, 0xffffffffu, 0xff812345u };
#define N_NAN ((int)(sizeof nan_bits / sizeof nan_bits[0]))
static float nan_at(int i)
{
    float f;
    memcpy(&f, &nan_bits[i], sizeof f);
    return f;
}

static void check_port(void)
{
    const float bad[] = { INFINITY, -INFINITY, 0.0f, -0.0f, 1.4e-45f, -1.4e-45f,
                          1e-39f, -1e-30f, -1.0f, -2.0f, 1.0000001f, 2.0f, 1e30f, FLT_MAX, -FLT_MAX };
    const int n_bad = (int)(sizeof bad / sizeof bad[0]);
    smp_rng rng = { 12345 };
    size_t ki;

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
                    ref_in[pos] = v < lo ? lo : v > hi ? hi : v;
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
        /* the NaN rule: every NaN class in every position, others valid,
         * out of domain or themselves NaN, gives +0 */
        {
            int nan_bad = 0;
            for (rep = 0; rep < 20; rep++)
                for (pos = 0; pos < k->n_inputs; pos++)
                    for (b = 0; b < N_NAN; b++) {
                        float in[FACET_MAX_INPUTS], got;
                        int j;
                        smp_inputs(&rng, k, in);
                        if (rep % 4 == 1) /* the others out of domain */
                            for (j = 0; j < k->n_inputs; j++)
                                in[j] = bad[(rep + j + b) % n_bad];
                        if (rep % 4 == 2) /* the others NaN too */
                            for (j = 0; j < k->n_inputs; j++)
                                in[j] = nan_at((b + j) % N_NAN);
                        in[pos] = nan_at(b);
                        got = f(in);
                        if (!same(got, 0.0f))
                            nan_bad++;
                    }
            CHECK(nan_bad == 0, "%s%s: %d samples with a NaN input are not +0", k->name, tier, nan_bad);
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
    /* named points of the Fresnel and diffuse menu, both tiers */
    {
        static const float vals[] = { 0.0f, 1e-30f, 0.02f, 0.04f, 0.5f, 0.9f, 0.99999994f, 1.0f };
        const int nv_ = (int)(sizeof vals / sizeof vals[0]);
        int i, j, tier;
        for (tier = 0; tier < 2; tier++) {
            float (*f90)(float, float, float) = tier ? facet_fresnel_schlick_f90_f32_fast : facet_fresnel_schlick_f90_f32;
            float (*ct)(float, float) = tier ? facet_fresnel_cook_torrance_f32_fast : facet_fresnel_cook_torrance_f32;
            float (*bu)(float, float, float, float, float) = tier ? facet_diffuse_burley_f32_fast : facet_diffuse_burley_f32;
            float (*on)(float, float, float, float, float) = tier ? facet_diffuse_oren_nayar_f32_fast : facet_diffuse_oren_nayar_f32;
            float (*hy)(float, float, float, float, float) = tier ? facet_diffuse_hammon_hybrid_f32_fast : facet_diffuse_hammon_hybrid_f32;
            float (*ch)(float, float, float, float, float) = tier ? facet_diffuse_hammon_cheap_f32_fast : facet_diffuse_hammon_cheap_f32;
            double bound = tier ? FACET_ERR_FRESNEL_COOK_TORRANCE_F32_FAST : FACET_ERR_FRESNEL_COOK_TORRANCE_F32;
            for (i = 0; i < nv_; i++) {
                float x = vals[i];
                for (j = 0; j < nv_; j++) {
                    float y = vals[j];
                    CHECK(f90(x, y, 1.0f) == x, "schlick_f90(f0 %g, f90 %g, 1) = f0 (tier %d)", x, y, tier);
                    CHECK(f90(x, y, 0.0f) == y, "schlick_f90(f0 %g, f90 %g, 0) = f90 (tier %d)", x, y, tier);
                    /* Cook-Torrance: F(0, c) = 0, F(1, c) = 1 exactly */
                    CHECK(ct(0.0f, y) == 0.0f, "cook_torrance(0, %g) = 0 (tier %d)", y, tier);
                    CHECK(ct(1.0f, y) == 1.0f, "cook_torrance(1, %g) = 1 (tier %d)", y, tier);
                    /* L = V = N: Burley and Hammon's cheap and hybrid forms, Oren-Nayar's A */
                    CHECK(same(bu(1.0f, 1.0f, y, x, x), facet_lambert_f32(x)),
                          "burley at N.L = N.V = 1 is lambert (alpha %g, albedo %g)", x, x);
                    CHECK(same(hy(1.0f, 1.0f, 1.0f, x, y), ch(1.0f, 1.0f, 1.0f, x, y)),
                          "hybrid = cheap at N.L = N.V = 1 (alpha %g, albedo %g)", x, y);
                }
                if (x > 0.0f) {
                    float f1 = ct(x, 1.0f), fz = ct(x, 0.0f);
                    CHECK(fabs(f1 - x) <= bound * x, "cook_torrance(%g, 1) = %.9g, not f0 (tier %d)", x, f1, tier);
                    CHECK(fabs(fz - 1.0) <= bound, "cook_torrance(%g, 0) = %.9g, not 1 (tier %d)", x, fz, tier);
                }
                {
                    double s2 = 0.25 * fmax(x, FACET_ALPHA_MIN) * fmax(x, FACET_ALPHA_MIN);
                    double want = (1.0 - 0.5 * s2 / (s2 + 0.33)) / M_PI;
                    float got = on(1.0f, 1.0f, 1.0f, x, 1.0f);
                    CHECK(fabs(got - want) <= 2.0 * FACET_ERR_DIFFUSE_OREN_NAYAR_F32_FAST * want,
                          "oren_nayar at L = V = N: A / pi (alpha %g): %.9g vs %.9g", x, got, want);
                }
                CHECK(bu(0.3f, 0.6f, 0.5f, x, 0.0f) == 0.0f && on(0.3f, 0.6f, 0.5f, x, 0.0f) == 0.0f &&
                      hy(0.3f, 0.6f, 0.5f, x, 0.0f) == 0.0f && ch(0.3f, 0.6f, 0.5f, x, 0.0f) == 0.0f,
                      "diffuse models: albedo 0 gives 0 (alpha %g)", x);
            }
        }
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
        /* the NaN rule per channel: a NaN in the geometry zeroes every channel,
         * one in f0[c] or albedo[c] channel c only (both tiers) */
        bad_rgb = 0;
        for (i = 0; i < 4000; i++) {
            float in[4], f0[3], alb[3], out[3], outf[3];
            int c, pos = i % 10;
            smp_geometry(&rng, &in[0], &in[1], &in[2]);
            in[3] = smp_alpha(&rng);
            for (c = 0; c < 3; c++) {
                f0[c] = smp_unit(&rng);
                alb[c] = smp_unit(&rng);
            }
            if (pos < 4)
                in[pos] = nan_at(i % N_NAN);
            else if (pos < 7)
                f0[pos - 4] = nan_at(i % N_NAN);
            else
                alb[pos - 7] = nan_at(i % N_NAN);
            facet_brdf_hammon_rgb_f32(out, in[0], in[1], in[2], in[3], f0, alb);
            facet_brdf_hammon_rgb_f32_fast(outf, in[0], in[1], in[2], in[3], f0, alb);
            for (c = 0; c < 3; c++) {
                int zero = pos < 4 || pos - 4 == c || pos - 7 == c;
                if (!same(out[c], facet_brdf_hammon_f32(in[0], in[1], in[2], in[3], f0[c], alb[c])) ||
                    !same(outf[c], facet_brdf_hammon_f32_fast(in[0], in[1], in[2], in[3], f0[c], alb[c])) ||
                    (zero && !same(out[c], 0.0f)) ||
                    (zero && !same(outf[c], 0.0f)))
                    bad_rgb++;
            }
        }
        CHECK(bad_rgb == 0, "brdf_hammon_rgb: %d channels break the NaN rule", bad_rgb);
        /* the case: NaN cosines no longer give the grazing maximum */
        CHECK(same(facet_brdf_hammon_f32(NAN, NAN, 0.1f, 0.16f, 0.04f, 0.5f), 0.0f),
              "brdf_hammon(NaN, NaN, 0.1, 0.16, ...) = 0");
    }
    /* the golden values, both tiers (the error measure of the accuracy
     * test: relative, absolute below 2^-100) */
    {
        size_t j, count;
        const golden_point *gt = golden_table(&count);
        golden_covers();
        for (j = 0; j < count; j++) {
            const golden_point *g = &gt[j];
            const facet_kernel *k = facet_kernel_find(g->kernel);
            float in[FACET_MAX_INPUTS] = { 0 }, got, fast;
            int i;
            if (!k)
                continue;
            for (i = 0; i < k->n_inputs; i++)
                in[i] = (float)g->in[i];
            got = k->f32(in);
            fast = k->f32_fast(in);
            CHECK(fabs(got - g->want) <= k->err_f32 * fmax(fabs(g->want), SMP_ERR_FLOOR),
                  "%s at golden point %d: %.9g vs %.17g (bound %.3g)", g->kernel, (int)j, got, g->want, k->err_f32);
            CHECK(fabs(fast - g->want) <= k->err_f32_fast * fmax(fabs(g->want), SMP_ERR_FLOOR),
                  "%s (fast) at golden point %d: %.9g vs %.17g (bound %.3g)", g->kernel, (int)j, fast, g->want,
                  k->err_f32_fast);
            if (g->exact)
                CHECK(same(got, (float)g->want), "%s at golden point %d: %.9g, not %.9g to the bit", g->kernel,
                      (int)j, got, (float)g->want);
        }
    }
}

int main(void)
{
    static char names[16][48];
    size_t pi;
    for (pi = 0; pi < facet_port_count() && pi < 16; pi++) {
        int sup;
        const char *pn = facet_port_at(pi, &sup, NULL);
        th_name = "f32_bad_input";
        if (!sup) {
            SKIP("port %s is compiled in but this CPU cannot run it", pn);
            continue;
        }
        CHECK(facet_set_port(pn) == 0 && !strcmp(facet_port_name(), pn), "cannot select port %s", pn);
        snprintf(names[pi], sizeof names[pi], "f32_bad_input (port %s)", pn);
        th_name = names[pi];
        check_port();
    }
    facet_set_port("auto");
    th_name = "f32_bad_input";
    return th_done();
}
