/* test_f32_accuracy.c - every f32 kernel against the oracle, at the same
 * float inputs: random samples aimed at the hard regions, dense grids, and
 * the edge list.  Enforces the FACET_ERR_* bounds of facet.h and prints the
 * measured table (max relative error, max ulp, argmax input). */
#include <stdio.h>
#include <stdlib.h>
#include <float.h>
#include "harness.h"
#include "sample.h"
#include "facet/oracle.h"

/* values this small are compared absolutely (flush-to-zero safe floor) */
#define ERR_FLOOR 0x1p-100

typedef struct {
    double max_rel, max_ulp;
    float arg[FACET_MAX_INPUTS];
    double got, want;
    long n;
} stat;

static double ulp_of(double x)
{
    int e;
    x = fabs(x);
    if (x < FLT_MIN)
        return 0x1p-149;
    frexp(x, &e);
    return ldexp(1.0, e - 24);
}

static void one(const facet_kernel *k, const float *in, stat *st)
{
    double din[FACET_MAX_INPUTS], want, got, rel, ulp;
    int i;
    for (i = 0; i < k->n_inputs; i++)
        din[i] = in[i];
    want = k->oracle(din);
    got = k->f32(in);
    rel = fabs(got - want) / fmax(fabs(want), ERR_FLOOR);
    if (got != got)
        rel = INFINITY;
    ulp = fabs(got - want) / ulp_of(want);
    st->n++;
    if (ulp > st->max_ulp && fabs(want) >= FLT_MIN)
        st->max_ulp = ulp;
    if (rel > st->max_rel) {
        st->max_rel = rel;
        st->got = got;
        st->want = want;
        for (i = 0; i < k->n_inputs; i++)
            st->arg[i] = in[i];
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
    for (i = 0; i < k->n_inputs; i++) {
        const char *n = k->inputs[i];
        float lo = 0.0f;
        if (!strcmp(n, "lov")) lo = -1.0f;
        else if (!strcmp(n, "alpha")) lo = FACET_ALPHA_MIN;
        else if (k->n_inputs > 2 && (!strcmp(n, "nol") || !strcmp(n, "nov"))) lo = FACET_COS_MIN;
        if (!(in[i] >= lo && in[i] <= 1.0f))
            return 0;
    }
    return 1;
}

static void edge_grid(const facet_kernel *k, stat *st)
{
    size_t idx[FACET_MAX_INPUTS] = {0}, total = 1, c;
    int i;
    for (i = 0; i < k->n_inputs; i++)
        total *= N_EDGES;
    for (c = 0; c < total; c++) {
        float in[FACET_MAX_INPUTS];
        size_t r = c;
        for (i = 0; i < k->n_inputs; i++) {
            idx[i] = r % N_EDGES;
            r /= N_EDGES;
            in[i] = edges[idx[i]];
        }
        if (in_domain(k, in))
            one(k, in, st);
    }
}

/* a regular grid, n points per input, alpha log-spaced */
static void dense_grid(const facet_kernel *k, int n, stat *st)
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
            if (!strcmp(nm, "alpha")) in[i] = (float)exp2(-10.0 * (1.0 - u));
            else if (!strcmp(nm, "lov")) in[i] = (float)(2.0 * u - 1.0);
            else if (!strcmp(nm, "noh")) in[i] = (float)(1.0 - exp2(-24.0 * u)); /* dense at the peak */
            else in[i] = (float)u;
        }
        for (i = 0; i < k->n_inputs; i++)
            if (k->n_inputs > 2 && (!strcmp(k->inputs[i], "nol") || !strcmp(k->inputs[i], "nov")) &&
                in[i] < FACET_COS_MIN)
                in[i] = FACET_COS_MIN;
        one(k, in, st);
    }
}

int main(int argc, char **argv)
{
    long n_random = argc > 1 ? atol(argv[1]) : getenv("FACET_TEST_QUICK") ? 30000 : 300000;
    const char *md_path = argc > 2 ? argv[2] : NULL; /* optional Markdown table */
    FILE *md = md_path ? fopen(md_path, "w") : NULL;
    size_t ki;
    th_name = "f32_accuracy";
    printf("%-22s %10s %8s %9s  %s\n", "kernel", "max rel", "log2", "max ulp", "argmax (inputs) -> got / oracle");
    if (md)
        fprintf(md, "| kernel | bound | max rel. error | log2 | max ulp | samples | argmax (inputs) |\n"
                    "|---|---|---|---|---|---|---|\n");
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const facet_kernel *k = facet_kernel_at(ki);
        stat st;
        smp_rng rng;
        long j;
        int i, grid_n;
        memset(&st, 0, sizeof st);
        rng.s = 0x5eed0000u + ki;
        for (j = 0; j < n_random; j++) {
            float in[FACET_MAX_INPUTS];
            smp_inputs(&rng, k, in);
            one(k, in, &st);
        }
        edge_grid(k, &st);
        grid_n = k->n_inputs <= 1 ? 1 << 20 : k->n_inputs == 2 ? 700 : k->n_inputs == 3 ? 72 : 12;
        dense_grid(k, grid_n, &st);
        printf("%-22s %10.3g %8.2f %9.2f  (", k->name, st.max_rel,
               st.max_rel > 0 ? log2(st.max_rel) : -999.0, st.max_ulp);
        for (i = 0; i < k->n_inputs; i++)
            printf("%s%.9g", i ? ", " : "", st.arg[i]);
        printf(") -> %.9g / %.17g\n", st.got, st.want);
        if (md) {
            fprintf(md, "| %s | 2^%.1f | %.3g | %.2f | %.2f | %ld | (", k->name, log2(k->err_f32), st.max_rel,
                    st.max_rel > 0 ? log2(st.max_rel) : -999.0, st.max_ulp, st.n);
            for (i = 0; i < k->n_inputs; i++)
                fprintf(md, "%s%.9g", i ? ", " : "", st.arg[i]);
            fprintf(md, ") |\n");
        }
        CHECK(st.max_rel <= k->err_f32, "%s: max relative error %.3g (2^%.2f) exceeds the bound 2^%.2f",
              k->name, st.max_rel, log2(st.max_rel), log2(k->err_f32));
    }
    if (md)
        fclose(md);
    return th_done();
}
