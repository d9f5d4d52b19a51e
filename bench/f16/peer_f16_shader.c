/* peer_f16_shader.c - the binary16 transcription of the shader-style peer
 * (bench/harness/peers_shader.c's brdf_hammon and terms, from the same dots)
 * in _Float16, built as a mobile shader's mediump is: -O3
 * -march=sapphirerapids -mprefer-vector-width=512 -ffast-math
 * (bench/f16.mk; this object alone).  No exact peak, no NaN rule, no
 * saturation: the bench measures what that costs in accuracy too. */
#include <stddef.h>
#include <stdint.h>
#include "f16/f16_peer.h"

typedef _Float16 h;
#define H(x) ((h)(x))

static inline h clamp_(h x, h lo, h hi)
{
    x = x > lo ? x : lo;
    return x < hi ? x : hi;
}
static inline h sat_(h x) { return clamp_(x, H(0.0f), H(1.0f)); }
static inline h cmax_(h x) { return clamp_(x, H(0.0078125f), H(1.0f)); }
static inline h amax_(h x) { return clamp_(x, H(0.0078125f), H(1.0f)); }
static inline h pow5_(h x) { h x2 = x * x; return x2 * x2 * x; }
static inline h sqrt_(h x) { return (h)__builtin_sqrtf((float)x); }
static inline h inv_len_h_(h lv)
{
    h l2 = H(2.0f) + H(2.0f) * lv;
    return H(1.0f) / sqrt_(l2 > H(6.1e-5f) ? l2 : H(6.1e-5f));
}
static inline h sh_f(h f0, h c) { return f0 + (H(1.0f) - f0) * pow5_(H(1.0f) - c); }
static inline h sh_diffuse(h nl, h nv, h lv, h noh, h a, h albedo)
{
    h facing = H(0.5f) + H(0.5f) * lv;
    h rough = facing * (H(0.9f) - H(0.4f) * facing) * ((H(0.5f) + noh) / noh);
    h smooth = H(1.05f) * (H(1.0f) - pow5_(H(1.0f) - nl)) * (H(1.0f) - pow5_(H(1.0f) - nv));
    h single = (smooth + a * (rough - smooth)) * H(0.318309886f);
    return albedo * (single + albedo * (H(0.1159f) * a));
}

#define IN_(q) const h *restrict x##q = (const h *)in[q]
static void brdf_(uint16_t *o_, const uint16_t *const *in, size_t n)
{
    h *restrict o = (h *)o_;
    IN_(0); IN_(1); IN_(2); IN_(3); IN_(4); IN_(5);
    size_t i;
    for (i = 0; i < n; i++) {
        h nl = cmax_(x0[i]), nv = cmax_(x1[i]), a = amax_(x3[i]);
        h lv = clamp_(x2[i], H(-1.0f), H(1.0f));
        h il = inv_len_h_(lv);
        h noh = sat_((nl + nv) * il);
        h loh = sat_(il + il * lv);
        h a2 = a * a;
        h d = (noh * a2 - noh) * noh + H(1.0f);
        h p = H(2.0f) * nl * nv;
        h vis = H(0.5f) / (p + (nl + nv - p) * a);
        h spec = a2 / (d * d) * H(0.318309886f) * vis * sh_f(x4[i], loh);
        o[i] = spec + sh_diffuse(nl, nv, lv, noh, a, x5[i]);
    }
}
static void ggx_d_(uint16_t *o_, const uint16_t *const *in, size_t n)
{
    h *restrict o = (h *)o_;
    IN_(0); IN_(1);
    size_t i;
    for (i = 0; i < n; i++) {
        h a = amax_(x1[i]), a2 = a * a, noh = x0[i];
        h d = noh * noh * (a2 - H(1.0f)) + H(1.0f);
        o[i] = a2 / (d * d) * H(0.318309886f);
    }
}
static void vis_(uint16_t *o_, const uint16_t *const *in, size_t n)
{
    h *restrict o = (h *)o_;
    IN_(0); IN_(1); IN_(2);
    size_t i;
    for (i = 0; i < n; i++) {
        h nl = cmax_(x0[i]), nv = cmax_(x1[i]), a = amax_(x2[i]), a2 = a * a;
        h gv = nl * sqrt_(nv * nv * (H(1.0f) - a2) + a2);
        h gl = nv * sqrt_(nl * nl * (H(1.0f) - a2) + a2);
        o[i] = H(0.5f) / (gv + gl);
    }
}
static void vish_(uint16_t *o_, const uint16_t *const *in, size_t n)
{
    h *restrict o = (h *)o_;
    IN_(0); IN_(1); IN_(2);
    size_t i;
    for (i = 0; i < n; i++) {
        h nl = cmax_(x0[i]), nv = cmax_(x1[i]), a = amax_(x2[i]);
        h p = H(2.0f) * nl * nv;
        o[i] = H(0.5f) / (p + a * (nl + nv - p));
    }
}
static void fresnel_(uint16_t *o_, const uint16_t *const *in, size_t n)
{
    h *restrict o = (h *)o_;
    IN_(0); IN_(1);
    size_t i;
    for (i = 0; i < n; i++)
        o[i] = sh_f(x0[i], x1[i]);
}
static void noh_(uint16_t *o_, const uint16_t *const *in, size_t n)
{
    h *restrict o = (h *)o_;
    IN_(0); IN_(1); IN_(2);
    size_t i;
    for (i = 0; i < n; i++)
        o[i] = sat_((cmax_(x0[i]) + cmax_(x1[i])) * inv_len_h_(clamp_(x2[i], H(-1.0f), H(1.0f))));
}
static void loh_(uint16_t *o_, const uint16_t *const *in, size_t n)
{
    h *restrict o = (h *)o_;
    IN_(0);
    size_t i;
    for (i = 0; i < n; i++) {
        h lv = clamp_(x0[i], H(-1.0f), H(1.0f)), il = inv_len_h_(lv);
        o[i] = sat_(il + il * lv);
    }
}
static void dh_(uint16_t *o_, const uint16_t *const *in, size_t n)
{
    h *restrict o = (h *)o_;
    IN_(0); IN_(1); IN_(2); IN_(3); IN_(4);
    size_t i;
    for (i = 0; i < n; i++) {
        h nl = cmax_(x0[i]), nv = cmax_(x1[i]), lv = clamp_(x2[i], H(-1.0f), H(1.0f));
        h noh = sat_((nl + nv) * inv_len_h_(lv));
        o[i] = sh_diffuse(nl, nv, lv, noh, amax_(x3[i]), x4[i]);
    }
}
static void lambert_(uint16_t *o_, const uint16_t *const *in, size_t n)
{
    h *restrict o = (h *)o_;
    IN_(0);
    size_t i;
    for (i = 0; i < n; i++)
        o[i] = sat_(x0[i]) * H(0.318309886f);
}

const f16_peer_entry f16_peer_shader[] = {
    { "brdf_hammon", brdf_ }, { "noh_from_dots", noh_ }, { "loh_from_dots", loh_ },
    { "fresnel_schlick", fresnel_ }, { "ggx_d", ggx_d_ }, { "smith_vis", vis_ },
    { "smith_vis_hammon", vish_ }, { "diffuse_hammon", dh_ }, { "lambert", lambert_ }, { NULL, NULL },
};
