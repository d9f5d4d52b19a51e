/* quad.h - Gauss-Legendre quadrature for the tests that integrate
 * (tests/oracle/test_oracle.c, tests/sample/test_sample_chi2.c,
 * tests/sample/test_sample_furnace.c): the rule, and the composite rule
 * over cells of the GGX q coordinates of h.
 *
 * Nodes by Newton's method on P_n (three-term recurrence), weights
 * 2 / ((1 - x^2) P_n'(x)^2) at the converged node. */
#ifndef FACET_TEST_QUAD_H
#define FACET_TEST_QUAD_H

#include <math.h>

#define GL_MAX 48

typedef struct {
    int n;
    double x[GL_MAX], w[GL_MAX];
} gl_rule;

static inline void gl_legendre(int n, double x, double *p, double *dp)
{
    double p0 = 1.0, p1 = x;
    int k;
    for (k = 2; k <= n; k++) {
        double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
    }
    *p = p1;
    *dp = n * (x * p1 - p0) / (x * x - 1.0);
}

/* the n-point rule on [-1, 1], n <= GL_MAX */
static inline void gl_make(gl_rule *r, int n)
{
    int i, it;
    r->n = n;
    for (i = 0; i < n; i++) {
        double x = cos(M_PI * (i + 0.75) / (n + 0.5)), p, dp;
        for (it = 0; it < 50; it++) {
            double dx;
            gl_legendre(n, x, &p, &dp);
            dx = p / dp;
            x -= dx;
            if (fabs(dx) < 1e-17)
                break;
        }
        gl_legendre(n, x, &p, &dp);
        r->x[i] = x;
        r->w[i] = 2.0 / ((1.0 - x * x) * dp * dp);
    }
}

/* The GGX q coordinates of a unit h around the normal, at width a:
 * q = tan^2 / (a^2 + tan^2) (the GGX CDF of theta_h, so equal steps in q
 * carry comparable mass) as w = sqrt(1 - q), and the azimuth phi.  h at
 * (w, phi); returns |d cos(theta) / dw| (tan^2 = a^2 q / w^2, dcos/dT =
 * -c^3 / 2, dT/dq = a^2 / w^4, dq/dw = -2w). */
static inline double gl_h_at(double a, double w, double phi, double h[3])
{
    double q = 1 - w * w, t2 = a * a * q / (w * w), c = 1 / sqrt(1 + t2), s = sqrt(t2) * c;
    h[0] = s * cos(phi);
    h[1] = s * sin(phi);
    h[2] = c;
    return c * c * c * a * a / (w * w * w);
}

/* The rule r on the cell [wa, wb] x [fa, fb] of (w, phi): f(h, weight, ctx)
 * at each node, weight = the node's product weight times |dcos/dw| (an
 * integral over the hemisphere in dw dphi is the sum of weight x value) */
static inline void gl_q_cell(const gl_rule *r, double a, double wa, double wb, double fa, double fb,
                             void (*f)(const double h[3], double weight, void *ctx), void *ctx)
{
    int i, k;
    for (i = 0; i < r->n; i++)
        for (k = 0; k < r->n; k++) {
            double w = 0.5 * (wa + wb) + 0.5 * (wb - wa) * r->x[i];
            double phi = 0.5 * (fa + fb) + 0.5 * (fb - fa) * r->x[k], h[3], jac;
            if (w <= 0)
                continue;
            jac = gl_h_at(a, w, phi, h);
            f(h, r->w[i] * r->w[k] * 0.25 * (wb - wa) * (fb - fa) * jac, ctx);
        }
}

#endif
