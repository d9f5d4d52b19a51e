/* msim.c - random walks on the Smith microsurface of GGX (msim.h).
 *
 * The microsurface (Smith's model as Walter et al. 2007, appendix A, derive
 * it and Hammon's GDC 2017 appendix retells it; the walk on it as Heitz et
 * al. 2016, "Multiple-scattering microfacet BSDFs with the Smith model"):
 * heights and slopes are independent; the slopes have GGX's distribution
 * P22(p, q) = alpha^2 / (pi (alpha^2 + p^2 + q^2)^2); the heights have any
 * distribution P1 with CDF C1, and only C1 matters, so the state of a walk
 * is l = -ln C1(h) >= 0 (l = 0 at and above the top of the surface; every
 * height distribution gives the same walk in this coordinate).
 *
 * Free paths.  Along a ray of direction d with slope mu = d_z / |d_xy| the
 * chance of meeting the surface in the next dtau, given none so far, is
 * dtau P1(h) mu Lambda(mu) / C1(h) (the slide "PDF of hitting heightfield":
 * the slopes steeper than the ray, weighted by how much steeper).  Per unit
 * height that is Lambda(mu) d ln C1, so, with l:
 *   going up   (d_z > 0): survival from l0 to l < l0 is exp(-Lambda(d) (l0 - l)),
 *              reaching the top (escape) with probability exp(-Lambda(d) l0);
 *   going down (d_z < 0): Lambda(mu) = -1 - Lambda(-d) for negative slopes
 *              (by the symmetry of P2), so survival to l > l0 is
 *              exp(-(1 + Lambda(-d)) (l - l0)): a downward ray always hits.
 * Inverting the survival at a uniform u gives the next height.  A ray from
 * the sky starts at l = 0; the first hit is at l ~ Exp(1 + Lambda(L)).
 * Smith's G1 follows: a random surface point (C1 uniform, l ~ Exp(1)) sees
 * direction o with probability E[exp(-Lambda(o) l)] = 1 / (1 + Lambda(o)); and
 * a single bounce from L to V survives with E over l ~ Exp(1 + Lambda_L) of
 * exp(-Lambda_V l) = (1 + Lambda_L) / (1 + Lambda_L + Lambda_V): the
 * height-correlated G2 over G1(L).  The tests check both.
 *
 * The hit facet.  Given a hit by a ray coming from direction w (= -d), the
 * hit facet's normal has density <w.m> D(m) / A(w) whatever the height
 * (slopes independent of heights), A(w) = integral <w.m> D(m) dm, the area
 * of the microsurface projected along w: w_z (1 + Lambda(w)) for w_z > 0 and
 * |w_z| Lambda(-w) for w_z < 0.  Sampled by stretching (the GGX microsurface
 * with width alpha is the unit hemisphere scaled by 1/alpha in x and y):
 * the visible part of the unit hemisphere seen from the stretched w is, in
 * the plane across w, the half disk on the side of +z plus (w_z > 0) or
 * minus (w_z < 0) half an ellipse of minor axis |w_z|; a uniform point of
 * the disk is mapped linearly, at each abscissa, onto that region, lifted to
 * the hemisphere and unstretched.  (The visible-normal sampler of Heitz 2018
 * does this for w_z > 0; the region's description holds for both signs,
 * which the walk needs: upward rays hit facets from below their horizon.)
 *
 * Facets (Hammon's appendix for his material):
 *   lambert: the outgoing direction is cosine-distributed about m, energy 1.
 *   mirror:  reflection about m, energy times Schlick F(f0, w.m).
 *   hammon:  with probability F = Schlick(f0, w.m) a mirror reflection; else
 *            a diffuse event leaving with density k (1 - (1 - o.m)^5) (o.m),
 *            k = 21 / (20 pi) (the light inside is Lambertian and leaves
 *            through the Fresnel transmittance, normalised so that all of it
 *            leaves): the facet BRDF F delta + (1 - F(w.m)) k (1 - (1 - o.m)^5)
 *            is symmetric in w and o up to the (1 - f0) folded into k.
 * The diffuse events run at albedo 1 and are counted (k in msim.h).
 *
 * Next-event estimation at every event, for each outgoing direction o:
 *   specular: the density of reflecting into o, averaged over the visible
 *     normals, F(w.h) D(h) / (4 A(w)) with h = normalize(w + o) (the Jacobian
 *     of the half vector, 1 / (4 w.h), cancels <w.h>), zero when h_z <= 0;
 *   diffuse: with the sampled m, (1 - F(w.m)) times the lobe above (or
 *     (o.m) / pi for lambert), zero when o.m <= 0;
 * each times exp(-Lambda(o) l), the escape from this height.  Summed over
 * the path's events this estimates the density of exiting towards o per
 * unit solid angle; over cos theta_o it is the BRDF.  Three devices keep its
 * variance finite on smooth surfaces (walk, nee_mis): upward flights are
 * forced to collide (the escape is tallied with its probability), Russian
 * roulette follows each event's estimates, and a mirror reflection into o
 * right after another event is also sampled from o's side (h ~ D h_z) and
 * the two combined by the balance heuristic.  What remains is the
 * asymmetry of the estimator: towards a grazing o from a steep L the
 * important paths pass through grazing segments that are rare from L, so
 * the tables take each (L, V) pair from the run at the more grazing of the
 * two (README.md, "Tables"). */
#include "msim.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define MSIM_BLOCKS 64

const char *const msim_acc_name[MSIM_NACC] = {
    "total", "single", "multi", "spec1", "specm", "diff1", "diff1m", "k2", "k3", "k4", "k5", "k6",
    "k7p",   "d100",   "d075",  "d050",  "d025"};
const double msim_rho[4] = {1.0, 0.75, 0.5, 0.25};

/* ---- random numbers: splitmix64 (Steele, Lea, Flood 2014) ---------------- */
static uint64_t mix64(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

void msim_rng_init(msim_rng *r, uint64_t key, uint64_t index)
{
    r->s = mix64(key ^ mix64(index * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull));
}

double msim_uniform(msim_rng *r)
{
    r->s += 0x9E3779B97F4A7C15ull;
    return ((double)(mix64(r->s) >> 11) + 0.5) * 0x1p-53;
}

static uint64_t bits(double x)
{
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    return b;
}

/* the run's stream key: its seed and the parameters that define the point,
 * so a point's paths do not depend on what else a table holds */
uint64_t msim_key(const msim_run *run)
{
    uint64_t k = mix64(run->seed + 0x2545F4914F6CDD1Dull);
    k = mix64(k ^ (uint64_t)run->mat.facet);
    k = mix64(k ^ bits(run->mat.alpha));
    k = mix64(k ^ bits(run->mat.f0));
    k = mix64(k ^ bits(run->nl));
    if (run->start_on_surface) {
        k = mix64(k ^ bits(run->start_dir.x));
        k = mix64(k ^ bits(run->start_dir.y));
        k = mix64(k ^ bits(run->start_dir.z));
    }
    return k;
}

/* ---- geometry ------------------------------------------------------------ */
static msim_v3 v3(double x, double y, double z)
{
    msim_v3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}
static double dot(msim_v3 a, msim_v3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static msim_v3 normalize(msim_v3 a)
{
    double r = 1.0 / sqrt(dot(a, a));
    return v3(a.x * r, a.y * r, a.z * r);
}
static msim_v3 cross(msim_v3 a, msim_v3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

/* Lambda(z) = (sqrt(1 + alpha^2 tan^2) - 1) / 2 = a2 r2 / (2 z (s + z)),
 * s = sqrt(z^2 + a2 r2): the second form keeps its precision when alpha is small */
double msim_lambda(double z, double r2, double alpha)
{
    double a2r2 = alpha * alpha * r2;
    if (a2r2 <= 0.0)
        return 0.0;
    return a2r2 / (2.0 * z * (sqrt(z * z + a2r2) + z));
}

double msim_proj_area(msim_v3 w, double alpha)
{
    /* |w_z| Lambda = a2 r2 / (2 (s + |w_z|)): finite at the horizon (alpha |w_xy| / 2) */
    double r2 = w.x * w.x + w.y * w.y, z = fabs(w.z), a2r2 = alpha * alpha * r2;
    double zl = a2r2 > 0.0 ? a2r2 / (2.0 * (sqrt(z * z + a2r2) + z)) : 0.0;
    return w.z > 0.0 ? w.z + zl : zl;
}

msim_v3 msim_dir(double z, double phi_deg)
{
    double s = sqrt(fmax(0.0, 1.0 - z * z)), p = phi_deg * PI / 180.0;
    return z >= 1.0 ? v3(0.0, 0.0, 1.0) : v3(s * cos(p), s * sin(p), z);
}

double msim_ggx_d(msim_v3 h, double alpha)
{
    /* alpha^2 / (pi (alpha^2 cos^2 + sin^2)^2) with cos^2 = hz^2 / |h|^2 */
    double a2 = alpha * alpha, hz2 = h.z * h.z, hxy2 = h.x * h.x + h.y * h.y;
    double e = a2 * hz2 + hxy2, hh = hz2 + hxy2;
    if (h.z <= 0.0)
        return 0.0;
    return a2 * hh * hh / (PI * e * e);
}

msim_v3 msim_sample_vndf(msim_v3 w, double alpha, double u1, double u2)
{
    msim_v3 ws = normalize(v3(alpha * w.x, alpha * w.y, w.z)), t1v, t2v, nh;
    double rxy2 = ws.x * ws.x + ws.y * ws.y, r, ph, t1, t2, s, t3;
    if (rxy2 > 0.0) {
        double ir = 1.0 / sqrt(rxy2);
        t1v = v3(-ws.y * ir, ws.x * ir, 0.0);
    } else {
        t1v = v3(1.0, 0.0, 0.0);
    }
    t2v = cross(ws, t1v); /* t2v_z = |ws_xy| >= 0: the +z side of the plane across ws */
    r = sqrt(u1);
    ph = 2.0 * PI * u2;
    t1 = r * cos(ph);
    t2 = r * sin(ph);
    /* map t2 in [-h, h] linearly onto [-ws_z h, h], h = sqrt(1 - t1^2):
     * the visible region's chord at abscissa t1 */
    s = 0.5 * (1.0 + ws.z);
    t2 = (1.0 - s) * sqrt(fmax(0.0, 1.0 - t1 * t1)) + s * t2;
    t3 = sqrt(fmax(0.0, 1.0 - t1 * t1 - t2 * t2));
    nh = v3(t1 * t1v.x + t2 * t2v.x + t3 * ws.x, t1 * t1v.y + t2 * t2v.y + t3 * ws.y,
            t1 * t1v.z + t2 * t2v.z + t3 * ws.z);
    return normalize(v3(alpha * nh.x, alpha * nh.y, fmax(nh.z, 1e-300)));
}

/* a direction about m with density (o.m) / pi */
static msim_v3 sample_cosine(msim_v3 m, double u1, double u2)
{
    msim_v3 b1, b2;
    double r = sqrt(u1), ph = 2.0 * PI * u2, x = r * cos(ph), y = r * sin(ph);
    double z = sqrt(fmax(0.0, 1.0 - u1));
    /* an orthonormal basis about m (Duff et al. 2017's branchless form) */
    double sg = m.z >= 0.0 ? 1.0 : -1.0, a = -1.0 / (sg + m.z), b = m.x * m.y * a;
    b1 = v3(1.0 + sg * m.x * m.x * a, sg * b, -sg * m.x);
    b2 = v3(b, sg + m.y * m.y * a, -m.y);
    return v3(x * b1.x + y * b2.x + z * m.x, x * b1.y + y * b2.y + z * m.y,
              x * b1.z + y * b2.z + z * m.z);
}

static double pow5(double x)
{
    double x2 = x * x;
    return x2 * x2 * x;
}
static double schlick(double f0, double c)
{
    return f0 + (1.0 - f0) * pow5(1.0 - c);
}

double msim_bin_measure(int i_mu, int nb_mu, int nb_phi)
{
    double m0 = (double)i_mu / nb_mu, m1 = (double)(i_mu + 1) / nb_mu;
    /* integral of mu over mu in [m0, m1] and |phi| in the bin: (m1^2 - m0^2) / 2 * 2 dphi */
    return 0.5 * (m1 * m1 - m0 * m0) * 2.0 * (PI / nb_phi);
}

/* ---- the walk ------------------------------------------------------------ */
#define KMAX 64 /* rho^k table length; higher k use rho^(KMAX-1) (never reached in practice) */

typedef struct {
    const msim_run *run;
    uint64_t key;
    double *lam_out;       /* Lambda of each next-event direction */
    double rho_pow[4][KMAX];
    volatile int next_block;
    pthread_mutex_t lock;
    /* per block results */
    msim_acc *blk_nee, *blk_bins, *blk_albedo, *blk_nee_alb;
    uint64_t *blk_events, *blk_cut;
    double (*blk_first)[2];
} ctx;

static void record(const ctx *c, double *row, double x, int k, int n)
{
    row[MSIM_TOTAL] += x;
    row[n == 1 ? MSIM_SINGLE : MSIM_MULTI] += x;
    if (k == 0) {
        row[n == 1 ? MSIM_SPEC1 : MSIM_SPECM] += x;
    } else {
        int kk = k < KMAX ? k : KMAX - 1, j;
        if (k == 1)
            row[n == 1 ? MSIM_DIFF1 : MSIM_DIFF1M] += x;
        else
            row[MSIM_K2 + (k < 7 ? k : 7) - 2] += x;
        for (j = 0; j < 4; j++)
            row[MSIM_D100 + j] += c->rho_pow[j][kk] * x;
    }
}

static void acc_add_first(double *f, double x)
{
    f[0] += x;
    f[1] += x * x;
}

static void acc_add_row(msim_acc *a, const double *row)
{
    int i;
    for (i = 0; i < MSIM_NACC; i++) {
        a->s[i] += row[i];
        a->q[i] += row[i] * row[i];
    }
}

#define K21 (21.0 / (20.0 * PI)) /* Hammon's diffuse lobe normalisation */

/* the density of leaving a Hammon facet with F(w.m) = f diffusely at
 * cos(o, m) = c, per unit solid angle (the choice's probability 1 - f included) */
static double hammon_lobe(double f, double c)
{
    return c > 0.0 ? (1.0 - f) * K21 * (1.0 - pow5(1.0 - c)) * c : 0.0;
}

/* the event just before this one, for the weight of the specular estimate
 * (see nee_mis): the density with which the walk drew the segment since */
typedef struct {
    int kind;     /* 0: none (first event), 1: diffuse (Hammon's facet), 2: mirror */
    msim_v3 m;    /* kind 1: its facet */
    double f;     /* kind 1: its F(w.m) */
    double q;     /* kind 2: the segment's density, (F) D(m) / (4 A(w)) */
} prev_event;

/* the walk's density of the segment d from the previous event (msim.c's
 * head: the mirror's D(h) / (4 A(w)) times F where F chooses the branch) */
static double prev_density(const prev_event *pe, msim_v3 d)
{
    return pe->kind == 1 ? hammon_lobe(pe->f, dot(d, pe->m)) : pe->q;
}

/* next-event estimate at one event towards o (unit, upward; lam_o = its
 * Lambda): the specular lobe averaged over the visible normals (analytic),
 * the diffuse lobe of the sampled facet m, each times the escape from l.
 * After another event the specular part is weighted by the balance
 * heuristic against nee_mis's estimate of the same paths. */
static void nee(const ctx *c, double *row, msim_v3 w, msim_v3 m, double f, double area, double l,
                msim_v3 o, double lam_o, double beta, int k, int n, const prev_event *pe)
{
    const msim_material *mat = &c->run->mat;
    double esc = exp(-lam_o * l), om;
    if (esc <= 0.0)
        return;
    if (mat->facet != MSIM_LAMBERT && area > 0.0) {
        msim_v3 h = v3(w.x + o.x, w.y + o.y, w.z + o.z);
        if (h.z > 0.0) {
            double hl = sqrt(dot(h, h)), wh = 0.5 * hl, dh = msim_ggx_d(h, mat->alpha);
            double ph = schlick(mat->f0, wh) * dh / (4.0 * area);
            if (pe->kind) {
                double q1 = prev_density(pe, v3(-w.x, -w.y, -w.z)), q2 = dh * (h.z / hl) / (4.0 * wh);
                ph = q1 + q2 > 0.0 ? ph * q1 / (q1 + q2) : 0.0;
            }
            if (ph > 0.0)
                record(c, row, beta * ph * esc, k, n);
        }
    }
    om = dot(o, m);
    if (om > 0.0) {
        if (mat->facet == MSIM_LAMBERT)
            record(c, row, beta * om / PI * esc, k + 1, n);
        else if (mat->facet == MSIM_HAMMON)
            record(c, row, beta * hammon_lobe(f, om) * esc, k + 1, n);
    }
}

/* The paths "an event here, then a mirror reflection into o": the walk
 * samples the segment between them from this event's lobe and estimates the
 * reflection at the next event (nee), whose value D(h) / (4 A(w)) peaks
 * like 1 / alpha^2 over a cone of width alpha: on a smooth surface such
 * segments are rare, and the estimate's variance grows like 1 / alpha (the
 * tables' reciprocity check found the diffuse part 10% low at alpha = 2^-6,
 * grazing V).  Here the same paths are sampled the other way: h from
 * D(h) h_z, the segment as the reflection of o about h, the next height from
 * the free path; the value over the sum of the two densities of that
 * segment (the balance heuristic; the peak cancels), once for each branch
 * of this event (Hammon's diffuse lobe given the sampled facet m; the
 * mirror, whose segment density is D(h') / (4 A(w)) over all facets, times
 * F(w.h') when F chooses the branch).  h (unit) and d_h = D(h) are shared by
 * all o; u is the free path's uniform. */
static void nee_mis(const ctx *c, double *row, msim_v3 w, double area, msim_v3 m, double f, double l,
                    msim_v3 o, double lam_o, double beta, int k, int n, msim_v3 h, double d_h, double u)
{
    const msim_material *mat = &c->run->mat;
    double oh = dot(o, h), q2, hit, lj, aj, g;
    msim_v3 wj, d, h1;
    if (oh <= 0.0)
        return;
    wj = v3(2.0 * oh * h.x - o.x, 2.0 * oh * h.y - o.y, 2.0 * oh * h.z - o.z);
    d = v3(-wj.x, -wj.y, -wj.z);
    q2 = d_h * h.z / (4.0 * oh);
    if (d.z > 0.0) {
        double lam = msim_lambda(d.z, d.x * d.x + d.y * d.y, mat->alpha);
        hit = lam > 0.0 ? -expm1(-lam * l) : 0.0;
        if (hit <= 0.0)
            return;
        lj = fmax(0.0, l + log1p(-u * hit) / lam);
    } else if (d.z < 0.0) {
        double lam = msim_lambda(-d.z, d.x * d.x + d.y * d.y, mat->alpha);
        hit = 1.0;
        lj = l - log(u) / (1.0 + lam);
    } else {
        return;
    }
    aj = msim_proj_area(wj, mat->alpha);
    if (aj <= 0.0)
        return;
    /* the value at the next event: reaching it, reflecting into o, escaping */
    g = beta * hit * schlick(mat->f0, oh) * d_h / (4.0 * aj) * exp(-lam_o * lj);
    if (!(g > 0.0))
        return;
    if (mat->facet == MSIM_HAMMON) {
        double e = hammon_lobe(f, dot(d, m));
        if (e > 0.0)
            record(c, row, e * g / (e + q2), k + 1, n + 1);
    }
    h1 = v3(w.x + d.x, w.y + d.y, w.z + d.z);
    if (h1.z > 0.0 && area > 0.0) {
        double hl = sqrt(dot(h1, h1)), f1 = schlick(mat->f0, 0.5 * hl);
        double q1 = msim_ggx_d(h1, mat->alpha) / (4.0 * area), e = f1 * q1;
        if (mat->facet == MSIM_HAMMON)
            q1 = e;
        if (e > 0.0)
            record(c, row, e * g / (q1 + q2), k, n + 1);
    }
}

/* a path's exits: the bins it left through, each with its row of parts */
typedef struct {
    int n, cap;
    int *bin;
    double *row; /* [cap][MSIM_NACC] */
} exits;

static int bin_of(const msim_run *run, msim_v3 d)
{
    int im = (int)(d.z * run->nb_mu), ip;
    double ph = atan2(fabs(d.y), d.x); /* [0, pi]: phi and -phi share a bin */
    if (im >= run->nb_mu)
        im = run->nb_mu - 1;
    ip = (int)(ph / PI * run->nb_phi);
    if (ip >= run->nb_phi)
        ip = run->nb_phi - 1;
    return im * run->nb_phi + ip;
}

static void exit_record(const ctx *c, exits *e, double *esc_row, msim_v3 d, double x, int k, int n)
{
    const msim_run *run = c->run;
    int b, i;
    record(c, esc_row, x, k, n);
    if (run->nb_mu <= 0)
        return;
    b = bin_of(run, d);
    for (i = 0; i < e->n && e->bin[i] != b; i++)
        ;
    if (i == e->n) {
        if (e->n == e->cap)
            return; /* never: cap = max_events + 2 exits per path */
        e->bin[i] = b;
        memset(e->row + (size_t)i * MSIM_NACC, 0, MSIM_NACC * sizeof *e->row);
        e->n++;
    }
    record(c, e->row + (size_t)i * MSIM_NACC, x, k, n);
}

#define RR_MIN 0.125 /* Russian roulette below this throughput (after the event's estimates) */

/* one path: NEE into nee_row[n_out][NACC] (and alb_row), its exits into
 * esc_row and ex; returns the number of events.
 * Upward flights are forced to collide (unless run->analog): the escape
 * probability 1 - P is recorded as an exit of weight beta (1 - P), the hit
 * height is drawn given a hit and beta is multiplied by P.  Without this a
 * ray leaving steeply on a smooth surface hits again with probability
 * ~ Lambda l, and the estimate at that event, ~ 1 / A(w) ~ 1 / Lambda, makes
 * the variance grow like 1 / Lambda (the tables' reciprocity check caught
 * it at alpha = 2^-6).  Russian roulette comes after the event's estimates,
 * so it adds no such tail. */
static int walk(const ctx *c, msim_rng *rng, double *nee_row, double *alb_row, double *esc_row, exits *ex,
                int *cut, double *first_escape)
{
    const msim_run *run = c->run;
    const msim_material *mat = &run->mat;
    const double alpha = mat->alpha;
    msim_v3 d;
    double l, beta = 1.0;
    int n = 0, k = 0, j;
    prev_event pe;
    pe.kind = 0;
    ex->n = 0;
    *cut = 0;
    *first_escape = 0;
    if (run->start_on_surface) {
        d = run->start_dir;
        l = -log(msim_uniform(rng));
    } else {
        double nl = run->nl;
        d = v3(-sqrt(fmax(0.0, 1.0 - nl * nl)), 0.0, -nl);
        l = 0.0;
    }
    for (;;) {
        msim_v3 w, m, o;
        double u = msim_uniform(rng), wm, f;
        /* the next height along d */
        if (d.z > 0.0) {
            double lam = msim_lambda(d.z, d.x * d.x + d.y * d.y, alpha);
            if (run->analog) {
                double lnew = lam > 0.0 ? l + log(u) / lam : -1.0;
                if (lnew <= 0.0) { /* escaped */
                    if (n == 0)
                        *first_escape = 1.0;
                    else
                        exit_record(c, ex, esc_row, d, beta, k, n);
                    return n;
                }
                l = lnew;
            } else {
                double p = lam > 0.0 ? -expm1(-lam * l) : 0.0; /* the chance of another hit */
                if (n == 0)
                    *first_escape = 1.0 - p;
                else if (p < 1.0)
                    exit_record(c, ex, esc_row, d, beta * (1.0 - p), k, n);
                if (p <= 0.0)
                    return n;
                l = fmax(0.0, l + log1p(-u * p) / lam);
                beta *= p;
            }
        } else if (d.z < 0.0) {
            double lam = msim_lambda(-d.z, d.x * d.x + d.y * d.y, alpha);
            l = l - log(u) / (1.0 + lam);
        } /* d.z == 0: hits at once (infinite hazard), l unchanged */
        if (n >= run->max_events) {
            *cut = 1;
            return n;
        }
        n++;
        w = v3(-d.x, -d.y, -d.z);
        {
            /* drawn in sequence (the order of a call's arguments is unspecified:
             * gcc and clang differ): u2 first, the order these tables were made with */
            double u2 = msim_uniform(rng), u1 = msim_uniform(rng);
            m = msim_sample_vndf(w, alpha, u1, u2);
        }
        wm = dot(w, m);
        if (wm < 0.0)
            wm = 0.0;
        f = mat->facet == MSIM_LAMBERT ? 0.0 : schlick(mat->f0, wm);
        /* next-event estimation towards every requested direction */
        if (run->n_out > 0 || run->nee_albedo) {
            double area = mat->facet != MSIM_LAMBERT ? msim_proj_area(w, alpha) : 0.0;
            msim_v3 hs = v3(0.0, 0.0, 1.0), ro = v3(0.0, 0.0, 1.0);
            double dhs = 0.0, um = 0.5;
            int mis = mat->facet != MSIM_LAMBERT;
            if (mis) { /* h ~ D(h) h_z for nee_mis: tan^2 = alpha^2 u / (1 - u) */
                double u1 = msim_uniform(rng), ph = 2.0 * PI * msim_uniform(rng);
                double t2 = alpha * alpha * u1 / (1.0 - u1), ch = 1.0 / sqrt(1.0 + t2), sh = sqrt(t2) * ch;
                hs = v3(sh * cos(ph), sh * sin(ph), ch);
                dhs = msim_ggx_d(hs, alpha);
                um = msim_uniform(rng);
            }
            for (j = 0; j < run->n_out; j++) {
                double *row = nee_row + (size_t)j * MSIM_NACC;
                nee(c, row, w, m, f, area, l, run->out[j], c->lam_out[j], beta, k, n, &pe);
                if (mis)
                    nee_mis(c, row, w, area, m, f, l, run->out[j], c->lam_out[j], beta, k, n, hs, dhs, um);
            }
            if (run->nee_albedo) {
                /* one random direction, density mu / pi: an unbiased estimate of the
                 * integral of the exit density over the hemisphere */
                double u1 = msim_uniform(rng), u2 = msim_uniform(rng), r = sqrt(u1), ph = 2.0 * PI * u2;
                double row[MSIM_NACC] = {0}, lam;
                int a;
                ro = v3(r * cos(ph), r * sin(ph), sqrt(fmax(0.0, 1.0 - u1)));
                lam = msim_lambda(ro.z, ro.x * ro.x + ro.y * ro.y, alpha);
                if (ro.z > 0.0) {
                    nee(c, row, w, m, f, area, l, ro, lam, beta, k, n, &pe);
                    if (mis)
                        nee_mis(c, row, w, area, m, f, l, ro, lam, beta, k, n, hs, dhs, um);
                    for (a = 0; a < MSIM_NACC; a++)
                        alb_row[a] += row[a] * PI / ro.z;
                }
            }
        }
        /* continue the walk */
        if (mat->facet == MSIM_MIRROR) {
            beta *= f;
            o = v3(2.0 * wm * m.x - w.x, 2.0 * wm * m.y - w.y, 2.0 * wm * m.z - w.z);
            pe.kind = 2;
            pe.q = msim_ggx_d(m, alpha) / (4.0 * msim_proj_area(w, alpha));
        } else if (mat->facet == MSIM_HAMMON && msim_uniform(rng) < f) {
            o = v3(2.0 * wm * m.x - w.x, 2.0 * wm * m.y - w.y, 2.0 * wm * m.z - w.z);
            pe.kind = 2;
            pe.q = f * msim_ggx_d(m, alpha) / (4.0 * msim_proj_area(w, alpha));
        } else if (mat->facet == MSIM_HAMMON) {
            /* the lobe (1 - (1 - o.m)^5)(o.m): cosine samples kept with
             * probability 1 - (1 - o.m)^5 (20/21 of them on average) */
            for (;;) {
                double u1 = msim_uniform(rng), u2 = msim_uniform(rng);
                double om = sqrt(fmax(0.0, 1.0 - u1));
                o = sample_cosine(m, u1, u2);
                if (msim_uniform(rng) < 1.0 - pow5(1.0 - om))
                    break;
            }
            pe.kind = 1;
            pe.m = m;
            pe.f = f;
            k++;
        } else {
            double u1 = msim_uniform(rng), u2 = msim_uniform(rng);
            o = sample_cosine(m, u1, u2);
            k++;
        }
        if (beta <= 0.0)
            return n;
        if (!run->analog && beta < RR_MIN) {
            if (msim_uniform(rng) * RR_MIN >= beta)
                return n;
            beta = RR_MIN;
        }
        d = normalize(o);
    }
}

static void run_block(ctx *c, int b)
{
    const msim_run *run = c->run;
    uint64_t i0 = run->paths * (uint64_t)b / MSIM_BLOCKS, i1 = run->paths * (uint64_t)(b + 1) / MSIM_BLOCKS, i;
    size_t nrow = (size_t)run->n_out * MSIM_NACC;
    double *nee_row = calloc(nrow ? nrow : 1, sizeof *nee_row);
    double esc_row[MSIM_NACC], alb_row[MSIM_NACC];
    msim_acc *nee_acc = c->blk_nee + (size_t)b * run->n_out;
    msim_acc *bins = c->blk_bins + (size_t)b * run->nb_mu * run->nb_phi;
    msim_acc *alb = c->blk_albedo + b;
    exits ex;
    ex.cap = run->max_events + 2;
    ex.bin = calloc((size_t)ex.cap, sizeof *ex.bin);
    ex.row = calloc((size_t)ex.cap * MSIM_NACC, sizeof *ex.row);
    for (i = i0; i < i1; i++) {
        msim_rng rng;
        int cut, j, n;
        double first;
        msim_rng_init(&rng, c->key, i);
        memset(nee_row, 0, nrow * sizeof *nee_row);
        memset(esc_row, 0, sizeof esc_row);
        memset(alb_row, 0, sizeof alb_row);
        n = walk(c, &rng, nee_row, alb_row, esc_row, &ex, &cut, &first);
        c->blk_events[b] += (uint64_t)n;
        c->blk_cut[b] += (uint64_t)cut;
        acc_add_first(c->blk_first[b], first);
        for (j = 0; j < run->n_out; j++)
            acc_add_row(&nee_acc[j], nee_row + (size_t)j * MSIM_NACC);
        acc_add_row(alb, esc_row);
        if (run->nee_albedo)
            acc_add_row(c->blk_nee_alb + b, alb_row);
        for (j = 0; j < ex.n; j++)
            acc_add_row(&bins[ex.bin[j]], ex.row + (size_t)j * MSIM_NACC);
    }
    free(ex.bin);
    free(ex.row);
    free(nee_row);
}

static void *worker(void *arg)
{
    ctx *c = arg;
    for (;;) {
        int b;
        pthread_mutex_lock(&c->lock);
        b = c->next_block++;
        pthread_mutex_unlock(&c->lock);
        if (b >= MSIM_BLOCKS)
            return NULL;
        run_block(c, b);
    }
}

static void acc_sum(msim_acc *dst, const msim_acc *src)
{
    int i;
    for (i = 0; i < MSIM_NACC; i++) {
        dst->s[i] += src->s[i];
        dst->q[i] += src->q[i];
    }
}

int msim_simulate(const msim_run *run, msim_result *res)
{
    ctx c;
    int nb = run->nb_mu * run->nb_phi, b, j, t, nt = run->threads > 0 ? run->threads : 1;
    pthread_t th[64];
    memset(res, 0, sizeof *res);
    memset(&c, 0, sizeof c);
    if (run->n_out < 0 || nb < 0 || run->paths == 0 || nt > 64)
        return -1;
    c.run = run;
    c.key = msim_key(run);
    c.lam_out = calloc((size_t)run->n_out + 1, sizeof *c.lam_out);
    for (j = 0; j < run->n_out; j++) {
        msim_v3 o = run->out[j];
        c.lam_out[j] = msim_lambda(o.z, o.x * o.x + o.y * o.y, run->mat.alpha);
    }
    for (j = 0; j < 4; j++) {
        int k;
        double p = 1.0;
        for (k = 0; k < KMAX; k++) {
            c.rho_pow[j][k] = p;
            p *= msim_rho[j];
        }
    }
    c.blk_nee = calloc((size_t)MSIM_BLOCKS * run->n_out + 1, sizeof *c.blk_nee);
    c.blk_bins = calloc((size_t)MSIM_BLOCKS * nb + 1, sizeof *c.blk_bins);
    c.blk_albedo = calloc(MSIM_BLOCKS, sizeof *c.blk_albedo);
    c.blk_nee_alb = calloc(MSIM_BLOCKS, sizeof *c.blk_nee_alb);
    c.blk_events = calloc(MSIM_BLOCKS, sizeof *c.blk_events);
    c.blk_cut = calloc(MSIM_BLOCKS, sizeof *c.blk_cut);
    c.blk_first = calloc(MSIM_BLOCKS, sizeof *c.blk_first);
    pthread_mutex_init(&c.lock, NULL);
    if (nt == 1) {
        worker(&c);
    } else {
        for (t = 0; t < nt; t++)
            pthread_create(&th[t], NULL, worker, &c);
        for (t = 0; t < nt; t++)
            pthread_join(th[t], NULL);
    }
    pthread_mutex_destroy(&c.lock);
    /* in block order: the same sums for any thread count */
    res->paths = run->paths;
    res->nee = calloc((size_t)run->n_out + 1, sizeof *res->nee);
    res->bins = calloc((size_t)nb + 1, sizeof *res->bins);
    for (b = 0; b < MSIM_BLOCKS; b++) {
        for (j = 0; j < run->n_out; j++)
            acc_sum(&res->nee[j], &c.blk_nee[(size_t)b * run->n_out + j]);
        for (j = 0; j < nb; j++)
            acc_sum(&res->bins[j], &c.blk_bins[(size_t)b * nb + j]);
        acc_sum(&res->albedo, &c.blk_albedo[b]);
        acc_sum(&res->nee_albedo, &c.blk_nee_alb[b]);
        res->events += c.blk_events[b];
        res->cut += c.blk_cut[b];
        res->first_escape += c.blk_first[b][0];
        res->first_escape_sq += c.blk_first[b][1];
    }
    free(c.lam_out);
    free(c.blk_nee);
    free(c.blk_bins);
    free(c.blk_albedo);
    free(c.blk_nee_alb);
    free(c.blk_events);
    free(c.blk_cut);
    free(c.blk_first);
    return 0;
}

void msim_free(msim_result *res)
{
    free(res->nee);
    free(res->bins);
    res->nee = res->bins = NULL;
}

double msim_mean(const msim_acc *acc, int a, uint64_t paths)
{
    return acc->s[a] / (double)paths;
}

double msim_se(const msim_acc *acc, int a, uint64_t paths)
{
    double n = (double)paths, m = acc->s[a] / n, v = acc->q[a] / n - m * m;
    return n > 1.0 && v > 0.0 ? sqrt(v / (n - 1.0)) : 0.0;
}
