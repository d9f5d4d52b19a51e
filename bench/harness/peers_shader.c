/* peers_shader.c - the "shader-style" peer: the operation sequences common
 * in engine shaders, written as SoA loops the compiler can auto-vectorize.
 * Built once per vector width and math mode (bench/bench.mk): -O3
 * -fno-math-errno -fno-trapping-math -ffp-contract=fast, PEER_WIDTH avx2 (-march=x86-64-v3) or
 * avx512 (-march=x86-64-v4) on x86, native elsewhere, and with -ffast-math
 * added (PEER_FASTMATH defined).  See peers.h. */
#include <math.h>
#include "facet/common.h"
#include "peers.h"

#define PEER_CAT_(a, b) a##b
#define PEER_CAT(a, b) PEER_CAT_(a, b)
#define PEER_STR_(x) #x
#define PEER_STR(x) PEER_STR_(x)
#ifdef PEER_WIDTH /* x86: the facet port of the same width */
#define BASE_ PEER_CAT(peer_shader_, PEER_WIDTH)
#define BASE_NAME_ "shader_" PEER_STR(PEER_WIDTH)
#define WIDTH_ PEER_STR(PEER_WIDTH)
#define MARCH_ PEER_MARCH
#else
#define BASE_ peer_shader
#define BASE_NAME_ "shader"
#define WIDTH_ NULL
#define MARCH_ "-march=native"
#endif
#ifdef PEER_FASTMATH
#define SET_ PEER_CAT(BASE_, _fm)
#define NAME_ BASE_NAME_ "_fm"
#define BUILD_ "-O3 " MARCH_ " -fno-math-errno -fno-trapping-math -ffp-contract=fast -ffast-math"
#else
#define SET_ BASE_
#define NAME_ BASE_NAME_
#define BUILD_ "-O3 " MARCH_ " -fno-math-errno -fno-trapping-math -ffp-contract=fast"
#endif

#define INV_PI_F 0.318309886f

/* clamps as two unconditional compares (HLSL's saturate / clamp): without
 * -ffast-math the compiler if-converts them (a nested ?: would make the
 * second compare conditional, which it may not speculate) */
static inline float clamp_(float x, float lo, float hi)
{
    x = x > lo ? x : lo;
    return x < hi ? x : hi;
}
static inline float sat_(float x) { return clamp_(x, 0.0f, 1.0f); }
static inline float cmax_(float x) { return clamp_(x, FACET_COS_MIN, 1.0f); }
static inline float amax_(float x) { return clamp_(x, FACET_ALPHA_MIN, 1.0f); }
static inline float pow5_(float x) { float x2 = x * x; return x2 * x2 * x; }

/* a2 / (pi (noh^2 (a2 - 1) + 1)^2) */
static inline float sh_d(float noh, float a)
{
    float a2 = a * a;
    float d = noh * noh * (a2 - 1.0f) + 1.0f;
    return a2 / (d * d) * INV_PI_F;
}

/* 0.5 / (nl sqrt(nv^2 (1 - a2) + a2) + nv sqrt(nl^2 (1 - a2) + a2)) */
static inline float sh_vis(float nl, float nv, float a)
{
    float a2 = a * a;
    float gv = nl * sqrtf(nv * nv * (1.0f - a2) + a2);
    float gl = nv * sqrtf(nl * nl * (1.0f - a2) + a2);
    return 0.5f / (gv + gl);
}

static inline float sh_f(float f0, float c) { return f0 + (1.0f - f0) * pow5_(1.0f - c); }

static inline float sh_diffuse(float nl, float nv, float lv, float noh, float a, float albedo)
{
    float facing = 0.5f + 0.5f * lv;
    float rough = facing * (0.9f - 0.4f * facing) * ((0.5f + noh) / noh);
    float smooth = 1.05f * (1.0f - pow5_(1.0f - nl)) * (1.0f - pow5_(1.0f - nv));
    float single = (smooth + a * (rough - smooth)) * INV_PI_F;
    return albedo * (single + albedo * (0.1159f * a));
}

static void sh_brdf(float *restrict out, const peer_brdf_in *in, size_t n)
{
    const float *restrict lx = in->lx, *restrict ly = in->ly, *restrict lz = in->lz;
    const float *restrict vx = in->vx, *restrict vy = in->vy, *restrict vz = in->vz;
    const float *restrict al = in->alpha, *restrict f0 = in->f0, *restrict alb = in->albedo;
    size_t i;
    for (i = 0; i < n; i++) {
        float hx = lx[i] + vx[i], hy = ly[i] + vy[i], hz = lz[i] + vz[i];
        float inv = 1.0f / sqrtf(hx * hx + hy * hy + hz * hz);
        float noh = sat_(hz * inv);
        float loh = sat_((lx[i] * hx + ly[i] * hy + lz[i] * hz) * inv);
        float lv = lx[i] * vx[i] + ly[i] * vy[i] + lz[i] * vz[i];
        float nl = cmax_(lz[i]), nv = cmax_(vz[i]), a = amax_(al[i]);
        float spec = sh_d(noh, a) * sh_vis(nl, nv, a) * sh_f(f0[i], loh);
        out[i] = spec + sh_diffuse(nl, nv, lv, noh, a, alb[i]);
    }
}

/* brdf_hammon's own formula as a shader writes it (same-formula peer), from
 * the same dots as facet (N.L, N.V, L.V, alpha, f0, albedo): N.H and L.H from
 * one rsqrt of |L + V|^2 = 2 + 2 L.V (as engines derive them from the dots),
 * D in the (N.H a2 - N.H) N.H + 1 form, Hammon's Vis
 * 0.5 / (2 N.L N.V + (N.L + N.V - 2 N.L N.V) alpha), pow5 by multiplication,
 * Hammon's diffuse.  L.V clamped and 2 + 2 L.V floored, as a shader does to
 * keep the rsqrt finite; no exact peak arithmetic, no NaN rule. */
/* 1 / |L + V| = rsqrt(2 + 2 L.V), floored as a shader does to keep it finite */
static inline float sh_inv_len_h(float lv)
{
    float l2 = 2.0f + 2.0f * lv;
    return 1.0f / sqrtf(l2 > 1e-12f ? l2 : 1e-12f);
}

static inline float sh_brdf_hammon_1(float x0, float x1, float x2, float x3, float x4, float x5)
{
    float nl = cmax_(x0), nv = cmax_(x1), a = amax_(x3);
    float lv = clamp_(x2, -1.0f, 1.0f);
    float inv_len_h = sh_inv_len_h(lv);
    float noh = sat_((nl + nv) * inv_len_h);
    float loh = sat_(inv_len_h + inv_len_h * lv);
    float a2 = a * a;
    float d = (noh * a2 - noh) * noh + 1.0f;
    float p = 2.0f * nl * nv;
    float vis = 0.5f / (p + (nl + nv - p) * a);
    float spec = a2 / (d * d) * INV_PI_F * vis * sh_f(x4, loh);
    return spec + sh_diffuse(nl, nv, lv, noh, a, x5);
}

#ifdef PEER_PERCALL
/* bench/harness/percall.h: the same formula one sample per iteration, the
 * loop not vectorized (bench.mk builds this object -O2 -fno-tree-vectorize
 * -ffast-math for the per-call comparison of `facet-bench api`) */
#include "percall.h"
void percall_peer(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x0 = in[0], *restrict x1 = in[1], *restrict x2 = in[2];
    const float *restrict x3 = in[3], *restrict x4 = in[4], *restrict x5 = in[5];
    size_t i;
    for (i = 0; i < n; i++)
        out[i] = sh_brdf_hammon_1(x0[i], x1[i], x2[i], x3[i], x4[i], x5[i]);
}
#else
static void sh_brdf_hammon_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x0 = in[0], *restrict x1 = in[1], *restrict x2 = in[2];
    const float *restrict x3 = in[3], *restrict x4 = in[4], *restrict x5 = in[5];
    size_t i;
    for (i = 0; i < n; i++)
        out[i] = sh_brdf_hammon_1(x0[i], x1[i], x2[i], x3[i], x4[i], x5[i]);
}

static void sh_fresnel_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict f0 = in[0], *restrict c = in[1];
    size_t i;
    for (i = 0; i < n; i++)
        out[i] = sh_f(f0[i], c[i]);
}
static void sh_ggx_d_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x = in[0], *restrict a = in[1];
    size_t i;
    for (i = 0; i < n; i++)
        out[i] = sh_d(x[i], amax_(a[i]));
}
/* G1 = 2 n / (n + sqrt(a2 + (1 - a2) n^2)) */
static void sh_g1_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x = in[0], *restrict al = in[1];
    size_t i;
    for (i = 0; i < n; i++) {
        float a = amax_(al[i]), a2 = a * a, nv = x[i];
        out[i] = 2.0f * nv / (nv + sqrtf(a2 + (1.0f - a2) * nv * nv));
    }
}
static void sh_g2_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x = in[0], *restrict y = in[1], *restrict al = in[2];
    size_t i;
    for (i = 0; i < n; i++) {
        float nl = cmax_(x[i]), nv = cmax_(y[i]);
        out[i] = 4.0f * nl * nv * sh_vis(nl, nv, amax_(al[i]));
    }
}
static void sh_vis_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x = in[0], *restrict y = in[1], *restrict al = in[2];
    size_t i;
    for (i = 0; i < n; i++)
        out[i] = sh_vis(cmax_(x[i]), cmax_(y[i]), amax_(al[i]));
}
/* Schlick-GGX, k = alpha/2: n / (n (1 - k) + k) */
static void sh_g1h_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x = in[0], *restrict al = in[1];
    size_t i;
    for (i = 0; i < n; i++) {
        float k = amax_(al[i]) * 0.5f, nv = x[i];
        out[i] = nv / (nv * (1.0f - k) + k);
    }
}
/* 0.5 / lerp(2 nl nv, nl + nv, a) */
static void sh_vish_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x = in[0], *restrict y = in[1], *restrict al = in[2];
    size_t i;
    for (i = 0; i < n; i++) {
        float nl = cmax_(x[i]), nv = cmax_(y[i]), a = amax_(al[i]);
        float p = 2.0f * nl * nv;
        out[i] = 0.5f / (p + a * (nl + nv - p));
    }
}

/* the terms brdf_hammon is made of, each from the same inputs as its facet
 * kernel: N.H and L.H from the dots (one rsqrt of 2 + 2 L.V), Hammon's G2,
 * Hammon's diffuse (N.H from the dots, (0.5 + N.H) / N.H as written) */
static void sh_noh_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x = in[0], *restrict y = in[1], *restrict z = in[2];
    size_t i;
    for (i = 0; i < n; i++)
        out[i] = sat_((cmax_(x[i]) + cmax_(y[i])) * sh_inv_len_h(clamp_(z[i], -1.0f, 1.0f)));
}
static void sh_loh_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x = in[0];
    size_t i;
    for (i = 0; i < n; i++) {
        float lv = clamp_(x[i], -1.0f, 1.0f), inv = sh_inv_len_h(lv);
        out[i] = sat_(inv + inv * lv);
    }
}
/* 2 nl nv / lerp(2 nl nv, nl + nv, a) */
static void sh_g2h_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x = in[0], *restrict y = in[1], *restrict al = in[2];
    size_t i;
    for (i = 0; i < n; i++) {
        float nl = cmax_(x[i]), nv = cmax_(y[i]), a = amax_(al[i]);
        float p = 2.0f * nl * nv;
        out[i] = p / (p + a * (nl + nv - p));
    }
}
static void sh_dh_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x0 = in[0], *restrict x1 = in[1], *restrict x2 = in[2];
    const float *restrict x3 = in[3], *restrict x4 = in[4];
    size_t i;
    for (i = 0; i < n; i++) {
        float nl = cmax_(x0[i]), nv = cmax_(x1[i]), lv = clamp_(x2[i], -1.0f, 1.0f);
        float noh = sat_((nl + nv) * sh_inv_len_h(lv));
        out[i] = sh_diffuse(nl, nv, lv, noh, amax_(x3[i]), x4[i]);
    }
}

static const peer_term_entry terms_[] = {
    { "brdf_hammon", sh_brdf_hammon_b }, { "noh_from_dots", sh_noh_b }, { "loh_from_dots", sh_loh_b },
    { "smith_g2_hammon", sh_g2h_b }, { "diffuse_hammon", sh_dh_b },
    { "fresnel_schlick", sh_fresnel_b }, { "ggx_d", sh_ggx_d_b }, { "smith_g1", sh_g1_b }, { "smith_g2", sh_g2_b },
    { "smith_vis", sh_vis_b }, { "smith_g1_hammon", sh_g1h_b }, { "smith_vis_hammon", sh_vish_b }, { NULL, NULL },
};

const peer_set SET_ = { NAME_, BUILD_, WIDTH_, sh_brdf, terms_ };
#endif
