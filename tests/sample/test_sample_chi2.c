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
 * 1 - N.H against the pdf's by quadrature (|z| < 4).
 *
 * The samplers come from the sampler table (facet_sampler_at): every one
 * that draws h (outputs hx, hy, hz from u1, u2) is drawn through its table
 * batch and judged against the oracle of its pdf (the table's sampler of
 * the same name with _pdf_ for _sample_), inputs set by name.  Which
 * widths and views each is tried at is kept here (chi[], mom[]); a sampler
 * of the table without a configuration there fails, named. */
#include <stdio.h>
#include <stdlib.h>
#include "../lib/harness.h"
#include "../lib/sample_common.h"
#include "../lib/quad.h"

#define NQ 16
#define NPHI 16
#define GL_N 6
/* Gauss-Legendre panels per bin and dimension: the VNDF pdf has a kink
 * (max(0, V.H)) crossing the bins, which near-grazing views put where the
 * mass is, so those get finer panels */
#define PANELS(c) ((c)->theta_v >= 85 ? 8 : 3)

/* A configuration: the sampler (a table name), its width(s), the view, and
 * for gtr_sample_d its gamma.  salt enters the seed (the configuration's
 * kind number in the first version of this test: 0 D, 1 D aniso, 2 VNDF,
 * 3 VNDF aniso, 4 GTR1, 5 Heitz; kept, so the seeds are those; the
 * macros D_ .. HEITZ_ below give both).  heitz:
 * drawn by Heitz's 2018 algorithm in double (below) instead, judged
 * against the sampler's pdf.  mis: a power check, samples drawn with
 * alpha * (1 + mis), which must fail. */
typedef struct {
    const char *sampler;
    int salt;
    double ax, ay, theta_v; /* degrees */
    double mis;
    double gamma;
    int heitz;
} config;

static const double PI_ = 3.14159265358979323846;
static gl_rule GL;

/* the pdf of a sampler: its _pdf_ namesake in the table */
static const facet_sampler *pdf_of_sampler(const facet_sampler *s)
{
    char name[64];
    const char *p = strstr(s->name, "_sample_");
    if (!p || strlen(s->name) + 1 > sizeof name)
        return NULL;
    snprintf(name, sizeof name, "%.*s_pdf_%s", (int)(p - s->name), s->name, p + strlen("_sample_"));
    return facet_sampler_find(name);
}

/* a sampler that draws h: outputs hx, hy, hz, and a u1 among its inputs */
static int draws_h(const facet_sampler *s)
{
    return s->n_outputs == 3 && !strcmp(s->outputs[0], "hx") && !strcmp(s->outputs[1], "hy") &&
           !strcmp(s->outputs[2], "hz") && ss_input_index(s, "u1") >= 0;
}

/* the configuration's label in the printed tables, into buf */
static void label(const config *c, char *buf, size_t size)
{
    if (c->heitz)
        snprintf(buf, size, "heitz2018(double)");
    else if (ss_input_index(facet_sampler_find(c->sampler), "gamma") >= 0)
        snprintf(buf, size, "%s(%g)", c->sampler, c->gamma);
    else
        snprintf(buf, size, "%s", c->sampler);
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

/* a configuration resolved against the table once: the sampler, its pdf,
 * and where each of the pdf's inputs comes from (by name) */
enum { SRC_NOH, SRC_NOV, SRC_VOH, SRC_H, SRC_V, SRC_AX, SRC_AY, SRC_GAMMA };
typedef struct {
    const config *c;
    const facet_sampler *s, *pdf;
    int src[FACET_SAMPLER_MAX_INPUTS], comp[FACET_SAMPLER_MAX_INPUTS];
} subject;

static int resolve(const config *c, subject *sb)
{
    int i;
    sb->c = c;
    sb->s = facet_sampler_find(c->sampler);
    sb->pdf = sb->s ? pdf_of_sampler(sb->s) : NULL;
    CHECK(sb->s && draws_h(sb->s) && sb->pdf && sb->pdf->n_outputs == 1,
          "configuration of '%s': no sampler of h by that name with a pdf in the table", c->sampler);
    if (!sb->pdf)
        return 0;
    for (i = 0; i < sb->pdf->n_inputs; i++) {
        const char *n = sb->pdf->inputs[i];
        sb->comp[i] = n[1] - 'x';
        sb->src[i] = !strcmp(n, "noh") ? SRC_NOH : !strcmp(n, "nov") ? SRC_NOV : !strcmp(n, "voh") ? SRC_VOH
                   : n[0] == 'h' && n[1] && !n[2] ? SRC_H : n[0] == 'v' && n[1] && !n[2] ? SRC_V
                   : !strcmp(n, "alpha_y") ? SRC_AY : !strcmp(n, "gamma") ? SRC_GAMMA : SRC_AX; /* alpha, alpha_x */
    }
    return 1;
}

/* the oracle pdf of h for the configuration */
static double pdf_of(const subject *sb, const double h[3], const float vf[3])
{
    double vh = vf[0] * h[0] + vf[1] * h[1] + vf[2] * h[2], in[FACET_SAMPLER_MAX_INPUTS], out[1];
    int i;
    for (i = 0; i < sb->pdf->n_inputs; i++)
        switch (sb->src[i]) {
        case SRC_NOH: in[i] = h[2]; break;
        case SRC_NOV: in[i] = vf[2]; break;
        case SRC_VOH: in[i] = vh; break;
        case SRC_H: in[i] = h[sb->comp[i]]; break;
        case SRC_V: in[i] = vf[sb->comp[i]]; break;
        case SRC_AY: in[i] = sb->c->ay; break;
        case SRC_GAMMA: in[i] = sb->c->gamma; break;
        default: in[i] = sb->c->ax; break;
        }
    sb->pdf->oracle(out, in);
    return out[0];
}

/* the integrands over a cell of (w, phi): the pdf, and its moments of
 * t = 1 - N.H */
typedef struct {
    const subject *sb;
    const float *vf;
    double sum, m1, m2;
} cell_ctx;

static void pdf_node(const double h[3], double weight, void *ctx)
{
    cell_ctx *x = ctx;
    x->sum += weight * pdf_of(x->sb, h, x->vf);
}

static void moment_node(const double h[3], double weight, void *ctx)
{
    cell_ctx *x = ctx;
    double pw = weight * pdf_of(x->sb, h, x->vf), t = (h[0] * h[0] + h[1] * h[1]) / (1 + h[2]);
    x->m1 += pw * t;
    x->m2 += pw * t * t;
}

static double bin_width(const config *c) { return sqrt(c->ax * c->ay); }

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

/* N samples of configuration c from seed into h[3][N]: the sampler's table
 * batch on the active port, its inputs by name */
static void draw(const subject *sb, long n, uint64_t seed, float *h[3], float *buf[8])
{
    const config *c = sb->c;
    const facet_sampler *s = sb->s;
    const float *in[FACET_SAMPLER_MAX_INPUTS];
    smp_rng rng;
    double v[3];
    long j;
    int i;
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
        buf[7][j] = (float)c->gamma;
    }
    if (c->heitz) {
        for (j = 0; j < n; j++) {
            double vv[3] = { buf[4][j], buf[5][j], buf[6][j] }, hh[3];
            heitz(hh, vv, buf[2][j], buf[0][j], buf[1][j]);
            h[0][j] = (float)hh[0];
            h[1][j] = (float)hh[1];
            h[2][j] = (float)hh[2];
        }
        return;
    }
    for (i = 0; i < s->n_inputs; i++) {
        const char *nm = s->inputs[i];
        in[i] = !strcmp(nm, "u1") ? buf[0] : !strcmp(nm, "u2") ? buf[1] : !strcmp(nm, "alpha_y") ? buf[3]
              : nm[0] == 'v' && nm[1] && !nm[2] ? buf[4 + (nm[1] - 'x')] : !strcmp(nm, "gamma") ? buf[7]
              : buf[2]; /* alpha, alpha_x */
    }
    s->f32_batch(h, in, (size_t)n);
}

static double chi2_config(const config *c, long n, float *h[3], float *buf[8])
{
    static double expect[NQ * NPHI];
    static long obs[NQ * NPHI];
    double a = bin_width(c), total = 0, chi2 = 0, pool_e = 0, p, v[3];
    float vf[3];
    long pool_o = 0, j;
    int b, pi, pk, bins = 0;
    subject sb;
    cell_ctx x;
    char name[64];
    if (!resolve(c, &sb))
        return 0;
    view_of(c, v);
    vf[0] = (float)v[0]; vf[1] = (float)v[1]; vf[2] = (float)v[2];
    draw(&sb, n, 0xc0ffee00u + (uint64_t)(c->ax * 1e4) * 7919u + (uint64_t)(c->theta_v * 10) * 31u + (uint64_t)c->salt, h, buf);
    memset(obs, 0, sizeof obs);
    for (j = 0; j < n; j++) {
        float hh[3] = { h[0][j], h[1][j], h[2][j] };
        obs[bin_of(a, hh)]++;
    }
    x.sb = &sb;
    x.vf = vf;
    for (b = 0; b < NQ * NPHI; b++) {
        int iq = b / NPHI, ip = b % NPHI;
        /* q in [iq/NQ, (iq+1)/NQ) <-> w = sqrt(1 - q) in (w1, w0] */
        double w0 = sqrt(1 - (double)iq / NQ), w1 = sqrt(1 - (double)(iq + 1) / NQ);
        double f0 = 2 * PI_ * ip / NPHI, f1 = 2 * PI_ * (ip + 1) / NPHI;
        x.sum = 0;
        for (pi = 0; pi < PANELS(c); pi++)
            for (pk = 0; pk < PANELS(c); pk++)
                gl_q_cell(&GL, a, w1 + (w0 - w1) * pi / PANELS(c), w1 + (w0 - w1) * (pi + 1) / PANELS(c),
                          f0 + (f1 - f0) * pk / PANELS(c), f0 + (f1 - f0) * (pk + 1) / PANELS(c), pdf_node, &x);
        expect[b] = x.sum * n;
        total += x.sum;
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
    label(c, name, sizeof name);
    if (c->mis != 0) {
        printf("power check: %s alpha %g drawn at alpha * %g: chi2 %.1f, dof %d, p %.3g\n",
               name, c->ax, 1 + c->mis, chi2, bins - 1, p);
        return p;
    }
    printf("| %-22s | %6.3f | %6.3f | %5.1f | %8.1f | %4d | %8.4f | %.2e |\n", name, c->ax,
           c->ay, c->theta_v, chi2, bins - 1, p, total - 1);
    CHECK(p > 0.01, "%s alpha (%g, %g) view %g deg: chi2 %.1f, dof %d, p %.4g <= 0.01",
          name, c->ax, c->ay, c->theta_v, chi2, bins - 1, p);
    CHECK(fabs(total - 1) < 2e-5, "%s alpha (%g, %g) view %g deg: the pdf integrates to %.8f, not 1",
          name, c->ax, c->ay, c->theta_v, total);
    return p;
}

/* moments of t = 1 - N.H: sample mean and variance against quadrature */
static void moment_config(const config *c, long n, float *h[3], float *buf[8])
{
    double a = bin_width(c), s1 = 0, s2 = 0, v[3], mean, var, sm, sv, z1, z2;
    float vf[3];
    long j;
    int iq, ip;
    const int NW = 200, NF = 32;
    subject sb;
    cell_ctx x;
    char name[64];
    if (!resolve(c, &sb))
        return;
    view_of(c, v);
    vf[0] = (float)v[0]; vf[1] = (float)v[1]; vf[2] = (float)v[2];
    draw(&sb, n, 0xabcd0000u + (uint64_t)c->salt * 977u + (uint64_t)(c->ax * 1e5), h, buf);
    for (j = 0; j < n; j++) {
        double hx = h[0][j], hy = h[1][j], hz = h[2][j], t = (hx * hx + hy * hy) / (1 + hz);
        s1 += t;
        s2 += t * t;
    }
    x.sb = &sb;
    x.vf = vf;
    x.m1 = x.m2 = 0;
    for (iq = 0; iq < NW; iq++)
        for (ip = 0; ip < NF; ip++)
            gl_q_cell(&GL, a, (double)iq / NW, (double)(iq + 1) / NW, 2 * PI_ * ip / NF, 2 * PI_ * (ip + 1) / NF,
                      moment_node, &x);
    mean = x.m1;
    var = x.m2 - x.m1 * x.m1;
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
    label(c, name, sizeof name);
    printf("| %-22s | %6.4f | %6.4f | %5.1f | mean %.6e vs %.6e (z %+.2f), var %.6e vs %.6e (z %+.2f) |\n",
           name, c->ax, c->ay, c->theta_v, sm, mean, z1, sv, var, z2);
    CHECK(fabs(z1) < 4 && fabs(z2) < 4, "%s alpha %g view %g: moment z-scores %.2f, %.2f", name,
          c->ax, c->theta_v, z1, z2);
}

/* the configurations (golden, per sampler); every sampler of h in the
 * table has at least one */
#define D_ "ggx_sample_d", 0
#define D_ANISO_ "ggx_sample_d_aniso", 1
#define VNDF_ "ggx_sample_vndf", 2
#define VNDF_ANISO_ "ggx_sample_vndf_aniso", 3
#define GTR1_ "gtr_sample_d", 4
#define HEITZ_ "ggx_sample_vndf", 5
static const config chi[] = {
    { D_, 0.05, 0.05, 0, 0, 0, 0 }, { D_, 0.1, 0.1, 0, 0, 0, 0 }, { D_, 0.25, 0.25, 0, 0, 0, 0 },
    { D_, 0.5, 0.5, 0, 0, 0, 0 }, { D_, 0.75, 0.75, 0, 0, 0, 0 }, { D_, 1.0, 1.0, 0, 0, 0, 0 },
    { D_ANISO_, 0.05, 0.3, 0, 0, 0, 0 }, { D_ANISO_, 0.5, 0.1, 0, 0, 0, 0 },
    { VNDF_, 0.05, 0.05, 0, 0, 0, 0 }, { VNDF_, 0.05, 0.05, 45, 0, 0, 0 }, { VNDF_, 0.05, 0.05, 80, 0, 0, 0 },
    { VNDF_, 0.05, 0.05, 89, 0, 0, 0 }, { VNDF_, 0.05, 0.05, 89.9, 0, 0, 0 },
    { VNDF_, 0.2, 0.2, 0, 0, 0, 0 }, { VNDF_, 0.2, 0.2, 60, 0, 0, 0 }, { VNDF_, 0.2, 0.2, 85, 0, 0, 0 },
    { VNDF_, 0.2, 0.2, 89.9, 0, 0, 0 },
    { VNDF_, 0.5, 0.5, 30, 0, 0, 0 }, { VNDF_, 0.5, 0.5, 75, 0, 0, 0 }, { VNDF_, 0.5, 0.5, 89.9, 0, 0, 0 },
    { VNDF_, 1.0, 1.0, 0, 0, 0, 0 }, { VNDF_, 1.0, 1.0, 60, 0, 0, 0 }, { VNDF_, 1.0, 1.0, 89.9, 0, 0, 0 },
    { VNDF_ANISO_, 0.1, 0.4, 60, 0, 0, 0 }, { VNDF_ANISO_, 0.1, 0.4, 85, 0, 0, 0 },
    { VNDF_ANISO_, 0.6, 0.05, 30, 0, 0, 0 }, { VNDF_ANISO_, 0.6, 0.05, 89, 0, 0, 0 },
    { GTR1_, 0.05, 0.05, 0, 0, 1, 0 }, { GTR1_, 0.25, 0.25, 0, 0, 1, 0 }, { GTR1_, 0.5, 0.5, 0, 0, 1, 0 },
    { GTR1_, 1.0, 1.0, 0, 0, 1, 0 },
    { HEITZ_, 0.05, 0.05, 80, 0, 0, 1 }, { HEITZ_, 0.3, 0.3, 60, 0, 0, 1 }, { HEITZ_, 1.0, 1.0, 89.9, 0, 0, 1 },
};
static const config mom[] = {
    { D_, 0.002, 0.002, 0, 0, 0, 0 }, { D_, 0.01, 0.01, 0, 0, 0, 0 }, { D_, 0.03, 0.03, 0, 0, 0, 0 },
    { VNDF_, 0.002, 0.002, 0, 0, 0, 0 }, { VNDF_, 0.01, 0.01, 60, 0, 0, 0 }, { VNDF_, 0.03, 0.03, 89, 0, 0, 0 },
    { GTR1_, 0.005, 0.005, 0, 0, 1, 0 }, { GTR1_, 0.02, 0.02, 0, 0, 1, 0 },
};

/* every sampler of h in the table has a configuration above */
static void check_configured(void)
{
    size_t i, j;
    for (i = 0; i < facet_sampler_count(); i++) {
        const facet_sampler *s = facet_sampler_at(i);
        int found = 0;
        if (!draws_h(s))
            continue;
        for (j = 0; j < sizeof chi / sizeof chi[0]; j++)
            found |= !chi[j].heitz && !strcmp(chi[j].sampler, s->name);
        CHECK(found, "sampler %s draws h but has no chi-square configuration (tests/sample/test_sample_chi2.c, chi[])",
              s->name);
        CHECK(pdf_of_sampler(s) != NULL, "sampler %s has no pdf namesake (_pdf_ for _sample_) in the table", s->name);
    }
}

int main(void)
{
    long n = getenv("FACET_TEST_QUICK") ? 200000 : 1000000, m = n;
    float *h[3], *buf[8];
    size_t i;
    th_name = "sample_chi2";
    gl_make(&GL, GL_N);
    check_configured();
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
        static const config off[] = { { D_, 0.25, 0.25, 0, 0.02, 0, 0 }, { VNDF_, 0.3, 0.3, 60, 0.03, 0, 0 } };
        for (i = 0; i < 2; i++)
            CHECK(chi2_config(&off[i], n, h, buf) < 1e-4, "chi-square test too weak: %s with alpha off by %g%% passes",
                  off[i].sampler, 100 * off[i].mis);
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
