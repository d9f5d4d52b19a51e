/* fx_kernels.c - the fixed-point kernels.  Integer arithmetic only (uint32
 * and uint64; products through fx_mul64), the portable specification every
 * port reproduces bit for bit.  Formats, domain and rounding: facet/fx.h.
 *
 * Notation: capitals are raw Q15 inputs after clamping (N = N.H 2^15, A =
 * alpha 2^15, NL, NV, F0, ...), S = NL + NV (Q15, <= 2^16), T = 2^15 + LOV
 * = (1 + L.V) 2^15 (<= 2^16).  "Q60 exact" means an integer that equals the
 * real value times 2^60 with no rounding; bounds in brackets are the reason
 * it fits its container.  fxf values (m 2^e, 32-bit m) carry the wide-range
 * intermediates; each fxf operation rounds once (<= 2^-32 relative).
 */
#include "facet/fx.h"
#include "fx_prims.h"
#include "../core/port.h"
#include "fx_ops_scalar.h"
#include "fx_body.h" /* the kernels written over lanes, here on one lane */

#define ONE 32768u

static uint32_t unit_(int32_t x) { return fxv_clamp(x, 0, FACET_FX_ONE); }
static uint32_t cos_(int32_t x) { return fxv_clamp(x, FACET_FX_COS_MIN, FACET_FX_ONE); }
static uint32_t alpha_(int32_t x) { return fxv_clamp(x, FACET_FX_ALPHA_MIN, FACET_FX_ONE); }
/* T = (1 + L.V) 2^15 in [0, 2^16] */
static uint32_t t_(int32_t lov) { return (uint32_t)(lov < -FACET_FX_ONE ? -FACET_FX_ONE : lov > FACET_FX_ONE ? FACET_FX_ONE : lov) + ONE; }

/* a 64-bit x times a 32-bit y, the product known to fit 64 bits */
static uint64_t mul64x32(uint64_t x, uint32_t y)
{
    return fx_mul64((uint32_t)x, y) + ((uint64_t)((uint32_t)(x >> 32) * y) << 32);
}

/* (1 + L.V) in Q31, raised to (N.L + N.V)^2 / 2 (the facet.h extension):
 * max(T 2^16, S^2) [<= 2^32: t <= 2 and s^2/2 <= 2]. */
static uint64_t t31_(uint32_t t, uint32_t s)
{
    uint64_t a = (uint64_t)t << 16, b = fx_mul64(s, s);
    return a > b ? a : b;
}

/* ---- noh_from_dots ----------------------------------------------------------
 * N.H = s / sqrt(2t), correctly rounded: raw = round(2^7 S / sqrt(T)) is the
 * largest k with (2k - 1)^2 T <= 2^16 S^2 [both sides <= 2^48].  If
 * 2^16 S^2 >= 2^32 T the triple is at or beyond N.H = 1 and the result is 1.
 * The estimate k0 (fxf sqrt and divide) is within 1; two exact compares fix it.
 * Error: 0 LSB (correctly rounded).  Cost: 1 sqrt, 1 division, ~8 mul64. */
int32_t facet_noh_from_dots_fx(int32_t nol, int32_t nov, int32_t lov)
{
    uint32_t s = cos_(nol) + cos_(nov), t = t_(lov), k;
    uint64_t s2 = fx_mul64(s, s) << 16; /* 2^16 S^2 <= 2^48 */
    if (s2 >= (uint64_t)t << 32)
        return FACET_FX_ONE;
    k = fxf_div_fixed(fxf_u64(s, 7), fxf_sqrt(fxf_u64(t, 0)), 0, ONE);
    while (k > 0 && mul64x32(fx_mul64(2 * k - 1, 2 * k - 1), t) > s2)
        k--;
    while (k < ONE && mul64x32(fx_mul64(2 * k + 1, 2 * k + 1), t) <= s2)
        k++;
    return (int32_t)k;
}

/* ---- loh_from_dots ----------------------------------------------------------
 * L.H = sqrt((1 + L.V) / 2): raw = round(sqrt(T 2^14)) [T 2^14 <= 2^30],
 * an exact integer square root.  L.V = -1 gives 0.
 * Error: 0 LSB (correctly rounded).  Cost: 1 isqrt. */
int32_t facet_loh_from_dots_fx(int32_t lov)
{
    return (int32_t)fx_isqrt64_rnd((uint64_t)t_(lov) << 14);
}

/* ---- Fresnel: src/fx/fx_body.h (written over lanes) ------------------------- */
int32_t facet_fresnel_schlick_fx(int32_t f0, int32_t cos_theta)
{
    return (int32_t)fxb_fresnel_schlick(f0, cos_theta);
}

/* ---- GGX D --------------------------------------------------------------------
 * D = alpha^2 / (pi d^2), d = 1 - n^2 (1 - alpha^2) = (1-n)(1+n) + (n alpha)^2.
 *   d60 = (2^15 - N)(2^15 + N) 2^30 + (N A)^2   Q60 exact [d <= 1: <= 2^60]
 *   raw = round(2^13 A^2 2^-30 / (pi (d60 2^-60)^2)), one rounded division
 *         of A^2 by the fxf pi d^2.
 * N.H = 1: D = 1/(pi alpha^2) and raw = round(2^43 / (pi A^2)) up to 2^31.3,
 * more than 32-bit intermediates can round exactly; computed as
 * floor(floor(2^64/pi) / 2^(21-s)) / (A^2 2^s), s = clz(A^2) in [1, 21], by
 * the exact 2-by-1 division: correctly rounded unless 2^43/(pi A^2) lies
 * within 2^-31 LSB of a rounding boundary (tested: never, all alpha).
 * Below the peak d >= 2^-14, so raw <= 2^23.3 and the fxf error (<= 4 roundings
 * of 2^-32) is < 2^-6 LSB.  Monotone in N (d exact and decreasing).
 * Cost: 1 division (+1 rcp), 3 fxf mul, 2 mul64. */
#define INV_PI_2_64 0x517CC1B727220A94ull /* floor(2^64 / pi) */
#define PI_M 0xC90FDAA2u                  /* round(pi 2^30), pi = PI_M 2^-30 */
#define INV_PI_M 0xA2F9836Eu              /* round(2^33 / pi), 1/pi = INV_PI_M 2^-33 */

uint32_t facet_ggx_d_fx(int32_t noh, int32_t alpha)
{
    uint32_t n = unit_(noh), a = alpha_(alpha), a2 = a * a; /* a2 <= 2^30 */
    uint64_t d60;
    fxf d, den;
    if (n == ONE) {
        int s = fx_clz32(a2);
        uint64_t u = fx_shr64(INV_PI_2_64, 21 - s);
        uint32_t dd = a2 << s, rem, q;
        q = fx_div64((uint32_t)(u >> 32), (uint32_t)u, dd, &rem);
        return q + (rem >= dd - rem); /* q < 2^31.4: no wrap */
    }
    d60 = ((uint64_t)((ONE - n) * (ONE + n)) << 30) + fx_mul64(n * a, n * a);
    d = fxf_u64(d60, -60);
    {
        fxf pi;
        pi.m = PI_M;
        pi.e = -30;
        den = fxf_mul(pi, fxf_mul(d, d));
    }
    return fxf_div_fixed(fxf_u64(a2, -30), den, FACET_FX_D_FRAC, FACET_FX_MAX_D);
}

/* ---- anisotropic GGX D ------------------------------------------------------
 * D = (ax ay)^3 / (pi K^2), K = (t ay)^2 + (b ax)^2 + (n ax ay)^2 (facet.h),
 * with P = AX AY Q30 exact [<= 2^30, >= 2^10], u = |T| AY, v = |B| AX Q30
 * exact [<= 2^30]:
 *   K90 = (u^2 + v^2) 2^30 + N^2 P^2    Q90 exact, held as hi 2^32 + lo
 *         [K <= 3: hi < 2^60], then rounded once to an fxf (hi >= 2^32:
 *         the rounding of hi alone is the rounding of the whole, lo below
 *         its last place; else the 64-bit value itself);
 *   floor K >= P^2 / 2 (k = K / P^2 >= 1/2, facet.h) by an exact compare;
 *   raw = round(2^13 (P / K)^2 P / pi): P/K, its square, times P, times
 *         1/pi (4 fxf roundings; the constant 2^-33.1), one rounding to
 *         the format (fxf_fixed, saturating).
 * The exact peak (N = 2^15, T = B = 0: D = 1/(pi ax ay)) is ggx_d's peak
 * with A^2 replaced by P: correctly rounded by the exact division.
 * Error: <= 5 K-and-fxf roundings of 2^-33 relative (1/pi's included),
 * 2^-30.7, plus the final half LSB: <= 1 LSB below raw 2^30; above (ax ay
 * < 2^-18, inputs near the peak) up to 2 LSB; measured in facet/fx.h.
 * Cost: 1 division, ~5 fxf, ~8 mul64. */
uint32_t facet_ggx_aniso_d_fx(int32_t noh, int32_t toh, int32_t boh, int32_t alpha_x, int32_t alpha_y)
{
    uint32_t n = unit_(noh), t = t_(toh), b = t_(boh), ax = alpha_(alpha_x), ay = alpha_(alpha_y);
    uint32_t p = ax * ay, u, v, n2 = n * n, lo, fl_lo;
    uint64_t s, p2 = fx_mul64(p, p), a, hi, fl_hi, low;
    fxf k, pf, q, ipi;
    t = t > ONE ? t - ONE : ONE - t; /* |T| */
    b = b > ONE ? b - ONE : ONE - b;
    if (n == ONE && t == 0 && b == 0) { /* the exact peak, as ggx_d's */
        int sh = fx_clz32(p);
        uint64_t w = fx_shr64(INV_PI_2_64, 21 - sh);
        uint32_t dd = p << sh, rem, qq;
        qq = fx_div64((uint32_t)(w >> 32), (uint32_t)w, dd, &rem);
        return qq + (rem >= dd - rem); /* < 2^31.4: no wrap */
    }
    u = t * ay;
    v = b * ax;
    s = fx_mul64(u, u) + fx_mul64(v, v); /* Q60 <= 2^61 */
    /* K90 = s 2^30 + n2 p2: p2 = H 2^32 + L; n2 L < 2^62, n2 H < 2^58 */
    a = fx_mul64(n2, (uint32_t)p2);
    low = (a & 0xFFFFFFFFu) + ((uint64_t)((uint32_t)s & 3u) << 30); /* < 2^33 */
    lo = (uint32_t)low;
    hi = fx_mul64(n2, (uint32_t)(p2 >> 32)) + (a >> 32) + (s >> 2) + (low >> 32);
    /* the floor P^2 / 2 in Q90: P^2 2^29 */
    fl_hi = p2 >> 3;
    fl_lo = (uint32_t)(p2 & 7u) << 29;
    if (hi < fl_hi || (hi == fl_hi && lo < fl_lo)) {
        hi = fl_hi;
        lo = fl_lo;
    }
    if (hi >> 32)
        k = fxf_u64(hi, -58);
    else
        k = fxf_u64((hi << 32) | lo, -90);
    pf = fxf_u64(p, -30);
    q = fxf_div(pf, k);
    ipi.m = INV_PI_M;
    ipi.e = -33;
    /* fxf_fixed, not fxf_div_fixed: raw reaches 2^31.3 (fxf_div_fixed stops below 2^31.6 - 2^30) */
    return (uint32_t)fxf_fixed(fxf_mul(fxf_mul(fxf_mul(q, q), pf), ipi), FACET_FX_D_FRAC, FACET_FX_MAX_D);
}

/* ---- Smith, exact ----------------------------------------------------------
 * w = alpha^2 (1 - n^2) + n^2 = A^2 (2^15-N)(2^15+N) + N^2 2^30   Q60 exact
 * [w <= 1]; sqrt(w) = fxf_sqrt64(w60): the root of the exact w, correctly
 * rounded to 32 significant bits (a fixed Q30 root would lose 2^-20
 * relative at sqrt(w) ~ alpha_min, 2^7 LSB of Vis at the grazing corner). */
static fxf smith_r_(uint32_t n, uint32_t a2)
{
    uint64_t w60 = fx_mul64(a2, (ONE - n) * (ONE + n)) + ((uint64_t)(n * n) << 30);
    return fxf_sqrt64(w60, -60);
}

/* G1 = 2n / (n + sqrt(w)), one rounded division of 2N by the fxf sum.
 * G1(0) = 0, G1(1) = 1 exactly (w = 1, the sum is 2).
 * Cost: 1 sqrt, 1 division, 1 fxf add, 3 mul. */
int32_t facet_smith_g1_fx(int32_t nov, int32_t alpha)
{
    uint32_t n = unit_(nov), a = alpha_(alpha);
    fxf den = fxf_add(fxf_u64(n, -15), smith_r_(n, a * a));
    return (int32_t)fxf_div_fixed(fxf_u64(2 * n, -15), den, 15, ONE);
}

/* nv sqrt(w(nl)) + nl sqrt(w(nv)) */
static fxf g2_den_(uint32_t nl, uint32_t nv, uint32_t a2)
{
    return fxf_add(fxf_mul(fxf_u64(nv, -15), smith_r_(nl, a2)),
                   fxf_mul(fxf_u64(nl, -15), smith_r_(nv, a2)));
}

/* G2 = 2 nl nv / den, one rounded division [2 NL NV <= 2^31 exact].
 * Cost: 2 sqrt, 1 division, 3 fxf ops, ~8 mul. */
int32_t facet_smith_g2_fx(int32_t nol, int32_t nov, int32_t alpha)
{
    uint32_t nl = cos_(nol), nv = cos_(nov), a = alpha_(alpha);
    return (int32_t)fxf_div_fixed(fxf_u64(fx_mul64(nl, nv) << 1, -30), g2_den_(nl, nv, a * a), 15, ONE);
}

/* Vis = 0.5 / den: UQ16.16, <= 0.5 / (2 c sqrt(a^2 + c^2 (1 - a^2))) =
 * 15894.3 at c = 2^-8, a = 2^-10 [raw < 2^30].  Cost: as smith_g2. */
uint32_t facet_smith_vis_fx(int32_t nol, int32_t nov, int32_t alpha)
{
    uint32_t nl = cos_(nol), nv = cos_(nov), a = alpha_(alpha);
    return fxf_div_fixed(fxf_u64(1, -1), g2_den_(nl, nv, a * a), FACET_FX_VIS_FRAC, FACET_FX_MAX_VIS);
}

/* G1(L) G1(V) = 4 nl nv / ((nl + sqrt w(nl)) (nv + sqrt w(nv))), one
 * reciprocal-based division.  Cost: 2 sqrt, 1 division, 3 fxf ops, ~8 mul. */
int32_t facet_smith_g2_uncorrelated_fx(int32_t nol, int32_t nov, int32_t alpha)
{
    uint32_t nl = cos_(nol), nv = cos_(nov), a = alpha_(alpha), a2 = a * a;
    fxf dl = fxf_add(fxf_u64(nl, -15), smith_r_(nl, a2));
    fxf dv = fxf_add(fxf_u64(nv, -15), smith_r_(nv, a2));
    return (int32_t)fxf_div_fixed(fxf_u64(fx_mul64(nl, nv) << 2, -30), fxf_mul(dl, dv), 15, ONE);
}

/* ---- Smith, Hammon's approximation ----------------------------------------
 * G1 ~ 2n / (n (2 - alpha) + alpha): den30 = N (2^16 - A) + A 2^15 exact
 * [<= 2^31]; raw = round(2N 2^30 / den30): both operands exact, so the result
 * is correctly rounded.  Cost: 1 division, 2 mul. */
int32_t facet_smith_g1_hammon_fx(int32_t nov, int32_t alpha)
{
    uint32_t n = unit_(nov), a = alpha_(alpha);
    uint32_t den30 = n * (2 * ONE - a) + (a << 15);
    return (int32_t)fxf_div_fixed(fxf_u64(2 * n, -15), fxf_u64(den30, -30), 15, ONE);
}

/* m = (1 - alpha) 2 nl nv + alpha (nl + nv) in Q45 exact
 * [(2^15 - A) 2 NL NV <= 2^46, A S 2^15 <= 2^46, m <= 2]. */
static uint64_t hammon_m45_(uint32_t nl, uint32_t nv, uint32_t a)
{
    return mul64x32(fx_mul64(nl, nv) << 1, ONE - a) + ((uint64_t)fx_mul64(a, nl + nv) << 15);
}

/* G2 ~ 2 nl nv / m.  m45 rounded once to 32 bits (<= 2^-32), then one
 * rounded division.  Cost: 1 division, ~6 mul. */
int32_t facet_smith_g2_hammon_fx(int32_t nol, int32_t nov, int32_t alpha)
{
    uint32_t nl = cos_(nol), nv = cos_(nov), a = alpha_(alpha);
    return (int32_t)fxf_div_fixed(fxf_u64(fx_mul64(nl, nv) << 1, -30),
                                  fxf_u64(hammon_m45_(nl, nv, a), -45), 15, ONE);
}

/* Vis ~ 0.5 / m: UQ16.16, <= 0.5 / (2 c^2 (1-a) + 2 a c) = 13117 [raw < 2^30]. */
uint32_t facet_smith_vis_hammon_fx(int32_t nol, int32_t nov, int32_t alpha)
{
    uint32_t nl = cos_(nol), nv = cos_(nov), a = alpha_(alpha);
    return fxf_div_fixed(fxf_u64(1, -1), fxf_u64(hammon_m45_(nl, nv, a), -45),
                         FACET_FX_VIS_FRAC, FACET_FX_MAX_VIS);
}

/* ---- shadowing and visibility: the rest of the menu ----------------------
 * Q15 inputs; the G terms are Q15 (max 1), the Vis terms UQ16.16. */

/* N.L N.V: Q30 exact [<= 2^30], rounded once. */
int32_t facet_g_implicit_fx(int32_t nol, int32_t nov)
{
    return (int32_t)((unit_(nol) * unit_(nov) + (1u << 14)) >> 15);
}

/* N.L N.V / max(N.L, N.V) = min(N.L, N.V): exact. */
int32_t facet_g_neumann_fx(int32_t nol, int32_t nov)
{
    uint32_t a = unit_(nol), b = unit_(nov);
    return (int32_t)(a < b ? a : b);
}

/* min(1, g / V.H), g = 2 N.H min(N.L, N.V) Q30 exact [<= 2^31]; g >= V.H
 * (V.H = 0 included) gives 1, else one rounded division. */
int32_t facet_g_cook_torrance_fx(int32_t nol, int32_t nov, int32_t noh, int32_t voh)
{
    uint32_t nl = cos_(nol), nv = cos_(nov), vh = unit_(voh);
    uint32_t g = 2 * unit_(noh) * (nl < nv ? nl : nv);
    if (g >= vh << 15)
        return ONE;
    return (int32_t)fxf_div_fixed(fxf_u64(g, -30), fxf_u64(vh, -15), 15, ONE);
}

/* min(1, N.L N.V / V.H^2): both Q30 exact [<= 2^30]. */
int32_t facet_g_kelemen_fx(int32_t nol, int32_t nov, int32_t voh)
{
    uint32_t p = cos_(nol) * cos_(nov), vh = unit_(voh), q = vh * vh;
    if (p >= q)
        return ONE;
    return (int32_t)fxf_div_fixed(fxf_u64(p, -30), fxf_u64(q, -30), 15, ONE);
}

/* Walter's Beckmann G1 (facet.h), with p = a sqrt(1 - n^2), q = n:
 * q < 1.6 p decided exactly as 25 N^2 2^24 < A^2 W, W = (2^15 - N)(2^15 + N)
 * [both < 2^60]; then G1 = min(1, q (3.535 p + 2.181 q) / (p (p + 2.276 q)
 * + 2.577 q^2)) in fxf (every term >= 0), the constants rounded to Q30. */
#define WALTER_A_ 3795677348u /* round(3.535 2^30) */
#define WALTER_B_ 2341830918u /* round(2.181 2^30) */
#define WALTER_C_ 2443836391u /* round(2.276 2^30) */
#define WALTER_D_ 2767032680u /* round(2.577 2^30) */
int32_t facet_smith_g1_beckmann_fx(int32_t nov, int32_t alpha)
{
    uint32_t n = unit_(nov), a = alpha_(alpha), w = (ONE - n) * (ONE + n);
    fxf p, q, num, den;
    if (!(fx_mul64(25 * n, n) << 24 < mul64x32(fx_mul64(a, a), w)))
        return ONE;
    p = fxf_mul(fxf_u64(a, -15), fxf_sqrt64(w, -30));
    q = fxf_u64(n, -15);
    num = fxf_mul(q, fxf_add(fxf_mul(fxf_u64(WALTER_A_, -30), p), fxf_mul(fxf_u64(WALTER_B_, -30), q)));
    den = fxf_add(fxf_mul(p, fxf_add(p, fxf_mul(fxf_u64(WALTER_C_, -30), q))),
                  fxf_mul(fxf_u64(WALTER_D_, -30), fxf_mul(q, q)));
    return (int32_t)fxf_div_fixed(num, den, 15, ONE);
}

/* n / (n (1 - k) + k), k = a sqrt(2/pi): k Q47 = A round(sqrt(2/pi) 2^32)
 * [< 2^47]; den Q62 = N (2^47 - k) + k 2^15 exact [< 2^63]. */
#define SQRT_2_PI_32_ 3426888095u /* round(sqrt(2/pi) 2^32) */
int32_t facet_smith_g1_schlick_beckmann_fx(int32_t nov, int32_t alpha)
{
    uint32_t n = unit_(nov);
    uint64_t k = fx_mul64(alpha_(alpha), SQRT_2_PI_32_);
    uint64_t den = mul64x32((1ull << 47) - k, n) + (k << 15);
    return (int32_t)fxf_div_fixed(fxf_u64(n, -15), fxf_u64(den, -62), 15, ONE);
}

/* 0.5 / (nl (nv (1 - a) + a) + nv (nl (1 - a) + a)) = 0.5 / m, Hammon's m:
 * the same function, the same exact m45, the same bits. */
uint32_t facet_smith_vis_joint_approx_fx(int32_t nol, int32_t nov, int32_t alpha)
{
    return facet_smith_vis_hammon_fx(nol, nov, alpha);
}

/* The fitted visibility: 1 / (nv R(nl) + nl R(nv)), R(x) = max(K1 a, K2 a +
 * K3 t, K4 a + K5 t), t = x sigma, sigma = 1 + C1 a - |C2| a^2 (the float
 * constants of facet/detail/vis_fit.h are exact in Q30).  sigma Q60 exact
 * [2^60 + C1 A 2^15 - |C2| A^2, in (0.35, 1.08) 2^60]; the rest fxf (all
 * terms >= 0). */
#define VFIT_K1_ 2215746816u
#define VFIT_K2_ 648049856u
#define VFIT_K3_ 2104759296u
#define VFIT_K4_ 1724301312u
#define VFIT_K5_ 1380932736u
#define VFIT_C1_ 82209328u
#define VFIT_C2_ 779814784u /* |C2| (C2 < 0) */
static fxf fxf_max_(fxf a, fxf b) /* both normalised and > 0 */
{
    if (a.e != b.e)
        return a.e > b.e ? a : b;
    return a.m >= b.m ? a : b;
}
static fxf vis_fit_r_(uint32_t x, fxf ka1, fxf ka2, fxf ka4, fxf s3, fxf s5)
{
    fxf xf = fxf_u64(x, -15);
    return fxf_max_(ka1, fxf_max_(fxf_add(ka2, fxf_mul(s3, xf)), fxf_add(ka4, fxf_mul(s5, xf))));
}
uint32_t facet_smith_vis_fit_fx(int32_t nol, int32_t nov, int32_t alpha)
{
    uint32_t nl = cos_(nol), nv = cos_(nov), a = alpha_(alpha);
    uint64_t sg = (1ull << 60) + (fx_mul64(VFIT_C1_, a) << 15) - mul64x32(fx_mul64(a, a), VFIT_C2_);
    fxf sgf = fxf_u64(sg, -60);
    fxf ka1 = fxf_u64(fx_mul64(VFIT_K1_, a), -45), ka2 = fxf_u64(fx_mul64(VFIT_K2_, a), -45);
    fxf ka4 = fxf_u64(fx_mul64(VFIT_K4_, a), -45);
    fxf s3 = fxf_mul(fxf_u64(VFIT_K3_, -30), sgf), s5 = fxf_mul(fxf_u64(VFIT_K5_, -30), sgf);
    fxf rl = vis_fit_r_(nl, ka1, ka2, ka4, s3, s5), rv = vis_fit_r_(nv, ka1, ka2, ka4, s3, s5);
    fxf den = fxf_add(fxf_mul(fxf_u64(nv, -15), rl), fxf_mul(fxf_u64(nl, -15), rv));
    return fxf_div_fixed(fxf_u64(1, 0), den, FACET_FX_VIS_FRAC, FACET_FX_MAX_VIS);
}

/* ---- Hammon's diffuse -------------------------------------------------------
 * With t = 1 + L.V (raised, t31 Q31 exact) and s = nl + nv:
 *   facing (0.9 - 0.4 facing) = t (4.5 - t) / 10    (facing = t/2)
 *   1 + 0.5 / N.H = (2s + sqrt(2t)) / (2s)          (N.H = s / sqrt(2t) <= 1)
 *   rough  = t (4.5 - t) (2s + sqrt(2t)) / (20 s)
 *   smooth = 1.05 P(nl) P(nv),  P(x) = 1 - (1 - x)^5
 *   result = albedo / pi ((1 - alpha) smooth + alpha rough + albedo 0.1159 pi alpha)
 * 4.5 - t = (9 2^30 - t31) 2^-31 and 2 - t are exact; P(x) is exact to Q30
 * (fxb_p_y4_hi's 90-bit product), everything else fxf (all terms >= 0: no
 * cancellation).  Max 20.65 at nl = nv = FACET_FX_COS_MIN, L.V = 1, alpha =
 * albedo = 1 (N.H = 2^-8) [UQ8.24 raw < 2^28.4]. */
#define C105_M 0x86666666u    /* round(1.05 2^31), e = -31 */
#define MULTI_M 0xBA6CB3FCu   /* round(0.1159 pi 2^33) (0.36411058855), e = -33 */
#define INV_PI_M 0xA2F9836Eu  /* round(2^33 / pi), e = -33 */

static fxf k_(uint32_t m, int32_t e)
{
    fxf r;
    r.m = m;
    r.e = e;
    return r;
}

/* 1 - (1 - x)^5 in Q30: 2^30 - round(Y^5 / 2^45) [Y^5 Q75 exact as in
 * Fresnel: fxb_p_y4_hi(Y, Y) = Y^5 / 2^32 < 2^44] */
static uint32_t one_minus_pow5_q30_(uint32_t x)
{
    uint32_t y = ONE - x;
    return (1u << 30) - fxv_narrow(fxb_rshr64(fxb_p_y4_hi(y, y), 13));
}

/* diffuse as fxf from the shared pieces; nl, nv, a, alb raw, t31 raised.
 * In two parts for the RGB form: single (no albedo), then the albedo part. */
static fxf diffuse_single_(uint32_t nl, uint32_t nv, uint64_t t31, uint32_t a)
{
    uint32_t s = nl + nv;
    fxf t = fxf_u64(t31, -31);
    fxf tt = fxf_mul(t, fxf_u64(9ull * (1u << 30) - t31, -31)); /* t (4.5 - t) */
    fxf sum = fxf_add(fxf_u64(s, -14), fxf_sqrt(fxf_u64(t31, -30))); /* 2s + sqrt(2t) */
    fxf rough = fxf_div(fxf_mul(tt, sum), fxf_u64(20u * s, -15));
    fxf smooth = fxf_mul(fxf_mul(fxf_u64(one_minus_pow5_q30_(nl), -30),
                                 fxf_u64(one_minus_pow5_q30_(nv), -30)), k_(C105_M, -31));
    return fxf_add(fxf_mul(fxf_u64(ONE - a, -15), smooth), fxf_mul(fxf_u64(a, -15), rough));
}

static fxf diffuse_albedo_(fxf single, uint32_t a, uint32_t alb)
{
    fxf multi = fxf_mul(fxf_mul(fxf_u64(alb, -15), fxf_u64(a, -15)), k_(MULTI_M, -33));
    return fxf_mul(fxf_mul(fxf_u64(alb, -15), k_(INV_PI_M, -33)), fxf_add(single, multi));
}

static fxf diffuse_fxf_(uint32_t nl, uint32_t nv, uint64_t t31, uint32_t a, uint32_t alb)
{
    return diffuse_albedo_(diffuse_single_(nl, nv, t31, a), a, alb);
}

/* Error: FACET_FX_ERR_DIFFUSE_HAMMON (measured).  Cost: 1 sqrt, 1 division,
 * ~12 fxf ops, ~10 mul64. */
uint32_t facet_diffuse_hammon_fx(int32_t nol, int32_t nov, int32_t lov, int32_t alpha,
                                 int32_t albedo)
{
    uint32_t nl = cos_(nol), nv = cos_(nov);
    fxf r = diffuse_fxf_(nl, nv, t31_(t_(lov), nl + nv), alpha_(alpha), unit_(albedo));
    return (uint32_t)fxf_fixed(r, FACET_FX_BRDF_FRAC, FACET_FX_MAX_DIFF);
}

/* ---- the whole model --------------------------------------------------------
 * brdf = D Vis_hammon F(f0, L.H) + diffuse, from the dots, N.H never formed:
 *   N.H^2 = s^2 / 2t, so d = 1 - N.H^2 (1 - alpha^2) = e / 2t with
 *   e60 = (t31 - S^2) 2^30 + A^2 S^2   Q60 exact [each term <= 2^62]
 *   (t31 - S^2 = (2t - s^2) 2^30 >= 0: the peak's cancellation is exact),
 *   D = alpha^2 (2t)^2 / (pi e^2),  Vis = 0.5 / m (m as hammon_m45_),
 *   L.H = sqrt(t/2), 1 - L.H = (2 - t) / (2 (1 + L.H)) [2 - t exact]:
 *   spec = (alpha 2t)^2 F / (2 pi e^2 m).
 * Max 4.38e9 (D 333772 x Vis 13117 at the grazing peak) [UQ40.24 < 2^57].
 * Error: FACET_FX_ERR_BRDF_HAMMON (LSB where brdf < 16; relative above).
 * Cost: 2 sqrt, 3 division, ~30 fxf ops. */
#define TWO_PI_M 0xC90FDAA2u /* round(2 pi 2^29), e = -29 */

/* What brdf_hammon computes before f0 and albedo enter, shared by the RGB
 * form; per channel the same fxf operations in the same order, so each
 * channel is facet_brdf_hammon_fx's bits. */
typedef struct brdf_geom_ {
    fxf y5, a2t2, den, single;
    uint32_t a;
} brdf_geom_;

static brdf_geom_ brdf_geometry_(int32_t nol, int32_t nov, int32_t lov, int32_t alpha)
{
    brdf_geom_ G;
    uint32_t nl = cos_(nol), nv = cos_(nov), a = alpha_(alpha), s = nl + nv;
    uint64_t s2 = fx_mul64(s, s), t31 = t31_(t_(lov), s);
    uint64_t e60 = ((t31 - s2) << 30) + mul64x32(s2, a * a);
    fxf e = fxf_u64(e60, -60);
    fxf a2t = fxf_mul(fxf_u64(a, -15), fxf_u64(t31, -30));
    fxf lh = fxf_sqrt(fxf_u64(t31, -32));
    fxf y = fxf_div(fxf_u64((1ull << 32) - t31, -32), fxf_add(k_(0x80000000u, -31), lh));
    fxf y2 = fxf_mul(y, y);
    G.y5 = fxf_mul(fxf_mul(y2, y2), y);
    G.den = fxf_mul(fxf_mul(fxf_mul(e, e), fxf_u64(hammon_m45_(nl, nv, a), -45)), k_(TWO_PI_M, -29));
    G.a2t2 = fxf_mul(a2t, a2t);
    G.single = diffuse_single_(nl, nv, t31, a);
    G.a = a;
    return G;
}

static uint64_t brdf_channel_(const brdf_geom_ *G, int32_t f0, int32_t albedo)
{
    uint32_t f0r = unit_(f0);
    fxf f = fxf_add(fxf_u64(f0r, -15), fxf_mul(fxf_u64(ONE - f0r, -15), G->y5));
    fxf spec = fxf_div(fxf_mul(G->a2t2, f), G->den);
    fxf r = fxf_add(spec, diffuse_albedo_(G->single, G->a, unit_(albedo)));
    return fxf_fixed(r, FACET_FX_BRDF_FRAC, FACET_FX_MAX_BRDF);
}

uint64_t facet_brdf_hammon_fx(int32_t nol, int32_t nov, int32_t lov, int32_t alpha,
                              int32_t f0, int32_t albedo)
{
    brdf_geom_ G = brdf_geometry_(nol, nov, lov, alpha);
    return brdf_channel_(&G, f0, albedo);
}

void facet_brdf_hammon_rgb_fx(uint64_t out[3], int32_t nol, int32_t nov, int32_t lov,
                              int32_t alpha, const int32_t f0[3], const int32_t albedo[3])
{
    brdf_geom_ G = brdf_geometry_(nol, nov, lov, alpha);
    int c;
    for (c = 0; c < 3; c++)
        out[c] = brdf_channel_(&G, f0[c], albedo[c]);
}

/* ---- the scalar port's batches: src/fx/fx_batch_scalar.h ----------------- */
#define FX_TIER fx
#define FX_SCALAR_VAR facet_fx_port_scalar
#define FX_TIER_PRECISE 1
#include "fx_batch_scalar.h"
