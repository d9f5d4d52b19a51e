/* test_oracle.c - the double-precision oracle (src/oracle/oracle.c) validated on
 * its own.  Every f32 kernel is judged against the oracle, so the oracle is
 * not trusted here: it is checked against integrals with known values (D and
 * the smooth diffuse term are normalised, the Smith constraint), against the
 * Smith Lambda redone by quadrature from the slope distribution, against its
 * own symmetries and inequalities, and against an independent long double
 * evaluation at the ill-conditioned points.  Each check prints its measured
 * residual next to its tolerance; every quadrature is also run with a second,
 * higher-order rule so that the printed quadrature error backs the tolerance.
 * FACET_TEST_QUICK=1 cuts the random sample counts (sanitizer builds).
 * Which kernels a check covers comes from the kernel table (facet_kernel_at)
 * by their inputs and names: every D term (a name ending in _d) is
 * normalised, every term of N.L and N.V is symmetric in them, every
 * diffuse model (albedo and geometry only) gets the white furnace; the
 * golden values are per kernel (tests/lib/golden.h, the furnace's closed
 * forms below), each list checked to cover every kernel it should. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include "../lib/harness.h"
#include "../lib/sample.h"
#include "../lib/quad.h"
#include "../lib/golden.h"
#include "facet/oracle.h"

#define EPS DBL_EPSILON /* 2^-52 */

static int quick;

static double rel_err(double got, double want)
{
    if (got == want)
        return 0.0;
    if (got != got || want != want)
        return INFINITY;
    return fabs(got - want) / fabs(want);
}

/* One CHECK per family of sampled comparisons: how many exceeded the
 * tolerance, and the worst residual with where it was (NaN counts as worst). */
typedef struct {
    const char *what;
    double tol, worst;
    long n, bad;
    char where[320];
} agg;

static void agg_init(agg *a, const char *what, double tol)
{
    a->what = what;
    a->tol = tol;
    a->worst = 0.0;
    a->n = a->bad = 0;
    a->where[0] = '\0';
}

static void agg_add(agg *a, double e, const char *fmt, ...)
{
    a->n++;
    if (!(e <= a->tol))
        a->bad++;
    if (a->n == 1 || (a->worst == a->worst && !(e <= a->worst))) {
        va_list ap;
        a->worst = e;
        va_start(ap, fmt);
        vsnprintf(a->where, sizeof a->where, fmt, ap);
        va_end(ap);
    }
}

static double agg_done(const agg *a)
{
    CHECK(a->bad == 0, "%s: %ld of %ld beyond %.3g; worst %.3g at %s", a->what, a->bad, a->n, a->tol,
          a->worst, a->where);
    return a->worst;
}

/* ---- Gauss-Legendre quadrature (the rule: tests/lib/quad.h) ---------------
 * Integrals are split into panels so that each panel's integrand is
 * analytic and well resolved. */
typedef double (*fn1)(double x, const void *ctx);

static double gl_int(fn1 f, const void *ctx, double a, double b, const gl_rule *r)
{
    double h = 0.5 * (b - a), m = 0.5 * (a + b), s = 0.0;
    int i;
    for (i = 0; i < r->n; i++)
        s += r->w[i] * f(m + h * r->x[i], ctx);
    return h * s;
}

/* The same with x = a + (b - a) u^2, u in [0, 1]: turns an (x - a)^(3/2)
 * kink at the left end into a smooth u^3. */
static double gl_int_sq(fn1 f, const void *ctx, double a, double b, const gl_rule *r)
{
    double s = 0.0;
    int i;
    for (i = 0; i < r->n; i++) {
        double u = 0.5 + 0.5 * r->x[i];
        s += r->w[i] * f(a + (b - a) * u * u, ctx) * 2.0 * u;
    }
    return 0.5 * (b - a) * s;
}

static int cmp_dbl(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Over [min bp, max bp], one panel between consecutive breakpoints; the
 * panel that starts at `kink` uses the u^2 map. */
static double gl_panels(fn1 f, const void *ctx, double *bp, int n, double kink, const gl_rule *r)
{
    double s = 0.0;
    int i;
    qsort(bp, (size_t)n, sizeof *bp, cmp_dbl);
    for (i = 0; i + 1 < n; i++) {
        if (!(bp[i + 1] > bp[i]))
            continue;
        s += bp[i] == kink ? gl_int_sq(f, ctx, bp[i], bp[i + 1], r)
                           : gl_int(f, ctx, bp[i], bp[i + 1], r);
    }
    return s;
}

/* theta breakpoints for a peak of width ~alpha at theta = 0: 0, then
 * alpha 2^j from alpha/256 doubling up to pi/2, so that every panel spans a
 * factor 2 in theta and the peak's poles (theta = +-i alpha) stay far from
 * the panels relative to their width.  Returns the count (<= 24). */
static int peak_breaks(double alpha, double *bp)
{
    int n = 0;
    double x;
    bp[n++] = 0.0;
    for (x = alpha / 256.0; x < 0.7 * M_PI / 2; x *= 2.0)
        bp[n++] = x;
    bp[n++] = M_PI / 2;
    return n;
}

static gl_rule R8, R20, R32;

/* The rules themselves: sum of weights 2, and exact for x^(2n-2). */
static void check_rules(void)
{
    const gl_rule *rs[3];
    int j;
    rs[0] = &R8;
    rs[1] = &R20;
    rs[2] = &R32;
    for (j = 0; j < 3; j++) {
        const gl_rule *r = rs[j];
        double sw = 0.0, sx = 0.0;
        int i;
        for (i = 0; i < r->n; i++) {
            sw += r->w[i];
            sx += r->w[i] * pow(r->x[i], 2.0 * r->n - 2.0);
        }
        CHECK(fabs(sw - 2.0) < 1e-14 && fabs(sx - 2.0 / (2.0 * r->n - 1.0)) < 1e-14,
              "Gauss-Legendre n=%d: sum w - 2 = %.3g, int x^%d error %.3g", r->n, sw - 2.0,
              2 * r->n - 2, sx - 2.0 / (2.0 * r->n - 1.0));
    }
}

/* ---- 1. D normalisation: int D(m) cos(theta_m) dw_m = 1 ------------------
 * In theta: 2 pi int_0^{pi/2} D cos sin dtheta, on the peak panels. */
typedef struct {
    double alpha;
    int use_tan2;
} dn_ctx;

static double dn_f(double th, const void *c)
{
    const dn_ctx *k = c;
    double ct = cos(th), st = sin(th), tt = st / ct;
    double d = k->use_tan2 ? facet_oracle_ggx_d_tan2(tt * tt, ct, k->alpha)
                           : facet_oracle_ggx_d(ct, k->alpha);
    return 2.0 * M_PI * d * ct * st;
}

static void check_d_normalisation(void)
{
    agg ac, at, aq;
    int i;
    printf("1. D normalisation  int D cos dw - 1  (alpha = 2^-10 .. 1, 12 values)\n");
    printf("   %-10s %12s %12s %12s %12s\n", "alpha", "D(cos)", "tol", "D_tan2", "quad err");
    agg_init(&ac, "D normalisation, D(cos), |I - 1| - input-rounding bound", 1e-13);
    agg_init(&at, "D normalisation, D_tan2, |I - 1|", 1e-13);
    agg_init(&aq, "D normalisation, quadrature error estimate |I20 - I32|", 1e-14);
    for (i = 0; i < 12; i++) {
        double alpha = exp2(-10.0 + 10.0 * i / 11.0), bp[32];
        dn_ctx k;
        int n = peak_breaks(alpha, bp);
        double ic, it, it32, q, tol_cos;
        k.alpha = alpha;
        k.use_tan2 = 0;
        ic = gl_panels(dn_f, &k, bp, n, -1.0, &R20);
        k.use_tan2 = 1;
        it = gl_panels(dn_f, &k, bp, n, -1.0, &R20);
        it32 = gl_panels(dn_f, &k, bp, n, -1.0, &R32);
        q = fabs(it - it32);
        /* D(cos) is conditioned by its input: cos theta rounded to double
         * moves tan^2 by up to 2^-52 near the peak, and D by
         * 2 dtan^2 / (alpha^2 + tan^2) <= 2^-51 / alpha^2 relative (4.7e-10
         * at alpha = 2^-10); the oracle's own 1 - c^2 adds at most as much.
         * D_tan2 gets tan^2 directly, so only quadrature and rounding. */
        tol_cos = 1e-13 + 0x1p-50 / (alpha * alpha);
        printf("   %-10.4g %12.3g %12.3g %12.3g %12.3g\n", alpha, ic - 1.0, tol_cos, it - 1.0, q);
        agg_add(&ac, fabs(ic - 1.0) - (tol_cos - 1e-13), "alpha %.6g: I = %.17g, tol %.3g", alpha, ic, tol_cos);
        agg_add(&at, fabs(it - 1.0), "alpha %.6g: I = %.17g", alpha, it);
        agg_add(&aq, q, "alpha %.6g", alpha);
    }
    agg_done(&ac);
    printf("   max |I - 1|: D_tan2 %.3g (tol 1e-13), quadrature estimate %.3g (tol 1e-14)\n", agg_done(&at),
           agg_done(&aq));
}

/* ---- 1b. every D term: normalisation; GTR's limits ----------------------
 * Every D term of the table (a kernel whose name ends in _d), evaluated by
 * its table oracle with the inputs by name, in theta as above; gamma (GTR's
 * tail) over 0 .. 4, including the gamma = 1 limit; the anisotropic ones
 * (with a T.H input) in (theta, phi), h = (sin cos phi, sin sin phi, cos).
 * D(cos) is conditioned by its input as GGX's is (a relative 2^-53 in cos
 * theta moves these D by up to about 2^-50 / alpha^2, times gamma for GTR),
 * hence the same tolerance form. */
typedef struct {
    const facet_kernel *k;
    double alpha, gamma, ax, ay;
    const gl_rule *rphi;
} dm_ctx;

static int is_d_term(const facet_kernel *k)
{
    size_t n = strlen(k->name);
    return n > 2 && !strcmp(k->name + n - 2, "_d");
}

static int has_input(const facet_kernel *k, const char *name)
{
    return smp_name_index(k->inputs, k->n_inputs, name) >= 0;
}

/* the kernel's oracle at h = (toh, boh, ct), the widths of the context */
static double dm_d(const dm_ctx *c, double ct, double toh, double boh)
{
    double in[FACET_MAX_INPUTS];
    int i;
    for (i = 0; i < c->k->n_inputs; i++) {
        const char *n = c->k->inputs[i];
        in[i] = !strcmp(n, "noh") ? ct : !strcmp(n, "toh") ? toh : !strcmp(n, "boh") ? boh
              : !strcmp(n, "gamma") ? c->gamma : !strcmp(n, "alpha_x") ? c->ax
              : !strcmp(n, "alpha_y") ? c->ay : c->alpha;
    }
    return c->k->oracle(in);
}

typedef struct {
    const dm_ctx *c;
    double theta;
} dm_phi_ctx;

static double dm_phi_f(double phi, const void *ctx)
{
    const dm_phi_ctx *p = ctx;
    double st = sin(p->theta), ct = cos(p->theta);
    return dm_d(p->c, ct, st * cos(phi), st * sin(phi));
}

static double dm_f(double th, const void *c)
{
    const dm_ctx *k = c;
    double ct = cos(th), st = sin(th);
    if (has_input(k->k, "toh")) {
        dm_phi_ctx p;
        double s = 0.0;
        int j;
        p.c = k;
        p.theta = th;
        for (j = 0; j < 8; j++) /* 8 panels over [0, 2 pi] */
            s += gl_int(dm_phi_f, &p, j * M_PI / 4, (j + 1) * M_PI / 4, k->rphi);
        return s * ct * st;
    }
    return 2.0 * M_PI * dm_d(k, ct, 0.0, 0.0) * ct * st;
}

static void check_d_menu(void)
{
    static const double gammas[] = { 0.0, 0.25, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0 };
    static const double aniso[][2] = { { 0.05, 0.3 }, { 0.2, 0.8 }, { 1.0, 0.5 }, { 0.01, 0.02 },
                                       { 0.6, 0.6 } };
    agg an, ag2, ag1, aa;
    size_t ki;
    int i, g, nd = 0;
    printf("1b. D normalisation of every D term of the table:");
    for (ki = 0; ki < facet_kernel_count(); ki++)
        if (is_d_term(facet_kernel_at(ki)))
            printf(" %s", facet_kernel_at(ki)->name);
    printf(" (gamma 0 .. 4)\n");
    agg_init(&an, "D normalisation (isotropic D terms), |I - 1| - input-rounding bound", 1e-12);
    agg_init(&aa, "D normalisation (anisotropic D terms), |I - 1|", 1e-10);
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const facet_kernel *d = facet_kernel_at(ki);
        int ng = has_input(d, "gamma") ? (int)(sizeof gammas / sizeof gammas[0]) : 1;
        if (!is_d_term(d))
            continue;
        nd++;
        if (has_input(d, "toh")) {
            for (i = 0; i < (int)(sizeof aniso / sizeof aniso[0]); i++) {
                double bp[32], I;
                dm_ctx k;
                int n = peak_breaks(fmin(aniso[i][0], aniso[i][1]), bp);
                memset(&k, 0, sizeof k);
                k.k = d;
                k.ax = aniso[i][0];
                k.ay = aniso[i][1];
                k.rphi = &R32;
                I = gl_panels(dm_f, &k, bp, n, -1.0, &R32);
                printf("   %-14s ax %-6g ay %-6g I - 1 = %.3g\n", d->name, k.ax, k.ay, I - 1.0);
                agg_add(&aa, fabs(I - 1.0), "%s ax %g ay %g: I = %.17g", d->name, k.ax, k.ay, I);
            }
            continue;
        }
        for (g = 0; g < ng; g++)
            for (i = 0; i < 8; i++) {
                double alpha = exp2(-10.0 + 10.0 * i / 7.0), bp[32], I, tol;
                dm_ctx k;
                int n = peak_breaks(alpha, bp);
                memset(&k, 0, sizeof k);
                k.k = d;
                k.alpha = alpha;
                k.gamma = gammas[g];
                I = gl_panels(dm_f, &k, bp, n, -1.0, &R32);
                tol = 4.0 * 0x1p-50 / (alpha * alpha);
                if (i == 7 || (i % 3) == 0)
                    printf("   %-14s gamma %-5.3g alpha %-10.4g I - 1 = %.3g\n", d->name, ng > 1 ? gammas[g] : 0.0,
                           alpha, I - 1.0);
                agg_add(&an, fabs(I - 1.0) - tol, "%s alpha %.6g gamma %g: I = %.17g", d->name, alpha,
                        gammas[g], I);
            }
    }
    CHECK(nd > 0, "no D term (a kernel named *_d) in the table");
    agg_done(&an);
    agg_done(&aa);

    /* GTR at gamma = 2 is GGX; near gamma = 1 it meets its limit; at gamma =
     * 0 it is 1/pi; anisotropic GGX with ax = ay at a unit h is GGX */
    agg_init(&ag2, "gtr_d(gamma = 2) vs ggx_d, and ggx_aniso_d(ax = ay) vs ggx_d, relative", 1e-13);
    agg_init(&ag1, "gtr_d at gamma = 1 +- 2^-30 vs gamma = 1 (the limit), relative", 1e-8);
    for (i = 0; i <= 40; i++)
        for (g = 0; g <= 20; g++) {
            double n = i == 40 ? 1.0 : 1.0 - exp2(-0.6 * i), a = exp2(-10.0 + 0.5 * g);
            double st = sqrt((1.0 - n) * (1.0 + n));
            double ggx = facet_oracle_ggx_d(n, a), d1 = facet_oracle_gtr_d(n, a, 1.0);
            agg_add(&ag2, rel_err(facet_oracle_gtr_d(n, a, 2.0), ggx), "gtr2 noh %.17g alpha %g", n, a);
            agg_add(&ag2, rel_err(facet_oracle_ggx_aniso_d(n, st * 0.6, st * 0.8, a, a), ggx),
                    "aniso noh %.17g alpha %g", n, a);
            agg_add(&ag1, rel_err(facet_oracle_gtr_d(n, a, 1.0 + 0x1p-30), d1), "noh %.17g alpha %g +", n, a);
            agg_add(&ag1, rel_err(facet_oracle_gtr_d(n, a, 1.0 - 0x1p-30), d1), "noh %.17g alpha %g -", n, a);
            agg_add(&ag2, rel_err(facet_oracle_gtr_d(n, a, 0.0), 1.0 / M_PI), "gtr0 noh %.17g alpha %g", n, a);
        }
    printf("   gtr_d(2) = ggx_d, aniso(a, a) = ggx_d, gtr_d(0) = 1/pi: worst %.3g; gtr_d(1 +- 2^-30) vs gtr_d(1): %.3g\n",
           agg_done(&ag2), agg_done(&ag1));
}

/* ---- 2. Smith G1 closed form vs Lambda by quadrature ----------------------
 * Slopes (p, q) of the normal m = (-p, -q, 1)/|.|: tan^2 theta_m = p^2 + q^2,
 * and the projected normal density D(m) cos(theta_m) dw_m becomes, with
 * dw_m = cos^3 theta_m dp dq, P22(p, q) = D(m) cos^4(theta_m).
 * P2(q) = int P22(p, q) dp (the slope along the ray's azimuth); the slides
 * and the brief give alpha^2 / (2 (alpha^2 + q^2)^(3/2)).
 * Lambda(mu) = (1/mu) int_mu^inf (q - mu) P2(q) dq,  mu = cot theta.
 * Both integrals are done numerically, P2 from the oracle's D itself. */
typedef struct {
    double alpha, q;
} p22_ctx;

/* P22(p, q) dp with p = c tan w, c = sqrt(alpha^2 + q^2): analytic on w */
static double p22_f(double w, const void *ctx)
{
    const p22_ctx *k = ctx;
    double c = sqrt(k->alpha * k->alpha + k->q * k->q), cw = cos(w);
    double p = c * tan(w), t2 = p * p + k->q * k->q, cm = 1.0 / sqrt(1.0 + t2);
    return facet_oracle_ggx_d_tan2(t2, cm, k->alpha) * (cm * cm) * (cm * cm) * c / (cw * cw);
}

static double p2_num(double q, double alpha, const gl_rule *r)
{
    p22_ctx k;
    k.alpha = alpha;
    k.q = q;
    return 2.0 * gl_int(p22_f, &k, 0.0, M_PI / 2, r); /* P22 is even in p */
}

typedef struct {
    double alpha, mu;
    const gl_rule *inner;
} lam_ctx;

/* (q - mu) P2(q) dq with q = alpha cot w: analytic on (0, atan(alpha/mu)] */
static double lam_f(double w, const void *ctx)
{
    const lam_ctx *k = ctx;
    double sw = sin(w), q = k->alpha * cos(w) / sw;
    return (q - k->mu) * p2_num(q, k->alpha, k->inner) * k->alpha / (sw * sw);
}

static double lambda_num(double mu, double alpha, const gl_rule *outer, const gl_rule *inner)
{
    lam_ctx k;
    double w0 = atan2(alpha, mu);
    k.alpha = alpha;
    k.mu = mu;
    k.inner = inner;
    return (gl_int(lam_f, &k, 0.0, 0.5 * w0, outer) + gl_int(lam_f, &k, 0.5 * w0, w0, outer)) / mu;
}

static void check_smith_lambda(void)
{
    static const double alphas[] = {0.0009765625, 0.015625, 0.05, 0.25, 0.6, 1.0};
    static const double degs[] = {0.5, 5.0, 30.0, 60.0, 85.0, 89.5};
    static const double qs[] = {0.0, 1e-4, 1e-3, 0.03, 0.5, 1.0, 7.0, 300.0};
    agg ap, al, ag, aq;
    size_t i, j;
    printf("2. Smith: P2 and Lambda by quadrature vs the closed forms\n");
    /* the quadrature error (printed) is ~1e-15; 1e-13 leaves room for the
     * rounding of mu and of the nested sums */
    agg_init(&ap, "P2 by quadrature vs alpha^2/(2(alpha^2+q^2)^1.5), rel", 1e-13);
    agg_init(&al, "smith_lambda vs Lambda by quadrature, rel", 1e-13);
    agg_init(&ag, "smith_g1 vs 1/(1 + Lambda by quadrature), rel", 1e-14);
    agg_init(&aq, "Lambda quadrature error estimate (n=20 vs 32), rel", 1e-14);
    for (i = 0; i < sizeof alphas / sizeof alphas[0]; i++) {
        double a = alphas[i];
        for (j = 0; j < sizeof qs / sizeof qs[0]; j++) {
            double q = qs[j], want = a * a / (2.0 * pow(a * a + q * q, 1.5));
            double got = p2_num(q, a, &R20), e = rel_err(got, want);
            agg_add(&ap, e, "q %g, alpha %g: %.17g vs %.17g", q, a, got, want);
        }
        for (j = 0; j < sizeof degs / sizeof degs[0]; j++) {
            double c = cos(degs[j] * M_PI / 180.0);
            double mu = c / sqrt((1.0 - c) * (1.0 + c)); /* cot theta of this very c */
            double ln = lambda_num(mu, a, &R20, &R20);
            double ln32 = lambda_num(mu, a, &R32, &R32);
            double lo = facet_oracle_smith_lambda(c, a), go = facet_oracle_smith_g1(c, a);
            double el = rel_err(lo, ln), eg = rel_err(go, 1.0 / (1.0 + ln)), q = rel_err(ln32, ln);
            agg_add(&al, el, "theta %g deg, alpha %g: oracle %.17g, integral %.17g", degs[j], a, lo, ln);
            agg_add(&ag, eg, "theta %g deg, alpha %g: oracle %.17g, 1/(1+Lambda) %.17g", degs[j], a, go,
                    1.0 / (1.0 + ln));
            agg_add(&aq, q, "theta %g deg, alpha %g", degs[j], a);
        }
    }
    printf("   P2 vs alpha^2/(2(alpha^2+q^2)^1.5): max rel %.3g (tol 1e-13)\n", agg_done(&ap));
    printf("   Lambda oracle vs integral:          max rel %.3g (tol 1e-13), quadrature %.3g (tol 1e-14)\n",
           agg_done(&al), agg_done(&aq));
    printf("   G1 oracle vs 1/(1+Lambda integral): max rel %.3g (tol 1e-14)\n", agg_done(&ag));
}

/* ---- 2b. Smith G1 for GTR: Dimov's closed forms vs the exact G1 -----------
 * The closed forms at gamma = 0 .. 4 (as rewritten in src/oracle/oracle.c) against
 * G1 = N.V / int max(0, v.m) D(m) dw by quadrature (the exact reference);
 * gamma = 2 against GGX's smith_g1; the interpolation equal to the closed
 * forms at the orders, within [0, 1], and its model error against the exact
 * G1 within what facet.h states (max 0.338 absolute at alpha = 2^-10). */
static void check_g1_gtr(void)
{
    static const double ns[] = { 0.001, 0.02, 0.1, 0.3, 0.5, 0.8, 0.95, 1.0 };
    static const double as[] = { 0.0009765625, 0.01, 0.1, 0.3, 0.7, 1.0 };
    agg ac, ai, am;
    double worst = 0.0, sum = 0.0;
    long cnt = 0;
    int i, j, g;
    printf("2b. GTR G1: closed forms (gamma 0..4) vs quadrature; the interpolation's model error\n");
    agg_init(&ac, "GTR G1 closed form vs exact by quadrature, relative", 1e-9);
    agg_init(&ai, "GTR G1 interpolation at the orders vs closed form; G1_gtr(gamma = 2) vs smith_g1", 1e-15);
    agg_init(&am, "GTR G1 interpolation vs exact: |error| <= 0.34 (facet.h)", 0.34);
    for (i = 0; i < 8; i++)
        for (j = 0; j < 6; j++) {
            for (g = 0; g <= 4; g++) {
                double c = facet_oracle_smith_g1_gtr_order(ns[i], as[j], g);
                double x = facet_oracle_smith_g1_gtr_exact(ns[i], as[j], g);
                agg_add(&ac, rel_err(c, x), "n %g alpha %g gamma %d: %.17g vs %.17g", ns[i], as[j], g, c, x);
                agg_add(&ai, rel_err(facet_oracle_smith_g1_gtr(ns[i], as[j], g), c), "n %g alpha %g gamma %d",
                        ns[i], as[j], g);
            }
            agg_add(&ai, rel_err(facet_oracle_smith_g1_gtr(ns[i], as[j], 2.0), facet_oracle_smith_g1(ns[i], as[j])),
                    "ggx n %g alpha %g", ns[i], as[j]);
            for (g = 1; g <= (quick ? 7 : 39); g += quick ? 2 : 1) {
                double G = g * 0.1, v = facet_oracle_smith_g1_gtr(ns[i], as[j], G);
                double e = fabs(v - facet_oracle_smith_g1_gtr_exact(ns[i], as[j], G));
                agg_add(&am, e, "n %g alpha %g gamma %g", ns[i], as[j], G);
                agg_add(&am, v >= 0.0 && v <= 1.0 ? 0.0 : 1.0, "range n %g alpha %g gamma %g", ns[i], as[j], G);
                worst = fmax(worst, e);
                sum += e;
                cnt++;
            }
        }
    printf("   closed forms vs quadrature %.3g; at the orders %.3g; model error max %.4g, mean %.4g\n",
           agg_done(&ac), agg_done(&ai), agg_done(&am), sum / cnt);
    (void)worst;
}

/* ---- 3. Smith constraint: G1(v) int D(m) <v.m>+ dw_m = v.n ----------------
 * The projected area of the visible microfacets equals the macro area:
 * int D(m) <v.m>+ dw_m = cos theta_v (1 + Lambda(v)).  2D quadrature: phi in
 * [0, phi_c(theta)] (the front-facing arc, times 2 by symmetry), theta on the
 * peak panels plus panels graded towards theta* = pi/2 - theta_v, where the
 * arc starts to shrink and the phi integral has a (theta - theta*)^(3/2) kink
 * (the panel after theta* uses the u^2 map). */
typedef struct {
    double alpha, cv, sv;
    const gl_rule *rphi;
} sc_ctx;

static double sc_f(double th, const void *ctx)
{
    const sc_ctx *k = ctx;
    double ct = cos(th), st = sin(th), tt = st / ct, a = k->cv * ct, b = k->sv * st;
    double phic = a >= b ? M_PI : acos(-a / b), h = 0.5 * phic, s = 0.0;
    int i;
    for (i = 0; i < k->rphi->n; i++)
        s += k->rphi->w[i] * (a + b * cos(h + h * k->rphi->x[i])); /* v.m */
    return facet_oracle_ggx_d_tan2(tt * tt, ct, k->alpha) * 2.0 * h * s * st;
}

static double smith_area(double deg, double alpha, const gl_rule *r, double *cv_out)
{
    sc_ctx k;
    double bp[64], kink = -1.0;
    int n, j;
    k.alpha = alpha;
    k.cv = cos(deg * M_PI / 180.0);
    k.sv = sin(deg * M_PI / 180.0);
    k.rphi = r;
    n = peak_breaks(alpha, bp);
    if (deg > 0.0) {
        double ts = M_PI / 2 - deg * M_PI / 180.0, h = M_PI / 2 - ts;
        kink = ts;
        bp[n++] = ts;
        for (j = 0; j <= 16; j++)
            bp[n++] = ts + h * exp2(-j);
    }
    *cv_out = k.cv;
    return gl_panels(sc_f, &k, bp, n, kink, r);
}

static void check_smith_constraint(void)
{
    static const double alphas[] = {0.0009765625, 0.03125, 0.2, 0.6, 1.0};
    static const double degs[] = {0.0, 30.0, 60.0, 80.0, 89.0, 89.9};
    agg ae, aq;
    size_t i, j;
    printf("3. Smith constraint  G1(v) int D <v.m>+ dw / cos theta_v - 1\n");
    /* quadrature error (printed) ~1e-15 at worst; tolerance 1e-12 */
    agg_init(&ae, "Smith constraint G1(v) int D <v.m>+ dw vs cos theta_v, rel", 1e-12);
    agg_init(&aq, "Smith constraint quadrature error estimate (n=20 vs 32), rel", 1e-13);
    for (i = 0; i < sizeof alphas / sizeof alphas[0]; i++)
        for (j = 0; j < sizeof degs / sizeof degs[0]; j++) {
            double cv, area = smith_area(degs[j], alphas[i], &R20, &cv);
            double area32 = smith_area(degs[j], alphas[i], &R32, &cv);
            double g1 = facet_oracle_smith_g1(cv, alphas[i]);
            double e = rel_err(g1 * area, cv), q = rel_err(area32, area);
            agg_add(&ae, e, "theta_v %g deg, alpha %g: G1 %.17g * area %.17g = %.17g vs cos %.17g", degs[j],
                    alphas[i], g1, area, g1 * area, cv);
            agg_add(&aq, q, "theta_v %g deg, alpha %g", degs[j], alphas[i]);
        }
    printf("   max rel residual %.3g (tol 1e-12), quadrature %.3g (tol 1e-13); %ld (theta_v, alpha) pairs\n",
           agg_done(&ae), agg_done(&aq), ae.n);
}

/* ---- 4. the smooth diffuse term: k = 21 / (20 pi) ------------------------
 * f = k (1 - (1 - N.L)^5)(1 - (1 - N.V)^5) has directional albedo
 * int f N.L dw_L = (1 - (1 - N.V)^5), i.e. exactly 1 at N.V = 1:
 * 2 pi k int_0^1 (1 - (1-mu)^5) mu dmu = 2 pi k (1/2 - 1/42) = 1.
 * The oracle's diffuse_hammon is single + albedo multi with
 * single = lerp(smooth, rough, alpha)/pi and multi = 0.1159 alpha: at fixed
 * albedo it is affine in alpha, so its smooth part is isolated exactly by
 * extrapolating to alpha = 0 from alpha_min and 2 alpha_min. */
static double smooth_part(double nl, double nv, double lv)
{
    double a1 = FACET_ALPHA_MIN;
    return 2.0 * facet_oracle_diffuse_hammon(nl, nv, lv, a1, 1.0) -
           facet_oracle_diffuse_hammon(nl, nv, lv, 2.0 * a1, 1.0);
}

static void check_smooth_diffuse(void)
{
    static const double nvs[] = {1.0, 0.5, 0.1};
    double k = 21.0 / (20.0 * M_PI), worst = 0.0, worst_pt = 0.0;
    size_t j;
    int i, ip;
    printf("4. smooth diffuse term: directional albedo with k = 21/(20 pi)\n");
    for (j = 0; j < sizeof nvs / sizeof nvs[0]; j++) {
        double nv = nvs[j], sv = sqrt((1.0 - nv) * (1.0 + nv)), alb = 0.0, alb_min = 0.0;
        double want = 1.0 - pow(1.0 - nv, 5.0);
        /* mu = N.L by Gauss-Legendre (the integrand is a degree-6 polynomial
         * in mu: exact with 8 nodes); phi by the midpoint rule over 8
         * azimuths (the smooth term does not depend on phi; the rough part,
         * which does, has to extrapolate away) */
        for (i = 0; i < R8.n; i++) {
            double mu = 0.5 + 0.5 * R8.x[i], sl = sqrt((1.0 - mu) * (1.0 + mu));
            for (ip = 0; ip < 8; ip++) {
                double phi = 2.0 * M_PI * (ip + 0.5) / 8.0, lv = mu * nv + sl * sv * cos(phi);
                double sm = smooth_part(mu, nv, lv), w = 0.5 * R8.w[i] * (2.0 * M_PI / 8.0) * mu;
                double pt = k * (1.0 - pow(1.0 - mu, 5.0)) * want;
                alb += w * sm;
                alb_min += w * facet_oracle_diffuse_hammon(mu, nv, lv, FACET_ALPHA_MIN, 1.0);
                worst_pt = fmax(worst_pt, rel_err(sm, pt));
            }
        }
        printf("   N.V = %-4g albedo(smooth) - (1-(1-N.V)^5) = %10.3g   raw diffuse at alpha_min: %.9f\n",
               nv, alb - want, alb_min);
        CHECK(fabs(alb - want) <= 1e-13, "smooth diffuse albedo at N.V = %g: %.17g, want %.17g", nv,
              alb, want);
        /* at alpha_min the rough and multi parts weigh 2^-10: the whole
         * diffuse stays within alpha_min (1.05 + 0.1159 pi) of the smooth
         * albedo (rough <= 1.05, smooth <= 1.05) */
        CHECK(fabs(alb_min - want) <= FACET_ALPHA_MIN * (1.05 + 0.1159 * M_PI),
              "diffuse albedo at alpha_min, N.V = %g: %.9f vs smooth %.9f", nv, alb_min, want);
        worst = fmax(worst, fabs(alb - want));
    }
    CHECK(worst_pt <= 1e-13, "smooth part of diffuse_hammon vs 21/(20 pi)(..)(..): rel %.3g", worst_pt);
    printf("   max |albedo residual| %.3g (tol 1e-13); pointwise smooth part vs k(..)(..): %.3g\n", worst,
           worst_pt);
}

/* ---- 4b. Fresnel: the exact dielectric reference and Schlick's error ------
 * The oracle's fresnel_cook_torrance follows Snell's law and the Fresnel
 * equations (rs, rp); Cook and Torrance's closed form in g = sqrt(eta^2 - 1
 * + c^2), evaluated plainly, must give the same where it does not cancel
 * (f0 in [0.01, 0.98]).  Named points, and the model error of Schlick
 * (fresnel_schlick) against it over the domain: the numbers facet.h states. */
#define MODEL_MAX2 0.9988
#define MODEL_MEAN2 0.1054
static double ct_plain(double f0, double c)
{
    double s = sqrt(f0), eta = (1.0 + s) / (1.0 - s), g = sqrt(eta * eta - 1.0 + c * c);
    double a = (g - c) / (g + c), b = ((g + c) * c - 1.0) / ((g - c) * c + 1.0);
    return 0.5 * a * a * (1.0 + b * b);
}

/* model error of an approximation against the exact Fresnel over a grid of
 * f0 in [lo, hi] (log-spaced) and V.H in [0, 1] (uniform, 2001 points) */
static void fresnel_model_error(double lo, double hi, double *mx, double *mean, double *at_f0,
                                double *at_c)
{
    int i, j, nf = 401, nc = 2001;
    double sum = 0.0;
    *mx = 0.0;
    for (i = 0; i < nf; i++) {
        double f0 = lo * pow(hi / lo, (double)i / (nf - 1));
        for (j = 0; j < nc; j++) {
            double c = (double)j / (nc - 1);
            double ex = facet_oracle_fresnel_cook_torrance(f0, c);
            double e = fabs(facet_oracle_fresnel_schlick(f0, c) - ex) / ex;
            sum += e;
            if (e > *mx) {
                *mx = e;
                *at_f0 = f0;
                *at_c = c;
            }
        }
    }
    *mean = sum / ((double)nf * nc);
}

static void check_fresnel(void)
{
    static const double f0s[] = {1e-30, 1e-9, 0.02, 0.04, 0.5, 0.9, 1.0 - 0x1p-24};
    double worst = 0.0, mx, mean, af, ac;
    int i, j;
    size_t k;
    printf("4b. Fresnel: exact dielectric (Snell + Fresnel equations) vs Cook-Torrance's g form\n");
    for (i = 0; i <= 100; i++)
        for (j = 0; j <= 100; j++) {
            double f0 = 0.01 + 0.97 * i / 100.0, c = 0.01 + 0.99 * j / 100.0;
            worst = fmax(worst, rel_err(facet_oracle_fresnel_cook_torrance(f0, c), ct_plain(f0, c)));
        }
    printf("   max rel difference %.3g (tol 1e-12) over f0 in [0.01, 0.98], V.H in [0.01, 1]\n", worst);
    CHECK(worst <= 1e-12, "fresnel_cook_torrance oracle vs Cook-Torrance's form: %.3g", worst);
    for (k = 0; k < sizeof f0s / sizeof f0s[0]; k++) {
        double f1 = facet_oracle_fresnel_cook_torrance(f0s[k], 1.0);
        double fz = facet_oracle_fresnel_cook_torrance(f0s[k], 0.0);
        CHECK(rel_err(f1, f0s[k]) <= 1e-14, "F_exact(%.17g, 1) = %.17g, not f0", f0s[k], f1);
        CHECK(rel_err(fz, 1.0) <= 1e-14, "F_exact(%.17g, 0) = %.17g, not 1", f0s[k], fz);
        /* a dielectric's unpolarised F never exceeds 1 */
        for (j = 0; j <= 1000; j++) {
            double f = facet_oracle_fresnel_cook_torrance(f0s[k], j / 1000.0);
            CHECK(f >= 0.0 && f <= 1.0 + 1e-15, "F_exact(%g, %g) = %.17g outside [0, 1]", f0s[k], j / 1000.0, f);
        }
    }
    CHECK(facet_oracle_fresnel_cook_torrance(0.0, 0.5) == 0.0 && facet_oracle_fresnel_cook_torrance(0.0, 0.0) == 0.0,
          "F_exact(0, c) = 0 (eta = 1)");
    CHECK(facet_oracle_fresnel_cook_torrance(1.0, 0.5) == 1.0 && facet_oracle_fresnel_cook_torrance(1.0, 0.0) == 1.0,
          "F_exact(1, c) = 1 (eta infinite)");
    /* fresnel_schlick_f90 at f90 = 1 is Schlick */
    worst = 0.0;
    for (i = 0; i <= 200; i++)
        for (j = 0; j <= 200; j++) {
            double f0 = i / 200.0, c = j / 200.0;
            worst = fmax(worst, rel_err(facet_oracle_fresnel_schlick_f90(f0, 1.0, c),
                                        facet_oracle_fresnel_schlick(f0, c)));
        }
    printf("   schlick_f90(f0, 1, c) vs schlick(f0, c): max rel %.3g (tol 1e-14)\n", worst);
    CHECK(worst <= 1e-14, "fresnel_schlick_f90 at f90 = 1 differs from fresnel_schlick: %.3g", worst);
    /* model error of Schlick (facet.h, fresnel_cook_torrance's contract) */
    fresnel_model_error(0.02, 0.1, &mx, &mean, &af, &ac);
    printf("   model error of fresnel_schlick vs exact, f0 in [0.02, 0.1] (dielectrics, eta 1.33 .. 1.92):\n"
           "     max rel %.4f at (f0 %.4g, V.H %.4g), mean rel %.5f\n", mx, af, ac, mean);
    CHECK(fabs(mx - 0.2357) < 0.0005 && fabs(mean - 0.0943) < 0.0005,
          "Schlick model error on dielectrics: max %.4f, mean %.5f (facet.h: 0.2357, 0.0943)", mx, mean);
    fresnel_model_error(0.02, 0.999, &mx, &mean, &af, &ac);
    printf("   f0 in [0.02, 0.999]: max rel %.4f at (f0 %.4g, V.H %.4g), mean rel %.5f\n", mx, af, ac, mean);
    CHECK(fabs(mx - MODEL_MAX2) < 0.0005 && fabs(mean - MODEL_MEAN2) < 0.0005,
          "Schlick model error over f0 in [0.02, 0.999]: max %.4f, mean %.5f (facet.h: %g, %g)", mx, mean,
          MODEL_MAX2, MODEL_MEAN2);
}

/* ---- 4c. white furnace: directional albedo of every diffuse model ---------
 * a(V) = int f(L, V) N.L dw_L at albedo = 1 (Lambert: exactly 1), by
 * Gauss-Legendre in mu = N.L (panels split at mu = N.V, where Oren-Nayar's
 * max/min switch) and the midpoint rule in the azimuth (a multiple of 4
 * points: Oren-Nayar's max(0, cos phi) kinks at +-pi/2 fall on cell
 * edges).  Closed forms where they exist:
 *   Burley at N.V = 1 (L.H^2 = (1 + mu)/2): 1 - 1/42 + 5 sqrt(alpha) / 84
 *     (int (1-mu)^5 mu = 1/42, int (1-mu)^5 mu^2 = 1/168);
 *   Oren-Nayar at N.V = 1 (its max(0, ..) term vanishes): A(alpha);
 *   the smooth part of Hammon's diffuse (affine in alpha: extrapolated to
 *   alpha = 0): 1 - (1 - N.V)^5 (section 4's); of the hybrid:
 *   (1 - (1 - N.V)^5 / 2)(1 - 1/42); of the cheap one: 1.
 * The models are the table's diffuse kernels (below); those closed forms
 * are their golden values, kept per model in furnace_golden. */
/* A diffuse model: a kernel of the table whose inputs are the geometry
 * (N.L, N.V, and L.V or L.H), alpha and albedo only, and that has an albedo */
static int is_diffuse_model(const facet_kernel *k)
{
    static const char *const ok[] = { "nol", "nov", "lov", "loh", "alpha", "albedo" };
    int i, j, fine = 1;
    for (i = 0; i < k->n_inputs; i++) {
        int known = 0;
        for (j = 0; j < (int)(sizeof ok / sizeof ok[0]); j++)
            known |= !strcmp(k->inputs[i], ok[j]);
        fine &= known;
    }
    return fine && has_input(k, "albedo");
}

/* the model's oracle at (N.L, N.V, L.V), its inputs by name (L.H from L.V) */
static double diffuse_at(const facet_kernel *k, double nl, double nv, double lv, double a, double rho)
{
    double in[FACET_MAX_INPUTS];
    int i;
    for (i = 0; i < k->n_inputs; i++) {
        const char *n = k->inputs[i];
        in[i] = !strcmp(n, "nol") ? nl : !strcmp(n, "nov") ? nv : !strcmp(n, "lov") ? lv
              : !strcmp(n, "loh") ? sqrt(0.5 * (1.0 + lv)) : !strcmp(n, "alpha") ? a : rho;
    }
    return k->oracle(in);
}

static double dir_albedo(const facet_kernel *f, double nv, double a, int nmu, int nphi)
{
    double sv = sqrt((1.0 - nv) * (1.0 + nv)), sum = 0.0, bp[3];
    int p, i, ip;
    gl_rule r, rp;
    gl_make(&r, nmu);
    gl_make(&rp, nphi);
    /* over theta_l (mu = cos, the integrand smooth in it), split at theta_v */
    bp[0] = 0.0;
    bp[1] = acos(nv);
    bp[2] = 0.5 * M_PI;
    for (p = 0; p < 2; p++) {
        double lo = bp[p], hi = bp[p + 1];
        if (hi <= lo)
            continue;
        for (i = 0; i < r.n; i++) {
            double th = lo + (hi - lo) * 0.5 * (1.0 + r.x[i]), mu = cos(th), sl = sin(th), row = 0.0;
            /* the azimuth: Gauss-Legendre on [0, pi/2] and [pi/2, pi] (the
             * integrand is even in phi; Oren-Nayar's max(0, cos phi) kinks
             * at pi/2) */
            for (ip = 0; ip < 2 * rp.n; ip++) {
                double phi = 0.25 * M_PI * (1.0 + rp.x[ip % rp.n]) + (ip < rp.n ? 0.0 : 0.5 * M_PI);
                row += 0.25 * M_PI * rp.w[ip % rp.n]
                       * diffuse_at(f, fmax(mu, FACET_COS_MIN), nv, fmin(fmax(mu * nv + sl * sv * cos(phi), -1.0), 1.0), a, 1.0);
            }
            sum += 0.5 * (hi - lo) * r.w[i] * mu * sl * 2.0 * row;
        }
    }
    return sum;
}

/* The furnace's golden values per diffuse model: the closed form of its
 * directional albedo where it has one (at N.V = 1 only, or at every N.V),
 * and that of its smooth part (models affine in alpha: extrapolated to
 * alpha = 0 from alpha_min and 2 alpha_min).  Every diffuse model of the
 * table has an entry (checked). */
static double al_lambert(double nv, double a) { (void)nv; (void)a; return 1.0; }
static double al_burley_nv1(double nv, double a)
{
    return nv == 1.0 ? 1.0 - 1.0 / 42.0 + 5.0 * sqrt(a) / 84.0 : NAN;
}
static double al_oren_nayar_nv1(double nv, double a)
{
    double s2 = 0.25 * a * a;
    return nv == 1.0 ? 1.0 - 0.5 * s2 / (s2 + 0.33) : NAN;
}
static double sm_hammon(double nv) { return 1.0 - pow(1.0 - nv, 5.0); }
static double sm_hybrid(double nv) { return (1.0 - 0.5 * pow(1.0 - nv, 5.0)) * (1.0 - 1.0 / 42.0); }
static double sm_cheap(double nv) { (void)nv; return 1.0; }

static const struct {
    const char *name;
    double (*albedo)(double nv, double alpha); /* NaN where it has none */
    double tol;
    double (*smooth)(double nv);
} furnace_golden[] = {
    { "lambert", al_lambert, 1e-12, NULL },
    { "diffuse_hammon", NULL, 0, sm_hammon },
    { "diffuse_burley", al_burley_nv1, 1e-10, NULL },
    { "diffuse_oren_nayar", al_oren_nayar_nv1, 1e-10, NULL },
    { "diffuse_hammon_hybrid", NULL, 0, sm_hybrid },
    { "diffuse_hammon_cheap", NULL, 0, sm_cheap },
};
#define N_FURNACE_GOLDEN ((int)(sizeof furnace_golden / sizeof furnace_golden[0]))

static int furnace_entry(const char *name)
{
    int g;
    for (g = 0; g < N_FURNACE_GOLDEN; g++)
        if (!strcmp(furnace_golden[g].name, name))
            return g;
    return -1;
}

static void check_diffuse_furnace(void)
{
    static const double nvs[] = {1.0, 0.5, 0.1, 0.01};
    static const double as[] = {FACET_ALPHA_MIN, 0.25, 0.5, 1.0};
    double worst_q = 0.0;
    size_t i, j, l;
    int nphi = 24, g;
    printf("4c. white furnace: directional albedo (albedo = 1) per diffuse model; rows N.V, columns alpha\n");
    for (g = 0; g < N_FURNACE_GOLDEN; g++) {
        const facet_kernel *k = facet_kernel_find(furnace_golden[g].name);
        CHECK(k && is_diffuse_model(k), "furnace golden values for '%s', which is no diffuse model of the table",
              furnace_golden[g].name);
    }
    for (i = 0; i < facet_kernel_count(); i++) {
        const facet_kernel *m = facet_kernel_at(i);
        double lo = INFINITY, hi = -INFINITY;
        if (!is_diffuse_model(m))
            continue;
        g = furnace_entry(m->name);
        CHECK(g >= 0, "diffuse model %s has no furnace golden values (tests/oracle/test_oracle.c, furnace_golden)",
              m->name);
        printf("   %-22s", m->name);
        for (j = 0; j < sizeof nvs / sizeof nvs[0]; j++) {
            printf("%s N.V %-4g:", j ? "\n                         " : "", nvs[j]);
            for (l = 0; l < sizeof as / sizeof as[0]; l++) {
                double v = dir_albedo(m, nvs[j], as[l], 20, nphi);
                double v2 = dir_albedo(m, nvs[j], as[l], 32, 32);
                double want = g >= 0 && furnace_golden[g].albedo ? furnace_golden[g].albedo(nvs[j], as[l]) : NAN;
                worst_q = fmax(worst_q, fabs(v - v2));
                printf(" %.4f", v2);
                lo = fmin(lo, v2);
                hi = fmax(hi, v2);
                if (want == want)
                    CHECK(fabs(v2 - want) <= furnace_golden[g].tol, "%s albedo at N.V = %g, alpha %g: %.15f vs %.15f",
                          m->name, nvs[j], as[l], v2, want);
            }
        }
        printf("\n   %-22s range over these: [%.4f, %.4f]\n", "", lo, hi);
        /* the smooth part, extrapolated to alpha = 0 */
        for (j = 0; g >= 0 && furnace_golden[g].smooth && j < sizeof nvs / sizeof nvs[0]; j++) {
            double a1 = FACET_ALPHA_MIN;
            double sm = 2.0 * dir_albedo(m, nvs[j], a1, 32, nphi) - dir_albedo(m, nvs[j], 2.0 * a1, 32, nphi);
            double want = furnace_golden[g].smooth(nvs[j]);
            CHECK(fabs(sm - want) <= 1e-9, "%s smooth albedo at N.V = %g: %.15f vs %.15f", m->name, nvs[j], sm, want);
        }
    }
    printf("   quadrature: 20 vs 32 nodes per panel: max difference %.3g (tol 1e-5)\n", worst_q);
    CHECK(worst_q <= 1e-5, "furnace quadrature not converged: %.3g", worst_q);
}

/* ---- random geometry in double -------------------------------------------- */

/* a cosine in [2^-20, 1]: uniform, log-uniform (grazing), or close to 1 */
static double rnd_cos(smp_rng *r)
{
    double c;
    switch (smp_next(r) % 4) {
    case 0: c = smp_log2u(r, -20, 0); break;
    case 1: c = 1.0 - smp_log2u(r, -40, -1); break;
    default: c = smp_u01(r); break;
    }
    return fmax(c, FACET_COS_MIN);
}

/* an (N.L, N.V, L.V) triple of real unit vectors (mirror-ish azimuths often),
 * or one time in 8 an arbitrary L.V (mostly inconsistent) */
static void rnd_triple(smp_rng *r, double *nl, double *nv, double *lv)
{
    double phi, sl, sv;
    *nl = rnd_cos(r);
    *nv = (smp_next(r) & 3) == 0 ? *nl * (1.0 + (smp_u01(r) - 0.5) * smp_log2u(r, -40, -2)) : rnd_cos(r);
    *nv = fmin(fmax(*nv, FACET_COS_MIN), 1.0);
    phi = (smp_next(r) & 1) ? 2.0 * M_PI * smp_u01(r) : M_PI + (smp_u01(r) - 0.5) * smp_log2u(r, -40, 0);
    sl = sqrt((1.0 - *nl) * (1.0 + *nl));
    sv = sqrt((1.0 - *nv) * (1.0 + *nv));
    *lv = fmin(fmax(*nl * *nv + sl * sv * cos(phi), -1.0), 1.0);
    if ((smp_next(r) & 7) == 0)
        *lv = 2.0 * smp_u01(r) - 1.0;
}

/* ---- 5. reciprocity: every (nol, nov, ...) term is symmetric in L and V ---
 * The terms: every kernel of the table with both an N.L and an N.V input;
 * each seeded by its name (smp_name_seed), so that its samples stay when
 * kernels are added. */
static void check_symmetry(void)
{
    long n = quick ? 4000 : 40000, j;
    size_t ki;
    int n_terms = 0;
    printf("5. symmetry in L and V (swap N.L and N.V), %ld samples per kernel\n", n);
    printf("   %-22s %12s %14s %12s %12s\n", "kernel", "oracle max", "f32 bit-equal", "f32 max", "f32 bound");
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const facet_kernel *k = facet_kernel_at(ki);
        double worst_o = 0.0, worst_f = 0.0, bound;
        long same = 0;
        int il = smp_name_index(k->inputs, k->n_inputs, "nol"), iv = smp_name_index(k->inputs, k->n_inputs, "nov");
        smp_rng rng;
        if (il < 0 || iv < 0)
            continue; /* not a term of N.L and N.V */
        n_terms++;
        bound = 2.0 * k->err_f32; /* each side within err of the (symmetric) oracle */
        rng.s = 0x5e11 ^ smp_name_seed(k->name);
        for (j = 0; j < n; j++) {
            double din[FACET_MAX_INPUTS], dsw[FACET_MAX_INPUTS], nl, nv, lv, a, b;
            float fin[FACET_MAX_INPUTS], fsw[FACET_MAX_INPUTS], fa, fb;
            int i;
            /* oracle, double inputs */
            rnd_triple(&rng, &nl, &nv, &lv);
            for (i = 0; i < k->n_inputs; i++) {
                const char *nm = k->inputs[i];
                din[i] = !strcmp(nm, "nol") ? nl : !strcmp(nm, "nov") ? nv : !strcmp(nm, "lov") ? lv
                       : !strcmp(nm, "alpha") ? smp_log2u(&rng, -10, 0) : smp_u01(&rng);
            }
            memcpy(dsw, din, sizeof din);
            dsw[il] = din[iv];
            dsw[iv] = din[il];
            a = k->oracle(din);
            b = k->oracle(dsw);
            worst_o = fmax(worst_o, rel_err(b, a));
            /* f32 kernel, the accuracy test's sampler */
            smp_inputs(&rng, k, fin);
            memcpy(fsw, fin, sizeof fin);
            fsw[il] = fin[iv];
            fsw[iv] = fin[il];
            fa = k->f32(fin);
            fb = k->f32(fsw);
            if (fa == fb)
                same++;
            else {
                double o;
                for (i = 0; i < k->n_inputs; i++)
                    din[i] = fin[i];
                o = k->oracle(din);
                worst_f = fmax(worst_f, fabs((double)fa - fb) / fmax(fabs(o), 0x1p-100));
            }
        }
        printf("   %-22s %12.3g %8ld/%-5ld %12.3g %12.3g\n", k->name, worst_o, same, n, worst_f, bound);
        /* the oracle evaluates the geometry in double-double and rounds once;
         * a few roundings of commuted products remain: 1e-15 (~4.5 ulp) */
        CHECK(worst_o <= 1e-15, "oracle %s not symmetric in N.L, N.V: rel %.3g", k->name, worst_o);
        CHECK(worst_f <= bound, "f32 %s: |f(l,v) - f(v,l)| %.3g > 2 err bound %.3g", k->name, worst_f, bound);
    }
    CHECK(n_terms > 0, "no kernel of N.L and N.V in the table");
}

/* ---- 11. named points: the oracle at every golden value -------------------
 * tests/lib/golden.h: per kernel, points where the contract's formula is
 * written out in closed form; every kernel of the table has one. */
static void check_named_points(void)
{
    agg ap;
    size_t j, count;
    const golden_point *gt = golden_table(&count);
    golden_covers();
    agg_init(&ap, "oracle at the named points of tests/lib/golden.h, relative (absolute at 0)", GOLDEN_ORACLE_TOL);
    for (j = 0; j < count; j++) {
        const golden_point *g = &gt[j];
        const facet_kernel *k = facet_kernel_find(g->kernel);
        double got;
        if (!k)
            continue;
        got = k->oracle(g->in);
        agg_add(&ap, g->want != 0 ? fabs(got - g->want) / fabs(g->want) : fabs(got), "%s point %d: %.17g vs %.17g",
                g->kernel, (int)j, got, g->want);
    }
    printf("11. named points (tests/lib/golden.h): %d points, every kernel of the table; max rel %.3g (tol %.0e)\n",
           (int)count, agg_done(&ap), GOLDEN_ORACLE_TOL);
}

/* ---- 6. height correlation can only increase G2 ---------------------------
 * 1/(1 + Ll + Lv) >= 1/((1 + Ll)(1 + Lv)); the ratio is exactly
 * 1 + Ll Lv / (1 + Ll + Lv), which is checked too. */
static void check_correlated_ge(void)
{
    static const double cs[] = {9.5367431640625e-07, 1e-5, 1e-3, 0.01, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5,
                                0.6, 0.7, 0.8, 0.9, 0.95, 0.99, 0.999, 0.999999, 1.0};
    size_t i, j;
    int ia;
    agg ag, ar;
    const size_t nc = sizeof cs / sizeof cs[0];
    /* when Ll Lv is below an ulp the two round either way: 2 ulp */
    agg_init(&ag, "G2 correlated >= uncorrelated: (uncorr - corr)/corr", 2.0 * EPS);
    agg_init(&ar, "G2corr/G2uncorr vs 1 + Ll Lv/(1+Ll+Lv), rel", 1e-14);
    for (ia = 0; ia < 12; ia++) {
        double a = exp2(-10.0 + 10.0 * ia / 11.0);
        for (i = 0; i < nc; i++)
            for (j = 0; j < nc; j++) {
                double c = facet_oracle_smith_g2(cs[i], cs[j], a);
                double u = facet_oracle_smith_g2_uncorrelated(cs[i], cs[j], a);
                double ll = facet_oracle_smith_lambda(cs[i], a), lv = facet_oracle_smith_lambda(cs[j], a);
                double ratio = 1.0 + ll * lv / (1.0 + ll + lv);
                agg_add(&ag, (u - c) / c, "(%g, %g, alpha %g): corr %.17g, uncorr %.17g", cs[i], cs[j], a, c, u);
                agg_add(&ar, rel_err(c / u, ratio), "(%g, %g, alpha %g): %.17g vs %.17g", cs[i], cs[j], a, c / u,
                        ratio);
            }
    }
    printf("6. G2 correlated >= uncorrelated on %ld points: max (uncorr - corr)/corr %.3g (tol 2 eps); "
           "ratio vs 1 + Ll Lv/(1+Ll+Lv) max rel %.3g (tol 1e-14)\n",
           ag.n, agg_done(&ag), agg_done(&ar));
}

/* ---- long double references (7, 8) ----------------------------------------
 * Written from the definitions, independently of the oracle's algebra.
 * Needs at least x87 extended precision (64-bit significand). */
typedef long double ld;

static const ld PI_L = 3.141592653589793238462643383279502884L;

static void ld_two_sum(ld a, ld b, ld *s, ld *e)
{
    ld bb;
    *s = a + b;
    bb = *s - a;
    *e = (a - (*s - bb)) + (b - bb);
}

/* 2 + 2 L.V - (N.L + N.V)^2 = |L + V|^2 - (N.(L + V))^2, the squared
 * tangential part of L + V, for double inputs: every term kept exactly
 * (two-sums, fmal for the square) until the final, benign roundings, so it
 * is accurate to 2^-64 relative plus ~2^-125 absolute even where it cancels
 * (the specular peak). */
static ld ref_num(double nl, double nv, double lv)
{
    ld A, a, sh, sl, p, pe, B, b;
    ld_two_sum(2.0L, 2.0L * lv, &A, &a);
    ld_two_sum(nl, nv, &sh, &sl);
    p = sh * sh;
    pe = fmal(sh, sh, -p);
    ld_two_sum(A, -p, &B, &b);
    return B + (((b + a) - pe) - (2.0L * sh * sl + sl * sl));
}

/* The geometry of a double triple by the identities (valid for any pair of
 * unit vectors with these dots): |L + V|^2 = 2t, t = 1 + L.V, N.H = s/|L+V|,
 * L.H = |L+V|/2, tan^2 = num / s^2, s = N.L + N.V; t raised to s^2/2 where
 * num < 0 (the contract's extension).  y = 1 - L.H = (1 - t/2)/(1 + L.H). */
typedef struct {
    ld t, n_h, l_h, tan2, y;
} ref_geom;

static ref_geom ref_geometry(double nl, double nv, double lv)
{
    ref_geom g;
    ld s = (ld)nl + (ld)nv, num = ref_num(nl, nv, lv), omh;
    if (num >= 0) {
        g.t = 1.0L + lv;
        omh = (1.0L - lv) / 2;
    } else {
        num = 0;
        g.t = s * s / 2;
        omh = ((1.0L - nl) + (1.0L - nv)) * (2 + s) / 4; /* 1 - s^2/4 */
    }
    g.tan2 = num / (s * s);
    g.n_h = s / sqrtl(2 * g.t);
    if (g.n_h > 1)
        g.n_h = 1;
    g.l_h = sqrtl(g.t / 2);
    g.y = omh / (1 + g.l_h);
    return g;
}

/* D = alpha^2 / (pi cos^4 (alpha^2 + tan^2)^2), 1/cos^2 = 1 + tan^2 */
static ld ref_d(ld tan2, ld a)
{
    ld a2 = a * a, q = a2 + tan2;
    return a2 * (1 + tan2) * (1 + tan2) / (PI_L * q * q);
}

static ld ref_one_minus_pow5(ld x) /* 1 - (1 - x)^5 */
{
    ld y = 1 - x;
    return x * (1 + y * (1 + y * (1 + y * (1 + y))));
}

static ld ref_diffuse_g(const ref_geom *g, double nl, double nv, double alpha, double rho)
{
    ld a = alpha;
    ld facing = g->t / 2;
    ld rough = facing * (0.9L - 0.4L * facing) * (0.5L + g->n_h) / g->n_h;
    ld smooth = 1.05L * ref_one_minus_pow5(nl) * ref_one_minus_pow5(nv);
    ld single = ((1 - a) * smooth + a * rough) / PI_L;
    return rho * (single + rho * 0.1159L * a);
}

static ld ref_diffuse(double nl, double nv, double lv, double alpha, double rho)
{
    ref_geom g = ref_geometry(nl, nv, lv);
    return ref_diffuse_g(&g, nl, nv, alpha, rho);
}

static ld ref_brdf(double nl, double nv, double lv, double alpha, double f0, double rho)
{
    ref_geom g = ref_geometry(nl, nv, lv);
    ld a = alpha, y2 = g.y * g.y;
    ld d = ref_d(g.tan2, a);
    ld vis = 0.5L / ((1 - a) * 2 * (ld)nl * nv + a * ((ld)nl + nv));
    ld f = f0 + (1 - (ld)f0) * y2 * y2 * g.y;
    return d * vis * f + ref_diffuse_g(&g, nl, nv, alpha, rho);
}

/* Lambda = (sqrt(1 + x) - 1)/2 = x / (2 (1 + sqrt(1 + x))), x = a^2 tan^2 */
static ld ref_lambda(double c, double a)
{
    ld x = (ld)a * a * ((1.0L - c) * (1.0L + c)) / ((ld)c * c);
    return x / (2 * (1 + sqrtl(1 + x)));
}

static int have_long_double(const char *what)
{
    if (LDBL_MANT_DIG >= 64)
        return 1;
    SKIP("%s: long double has %d significand bits here (need >= 64)", what, (int)LDBL_MANT_DIG);
    return 0;
}

/* ---- 7. geometry against vectors built in long double --------------------- */
static void check_geometry(void)
{
    static const char *const fields[4] = {
        "geometry n_h vs vectors, rel beyond 2x the L.V rounding",
        "geometry l_h vs vectors, rel beyond 2x the L.V rounding",
        "geometry l_v vs vectors, rel beyond 2x the L.V rounding",
        "geometry tan2_h vs vectors, rel beyond 2x the L.V rounding",
    };
    long n = quick ? 5000 : 50000, j;
    double worst_near = 0.0;
    agg av[4], acons, atan, anh;
    smp_rng rng;
    size_t i;
    int q;
    /* triples no unit vectors can form */
    static const double bad[][3] = {
        {1.0, 1.0, 0.0}, {1.0, 0.5, 0.9}, {0.5, 0.5, -0.9}, {0.9, 0.1, 0.99}, {0.2, 0.3, 0.999},
        {1e-6, 1e-6, -1.0 + 1e-20}, {0.7, 0.7, -0.9},
    };
    if (!have_long_double("geometry vs long double vectors"))
        return;
    for (q = 0; q < 4; q++)
        agg_init(&av[q], fields[q], 1e-14);
    agg_init(&acons, "geometry: genuine pair well inside the feasible set reported inconsistent", 0.0);
    agg_init(&atan, "geometry tan2_h vs the exact triple (abs floor 1e-28), rel", 1e-14);
    agg_init(&anh, "geometry n_h vs the exact triple, rel", 1e-15);
    rng.s = 0x9e0;
    for (j = 0; j < n; j++) {
        /* N = z, V = (sv, 0, nv), L = (-sl cos d, -sl sin d, nl): d is the
         * departure from the mirror azimuth, uniform or tiny.  The cosines
         * are doubles, the rest long double; only L.V gets rounded. */
        double nl = rnd_cos(&rng), nv = (j & 3) == 0 ? nl : rnd_cos(&rng), lv;
        ld d = (j & 1) ? PI_L * (2 * smp_u01(&rng) - 1) : (smp_u01(&rng) - 0.5) * smp_log2u(&rng, -30, 0);
        ld sl = sqrtl((1.0L - nl) * (1.0L + nl)), sv = sqrtl((1.0L - nv) * (1.0L + nv));
        ld cd = cosl(d), sd = sinl(d), sh = sinl(d / 2);
        ld L[3], H[3], len, lvx, dlv, t, s, nh, lh, tan2, pred[4], want[4];
        double got[4];
        facet_oracle_geom g;
        L[0] = -sl * cd;
        L[1] = -sl * sd;
        L[2] = nl;
        lvx = -sl * sv * cd + (ld)nl * nv;
        lv = (double)lvx;
        /* the rounding of L.V, plus the long double slop of lvx itself */
        dlv = fabsl((ld)lv - lvx) + 0x1p-62L;
        /* h = L + V; near the mirror azimuth sv - sl cos d cancels, so it is
         * (sv^2 - sl^2)/(sv + sl) + sl (1 - cos d), sv^2 - sl^2 = nl^2 - nv^2 */
        H[0] = cd > 0 ? ((ld)nl - nv) * ((ld)nl + nv) / (sv + sl) + 2 * sl * sh * sh : sv - sl * cd;
        H[1] = L[1];
        H[2] = (ld)nl + nv;
        len = sqrtl(H[0] * H[0] + H[1] * H[1] + H[2] * H[2]);
        t = 1 + lvx;
        nh = H[2] / len;
        lh = t / len; /* L.h = L.L + L.V */
        tan2 = (H[0] * H[0] + H[1] * H[1]) / (H[2] * H[2]);
        s = H[2];
        g = facet_oracle_geometry(nl, nv, lv);
        /* first-order effect of rounding L.V on each quantity (relative) */
        want[0] = nh;   got[0] = g.n_h;    pred[0] = dlv / (2 * t);
        want[1] = lh;   got[1] = g.l_h;    pred[1] = dlv / (2 * t);
        want[2] = lvx;  got[2] = g.l_v;    pred[2] = dlv / fabsl(lvx);
        want[3] = tan2; got[3] = g.tan2_h; pred[3] = 2 * dlv / (tan2 * s * s);
        for (q = 0; q < 4; q++) {
            double e;
            if (!(pred[q] < 1e-6) || !g.consistent)
                continue; /* conditioned away by the input rounding: next */
            e = (double)(fabsl((ld)got[q] - want[q]) / fabsl(want[q]));
            agg_add(&av[q], fmax(e - 2.0 * (double)pred[q], 0.0), "(%.17g, %.17g, %.17g): %.17g vs vectors %.17Lg", nl, nv,
                    lv, got[q], want[q]);
        }
        /* well inside the feasible set (|cos d| < 1 - 1e-6, sl sv > 1e-3,
         * so rounding moves cos d by < 1e-12): consistent */
        if (fabsl(cd) < 1 - 1e-6L && sl * sv > 1e-3L)
            agg_add(&acons, g.consistent ? 0.0 : 1.0, "(%.17g, %.17g, %.17g)", nl, nv, lv);
        /* near the peak (and anywhere) tan^2 and N.H against the exact
         * geometry of the double triple itself; floor 1e-28: a zero
         * tangential part comes out as double-double rounding */
        {
            ref_geom r = ref_geometry(nl, nv, lv);
            ld dt = fabsl((ld)g.tan2_h - r.tan2);
            double e = dt < 1e-28L ? 0.0 : (double)(dt / r.tan2);
            agg_add(&atan, e, "(%.17g, %.17g, %.17g): %.17g vs %.17Lg", nl, nv, lv, g.tan2_h, r.tan2);
            agg_add(&anh, (double)(fabsl((ld)g.n_h - r.n_h) / r.n_h), "(%.17g, %.17g, %.17g): %.17g vs %.17Lg", nl,
                    nv, lv, g.n_h, r.n_h);
            if (r.tan2 < 1e-6L)
                worst_near = fmax(worst_near, e);
        }
    }
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        facet_oracle_geom g = facet_oracle_geometry(bad[i][0], bad[i][1], bad[i][2]);
        ref_geom r = ref_geometry(bad[i][0], bad[i][1], bad[i][2]);
        CHECK(g.consistent == 0, "geometry(%g, %g, %g): impossible triple reported consistent", bad[i][0],
              bad[i][1], bad[i][2]);
        /* the extension (t raised to s^2/2) by the same identities */
        CHECK(rel_err(g.n_h, (double)r.n_h) <= 1e-15 && rel_err(g.l_h, (double)r.l_h) <= 1e-15 &&
                  fabs(g.tan2_h - (double)r.tan2) <= 1e-15 * fmax((double)r.tan2, 1.0),
              "geometry(%g, %g, %g) extension: n_h %.17g/%.17Lg l_h %.17g/%.17Lg tan2 %.17g/%.17Lg", bad[i][0],
              bad[i][1], bad[i][2], g.n_h, r.n_h, g.l_h, r.l_h, g.tan2_h, r.tan2);
    }
    printf("7. geometry vs long double vectors, %ld pairs (%ld well inside: all consistent), beyond 2x the rounding of L.V:\n"
           "   n_h %.3g  l_h %.3g  l_v %.3g  tan2_h %.3g (tol 1e-14)\n", n, acons.n, agg_done(&av[0]),
           agg_done(&av[1]), agg_done(&av[2]), agg_done(&av[3]));
    agg_done(&acons);
    printf("   vs the exact triple (long double, exact 2 + 2 L.V - (N.L + N.V)^2): tan2_h %.3g, of which near "
           "the peak (tan2 < 1e-6) %.3g (tol 1e-14); n_h %.3g (tol 1e-15)\n",
           agg_done(&atan), worst_near, agg_done(&anh));
}

/* ---- 8. ill-conditioned points against long double ------------------------
 * Specular peak (L the mirror image of V, and tiny departures from it) at
 * alpha = 2^-10, grazing angles down to 2^-20, L nearly opposite V at grazing,
 * L nearly equal V; f0 = 0 exposes 1 - L.H.  The oracle judges f32 kernels
 * at ~1e-7, so it must be >= 100x better: the requirement is 1e-9; the
 * tolerance here is the oracle's documented 1e-12. */
#define TOL8 1e-12

static void check_ill_conditioned(void)
{
    static const double nvs[] = {9.5367431640625e-07, 1e-6, 1e-5, 1e-4, 1e-3, 0.01, 0.1, 0.3, 0.5,
                                 0.7071067811865476, 0.9, 0.99, 0.9999, 1.0 - 1e-8, 1.0};
    static const double dth[] = {0.0, 1e-12, -1e-9, 1e-6, -1e-4, 1e-3};
    static const double dph[] = {0.0, 1e-12, 1e-9, 1e-6, 1e-4, 1e-2};
    static const double alphas[] = {0.0009765625, 0.03125, 0.5};
    static const double f0s[] = {0.0, 0.04, 1.0};
    static const double rhos[] = {0.0, 0.5};
    long n_rand = quick ? 300 : 3000, j;
    size_t i, ia, k;
    agg ab, ad, at, an, as, al;
    smp_rng rng;
    if (!have_long_double("ill-conditioned points vs long double"))
        return;
    agg_init(&ab, "brdf_hammon vs long double at the peak, rel (abs below 2^-100)", TOL8);
    agg_init(&ad, "D through the oracle's geometry vs long double at the peak, rel", TOL8);
    agg_init(&at, "geometry tan2_h at the peak vs the exact triple, rel x tan2/(alpha_min^2 + tan2)", TOL8);
    agg_init(&an, "ggx_d(1 - 2^-k) vs long double, rel", TOL8);
    agg_init(&as, "Smith G1/G2/Vis/Lambda at grazing and near-normal cosines vs long double, rel", TOL8);
    agg_init(&al, "loh_from_dots near L.V = +-1 vs long double, rel", TOL8);
    rng.s = 0x111c;
    for (j = 0; j < (long)(sizeof nvs / sizeof nvs[0] * 36) + n_rand; j++) {
        double nl, nv, lv;
        ld sl, sv, lvx, dphi;
        if (j < (long)(sizeof nvs / sizeof nvs[0] * 36)) {
            /* the grid: nv, then N.L = N.V (1 + dth), azimuth pi + dph */
            nv = nvs[j / 36];
            nl = fmin(fmax(nv * (1.0 + dth[(j / 6) % 6]), FACET_COS_MIN), 1.0);
            dphi = dph[j % 6];
        } else {
            nv = smp_log2u(&rng, -20, 0);
            nl = fmin(fmax(nv * (1.0 + (smp_u01(&rng) - 0.5) * smp_log2u(&rng, -40, -1)), FACET_COS_MIN), 1.0);
            dphi = (smp_next(&rng) & 3) ? smp_log2u(&rng, -40, 0) : PI_L - smp_log2u(&rng, -30, 1);
        }
        /* L = (-sl cos dphi, -sl sin dphi, nl), V = (sv, 0, nv) */
        sl = sqrtl((1.0L - nl) * (1.0L + nl));
        sv = sqrtl((1.0L - nv) * (1.0L + nv));
        lvx = -sl * sv * cosl(dphi) + (ld)nl * nv;
        lv = (double)fminl(fmaxl(lvx, -1.0L), 1.0L);
        for (ia = 0; ia < sizeof alphas / sizeof alphas[0]; ia++) {
            double a = alphas[ia];
            for (i = 0; i < sizeof f0s / sizeof f0s[0]; i++)
                for (k = 0; k < sizeof rhos / sizeof rhos[0]; k++) {
                    double got = facet_oracle_brdf_hammon(nl, nv, lv, a, f0s[i], rhos[k]);
                    ld want = ref_brdf(nl, nv, lv, a, f0s[i], rhos[k]);
                    /* values below 2^-100 compared absolutely, as in test_f32_accuracy */
                    double e = (double)(fabsl(got - want) / fmaxl(want, 0x1p-100L));
                    agg_add(&ab, e, "(%.17g, %.17g, %.17g, %g, %g, %g): %.17g vs %.17Lg", nl, nv, lv, a, f0s[i],
                            rhos[k], got, want);
                }
            {
                /* D alone, through the oracle's geometry */
                facet_oracle_geom g = facet_oracle_geometry(nl, nv, lv);
                ref_geom r = ref_geometry(nl, nv, lv);
                double got = facet_oracle_ggx_d_tan2(g.tan2_h, g.n_h, a);
                ld want = ref_d(r.tan2, a);
                agg_add(&ad, (double)(fabsl(got - want) / want), "(%.17g, %.17g, %.17g), alpha %g: %.17g vs %.17Lg",
                        nl, nv, lv, a, got, want);
                /* tan^2 as D sees it: its error relative to alpha^2 + tan^2 */
                agg_add(&at, (double)(fabsl((ld)g.tan2_h - r.tan2) / (r.tan2 + (ld)FACET_ALPHA_MIN * FACET_ALPHA_MIN)),
                        "(%.17g, %.17g, %.17g): %.17g vs %.17Lg", nl, nv, lv, g.tan2_h, r.tan2);
            }
        }
    }
    /* ggx_d(noh) at N.H = 1 - 2^-k, and the Smith terms at grazing angles */
    for (ia = 0; ia < sizeof alphas / sizeof alphas[0]; ia++) {
        double a = alphas[ia];
        int e2;
        for (e2 = 1; e2 <= 53; e2++) {
            double c = 1.0 - exp2(-e2), got = facet_oracle_ggx_d(c, a);
            ld want = ref_d((1.0L - c) * (1.0L + c) / ((ld)c * c), a);
            agg_add(&an, (double)(fabsl(got - want) / want), "ggx_d(1 - 2^-%d, %g) = %.17g vs %.17Lg", e2, a, got,
                    want);
        }
        for (i = 0; i < sizeof nvs / sizeof nvs[0]; i++)
            for (k = 0; k < sizeof nvs / sizeof nvs[0]; k++) {
                double cl = nvs[i], cv = nvs[k];
                ld ll = ref_lambda(cl, a), lw = ref_lambda(cv, a);
                double e1 = (double)(fabsl(facet_oracle_smith_g1(cv, a) - 1 / (1 + lw)) * (1 + lw));
                double e2v = (double)(fabsl(facet_oracle_smith_g2(cl, cv, a) - 1 / (1 + ll + lw)) * (1 + ll + lw));
                ld vis = 1 / ((1 + ll + lw) * 4 * (ld)cl * cv);
                double e3 = (double)(fabsl(facet_oracle_smith_vis(cl, cv, a) - vis) / vis);
                double el = lw > 0 ? (double)(fabsl(facet_oracle_smith_lambda(cv, a) - lw) / lw) : 0.0;
                agg_add(&as, fmax(fmax(e1, e2v), fmax(e3, el)), "(%.17g, %.17g, %g): G1 %.3g G2 %.3g Vis %.3g Lambda %.3g",
                        cl, cv, a, e1, e2v, e3, el);
            }
    }
    /* L.H near L.V = -1 (the half angle near 90 degrees) and near +1 */
    for (i = 0; i <= 52; i++) {
        double lvs[2];
        int s;
        lvs[0] = -1.0 + exp2(-(double)i);
        lvs[1] = 1.0 - exp2(-(double)i - 1.0);
        for (s = 0; s < 2; s++) {
            ld want = sqrtl((1.0L + lvs[s]) / 2);
            double got = facet_oracle_loh_from_dots(lvs[s]);
            agg_add(&al, (double)(fabsl(got - want) / want), "loh_from_dots(%.17g) = %.17g vs %.17Lg", lvs[s], got,
                    want);
        }
    }
    printf("8. ill-conditioned points vs long double (tol %.0e; required 1e-9):\n"
           "   brdf_hammon %.3g over %ld evaluations, worst at %s\n", TOL8, agg_done(&ab), ab.n, ab.where);
    printf("   D from the geometry %.3g, tan2_h (as D sees it) %.3g, ggx_d(1 - 2^-k) %.3g,\n"
           "   Smith G1/G2/Vis/Lambda at grazing %.3g, loh_from_dots near +-1 %.3g\n",
           agg_done(&ad), agg_done(&at), agg_done(&an), agg_done(&as), agg_done(&al));
}

/* ---- 9. Fresnel end points, D at the peak ---------------------------------- */
static void check_end_points(void)
{
    static const double f0s[] = {0.0, 0.02, 0.04, 0.1, 1.0 / 3.0, 0.5, 0.9, 0.99, 1.0};
    size_t i;
    int ia;
    agg ad;
    /* a handful of roundings each side: 4 eps */
    agg_init(&ad, "ggx_d(1) vs 1/(pi alpha^2) and ggx_d(0) vs alpha^2/pi, rel", 4 * EPS);
    for (i = 0; i < sizeof f0s / sizeof f0s[0]; i++) {
        double f1 = facet_oracle_fresnel_schlick(f0s[i], 1.0), fz = facet_oracle_fresnel_schlick(f0s[i], 0.0);
        CHECK(f1 == f0s[i], "fresnel_schlick(%.17g, 1) = %.17g, not f0", f0s[i], f1);
        CHECK(fz == 1.0, "fresnel_schlick(%.17g, 0) = %.17g, not 1", f0s[i], fz);
    }
    for (ia = 0; ia <= 40; ia++) {
        double a = exp2(-10.0 + ia / 4.0), d1 = facet_oracle_ggx_d(1.0, a), d0 = facet_oracle_ggx_d(0.0, a);
        double e1 = rel_err(d1, 1.0 / (M_PI * a * a)), e0 = rel_err(d0, a * a / M_PI);
        agg_add(&ad, e1, "ggx_d(1, %.17g) = %.17g vs %.17g", a, d1, 1.0 / (M_PI * a * a));
        agg_add(&ad, e0, "ggx_d(0, %.17g) = %.17g vs %.17g", a, d0, a * a / M_PI);
    }
    printf("9. Fresnel F(f0,1) = f0 and F(f0,0) = 1 exactly for %d f0; D(1) = 1/(pi a^2), D(0) = a^2/pi: max rel %.3g "
           "(tol 4 eps)\n",
           (int)(sizeof f0s / sizeof f0s[0]), agg_done(&ad));
}

/* ---- 10. L.V near -1 with tiny cosines --------------------------------------
 * L nearly opposite V at grazing angles: t = 1 + L.V is tiny (down to
 * (2 FACET_COS_MIN)^2 / 2 = 2^-39 after the raise), and the diffuse term's
 * facing = t/2 is made of it alone, so t must keep its relative precision
 * (as a double l_v = t - 1 it keeps only 2^-53 / t).  Consistent triples
 * (t above (N.L + N.V)^2 / 2) and raised ones, against long double; the
 * small albedos make the single-scattering part (rough, smooth) dominate
 * the multiple-scattering constant. */
#define TOL10 4e-15

static void check_antipodal(void)
{
    static const double cs[] = {9.5367431640625e-07, 9.5370342954993248e-07 /* 2^-20 + 2^-35 */, 1e-6,
                                0x1p-16, 1e-4, 1e-3, 0.01, 0.1};
    static const double alphas[] = {0.0009765625, 0.03125, 0.5, 1.0};
    static const double rhos[] = {1e-12, 1e-6, 0.5, 1.0};
    size_t ia, ir;
    int e;
    long n_rand = quick ? 2000 : 20000, j;
    agg adf, abr, at;
    smp_rng rng;
    /* the example, against a 40-digit evaluation of facet.h's
     * formula (mpmath: t = (N.L + N.V)^2 / 2, facing = t/2, N.H = 1/sqrt2);
     * needs no long double, so it runs on every target */
    {
        double got = facet_oracle_diffuse_hammon(0x1p-20, 0x1p-20 + 0x1p-35, -1.0, 1.0, 1e-12);
        double want = 5.067384864291308123600496955406599075155e-25;
        CHECK(rel_err(got, want) <= TOL10, "diffuse_hammon(2^-20, 2^-20 + 2^-35, -1, 1, 1e-12) = %.17g, 40 digits "
              "give %.17g: rel %.3g", got, want, rel_err(got, want));
    }
    if (!have_long_double("L.V near -1 vs long double"))
        return;
    agg_init(&adf, "diffuse_hammon near L.V = -1 at tiny cosines vs long double, rel", TOL10);
    agg_init(&abr, "brdf_hammon near L.V = -1 at tiny cosines vs long double, rel", TOL10);
    agg_init(&at, "geometry near L.V = -1: n_h and l_h vs long double, rel", TOL10);
    rng.s = 0xa11;
    for (j = 0; j < (long)(sizeof cs / sizeof cs[0] * sizeof cs / sizeof cs[0]) * 56 + n_rand; j++) {
        double nl, nv, lv;
        ref_geom r;
        facet_oracle_geom g;
        if (j < (long)(sizeof cs / sizeof cs[0] * sizeof cs / sizeof cs[0]) * 56) {
            /* the grid: L.V = -1 + 2^-e, e = 0..54 (54: -1 itself) and -1.5 */
            e = (int)(j % 56);
            nl = cs[(j / 56) % (sizeof cs / sizeof cs[0])];
            nv = cs[(j / 56) / (sizeof cs / sizeof cs[0])];
            lv = e < 55 ? -1.0 + ldexp(1.0, -e) : -1.5;
        } else {
            nl = fmax(smp_log2u(&rng, -21, -3), FACET_COS_MIN);
            nv = (smp_next(&rng) & 1) ? nl : fmax(smp_log2u(&rng, -21, -3), FACET_COS_MIN);
            lv = -1.0 + smp_log2u(&rng, -54, -20);
        }
        g = facet_oracle_geometry(nl, nv, lv);
        r = ref_geometry(nl, nv, fmax(lv, -1.0));
        agg_add(&at, fmax(rel_err(g.n_h, (double)r.n_h), rel_err(g.l_h, (double)r.l_h)),
                "(%.17g, %.17g, %.17g): n_h %.17g vs %.17Lg, l_h %.17g vs %.17Lg", nl, nv, lv, g.n_h, r.n_h, g.l_h,
                r.l_h);
        for (ia = 0; ia < sizeof alphas / sizeof alphas[0]; ia++)
            for (ir = 0; ir < sizeof rhos / sizeof rhos[0]; ir++) {
                double a = alphas[ia], rho = rhos[ir];
                double got = facet_oracle_diffuse_hammon(nl, nv, lv, a, rho);
                ld want = ref_diffuse(nl, nv, fmax(lv, -1.0), a, rho);
                agg_add(&adf, (double)(fabsl(got - want) / want),
                        "diffuse_hammon(%.17g, %.17g, %.17g, %g, %g) = %.17g vs %.17Lg", nl, nv, lv, a, rho, got,
                        want);
                got = facet_oracle_brdf_hammon(nl, nv, lv, a, 0.0, rho);
                want = ref_brdf(nl, nv, fmax(lv, -1.0), a, 0.0, rho);
                agg_add(&abr, (double)(fabsl(got - want) / want),
                        "brdf_hammon(%.17g, %.17g, %.17g, %g, 0, %g) = %.17g vs %.17Lg", nl, nv, lv, a, rho, got,
                        want);
            }
    }
    printf("10. L.V near -1 at tiny cosines vs long double (tol %.0e), %ld triples:\n"
           "   diffuse_hammon %.3g (worst at %s)\n   brdf_hammon %.3g, n_h and l_h %.3g\n",
           TOL10, at.n, agg_done(&adf), adf.where, agg_done(&abr), agg_done(&at));
}

int main(void)
{
    th_name = "oracle";
    quick = getenv("FACET_TEST_QUICK") != NULL && strcmp(getenv("FACET_TEST_QUICK"), "0") != 0;
    gl_make(&R8, 8);
    gl_make(&R20, 20);
    gl_make(&R32, 32);
    check_rules();
    check_d_normalisation();
    check_d_menu();
    check_smith_lambda();
    check_g1_gtr();
    check_smith_constraint();
    check_smooth_diffuse();
    check_fresnel();
    check_diffuse_furnace();
    check_symmetry();
    check_correlated_ge();
    check_geometry();
    check_ill_conditioned();
    check_end_points();
    check_antipodal();
    check_named_points();
    return th_done();
}
