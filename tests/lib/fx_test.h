/* fx_test.h - helpers of the fixed-point tests: a seeded PRNG (splitmix64),
 * the fx rounding rule on doubles, and the input families the accuracy
 * tests sample (tests/fx/test_fx_accuracy.c, the precise tier, and
 * tests/fx/test_fx_fast.c, the fast tier), written once here:
 *   fx_alpha_set      both alpha ends, their neighbours, a log-spaced set
 *   fx_geometry       a consistent (N.L, N.V, L.V) aimed at the specular
 *                     peak, grazing angles, L near V, and (FX_GEOM_NEAR_NORMAL)
 *                     the peak near normal incidence
 *   fx_random_inputs  a kernel's inputs from fx_geometry, alpha log-uniform
 *                     3 in 4, 1 in 16 any raw value of the domain, and
 *                     (FX_GEOM_TINY) tiny f0 / albedo / cos 1 in 4
 *   fx_edge_grid      every tuple of an edge set inside the domain
 * The precise tier's families are those its accuracy tables were first
 * printed with (flags 0: the tables are pinned by tests/digest/digest.sh);
 * the fast tier's test adds the two flagged families. */
#ifndef FACET_FX_TEST_H
#define FACET_FX_TEST_H

#include <stdint.h>
#include <string.h>
#include <math.h>
#include "facet/fx.h"

typedef struct { uint64_t s; } fx_rng;

static inline uint64_t fx_next(fx_rng *r)
{
    uint64_t z = (r->s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/* uniform integer in [lo, hi] */
static inline int32_t fx_range(fx_rng *r, int32_t lo, int32_t hi)
{
    return (int32_t)(lo + (int64_t)(fx_next(r) % (uint64_t)((int64_t)hi - lo + 1)));
}

/* uniform double in [0, 1) */
static inline double fx_unit(fx_rng *r) { return (fx_next(r) >> 11) * 0x1p-53; }

/* round half up, the fx rule (facet/fx.h) */
static inline double fx_round_hu(double x) { return floor(x + 0.5); }

/* alphas: both ends, their neighbours, and n_log log-spaced; returns the count */
static inline int fx_alpha_set(int32_t *a, int n_log)
{
    int n = 0, i;
    a[n++] = 32; a[n++] = 33; a[n++] = 32767; a[n++] = 32768;
    for (i = 0; i < n_log; i++)
        a[n++] = (int32_t)floor(32.0 * pow(1024.0, (i + 0.5) / n_log));
    return n;
}

#define FX_GEOM_NEAR_NORMAL 1 /* fx_geometry: also the peak near normal incidence */
#define FX_GEOM_TINY 2        /* fx_random_inputs: also tiny (or 0) f0 / albedo / cos */

/* a pair of cosines and L.V from unit vectors, quantised to Q15 */
static inline void fx_geometry(fx_rng *r, int flags, int32_t *nl, int32_t *nv, int32_t *lv)
{
    double cl, cv, phi, u = fx_unit(r), w = fx_unit(r);
    unsigned mode = (unsigned)(fx_next(r) % ((flags & FX_GEOM_NEAR_NORMAL) ? 7 : 6));
    cl = u;
    cv = w;
    phi = 2 * M_PI * fx_unit(r);
    if (mode == 0) { /* the specular peak: mirror azimuth, equal angles */
        cv = cl + (w - 0.5) * 0x1p-10;
        phi = M_PI + (phi - M_PI) * 0x1p-12;
    } else if (mode == 1) { /* grazing */
        cl = 0x1p-8 * (1 + 8 * u);
    } else if (mode == 2) { /* L near V */
        cv = cl + (w - 0.5) * 0x1p-9;
        phi = (phi - M_PI) * 0x1p-10;
    } else if (mode == 3 && (flags & FX_GEOM_NEAR_NORMAL)) { /* the peak near normal incidence: L ~ V ~ N */
        cl = cos(0.3 * u);
        cv = cos(0.3 * u * (1 + (w - 0.5) * 0.02));
        phi = M_PI + (phi - M_PI) * 0x1p-8;
    }
    cl = fmin(fmax(cl, 0x1p-8), 1.0);
    cv = fmin(fmax(cv, 0x1p-8), 1.0);
    *nl = (int32_t)fx_round_hu(cl * 32768);
    *nv = (int32_t)fx_round_hu(cv * 32768);
    *lv = (int32_t)fx_round_hu(fmin(fmax(cl * cv + sqrt(1 - cl * cl) * sqrt(1 - cv * cv) * cos(phi), -1.0), 1.0) * 32768);
}

/* the inputs of kernel fk from one fx_geometry, by input name */
static inline void fx_random_inputs(fx_rng *r, int flags, const facet_fx_kernel *fk, int32_t *in)
{
    int32_t nl, nv, lv;
    int i;
    fx_geometry(r, flags, &nl, &nv, &lv);
    for (i = 0; i < fk->n_inputs; i++) {
        const char *nm = fk->inputs[i];
        if (!strcmp(nm, "nol")) in[i] = nl;
        else if (!strcmp(nm, "nov")) in[i] = nv;
        else if (!strcmp(nm, "lov")) in[i] = lv;
        else if (!strcmp(nm, "alpha")) in[i] = (fx_next(r) & 3) ? (int32_t)floor(32.0 * pow(1024.0, fx_unit(r))) : fx_range(r, 32, 32768);
        else if ((flags & FX_GEOM_TINY) && fx_next(r) % 4 == 0) in[i] = (int32_t)(fx_next(r) % 64);
        else in[i] = fx_range(r, 0, 32768);
        if (fx_next(r) % 16 == 0) /* any raw value of the domain, consistent or not */
            in[i] = fx_range(r, fk->lo[i], fk->hi[i]);
    }
}

/* the edge values of every input */
static const int32_t fx_edges[] = { 0, 1, 32, 33, 127, 128, 129, 1000, 16384, 23170, 32000, 32767, 32768,
                                    -1, -16384, -32767, -32768 };
#define FX_N_EDGES ((int)(sizeof fx_edges / sizeof fx_edges[0]))

/* visit(in, ctx) for the first `limit` tuples of fx_edges^n_inputs that lie
 * in fk's domain */
static inline void fx_edge_grid(const facet_fx_kernel *fk, long limit, void (*visit)(const int32_t *, void *),
                                void *ctx)
{
    long total = 1, c;
    int i;
    for (i = 0; i < fk->n_inputs; i++)
        total *= FX_N_EDGES;
    if (total > limit)
        total = limit;
    for (c = 0; c < total; c++) {
        int32_t in[FACET_FX_MAX_INPUTS];
        long q = c;
        int ok = 1;
        for (i = 0; i < fk->n_inputs; i++) {
            in[i] = fx_edges[q % FX_N_EDGES];
            q /= FX_N_EDGES;
            ok &= in[i] >= fk->lo[i] && in[i] <= fk->hi[i];
        }
        if (ok)
            visit(in, ctx);
    }
}

#endif
