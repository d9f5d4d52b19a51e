/* msim.h - random walks on the Smith microsurface of GGX (a reference tool,
 * double precision, libm; not a kernel).  The model and every formula are
 * stated in bench/microsurface/README.md; msim.c says where each comes from.
 *
 * A run: one material, one incident direction L = (sqrt(1 - nl^2), 0, nl),
 * N paths.  Each path is a random walk that starts above the surface; every
 * scattering event adds, for each requested outgoing direction, the density
 * of leaving the surface there at once (next-event estimation: the facet's
 * lobe times the probability Smith's masking gives of escaping from that
 * height), which estimates the BRDF at exact points; and the walk's own exit
 * direction is binned (the analog estimator: a histogram over cos theta_o and
 * the azimuth, and the directional albedo).  Both are tallied per path into
 * the parts below, so every figure has its Monte Carlo standard error.
 *
 * Deterministic: path i draws from its own splitmix64 stream (seeded from the
 * run's seed, its parameters and i); paths are summed in 64 fixed blocks, in
 * block order, so results are bit-identical for any thread count. */
#ifndef MSIM_H
#define MSIM_H

#include <stdint.h>

enum msim_facet {
    MSIM_LAMBERT = 0, /* Lambertian facets, albedo 1 (k counts bounces)            */
    MSIM_HAMMON = 1,  /* Hammon's facet: Schlick-F weighted mirror + symmetric diffuse */
    MSIM_MIRROR = 2   /* mirror facets with Schlick F (f0 = 1: a white conductor)   */
};

typedef struct {
    int facet;    /* enum msim_facet */
    double alpha; /* GGX width */
    double f0;    /* Schlick's F0 (HAMMON, MIRROR) */
} msim_material;

/* The parts a path's contribution is tallied into.  k = the number of
 * diffuse events on the path (each multiplies by the facet albedo rho when
 * rho < 1: the walk runs at rho = 1 and a result for any rho is
 * sum_k rho^k part_k), n = the number of scattering events. */
enum {
    MSIM_TOTAL = 0, /* everything, rho = 1                          */
    MSIM_SINGLE,    /* n = 1                                         */
    MSIM_MULTI,     /* n >= 2                                        */
    MSIM_SPEC1,     /* k = 0, n = 1: single-bounce specular          */
    MSIM_SPECM,     /* k = 0, n >= 2: multiple-bounce specular       */
    MSIM_DIFF1,     /* k = 1, n = 1: single-bounce diffuse           */
    MSIM_DIFF1M,    /* k = 1, n >= 2 (one diffuse event + specular)   */
    MSIM_K2,        /* k = 2 .. 6: MSIM_K2 + k - 2                   */
    MSIM_K7P = MSIM_K2 + 5, /* k >= 7                                */
    MSIM_D100,      /* diffuse part (k >= 1) at rho = 1              */
    MSIM_D075,      /*                       rho = 0.75               */
    MSIM_D050,      /*                       rho = 0.5                */
    MSIM_D025,      /*                       rho = 0.25               */
    MSIM_NACC
};
extern const char *const msim_acc_name[MSIM_NACC];
extern const double msim_rho[4]; /* the albedos of MSIM_D100 .. MSIM_D025 */

typedef struct {
    double s[MSIM_NACC], q[MSIM_NACC]; /* sum and sum of squares of per-path values */
} msim_acc;

typedef struct {
    double x, y, z;
} msim_v3;

typedef struct {
    msim_material mat;
    double nl;             /* N.L of the incident direction */
    int n_out;             /* next-event directions (upper hemisphere, unit) */
    const msim_v3 *out;
    int nb_mu, nb_phi;     /* analog bins: cos theta_o uniform, azimuth in [0, pi] */
    uint64_t seed, paths;
    int threads;
    int max_events;        /* a path is cut after this many events (counted) */
    int analog;            /* no forced collisions, no roulette (tests) */
    int nee_albedo;        /* also estimate the albedo by next-event estimation
                            * towards one random direction per event */
    /* test hooks: start each path on the surface at a random height (log-CDF
     * l ~ Exp(1)) going in direction start_dir, instead of arriving from L */
    int start_on_surface;
    msim_v3 start_dir;
} msim_run;

typedef struct {
    uint64_t paths;
    msim_acc *nee;    /* [n_out]: BRDF values f(L, out[j]) */
    msim_acc *bins;   /* [nb_mu * nb_phi]: BRDF averaged over the bin (mu-major) */
    msim_acc albedo;  /* directional albedo (escaped energy per path) */
    msim_acc nee_albedo; /* the same by next-event estimation (run->nee_albedo) */
    uint64_t events;  /* scattering events over all paths */
    uint64_t cut;     /* paths cut at max_events */
    double first_escape, first_escape_sq; /* start_on_surface: the weight that left
                             * before a hit (sum and sum of squares over paths) */
} msim_result;

/* runs; fills res (arrays allocated here: msim_free).  0 on success. */
int msim_simulate(const msim_run *run, msim_result *res);
void msim_free(msim_result *res);
/* mean and standard error of part a of an accumulator over res->paths paths,
 * scaled by scale (the bins' solid-angle normalisation) */
double msim_mean(const msim_acc *acc, int a, uint64_t paths);
double msim_se(const msim_acc *acc, int a, uint64_t paths);

/* building blocks, exposed for the tests */
typedef struct {
    uint64_t s;
} msim_rng;
void msim_rng_init(msim_rng *r, uint64_t key, uint64_t index);
double msim_uniform(msim_rng *r); /* in (0, 1), never 0 or 1 */
uint64_t msim_key(const msim_run *run);
/* Smith's Lambda of GGX for a direction with cos theta = z > 0 and
 * |xy|^2 = r2 (0 when z >= 1) */
double msim_lambda(double z, double r2, double alpha);
/* visible-normal sample for any direction w (unit, either hemisphere): m with
 * density <w.m> D(m) / A(w); A(w) = msim_proj_area */
msim_v3 msim_sample_vndf(msim_v3 w, double alpha, double u1, double u2);
double msim_proj_area(msim_v3 w, double alpha);
double msim_ggx_d(msim_v3 h, double alpha); /* D of normalize(h), h any length */
/* the unit direction with cos theta = z and azimuth phi_deg (degrees) from +x */
msim_v3 msim_dir(double z, double phi_deg);
/* the BRDF bin's projected solid angle: integral of cos theta over the bin
 * (both azimuth signs: the bins fold phi and -phi) */
double msim_bin_measure(int i_mu, int nb_mu, int nb_phi);

#endif
