/* peers_textbook.c - the "textbook" peer: the formulas as printed, in float
 * C the way a first port looks.  Built -O2 (bench/bench.mk).  See peers.h. */
#include <math.h>
#include "facet/common.h"
#include "peers.h"

#define PI_F 3.14159265f

static float clampf_(float x, float lo, float hi) { return x < lo ? lo : (x > hi ? hi : x); }

/* D = 1 / (pi alpha^2 cos^4 (1 + tan^2 / alpha^2)^2) */
static float tb_d(float noh, float a)
{
    float c2 = noh * noh;
    float tan2 = (1.0f - c2) / c2;
    float a2 = a * a;
    float b = 1.0f + tan2 / a2;
    return 1.0f / (PI_F * a2 * c2 * c2 * b * b);
}

/* Lambda = (-1 + sqrt(1 + alpha^2 tan^2)) / 2 */
static float tb_lambda(float n, float a)
{
    float tan2 = (1.0f - n * n) / (n * n);
    return (-1.0f + sqrtf(1.0f + a * a * tan2)) / 2.0f;
}

static float tb_fresnel(float f0, float c) { return f0 + (1.0f - f0) * powf(1.0f - c, 5.0f); }

static float tb_diffuse(float nl, float nv, float lv, float noh, float a, float albedo)
{
    float facing = 0.5f + 0.5f * lv;
    float rough = facing * (0.9f - 0.4f * facing) * ((0.5f + noh) / noh);
    float smooth = 1.05f * (1.0f - powf(1.0f - nl, 5.0f)) * (1.0f - powf(1.0f - nv, 5.0f));
    float single = ((1.0f - a) * smooth + a * rough) / PI_F;
    float multi = 0.1159f * a;
    return albedo * (single + albedo * multi);
}

static void tb_brdf(float *out, const peer_brdf_in *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        float lx = in->lx[i], ly = in->ly[i], lz = in->lz[i];
        float vx = in->vx[i], vy = in->vy[i], vz = in->vz[i];
        float a = clampf_(in->alpha[i], FACET_ALPHA_MIN, 1.0f);
        float hx = lx + vx, hy = ly + vy, hz = lz + vz;
        float len = sqrtf(hx * hx + hy * hy + hz * hz);
        float nl = clampf_(lz, FACET_COS_MIN, 1.0f), nv = clampf_(vz, FACET_COS_MIN, 1.0f);
        float noh, loh, lv, d, g, f;
        hx /= len;
        hy /= len;
        hz /= len;
        noh = clampf_(hz, 0.0f, 1.0f);
        loh = clampf_(lx * hx + ly * hy + lz * hz, 0.0f, 1.0f);
        lv = lx * vx + ly * vy + lz * vz;
        d = tb_d(noh, a);
        g = 1.0f / (1.0f + tb_lambda(nl, a) + tb_lambda(nv, a));
        f = tb_fresnel(in->f0[i], loh);
        out[i] = d * g * f / (4.0f * nl * nv) + tb_diffuse(nl, nv, lv, noh, a, in->albedo[i]);
    }
}

static void tb_fresnel_b(float *out, const float *const *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        out[i] = tb_fresnel(in[0][i], in[1][i]);
}
static void tb_ggx_d_b(float *out, const float *const *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        out[i] = tb_d(in[0][i], clampf_(in[1][i], FACET_ALPHA_MIN, 1.0f));
}
static void tb_g1_b(float *out, const float *const *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        out[i] = 1.0f / (1.0f + tb_lambda(in[0][i], clampf_(in[1][i], FACET_ALPHA_MIN, 1.0f)));
}
static void tb_g2_b(float *out, const float *const *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        float a = clampf_(in[2][i], FACET_ALPHA_MIN, 1.0f);
        float nl = clampf_(in[0][i], FACET_COS_MIN, 1.0f), nv = clampf_(in[1][i], FACET_COS_MIN, 1.0f);
        out[i] = 1.0f / (1.0f + tb_lambda(nl, a) + tb_lambda(nv, a));
    }
}
static void tb_vis_b(float *out, const float *const *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        float a = clampf_(in[2][i], FACET_ALPHA_MIN, 1.0f);
        float nl = clampf_(in[0][i], FACET_COS_MIN, 1.0f), nv = clampf_(in[1][i], FACET_COS_MIN, 1.0f);
        out[i] = 1.0f / (1.0f + tb_lambda(nl, a) + tb_lambda(nv, a)) / (4.0f * nl * nv);
    }
}
/* Schlick-GGX with k = alpha/2: n / (n (1 - k) + k) */
static void tb_g1h_b(float *out, const float *const *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        float k = clampf_(in[1][i], FACET_ALPHA_MIN, 1.0f) / 2.0f;
        float nv = in[0][i];
        out[i] = nv / (nv * (1.0f - k) + k);
    }
}
/* Hammon: G2 / (4 nl nv), G2 = 2 nl nv / lerp(2 nl nv, nl + nv, alpha) */
static void tb_vish_b(float *out, const float *const *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        float a = clampf_(in[2][i], FACET_ALPHA_MIN, 1.0f);
        float nl = clampf_(in[0][i], FACET_COS_MIN, 1.0f), nv = clampf_(in[1][i], FACET_COS_MIN, 1.0f);
        float g2 = 2.0f * nl * nv / ((1.0f - a) * 2.0f * nl * nv + a * (nl + nv));
        out[i] = g2 / (4.0f * nl * nv);
    }
}

static const peer_term_entry terms[] = {
    { "fresnel_schlick", tb_fresnel_b }, { "ggx_d", tb_ggx_d_b }, { "smith_g1", tb_g1_b }, { "smith_g2", tb_g2_b },
    { "smith_vis", tb_vis_b }, { "smith_g1_hammon", tb_g1h_b }, { "smith_vis_hammon", tb_vish_b }, { NULL, NULL },
};

const peer_set peer_textbook = {
    "textbook", "-O2 (gcc/clang default fp: no contraction, math-errno)", NULL, tb_brdf, terms,
};
