/* bench.h - the benchmark engine behind `facet-bench bench` and the report:
 * every kernel x format x port x way of calling it (plus the peers), each
 * with its error against the double oracle and its cost in clock units. */
#ifndef FACET_BENCH_H
#define FACET_BENCH_H

#include <stddef.h>
#include <stdio.h>
#include "facet.h"
#include "cycles.h"

typedef struct bench_opts {
    size_t n_time;        /* samples per timed pass, multiple of 8 (1024) */
    size_t n_err;         /* samples for the error measurement (1 << 16) */
    int epochs;           /* timed epochs after warm-up, >= 11 */
    double target;        /* clock units per R-pass (1e5) */
    unsigned long long seed;
    int peers;            /* 1: include the peers */
    const char *kernel;   /* NULL: all */
    const char *port;     /* NULL: all available */
    const char *format;   /* NULL: all ("f32", "fx") */
    int progress;         /* progress lines on stderr */
    int sampler_batch_only; /* 1: the samplers' batch and peer rows only (the report) */
} bench_opts;

void bench_defaults(bench_opts *o);

typedef struct bench_err {
    double max_rel, mean_rel;   /* relative to the oracle (floor 2^-100) */
    double max_rel_vis;         /* max_rel over the samples whose oracle value is >= 2^-8:
                                 * what can show in a picture (the Pareto plots) */
    float arg[FACET_MAX_INPUTS];/* input at the max */
    double got, want;
    long n;
    /* fixed-point rows: error in units of the output's last place against
     * round-half-up(oracle * 2^frac) at the same (Q15) inputs, as
     * tests/fx/test_fx_accuracy.c measures it; max_rel/mean_rel are then
     * relative to the oracle at the Q15 inputs (floor: one LSB) */
    int has_lsb;
    double max_lsb, mean_lsb;
    /* brdf_hammon (64-bit output): where the oracle is >= 16 its LSB (2^-24)
     * is below what the double oracle resolves, so those samples are held to
     * 2^-26 relative instead (as in tests/fx/test_fx_accuracy.c): their max
     * relative error (-1: none) and the count of samples in max/mean_lsb */
    double big_rel;
    long n_lsb;
} bench_err;

typedef struct bench_row {
    const char *kernel;     /* facet kernel name */
    const char *format;     /* "f32", "fx" */
    const char *port;       /* scalar, sse2, avx2, neon; the peer's name for peers */
    const char *path;       /* batch, inline, call, peer, peer-vectors */
    const char *note;       /* what a peer row computes, or "" */
    int n_inputs;
    int lanes;              /* samples per call */
    bench_err err;
    double bound;           /* the facet.h bound (0: none, e.g. peers); fx: LSB */
    int within;             /* err.max_rel (fx: err.max_lsb) <= bound (1 when bound == 0) */
    cyc_stat thr;           /* clock units per sample */
    int has_lat;
    cyc_stat lat;           /* clock units per dependent call, overhead removed */
} bench_row;

typedef void (*bench_sink)(const bench_row *r, void *ctx);

/* Runs every selected combination; returns the number of rows, -1 if the
 * selection names an unknown kernel/port/format, -2 if a peer's term names
 * no kernel of the list (peers.h peer_check). */
int bench_run(const bench_opts *o, bench_sink sink, void *ctx);

/* The relative error used everywhere: |got - want| / max(|want|, 2^-100),
 * infinite for a NaN result. */
double bench_rel_err(double got, double want);

/* The exact model that the full-BRDF peers compute:
 * D(N.H) Vis_exact(N.L, N.V) F(f0, L.H) + diffuse_hammon, in double. */
double bench_oracle_brdf_exact(double nol, double nov, double lov, double alpha,
                               double f0, double albedo);

/* Unit vectors L, V over N = z with the given dots (azimuth psi of V),
 * in double. */
void bench_vectors(double nl, double nv, double lv, double psi, double L[3], double V[3]);

#endif
