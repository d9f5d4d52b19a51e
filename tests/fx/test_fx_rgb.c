/* test_fx_rgb.c - facet_brdf_hammon_rgb_fx / _fx_fast and their batches
 * (facet/fx.h): every channel bit-equal to the per-channel kernel of its
 * tier, for random Q15 inputs, every int32 edge (clamping, saturation at
 * the grazing peak) and random int32 patterns, planar and interleaved, at
 * every n from 0 to 9. */
#include <stdio.h>
#include <stdint.h>
#include <string.h>
#include "../lib/harness.h"
#include "facet/fx.h"

static uint64_t rng_ = 0x9e3779b97f4a7c15ull;
static uint32_t next_(void)
{
    rng_ = rng_ * 6364136223846793005ull + 1442695040888963407ull;
    return (uint32_t)(rng_ >> 32);
}

static int32_t pick_(int mode)
{
    static const int32_t edge[] = { INT32_MIN, -32769, -32768, -1, 0, 1, 31, 32, 127, 128, 129,
                                    16384, 32767, 32768, 32769, INT32_MAX };
    switch (mode) {
    case 0: return (int32_t)(next_() % 32769u);
    case 1: return (int32_t)(next_() % 65537u) - 32768;
    case 2: return edge[next_() % 16];
    default: return (int32_t)next_();
    }
}

int main(void)
{
    int i, c, t, bad[2] = { 0, 0 }, bad_batch = 0;
    th_name = "fx_rgb";
    for (i = 0; i < 200000; i++) {
        int32_t in[4], f0[3], alb[3];
        uint64_t out[3];
        int mode = i % 4;
        for (c = 0; c < 4; c++)
            in[c] = pick_(c == 2 && mode == 0 ? 1 : mode);
        for (c = 0; c < 3; c++) {
            f0[c] = pick_(mode);
            alb[c] = pick_(mode);
        }
        facet_brdf_hammon_rgb_fx(out, in[0], in[1], in[2], in[3], f0, alb);
        for (c = 0; c < 3; c++)
            bad[0] += out[c] != facet_brdf_hammon_fx(in[0], in[1], in[2], in[3], f0[c], alb[c]);
        facet_brdf_hammon_rgb_fx_fast(out, in[0], in[1], in[2], in[3], f0, alb);
        for (c = 0; c < 3; c++)
            bad[1] += out[c] != facet_brdf_hammon_fx_fast(in[0], in[1], in[2], in[3], f0[c], alb[c]);
    }
    CHECK(bad[0] == 0, "brdf_hammon_rgb_fx differs from brdf_hammon_fx in %d channels", bad[0]);
    CHECK(bad[1] == 0, "brdf_hammon_rgb_fx_fast differs from brdf_hammon_fx_fast in %d channels", bad[1]);
    /* the grazing peak saturates or nearly: the largest outputs */
    {
        int32_t f0[3] = { 32768, 0, 16384 }, alb[3] = { 32768, 0, 1 };
        uint64_t out[3];
        facet_brdf_hammon_rgb_fx(out, 128, 128, -32768, 32, f0, alb);
        for (c = 0; c < 3; c++)
            CHECK(out[c] == facet_brdf_hammon_fx(128, 128, -32768, 32, f0[c], alb[c]), "grazing peak, channel %d", c);
    }
    /* batches: planar and interleaved, every n 0..9, both tiers */
    for (t = 0; t < 2; t++) {
        int n;
        for (n = 0; n <= 9; n++) {
            int32_t nl[9], nv[9], lv[9], a[9], fp[3][9], ap[3][9], fi[27], ai[27];
            uint64_t op[3][9], oi[27];
            uint64_t *o[3] = { op[0], op[1], op[2] };
            const int32_t *f[3] = { fp[0], fp[1], fp[2] }, *b[3] = { ap[0], ap[1], ap[2] };
            for (i = 0; i < n; i++) {
                nl[i] = pick_(i % 4);
                nv[i] = pick_(i % 4);
                lv[i] = pick_(1);
                a[i] = pick_(i % 4);
                for (c = 0; c < 3; c++) {
                    fp[c][i] = fi[3 * i + c] = pick_(i % 4);
                    ap[c][i] = ai[3 * i + c] = pick_(i % 4);
                }
            }
            (t ? facet_brdf_hammon_rgb_fx_fast_batch : facet_brdf_hammon_rgb_fx_batch)(o, nl, nv, lv, a, f, b, (size_t)n);
            (t ? facet_brdf_hammon_rgb_fx_fast_batch_interleaved : facet_brdf_hammon_rgb_fx_batch_interleaved)(
                oi, nl, nv, lv, a, fi, ai, (size_t)n);
            for (i = 0; i < n; i++)
                for (c = 0; c < 3; c++) {
                    uint64_t want = t ? facet_brdf_hammon_fx_fast(nl[i], nv[i], lv[i], a[i], fp[c][i], ap[c][i])
                                      : facet_brdf_hammon_fx(nl[i], nv[i], lv[i], a[i], fp[c][i], ap[c][i]);
                    bad_batch += (op[c][i] != want) + (oi[3 * i + c] != want);
                }
        }
    }
    CHECK(bad_batch == 0, "RGB fx batches differ from the per-channel kernels (%d)", bad_batch);
    return th_done();
}
