/* test_fx_ports.c - the fixed-point batch API on every port this CPU runs
 * (facet_set_port; each port runs its own fx code where it has some, the
 * scalar loops elsewhere):
 * bit-exact equality with the scalar kernels (the specification) on large
 * random sets over the whole int32 range - in domain, near it, anywhere,
 * and edge values - every tail length 0 .. 3*16+1, unaligned pointers, out
 * aliasing each input, and the pinned hashes of tests/lib/fx_hash.h through the
 * batch API.  FACET_TEST_QUICK=1 (sanitizers, qemu) cuts the random set.
 * FACET_FX_TIMING=1 also prints rough ticks/sample per kernel and port
 * (rdtsc on x86, ns elsewhere): the README's speedup table. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "../lib/harness.h"
#include "facet.h"
#include "facet/fx.h"
#include "../lib/fx_test.h"
#define FXH_FAST /* the fx_fast pinned hashes too */
#include "../lib/fx_hash.h"
#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#endif

#define MAXLANES 16 /* tails 0 .. 3 * MAXLANES + 1 cover every port's width */

static int fast_tier; /* 0: fx, 1: fx_fast */
typedef void (*batch_fn)(void *out, const int32_t *const *in, size_t n);

/* the public batch entry point of k in the tier under test;
 * out holds out_bits/8-byte elements */
static void batch(const facet_fx_kernel *k, void *out, int32_t *const *in, size_t n)
{
    (fast_tier ? k->fx_fast_batch : k->fx_batch)(out, (const int32_t *const *)in, n);
}


static uint64_t get(const facet_fx_kernel *k, const void *out, size_t i)
{
    if (k->out_bits == 64)
        return ((const uint64_t *)out)[i];
    return ((const uint32_t *)out)[i];
}

/* one raw input: 1/2 in the domain, 1/4 within 70000 of it, 1/8 any int32,
 * 1/8 an edge value */
static int32_t gen(fx_rng *r, const facet_fx_kernel *k, int i)
{
    int32_t lo = k->lo[i], hi = k->hi[i];
    uint64_t c = fx_next(r) & 7u;
    if (c < 4)
        return fx_range(r, lo, hi);
    if (c < 6)
        return fx_range(r, lo - 70000, hi + 70000);
    if (c == 6)
        return (int32_t)(uint32_t)fx_next(r);
    {
        const int32_t edge[] = { INT32_MIN, INT32_MIN + 1, -65537, -32769, -32768, -32767, -1, 0, 1,
                                 31, 32, 33, 127, 128, 129, 16384, 32767, 32768, 32769, 65536,
                                 INT32_MAX - 1, INT32_MAX, lo - 1, lo, lo + 1, hi - 1, hi, hi + 1 };
        return edge[fx_next(r) % (sizeof edge / sizeof edge[0])];
    }
}

static int32_t *in_[FACET_FX_MAX_INPUTS];
static uint64_t *ref_;
static size_t n_;

static void make_set(const facet_fx_kernel *k, size_t n, uint64_t seed)
{
    fx_rng r;
    size_t j;
    int i;
    r.s = seed;
    n_ = n;
    for (i = 0; i < k->n_inputs; i++)
        in_[i] = realloc(in_[i], n * sizeof(int32_t));
    ref_ = realloc(ref_, n * sizeof(uint64_t));
    for (j = 0; j < n; j++) {
        int32_t t[FACET_FX_MAX_INPUTS];
        for (i = 0; i < k->n_inputs; i++)
            t[i] = in_[i][j] = gen(&r, k, i);
        ref_[j] = (fast_tier ? k->fx_fast : k->fx)(t);
    }
}

/* runs k's batch on [first, first + n) with every input copied to a buffer
 * of exactly n elements at element offset `mis` (a sanitizer sees any
 * access outside); returns the count of outputs differing from ref_ */
static long run_cmp(const facet_fx_kernel *k, size_t first, size_t n, size_t mis)
{
    int32_t *b[FACET_FX_MAX_INPUTS];
    size_t es = (size_t)k->out_bits / 8, j;
    char *o = malloc((n + mis) * es + 1);
    long bad = 0;
    int i;
    for (i = 0; i < k->n_inputs; i++) {
        b[i] = malloc((n + mis) * sizeof(int32_t) + 1);
        memcpy(b[i] + mis, in_[i] + first, n * sizeof(int32_t));
        b[i] += mis;
    }
    batch(k, o + mis * es, b, n);
    for (j = 0; j < n; j++)
        bad += get(k, o + mis * es, j) != ref_[first + j];
    for (i = 0; i < k->n_inputs; i++)
        free(b[i] - mis);
    free(o);
    return bad;
}

static long total_compared;

static void test_kernel_port(const facet_fx_kernel *k, const char *port)
{
    size_t es = (size_t)k->out_bits / 8, n, j;
    char *o = malloc(n_ * es);
    long bad = 0, bad_tail = 0, bad_align = 0, bad_alias = 0;
    int i, s;
    /* the whole random set */
    batch(k, o, in_, n_);
    for (j = 0; j < n_; j++)
        if (get(k, o, j) != ref_[j]) {
            if (!bad) {
                printf("    %s/%s: first difference at (", port, k->name);
                for (i = 0; i < k->n_inputs; i++)
                    printf("%s%ld", i ? ", " : "", (long)in_[i][j]);
                printf("): batch %llu, scalar %llu\n", (unsigned long long)get(k, o, j),
                       (unsigned long long)ref_[j]);
            }
            bad++;
        }
    total_compared += (long)n_;
    free(o);
    /* every tail length, from several starting points */
    for (n = 0; n <= 3 * MAXLANES + 1; n++)
        for (s = 0; s < 3; s++)
            bad_tail += run_cmp(k, (size_t)s * 97 % (n_ - n), n, 0);
    /* unaligned pointers (element offsets 1 .. 7 from malloc's alignment) */
    for (s = 1; s < 8; s++)
        bad_align += run_cmp(k, 11, 61 + (size_t)s, (size_t)s);
    /* out is the very same array as input i (32-bit outputs) */
    if (k->out_bits == 32)
        for (i = 0; i < k->n_inputs; i++) {
            int32_t *a[FACET_FX_MAX_INPUTS];
            int q;
            for (q = 0; q < k->n_inputs; q++) {
                a[q] = malloc(101 * sizeof(int32_t));
                memcpy(a[q], in_[q] + 5, 101 * sizeof(int32_t));
            }
            batch(k, a[i], a, 101);
            for (j = 0; j < 101; j++)
                bad_alias += (uint32_t)a[i][j] != ref_[5 + j];
            for (q = 0; q < k->n_inputs; q++)
                free(a[q]);
        }
    CHECK(bad == 0, "%s/%s: %ld of %lu random inputs differ from the scalar kernel", port, k->name,
          bad, (unsigned long)n_);
    CHECK(bad_tail == 0, "%s/%s: %ld tail outputs differ", port, k->name, bad_tail);
    CHECK(bad_align == 0, "%s/%s: %ld outputs differ on unaligned buffers", port, k->name, bad_align);
    CHECK(bad_alias == 0, "%s/%s: %ld outputs differ with out aliasing an input", port, k->name, bad_alias);
}

/* the pinned hash through the batch API */
struct col { int32_t *in[FACET_FX_MAX_INPUTS]; size_t n; int nin; };
static void collect(const int32_t *t, void *ctx)
{
    struct col *c = (struct col *)ctx;
    int i;
    for (i = 0; i < c->nin; i++)
        c->in[i][c->n] = t[i];
    c->n++;
}

/* the pinned hashes of the tier under test, through its batch API */
static void test_hash(const char *port)
{
    size_t pi, np = fast_tier ? FXH_N_PINNED_FAST : FXH_N_PINNED;
    for (pi = 0; pi < np; pi++) {
        const char *name = fast_tier ? fxh_pinned_fast[pi].name : fxh_pinned[pi].name;
        uint64_t pinned = fast_tier ? fxh_pinned_fast[pi].hash : fxh_pinned[pi].hash;
        const facet_fx_kernel *k = facet_fx_kernel_find(name);
        struct col c;
        uint64_t h = FXH_INIT;
        size_t j, cap = 80001 + 131 * 131 + 3000;
        void *o;
        int i;
        if (!k) {
            CHECK(0, "%s: not in the fx table", name);
            continue;
        }
        c.n = 0;
        c.nin = k->n_inputs;
        for (i = 0; i < k->n_inputs; i++)
            c.in[i] = malloc(cap * sizeof(int32_t));
        fxh_walk(k, collect, &c);
        o = malloc(c.n * 8);
        batch(k, o, c.in, c.n);
        for (j = 0; j < c.n; j++)
            fxh_feed(&h, get(k, o, j), k->out_bits / 8);
        CHECK(h == pinned, "%s/%s%s: batch hash %08lx%08lx, pinned %08lx%08lx", port, k->name,
              fast_tier ? " (fx_fast)" : "", (unsigned long)(h >> 32), (unsigned long)(h & 0xFFFFFFFFu),
              (unsigned long)(pinned >> 32), (unsigned long)(pinned & 0xFFFFFFFFu));
        free(o);
        for (i = 0; i < k->n_inputs; i++)
            free(c.in[i]);
    }
}

static uint64_t ticks(void)
{
#if defined(__x86_64__) || defined(__i386__)
    return __rdtsc();
#elif !defined(CLOCK_MONOTONIC) /* bare metal (newlib, tests/ports/helium.mk): clock() */
    return (uint64_t)clock();
#else
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
#endif
}

/* best of 5 runs over the random set, per sample */
static double time_batch(const facet_fx_kernel *k)
{
    void *o = malloc(n_ * 8);
    uint64_t best = ~(uint64_t)0;
    int r;
    for (r = 0; r < 5; r++) {
        uint64_t t0 = ticks(), t;
        batch(k, o, in_, n_);
        t = ticks() - t0;
        if (t < best)
            best = t;
    }
    free(o);
    return (double)best / (double)n_;
}

int main(void)
{
    const char *q = getenv("FACET_TEST_QUICK"), *tm = getenv("FACET_FX_TIMING");
    int quick = q && *q && strcmp(q, "0"), timing = tm && *tm && strcmp(tm, "0");
    size_t n = quick ? 4096 : 200000, ki, pi;
    th_name = "fx_ports";
    CHECK(facet_set_port("scalar") == 0 && !strcmp(facet_fx_port_name(), "scalar"),
          "the scalar port runs the scalar fx loops");
    if (timing)
        printf("ticks/sample (%s), best of 5 over %lu samples\n",
#if defined(__x86_64__) || defined(__i386__)
               "rdtsc",
#else
               "ns",
#endif
               (unsigned long)n);
    for (fast_tier = 0; fast_tier < 2; fast_tier++)
    for (ki = 0; ki < facet_fx_kernel_count(); ki++) {
        const facet_fx_kernel *k = facet_fx_kernel_at(ki);
        double t_scalar = 0;
        if (!fast_tier && !k->fx_batch) { /* the fast tier only (kernels.def fx_code fast) */
            CHECK(!k->fx && k->fx_fast_batch, "%s: a precise batch without a kernel or neither tier", k->name);
            continue;
        }
        make_set(k, n, 0xF00D + ki); /* the reference: the tier's scalar kernel */
        for (pi = 0; pi < facet_port_count(); pi++) {
            int sup;
            const char *pn = facet_port_at(pi, &sup, NULL), *fxn;
            if (!sup)
                continue;
            CHECK(facet_set_port(pn) == 0, "%s: facet_set_port", pn);
            fxn = facet_fx_port_name();
            CHECK(!strcmp(fxn, pn) || !strcmp(fxn, "scalar") || (!strcmp(pn, "avx512") && !strcmp(fxn, "avx2")),
                  "%s: fx port %s", pn, fxn);
            test_kernel_port(k, pn); /* as dispatched: the port's own code where it has some */
            if (timing) {
                double t = time_batch(k);
                if (!strcmp(fxn, "scalar") && !strcmp(pn, "scalar"))
                    t_scalar = t;
                printf("  %-22s %-7s %-7s (fx %-6s) %9.1f", k->name, fast_tier ? "fx_fast" : "fx", pn, fxn, t);
                if (t_scalar > 0)
                    printf("  x%.2f", t_scalar / t);
                printf("\n");
            }
        }
    }
    for (pi = 0; pi < facet_port_count(); pi++) {
        int sup;
        const char *pn = facet_port_at(pi, &sup, NULL);
        if (!sup)
            continue;
        facet_set_port(pn);
#if defined(__x86_64__) || defined(__i386__)
        if (!strcmp(pn, "avx2") || !strcmp(pn, "avx512"))
            CHECK(!strcmp(facet_fx_port_name(), "avx2"), "%s: the fx kernels run on avx2", pn);
#endif
#if defined(__aarch64__)
        if (!strcmp(pn, "neon"))
            CHECK(!strcmp(facet_fx_port_name(), "neon"), "neon: the fx lanes code runs");
#elif defined(__arm__) && defined(__linux__)
        if (!strcmp(pn, "neon"))
            CHECK(!strcmp(facet_fx_port_name(), "scalar"), "armv7 neon: the scalar fx loops run");
#endif
        for (fast_tier = 0; fast_tier < 2; fast_tier++)
            test_hash(pn);
    }
    facet_set_port("auto");
    printf("fx_ports: %ld random outputs compared bit for bit (%lu per kernel and port)\n",
           total_compared, (unsigned long)n);
    {
        int i;
        for (i = 0; i < FACET_FX_MAX_INPUTS; i++)
            free(in_[i]);
        free(ref_);
    }
    return th_done();
}
