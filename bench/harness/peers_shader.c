/* peers_shader.c - the "shader-style" peer: the operation sequences common
 * in engine shaders, written as SoA loops the compiler can auto-vectorize.
 * Built once per vector width and math mode (bench/bench.mk): -O3
 * -fno-math-errno -fno-trapping-math -ffp-contract=fast, PEER_WIDTH avx2 (-march=x86-64-v3) or
 * avx512 (-march=x86-64-v4) on x86, native elsewhere, and with -ffast-math
 * added (PEER_FASTMATH defined).  See peers.h. */
#include <math.h>
#include "facet/common.h"
#include "facet/detail/vis_fit.h"
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

/* ---- the rest of the kernel list (issue 21 item 0): each kernel's own
 * formula from its own inputs, written as a shader writes it (libm's
 * exp2f / expf / powf / logf where the formula has a power, as HLSL's exp2
 * / exp / pow / log; the divisions as written), the inputs clamped to the
 * kernel's domain (cosines N.L, N.V to [FACET_COS_MIN, 1], alpha to
 * [FACET_ALPHA_MIN, 1], L.V, T.H, B.H to [-1, 1], gamma to [0, 4], the rest
 * to [0, 1]) and a divisor floored where the kernel's contract defines the
 * value at that point (stated beside it); no NaN rule, no cancellation-free
 * rearrangement. ---------------------------------------------------------- */
static inline float lov_(float x) { return clamp_(x, -1.0f, 1.0f); }

/* Cook-Torrance's Fresnel equations as printed: eta = (1 + sqrt f0) /
 * (1 - sqrt f0), g = sqrt(eta^2 - 1 + c^2),
 * F = 0.5 ((g - c)/(g + c))^2 (1 + (((g + c) c - 1)/((g - c) c + 1))^2);
 * sqrt f0 capped at 1 - 2^-20 (the kernel's f0 = 1 mirror, where eta is
 * infinite) */
static void sh_fct_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x0 = in[0], *restrict x1 = in[1];
    size_t i;
    for (i = 0; i < n; i++) {
        float s = sqrtf(sat_(x0[i])), c = sat_(x1[i]);
        float eta, g, a, b;
        s = s < 0.999999f ? s : 0.999999f;
        eta = (1.0f + s) / (1.0f - s);
        g = sqrtf(eta * eta - 1.0f + c * c);
        a = (g - c) / (g + c);
        b = ((g + c) * c - 1.0f) / ((g - c) * c + 1.0f);
        out[i] = 0.5f * a * a * (1.0f + b * b);
    }
}
/* f0 + (f90 - f0) (1 - c)^5 */
static void sh_f90_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x0 = in[0], *restrict x1 = in[1], *restrict x2 = in[2];
    size_t i;
    for (i = 0; i < n; i++) {
        float f0 = sat_(x0[i]);
        out[i] = f0 + (sat_(x1[i]) - f0) * pow5_(1.0f - sat_(x2[i]));
    }
}
/* f0 + (1 - f0) exp2((-5.55473 c - 6.98316) c) */
static void sh_fsg_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x0 = in[0], *restrict x1 = in[1];
    size_t i;
    for (i = 0; i < n; i++) {
        float f0 = sat_(x0[i]), c = sat_(x1[i]);
        out[i] = f0 + (1.0f - f0) * exp2f((-5.55473f * c - 6.98316f) * c);
    }
}
/* N.H^p / (pi alpha^2), p = 2 / alpha^2 - 2 */
static void sh_blinn_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x0 = in[0], *restrict x1 = in[1];
    size_t i;
    for (i = 0; i < n; i++) {
        float a = amax_(x1[i]), a2 = a * a;
        out[i] = powf(sat_(x0[i]), 2.0f / a2 - 2.0f) * (INV_PI_F / a2);
    }
}
/* exp((N.H^2 - 1) / (alpha^2 N.H^2)) / (pi alpha^2 N.H^4); N.H^2 floored at
 * 1e-12 (the kernel's D(0) = 0: the exponential underflows there) */
static void sh_beckmann_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x0 = in[0], *restrict x1 = in[1];
    size_t i;
    for (i = 0; i < n; i++) {
        float nh = sat_(x0[i]), a = amax_(x1[i]), a2 = a * a, c2 = nh * nh;
        c2 = c2 > 1e-12f ? c2 : 1e-12f;
        out[i] = expf((c2 - 1.0f) / (a2 * c2)) / (3.14159265f * a2 * c2 * c2);
    }
}
/* UE4's anisotropic GGX: a2 = ax ay, S = |(ay T.H, ax B.H, a2 N.H)|^2,
 * D = a2 (a2 / S)^2 / pi; S floored at a2^2 / 2 (the kernel's bracket floor
 * for inputs no unit h has) */
static void sh_aniso_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x0 = in[0], *restrict x1 = in[1], *restrict x2 = in[2];
    const float *restrict x3 = in[3], *restrict x4 = in[4];
    size_t i;
    for (i = 0; i < n; i++) {
        float ax = amax_(x3[i]), ay = amax_(x4[i]), a2 = ax * ay;
        float t = ay * lov_(x1[i]), b = ax * lov_(x2[i]), nh = a2 * sat_(x0[i]);
        float s = t * t + b * b + nh * nh, fl = 0.5f * a2 * a2, q;
        s = s > fl ? s : fl;
        q = a2 / s;
        out[i] = INV_PI_F * a2 * q * q;
    }
}
/* GTR: c / (1 + (alpha^2 - 1) N.H^2)^gamma, c = E(L) / (pi E((1 - gamma) L)),
 * L = ln alpha^2, E(y) = expm1(y) / y (1 at y = 0: the limits gamma = 1 and
 * alpha = 1 without a branch of their own) */
static inline float e_(float y) { return y != 0.0f ? expm1f(y) / y : 1.0f; }
static void sh_gtr_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x0 = in[0], *restrict x1 = in[1], *restrict x2 = in[2];
    size_t i;
    for (i = 0; i < n; i++) {
        float nh = sat_(x0[i]), a = amax_(x1[i]), g = clamp_(x2[i], 0.0f, 4.0f), a2 = a * a;
        float l = logf(a2), c = e_(l) / (3.14159265f * e_((1.0f - g) * l));
        out[i] = c / powf(1.0f + (a2 - 1.0f) * nh * nh, g);
    }
}
/* G1(N.L) G1(N.V), G1 = 2 n / (n + sqrt(a2 + (1 - a2) n^2)) */
static inline float sh_g1_(float nv, float a)
{
    float a2 = a * a;
    return 2.0f * nv / (nv + sqrtf(a2 + (1.0f - a2) * nv * nv));
}
static void sh_g2u_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x = in[0], *restrict y = in[1], *restrict al = in[2];
    size_t i;
    for (i = 0; i < n; i++) {
        float a = amax_(al[i]);
        out[i] = sh_g1_(cmax_(x[i]), a) * sh_g1_(cmax_(y[i]), a);
    }
}
/* Smith G1 for GTR (Dimov), the kernel's formula: the closed forms at gamma
 * = 0 .. 4 in N.V (facet.h's contract) and the monotone cubic Hermite
 * interpolant (Fritsch-Carlson) between them */
static inline float pchip_end_(float d0, float d1)
{
    float m = (3.0f * d0 - d1) * 0.5f;
    if (m * d0 <= 0.0f)
        return 0.0f;
    if (d0 * d1 <= 0.0f && fabsf(m) > 3.0f * fabsf(d0))
        return 3.0f * d0;
    return m;
}
static inline float pchip_mid_(float d0, float d1)
{
    return d0 * d1 > 0.0f ? 2.0f * d0 * d1 / (d0 + d1) : 0.0f;
}
static void sh_g1gtr_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x0 = in[0], *restrict x1 = in[1], *restrict x2 = in[2];
    size_t i;
    for (i = 0; i < n; i++) {
        float nv = sat_(x0[i]), a = amax_(x1[i]), G = clamp_(x2[i], 0.0f, 4.0f), y[5], d[4], m[5], t;
        float a2 = a * a, s2 = 1.0f - nv * nv, w = sqrtf(nv * nv + a2 * s2), w3 = w * w * w;
        float l = logf(a2), e = e_(l), q = (w + 1.0f) * (nv + w), u = (1.0f - a2) * s2 / q;
        float r = u > 0.0f ? log1pf(u) / u : 1.0f;
        float k = 8.0f * (a2 * a2 + a2 + 1.0f), p5 = 5.0f * a2 * a2 + 2.0f * a2 + 1.0f;
        float p2 = 2.0f * a2 * a2 + a2 + 1.0f;
        int j;
        y[0] = 2.0f * nv / (1.0f + nv);
        y[1] = nv / (nv + e * s2 * (w + nv * (1.0f - r)) / q);
        y[2] = 2.0f * nv / (nv + w);
        y[3] = 4.0f * (1.0f + a2) * nv * w / (a2 * (3.0f * a2 + 1.0f) * s2 + 2.0f * (1.0f + a2) * nv * (nv + w));
        y[4] = 2.0f * k * nv * w3 /
               (k * nv * (w3 + nv * nv * nv) + 3.0f * a2 * (a2 * p5 * s2 * s2 + 4.0f * nv * nv * s2 * p2));
        if (nv == 0.0f) {
            out[i] = 0.0f;
            continue;
        }
        for (j = 0; j < 4; j++)
            d[j] = y[j + 1] - y[j];
        for (j = 1; j < 4; j++)
            m[j] = pchip_mid_(d[j - 1], d[j]);
        m[0] = pchip_end_(d[0], d[1]);
        m[4] = pchip_end_(d[3], d[2]);
        j = G >= 3.0f ? 3 : (int)G;
        t = G - (float)j;
        out[i] = (1.0f + 2.0f * t) * (1.0f - t) * (1.0f - t) * y[j] + t * t * (3.0f - 2.0f * t) * y[j + 1] +
                 t * (1.0f - t) * (1.0f - t) * m[j] - t * t * (1.0f - t) * m[j + 1];
    }
}
/* N.L N.V */
static void sh_gimp_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x = in[0], *restrict y = in[1];
    size_t i;
    for (i = 0; i < n; i++)
        out[i] = sat_(x[i]) * sat_(y[i]);
}
/* Karis's N.L N.V / max(N.L, N.V); the max floored at 2^-126 (the kernel's
 * 0 at N.L = N.V = 0, where the quotient is 0/0) */
static void sh_gneu_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x = in[0], *restrict y = in[1];
    size_t i;
    for (i = 0; i < n; i++) {
        float nl = sat_(x[i]), nv = sat_(y[i]), m = nl > nv ? nl : nv;
        out[i] = nl * nv / (m > 1.17549435e-38f ? m : 1.17549435e-38f);
    }
}
/* min(1, 2 N.H N.V / V.H, 2 N.H N.L / V.H); V.H floored at 2^-126 (the
 * kernel's cap at V.H = 0) */
static void sh_gct_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x0 = in[0], *restrict x1 = in[1], *restrict x2 = in[2], *restrict x3 = in[3];
    size_t i;
    for (i = 0; i < n; i++) {
        float nl = cmax_(x0[i]), nv = cmax_(x1[i]), nh = sat_(x2[i]), vh = sat_(x3[i]);
        float k = 2.0f * nh / (vh > 1.17549435e-38f ? vh : 1.17549435e-38f);
        float g = k * nv < k * nl ? k * nv : k * nl;
        out[i] = g < 1.0f ? g : 1.0f;
    }
}
/* min(1, N.L N.V / V.H^2); V.H^2 floored at 2^-126 (the kernel's cap) */
static void sh_gkel_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x0 = in[0], *restrict x1 = in[1], *restrict x2 = in[2];
    size_t i;
    for (i = 0; i < n; i++) {
        float vh = sat_(x2[i]), v2 = vh * vh, g;
        g = cmax_(x0[i]) * cmax_(x1[i]) / (v2 > 1.17549435e-38f ? v2 : 1.17549435e-38f);
        out[i] = g < 1.0f ? g : 1.0f;
    }
}
/* Walter's rational: c = N.V / (alpha sqrt(1 - N.V^2)), c < 1.6:
 * min(1, (3.535 c + 2.181 c^2) / (1 + 2.276 c + 2.577 c^2)), else 1 (c is
 * +Inf at N.V = 1: the else) */
static void sh_g1b_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x = in[0], *restrict al = in[1];
    size_t i;
    for (i = 0; i < n; i++) {
        float nv = sat_(x[i]), c = nv / (amax_(al[i]) * sqrtf(1.0f - nv * nv));
        float g = (3.535f * c + 2.181f * c * c) / (1.0f + 2.276f * c + 2.577f * c * c);
        g = g < 1.0f ? g : 1.0f;
        out[i] = c < 1.6f ? g : 1.0f;
    }
}
/* Schlick-Beckmann: n / (n (1 - k) + k), k = alpha sqrt(2 / pi) */
static void sh_g1sb_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x = in[0], *restrict al = in[1];
    size_t i;
    for (i = 0; i < n; i++) {
        float k = amax_(al[i]) * 0.797884561f, nv = sat_(x[i]);
        out[i] = nv / (nv * (1.0f - k) + k);
    }
}
/* UE4: 0.5 / (N.L (N.V (1 - a) + a) + N.V (N.L (1 - a) + a)) */
static void sh_visj_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x = in[0], *restrict y = in[1], *restrict al = in[2];
    size_t i;
    for (i = 0; i < n; i++) {
        float nl = cmax_(x[i]), nv = cmax_(y[i]), a = amax_(al[i]);
        out[i] = 0.5f / (nl * (nv * (1.0f - a) + a) + nv * (nl * (1.0f - a) + a));
    }
}
/* the fitted visibility: 0.5 / (N.V r~(N.L) + N.L r~(N.V)), r~(x) = the
 * largest of three lines in a and t = x (1 + a (c1 + c2 a)), the constants
 * of facet/detail/vis_fit.h (stored as 2 k_i, halved here) */
static inline float sh_fit_r(float x, float a)
{
    float t = x * (1.0f + a * (FACET_VIS_FIT_C1 + FACET_VIS_FIT_C2 * a));
    float l1 = 0.5f * FACET_VIS_FIT_K1 * a;
    float l2 = 0.5f * (FACET_VIS_FIT_K2 * a + FACET_VIS_FIT_K3 * t);
    float l3 = 0.5f * (FACET_VIS_FIT_K4 * a + FACET_VIS_FIT_K5 * t);
    float m = l1 > l2 ? l1 : l2;
    return m > l3 ? m : l3;
}
static void sh_visfit_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x = in[0], *restrict y = in[1], *restrict al = in[2];
    size_t i;
    for (i = 0; i < n; i++) {
        float nl = cmax_(x[i]), nv = cmax_(y[i]), a = amax_(al[i]);
        out[i] = 0.5f / (nv * sh_fit_r(nl, a) + nl * sh_fit_r(nv, a));
    }
}
/* Burley: albedo / pi (1 + (fd90 - 1)(1 - N.L)^5)(1 + (fd90 - 1)(1 - N.V)^5),
 * fd90 = 0.5 + 2 sqrt(alpha) L.H^2 */
static void sh_burley_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x0 = in[0], *restrict x1 = in[1], *restrict x2 = in[2];
    const float *restrict x3 = in[3], *restrict x4 = in[4];
    size_t i;
    for (i = 0; i < n; i++) {
        float lh = sat_(x2[i]), fd = 2.0f * sqrtf(amax_(x3[i])) * lh * lh - 0.5f;
        out[i] = sat_(x4[i]) * INV_PI_F * (1.0f + fd * pow5_(1.0f - cmax_(x0[i]))) *
                 (1.0f + fd * pow5_(1.0f - cmax_(x1[i])));
    }
}
/* Oren-Nayar qualitative, sigma = alpha / 2: albedo / pi (A + B max(0, L.V -
 * N.L N.V) / max(N.L, N.V)) */
static void sh_on_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x0 = in[0], *restrict x1 = in[1], *restrict x2 = in[2];
    const float *restrict x3 = in[3], *restrict x4 = in[4];
    size_t i;
    for (i = 0; i < n; i++) {
        float nl = cmax_(x0[i]), nv = cmax_(x1[i]), a = amax_(x3[i]), s2 = 0.25f * a * a;
        float A = 1.0f - 0.5f * s2 / (s2 + 0.33f), B = 0.45f * s2 / (s2 + 0.09f);
        float s = lov_(x2[i]) - nl * nv;
        s = s > 0.0f ? s : 0.0f;
        out[i] = sat_(x4[i]) * INV_PI_F * (A + B * s / (nl > nv ? nl : nv));
    }
}
/* diffuse_hammon with another smooth term (hybrid: Disney's at f_d90 = 1/2;
 * cheap: 1), N.H from the dots as sh_dh_b */
static inline float sh_dvar(float nl, float nv, float lv, float a, float albedo, float smooth)
{
    float noh = sat_((nl + nv) * sh_inv_len_h(lv)), facing = 0.5f + 0.5f * lv;
    float rough = facing * (0.9f - 0.4f * facing) * ((0.5f + noh) / noh);
    float single = (smooth + a * (rough - smooth)) * INV_PI_F;
    return albedo * (single + albedo * (0.1159f * a));
}
static void sh_dhy_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x0 = in[0], *restrict x1 = in[1], *restrict x2 = in[2];
    const float *restrict x3 = in[3], *restrict x4 = in[4];
    size_t i;
    for (i = 0; i < n; i++) {
        float nl = cmax_(x0[i]), nv = cmax_(x1[i]);
        float smooth = (1.0f - 0.5f * pow5_(1.0f - nl)) * (1.0f - 0.5f * pow5_(1.0f - nv));
        out[i] = sh_dvar(nl, nv, lov_(x2[i]), amax_(x3[i]), sat_(x4[i]), smooth);
    }
}
static void sh_dch_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x0 = in[0], *restrict x1 = in[1], *restrict x2 = in[2];
    const float *restrict x3 = in[3], *restrict x4 = in[4];
    size_t i;
    for (i = 0; i < n; i++)
        out[i] = sh_dvar(cmax_(x0[i]), cmax_(x1[i]), lov_(x2[i]), amax_(x3[i]), sat_(x4[i]), 1.0f);
}
/* albedo / pi */
static void sh_lambert_b(float *restrict out, const float *const *in, size_t n)
{
    const float *restrict x = in[0];
    size_t i;
    for (i = 0; i < n; i++)
        out[i] = sat_(x[i]) * INV_PI_F;
}

static const peer_term_entry terms_[] = {
    { "brdf_hammon", sh_brdf_hammon_b }, { "noh_from_dots", sh_noh_b }, { "loh_from_dots", sh_loh_b },
    { "smith_g2_hammon", sh_g2h_b }, { "diffuse_hammon", sh_dh_b },
    { "fresnel_schlick", sh_fresnel_b }, { "ggx_d", sh_ggx_d_b }, { "smith_g1", sh_g1_b }, { "smith_g2", sh_g2_b },
    { "smith_vis", sh_vis_b }, { "smith_g1_hammon", sh_g1h_b }, { "smith_vis_hammon", sh_vish_b },
    { "fresnel_cook_torrance", sh_fct_b }, { "fresnel_schlick_f90", sh_f90_b }, { "fresnel_schlick_sg", sh_fsg_b },
    { "blinn_phong_d", sh_blinn_b }, { "beckmann_d", sh_beckmann_b }, { "ggx_aniso_d", sh_aniso_b },
    { "gtr_d", sh_gtr_b }, { "smith_g2_uncorrelated", sh_g2u_b }, { "smith_g1_gtr", sh_g1gtr_b },
    { "g_implicit", sh_gimp_b }, { "g_neumann", sh_gneu_b }, { "g_cook_torrance", sh_gct_b },
    { "g_kelemen", sh_gkel_b }, { "smith_g1_beckmann", sh_g1b_b }, { "smith_g1_schlick_beckmann", sh_g1sb_b },
    { "smith_vis_joint_approx", sh_visj_b }, { "smith_vis_fit", sh_visfit_b }, { "diffuse_burley", sh_burley_b },
    { "diffuse_oren_nayar", sh_on_b }, { "diffuse_hammon_hybrid", sh_dhy_b }, { "diffuse_hammon_cheap", sh_dch_b },
    { "lambert", sh_lambert_b }, { NULL, NULL },
};

const peer_set SET_ = { NAME_, BUILD_, WIDTH_, sh_brdf, terms_ };
#endif
