/* test_fx_sphere.c - the rendered check of the fixed point: a lit sphere shaded
 * with brdf_hammon in fixed point and with the double oracle, at the same
 * (Q15) dot products, for alpha across the range and a few lights and
 * materials; radiance = brdf N.L E, encoded to 8-bit sRGB.  The two images
 * may differ by at most 1 code value anywhere.  Also printed (not checked):
 * the largest difference against the oracle at the unquantised dots, which
 * shows the cost of Q15 inputs themselves (at the sharp peaks of small
 * alpha). */
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include "../lib/harness.h"
#include "facet.h"
#include "facet/fx.h"
#include "facet/oracle.h"

static int srgb8(double lin)
{
    double c;
    if (!(lin > 0))
        return 0;
    if (lin >= 1)
        return 255;
    c = lin <= 0.0031308 ? 12.92 * lin : 1.055 * pow(lin, 1 / 2.4) - 0.055;
    return (int)floor(c * 255 + 0.5);
}

static int32_t q15(double x)
{
    double y = x * 32768, r = floor(y);
    return (int32_t)(y - r >= 0.5 ? r + 1 : r);
}

int main(void)
{
    static const double alphas[] = { 0x1p-10, 0x1p-8, 0x1p-6, 0.03, 0.1, 0.25, 0.5, 0.75, 1.0 };
    static const double lights[][3] = { { 0.3, 0.4, 0.866 }, { -0.7, 0.1, 0.707 }, { 0.98, 0.0, 0.199 } };
    static const double mats[][2] = { { 0.04, 0.8 }, { 0.95, 0.05 } }; /* f0, albedo */
    const int size = getenv("FACET_TEST_QUICK") ? 48 : 160;
    const double E = 2.0; /* light intensity */
    int ai, li, mi, x, y, worst = 0, worst_unq = 0;
    long pixels = 0;
    th_name = "fx_sphere";
    for (ai = 0; ai < (int)(sizeof alphas / sizeof alphas[0]); ai++)
        for (li = 0; li < 3; li++)
            for (mi = 0; mi < 2; mi++) {
                const double *l = lights[li];
                double ll = sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
                int img_worst = 0;
                for (y = 0; y < size; y++)
                    for (x = 0; x < size; x++) {
                        double nx = (x + 0.5) / size * 2 - 1, ny = (y + 0.5) / size * 2 - 1, nz2 = 1 - nx * nx - ny * ny;
                        double nl, nv, lv, din[6], want, want_unq, got;
                        int32_t in[6];
                        int d;
                        if (nz2 <= 0)
                            continue;
                        /* V = z (orthographic camera), N on the sphere */
                        nv = sqrt(nz2);
                        nl = (nx * l[0] + ny * l[1] + nv * l[2]) / ll;
                        lv = l[2] / ll;
                        if (nl <= 0)
                            continue; /* unlit: black in both */
                        in[0] = q15(nl); in[1] = q15(nv); in[2] = q15(lv);
                        in[3] = q15(alphas[ai]); in[4] = q15(mats[mi][0]); in[5] = q15(mats[mi][1]);
                        if (in[0] < FACET_FX_COS_MIN)
                            in[0] = FACET_FX_COS_MIN; /* the fx cos floor, for both */
                        if (in[1] < FACET_FX_COS_MIN)
                            in[1] = FACET_FX_COS_MIN;
                        for (d = 0; d < 6; d++)
                            din[d] = in[d] / 32768.0;
                        got = ldexp((double)facet_brdf_hammon_fx(in[0], in[1], in[2], in[3], in[4], in[5]), -24) * din[0] * E;
                        want = facet_oracle_brdf_hammon(din[0], din[1], din[2], din[3], din[4], din[5]) * din[0] * E;
                        want_unq = facet_oracle_brdf_hammon(nl, nv, lv, alphas[ai], mats[mi][0], mats[mi][1]) * nl * E;
                        d = abs(srgb8(got) - srgb8(want));
                        if (d > img_worst)
                            img_worst = d;
                        d = abs(srgb8(got) - srgb8(want_unq));
                        if (d > worst_unq)
                            worst_unq = d;
                        pixels++;
                    }
                if (img_worst > worst)
                    worst = img_worst;
                CHECK(img_worst <= 1, "alpha %g light %d material %d: %d sRGB codes off", alphas[ai], li, mi, img_worst);
            }
    printf("%ld lit pixels: max |fx - oracle| = %d sRGB code(s) at the same Q15 dots; "
           "%d vs the oracle at unquantised dots (input quantisation, not checked)\n", pixels, worst, worst_unq);
    return th_done();
}
