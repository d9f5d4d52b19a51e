/* test_f32_accuracy.c - every f32 kernel against the oracle, at the same
 * float inputs: random samples aimed at the hard regions, dense grids, and
 * the edge list.  Enforces the FACET_ERR_* bounds of facet.h and prints the
 * measured table (max relative error, max ulp, argmax input).  On every
 * port this CPU runs: its batches and its per-sample entries (the
 * facet_<kernel>_f32 calls, src/f32/f32_one_body.h; rows "<port>/1"). */
#include <stdio.h>
#include <stdlib.h>
#include <float.h>
#include "../lib/harness.h"
#include "../lib/sample.h"
#include "facet/oracle.h"

/* values below the floor (SMP_ERR_FLOOR, tests/lib/sample.h) are compared
 * absolutely: the error allowed there is bound * floor (facet.h);
 * flush-to-zero ports have the larger floor */

typedef struct {
    double max_rel, max_ulp;
    float arg[FACET_MAX_INPUTS];
    double got, want;
    long n;
} stat;

/* the sample set of one kernel: SoA inputs and the oracle's answers */
typedef struct {
    float *in[FACET_MAX_INPUTS];
    double *want;
    long n, cap;
    int n_in;
} set;

static double ulp_of(double x)
{
    int e;
    x = fabs(x);
    if (x < FLT_MIN)
        return 0x1p-149;
    frexp(x, &e);
    return ldexp(1.0, e - 24);
}

static void set_add(set *st, const facet_kernel *k, const float *in)
{
    int i;
    if (st->n == st->cap) {
        st->cap = st->cap ? 2 * st->cap : 1 << 16;
        for (i = 0; i < k->n_inputs; i++)
            st->in[i] = realloc(st->in[i], st->cap * sizeof(float));
        st->want = realloc(st->want, st->cap * sizeof(double));
    }
    for (i = 0; i < k->n_inputs; i++)
        st->in[i][st->n] = in[i];
    st->n++;
}

static void set_oracle(set *st, const facet_kernel *k)
{
    long j;
    int i;
    for (j = 0; j < st->n; j++) {
        double din[FACET_MAX_INPUTS];
        for (i = 0; i < k->n_inputs; i++)
            din[i] = st->in[i][j];
        st->want[j] = k->oracle(din);
    }
}

static int has_denormal(const set *st, const facet_kernel *k, long j)
{
    int i;
    for (i = 0; i < k->n_inputs; i++)
        if (st->in[i][j] != 0.0f && fabsf(st->in[i][j]) < FLT_MIN)
            return 1;
    return 0;
}

/* "<kernel>_fast": the row name of the fast tier */
static const char *fast_name(const char *name)
{
    static char buf[64];
    snprintf(buf, sizeof buf, "%s_fast", name);
    return buf;
}

typedef void (*batch_fn)(float *out, const float *const *in, size_t n);

/* ftz: the path flushes denormal inputs (then judged at the flushed
 * input): a port's batches (smp_port_flushes_denormals) and its per-sample
 * entries (scalar code: on armv7 and Helium the scalar FPU keeps the
 * denormals the vector unit flushes) are probed apart */
static void measure(const set *st, const facet_kernel *k, batch_fn batch, int ftz, float *out, stat *r)
{
    long j;
    int i;
    double floor_ = ftz ? SMP_ERR_FLOOR_FTZ : SMP_ERR_FLOOR;
    memset(r, 0, sizeof *r);
    batch(out, (const float *const *)st->in, (size_t)st->n);
    for (j = 0; j < st->n; j++) {
        double want = st->want[j], got = out[j];
        if (ftz && has_denormal(st, k, j)) {
            /* a flushing port is judged at the flushed input (facet/neon.h) */
            double din[FACET_MAX_INPUTS];
            for (i = 0; i < k->n_inputs; i++)
                din[i] = fabsf(st->in[i][j]) < FLT_MIN ? 0.0 : st->in[i][j];
            want = k->oracle(din);
        }
        double rel = fabs(got - want) / fmax(fabs(want), floor_);
        double ulp = fabs(got - want) / ulp_of(want);
        if (got != got || got < 0.0)
            rel = INFINITY;
        r->n++;
        if (ulp > r->max_ulp && fabs(want) >= FLT_MIN)
            r->max_ulp = ulp;
        if (rel > r->max_rel) {
            r->max_rel = rel;
            r->got = got;
            r->want = want;
            for (i = 0; i < k->n_inputs; i++)
                r->arg[i] = st->in[i][j];
        }
    }
}

/* the per-sample calls as a batch: facet_<kernel>_f32 (_fast) on each
 * sample, i.e. the active port's per-sample entry */
static const facet_kernel *one_k_;
static int one_fast_;
static void one_batch(float *out, const float *const *in, size_t n)
{
    float (*f)(const float *) = one_fast_ ? one_k_->f32_fast : one_k_->f32;
    size_t j;
    int i;
    for (j = 0; j < n; j++) {
        float x[FACET_MAX_INPUTS];
        for (i = 0; i < one_k_->n_inputs; i++)
            x[i] = in[i][j];
        out[j] = f(x);
    }
}

static const float edges[] = {
    0.0f, 1.4e-45f, 1e-38f, 9.5367431640625e-07f, 1e-6f, 1e-4f, 0.0009765625f, 0.01f,
    0.25f, 0.5f, 0.70710677f, 0.9f, 0.99999994f, 1.0f, -1.0f, -0.99999994f, -0.5f,
};
#define N_EDGES (sizeof edges / sizeof edges[0])

static int in_domain(const facet_kernel *k, const float *in)
{
    int i;
    for (i = 0; i < k->n_inputs; i++)
        if (!(in[i] >= smp_domain_lo(k, i) && in[i] <= smp_domain_hi(k, i)))
            return 0;
    return 1;
}

/* FACET_TEST_QUICK=2: under an emulator (the Cortex-M55 image,
 * tests/ports/helium.mk, where the double oracle is emulated; the qemu-user and
 * old-CPU suites): the 5- and 6-input
 * kernels' edge grids are walked with a prime stride (13, 211: every edge
 * value still in every input, 1/13 and 1/211 of the 17^5 and 17^6
 * combinations) and their dense grids are 6 and 5 points per input */
static int emulated;

static void edge_grid(const facet_kernel *k, set *st)
{
    size_t idx[FACET_MAX_INPUTS] = {0}, total = 1, c;
    size_t stride = !emulated || k->n_inputs < 5 ? 1 : k->n_inputs == 5 ? 13 : 211;
    int i;
    for (i = 0; i < k->n_inputs; i++)
        total *= N_EDGES;
    for (c = 0; c < total; c += stride) {
        float in[FACET_MAX_INPUTS];
        size_t r = c;
        for (i = 0; i < k->n_inputs; i++) {
            idx[i] = r % N_EDGES;
            r /= N_EDGES;
            in[i] = edges[idx[i]];
        }
        if (in_domain(k, in))
            set_add(st, k, in);
    }
}

/* a regular grid, n points per input, alpha log-spaced */
static void dense_grid(const facet_kernel *k, int n, set *st)
{
    long total = 1, c;
    int i;
    for (i = 0; i < k->n_inputs; i++)
        total *= n;
    for (c = 0; c < total; c++) {
        float in[FACET_MAX_INPUTS];
        long r = c;
        for (i = 0; i < k->n_inputs; i++) {
            double u = (double)(r % n) / (n - 1);
            const char *nm = k->inputs[i];
            r /= n;
            if (!strncmp(nm, "alpha", 5)) in[i] = (float)exp2(-10.0 * (1.0 - u));
            else if (!strcmp(nm, "lov") || !strcmp(nm, "toh") || !strcmp(nm, "boh"))
                in[i] = (float)(2.0 * u - 1.0);
            else if (!strcmp(nm, "gamma")) in[i] = (float)(4.0 * u);
            else if (!strcmp(nm, "noh")) in[i] = (float)(1.0 - exp2(-24.0 * u)); /* dense at the peak */
            else in[i] = (float)u;
        }
        for (i = 0; i < k->n_inputs; i++)
            if (in[i] < smp_domain_lo(k, i))
                in[i] = smp_domain_lo(k, i);
        set_add(st, k, in);
    }
}

int main(int argc, char **argv)
{
    long n_random = argc > 1 ? atol(argv[1]) : getenv("FACET_TEST_QUICK") ? 30000 : 300000;
    const char *md_path = argc > 2 ? argv[2] : NULL; /* optional Markdown table */
    FILE *md = md_path ? fopen(md_path, "w") : NULL;
    size_t ki, pi, n_ports = facet_port_count();
    th_name = "f32_accuracy";
    emulated = getenv("FACET_TEST_QUICK") && atoi(getenv("FACET_TEST_QUICK")) >= 2;

    for (pi = 0; pi < n_ports; pi++) {
        int sup;
        const char *pn = facet_port_at(pi, &sup, NULL);
        if (!sup)
            SKIP("port %s is compiled in but this CPU cannot run it", pn);
    }
    if (md) {
        fprintf(md, "| kernel | bound |");
        for (pi = 0; pi < n_ports; pi++)
            fprintf(md, " %s |", facet_port_at(pi, NULL, NULL));
        fprintf(md, " samples | argmax (inputs), worst port |\n|---|---|");
        for (pi = 0; pi < n_ports; pi++)
            fprintf(md, "---|");
        fprintf(md, "---|---|\n");
    }
    printf("%-22s %-7s %10s %8s %9s  %s\n", "kernel", "port", "max rel", "log2", "max ulp",
           "argmax (inputs) -> got / oracle");
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const facet_kernel *k = facet_kernel_at(ki);
        set st;
        smp_rng rng;
        long j;
        int i, grid_n, tier;
        float *out;
        stat worst;
        const char *worst_port = "";
        /* FACET_TEST_KERNEL=name: that kernel alone (while working on it) */
        if (getenv("FACET_TEST_KERNEL") && strcmp(getenv("FACET_TEST_KERNEL"), k->name))
            continue;
        memset(&st, 0, sizeof st);
        memset(&worst, 0, sizeof worst);
        rng.s = 0x5eed0000u + ki;
        for (j = 0; j < n_random; j++) {
            float in[FACET_MAX_INPUTS];
            smp_inputs(&rng, k, in);
            set_add(&st, k, in);
        }
        edge_grid(k, &st);
        grid_n = k->n_inputs <= 1 ? 1 << 20 : k->n_inputs == 2 ? 700 : k->n_inputs == 3 ? 72 : 12;
        if (getenv("FACET_TEST_QUICK"))
            grid_n = k->n_inputs <= 1 ? 1 << 16 : k->n_inputs == 2 ? 200 : k->n_inputs == 3 ? 30 : 7;
        if (emulated && k->n_inputs >= 5)
            grid_n = k->n_inputs == 5 ? 6 : 5;
        dense_grid(k, grid_n, &st);
        set_oracle(&st, k);
        out = malloc(st.n * sizeof(float));
        /* both tiers on the same samples: f32, then f32_fast */
        for (tier = 0; tier < 2; tier++) {
        batch_fn batch = tier ? k->f32_fast_batch : k->f32_batch;
        double bound = tier ? k->err_f32_fast : k->err_f32;
        const char *kn = tier ? fast_name(k->name) : k->name;
        memset(&worst, 0, sizeof worst);
        worst_port = "";
        if (md)
            fprintf(md, "| %s | 2^%.1f |", kn, log2(bound));
        for (pi = 0; pi < n_ports; pi++) {
            int sup;
            const char *pn = facet_port_at(pi, &sup, NULL);
            stat r;
            if (!sup) {
                if (md)
                    fprintf(md, " - |");
                continue;
            }
            CHECK(facet_set_port(pn) == 0 && !strcmp(facet_port_name(), pn), "cannot select port %s", pn);
            measure(&st, k, batch, smp_port_flushes_denormals(), out, &r);
            printf("%-22s %-7s %10.3g %8.2f %9.2f  (", kn, pn, r.max_rel,
                   r.max_rel > 0 ? log2(r.max_rel) : -999.0, r.max_ulp);
            for (i = 0; i < k->n_inputs; i++)
                printf("%s%.9g", i ? ", " : "", r.arg[i]);
            printf(") -> %.9g / %.17g\n", r.got, r.want);
            if (md)
                fprintf(md, " 2^%.2f |", r.max_rel > 0 ? log2(r.max_rel) : -999.0);
            CHECK(r.max_rel <= bound, "%s on %s: max relative error %.3g (2^%.2f) exceeds the bound 2^%.2f",
                  kn, pn, r.max_rel, log2(r.max_rel), log2(bound));
            if (r.max_rel >= worst.max_rel) {
                worst = r;
                worst_port = pn;
            }
            /* the same samples through the port's per-sample entries */
            one_k_ = k;
            one_fast_ = tier;
            measure(&st, k, one_batch, facet_lambert_f32(1e-39f) == 0.0f, out, &r);
            printf("%-22s %-7s %10.3g %8.2f %9.2f  (", kn, pn, r.max_rel,
                   r.max_rel > 0 ? log2(r.max_rel) : -999.0, r.max_ulp);
            for (i = 0; i < k->n_inputs; i++)
                printf("%s%.9g", i ? ", " : "", r.arg[i]);
            printf(") -> %.9g / %.17g  (%s/1: per sample)\n", r.got, r.want, pn);
            CHECK(r.max_rel <= bound, "%s per sample on %s: max relative error %.3g (2^%.2f) exceeds the bound 2^%.2f",
                  kn, pn, r.max_rel, log2(r.max_rel), log2(bound));
        }
        if (md) {
            fprintf(md, " %ld | (", st.n);
            for (i = 0; i < k->n_inputs; i++)
                fprintf(md, "%s%.9g", i ? ", " : "", worst.arg[i]);
            fprintf(md, "), %s |\n", worst_port);
        }
        }
        free(out);
        for (i = 0; i < k->n_inputs; i++)
            free(st.in[i]);
        free(st.want);
    }
    facet_set_port("auto");
    if (md)
        fclose(md);
    return th_done();
}
