/* test_sample_chi2.c - goodness of fit of every sampler against its pdf.
 *
 * For each configuration (sampler, alpha, view), N samples (10^6; 2 10^5
 * under FACET_TEST_QUICK) from a fixed seed on the active port's batch
 * function, binned on a 2-D histogram of h: 16 bins in q (the GGX CDF of
 * theta_h for the configuration's width, q = tan^2 / (a^2 + tan^2), so that
 * bins carry comparable mass) by 16 in phi_h.  Expected counts: N times the
 * integral of the oracle pdf over each bin (composite Gauss-Legendre in
 * (w, phi), q = 1 - w^2, which removes the Jacobian's (1 - q)^-1/2 at the
 * horizon); bins expecting fewer than 5 are pooled.  Pass: p > 0.01
 * (Pearson chi-square, dof = bins - 1), and the expected counts sum to N
 * within 2e-5 (the pdf integrates to 1 over the hemisphere).
 *
 * Also: Heitz's 2018 VNDF algorithm, written here in double from the paper's
 * description, against the same pdf (it and the library's spherical-cap
 * form are the same law), and for alpha below 0.05, where a histogram
 * cannot resolve the peak, a moment test: the sample mean and variance of
 * 1 - N.H against the pdf's by quadrature (|z| < 4). */
#include <stdio.h>
#include <stdlib.h>
#include "../lib/harness.h"
#include "../lib/sample_common.h"
#include "facet/oracle.h"

#define NQ 16
#define NPHI 16
#define GL_N 6
/* Gauss-Legendre panels per bin and dimension: the VNDF pdf has a kink
 * (max(0, V.H)) crossing the bins, which near-grazing views put where the
 * mass is, so those get finer panels */
#define PANELS(c) ((c)->theta_v >= 85 ? 8 : 3)

enum { S_D, S_D_ANISO, S_VNDF, S_VNDF_ANISO, S_GTR1, S_HEITZ };
static const char *const kind_name[] = { "ggx_sample_d", "ggx_sample_d_aniso", "ggx_sample_vndf",
                                         "ggx_sample_vndf_aniso", "gtr_sample_d(1)", "heitz2018(double)" };

typedef struct {
    int kind;
    double ax, ay, theta_v; /* degrees */
    double mis; /* power check: samples drawn with alpha * (1 + mis), must fail */
} config;

static const double PI_ = 3.14159265358979323846;
static double gl_x[GL_N], gl_w[GL_N];

/* Gauss-Legendre nodes on [-1, 1] by Newton on P_n */
static void gl_init(void)
{
    int i, j;
    for (i = 0; i < GL_N; i++) {
        double x = cos(PI_ * (i + 0.75) / (GL_N + 0.5)), p0, p1, dp;
        for (j = 0; j < 100; j++) {
            int k;
            p0 = 1;
            p1 = x;
            for (k = 2; k <= GL_N; k++) {
                double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = GL_N * (x * p1 - p0) / (x * x - 1);
            x -= p1 / dp;
        }
        gl_x[i] = x;
        gl_w[i] = 2 / ((1 - x * x) * dp * dp);
    }
}

/* upper regularized incomplete gamma Q(a, x): series for P below a + 1,
 * continued fraction (modified Lentz) above */
static double gamma_q(double a, double x)
{
    double gln = lgamma(a);
    if (x <= 0)
        return 1;
    if (x < a + 1) {
        double ap = a, sum = 1 / a, del = sum;
        int n;
        for (n = 0; n < 10000; n++) {
            ap += 1;
            del *= x / ap;
            sum += del;
            if (fabs(del) < fabs(sum) * 1e-15)
                break;
        }
        return 1 - sum * exp(-x + a * log(x) - gln);
    } else {
        double b = x + 1 - a, c = 1e300, d = 1 / b, h = d;
        int i;
        for (i = 1; i < 10000; i++) {
            double an = -i * (i - a), del;
            b += 2;
            d = an * d + b;
            if (fabs(d) < 1e-300) d = 1e-300;
            c = b + an / c;
            if (fabs(c) < 1e-300) c = 1e-300;
            d = 1 / d;
            del = d * c;
            h *= del;
            if (fabs(del - 1) < 1e-15)
                break;
        }
        return exp(-x + a * log(x) - gln) * h;
    }
}

static void view_of(const config *c, double v[3])
{
    double t = c->theta_v * PI_ / 180, p = 0.7; /* an azimuth off the axes */
    v[0] = sin(t) * cos(p);
    v[1] = sin(t) * sin(p);
    v[2] = cos(t);
}

/* the oracle pdf of h for the configuration */
static double pdf_of(const config *c, const double h[3], const float vf[3])
{
    double vh = vf[0] * h[0] + vf[1] * h[1] + vf[2] * h[2];
    switch (c->kind) {
    case S_D: return facet_oracle_ggx_pdf_d(h[2], c->ax);
    case S_D_ANISO: return facet_oracle_ggx_pdf_d_aniso(h[0], h[1], h[2], c->ax, c->ay);
    case S_VNDF:
    case S_HEITZ: return facet_oracle_ggx_pdf_vndf(vf[2], h[2], vh, c->ax);
    case S_VNDF_ANISO:
        return facet_oracle_ggx_pdf_vndf_aniso(vf[0], vf[1], vf[2], h[0], h[1], h[2], c->ax, c->ay);
    default: return facet_oracle_gtr_pdf_d(h[2], c->ax, 1.0);
    }
}

static double bin_width(const config *c) { return sqrt(c->ax * c->ay); }

/* h at (w, phi), q = 1 - w^2, tan^2 = a^2 q / (1 - q); returns
 * |d cos(theta) / dw| */
static double h_at(double a, double w, double phi, double h[3])
{
    double q = 1 - w * w, t2 = a * a * q / (w * w), c = 1 / sqrt(1 + t2), s = sqrt(t2) * c;
    h[0] = s * cos(phi);
    h[1] = s * sin(phi);
    h[2] = c;
    /* dcos/dT = -c^3 / 2, dT/dq = a^2 / w^4, dq/dw = -2w */
    return c * c * c * a * a / (w * w * w);
}

static int bin_of(double a, const float h[3])
{
    double hx = h[0], hy = h[1], hz = h[2];
    double t2 = (hx * hx + hy * hy) / (hz * hz), q = t2 / (a * a + t2), phi = atan2(hy, hx);
    int iq = (int)(q * NQ), ip;
    if (phi < 0)
        phi += 2 * PI_;
    ip = (int)(phi / (2 * PI_) * NPHI);
    if (iq >= NQ) iq = NQ - 1;
    if (ip >= NPHI) ip = NPHI - 1;
    if (iq < 0) iq = 0;
    return iq * NPHI + ip;
}

/* Heitz 2018, from the paper's description, in double: stretch the view,
 * an orthonormal basis around it, a point of the unit disk by polar
 * coordinates with the half-disk warped by s = (1 + Vh.z) / 2, lifted onto
 * the hemisphere, unstretched. */
static void heitz(double h[3], const double v[3], double a, double u1, double u2)
{
    double V[3] = { a * v[0], a * v[1], v[2] }, n, l2, T1[3], T2[3], r, p, t1, t2, s, N[3];
    n = sqrt(V[0] * V[0] + V[1] * V[1] + V[2] * V[2]);
    V[0] /= n; V[1] /= n; V[2] /= n;
    l2 = V[0] * V[0] + V[1] * V[1];
    if (l2 > 0) {
        T1[0] = -V[1] / sqrt(l2); T1[1] = V[0] / sqrt(l2); T1[2] = 0;
    } else {
        T1[0] = 1; T1[1] = 0; T1[2] = 0;
    }
    T2[0] = V[1] * T1[2] - V[2] * T1[1];
    T2[1] = V[2] * T1[0] - V[0] * T1[2];
    T2[2] = V[0] * T1[1] - V[1] * T1[0];
    r = sqrt(u1);
    p = 2 * PI_ * u2;
    t1 = r * cos(p);
    t2 = r * sin(p);
    s = 0.5 * (1 + V[2]);
    t2 = (1 - s) * sqrt(1 - t1 * t1) + s * t2;
    {
        double z = sqrt(fmax(0, 1 - t1 * t1 - t2 * t2));
        int i;
        for (i = 0; i < 3; i++)
            N[i] = t1 * T1[i] + t2 * T2[i] + z * V[i];
    }
    N[0] *= a; N[1] *= a; N[2] = fmax(1e-300, N[2]);
    n = sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
    h[0] = N[0] / n; h[1] = N[1] / n; h[2] = N[2] / n;
}

/* N samples of configuration c from seed into h[3][N] */
static void draw(const config *c, long n, uint64_t seed, float *h[3], float *buf[8])
{
    smp_rng rng;
    double v[3];
    long j;
    rng.s = seed;
    view_of(c, v);
    for (j = 0; j < n; j++) {
        buf[0][j] = ss_u24(&rng);
        buf[1][j] = ss_u24(&rng);
        buf[2][j] = (float)(c->ax * (1 + c->mis));
        buf[3][j] = (float)(c->ay * (1 + c->mis));
        buf[4][j] = (float)v[0];
        buf[5][j] = (float)v[1];
        buf[6][j] = (float)v[2];
        buf[7][j] = 1.0f;
    }
    switch (c->kind) {
    case S_D: facet_ggx_sample_d_f32_batch(h[0], h[1], h[2], buf[0], buf[1], buf[2], n); break;
    case S_D_ANISO:
        facet_ggx_sample_d_aniso_f32_batch(h[0], h[1], h[2], buf[0], buf[1], buf[2], buf[3], n);
        break;
    case S_VNDF:
        facet_ggx_sample_vndf_f32_batch(h[0], h[1], h[2], buf[4], buf[5], buf[6], buf[0], buf[1],
                                        buf[2], n);
        break;
    case S_VNDF_ANISO:
        facet_ggx_sample_vndf_aniso_f32_batch(h[0], h[1], h[2], buf[4], buf[5], buf[6], buf[0],
                                              buf[1], buf[2], buf[3], n);
        break;
    case S_GTR1:
        facet_gtr_sample_d_f32_batch(h[0], h[1], h[2], buf[0], buf[1], buf[2], buf[7], n);
        break;
    default:
        for (j = 0; j < n; j++) {
            double vv[3] = { buf[4][j], buf[5][j], buf[6][j] }, hh[3];
            heitz(hh, vv, buf[2][j], buf[0][j], buf[1][j]);
            h[0][j] = (float)hh[0];
            h[1][j] = (float)hh[1];
            h[2][j] = (float)hh[2];
        }
    }
}

static double chi2_config(const config *c, long n, float *h[3], float *buf[8])
{
    static double expect[NQ * NPHI];
    static long obs[NQ * NPHI];
    double a = bin_width(c), total = 0, chi2 = 0, pool_e = 0, p, v[3];
    float vf[3];
    long pool_o = 0, j;
    int b, i, k, pi, pk, bins = 0;
    view_of(c, v);
    vf[0] = (float)v[0]; vf[1] = (float)v[1]; vf[2] = (float)v[2];
    draw(c, n, 0xc0ffee00u + (uint64_t)(c->ax * 1e4) * 7919u + (uint64_t)(c->theta_v * 10) * 31u + (uint64_t)c->kind, h, buf);
    memset(obs, 0, sizeof obs);
    for (j = 0; j < n; j++) {
        float hh[3] = { h[0][j], h[1][j], h[2][j] };
        obs[bin_of(a, hh)]++;
    }
    for (b = 0; b < NQ * NPHI; b++) {
        int iq = b / NPHI, ip = b % NPHI;
        /* q in [iq/NQ, (iq+1)/NQ) <-> w = sqrt(1 - q) in (w1, w0] */
        double w0 = sqrt(1 - (double)iq / NQ), w1 = sqrt(1 - (double)(iq + 1) / NQ);
        double f0 = 2 * PI_ * ip / NPHI, f1 = 2 * PI_ * (ip + 1) / NPHI, sum = 0;
        for (pi = 0; pi < PANELS(c); pi++)
            for (pk = 0; pk < PANELS(c); pk++) {
                double wa = w1 + (w0 - w1) * pi / PANELS(c), wb = w1 + (w0 - w1) * (pi + 1) / PANELS(c);
                double fa = f0 + (f1 - f0) * pk / PANELS(c), fb = f0 + (f1 - f0) * (pk + 1) / PANELS(c);
                for (i = 0; i < GL_N; i++)
                    for (k = 0; k < GL_N; k++) {
                        double w = 0.5 * (wa + wb) + 0.5 * (wb - wa) * gl_x[i];
                        double f = 0.5 * (fa + fb) + 0.5 * (fb - fa) * gl_x[k], hh[3], jac;
                        if (w <= 0)
                            continue;
                        jac = h_at(a, w, f, hh);
                        sum += gl_w[i] * gl_w[k] * 0.25 * (wb - wa) * (fb - fa) * jac * pdf_of(c, hh, vf);
                    }
            }
        expect[b] = sum * n;
        total += sum;
    }
    for (b = 0; b < NQ * NPHI; b++) {
        if (expect[b] < 5) {
            pool_e += expect[b];
            pool_o += obs[b];
            continue;
        }
        chi2 += (obs[b] - expect[b]) * (obs[b] - expect[b]) / expect[b];
        bins++;
    }
    if (pool_e >= 5) {
        chi2 += (pool_o - pool_e) * (pool_o - pool_e) / pool_e;
        bins++;
    } else if (pool_o > 3 * pool_e + 10) {
        chi2 += 1e9; /* samples where the pdf says there are almost none */
    }
    p = gamma_q(0.5 * (bins - 1), 0.5 * chi2);
    if (c->mis != 0) {
        printf("power check: %s alpha %g drawn at alpha * %g: chi2 %.1f, dof %d, p %.3g\n",
               kind_name[c->kind], c->ax, 1 + c->mis, chi2, bins - 1, p);
        return p;
    }
    printf("| %-22s | %6.3f | %6.3f | %5.1f | %8.1f | %4d | %8.4f | %.2e |\n", kind_name[c->kind], c->ax,
           c->ay, c->theta_v, chi2, bins - 1, p, total - 1);
    CHECK(p > 0.01, "%s alpha (%g, %g) view %g deg: chi2 %.1f, dof %d, p %.4g <= 0.01",
          kind_name[c->kind], c->ax, c->ay, c->theta_v, chi2, bins - 1, p);
    CHECK(fabs(total - 1) < 2e-5, "%s alpha (%g, %g) view %g deg: the pdf integrates to %.8f, not 1",
          kind_name[c->kind], c->ax, c->ay, c->theta_v, total);
    return p;
}

/* moments of t = 1 - N.H: sample mean and variance against quadrature */
static void moment_config(const config *c, long n, float *h[3], float *buf[8])
{
    double a = bin_width(c), m1 = 0, m2 = 0, s1 = 0, s2 = 0, v[3], mean, var, sm, sv, z1, z2;
    float vf[3];
    long j;
    int iq, ip, i, k;
    const int NW = 200, NF = 32;
    view_of(c, v);
    vf[0] = (float)v[0]; vf[1] = (float)v[1]; vf[2] = (float)v[2];
    draw(c, n, 0xabcd0000u + (uint64_t)c->kind * 977u + (uint64_t)(c->ax * 1e5), h, buf);
    for (j = 0; j < n; j++) {
        double hx = h[0][j], hy = h[1][j], hz = h[2][j], t = (hx * hx + hy * hy) / (1 + hz);
        s1 += t;
        s2 += t * t;
    }
    for (iq = 0; iq < NW; iq++)
        for (ip = 0; ip < NF; ip++) {
            double wa = (double)iq / NW, wb = (double)(iq + 1) / NW;
            double fa = 2 * PI_ * ip / NF, fb = 2 * PI_ * (ip + 1) / NF;
            for (i = 0; i < GL_N; i++)
                for (k = 0; k < GL_N; k++) {
                    double w = 0.5 * (wa + wb) + 0.5 * (wb - wa) * gl_x[i];
                    double f = 0.5 * (fa + fb) + 0.5 * (fb - fa) * gl_x[k], hh[3], jac, pw, t;
                    jac = h_at(a, w, f, hh);
                    pw = gl_w[i] * gl_w[k] * 0.25 * (wb - wa) * (fb - fa) * jac * pdf_of(c, hh, vf);
                    t = (hh[0] * hh[0] + hh[1] * hh[1]) / (1 + hh[2]);
                    m1 += pw * t;
                    m2 += pw * t * t;
                }
        }
    mean = m1;
    var = m2 - m1 * m1;
    sm = s1 / n;
    sv = s2 / n - sm * sm;
    z1 = (sm - mean) / sqrt(var / n);
    /* Var of the sample variance ~ (mu4 - var^2) / n; mu4 bounded by the
     * 4th raw moment, taken from the samples */
    {
        double m4 = 0;
        for (j = 0; j < n; j++) {
            double hx = h[0][j], hy = h[1][j], hz = h[2][j], t = (hx * hx + hy * hy) / (1 + hz) - sm;
            m4 += t * t * t * t;
        }
        m4 /= n;
        z2 = (sv - var) / sqrt(fmax(m4 - sv * sv, 1e-300) / n);
    }
    printf("| %-22s | %6.4f | %6.4f | %5.1f | mean %.6e vs %.6e (z %+.2f), var %.6e vs %.6e (z %+.2f) |\n",
           kind_name[c->kind], c->ax, c->ay, c->theta_v, sm, mean, z1, sv, var, z2);
    CHECK(fabs(z1) < 4 && fabs(z2) < 4, "%s alpha %g view %g: moment z-scores %.2f, %.2f", kind_name[c->kind],
          c->ax, c->theta_v, z1, z2);
}

int main(void)
{
    static const config chi[] = {
        { S_D, 0.05, 0.05, 0, 0 }, { S_D, 0.1, 0.1, 0, 0 }, { S_D, 0.25, 0.25, 0, 0 }, { S_D, 0.5, 0.5, 0, 0 },
        { S_D, 0.75, 0.75, 0, 0 }, { S_D, 1.0, 1.0, 0, 0 },
        { S_D_ANISO, 0.05, 0.3, 0, 0 }, { S_D_ANISO, 0.5, 0.1, 0, 0 },
        { S_VNDF, 0.05, 0.05, 0, 0 }, { S_VNDF, 0.05, 0.05, 45, 0 }, { S_VNDF, 0.05, 0.05, 80, 0 },
        { S_VNDF, 0.05, 0.05, 89, 0 }, { S_VNDF, 0.05, 0.05, 89.9, 0 },
        { S_VNDF, 0.2, 0.2, 0, 0 }, { S_VNDF, 0.2, 0.2, 60, 0 }, { S_VNDF, 0.2, 0.2, 85, 0 }, { S_VNDF, 0.2, 0.2, 89.9, 0 },
        { S_VNDF, 0.5, 0.5, 30, 0 }, { S_VNDF, 0.5, 0.5, 75, 0 }, { S_VNDF, 0.5, 0.5, 89.9, 0 },
        { S_VNDF, 1.0, 1.0, 0, 0 }, { S_VNDF, 1.0, 1.0, 60, 0 }, { S_VNDF, 1.0, 1.0, 89.9, 0 },
        { S_VNDF_ANISO, 0.1, 0.4, 60, 0 }, { S_VNDF_ANISO, 0.1, 0.4, 85, 0 },
        { S_VNDF_ANISO, 0.6, 0.05, 30, 0 }, { S_VNDF_ANISO, 0.6, 0.05, 89, 0 },
        { S_GTR1, 0.05, 0.05, 0, 0 }, { S_GTR1, 0.25, 0.25, 0, 0 }, { S_GTR1, 0.5, 0.5, 0, 0 }, { S_GTR1, 1.0, 1.0, 0, 0 },
        { S_HEITZ, 0.05, 0.05, 80, 0 }, { S_HEITZ, 0.3, 0.3, 60, 0 }, { S_HEITZ, 1.0, 1.0, 89.9, 0 },
    };
    static const config mom[] = {
        { S_D, 0.002, 0.002, 0, 0 }, { S_D, 0.01, 0.01, 0, 0 }, { S_D, 0.03, 0.03, 0, 0 },
        { S_VNDF, 0.002, 0.002, 0, 0 }, { S_VNDF, 0.01, 0.01, 60, 0 }, { S_VNDF, 0.03, 0.03, 89, 0 },
        { S_GTR1, 0.005, 0.005, 0, 0 }, { S_GTR1, 0.02, 0.02, 0, 0 },
    };
    long n = getenv("FACET_TEST_QUICK") ? 200000 : 1000000, m = n;
    float *h[3], *buf[8];
    size_t i;
    th_name = "sample_chi2";
    gl_init();
    for (i = 0; i < 3; i++)
        h[i] = malloc(n * sizeof(float));
    for (i = 0; i < 8; i++)
        buf[i] = malloc(n * sizeof(float));
    printf("port %s, %ld samples per configuration, %d x %d bins\n", facet_port_name(), n, NQ, NPHI);
    printf("| sampler | alpha_x | alpha_y | view (deg) | chi2 | dof | p | integral - 1 |\n|---|---|---|---|---|---|---|---|\n");
    for (i = 0; i < sizeof chi / sizeof chi[0]; i++)
        chi2_config(&chi[i], n, h, buf);
    {
        /* the test's power: alpha off by 2% (D) or 3% (VNDF at 60 degrees) must be rejected */
        static const config off[] = { { S_D, 0.25, 0.25, 0, 0.02 }, { S_VNDF, 0.3, 0.3, 60, 0.03 } };
        for (i = 0; i < 2; i++)
            CHECK(chi2_config(&off[i], n, h, buf) < 1e-4, "chi-square test too weak: %s with alpha off by %g%% passes",
                  kind_name[off[i].kind], 100 * off[i].mis);
    }
    printf("\nmoments of 1 - N.H (small alpha)\n");
    for (i = 0; i < sizeof mom / sizeof mom[0]; i++)
        moment_config(&mom[i], m, h, buf);
    for (i = 0; i < 3; i++)
        free(h[i]);
    for (i = 0; i < 8; i++)
        free(buf[i]);
    (void)smp_inputs;
    (void)ss_inputs;
    return th_done();
}
