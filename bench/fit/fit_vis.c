/* fit_vis.c - reproduces the coefficients of facet's smith_vis_fit
 * (include/facet.h): a visibility term at Hammon's cost (one reciprocal,
 * no square root) fitted against exact height-correlated Smith.
 *
 * The model.  Exact correlated Smith visibility is
 *   Vis = 0.5 / (N.V r(N.L) + N.L r(N.V)),  r(x) = sqrt(a^2 + (1 - a^2) x^2)
 * (a = alpha).  Hammon replaces r by its chord a + (1 - a) x, which is up
 * to sqrt(2) too large where x ~ a << 1 (Vis 29% low).  r(x) is the length
 * of the vector (a, s x), s = sqrt(1 - a^2): a hypotenuse, which the max of
 * a few lines approximates well ("alpha max plus beta min").  The fit uses
 *   r~(x) = max(k1 a, k2 a + k3 t, k4 a + k5 t),  t = x (1 + a (c1 + c2 a))
 * (the quadratic standing in for s), and since
 *   Vis~ / Vis - 1 = (N.V r(N.L) + N.L r(N.V)) / (N.V r~(N.L) + N.L r~(N.V)) - 1
 * lies between the values of r / r~ - 1 at N.L and at N.V (equal at
 * N.L = N.V), the largest model error of Vis over the square of cosines is
 * the largest of |r / r~ - 1| over the cosines: the fit minimises that
 * maximum over x in [2^-8, 1] and alpha in [2^-10, 1] (a grid, log- and
 * linearly spaced in both), by Nelder-Mead restarted from its own best
 * point (deterministic), then checks it on a 4x finer grid.  The kernel
 * stores 2 k_i (the 0.5 folded in) and c1, c2 rounded to float; this
 * program reports the error with those rounded values too.
 *
 * Build and run:  cc -O2 -o fit_vis bench/fit/fit_vis.c -lm && ./fit_vis
 * (a minute or two).  tests/f32/test_vis_fit.c checks the 5% bound on the
 * 3-D grid with the oracle (facet_oracle_smith_vis_fit vs smith_vis). */
#include <stdio.h>
#include <stdlib.h>
#include <math.h>

#define NP 7 /* k1 k2 k3 k4 k5 c1 c2 */

static double gx[1024], ga[1024];
static int nx, na;

static void grid(int n)
{
    int i;
    nx = na = 0;
    for (i = 0; i < n; i++) {
        gx[nx++] = pow(2.0, -8.0 * (1.0 - (double)i / (n - 1)));
        gx[nx++] = 0x1p-8 + (1.0 - 0x1p-8) * i / (n - 1);
        ga[na++] = pow(2.0, -10.0 * (1.0 - (double)i / (n - 1)));
        ga[na++] = 0x1p-10 + (1.0 - 0x1p-10) * i / (n - 1);
    }
}

static double rfit(const double *p, double a, double x)
{
    double t = x * (1.0 + a * (p[5] + p[6] * a));
    return fmax(p[0] * a, fmax(p[1] * a + p[2] * t, p[3] * a + p[4] * t));
}

static double maxerr(const double *p, double *wx, double *wa)
{
    double m = 0;
    int i, j;
    for (j = 0; j < na; j++)
        for (i = 0; i < nx; i++) {
            double a = ga[j], x = gx[i];
            double r = sqrt(a * a + (1 - a * a) * x * x), q = rfit(p, a, x);
            double e = q > 0 ? fabs(r / q - 1) : 1e9;
            if (e > m) {
                m = e;
                if (wx) {
                    *wx = x;
                    *wa = a;
                }
            }
        }
    return m;
}

static unsigned long long seed = 1;
static double rnd(void)
{
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return (seed >> 11) * 0x1p-53;
}

/* Nelder-Mead on the maximum error, from p, with a random initial simplex */
static double nelder_mead(double *p, int iters, double scale)
{
    double X[NP + 1][NP], F[NP + 1];
    int i, j, k, n = NP;
    for (i = 0; i <= n; i++) {
        for (j = 0; j < n; j++)
            X[i][j] = p[j] + (i == j + 1 ? scale * (0.05 + 0.1 * fabs(p[j])) * (rnd() < 0.5 ? -1 : 1) : 0);
        F[i] = maxerr(X[i], 0, 0);
    }
    for (k = 0; k < iters; k++) {
        int hi = 0, lo = 0, nh;
        double c[NP] = { 0 }, xr[NP], xe[NP], xc[NP], fr, fe, fc;
        for (i = 0; i <= n; i++) {
            if (F[i] > F[hi]) hi = i;
            if (F[i] < F[lo]) lo = i;
        }
        nh = lo;
        for (i = 0; i <= n; i++)
            if (i != hi && F[i] > F[nh]) nh = i;
        for (i = 0; i <= n; i++)
            if (i != hi)
                for (j = 0; j < n; j++)
                    c[j] += X[i][j] / n;
        for (j = 0; j < n; j++)
            xr[j] = 2 * c[j] - X[hi][j];
        fr = maxerr(xr, 0, 0);
        if (fr < F[lo]) {
            for (j = 0; j < n; j++)
                xe[j] = 3 * c[j] - 2 * X[hi][j];
            fe = maxerr(xe, 0, 0);
            for (j = 0; j < n; j++)
                X[hi][j] = fe < fr ? xe[j] : xr[j];
            F[hi] = fe < fr ? fe : fr;
        } else if (fr < F[nh]) {
            for (j = 0; j < n; j++)
                X[hi][j] = xr[j];
            F[hi] = fr;
        } else {
            for (j = 0; j < n; j++)
                xc[j] = 0.5 * (c[j] + X[hi][j]);
            fc = maxerr(xc, 0, 0);
            if (fc < F[hi]) {
                for (j = 0; j < n; j++)
                    X[hi][j] = xc[j];
                F[hi] = fc;
            } else {
                for (i = 0; i <= n; i++)
                    if (i != lo) {
                        for (j = 0; j < n; j++)
                            X[i][j] = 0.5 * (X[lo][j] + X[i][j]);
                        F[i] = maxerr(X[i], 0, 0);
                    }
            }
        }
    }
    k = 0;
    for (i = 0; i <= n; i++)
        if (F[i] < F[k]) k = i;
    for (j = 0; j < n; j++)
        p[j] = X[k][j];
    return F[k];
}

int main(int argc, char **argv)
{
    /* start: alpha max plus beta min (0.96, 0.40) with a 45-degree third line */
    double best[NP] = { 1.0, 0.40, 0.96, 0.75, 0.70, 0.0, -0.5 }, p[NP], fb, f, wx, wa;
    int rounds = argc > 1 ? atoi(argv[1]) : 12, r, j;
    setvbuf(stdout, NULL, _IONBF, 0);
    grid(48);
    fb = maxerr(best, 0, 0);
    printf("start: max |r/r~ - 1| = %.5f\n", fb);
    for (r = 0; r < rounds; r++) {
        for (j = 0; j < NP; j++)
            p[j] = best[j];
        f = nelder_mead(p, 3000, r < rounds / 2 ? 1.0 : 0.1);
        if (f < fb) {
            fb = f;
            for (j = 0; j < NP; j++)
                best[j] = p[j];
        }
        printf("round %2d: %.5f\n", r, fb);
    }
    grid(192);
    printf("fitted (grid 48):  %.5f; on the 4x finer grid %.5f", fb, maxerr(best, &wx, &wa));
    printf(" at x = %.4g, alpha = %.4g\n", wx, wa);
    for (j = 0; j < NP; j++)
        best[j] = j < 5 ? (double)(float)(2.0 * best[j]) / 2.0 : (double)(float)best[j];
    printf("with float coefficients: %.5f\n", maxerr(best, &wx, &wa));
    printf("kernel constants (2 k1 .. 2 k5, c1, c2):\n");
    for (j = 0; j < NP; j++)
        printf("  %.9gf\n", j < 5 ? 2.0 * best[j] : best[j]);
    return 0;
}
