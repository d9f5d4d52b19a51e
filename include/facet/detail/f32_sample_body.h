/* facet/detail/f32_sample_body.h - the one body of the f32 samplers (GGX D,
 * GGX visible normals, GTR D) and their pdfs.
 *
 * Like f32_body.h: no include guard; each port header includes it once per
 * tier (facet/detail/f32_tiers.h), after f32_body.h (it calls that body's ggx_d core, x_ggx_d, which
 * has no NaN rule, and its Smith helpers), with
 * the same FACET_V / FACET_OP / FACET_K / FACET_TIER_FAST, and with three
 * ops more than f32_body.h needs (see facet/scalar.h, "sampling ops"):
 *   exp2i(k)    2^k for an integral-valued k in [-126, 127] (exponent bits)
 *   getexp(x)   floor(log2 x) as a float, x positive and normal
 *   getmant(x)  x / 2^getexp(x), in [1, 2)
 * Contracts are in facet.h ("GGX and GTR importance sampling"); the comments
 * here derive the formulas and explain the numerics.
 *
 * Frame: the shading frame, N = +z.  Every sampler returns a unit h with
 * h.z > 0 and no libm: sin/cos, log2 and 2^x are built below from
 * add/mul/fma, selects and the exponent bits, each with its error.
 */
#ifndef FACET_V
#error "include a port header (facet/scalar.h, facet/sse2.h, ...), not this file"
#endif

#define V_ FACET_V
#define C_(x) FACET_OP(set)(x)
#define ADD_ FACET_OP(add)
#define SUB_ FACET_OP(sub)
#define MUL_ FACET_OP(mul)
#define FMA_ FACET_OP(fma)
#define FNMA_ FACET_OP(fnma)
#define MIN_ FACET_OP(min)
#define MAX_ FACET_OP(max)
#define CLAMP_ FACET_OP(clamp)
#define SEL_LT_ FACET_OP(sel_lt)
#if defined(FACET_TIER_FAST) && FACET_TIER_FAST
#define RCP_ FACET_OP(rcp_fast)
#define RSQRT_ FACET_OP(rsqrt_fast)
#else
#define RCP_ FACET_OP(rcp)
#define RSQRT_ FACET_OP(rsqrt)
#endif

/* the final normalization of every sampled h: the precise rsqrt in both
 * tiers, so that |h| = 1 to rounding in f32_fast too (callers rely on a
 * unit h, e.g. to reflect about it); the fast tier saves elsewhere */
#define RSQRT_UNIT_ FACET_OP(rsqrt)

#define S_INV_PI_ 0.318309886f
/* the largest float below 1: every u is clamped to [0, S_U_MAX_] */
#define S_U_MAX_ 0.99999994f

#define S_U_ FACET_K(xs_u)
#define S_SQRT0_ FACET_K(xs_sqrt0)
#define S_EXP2M1R_ FACET_K(x_exp2m1r)
#define S_LOG2_ FACET_K(x_log2)
#define S_FROM_SC_ FACET_K(xs_from_sc)
#define S_VNDF_ FACET_K(xs_vndf)
#define S_GTR1_SC_ FACET_K(xs_gtr1_sc)
#define S_ANISO_K_ FACET_K(xs_aniso_k)

/* u clamped to [0, 1): NaN and -Inf -> 0, 1 and above -> 1 - 2^-24. */
FACET_INLINE V_ S_U_(V_ u) { return CLAMP_(u, C_(0.0f), C_(S_U_MAX_)); }

/* sqrt(x) for x >= 0 as x rsqrt(x), with sqrt(0) = 0: x below 2^-100 is
 * scaled by a too-large rsqrt of 2^-100, i.e. gives a result below 2^-50. */
FACET_INLINE V_ S_SQRT0_(V_ x) { return MUL_(x, RSQRT_(MAX_(x, C_(7.88860905e-31f)))); }

/* ---- sin and cos of 2 pi u ----------------------------------------------
 * Reduction by the symmetries of the circle, every step exact in float:
 *   a = min(u, 1 - u)          sin(2 pi u) = +-sin(2 pi a) (- for u >= 1/2),
 *                              cos(2 pi u) = cos(2 pi a); 1 - u is exact
 *                              for u >= 1/2 (Sterbenz), a in [0, 1/2]
 *   b = min(a, 1/2 - a)        sin(2 pi a) = sin(2 pi b), cos(2 pi a) =
 *                              +-cos(2 pi b) (- for a >= 1/4); b in [0, 1/4]
 *   c = min(b, 1/4 - b)        for b >= 1/8 sine and cosine swap; c in [0, 1/8]
 * then sin(2 pi c) = c S(c^2), cos(2 pi c) = C(c^2) on c in [0, 1/8], S of
 * degree 3 and C of degree 4: interpolants at Chebyshev nodes (near
 * minimax) fitted in long double, coefficients rounded to float; with
 * those float coefficients and exact arithmetic the relative error is
 * below 3.6e-8 (S) and 9.5e-9 (C).  Tested: tests/sample/test_sample_prims.c. */
FACET_INLINE void FACET_K(sincos_2pi)(V_ *sin_out, V_ *cos_out, V_ u)
{
    V_ x = S_U_(u);
    V_ a = MIN_(x, SUB_(C_(1.0f), x));
    V_ b = MIN_(a, SUB_(C_(0.5f), a));
    V_ c = MIN_(b, SUB_(C_(0.25f), b));
    V_ t = MUL_(c, c);
    V_ s = FMA_(t, C_(-7.540161133e+01f), C_(8.159254456e+01f));
    V_ k;
    s = FMA_(s, t, C_(-4.134166336e+01f));
    s = FMA_(s, t, C_(6.283185482e+00f));
    s = MUL_(s, c);
    k = FMA_(t, C_(5.922016907e+01f), C_(-8.544284821e+01f));
    k = FMA_(k, t, C_(6.493931580e+01f));
    k = FMA_(k, t, C_(-1.973920822e+01f));
    k = FMA_(k, t, C_(1.0f));
    /* swap for b >= 1/8, then the signs */
    *sin_out = MUL_(SEL_LT_(b, C_(0.125f), s, k), SEL_LT_(x, C_(0.5f), C_(1.0f), C_(-1.0f)));
    *cos_out = MUL_(SEL_LT_(b, C_(0.125f), k, s), SEL_LT_(a, C_(0.25f), C_(1.0f), C_(-1.0f)));
}

/* ---- 2^y and log2 ----------------------------------------------------------
 * (2^y - 1) / y and log2 x are f32_body.h's x_exp2m1r and x_log2 (its
 * section "2^y and log2", with their errors). */

/* ---- the half vector from sin and cos ------------------------------------
 * h = normalize(ax s cos(2 pi u2), ay s sin(2 pi u2), c) for s, c >= 0 with
 * s^2 / c^2 the sampled tan^2 of the unit-width distribution.  Normalizing
 * here (rather than trusting s^2 + c^2 = 1) makes |h| = 1 to rounding
 * whatever the error of sin/cos; c > 0 keeps h.z > 0. */
FACET_INLINE void S_FROM_SC_(V_ *hx, V_ *hy, V_ *hz, V_ s, V_ c, V_ u2, V_ ax, V_ ay)
{
    V_ sn, cs, x, y, n;
    FACET_K(sincos_2pi)(&sn, &cs, u2);
    x = MUL_(MUL_(ax, s), cs);
    y = MUL_(MUL_(ay, s), sn);
    n = RSQRT_UNIT_(FMA_(x, x, FMA_(y, y, MUL_(c, c))));
    *hx = MUL_(x, n);
    *hy = MUL_(y, n);
    *hz = MUL_(c, n);
}

/* ---- GGX D sampling ------------------------------------------------------
 * GGX D with widths (ax, ay) is the slope distribution
 *   P(x, y) = 1 / (pi ax ay (1 + x^2/ax^2 + y^2/ay^2)^2),
 * with D(h) h.z dw = P(slope) d(slope) and h = normalize(-x, -y, 1).  With
 * x = ax r cos phi, y = ay r sin phi the unit-width radial law is
 * 2 r dr / (1 + r^2)^2, whose CDF is r^2 / (1 + r^2) = u1, so
 * r^2 = u1 / (1 - u1), and phi = 2 pi u2 (the sign of the slope is
 * immaterial: phi is uniform).  Multiplying by sqrt(1 - u1):
 *   h = normalize(ax sqrt(u1) cos phi, ay sqrt(u1) sin phi, sqrt(1 - u1)).
 * For ax = ay = alpha: tan^2 theta = alpha^2 u1 / (1 - u1), i.e.
 * cos^2 theta = (1 - u1) / (1 + (alpha^2 - 1) u1), Schutte's and the VSB
 * notes' inverse CDF.  No cancellation anywhere (1 - u1 is exact for u1 >= 1/2). */
FACET_INLINE void FACET_K(ggx_sample_d_aniso)(V_ *hx_out, V_ *hy_out, V_ *hz_out, V_ u1, V_ u2, V_ alpha_x, V_ alpha_y)
{
    V_ u = S_U_(u1);
    S_FROM_SC_(hx_out, hy_out, hz_out, S_SQRT0_(u), S_SQRT0_(SUB_(C_(1.0f), u)), u2,
               FACET_K(x_alpha)(alpha_x), FACET_K(x_alpha)(alpha_y));
}

FACET_INLINE void FACET_K(ggx_sample_d)(V_ *hx_out, V_ *hy_out, V_ *hz_out, V_ u1, V_ u2, V_ alpha)
{
    V_ a = FACET_K(x_alpha)(alpha);
    V_ u = S_U_(u1);
    S_FROM_SC_(hx_out, hy_out, hz_out, S_SQRT0_(u), S_SQRT0_(SUB_(C_(1.0f), u)), u2, a, a);
}

/* pdf of h: D(h) N.H, D by ggx_d's own code (so D agrees with ggx_d to the
 * bit, and pdf = fl(ggx_d(N.H) N.H) with N.H clamped to [0, 1]). */
FACET_INLINE V_ FACET_K(ggx_pdf_d)(V_ noh, V_ alpha)
{
    return MUL_(FACET_K(x_ggx_d)(noh, alpha), FACET_K(x_unit)(noh));
}

/* Anisotropic: D(h) = 1 / (pi ax ay k^2), k = (hx/ax)^2 + (hy/ay)^2 + hz^2
 * for a unit h.  Without dividing by ax, ay: with K = ax^2 ay^2 k =
 * hx^2 ay^2 + hy^2 ax^2 + hz^2 ax^2 ay^2, pdf = D h.z = hz ax^3 ay^3 / (pi K^2),
 * one reciprocal (K^2 >= 2^-80: no underflow).  h.x, h.y clamped to
 * [-1, 1], h.z to [0, 1]; k >= 1 for a unit h (1/a^2 >= 1), floored at 1/2
 * (K at ax^2 ay^2 / 2) so a non-unit or NaN h stays finite. */
FACET_INLINE V_ S_ANISO_K_(V_ x, V_ y, V_ z, V_ ax, V_ ay, V_ *a3)
{
    V_ ax2 = MUL_(ax, ax), ay2 = MUL_(ay, ay), a2 = MUL_(ax2, ay2);
    V_ K = FMA_(MUL_(x, x), ay2, FMA_(MUL_(y, y), ax2, MUL_(MUL_(z, z), a2)));
    *a3 = MUL_(a2, MUL_(ax, ay));
    return MAX_(K, MUL_(C_(0.5f), a2));
}

FACET_INLINE V_ FACET_K(ggx_pdf_d_aniso)(V_ hx, V_ hy, V_ hz, V_ alpha_x, V_ alpha_y)
{
    V_ ax = FACET_K(x_alpha)(alpha_x), ay = FACET_K(x_alpha)(alpha_y), a3;
    V_ z = FACET_K(x_unit)(hz);
    V_ K = S_ANISO_K_(CLAMP_(hx, C_(-1.0f), C_(1.0f)), CLAMP_(hy, C_(-1.0f), C_(1.0f)), z, ax, ay, &a3);
    /* a3 / K^2 first: it lies in [2^-65, 2^22] (K in [a2 / 2, 3]), so the
     * products with h.z and 1/pi underflow only where the pdf itself does
     * (h.z first would take h.z ax^3 ay^3 below 2^-126 for pdfs far above
     * the 2^-100 floor) */
    return MUL_(MUL_(z, MUL_(a3, RCP_(MUL_(K, K)))), C_(S_INV_PI_));
}

/* ---- visible normals (VNDF) ---------------------------------------------
 * Heitz 2018: stretch the view to the unit-width configuration,
 * Vh = normalize(ax v.x, ay v.y, v.z); sample a normal m of the unit
 * hemisphere with density proportional to max(0, Vh.m); unstretch:
 * h = normalize(ax m.x, ay m.y, m.z).  Heitz samples m from the projected
 * disk in a basis around Vh.  We sample the same law more cheaply:
 *   a point uniform on the unit sphere centred at Vh (which passes through
 *   the origin) seen from the origin has, in direction m, distance
 *   rho = 2 Vh.m and area element rho^2 dw / cos(angle to the sphere's
 *   normal) = 4 (Vh.m)^2 dw / (Vh.m) = 4 (Vh.m) dw: density prop. to Vh.m.
 *   So m = normalize(Vh + c), c uniform on the unit sphere; m.z > 0 iff
 *   c.z > -Vh.z, i.e. c uniform on that spherical cap: c.z uniform in
 *   (-Vh.z, 1] (Archimedes), azimuth uniform.
 * The cap's rim passes through -Vh, where H = Vh + c vanishes: there the
 * direction of H is well defined (the map is well-conditioned) but Vh.x +
 * c.x cancels.  So the azimuth phi' = 2 pi u2 is measured from Vh's own
 * azimuth e1 = Vh_t / |Vh_t| (e1 = x at normal view; phi' is uniform like
 * any azimuth), e2 = z x e1, and with rho = |Vh_t| = sqrt(1 - Vh.z^2),
 * s = sqrt(1 - c.z^2):
 *   c.z = (1 - u1)(1 + Vh.z) - Vh.z,   H.z = (1 - u1)(1 + Vh.z)  (>= 2^-24)
 *   s^2 = (1 - c.z)(1 + c.z) = u1 (1 + Vh.z) (H.z + (1 - Vh.z)),
 *         1 - Vh.z = rho^2 / (1 + Vh.z)           (no cancellation at normal view)
 *   H.e1 = rho + s cos phi' = (rho - s) + s (1 + cos phi')
 *        = H.z (H.z - 2 Vh.z) / (rho + s) + 2 s cos^2(phi'/2),
 *     H.z - 2 Vh.z = (1 - Vh.z) - u1 (1 + Vh.z)  (exact at u1 = 0, where the
 *     first form cancels for a nearly normal view)
 *   H.e2 = s sin phi' = 2 s sin(phi'/2) cos(phi'/2)
 * (both terms of H.e1 small and exact-ish where H is short; the rim form is
 * used for cos phi' < -1/2 only, the plain one elsewhere), with
 * (sin, cos)(phi'/2) = sincos_2pi(u2 / 2); then h = normalize(ax H.x, ay H.y,
 * H.z).  4 rsqrt and 2 rcp, against Heitz's 6 rsqrt; the distributions are
 * equal (derivation above; tests/sample/test_sample_chi2.c checks this form and,
 * in double, Heitz's).
 * v: components clamped to [-1, 1] (NaN -> -1), v.z raised to 0 (below the
 * horizon: the view from the horizon at the same azimuth); only v's
 * direction matters; a stretched v shorter than 2^-50 acts as (0, 0, 1). */
FACET_INLINE void S_VNDF_(V_ *hx_out, V_ *hy_out, V_ *hz_out, V_ vx, V_ vy, V_ vz, V_ u1, V_ u2, V_ ax, V_ ay)
{
    V_ x = MUL_(ax, CLAMP_(vx, C_(-1.0f), C_(1.0f)));
    V_ y = MUL_(ay, CLAMP_(vy, C_(-1.0f), C_(1.0f)));
    V_ z = FACET_K(x_unit)(vz);
    V_ t2 = FMA_(x, x, MUL_(y, y));
    V_ l2 = FMA_(z, z, t2);
    V_ tiny = C_(7.88860905e-31f); /* 2^-100 */
    V_ flat, r, rt, e1x, e1y, rho, Vz, opv, omv, u, Hz, s, sn, cs, cphi, A, B, Hx, Hy, mx, my, n;
    z = SEL_LT_(l2, tiny, C_(1.0f), z);
    t2 = SEL_LT_(l2, tiny, C_(0.0f), t2);
    l2 = SEL_LT_(l2, tiny, C_(1.0f), l2);
    r = RSQRT_(l2);
    /* e1: Vh's azimuth, x where Vh_t is too short to have one */
    flat = SEL_LT_(t2, tiny, C_(0.0f), C_(1.0f));
    rt = RSQRT_(MAX_(t2, tiny));
    e1x = SEL_LT_(t2, tiny, C_(1.0f), MUL_(x, rt));
    e1y = MUL_(MUL_(y, rt), flat);
    rho = MUL_(MUL_(t2, rt), r);
    Vz = MIN_(MUL_(z, r), C_(1.0f));
    opv = ADD_(C_(1.0f), Vz);
    omv = MUL_(MUL_(rho, rho), RCP_(opv));
    u = S_U_(u1);
    Hz = MUL_(SUB_(C_(1.0f), u), opv);
    s = S_SQRT0_(MUL_(MUL_(u, opv), ADD_(Hz, omv)));
    FACET_K(sincos_2pi)(&sn, &cs, MUL_(S_U_(u2), C_(0.5f)));
    /* H.e1 = rho + s cos phi' directly where cos phi' >= -1/2 (no
     * cancellation worse than the value's own conditioning), else from the
     * rim form; its reciprocal is the precise one in both tiers, since a
     * cancelling sum would amplify an unrefined estimate's error */
    cphi = FNMA_(sn, sn, MUL_(cs, cs));
    A = MUL_(MUL_(Hz, FNMA_(u, opv, omv)), FACET_OP(rcp)(MAX_(ADD_(rho, s), tiny)));
    A = FMA_(ADD_(s, s), MUL_(cs, cs), A);
    A = SEL_LT_(cphi, C_(-0.5f), A, FMA_(s, cphi, rho));
    B = MUL_(ADD_(s, s), MUL_(sn, cs));
    Hx = FMA_(e1x, A, MUL_(SUB_(C_(0.0f), e1y), B));
    Hy = FMA_(e1y, A, MUL_(e1x, B));
    mx = MUL_(ax, Hx);
    my = MUL_(ay, Hy);
    n = RSQRT_UNIT_(FMA_(mx, mx, FMA_(my, my, MUL_(Hz, Hz))));
    *hx_out = MUL_(mx, n);
    *hy_out = MUL_(my, n);
    *hz_out = MUL_(Hz, n);
}

FACET_INLINE void FACET_K(ggx_sample_vndf)(V_ *hx_out, V_ *hy_out, V_ *hz_out, V_ vx, V_ vy, V_ vz, V_ u1, V_ u2, V_ alpha)
{
    V_ a = FACET_K(x_alpha)(alpha);
    S_VNDF_(hx_out, hy_out, hz_out, vx, vy, vz, u1, u2, a, a);
}

FACET_INLINE void FACET_K(ggx_sample_vndf_aniso)(V_ *hx_out, V_ *hy_out, V_ *hz_out, V_ vx, V_ vy, V_ vz, V_ u1, V_ u2,
                                                 V_ alpha_x, V_ alpha_y)
{
    S_VNDF_(hx_out, hy_out, hz_out, vx, vy, vz, u1, u2, FACET_K(x_alpha)(alpha_x), FACET_K(x_alpha)(alpha_y));
}

/* pdf of h: G1(v) max(0, V.H) D(h) / N.V.  With G1 = 2 n / (n + r),
 * r = sqrt(alpha^2 + (1 - alpha^2) n^2) (smith_g1's own terms), G1 / N.V =
 * 2 / (n + r): finite down to N.V = 0 (2 / alpha there).  D is ggx_d's code.
 * N.V, V.H clamped to [0, 1] (V.H <= 0 gives 0); N.H as ggx_d.  The
 * reciprocal of n + r is the precise one in both tiers: with D's two
 * estimate errors (k^2) and r's, an unrefined one would reach 2^-12. */
FACET_INLINE V_ FACET_K(ggx_pdf_vndf)(V_ nov, V_ noh, V_ voh, V_ alpha)
{
    V_ n = FACET_K(x_unit)(nov);
    V_ a = FACET_K(x_alpha)(alpha);
    V_ r = FACET_K(x_sqrt)(FACET_K(x_smith_w)(n, MUL_(a, a)));
    V_ g = MUL_(C_(2.0f), FACET_OP(rcp)(ADD_(n, r)));
    return MUL_(FACET_K(x_ggx_d)(noh, alpha), MUL_(FACET_K(x_unit)(voh), g));
}

/* pdf of the reflected direction l = 2 (V.H) H - V: pdf_vndf / (4 V.H)
 * = D G1(v) / (4 N.V) = D / (2 (n + r)) for V.H > 0, else 0. */
FACET_INLINE V_ FACET_K(ggx_pdf_vndf_reflect)(V_ nov, V_ noh, V_ voh, V_ alpha)
{
    V_ n = FACET_K(x_unit)(nov);
    V_ a = FACET_K(x_alpha)(alpha);
    V_ r = FACET_K(x_sqrt)(FACET_K(x_smith_w)(n, MUL_(a, a)));
    V_ p = MUL_(FACET_K(x_ggx_d)(noh, alpha), MUL_(C_(0.5f), FACET_OP(rcp)(ADD_(n, r))));
    return SEL_LT_(C_(0.0f), voh, p, C_(0.0f));
}

/* Anisotropic: G1(v) / v.z = 2 / (v.z + sqrt(ax^2 v.x^2 + ay^2 v.y^2 + v.z^2))
 * for a unit v (Lambda = (sqrt(1 + (ax^2 v.x^2 + ay^2 v.y^2) / v.z^2) - 1) / 2),
 * the denominator floored at 2^-20 (only a non-unit v reaches it); D(h) as
 * in ggx_pdf_d_aniso. */
FACET_INLINE V_ FACET_K(ggx_pdf_vndf_aniso)(V_ vx, V_ vy, V_ vz, V_ hx, V_ hy, V_ hz,
                                            V_ alpha_x, V_ alpha_y)
{
    V_ ax = FACET_K(x_alpha)(alpha_x), ay = FACET_K(x_alpha)(alpha_y);
    V_ cx = CLAMP_(vx, C_(-1.0f), C_(1.0f)), cy = CLAMP_(vy, C_(-1.0f), C_(1.0f));
    V_ cz = FACET_K(x_unit)(vz);
    V_ gx = CLAMP_(hx, C_(-1.0f), C_(1.0f)), gy = CLAMP_(hy, C_(-1.0f), C_(1.0f));
    V_ gz = FACET_K(x_unit)(hz);
    V_ sx = MUL_(ax, cx), sy = MUL_(ay, cy);
    V_ w = FMA_(sx, sx, FMA_(sy, sy, MUL_(cz, cz)));
    V_ den = MAX_(ADD_(cz, FACET_K(x_sqrt)(MAX_(w, C_(7.88860905e-31f)))), C_(9.53674316e-07f));
    V_ vh = MAX_(FMA_(cx, gx, FMA_(cy, gy, MUL_(cz, gz))), C_(0.0f));
    V_ a3, K = S_ANISO_K_(gx, gy, gz, ax, ay, &a3);
    /* pdf = 2 vh D / den, D = ax^3 ay^3 / (pi K^2): one reciprocal, and
     * a3 / (K^2 den) first (in [2^-70, 2^42]: K^2 den >= 2^-102), so that
     * vh times it underflows only where the pdf does */
    return MUL_(MUL_(vh, MUL_(a3, RCP_(MUL_(MUL_(K, K), den)))), C_(2.0f * S_INV_PI_));
}

/* l = 2 (v.h) h - v, components clamped to [-1, 1] first (NaN -> -1). */
FACET_INLINE void FACET_K(reflect)(V_ *lx_out, V_ *ly_out, V_ *lz_out, V_ vx, V_ vy, V_ vz, V_ hx, V_ hy, V_ hz)
{
    V_ one = C_(1.0f), mone = C_(-1.0f);
    V_ x = CLAMP_(vx, mone, one), y = CLAMP_(vy, mone, one), z = CLAMP_(vz, mone, one);
    V_ a = CLAMP_(hx, mone, one), b = CLAMP_(hy, mone, one), c = CLAMP_(hz, mone, one);
    V_ d = FMA_(x, a, FMA_(y, b, MUL_(z, c)));
    V_ d2 = ADD_(d, d);
    *lx_out = FMA_(d2, a, SUB_(C_(0.0f), x));
    *ly_out = FMA_(d2, b, SUB_(C_(0.0f), y));
    *lz_out = FMA_(d2, c, SUB_(C_(0.0f), z));
}

/* ---- GTR D sampling ------------------------------------------------------
 * GTR: D prop. to 1 / (1 + (alpha^2 - 1) x)^gamma, x = cos^2 theta; with
 * dw = d(cos theta) dphi the law of x is prop. to (1 + (alpha^2 - 1) x)^-gamma
 * dx.  Integrating from x to 1 and normalizing, B = 1 + (alpha^2 - 1) x solves
 *   B^(1 - gamma) = (1 - u) alpha^(2 (1 - gamma)) + u    (gamma != 1)
 *   B = alpha^(2 (1 - u))                                (gamma = 1)
 * and x = (1 - B) / (1 - alpha^2), 1 - x = (B - alpha^2) / (1 - alpha^2).
 * gamma = 2 is GGX (above).  gamma = 1 with L = log2 alpha^2 in [-20, 0],
 * writing 2^y - 1 = y E(y):
 *   1 - x prop. to alpha^2 (2^(-u L) - 1) = alpha^2 (-u L) E(-u L)
 *   x     prop. to 1 - 2^((1 - u) L)      = -(1 - u) L E((1 - u) L)
 * and the common factor -L / (1 - alpha^2) drops out in the normalization:
 *   sin prop. to alpha sqrt(u E(-u L)), cos prop. to sqrt((1 - u) E((1 - u) L)),
 * which stays exact at alpha = 1 (L = 0: E = ln 2, cos^2 theta = 1 - u, the
 * limit) and needs no 1 - alpha^2 or 1 - B. */
FACET_INLINE void S_GTR1_SC_(V_ *s, V_ *c, V_ u, V_ a)
{
    V_ L = MUL_(C_(2.0f), S_LOG2_(a));
    V_ e1 = S_EXP2M1R_(MUL_(SUB_(C_(0.0f), u), L));
    V_ e2 = S_EXP2M1R_(MUL_(SUB_(C_(1.0f), u), L));
    *s = S_SQRT0_(MUL_(u, e1));
    *c = S_SQRT0_(MUL_(SUB_(C_(1.0f), u), e2));
}

/* gamma < 1.5 samples GTR1 (gamma = 1), otherwise (NaN too) GGX (gamma = 2):
 * the two orders with a closed-form inverse CDF in this library. */
FACET_INLINE void FACET_K(gtr_sample_d)(V_ *hx_out, V_ *hy_out, V_ *hz_out, V_ u1, V_ u2, V_ alpha, V_ gamma)
{
    V_ a = FACET_K(x_alpha)(alpha);
    V_ u = S_U_(u1);
    V_ s1, c1;
    V_ s2 = S_SQRT0_(u), c2 = S_SQRT0_(SUB_(C_(1.0f), u));
    V_ g = SEL_LT_(gamma, C_(1.5f), C_(1.0f), C_(0.0f));
    S_GTR1_SC_(&s1, &c1, u, a);
    S_FROM_SC_(hx_out, hy_out, hz_out, SEL_LT_(C_(0.5f), g, s1, s2), SEL_LT_(C_(0.5f), g, c1, c2), u2, a, a);
}

/* GTR1: D = (alpha^2 - 1) / (pi ln(alpha^2) d), d = 1 + (alpha^2 - 1) N.H^2
 * = (1 - N.H)(1 + N.H) + (N.H alpha)^2 as in ggx_d; (alpha^2 - 1) / ln alpha^2
 * = E(L) / ln 2 (1/pi at alpha = 1).  pdf = D N.H; gamma as gtr_sample_d. */
FACET_INLINE V_ FACET_K(gtr_pdf_d)(V_ noh, V_ alpha, V_ gamma)
{
    V_ n = FACET_K(x_unit)(noh);
    V_ a = FACET_K(x_alpha)(alpha);
    V_ na = MUL_(n, a);
    V_ d = FMA_(SUB_(C_(1.0f), n), ADD_(C_(1.0f), n), MUL_(na, na));
    V_ L = MUL_(C_(2.0f), S_LOG2_(a));
    V_ p1 = MUL_(MUL_(MUL_(S_EXP2M1R_(L), C_(0.459224094f)), RCP_(d)), n); /* 1 / (pi ln 2) */
    return SEL_LT_(gamma, C_(1.5f), p1, FACET_K(ggx_pdf_d)(noh, alpha));
}

#undef V_
#undef C_
#undef ADD_
#undef SUB_
#undef MUL_
#undef FMA_
#undef FNMA_
#undef MIN_
#undef MAX_
#undef CLAMP_
#undef SEL_LT_
#undef RCP_
#undef RSQRT_
#undef RSQRT_UNIT_
#undef S_INV_PI_
#undef S_U_MAX_
#undef S_U_
#undef S_SQRT0_
#undef S_EXP2M1R_
#undef S_LOG2_
#undef S_FROM_SC_
#undef S_VNDF_
#undef S_GTR1_SC_
#undef S_ANISO_K_
