/* oracle.c - double-precision reference, from the definitions.
 * Built with -ffp-contract=off (Makefile).  See facet/oracle.h. */
#include <math.h>
#include "facet/common.h"
#include "facet/oracle.h"
#include "facet/detail/vis_fit.h"

static const double PI = 3.14159265358979323846;

/* The contract's domain rule: clamp, NaN and -Inf to the low end. */
static double clampd(double x, double lo, double hi)
{
    if (!(x > lo))
        return lo;
    return x > hi ? hi : x;
}

static double cosd(double x) { return clampd(x, FACET_COS_MIN, 1.0); }
static double unitd(double x) { return clampd(x, 0.0, 1.0); }
static double alphad(double x) { return clampd(x, FACET_ALPHA_MIN, 1.0); }
static double lerpd(double a, double b, double t) { return a + t * (b - a); }
static double sgnd(double x) { return clampd(x, -1.0, 1.0); }

/* ---- double-double, for the geometry only --------------------------------
 * Building L and V from their dots cancels badly where L and V are nearly
 * opposite at grazing angles (1 - cos^2 of the azimuth), exactly where D is
 * most sensitive, so the vectors are built with ~106-bit arithmetic. */
typedef struct { double hi, lo; } dd;

static dd dd_two_sum(double a, double b)
{
    dd r;
    double bb;
    r.hi = a + b;
    bb = r.hi - a;
    r.lo = (a - (r.hi - bb)) + (b - bb);
    return r;
}

static dd dd_norm(double hi, double lo) { return dd_two_sum(hi, lo); }
static dd dd_d(double a) { dd r; r.hi = a; r.lo = 0.0; return r; }

static dd dd_add(dd a, dd b)
{
    dd s = dd_two_sum(a.hi, b.hi);
    return dd_norm(s.hi, s.lo + a.lo + b.lo);
}

static dd dd_neg(dd a) { a.hi = -a.hi; a.lo = -a.lo; return a; }
static dd dd_sub(dd a, dd b) { return dd_add(a, dd_neg(b)); }

static dd dd_mul(dd a, dd b)
{
    double p = a.hi * b.hi;
    double e = fma(a.hi, b.hi, -p); /* exact (libm fma is correctly rounded) */
    return dd_norm(p, e + a.hi * b.lo + a.lo * b.hi);
}

static dd dd_div(dd a, dd b)
{
    double q1 = a.hi / b.hi;
    dd r = dd_sub(a, dd_mul(dd_d(q1), b));
    double q2 = r.hi / b.hi;
    return dd_norm(q1, q2);
}

static dd dd_sqrt(dd a)
{
    double r0;
    if (a.hi <= 0.0)
        return dd_d(0.0);
    r0 = sqrt(a.hi);
    /* one Newton step: r0 + (a - r0^2) / (2 r0) */
    return dd_norm(r0, dd_sub(a, dd_mul(dd_d(r0), dd_d(r0))).hi / (2.0 * r0));
}

/* dd within [-1, 1], judged on the whole value: c = -1 - 1e-17 has c.hi = -1 */
static int dd_in_unit(dd c)
{
    if (c.hi == -1.0)
        return c.lo >= 0.0;
    if (c.hi == 1.0)
        return c.lo <= 0.0;
    return c.hi > -1.0 && c.hi < 1.0;
}

static dd dd_half(dd a) { a.hi *= 0.5; a.lo *= 0.5; return a; } /* exact */

/* The geometry, and y = 1 - L.H to full relative precision: L.H is close to
 * 1 wherever L is close to V, and Fresnel raises 1 - L.H to the fifth power.
 *
 * tan^2(theta_h) is |h_t|^2 / h_z^2 with h = L + V, formed for both branches
 * from the identities |h|^2 = 2 + 2 L.V, h_z = N.L + N.V on the exact inputs:
 * |h_t|^2 = 2t - s^2 (t = 1 + L.V, s = N.L + N.V) in double-double has an
 * error of ~2^-105 (2t), whereas through the built vectors it inherits the
 * error of the azimuth cosine c, which where L is nearly opposite V at
 * grazing angles (1 + c ~ 1e-19) is 1e-13 of tan^2. */
static facet_oracle_geom geometry_y(double nol, double nov, double lov, double *y)
{
    facet_oracle_geom g;
    double nl = cosd(nol), nv = cosd(nov), lv = clampd(lov, -1.0, 1.0);
    dd one = dd_d(1.0);
    dd sl = dd_sqrt(dd_sub(one, dd_mul(dd_d(nl), dd_d(nl))));
    dd sv = dd_sqrt(dd_sub(one, dd_mul(dd_d(nv), dd_d(nv))));
    dd slsv = dd_mul(sl, sv);
    dd c = dd_d(0.0);
    dd s = dd_add(dd_d(nl), dd_d(nv));
    dd t = dd_add(one, dd_d(lv));
    dd s2 = dd_mul(s, s);
    dd num = dd_sub(dd_add(t, t), s2); /* |h|^2 - h_z^2 = |h_t|^2 */
    dd l_h;

    g.n_l = nl;
    g.n_v = nv;
    if (slsv.hi > 0.0) {
        /* cos of the azimuth between L and V */
        c = dd_div(dd_sub(dd_d(lv), dd_mul(dd_d(nl), dd_d(nv))), slsv);
        g.consistent = dd_in_unit(c);
    } else {
        g.consistent = lv == nl * nv; /* L or V is N: L.V must be the other cosine */
    }
    if (g.consistent) {
        /* N = z, V = (sv, 0, nv), L = (sl c, sl sqrt(1 - c^2), nl), h = L + V */
        dd s_phi = dd_sqrt(dd_mul(dd_sub(one, c), dd_add(one, c)));
        dd hx = dd_add(dd_mul(sl, c), sv);
        dd hy = dd_mul(sl, s_phi);
        dd hz = dd_add(dd_d(nl), dd_d(nv));
        dd hxy2 = dd_add(dd_mul(hx, hx), dd_mul(hy, hy));
        dd len2 = dd_add(hxy2, dd_mul(hz, hz));
        dd len = dd_sqrt(len2);
        /* L.h = sl c (sl c + sv) + sl^2 (1 - c^2) + nl (nl + nv) */
        dd lh = dd_add(dd_add(dd_mul(dd_mul(sl, c), hx), dd_mul(hy, hy)), dd_mul(dd_d(nl), hz));
        dd lvv = dd_add(dd_mul(dd_mul(sl, c), sv), dd_mul(dd_d(nl), dd_d(nv)));
        l_h = dd_div(lh, len);
        g.n_h = dd_div(hz, len).hi;
        g.l_v = lvv.hi;
        /* t = 1 + L.V as given (exact in double-double), not 1 + g.l_v:
         * near L.V = -1 a double l_v keeps only 2^-53 / t of t */
    } else {
        /* No unit vectors have these dots: the identities, with t = 1 + L.V
         * raised to (N.L + N.V)^2 / 2 (the contract's extension).  Rounding
         * turns mirror pairs into such triples all the time, so these are
         * peak values too: double-double as well. */
        if (num.hi < 0.0) {
            t = dd_half(s2);
            num = dd_d(0.0);
        }
        l_h = dd_sqrt(dd_half(t));
        g.n_h = dd_div(s, dd_sqrt(dd_add(t, t))).hi;
        g.l_v = dd_sub(t, one).hi;
    }
    /* t itself, to full relative precision: facing = t/2 is made of it
     * alone, and near L.V = -1 (t down to 2^-39 at the raise) l_v = t - 1
     * as a double would have lost all but 53 - 39 of its bits */
    g.t = t.hi;
    g.l_h = l_h.hi;
    g.tan2_h = num.hi > 0.0 ? dd_div(num, s2).hi : 0.0;
    /* 1 - L.H = (1 - L.H^2) / (1 + L.H), L.H^2 = |h|^2 / 4 = t / 2; exact 0
     * at L = V, where 1 - L.h/|h| would leave the double-double's rounding */
    *y = dd_div(dd_sub(one, dd_half(t)), dd_add(one, l_h)).hi;
    if (g.n_h > 1.0)
        g.n_h = 1.0;
    if (g.l_h > 1.0)
        g.l_h = 1.0;
    if (*y < 0.0)
        *y = 0.0;
    return g;
}

facet_oracle_geom facet_oracle_geometry(double nol, double nov, double lov)
{
    double y;
    return geometry_y(nol, nov, lov, &y);
}

double facet_oracle_noh_from_dots(double nol, double nov, double lov)
{
    return facet_oracle_geometry(nol, nov, lov).n_h;
}

double facet_oracle_loh_from_dots(double lov)
{
    double lv = clampd(lov, -1.0, 1.0);
    if (lv == -1.0)
        return 0.0; /* H undefined; the contract says 0 */
    /* the cosine of half the angle between L and V; for an obtuse angle
     * pi - acos(-L.V), whose half-angle cosine is sin(acos(-L.V) / 2): acos
     * near pi has lost the small angle that the result is made of */
    if (lv < 0.0)
        return sin(0.5 * acos(-lv));
    return cos(0.5 * acos(lv));
}

/* F from y = 1 - cos */
static double fresnel_y(double f0, double y)
{
    f0 = unitd(f0);
    return f0 + (1.0 - f0) * pow(y, 5.0);
}

double facet_oracle_fresnel_schlick(double f0, double cos_theta)
{
    return fresnel_y(f0, 1.0 - unitd(cos_theta));
}

/* Schlick with a free grazing value: f0 + (f90 - f0)(1 - c)^5, as the
 * convex combination f0 (1 - (1 - c)^5) + f90 (1 - c)^5 (no cancellation
 * when f90 < f0; 1 - (1 - c)^5 by expm1/log1p at small c) */
static double one_minus_pow5(double x);

double facet_oracle_fresnel_schlick_f90(double f0, double f90, double voh)
{
    double c = unitd(voh);
    return unitd(f0) * one_minus_pow5(c) + unitd(f90) * pow(1.0 - c, 5.0);
}

/* The Fresnel equations of a dielectric interface (relative index eta > 1,
 * light from the outside), unpolarised: with Snell's law for the refracted
 * cosine ct = sqrt(eta^2 - 1 + c^2) / eta,
 *   rs = (c - eta ct) / (c + eta ct),  rp = (ct - eta c) / (ct + eta c),
 *   F = (rs^2 + rp^2) / 2,
 * and eta from f0 = ((eta - 1)/(eta + 1))^2.  The numerators are differences
 * of nearly equal terms where eta -> 1 (f0 -> 0), so they are formed from
 * their difference of squares, with m = eta^2 - 1 = 4 sqrt(f0) / (1 -
 * sqrt(f0))^2 (m = 4 s (1 + s)^2 / (1 - f0)^2, s = sqrt f0):
 *   c^2 - eta^2 ct^2 = -m,  ct^2 - eta^2 c^2 = m (1 - (m + 2) c^2) / eta^2,
 * so rs = -m / (c + w)^2, rp = m (1 - (m + 2) c^2) / (w + (1 + m) c)^2 with
 * w = eta ct = sqrt(m + c^2).  f0 = 1 (eta infinite): F = 1; f0 = 0 (eta =
 * 1, no interface): F = 0, also at c = 0. */
double facet_oracle_fresnel_cook_torrance(double f0, double voh)
{
    double f = unitd(f0), c = unitd(voh), s, m, w, rs, rp;
    if (f >= 1.0)
        return 1.0;
    if (f <= 0.0)
        return 0.0;
    s = sqrt(f);
    m = 4.0 * s * (1.0 + s) * (1.0 + s) / ((1.0 - f) * (1.0 - f));
    w = sqrt(m + c * c);
    rs = -m / ((c + w) * (c + w));
    rp = m * (1.0 - (m + 2.0) * c * c) / ((w + (1.0 + m) * c) * (w + (1.0 + m) * c));
    return 0.5 * (rs * rs + rp * rp);
}

/* the spherical-Gaussian Schlick: f0 + (1 - f0) 2^((-5.55473 c - 6.98316) c) */
double facet_oracle_fresnel_schlick_sg(double f0, double cos_theta)
{
    double f = unitd(f0), c = unitd(cos_theta);
    return f + (1.0 - f) * exp2((-5.55473 * c - 6.98316) * c);
}

/* D(m) = alpha^2 / (pi cos^4(theta_m) (alpha^2 + tan^2(theta_m))^2) */
double facet_oracle_ggx_d_tan2(double tan2_h, double cos_h, double alpha)
{
    double a2 = alpha * alpha, c2 = cos_h * cos_h, q = a2 + tan2_h;
    return a2 / (PI * c2 * c2 * q * q);
}

double facet_oracle_ggx_d(double noh, double alpha)
{
    double c = unitd(noh), a = alphad(alpha);
    if (c == 0.0)
        return a * a / PI; /* the limit theta_m -> 90 degrees */
    /* sin^2 as (1 - c)(1 + c), exact but for two roundings: 1 - c*c would
     * cost 2^-53 absolute, ~1e-10 of D at the peak for alpha = 2^-10 */
    return facet_oracle_ggx_d_tan2((1.0 - c) * (1.0 + c) / (c * c), c, a);
}

/* ---- D terms beyond GGX ----------------------------------------------------
 * From the definitions, with pow/exp/expm1; each normalised so that the
 * integral of D(m) (n.m) over the hemisphere is 1 (tests/oracle/test_oracle.c
 * checks it by quadrature). */

/* Blinn-Phong: N.H^p / (pi alpha^2), p = 2 / alpha^2 - 2 = 2 (1 - alpha^2) / alpha^2 */
double facet_oracle_blinn_phong_d(double noh, double alpha)
{
    double n = unitd(noh), a = alphad(alpha), a2 = a * a;
    double p = 2.0 * (1.0 - a) * (1.0 + a) / a2;
    return pow(n, p) / (PI * a2);
}

/* Beckmann: exp(-tan^2 / alpha^2) / (pi alpha^2 cos^4) */
double facet_oracle_beckmann_d(double noh, double alpha)
{
    double n = unitd(noh), a = alphad(alpha), a2 = a * a, t2;
    if (n == 0.0)
        return 0.0; /* the limit */
    t2 = (1.0 - n) * (1.0 + n) / (n * n);
    return exp(-t2 / a2) / (PI * a2 * n * n * n * n);
}

/* anisotropic GGX: 1 / (pi ax ay k^2), k = (T.H/ax)^2 + (B.H/ay)^2 + N.H^2,
 * k floored at 1/2 (the contract's extension to non-unit h) */
double facet_oracle_ggx_aniso_d(double noh, double toh, double boh, double alpha_x,
                                double alpha_y)
{
    double ax = alphad(alpha_x), ay = alphad(alpha_y), n = unitd(noh);
    double x = sgnd(toh) / ax, y = sgnd(boh) / ay;
    double k = fmax(x * x + y * y + n * n, 0.5);
    return 1.0 / (PI * ax * ay * k * k);
}

/* GTR: c / (1 + (alpha^2 - 1) N.H^2)^gamma,
 * c = (gamma - 1)(alpha^2 - 1) / (pi (1 - alpha^(2 (1 - gamma)))), with its
 * limits: (alpha^2 - 1) / (pi ln alpha^2) at gamma = 1, 1/pi at alpha = 1. */
static double gtr_gamma(double g) { return clampd(g, 0.0, 4.0); }

double facet_oracle_gtr_d(double noh, double alpha, double gamma)
{
    double n = unitd(noh), a = alphad(alpha), g = gtr_gamma(gamma), a2 = a * a, c, d;
    double la2 = 2.0 * log(a);
    if (a == 1.0)
        c = 1.0 / PI;
    else if (g == 1.0)
        c = (a2 - 1.0) / (PI * la2);
    else
        c = (g - 1.0) * (a2 - 1.0) / (PI * -expm1((1.0 - g) * la2));
    d = (1.0 - n) * (1.0 + n) + (n * a) * (n * a);
    return c / pow(d, g);
}

/* ---- Smith G1 for GTR (Dimov 2015) ----------------------------------------
 * Closed forms of G1 = 1 / (1 + Lambda) for gamma = 0 .. 4, rewritten from
 * mu = cot(theta_v) to n = N.V (multiplying through by sin theta_v = sqrt(s2),
 * s2 = 1 - n^2), with W = sqrt(n^2 + alpha^2 s2) (mu^2 + alpha^2 = W^2 / s2):
 *   G^0 = 2n / (1 + n)                         (the uniform D, 1/pi)
 *   G^1 = n / (n + e s2 (W + n (1 - R(u))) / ((W + 1)(n + W))),
 *         e = (alpha^2 - 1) / ln alpha^2, u = (1 - alpha^2) s2 / ((W + 1)(n + W)),
 *         R(u) = ln(1 + u) / u   (Dimov's form divided through by ln alpha^2:
 *         A - B = (alpha^2 - 1) / (A + B), and the log of
 *         (mu + B) / (mu + A) = 1 + u; no 0/0 at alpha = 1)
 *   G^2 = 2n / (n + W)                         (GGX, smith_g1)
 *   G^3 = 4 (1 + alpha^2) n W / (alpha^2 (3 alpha^2 + 1) s2 + 2 (1 + alpha^2) n (n + W))
 *   G^4 = 2 K n W^3 / (K n (W^3 + n^3) + 3 alpha^2 (alpha^2 P5 s2^2 + 4 n^2 s2 P2)),
 *         K = 8 (alpha^4 + alpha^2 + 1), P5 = 5 alpha^4 + 2 alpha^2 + 1,
 *         P2 = 2 alpha^4 + alpha^2 + 1.
 * All equal 2n / (1 + n) at alpha = 1.  Between the orders, Dimov
 * interpolates "by a spline" without saying which: we take the monotone
 * piecewise cubic Hermite interpolant (Fritsch-Carlson, as MATLAB's pchip)
 * through the five values at gamma = 0, 1, 2, 3, 4, which stays between
 * neighbouring values; the natural cubic spline overshoots to G1 = -0.099
 * (N.V = 0.0017, alpha = 2^-10, gamma = 0.56). */
static void g1_gtr_orders(double n, double a, double g[5])
{
    double a2 = a * a, s2 = (1.0 - n) * (1.0 + n), W = sqrt(n * n + a2 * s2);
    double la2 = 2.0 * log(a), e = a == 1.0 ? 1.0 : expm1(la2) / la2;
    double u = (1.0 - a2) * s2 / ((W + 1.0) * (n + W)), R = u > 0.0 ? log1p(u) / u : 1.0;
    double K = 8.0 * (a2 * a2 + a2 + 1.0), P5 = 5.0 * a2 * a2 + 2.0 * a2 + 1.0;
    double P2 = 2.0 * a2 * a2 + a2 + 1.0, W3 = W * W * W;
    if (n == 0.0) {
        g[0] = g[1] = g[2] = g[3] = g[4] = 0.0;
        return;
    }
    g[0] = 2.0 * n / (1.0 + n);
    g[1] = n / (n + e * s2 * (W + n * (1.0 - R)) / ((W + 1.0) * (n + W)));
    g[2] = 2.0 * n / (n + W);
    g[3] = 4.0 * (1.0 + a2) * n * W / (a2 * (3.0 * a2 + 1.0) * s2 + 2.0 * (1.0 + a2) * n * (n + W));
    g[4] = 2.0 * K * n * W3 / (K * n * (W3 + n * n * n) + 3.0 * a2 * (a2 * P5 * s2 * s2 + 4.0 * n * n * s2 * P2));
}

double facet_oracle_smith_g1_gtr_order(double nov, double alpha, int order)
{
    double g[5];
    g1_gtr_orders(unitd(nov), alphad(alpha), g);
    return g[order < 0 ? 0 : order > 4 ? 4 : order];
}

/* Fritsch-Carlson end slope (MATLAB pchip's): the one-sided three-point
 * estimate, zeroed if it points against the first secant, limited to 3 times
 * it where the data turn */
static double pchip_end(double d0, double d1)
{
    double m = (3.0 * d0 - d1) / 2.0;
    if (m * d0 <= 0.0)
        return 0.0;
    if (d0 * d1 <= 0.0 && fabs(m) > 3.0 * fabs(d0))
        return 3.0 * d0;
    return m;
}

double facet_oracle_smith_g1_gtr(double nov, double alpha, double gamma)
{
    double y[5], d[4], m[5], t, G = gtr_gamma(gamma);
    int j, k;
    g1_gtr_orders(unitd(nov), alphad(alpha), y);
    for (k = 0; k < 4; k++)
        d[k] = y[k + 1] - y[k];
    for (k = 1; k < 4; k++) /* harmonic mean of the secants, 0 at a turn */
        m[k] = d[k - 1] * d[k] > 0.0 ? 2.0 * d[k - 1] * d[k] / (d[k - 1] + d[k]) : 0.0;
    m[0] = pchip_end(d[0], d[1]);
    m[4] = pchip_end(d[3], d[2]);
    j = G >= 3.0 ? 3 : (int)G;
    t = G - j;
    return (1.0 + 2.0 * t) * (1.0 - t) * (1.0 - t) * y[j] + t * t * (3.0 - 2.0 * t) * y[j + 1]
           + t * (1.0 - t) * (1.0 - t) * m[j] - t * t * (1.0 - t) * m[j + 1];
}

/* The exact G1 of GTR by quadrature, from the Smith normalisation
 * int G1(v) max(0, v.m) D(m) dw_m = N.V with G1 independent of m:
 * G1 = N.V / I, I = int_0^{pi/2} D(theta) f(theta) sin(theta) dtheta, where
 * the azimuth integral f = int max(0, a cos phi + b) dphi (a = sin theta_v
 * sin theta, b = N.V cos theta) is 2 pi b for b >= a, else
 * 2 (a sin phi_c + b phi_c), cos phi_c = -b / a.  Gauss-Legendre (32
 * nodes, computed here) on panels doubling away from the peak, with the
 * kink at theta = pi/2 - theta_v a breakpoint and the panel after it mapped
 * by u^2 (f - its left side behaves like (theta - kink)^(3/2)). */
typedef struct { double n, sv, a, g; } g1x_ctx;

static double g1x_f(double th, const g1x_ctx *k)
{
    double ct = cos(th), st = sin(th), a = k->sv * st, b = k->n * ct, f;
    if (b >= a)
        f = 2.0 * PI * b;
    else {
        double r = b / a;
        f = 2.0 * (a * sqrt((1.0 - r) * (1.0 + r)) + b * acos(-r));
    }
    return facet_oracle_gtr_d(ct, k->a, k->g) * f * st;
}

#define GLN_ 32
/* the Legendre polynomial P_GLN_(z) by its recurrence; *dp = P'(z) */
static double g1x_legendre(double z, double *dp)
{
    double p0 = 1.0, p1 = z;
    int k;
    for (k = 2; k <= GLN_; k++) {
        double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
    }
    *dp = GLN_ * (z * p1 - p0) / (z * z - 1.0);
    return p1;
}

static void g1x_rule(double *x, double *w)
{
    int i, it;
    for (i = 0; i < GLN_; i++) {
        double z = cos(PI * (i + 0.75) / (GLN_ + 0.5)), dp;
        for (it = 0; it < 100; it++) { /* Newton on P's root */
            double p = g1x_legendre(z, &dp), dz = p / dp;
            z -= dz;
            if (fabs(dz) < 1e-16)
                break;
        }
        g1x_legendre(z, &dp);
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
}

static double g1x_panel(const g1x_ctx *k, double lo, double hi, int sq, const double *x, const double *w)
{
    double s = 0.0;
    int i;
    for (i = 0; i < GLN_; i++) {
        if (sq) {
            double u = 0.5 + 0.5 * x[i];
            s += w[i] * g1x_f(lo + (hi - lo) * u * u, k) * 2.0 * u;
        } else
            s += w[i] * g1x_f(0.5 * (lo + hi) + 0.5 * (hi - lo) * x[i], k);
    }
    return 0.5 * (hi - lo) * s;
}

double facet_oracle_smith_g1_gtr_exact(double nov, double alpha, double gamma)
{
    double x[GLN_], w[GLN_], bp[96], I = 0.0, kink, t;
    g1x_ctx k;
    int nb = 0, i, j;
    k.n = unitd(nov);
    k.a = alphad(alpha);
    k.g = gtr_gamma(gamma);
    k.sv = sqrt((1.0 - k.n) * (1.0 + k.n));
    if (k.n == 0.0)
        return 0.0;
    g1x_rule(x, w);
    kink = atan2(k.n, k.sv); /* pi/2 - theta_v */
    bp[nb++] = 0.0;
    for (t = k.a / 256.0; t < 0.7 * PI / 2; t *= 2.0)
        bp[nb++] = t;
    bp[nb++] = PI / 2;
    if (k.sv > 0.0) {
        bp[nb++] = kink;
        for (j = 0; j <= 16; j++)
            bp[nb++] = kink + (PI / 2 - kink) * exp2(-j);
    }
    /* sort (insertion: at most ~45 entries) */
    for (i = 1; i < nb; i++)
        for (j = i; j > 0 && bp[j - 1] > bp[j]; j--) {
            t = bp[j];
            bp[j] = bp[j - 1];
            bp[j - 1] = t;
        }
    for (i = 0; i + 1 < nb; i++)
        if (bp[i + 1] > bp[i])
            I += g1x_panel(&k, bp[i], bp[i + 1], k.sv > 0.0 && bp[i] == kink, x, w);
    return fmin(k.n / I, 1.0);
}

/* Lambda(theta) = (-1 + sqrt(1 + x)) / 2, x = alpha^2 tan^2 theta; for
 * x < 1 as x / (2 (1 + sqrt(1 + x))), which does not cancel (Lambda is
 * tiny near the normal and for small alpha). */
double facet_oracle_smith_lambda(double nov, double alpha)
{
    double c = nov, a = alpha, x;
    if (c <= 0.0)
        return INFINITY;
    x = a * a * ((1.0 - c) * (1.0 + c)) / (c * c);
    if (x < 1.0)
        return 0.5 * x / (1.0 + sqrt(1.0 + x));
    return 0.5 * (sqrt(1.0 + x) - 1.0);
}

double facet_oracle_smith_g1(double nov, double alpha)
{
    return 1.0 / (1.0 + facet_oracle_smith_lambda(unitd(nov), alphad(alpha)));
}

double facet_oracle_smith_g2(double nol, double nov, double alpha)
{
    double a = alphad(alpha);
    return 1.0 / (1.0 + facet_oracle_smith_lambda(cosd(nol), a)
                  + facet_oracle_smith_lambda(cosd(nov), a));
}

double facet_oracle_smith_g2_uncorrelated(double nol, double nov, double alpha)
{
    double a = alphad(alpha);
    return facet_oracle_smith_g1(cosd(nol), a) * facet_oracle_smith_g1(cosd(nov), a);
}

double facet_oracle_smith_vis(double nol, double nov, double alpha)
{
    double nl = cosd(nol), nv = cosd(nov);
    return facet_oracle_smith_g2(nl, nv, alpha) / (4.0 * nl * nv);
}

double facet_oracle_smith_g1_hammon(double nov, double alpha)
{
    double c = unitd(nov), a = alphad(alpha);
    return 2.0 * c / (lerpd(c, 1.0, a) + c);
}

double facet_oracle_smith_g2_hammon(double nol, double nov, double alpha)
{
    double nl = cosd(nol), nv = cosd(nov), a = alphad(alpha);
    return 2.0 * nl * nv / lerpd(2.0 * nl * nv, nl + nv, a);
}

double facet_oracle_smith_vis_hammon(double nol, double nov, double alpha)
{
    double nl = cosd(nol), nv = cosd(nov);
    return facet_oracle_smith_g2_hammon(nl, nv, alpha) / (4.0 * nl * nv);
}

/* ---- shadowing and visibility: the rest of the menu ------------------------ */

double facet_oracle_g_implicit(double nol, double nov)
{
    return unitd(nol) * unitd(nov);
}

/* Karis's form; 0 where both are 0 (the limit along any path is 0) */
double facet_oracle_g_neumann(double nol, double nov)
{
    double nl = unitd(nol), nv = unitd(nov), m = fmax(nl, nv);
    return m > 0.0 ? nl * nv / m : 0.0;
}

double facet_oracle_g_cook_torrance(double nol, double nov, double noh, double voh)
{
    double nl = cosd(nol), nv = cosd(nov), nh = unitd(noh), vh = unitd(voh);
    double g;
    if (vh == 0.0)
        return 1.0; /* both ratios are +Inf (N.H > 0) or 0/0: the cap */
    g = fmin(2.0 * nh * nv / vh, 2.0 * nh * nl / vh);
    return fmin(1.0, g);
}

double facet_oracle_g_kelemen(double nol, double nov, double voh)
{
    double nl = cosd(nol), nv = cosd(nov), vh = unitd(voh);
    if (vh == 0.0)
        return 1.0;
    return fmin(1.0, nl * nv / (vh * vh));
}

/* c = N.V / (alpha sqrt(1 - N.V^2)); 1 - N.V^2 as (1 - n)(1 + n) */
static double beckmann_c(double n, double a)
{
    double w = (1.0 - n) * (1.0 + n);
    return w > 0.0 ? n / (a * sqrt(w)) : INFINITY;
}

double facet_oracle_smith_g1_beckmann(double nov, double alpha)
{
    double c = beckmann_c(unitd(nov), alphad(alpha));
    if (!(c < 1.6))
        return 1.0;
    return fmin(1.0, (3.535 * c + 2.181 * c * c) / (1.0 + 2.276 * c + 2.577 * c * c));
}

/* 1 / (1 + Lambda), Lambda = (erf(c) - 1)/2 + exp(-c^2) / (2 c sqrt(pi)),
 * with erf(c) - 1 = -erfc(c) (no cancellation in erf itself) */
double facet_oracle_smith_g1_beckmann_exact(double nov, double alpha)
{
    double n = unitd(nov), c = beckmann_c(n, alphad(alpha)), lambda;
    if (n == 0.0)
        return 0.0;
    if (isinf(c))
        return 1.0;
    lambda = 0.5 * (exp(-c * c) / (c * sqrt(PI)) - erfc(c));
    return 1.0 / (1.0 + lambda);
}

double facet_oracle_smith_g1_schlick_beckmann(double nov, double alpha)
{
    double n = unitd(nov), k = alphad(alpha) * sqrt(2.0 / PI);
    return n / (n * (1.0 - k) + k);
}

double facet_oracle_smith_vis_joint_approx(double nol, double nov, double alpha)
{
    double nl = cosd(nol), nv = cosd(nov), a = alphad(alpha);
    return 0.5 / (nl * (nv * (1.0 - a) + a) + nv * (nl * (1.0 - a) + a));
}

/* r~(x) = max(k1 a, k2 a + k3 t, k4 a + k5 t), t = x (1 + a (c1 + c2 a)),
 * with the constants of facet/detail/vis_fit.h (stored as 2 k_i) */
static double vis_fit_r(double x, double a)
{
    double t = x * (1.0 + a * ((double)FACET_VIS_FIT_C1 + (double)FACET_VIS_FIT_C2 * a));
    double l1 = 0.5 * (double)FACET_VIS_FIT_K1 * a;
    double l2 = 0.5 * ((double)FACET_VIS_FIT_K2 * a + (double)FACET_VIS_FIT_K3 * t);
    double l3 = 0.5 * ((double)FACET_VIS_FIT_K4 * a + (double)FACET_VIS_FIT_K5 * t);
    return fmax(l1, fmax(l2, l3));
}

double facet_oracle_smith_vis_fit(double nol, double nov, double alpha)
{
    double nl = cosd(nol), nv = cosd(nov), a = alphad(alpha);
    return 0.5 / (nv * vis_fit_r(nl, a) + nl * vis_fit_r(nv, a));
}

/* 1 - (1 - x)^5 as -expm1(5 log1p(-x)): 1 - pow(1 - x, 5) cancels for
 * small x (relative error 2^-53 / (5 x), 2e-11 at x = 1e-6) */
static double one_minus_pow5(double x)
{
    return -expm1(5.0 * log1p(-x));
}

static double diffuse_from_geom(const facet_oracle_geom *g, double alpha, double albedo)
{
    double a = alphad(alpha), rho = unitd(albedo);
    double facing = 0.5 * g->t; /* 0.5 + 0.5 L.V, from t = 1 + L.V */
    double rough = facing * (0.9 - 0.4 * facing) * ((0.5 + g->n_h) / g->n_h);
    double smooth = 1.05 * one_minus_pow5(g->n_l) * one_minus_pow5(g->n_v);
    /* lerp as (1 - a) smooth + a rough: two non-negative terms, whereas
     * smooth + a (rough - smooth) cancels where rough << smooth (grazing
     * angles, L.V near -1) and alpha is near 1 */
    double single = ((1.0 - a) * smooth + a * rough) / PI;
    double multi = 0.1159 * a;
    return rho * (single + rho * multi);
}

double facet_oracle_diffuse_hammon(double nol, double nov, double lov, double alpha,
                                   double albedo)
{
    facet_oracle_geom g = facet_oracle_geometry(nol, nov, lov);
    return diffuse_from_geom(&g, alpha, albedo);
}

/* Burley: albedo / pi (1 + (f_d90 - 1)(1 - N.L)^5)(1 + (f_d90 - 1)(1 - N.V)^5),
 * f_d90 = 0.5 + 2 roughness L.H^2 with Disney's roughness = sqrt(alpha) */
double facet_oracle_diffuse_burley(double nol, double nov, double loh, double alpha,
                                   double albedo)
{
    double nl = cosd(nol), nv = cosd(nov), lh = unitd(loh), a = alphad(alpha);
    double fd90 = 0.5 + 2.0 * sqrt(a) * lh * lh;
    return unitd(albedo) / PI * (1.0 + (fd90 - 1.0) * pow(1.0 - nl, 5.0))
           * (1.0 + (fd90 - 1.0) * pow(1.0 - nv, 5.0));
}

/* Oren-Nayar's qualitative model, sigma = alpha / 2, from the angles:
 * theta = acos of each cosine, the azimuth difference from L.V = cos cos +
 * sin sin cos(phi) (unclamped: inconsistent triples extend it), and
 * albedo / pi (A + B max(0, cos phi) sin(theta_max) tan(theta_min)).
 * With L or V along N (a sine 0) the azimuth is undefined and the term is
 * the limit of the definition's product, max(0, L.V - N.L N.V) / max(N.L, N.V)
 * (0 for consistent dots). */
double facet_oracle_diffuse_oren_nayar(double nol, double nov, double lov, double alpha,
                                       double albedo)
{
    double nl = cosd(nol), nv = cosd(nov), lv = clampd(lov, -1.0, 1.0), a = alphad(alpha);
    double sigma2 = 0.25 * a * a;
    double A = 1.0 - 0.5 * sigma2 / (sigma2 + 0.33), B = 0.45 * sigma2 / (sigma2 + 0.09);
    double tl = acos(nl), tv = acos(nv), sl = sin(tl), sv = sin(tv), term;
    if (sl > 0.0 && sv > 0.0) {
        double cphi = (lv - nl * nv) / (sl * sv);
        term = (cphi > 0.0 ? cphi : 0.0) * sin(fmax(tl, tv)) * tan(fmin(tl, tv));
    } else {
        term = fmax(lv - nl * nv, 0.0) / fmax(nl, nv);
    }
    return unitd(albedo) / PI * (A + B * term);
}

/* Hammon's diffuse with the smooth term replaced (diffuse_from_geom's
 * rough, single and multi) */
static double diffuse_variant(const facet_oracle_geom *g, double alpha, double albedo,
                              double smooth)
{
    double a = alphad(alpha), rho = unitd(albedo);
    double facing = 0.5 * g->t;
    double rough = facing * (0.9 - 0.4 * facing) * ((0.5 + g->n_h) / g->n_h);
    double single = ((1.0 - a) * smooth + a * rough) / PI;
    return rho * (single + rho * 0.1159 * a);
}

/* hybrid: smooth = Disney's two factors at f_d90 = 0.5 */
double facet_oracle_diffuse_hammon_hybrid(double nol, double nov, double lov, double alpha,
                                          double albedo)
{
    facet_oracle_geom g = facet_oracle_geometry(nol, nov, lov);
    double smooth = (1.0 - 0.5 * pow(1.0 - g.n_l, 5.0)) * (1.0 - 0.5 * pow(1.0 - g.n_v, 5.0));
    return diffuse_variant(&g, alpha, albedo, smooth);
}

/* cheaper: smooth = 1 (Lambert) */
double facet_oracle_diffuse_hammon_cheap(double nol, double nov, double lov, double alpha,
                                         double albedo)
{
    facet_oracle_geom g = facet_oracle_geometry(nol, nov, lov);
    return diffuse_variant(&g, alpha, albedo, 1.0);
}

double facet_oracle_brdf_hammon(double nol, double nov, double lov, double alpha,
                                double f0, double albedo)
{
    double y;
    facet_oracle_geom g = geometry_y(nol, nov, lov, &y);
    double a = alphad(alpha);
    double d = facet_oracle_ggx_d_tan2(g.tan2_h, g.n_h, a);
    double g2 = facet_oracle_smith_g2_hammon(g.n_l, g.n_v, a);
    double f = fresnel_y(f0, y); /* not 1 - g.l_h: l_h is rounded near 1 */
    return d * g2 * f / (4.0 * g.n_l * g.n_v) + diffuse_from_geom(&g, a, albedo);
}

double facet_oracle_lambert(double albedo)
{
    return unitd(albedo) / PI;
}

/* ---- samplers (facet.h, "GGX and GTR importance sampling") ----------------
 * From the definitions: the inverse CDFs in their tan / slope form with
 * libm's atan-free sqrt, cos, sin, expm1, log; the VNDF in its spherical-cap
 * definition (Vh, the cap height z, c, H = Vh + c), with 1 - z^2 as is (in
 * double its cancellation costs ~1e-16 / |H|, far below the f32 bounds).
 * Domain handling as the contracts. */
#define U_MAX_ 0.99999994039535522 /* 1 - 2^-24 */
static double ud(double u) { return clampd(u, 0.0, U_MAX_); }

static void normalize3(double h[3], double x, double y, double z)
{
    double n = sqrt(x * x + y * y + z * z);
    h[0] = x / n;
    h[1] = y / n;
    h[2] = z / n;
}

void facet_oracle_sincos_2pi(double sc[2], double u)
{
    double p = 2.0 * PI * ud(u);
    sc[0] = sin(p);
    sc[1] = cos(p);
}

/* slope radius r = tan theta of the unit-width law: r^2 = u1 / (1 - u1) */
void facet_oracle_ggx_sample_d_aniso(double h[3], double u1, double u2, double alpha_x,
                                     double alpha_y)
{
    double u = ud(u1), r = sqrt(u / (1.0 - u)), p = 2.0 * PI * ud(u2);
    normalize3(h, alphad(alpha_x) * r * cos(p), alphad(alpha_y) * r * sin(p), 1.0);
}

void facet_oracle_ggx_sample_d(double h[3], double u1, double u2, double alpha)
{
    facet_oracle_ggx_sample_d_aniso(h, u1, u2, alpha, alpha);
}

double facet_oracle_ggx_pdf_d(double noh, double alpha)
{
    return facet_oracle_ggx_d(noh, alpha) * unitd(noh);
}

/* D(h) h.z = h.z / (pi ax ay k^2), k = (hx/ax)^2 + (hy/ay)^2 + hz^2 (unit h:
 * 1 / (ax ay cos^4 (1 + tan^2 (cos^2 phi / ax^2 + sin^2 phi / ay^2))^2)) */
double facet_oracle_ggx_pdf_d_aniso(double hx, double hy, double hz, double alpha_x,
                                    double alpha_y)
{
    double ax = alphad(alpha_x), ay = alphad(alpha_y);
    double x = sgnd(hx) / ax, y = sgnd(hy) / ay, z = unitd(hz);
    double k = fmax(x * x + y * y + z * z, 0.5);
    return z / (PI * ax * ay * k * k);
}

void facet_oracle_ggx_sample_vndf_aniso(double h[3], double vx, double vy, double vz, double u1,
                                        double u2, double alpha_x, double alpha_y)
{
    double ax = alphad(alpha_x), ay = alphad(alpha_y);
    double x = ax * sgnd(vx), y = ay * sgnd(vy), z = unitd(vz);
    double V[3], u = ud(u1), p = 2.0 * PI * ud(u2), cz, s, t, e1x = 1.0, e1y = 0.0, c1, c2;
    if (x * x + y * y + z * z < 0x1p-100) {
        x = y = 0.0;
        z = 1.0;
    }
    normalize3(V, x, y, z);
    t = sqrt(x * x + y * y); /* the azimuth of Vh, x at normal view */
    if (x * x + y * y >= 0x1p-100) {
        e1x = x / t;
        e1y = y / t;
    }
    cz = (1.0 - u) * (1.0 + V[2]) - V[2]; /* uniform in (-Vh.z, 1] */
    s = sqrt(fmax(0.0, 1.0 - cz * cz));
    c1 = s * cos(p); /* c along e1 and e2 = z x e1 */
    c2 = s * sin(p);
    normalize3(h, ax * (V[0] + c1 * e1x - c2 * e1y), ay * (V[1] + c1 * e1y + c2 * e1x),
               V[2] + cz);
}

void facet_oracle_ggx_sample_vndf(double h[3], double vx, double vy, double vz, double u1,
                                  double u2, double alpha)
{
    facet_oracle_ggx_sample_vndf_aniso(h, vx, vy, vz, u1, u2, alpha, alpha);
}

/* G1(v) / N.V, 2 / alpha at N.V = 0 (the limit) */
static double g1_over_nv(double nov, double alpha)
{
    double n = unitd(nov), a = alphad(alpha);
    return n > 0.0 ? facet_oracle_smith_g1(n, a) / n : 2.0 / a;
}

double facet_oracle_ggx_pdf_vndf(double nov, double noh, double voh, double alpha)
{
    return g1_over_nv(nov, alpha) * unitd(voh) * facet_oracle_ggx_d(noh, alpha);
}

double facet_oracle_ggx_pdf_vndf_reflect(double nov, double noh, double voh, double alpha)
{
    if (!(voh > 0.0))
        return 0.0;
    return g1_over_nv(nov, alpha) * facet_oracle_ggx_d(noh, alpha) / 4.0;
}

double facet_oracle_ggx_pdf_vndf_aniso(double vx, double vy, double vz, double hx, double hy,
                                       double hz, double alpha_x, double alpha_y)
{
    double ax = alphad(alpha_x), ay = alphad(alpha_y);
    double x = sgnd(vx), y = sgnd(vy), z = unitd(vz);
    double gx = sgnd(hx), gy = sgnd(hy), gz = unitd(hz);
    double den = fmax(z + sqrt(ax * ax * x * x + ay * ay * y * y + z * z), 0x1p-20);
    double vh = fmax(x * gx + y * gy + z * gz, 0.0);
    /* D = pdf_d_aniso / h.z; with h.z = 0, D = 1 / (pi ax ay k^2) directly */
    double x2 = gx / ax, y2 = gy / ay, k = fmax(x2 * x2 + y2 * y2 + gz * gz, 0.5);
    return 2.0 * vh / (PI * ax * ay * k * k) / den;
}

void facet_oracle_reflect(double l[3], double vx, double vy, double vz, double hx, double hy,
                          double hz)
{
    double v[3] = { sgnd(vx), sgnd(vy), sgnd(vz) }, h[3] = { sgnd(hx), sgnd(hy), sgnd(hz) };
    double d = v[0] * h[0] + v[1] * h[1] + v[2] * h[2];
    int i;
    for (i = 0; i < 3; i++)
        l[i] = 2.0 * d * h[i] - v[i];
}

/* GTR1: tan^2 theta = alpha^2 (alpha^(-2u) - 1) / (1 - alpha^(2 (1 - u)))
 * (from cos^2 theta = (1 - alpha^(2 (1 - u))) / (1 - alpha^2)), with
 * expm1; u / (1 - u) at alpha = 1. */
void facet_oracle_gtr_sample_d(double h[3], double u1, double u2, double alpha, double gamma)
{
    double a = alphad(alpha), u = ud(u1), p = 2.0 * PI * ud(u2), t2, t;
    if (!(gamma < 1.5)) {
        facet_oracle_ggx_sample_d(h, u1, u2, alpha);
        return;
    }
    if (a == 1.0) {
        t2 = u / (1.0 - u);
    } else {
        double l = 2.0 * log(a);
        t2 = a * a * expm1(-u * l) / -expm1((1.0 - u) * l);
    }
    t = sqrt(t2);
    normalize3(h, t * cos(p), t * sin(p), 1.0);
}

double facet_oracle_gtr_pdf_d(double noh, double alpha, double gamma)
{
    double n = unitd(noh), a = alphad(alpha), a2 = a * a, k, d;
    if (!(gamma < 1.5))
        return facet_oracle_ggx_pdf_d(noh, alpha);
    k = a == 1.0 ? 1.0 : (a2 - 1.0) / log(a2); /* (alpha^2 - 1) / ln alpha^2 */
    d = 1.0 + (a2 - 1.0) * n * n;
    return k / (PI * d) * n;
}
