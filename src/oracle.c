/* oracle.c - double-precision reference, from the definitions.
 * Built with -ffp-contract=off (Makefile).  See facet/oracle.h. */
#include <math.h>
#include "facet/common.h"
#include "facet/oracle.h"

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

facet_oracle_geom facet_oracle_geometry(double nol, double nov, double lov)
{
    facet_oracle_geom g;
    double nl = cosd(nol), nv = cosd(nov), lv = clampd(lov, -1.0, 1.0);
    dd one = dd_d(1.0);
    dd sl = dd_sqrt(dd_sub(one, dd_mul(dd_d(nl), dd_d(nl))));
    dd sv = dd_sqrt(dd_sub(one, dd_mul(dd_d(nv), dd_d(nv))));
    dd slsv = dd_mul(sl, sv);
    dd c = dd_d(0.0);

    g.n_l = nl;
    g.n_v = nv;
    if (slsv.hi > 0.0) {
        /* cos of the azimuth between L and V */
        c = dd_div(dd_sub(dd_d(lv), dd_mul(dd_d(nl), dd_d(nv))), slsv);
        g.consistent = c.hi >= -1.0 && c.hi <= 1.0;
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
        g.n_h = dd_div(hz, len).hi;
        g.l_h = dd_div(lh, len).hi;
        g.l_v = lvv.hi;
        g.tan2_h = dd_div(hxy2, dd_mul(hz, hz)).hi;
        if (g.n_h > 1.0)
            g.n_h = 1.0;
        if (g.l_h > 1.0)
            g.l_h = 1.0;
    } else {
        /* No unit vectors have these dots: the identities, with 1 + L.V
         * raised to (N.L + N.V)^2 / 2 (the contract's extension). */
        double s = nl + nv, t = 1.0 + lv;
        if (t < 0.5 * s * s)
            t = 0.5 * s * s;
        g.n_h = s / sqrt(2.0 * t);
        if (g.n_h > 1.0)
            g.n_h = 1.0;
        g.l_h = sqrt(0.5 * t);
        g.l_v = t - 1.0;
        g.tan2_h = (2.0 * t - s * s) / (s * s);
        if (g.tan2_h < 0.0)
            g.tan2_h = 0.0;
    }
    return g;
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
    return cos(0.5 * acos(lv)); /* the half angle between L and V */
}

double facet_oracle_fresnel_schlick(double f0, double cos_theta)
{
    f0 = unitd(f0);
    return f0 + (1.0 - f0) * pow(1.0 - unitd(cos_theta), 5.0);
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
    return facet_oracle_ggx_d_tan2((1.0 - c * c) / (c * c), c, a);
}

/* Lambda(theta) = (-1 + sqrt(1 + alpha^2 tan^2 theta)) / 2 */
double facet_oracle_smith_lambda(double nov, double alpha)
{
    double c = nov, a = alpha;
    if (c <= 0.0)
        return INFINITY;
    return 0.5 * (-1.0 + sqrt(1.0 + a * a * (1.0 - c * c) / (c * c)));
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

static double diffuse_from_geom(const facet_oracle_geom *g, double alpha, double albedo)
{
    double a = alphad(alpha), rho = unitd(albedo);
    double facing = 0.5 + 0.5 * g->l_v;
    double rough = facing * (0.9 - 0.4 * facing) * ((0.5 + g->n_h) / g->n_h);
    double smooth = 1.05 * (1.0 - pow(1.0 - g->n_l, 5.0)) * (1.0 - pow(1.0 - g->n_v, 5.0));
    double single = lerpd(smooth, rough, a) / PI;
    double multi = 0.1159 * a;
    return rho * (single + rho * multi);
}

double facet_oracle_diffuse_hammon(double nol, double nov, double lov, double alpha,
                                   double albedo)
{
    facet_oracle_geom g = facet_oracle_geometry(nol, nov, lov);
    return diffuse_from_geom(&g, alpha, albedo);
}

double facet_oracle_brdf_hammon(double nol, double nov, double lov, double alpha,
                                double f0, double albedo)
{
    facet_oracle_geom g = facet_oracle_geometry(nol, nov, lov);
    double a = alphad(alpha);
    double d = facet_oracle_ggx_d_tan2(g.tan2_h, g.n_h, a);
    double g2 = facet_oracle_smith_g2_hammon(g.n_l, g.n_v, a);
    double f = facet_oracle_fresnel_schlick(f0, g.l_h);
    return d * g2 * f / (4.0 * g.n_l * g.n_v) + diffuse_from_geom(&g, a, albedo);
}

double facet_oracle_lambert(double albedo)
{
    return unitd(albedo) / PI;
}
