/* speed.h - both f32 tiers' batch functions against the same-formula peers
 * built for the same width, timed in interleaved rounds (speed_bench.c):
 * the engine behind `facet-bench speed` and the report's speed table. */
#ifndef FACET_BENCH_SPEED_H
#define FACET_BENCH_SPEED_H

#include <stddef.h>

/* one entry of one kernel: a facet port in a tier, or a peer */
typedef struct speed_row {
    const char *kernel;
    const char *port;   /* facet port, or the peer set's name */
    const char *tier;   /* "f32", "f32_fast", or "peer" */
    const char *width;  /* the facet port of the same vector width, or "-" */
    double min, median; /* clock units per sample over the rounds */
    double err, err_peak; /* max relative error vs the oracle: random set, peak set (NaN: none) */
} speed_row;

typedef void (*speed_sink)(const speed_row *r, void *ctx);

/* Every kernel (or only), each entry of a kernel timed once per round for
 * `rounds` interleaved rounds of one pass over n samples (n a multiple of
 * 16); the rows go to sink, a kernel's rows together.  Runs peer_check
 * first.  Returns 0, -1 on bad arguments, -2 if the peer check fails.
 * The clock must be initialised (cyc_init). */
int speed_run(const char *only, int rounds, size_t n, speed_sink sink, void *ctx);

/* the bytes one pass reads and writes for kernel (its inputs and output) */
size_t speed_pass_bytes(const char *kernel, size_t n);

#define SPEED_MAX_ROUNDS 1001

#endif
