/* test_f32_rgb.c - the RGB batches of facet.h on every port this CPU runs,
 * both tiers, every layout (planar, interleaved, uniform material planar and
 * interleaved, textured: uniform alpha and f0 with per-sample albedo, and
 * the same with per-sample alpha): each channel bit-equal to the port's brdf_hammon batch at
 * that channel's f0 and albedo (and, for the material forms, the material's
 * alpha), at every n mod the lane count (0 .. 3W + 1, and long runs), from
 * unaligned pointers, with an output that is the very same array as an
 * input, and under the NaN rule (every NaN class in each stream).  Also the
 * vector entry facet_shade_hammon_rgb_f32 (dots, below-horizon rule, N.L
 * factor, NaN). */
#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>
#include <float.h>
#include "../lib/harness.h"
#include "../lib/sample.h"

#define MAXN 200

static int same(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

static const uint32_t nan_bits[] = { 0x7fc00000u, 0xffc00000u, 0x7f800001u, 0xff800001u, 0x7fa00000u,
                                     0x7fc12345u, 0x7fffffffu, 0xffffffffu };
static float nan_at(int i)
{
    float f;
    memcpy(&f, &nan_bits[i % 8], sizeof f);
    return f;
}

typedef void (*mono_fn)(float *, const float *, const float *, const float *, const float *, const float *,
                        const float *, size_t);

static float nol[MAXN], nov[MAXN], lov[MAXN], alpha[MAXN], f0p[3][MAXN], albp[3][MAXN];

/* which streams of a layout are the material's uniform values rather
 * than per-sample arrays: bit 0 alpha, bit 1 f0, bit 2 albedo */
static int uniform_of(int lay) { return lay == 2 || lay == 3 ? 7 : lay == 4 ? 3 : lay == 5 ? 2 : 0; }

/* the reference: the port's mono batch per channel, with the uniform
 * streams (uniform_of) m's values */
static void reference(int fast, float ref[3][MAXN], size_t n, const facet_material_f32 *m, int uni)
{
    mono_fn f = fast ? facet_brdf_hammon_f32_fast_batch : facet_brdf_hammon_f32_batch;
    static float ua[MAXN], uf[MAXN], ub[MAXN];
    size_t i;
    int c;
    for (c = 0; c < 3; c++) {
        for (i = 0; i < n; i++) {
            ua[i] = uni & 1 ? m->alpha : alpha[i];
            uf[i] = uni & 2 ? m->f0[c] : f0p[c][i];
            ub[i] = uni & 4 ? m->albedo[c] : albp[c][i];
        }
        f(ref[c], nol, nov, lov, ua, uf, ub, n);
    }
}

/* runs layout `lay` (0 planar, 1 interleaved, 2 material planar, 3 material
 * interleaved, 4 textured, 5 textured with per-sample roughness) on n samples, inputs copied to exact-size buffers at float
 * offset `mis`; out[c][i] back */
static void run(int fast, int lay, size_t n, int mis, const facet_material_f32 *m, float out[3][MAXN])
{
    float *b[6], *o[3], *fi, *ai, *oi;
    const float *fp[3], *ap[3];
    const float *src[4] = { nol, nov, lov, alpha };
    size_t i;
    int c;
    for (c = 0; c < 4; c++) {
        b[c] = (float *)malloc((n + mis) * sizeof(float) + 1) + mis;
        memcpy(b[c], src[c], n * sizeof(float));
    }
    fi = (float *)malloc((3 * n + mis) * sizeof(float) + 1) + mis;
    ai = (float *)malloc((3 * n + mis) * sizeof(float) + 1) + mis;
    oi = (float *)malloc((3 * n + mis) * sizeof(float) + 1) + mis;
    for (c = 0; c < 3; c++) {
        b[4] = NULL;
        o[c] = (float *)malloc((n + mis) * sizeof(float) + 1) + mis;
        fp[c] = f0p[c];
        ap[c] = albp[c];
        for (i = 0; i < n; i++) {
            fi[3 * i + c] = f0p[c][i];
            ai[3 * i + c] = albp[c][i];
        }
    }
    switch (lay) {
    case 0:
        (fast ? facet_brdf_hammon_rgb_f32_fast_batch : facet_brdf_hammon_rgb_f32_batch)(o, b[0], b[1], b[2], b[3], fp, ap, n);
        break;
    case 1:
        (fast ? facet_brdf_hammon_rgb_f32_fast_batch_interleaved : facet_brdf_hammon_rgb_f32_batch_interleaved)(
            oi, b[0], b[1], b[2], b[3], fi, ai, n);
        break;
    case 2:
        (fast ? facet_brdf_hammon_rgb_f32_fast_batch_material : facet_brdf_hammon_rgb_f32_batch_material)(
            o, b[0], b[1], b[2], m, n);
        break;
    case 3:
        (fast ? facet_brdf_hammon_rgb_f32_fast_batch_material_interleaved
              : facet_brdf_hammon_rgb_f32_batch_material_interleaved)(oi, b[0], b[1], b[2], m, n);
        break;
    case 4:
        (fast ? facet_brdf_hammon_rgb_f32_fast_batch_textured : facet_brdf_hammon_rgb_f32_batch_textured)(
            o, b[0], b[1], b[2], m, ap, n);
        break;
    default:
        (fast ? facet_brdf_hammon_rgb_f32_fast_batch_textured_rough
              : facet_brdf_hammon_rgb_f32_batch_textured_rough)(o, b[0], b[1], b[2], b[3], m, ap, n);
    }
    for (c = 0; c < 3; c++)
        for (i = 0; i < n; i++)
            out[c][i] = (lay == 1 || lay == 3) ? oi[3 * i + c] : o[c][i];
    for (c = 0; c < 4; c++)
        free(b[c] - mis);
    for (c = 0; c < 3; c++)
        free(o[c] - mis);
    free(fi - mis);
    free(ai - mis);
    free(oi - mis);
}

static void fill(smp_rng *rng)
{
    int i, c;
    for (i = 0; i < MAXN; i++) {
        smp_geometry(rng, &nol[i], &nov[i], &lov[i]);
        alpha[i] = smp_alpha(rng);
        for (c = 0; c < 3; c++) {
            f0p[c][i] = smp_unit(rng);
            albp[c][i] = smp_unit(rng);
        }
    }
}

static void test_port(const char *pn, int lanes, int fast)
{
    static float ref[3][MAXN], out[3][MAXN];
    smp_rng rng = { 4242 };
    facet_material_f32 m = { 0.0625f, { 0.04f, 0.5f, 0.95f }, { 0.8f, 0.2f, 0.0f } };
    int lay, bad[6] = { 0, 0, 0, 0, 0, 0 }, bad_alias = 0, bad_nan = 0, c;
    size_t n, i;
    fill(&rng);
    for (lay = 0; lay < 6; lay++) {
        const facet_material_f32 *mm = lay >= 2 ? &m : NULL;
        reference(fast, ref, MAXN, &m, uniform_of(lay));
        /* every n mod W, from 0 to 3W + 1, and long runs; misaligned */
        for (n = 0; n <= (size_t)(3 * lanes + 1) || n == 3 * (size_t)lanes + 2; n++) {
            run(fast, lay, n, (int)(n % 4), mm, out);
            for (c = 0; c < 3; c++)
                for (i = 0; i < n; i++)
                    bad[lay] += !same(out[c][i], ref[c][i]);
        }
        for (n = MAXN - lanes; n <= MAXN; n++) {
            run(fast, lay, n, 1 + (int)(n % 3), mm, out);
            for (c = 0; c < 3; c++)
                for (i = 0; i < n; i++)
                    bad[lay] += !same(out[c][i], ref[c][i]);
        }
    }
    CHECK(bad[0] == 0, "%s%s: planar RGB batch differs from brdf_hammon per channel (%d)", pn, fast ? "/fast" : "", bad[0]);
    CHECK(bad[1] == 0, "%s%s: interleaved RGB batch differs (%d)", pn, fast ? "/fast" : "", bad[1]);
    CHECK(bad[2] == 0, "%s%s: material RGB batch differs (%d)", pn, fast ? "/fast" : "", bad[2]);
    CHECK(bad[3] == 0, "%s%s: material interleaved RGB batch differs (%d)", pn, fast ? "/fast" : "", bad[3]);
    CHECK(bad[4] == 0, "%s%s: textured RGB batch (uniform alpha, f0) differs (%d)", pn, fast ? "/fast" : "", bad[4]);
    CHECK(bad[5] == 0, "%s%s: textured RGB batch with per-sample roughness (uniform f0) differs (%d)", pn,
          fast ? "/fast" : "", bad[5]);

    /* aliasing: planar out[0] is nol, out[2] is lov; interleaved out is f0 */
    reference(fast, ref, 77, &m, 0);
    {
        float a_nl[77], a_nv[77], a_lv[77], a_al[77], o1[77], fi[3 * 77], ai[3 * 77];
        float *o[3];
        const float *fp[3] = { f0p[0], f0p[1], f0p[2] }, *ap[3] = { albp[0], albp[1], albp[2] };
        memcpy(a_nl, nol, sizeof a_nl);
        memcpy(a_nv, nov, sizeof a_nv);
        memcpy(a_lv, lov, sizeof a_lv);
        memcpy(a_al, alpha, sizeof a_al);
        o[0] = a_nl;
        o[1] = o1;
        o[2] = a_lv;
        (fast ? facet_brdf_hammon_rgb_f32_fast_batch : facet_brdf_hammon_rgb_f32_batch)(o, a_nl, a_nv, a_lv, a_al, fp, ap, 77);
        for (i = 0; i < 77; i++)
            bad_alias += !same(a_nl[i], ref[0][i]) + !same(o1[i], ref[1][i]) + !same(a_lv[i], ref[2][i]);
        for (i = 0; i < 77; i++)
            for (c = 0; c < 3; c++) {
                fi[3 * i + c] = f0p[c][i];
                ai[3 * i + c] = albp[c][i];
            }
        (fast ? facet_brdf_hammon_rgb_f32_fast_batch_interleaved : facet_brdf_hammon_rgb_f32_batch_interleaved)(
            fi, nol, nov, lov, alpha, fi, ai, 77);
        for (i = 0; i < 77; i++)
            for (c = 0; c < 3; c++)
                bad_alias += !same(fi[3 * i + c], ref[c][i]);
    }
    CHECK(bad_alias == 0, "%s%s: an output aliasing an input changes results (%d)", pn, fast ? "/fast" : "", bad_alias);

    /* the NaN rule: a NaN in a geometry stream zeroes all channels, in a
     * channel's f0 / albedo that channel; the material's alpha NaN zeroes all */
    for (i = 0; i < 3 * (size_t)lanes + 5; i++) {
        int s = (int)(i % 10);
        float v = nan_at((int)i);
        if (s < 4)
            (s == 0 ? nol : s == 1 ? nov : s == 2 ? lov : alpha)[i] = v;
        else if (s < 7)
            f0p[s - 4][i] = v;
        else
            albp[s - 7][i] = v;
    }
    n = 3 * (size_t)lanes + 5;
    run(fast, 0, n, 0, NULL, out);
    for (i = 0; i < n; i++)
        for (c = 0; c < 3; c++) {
            int s = (int)(i % 10), zero = s < 4 || s - 4 == c || s - 7 == c;
            if (zero ? !same(out[c][i], 0.0f) : !(out[c][i] >= 0.0f && out[c][i] <= FLT_MAX))
                bad_nan++;
        }
    run(fast, 1, n, 0, NULL, out);
    for (i = 0; i < n; i++)
        for (c = 0; c < 3; c++) {
            int s = (int)(i % 10), zero = s < 4 || s - 4 == c || s - 7 == c;
            if (zero && !same(out[c][i], 0.0f))
                bad_nan++;
        }
    /* the textured forms: alpha uniform (4) or per sample (5), f0 uniform,
     * albedo per sample */
    for (lay = 4; lay < 6; lay++) {
        run(fast, lay, n, 0, &m, out);
        for (i = 0; i < n; i++)
            for (c = 0; c < 3; c++) {
                int s = (int)(i % 10), zero = s < (lay == 4 ? 3 : 4) || s - 7 == c;
                if (zero ? !same(out[c][i], 0.0f) : !(out[c][i] >= 0.0f && out[c][i] <= FLT_MAX))
                    bad_nan++;
            }
    }
    m.alpha = nan_at(2);
    run(fast, 2, n, 0, &m, out);
    for (i = 0; i < n; i++)
        for (c = 0; c < 3; c++)
            bad_nan += !same(out[c][i], 0.0f);
    CHECK(bad_nan == 0, "%s%s: RGB batches break the NaN rule (%d)", pn, fast ? "/fast" : "", bad_nan);
}

static facet_vec3_f32 v3(double x, double y, double z)
{
    facet_vec3_f32 r;
    r.x = (float)x;
    r.y = (float)y;
    r.z = (float)z;
    return r;
}

static void test_shade(void)
{
    smp_rng rng = { 99 };
    facet_material_f32 m = { 0.09f, { 0.04f, 0.05f, 0.06f }, { 0.8f, 0.2f, 0.1f } };
    facet_dirs_f32 d;
    float out[3], brdf[3];
    int i, c, bad = 0, below = 0, nanb = 0;
    for (i = 0; i < 20000; i++) {
        double tl = acos(smp_u01(&rng) * 2 - 1), pl = 2 * M_PI * smp_u01(&rng);
        double tv = acos(smp_u01(&rng) * 2 - 1), pv = 2 * M_PI * smp_u01(&rng);
        float snl, snv, slv, k;
        d.n = v3(0, 0, 1);
        d.l = v3(sin(tl) * cos(pl), sin(tl) * sin(pl), cos(tl));
        d.v = v3(sin(tv) * cos(pv), sin(tv) * sin(pv), cos(tv));
        facet_shade_hammon_rgb_f32(out, &d, &m);
        snl = d.n.x * d.l.x + d.n.y * d.l.y + d.n.z * d.l.z;
        snv = d.n.x * d.v.x + d.n.y * d.v.y + d.n.z * d.v.z;
        slv = d.l.x * d.v.x + d.l.y * d.v.y + d.l.z * d.v.z;
        facet_brdf_hammon_rgb_f32(brdf, snl, snv, slv, m.alpha, m.f0, m.albedo);
        k = snl > 0.0f ? (snl < 1.0f ? snl : 1.0f) : 0.0f;
        for (c = 0; c < 3; c++) {
            bad += !same(out[c], brdf[c] * k);
            if (snl <= 0.0f)
                below += !same(out[c], 0.0f);
        }
        /* a view below the horizon is the view at N.V = FACET_COS_MIN */
        if (snv <= 0.0f && snl > 0.0f) {
            facet_brdf_hammon_rgb_f32(brdf, snl, FACET_COS_MIN, slv, m.alpha, m.f0, m.albedo);
            for (c = 0; c < 3; c++)
                bad += !same(out[c], brdf[c] * k);
        }
    }
    CHECK(bad == 0, "shade_hammon_rgb: differs from the dots + brdf_hammon_rgb * N.L (%d)", bad);
    CHECK(below == 0, "shade_hammon_rgb: light below the horizon not 0 (%d)", below);
    for (i = 0; i < 9 * 8; i++) {
        float *comp[9];
        d.n = v3(0, 0.6, 0.8);
        d.l = v3(0, -0.6, 0.8);
        d.v = v3(0.6, 0, 0.8);
        comp[0] = &d.n.x; comp[1] = &d.n.y; comp[2] = &d.n.z;
        comp[3] = &d.l.x; comp[4] = &d.l.y; comp[5] = &d.l.z;
        comp[6] = &d.v.x; comp[7] = &d.v.y; comp[8] = &d.v.z;
        *comp[i % 9] = nan_at(i / 9);
        facet_shade_hammon_rgb_f32(out, &d, &m);
        for (c = 0; c < 3; c++)
            nanb += !same(out[c], 0.0f);
        facet_shade_hammon_rgb_f32_fast(out, &d, &m);
        for (c = 0; c < 3; c++)
            nanb += !same(out[c], 0.0f);
    }
    CHECK(nanb == 0, "shade_hammon_rgb: a NaN component does not give 0 (%d)", nanb);
    d.n = v3(0, 0, 1);
    d.l = v3(0, 0.6, 0.8);
    d.v = v3(0, -0.6, 0.8);
    facet_shade_hammon_rgb_f32(out, &d, &m);
    facet_brdf_hammon_rgb_f32(brdf, 0.8f, 0.8f, -0.28f, m.alpha, m.f0, m.albedo);
    CHECK(fabsf(out[0] - 0.8f * brdf[0]) <= 1e-6f * out[0] && out[0] > 0.0f,
          "shade_hammon_rgb: a mirror configuration gives brdf * N.L (%g vs %g)", out[0], 0.8f * brdf[0]);
}

/* sample.h helpers this test does not need */
static void unused_(void) { (void)smp_inputs; }

int main(void)
{
    size_t pi;
    th_name = "f32_rgb";
    (void)unused_;
    for (pi = 0; pi < facet_port_count(); pi++) {
        int sup, lanes, fast;
        const char *pn = facet_port_at(pi, &sup, &lanes);
        if (!sup) {
            SKIP("port %s: compiled in, but this CPU cannot run it", pn);
            continue;
        }
        facet_set_port(pn);
        for (fast = 0; fast < 2; fast++)
            test_port(pn, lanes, fast);
    }
    facet_set_port("auto");
    test_shade();
    return th_done();
}
