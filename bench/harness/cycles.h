/* cycles.h - the benchmark clock: core cycles where the kernel lets us count
 * them, else the CPU's constant-rate counter, always labelled for what it is.
 *
 *   source "perf"  PERF_COUNT_HW_CPU_CYCLES, user space only (exclude_kernel),
 *                  read with read(2): unit "cycles" (measured core cycles).
 *   source "tsc"   rdtsc (x86) / cntvct_el0 (aarch64): unit "ticks".  A tick
 *                  is not a core cycle (constant rate, turbo-independent).
 *                  cyc_ticks_per_cycle() estimates the ratio from a dependent
 *                  chain of 1-cycle integer adds; numbers converted with it
 *                  are reported as "est. cycles", never as measured cycles.
 *
 * Measurements run pinned to one CPU (cyc_init pins the calling thread).
 */
#ifndef FACET_BENCH_CYCLES_H
#define FACET_BENCH_CYCLES_H

#include <stdint.h>

typedef struct cyc_stat {
    double min, median, max; /* per unit of work, in cyc_unit() */
    double spread;           /* (max - min) / median over the epochs */
    int epochs;
    int noisy;               /* spread > 5% */
} cyc_stat;

/* Pins to one CPU (the current one), opens the counter.  Returns 0.
 * FACET_BENCH_CLOCK=tsc forces the tick counter. */
int cyc_init(void);
uint64_t cyc_now(void);
const char *cyc_source(void);       /* "perf" or "tsc" or "cntvct" */
const char *cyc_unit(void);         /* "cycles" or "ticks" */
int cyc_is_cycles(void);            /* 1 when cyc_now counts core cycles */
int cyc_cpu(void);                  /* the CPU we are pinned to (-1: not pinned) */
/* ticks per core cycle (1.0 when the source counts cycles); measured once. */
double cyc_ticks_per_cycle(void);

/* Work is fn(ctx, reps): do `reps` repetitions of the unit of work.
 * Measures t(2R) - t(R) for `epochs` epochs after a warm-up, divides by
 * R * units_per_rep.  epochs < 11 is raised to 11. */
typedef void (*cyc_work)(void *ctx, long reps);
cyc_stat cyc_measure(cyc_work fn, void *ctx, long reps, double units_per_rep, int epochs);

/* Picks R so that one R-pass takes about target clock units. */
long cyc_calibrate_reps(cyc_work fn, void *ctx, double target);

#endif
