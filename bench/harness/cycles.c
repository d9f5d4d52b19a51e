/* cycles.c - see cycles.h. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "cycles.h"

#if defined(__linux__)
#include <linux/perf_event.h>
#include <sys/syscall.h>
#define HAVE_PERF 1
#else
#define HAVE_PERF 0
#endif

static int perf_fd = -1;
static int pinned_cpu = -1;
static double tpc = 0.0;
static volatile unsigned spin_sink;

static uint64_t tick_now(void)
{
#if defined(__x86_64__) || defined(__i386__)
    uint32_t lo, hi;
    __asm__ __volatile__("lfence\n\trdtsc" : "=a"(lo), "=d"(hi) :: "memory");
    return ((uint64_t)hi << 32) | lo;
#elif defined(__aarch64__)
    uint64_t v;
    __asm__ __volatile__("isb\n\tmrs %0, cntvct_el0" : "=r"(v) :: "memory");
    return v;
#else
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
#endif
}

int cyc_init(void)
{
    const char *force = getenv("FACET_BENCH_CLOCK");
#ifdef __linux__
    {
        int cpu = sched_getcpu();
        cpu_set_t set;
        if (cpu < 0)
            cpu = 0;
        CPU_ZERO(&set);
        CPU_SET(cpu, &set);
        if (sched_setaffinity(0, sizeof set, &set) == 0)
            pinned_cpu = cpu;
    }
#endif
#if HAVE_PERF
    if (perf_fd < 0 && !(force && !strcmp(force, "tsc"))) {
        struct perf_event_attr a;
        memset(&a, 0, sizeof a);
        a.size = sizeof a;
        a.type = PERF_TYPE_HARDWARE;
        a.config = PERF_COUNT_HW_CPU_CYCLES;
        a.exclude_kernel = 1;
        a.exclude_hv = 1;
        perf_fd = (int)syscall(SYS_perf_event_open, &a, 0, -1, -1, 0);
        if (perf_fd >= 0) {
            /* a VM may open the event and never count: check it moves */
            uint64_t v0 = 0, v1 = 0;
            unsigned i;
            if (read(perf_fd, &v0, sizeof v0) != sizeof v0) v0 = 0;
            for (i = 0; i < 100000; i++) spin_sink += i;
            if (read(perf_fd, &v1, sizeof v1) != sizeof v1) v1 = 0;
            if (v1 <= v0) {
                close(perf_fd);
                perf_fd = -1;
            }
        }
    }
#endif
    (void)force;
    return 0;
}

uint64_t cyc_now(void)
{
#if HAVE_PERF
    if (perf_fd >= 0) {
        uint64_t v = 0;
        if (read(perf_fd, &v, sizeof v) == sizeof v)
            return v;
    }
#endif
    return tick_now();
}

int cyc_is_cycles(void) { return perf_fd >= 0; }
const char *cyc_unit(void) { return perf_fd >= 0 ? "cycles" : "ticks"; }
int cyc_cpu(void) { return pinned_cpu; }

const char *cyc_source(void)
{
    if (perf_fd >= 0)
        return "perf";
#if defined(__x86_64__) || defined(__i386__)
    return "tsc";
#elif defined(__aarch64__)
    return "cntvct";
#else
    return "clock_gettime";
#endif
}

/* A dependent chain of 1-cycle integer adds, 1000 per rep. */
static void add_chain(void *ctx, long reps)
{
    uint64_t x = (uint64_t)(uintptr_t)ctx;
    long r;
    for (r = 0; r < reps; r++) {
#if defined(__x86_64__)
#define A10 "add %1, %0\n\tadd %1, %0\n\tadd %1, %0\n\tadd %1, %0\n\tadd %1, %0\n\t" \
            "add %1, %0\n\tadd %1, %0\n\tadd %1, %0\n\tadd %1, %0\n\tadd %1, %0\n\t"
#define A100 A10 A10 A10 A10 A10 A10 A10 A10 A10 A10
        __asm__ __volatile__(A100 A100 A100 A100 A100 A100 A100 A100 A100 A100
                             : "+r"(x) : "r"((uint64_t)r));
#elif defined(__aarch64__)
#define A10 "add %0, %0, %1\n\tadd %0, %0, %1\n\tadd %0, %0, %1\n\tadd %0, %0, %1\n\tadd %0, %0, %1\n\t" \
            "add %0, %0, %1\n\tadd %0, %0, %1\n\tadd %0, %0, %1\n\tadd %0, %0, %1\n\tadd %0, %0, %1\n\t"
#define A100 A10 A10 A10 A10 A10 A10 A10 A10 A10 A10
        __asm__ __volatile__(A100 A100 A100 A100 A100 A100 A100 A100 A100 A100
                             : "+r"(x) : "r"((uint64_t)r));
#else
        int i;
        for (i = 0; i < 1000; i++)
            x = x * 3u + 1u; /* no known latency: the estimate is rough */
#endif
    }
    __asm__ __volatile__("" :: "r"(x));
}

double cyc_ticks_per_cycle(void)
{
    if (perf_fd >= 0)
        return 1.0;
    if (tpc == 0.0) {
        /* spin ~50 ms first so the core has left any low-power state, then
         * take the median of 21 epochs */
        uint64_t t0 = tick_now();
        cyc_stat s;
        while (tick_now() - t0 < 100000000u)
            add_chain(NULL, 10);
        s = cyc_measure(add_chain, NULL, 200, 1000.0, 21);
        tpc = s.median;
    }
    return tpc;
}

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static uint64_t run_once(cyc_work fn, void *ctx, long reps)
{
    uint64_t t0 = cyc_now();
    fn(ctx, reps);
    return cyc_now() - t0;
}

long cyc_calibrate_reps(cyc_work fn, void *ctx, double target)
{
    long r = 1;
    fn(ctx, 1); /* warm-up */
    while (r < (1L << 24)) {
        uint64_t t = run_once(fn, ctx, r);
        if ((double)t >= target)
            break;
        r *= 2;
    }
    return r;
}

cyc_stat cyc_measure(cyc_work fn, void *ctx, long reps, double units_per_rep, int epochs)
{
    cyc_stat s;
    double v[64];
    int e, n;
    if (epochs < 11)
        epochs = 11;
    if (epochs > 64)
        epochs = 64;
    if (reps < 1)
        reps = 1;
    fn(ctx, reps); /* warm-up: caches, branch predictors, clock ramp */
    fn(ctx, 2 * reps);
    for (e = 0; e < epochs; e++) {
        /* each epoch: best of 3 for each of R and 2R, then the difference */
        uint64_t a = UINT64_MAX, b = UINT64_MAX, t;
        int k;
        for (k = 0; k < 3; k++) {
            t = run_once(fn, ctx, reps);
            if (t < a) a = t;
            t = run_once(fn, ctx, 2 * reps);
            if (t < b) b = t;
        }
        v[e] = ((double)b - (double)a) / ((double)reps * units_per_rep);
    }
    n = epochs;
    qsort(v, (size_t)n, sizeof v[0], cmp_d);
    s.min = v[0];
    s.max = v[n - 1];
    s.median = v[n / 2];
    s.spread = s.median > 0 ? (s.max - s.min) / s.median : 0.0;
    s.epochs = n;
    s.noisy = s.spread > 0.05;
    return s;
}
