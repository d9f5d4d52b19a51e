/* speed_bench.c - `facet-bench speed`: the two f32 tiers' batch functions of
 * every port this CPU runs against the same-formula peers built for the same
 * width (peers.h), timed in INTERLEAVED ROUNDS (issue 21): each round times
 * one pass of every entry of a kernel (cyc_now() around the call), so the
 * entries compared with each other meet the same load; per entry the minimum
 * over the rounds (interruptions by other load only add time) and the
 * median.  The ports are called through their tables (src/core/port.h, as
 * report/symbols.c reads them), not the dispatcher.  Error of each entry
 * against the double oracle on the timed samples (tests/lib/sample.h's
 * generator: a quarter of them at the specular peak) and on a peak set
 * (mirror geometry within 2^-30 .. 2^-3, alpha in [2^-10, 2^-8]) for the
 * two-cosine kernels.
 *
 * Binary16 (facet/f16.h): where a port's line runs an f16 table of its own
 * (avx512fp16 on avx512), that table's batch is one more entry of the same
 * rounds (tier "f16", port the table, width the port), on the same inputs
 * rounded to binary16 (facet_f16_from_f32; in and out 2 bytes a value), called
 * through the dispatcher with that port active (set outside the timed call);
 * its error in facet/f16.h's measure at those binary16 inputs, clamped to
 * the f16 domain; no peak set (the peak set's alpha lies below the f16
 * floor 2^-7).  Beside it, where this build has it (BENCH_F16_PEER: x86-64,
 * bench/f16.mk), the binary16 shader-style transcription
 * (bench/f16/peer_f16_shader.c, port "shader_f16_fm", tier "peer", width
 * the same port) on the same binary16 inputs, judged by the same measure
 * (an Inf result is an infinite error). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "facet.h"
#include "facet/f16.h"
#include "tests/f16/f16_test.h"
#include "src/core/port.h"
#include "port_tables.h"
#include "cycles.h"
#include "peers.h"
#include "facet_bench.h"
#include "speed.h"
#ifdef BENCH_F16_PEER
#include "f16/f16_peer.h"
#endif


#define MAX_ROUNDS SPEED_MAX_ROUNDS
#define MAX_ENTRIES 26

/* one kernel's batch function in a port table, called on SoA columns */
typedef void (*tab_call)(const facet_f32_port *p, float *out, const float *const *in, size_t n);
#define COL_(q) in[q]
#define FACET_KERNEL(name, NAME, n_in, ...)                                                   \
    static void call_##name(const facet_f32_port *p, float *out, const float *const *in, size_t n) \
    {                                                                                         \
        p->name(out, FACET_EACH_INPUT(n_in, COL_), n);                                        \
    }
#include "src/core/kernels.def"
#undef FACET_KERNEL
static const tab_call calls_[] = {
#define FACET_KERNEL(name, ...) call_##name,
#include "src/core/kernels.def"
#undef FACET_KERNEL
};

typedef struct entry {
    const char *port, *tier;    /* facet port + tier, or peer name + "peer" */
    const char *width;          /* the vector width it belongs to (port name) */
    const facet_f32_port *tab;  /* facet: the port table */
    peer_term_fn peer;          /* peer: the loop */
    const facet_f16_kernel *h;  /* f16: the kernel, run through the dispatcher with port `via` active */
    const char *via;
    void (*hpeer)(uint16_t *out, const uint16_t *const *in, size_t n); /* the binary16 peer */
    double t[MAX_ROUNDS];
    double min, median, err, err_peak;
} entry;

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* the binary16 inputs and output of the f16 entries */
static facet_f16 *hin_[FACET_MAX_INPUTS], *hout_;

static void run(entry *e, size_t ki, float *out, const float *const *in, size_t n)
{
    if (e->tab)
        calls_[ki](e->tab, out, in, n);
    else if (e->h)
        e->h->f16_batch(hout_, (const facet_f16 *const *)hin_, n);
    else if (e->hpeer)
        e->hpeer(hout_, (const uint16_t *const *)hin_, n);
    else
        e->peer(out, in, n);
}

static double max_err(entry *e, size_t ki, float *out, const float *const *in, const double *want, size_t n)
{
    size_t i;
    double m = 0;
    if (e->h || e->hpeer) { /* f16: facet/f16.h's measure at the binary16 inputs */
        const facet_kernel *k = facet_kernel_at(ki);
        int j;
        if (e->h) {
            facet_set_port(e->via);
            e->h->f16_batch(hout_, (const facet_f16 *const *)hin_, n);
        } else {
            e->hpeer(hout_, (const uint16_t *const *)hin_, n);
        }
        for (i = 0; i < n; i++) {
            double dv[FACET_MAX_INPUTS], got = facet_f32_from_f16(hout_[i]), d;
            for (j = 0; j < k->n_inputs; j++)
                dv[j] = f16t_clamp(k->inputs[j], facet_f32_from_f16(hin_[j][i]));
            d = got != got ? INFINITY : f16t_err(got, k->oracle(dv));
            if (d > m)
                m = d;
        }
        return m;
    }
    run(e, ki, out, in, n);
    for (i = 0; i < n; i++) {
        double d = out[i] != out[i] ? INFINITY : fabs(out[i] - want[i]) / fmax(fabs(want[i]), 0x1p-100);
        if (d > m)
            m = d;
    }
    return m;
}

static void usage(FILE *f)
{
    fprintf(f, "usage: facet-bench speed [KERNEL] [--rounds R] [--samples N] [--tsv FILE] [--quick]\n"
               "Times both f32 tiers' batch functions on every port this CPU runs, and the\n"
               "same-formula peers (shader and shader_fm at each port's vector width, the\n"
               "textbook peer), in interleaved rounds: each round times one pass of every\n"
               "entry of a kernel, so all of them meet the same load; min and median over\n"
               "the rounds, clock units per sample.  Every kernel, or KERNEL.\n"
               "  --rounds R    rounds (default 41, 5..%d)\n"
               "  --samples N   samples per pass (default 4096, 16..65536)\n"
               "  --tsv FILE    also write the table as TSV (for the report)\n"
               "  --quick       5 rounds of 256 samples (tests)\n", MAX_ROUNDS);
}

size_t speed_pass_bytes(const char *kernel, size_t n)
{
    const facet_kernel *k = facet_kernel_find(kernel);
    return k ? n * (size_t)(k->n_inputs + 1) * sizeof(float) : 0;
}

int speed_run(const char *only, int rounds, size_t n, speed_sink sink, void *ctx)
{
    static const struct { const char *name; const facet_f32_port *f32, *fast; } ports[] = {
        { "avx512", &facet_port_avx512_f32, &facet_port_avx512_f32_fast },
        { "avx2", &facet_port_avx2_f32, &facet_port_avx2_f32_fast },
        { "sse2", &facet_port_sse2_f32, &facet_port_sse2_f32_fast },
        { "neon", &facet_port_neon_f32, &facet_port_neon_f32_fast },
        { "scalar", &facet_port_scalar_f32, &facet_port_scalar_f32_fast },
    };
    static entry e[MAX_ENTRIES];
    const char *saved = facet_port_name(), *via;
    size_t ki, nk = facet_kernel_count();
    float *in[FACET_MAX_INPUTS], *pin[FACET_MAX_INPUTS], *out;
    double *want, *pwant;
    int a;
    if (rounds < 5 || rounds > MAX_ROUNDS || n < 16 || n > 65536 || n % 16 || (only && !facet_kernel_find(only)))
        return -1;
    if (peer_check(stderr) != 0)
        return -2;
    for (a = 0; a < FACET_MAX_INPUTS; a++) {
        in[a] = malloc(n * sizeof(float));
        pin[a] = malloc(n * sizeof(float));
    }
    out = malloc(n * sizeof(float));
    want = malloc(n * sizeof(double));
    pwant = malloc(n * sizeof(double));
    for (a = 0; a < FACET_MAX_INPUTS; a++)
        hin_[a] = malloc(n * sizeof(facet_f16));
    hout_ = malloc(n * sizeof(facet_f16));
    for (ki = 0; ki < nk; ki++) {
        const facet_kernel *k = facet_kernel_at(ki);
        smp_rng r = { 0x5eed0021ull + ki };
        int ne = 0, i, j, two_cos = k->n_inputs >= 2 && !strcmp(k->inputs[0], "nol") && !strcmp(k->inputs[1], "nov");
        size_t p, s, q;
        if (only && strcmp(only, k->name))
            continue;
        for (q = 0; q < n; q++) {
            float v[FACET_MAX_INPUTS];
            double dv[FACET_MAX_INPUTS];
            smp_inputs(&r, k, v);
            for (j = 0; j < k->n_inputs; j++) {
                in[j][q] = v[j];
                dv[j] = v[j];
            }
            want[q] = k->oracle(dv);
            /* the peak set: mirror azimuth, nearly equal angles, small alpha */
            if (two_cos) {
                double cl = fmax(smp_u01(&r), 0.05), cv = cl + (smp_u01(&r) - 0.5) * smp_log2u(&r, -30, -3);
                double phi = M_PI + (smp_u01(&r) - 0.5) * smp_log2u(&r, -30, -3), sl, sv;
                cv = fmin(fmax(cv, FACET_COS_MIN), 1.0);
                sl = sqrt(1 - cl * cl);
                sv = sqrt(1 - cv * cv);
                v[0] = (float)cl;
                v[1] = (float)cv;
                if (k->n_inputs >= 3 && !strcmp(k->inputs[2], "lov"))
                    v[2] = (float)fmin(fmax(cl * cv + sl * sv * cos(phi), -1.0), 1.0);
                for (j = 2; j < k->n_inputs; j++)
                    if (!strcmp(k->inputs[j], "alpha"))
                        v[j] = (float)smp_log2u(&r, -10, -8);
            }
            for (j = 0; j < k->n_inputs; j++) {
                pin[j][q] = v[j];
                dv[j] = v[j];
            }
            pwant[q] = k->oracle(dv);
        }
        for (j = 0; j < k->n_inputs; j++)
            facet_f16_from_f32_batch(hin_[j], in[j], n);
        for (p = 0; p < sizeof ports / sizeof ports[0]; p++) {
            if (!ports[p].f32 || !facet_port_supported(ports[p].name) || ne + 2 > MAX_ENTRIES)
                continue;
            e[ne].port = e[ne + 1].port = ports[p].name;
            e[ne].width = e[ne + 1].width = ports[p].name;
            e[ne].tier = "f32";
            e[ne].tab = ports[p].f32;
            e[ne + 1].tier = "f32_fast";
            e[ne + 1].tab = ports[p].fast;
            e[ne].peer = e[ne + 1].peer = NULL;
            e[ne].h = e[ne + 1].h = NULL;
            e[ne].hpeer = e[ne + 1].hpeer = NULL;
            ne += 2;
            /* the port's own f16 table, if its line has one and this CPU runs it */
            {
                const facet_f16_kernel *h = facet_f16_kernel_find(k->name);
                const char *hn;
                if (h && h->f16 && ne < MAX_ENTRIES && facet_set_port(ports[p].name) == 0 &&
                    strcmp(hn = facet_f16_port_name(), "scalar")) {
                    e[ne].port = hn;
                    e[ne].width = ports[p].name;
                    e[ne].tier = "f16";
                    e[ne].tab = NULL;
                    e[ne].peer = NULL;
                    e[ne].h = h;
                    e[ne].hpeer = NULL;
                    e[ne].via = ports[p].name;
                    ne++;
#ifdef BENCH_F16_PEER
                    /* the binary16 transcription, where it runs: the same
                     * CPU feature as the avx512fp16 table */
                    {
                        const f16_peer_entry *pe = f16_peer_find(k->name);
                        if (pe && !strcmp(hn, "avx512fp16") && ne < MAX_ENTRIES) {
                            e[ne].port = "shader_f16_fm";
                            e[ne].width = ports[p].name;
                            e[ne].tier = "peer";
                            e[ne].tab = NULL;
                            e[ne].peer = NULL;
                            e[ne].h = NULL;
                            e[ne].hpeer = pe->fn;
                            e[ne].via = ports[p].name;
                            ne++;
                        }
                    }
#endif
                }
            }
        }
        for (s = 0; peer_sets[s] && ne < MAX_ENTRIES; s++) {
            peer_term_fn fn = peer_term(peer_sets[s], k->name);
            if (!fn || !peer_available(peer_sets[s]))
                continue;
            e[ne].port = peer_sets[s]->name;
            e[ne].width = peer_sets[s]->width ? peer_sets[s]->width : "-";
            e[ne].tier = "peer";
            e[ne].tab = NULL;
            e[ne].peer = fn;
            e[ne].h = NULL;
            e[ne].hpeer = NULL;
            ne++;
        }
        /* the active port matters to the f16 entries alone: set when it
         * changes, not before every call (facet_set_port asks the CPU, and
         * under a hypervisor each CPUID is a VM exit, after which the next
         * AVX-512 call measured up to 2.6x slower) */
        via = NULL;
        for (i = 0; i < ne; i++) {
            e[i].err = max_err(&e[i], ki, out, (const float *const *)in, want, n);
            e[i].err_peak = two_cos && !e[i].h && !e[i].hpeer ? max_err(&e[i], ki, out, (const float *const *)pin, pwant, n) : NAN;
            if (e[i].h)
                facet_set_port(via = e[i].via);
            run(&e[i], ki, out, (const float *const *)in, n); /* warm-up */
        }
        for (j = 0; j < rounds; j++)
            for (i = 0; i < ne; i++) {
                uint64_t t0;
                if (e[i].h && strcmp(e[i].via, via))
                    facet_set_port(via = e[i].via);
                t0 = cyc_now();
                run(&e[i], ki, out, (const float *const *)in, n);
                e[i].t[j] = (double)(cyc_now() - t0) / (double)n;
            }
        for (i = 0; i < ne; i++) {
            speed_row row;
            qsort(e[i].t, (size_t)rounds, sizeof(double), cmp_d);
            e[i].min = e[i].t[0];
            e[i].median = e[i].t[rounds / 2];
            row.kernel = k->name;
            row.port = e[i].port;
            row.tier = e[i].tier;
            row.width = e[i].width;
            row.min = e[i].min;
            row.median = e[i].median;
            row.err = e[i].err;
            row.err_peak = e[i].err_peak;
            sink(&row, ctx);
        }
    }
    for (a = 0; a < FACET_MAX_INPUTS; a++) {
        free(in[a]);
        free(pin[a]);
    }
    for (a = 0; a < FACET_MAX_INPUTS; a++)
        free(hin_[a]);
    free(hout_);
    free(out);
    free(want);
    free(pwant);
    facet_set_port(saved ? saved : "auto");
    return 0;
}

/* ---- the verb: the rows as a table, each kernel's ratios after its rows ---- */

typedef struct verb_ctx {
    FILE *tsv;
    speed_row rows[MAX_ENTRIES];
    char names[MAX_ENTRIES][3][40];
    int n;
} verb_ctx;

static const speed_row *vfind(const verb_ctx *c, const char *port, const char *tier)
{
    int i;
    for (i = 0; i < c->n; i++)
        if (!strcmp(c->rows[i].port, port) && !strcmp(c->rows[i].tier, tier))
            return &c->rows[i];
    return NULL;
}

/* the ratios the targets are stated in, from the minima */
static void ratios(verb_ctx *c)
{
    static const char *const widths[] = { "avx512", "avx2", "sse2", "neon", "scalar" };
    size_t p;
    for (p = 0; c->n && p < sizeof widths / sizeof widths[0]; p++) {
        const speed_row *f = vfind(c, widths[p], "f32"), *ff = vfind(c, widths[p], "f32_fast"), *pk, *pf;
        char pn[40];
        if (!f || !ff)
            continue;
        snprintf(pn, sizeof pn, "shader_%s", widths[p]);
        pk = vfind(c, pn, "peer");
        snprintf(pn, sizeof pn, "shader_%s_fm", widths[p]);
        pf = vfind(c, pn, "peer");
        printf("%-22s %-16s ratios (min): f32_fast/f32 %.2fx", f->kernel, widths[p], f->min / ff->min);
        if (pf)
            printf("; vs %s: f32 %.2fx, f32_fast %.2fx", pn, pf->min / f->min, pf->min / ff->min);
        if (pk)
            printf("; vs shader_%s: f32 %.2fx, f32_fast %.2fx", widths[p], pk->min / f->min, pk->min / ff->min);
        printf("\n");
    }
    c->n = 0;
}

static void verb_sink(const speed_row *r, void *ctx)
{
    verb_ctx *c = ctx;
    if (c->n && strcmp(c->names[0][0], r->kernel))
        ratios(c);
    printf("%-22s %-16s %-8s %9.3f %9.3f %10.3g %10.3g\n", r->kernel, r->port, r->tier, r->min, r->median, r->err,
           r->err_peak);
    if (c->tsv)
        fprintf(c->tsv, "%s\t%s\t%s\t%s\t%.4f\t%.4f\t%.4g\t%.4g\n", r->kernel, r->port, r->tier, r->width, r->min,
                r->median, r->err, r->err_peak);
    if (c->n < MAX_ENTRIES) {
        c->rows[c->n] = *r;
        snprintf(c->names[c->n][0], 40, "%s", r->kernel);
        snprintf(c->names[c->n][1], 40, "%s", r->port);
        snprintf(c->names[c->n][2], 40, "%s", r->tier);
        c->rows[c->n].kernel = c->names[c->n][0];
        c->rows[c->n].port = c->names[c->n][1];
        c->rows[c->n].tier = c->names[c->n][2];
        c->n++;
    }
}

int facet_bench_speed(int argc, char **argv)
{
    static verb_ctx c;
    int rounds = 41, a, quick = 0, rc;
    size_t n = 4096, bytes;
    const char *only = NULL, *tsv = NULL;
    for (a = 1; a < argc; a++) {
        if (!strcmp(argv[a], "--rounds") && a + 1 < argc)
            rounds = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--samples") && a + 1 < argc)
            n = (size_t)atol(argv[++a]);
        else if (!strcmp(argv[a], "--tsv") && a + 1 < argc)
            tsv = argv[++a];
        else if (!strcmp(argv[a], "--quick"))
            quick = 1;
        else if (!strcmp(argv[a], "--help")) {
            usage(stdout);
            return 0;
        } else if (argv[a][0] != '-' && !only && facet_kernel_find(argv[a]))
            only = argv[a];
        else {
            usage(stderr);
            return 2;
        }
    }
    if (quick) {
        rounds = 5;
        n = 256;
    }
    if (rounds < 5 || rounds > MAX_ROUNDS || n < 16 || n > 65536) {
        usage(stderr);
        return 2;
    }
    n = n / 16 * 16;
    memset(&c, 0, sizeof c);
    if (tsv && !(c.tsv = fopen(tsv, "w"))) {
        fprintf(stderr, "facet-bench speed: cannot write %s\n", tsv);
        return 1;
    }
    cyc_init();
    bytes = speed_pass_bytes(only ? only : "brdf_hammon", n);
    printf("# facet-bench speed: %s per sample (clock %s%s), %zu samples per pass (%zu KiB of inputs and\n"
           "# output for %s: %s), %d interleaved rounds, min and median; pinned to cpu %d; ticks per core cycle %.3f\n",
           cyc_unit(), cyc_source(), cyc_is_cycles() ? "" : ", not core cycles", n, bytes / 1024,
           only ? only : "brdf_hammon", bytes <= 32768 ? "L1-resident" : "L2-resident, beyond a 32-48 KiB L1", rounds,
           cyc_cpu(), cyc_ticks_per_cycle());
    printf("%-22s %-16s %-8s %9s %9s %10s %10s\n", "kernel", "port", "tier", "min", "median", "max_err",
           "peak_err");
    if (c.tsv)
        fprintf(c.tsv, "# kernel\tport\ttier\twidth\tmin\tmedian\tmax_err\tpeak_err\t(%s per sample, %zu samples, "
                       "%d interleaved rounds)\n", cyc_unit(), n, rounds);
    rc = speed_run(only, rounds, n, verb_sink, &c);
    ratios(&c);
    if (rc == -2) {
        fprintf(stderr, "facet-bench speed: the peer check failed (above)\n");
        return 1;
    }
    if (c.tsv && fclose(c.tsv) != 0)
        return 1;
    return rc != 0 || fflush(stdout) != 0;
}
