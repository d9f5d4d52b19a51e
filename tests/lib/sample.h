/* sample.h - input generators shared by the tests and the benchmarks:
 * a seeded PRNG and samplers that aim at the hard parts of each input's
 * domain (specular peak, grazing angles, L.V near +-1, 0 and 1). */
#ifndef FACET_TEST_SAMPLE_H
#define FACET_TEST_SAMPLE_H

#include <stdint.h>
#include <string.h>
#include <math.h>
#include "facet.h"
#include "../../src/core/kernel_list.h"

typedef struct { uint64_t s; } smp_rng;

static inline uint64_t smp_next(smp_rng *r) /* splitmix64 */
{
    uint64_t z = (r->s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static inline double smp_u01(smp_rng *r) { return (smp_next(r) >> 11) * (1.0 / 9007199254740992.0); }

/* the index of name among names[0 .. n - 1] (a kernel's or a sampler's
 * inputs), or -1 */
static inline int smp_name_index(const char *const *names, int n, const char *name)
{
    int i;
    for (i = 0; i < n; i++)
        if (!strcmp(names[i], name))
            return i;
    return -1;
}

/* a seed from a kernel's name (FNV-1a): a test seeded so per kernel draws
 * the same samples when kernels are added to the list */
static inline uint64_t smp_name_seed(const char *name)
{
    uint64_t h = 0xcbf29ce484222325ull;
    for (; *name; name++)
        h = (h ^ (unsigned char)*name) * 0x100000001b3ull;
    return h;
}

/* The error measure's floor (facet.h): a result is judged relative to
 * max(|oracle|, floor), the larger floor on a port that flushes denormals */
#define SMP_ERR_FLOOR 0x1p-100
#define SMP_ERR_FLOOR_FTZ 0x1p-60

/* Does the active port flush denormal inputs to zero (armv7 NEON and Helium do)?
 * Probed, not assumed: lambert(1e-39) is 0 only if the input was flushed. */
static inline int smp_port_flushes_denormals(void)
{
    float in = 1e-39f, out = 1.0f;
    facet_lambert_f32_batch(&out, &in, 1);
    return out == 0.0f;
}

/* log-uniform in [2^lo, 2^hi] */
static inline double smp_log2u(smp_rng *r, double lo, double hi) { return exp2(lo + (hi - lo) * smp_u01(r)); }

/* A pair (L, V) over N = z: writes N.L, N.V, L.V rounded to float. */
static inline void smp_geometry(smp_rng *r, float *nl, float *nv, float *lv)
{
    double cl, cv, phi, sl, sv;
    unsigned mode = (unsigned)(smp_next(r) % 8);
    switch (mode) {
    case 0: /* near the specular peak: mirror azimuth, nearly equal angles */
    case 1:
        cl = smp_u01(r);
        cv = cl + (smp_u01(r) - 0.5) * smp_log2u(r, -30, -3);
        phi = M_PI + (smp_u01(r) - 0.5) * smp_log2u(r, -30, -2);
        break;
    case 2: /* grazing L or V */
        cl = smp_log2u(r, -20, -1);
        cv = (smp_next(r) & 1) ? smp_log2u(r, -20, 0) : smp_u01(r);
        phi = 2 * M_PI * smp_u01(r);
        break;
    case 3: /* L.V near +1: L close to V */
        cl = smp_u01(r);
        cv = cl + (smp_u01(r) - 0.5) * smp_log2u(r, -30, -4);
        phi = (smp_u01(r) - 0.5) * smp_log2u(r, -30, -4);
        break;
    default: /* uniform in cosines and azimuth */
        cl = smp_u01(r);
        cv = smp_u01(r);
        phi = 2 * M_PI * smp_u01(r);
        break;
    }
    cl = fmin(fmax(cl, FACET_COS_MIN), 1.0);
    cv = fmin(fmax(cv, FACET_COS_MIN), 1.0);
    sl = sqrt(1 - cl * cl);
    sv = sqrt(1 - cv * cv);
    *nl = (float)cl;
    *nv = (float)cv;
    *lv = (float)fmin(fmax(cl * cv + sl * sv * cos(phi), -1.0), 1.0);
}

static inline float smp_alpha(smp_rng *r)
{
    return (float)smp_log2u(r, -10, 0);
}

/* a [0, 1] value: often 0, 1, tiny, or near 1 */
static inline float smp_unit(smp_rng *r)
{
    switch (smp_next(r) % 8) {
    case 0: return 0.0f;
    case 1: return 1.0f;
    case 2: return (float)smp_log2u(r, -40, 0);
    case 3: return (float)(1.0 - smp_log2u(r, -24, -1));
    default: return (float)smp_u01(r);
    }
}

/* The low end of input i's domain (facet.h): -1 for L.V, T.H and B.H,
 * alpha_min for alpha (alpha_x, alpha_y), FACET_COS_MIN for N.L / N.V of the
 * two-cosine kernels (those with an N.L), else 0; the high end (smp_domain_hi) is 4 for the GTR
 * tail gamma and 1 for every other input. */
/* a two-cosine kernel: it takes N.L (and N.V); a kernel of N.V alone
 * (smith_g1, smith_g1_gtr) takes N.V in [0, 1] */
static inline int smp_two_cos(const facet_kernel *k)
{
    return !strcmp(k->inputs[0], "nol");
}

/* each input's domain class, as src/core/kernels.def gives it (COS: the cosine
 * floor FACET_COS_MIN; UNIT: 0; ...) */
#define SMP_DOMAIN_CLASS_(input, domain) #domain
static const struct smp_domains_ {
    const char *name, *cls[FACET_MAX_INPUTS];
} smp_domains_[] = {
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    { #name, { FACET_MAP_INPUTS(n, SMP_DOMAIN_CLASS_, __VA_ARGS__) } },
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
};

static inline const char *smp_domain_class(const facet_kernel *k, int i)
{
    size_t j;
    for (j = 0; j < sizeof smp_domains_ / sizeof smp_domains_[0]; j++)
        if (!strcmp(smp_domains_[j].name, k->name))
            return smp_domains_[j].cls[i];
    return "UNIT";
}

static inline float smp_domain_lo(const facet_kernel *k, int i)
{
    const char *n = k->inputs[i], *c = smp_domain_class(k, i);
    if (!strcmp(n, "lov") || !strcmp(n, "toh") || !strcmp(n, "boh")) return -1.0f;
    if (!strncmp(n, "alpha", 5)) return FACET_ALPHA_MIN;
    if (!strcmp(c, "COS")) return FACET_COS_MIN;
    return 0.0f;
}

static inline float smp_domain_hi(const facet_kernel *k, int i)
{
    return !strcmp(k->inputs[i], "gamma") ? 4.0f : 1.0f;
}

/* GTR's gamma in [0, 4]: the closed-form orders 0 .. 4 exactly, next to 1
 * (the limit), or uniform */
static inline float smp_gamma(smp_rng *r)
{
    switch (smp_next(r) % 4) {
    case 0: return (float)(smp_next(r) % 9) * 0.5f;
    case 1: return (float)(1.0 + ((smp_next(r) & 1) ? 1 : -1) * smp_log2u(r, -24, -4));
    default: return (float)(4.0 * smp_u01(r));
    }
}

/* The first (best) port this CPU runs: what "auto" must choose. */
static inline const char *smp_best_port(void)
{
    size_t i;
    for (i = 0; i < facet_port_count(); i++) {
        int sup;
        const char *n = facet_port_at(i, &sup, NULL);
        if (sup)
            return n;
    }
    return "scalar";
}

/* One in-domain sample for a kernel, by its input names. */
static inline void smp_inputs(smp_rng *r, const facet_kernel *k, float *in)
{
    float nl, nv, lv;
    int i;
    smp_geometry(r, &nl, &nv, &lv);
    for (i = 0; i < k->n_inputs; i++) {
        const char *n = k->inputs[i];
        if (!strcmp(n, "nol")) in[i] = nl;
        else if (!strcmp(n, "nov")) in[i] = smp_two_cos(k) ? nv : smp_unit(r);
        else if (!strcmp(n, "lov")) in[i] = k->n_inputs == 1 ? (float)(2 * smp_u01(r) - 1) : lv;
        else if (!strncmp(n, "alpha", 5)) in[i] = smp_alpha(r);
        else if (!strcmp(n, "gamma")) in[i] = smp_gamma(r);
        else if (!strcmp(n, "toh") || !strcmp(n, "boh")) in[i] = (float)(2 * smp_u01(r) - 1);
        else if (!strcmp(n, "noh")) in[i] = (smp_next(r) & 1) ? smp_unit(r) : (float)(1.0 - smp_log2u(r, -24, -4));
        else in[i] = smp_unit(r);
    }
    if (k->n_inputs == 1 && !strcmp(k->inputs[0], "lov") && (smp_next(r) & 3) == 0)
        in[0] = (float)(-1.0 + smp_log2u(r, -24, 0));
    /* (N.H, T.H, B.H): mostly the components of a unit h, 1 in 8 anything */
    if (k->n_inputs >= 3 && !strcmp(k->inputs[0], "noh") && !strcmp(k->inputs[1], "toh")
        && (smp_next(r) & 7) != 0) {
        double phi = 2 * M_PI * smp_u01(r), n = in[0], st = sqrt((1 - n) * (1 + n));
        in[1] = (float)(st * cos(phi));
        in[2] = (float)(st * sin(phi));
    }
}

#endif
