/* test_sample_ports.c - the samplers' batch API on every port this CPU runs,
 * both tiers: the bad-input contract (NaN, Inf, out-of-range and denormal
 * inputs give finite results; every sampled h is unit with h.z > 0; pdfs
 * are finite and >= 0; u = 0 and u just below 1 included; each result
 * equals the sampler at the documented substitute, to the bit), v below the
 * horizon sampled as v.z = 0 (to the bit), gamma NaN as gamma = 2, lane
 * independence, every tail length, unaligned buffers and outputs aliasing
 * inputs (all to the bit). */
#include <stdio.h>
#include <stdlib.h>
#include <float.h>
#include "../lib/harness.h"
#include "../lib/sample_common.h"
#include "../lib/batch_check.h"

#define MAXN BC_MAXN
#define NIN FACET_SAMPLER_MAX_INPUTS
#define NOUT FACET_SAMPLER_MAX_OUTPUTS

static int tier;

static int same(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }
static int is_sampler(const facet_sampler *k) { return strstr(k->name, "sample") != NULL; }

/* runs k on n samples of src (SoA, stride MAXN) from `first`, inputs copied to
 * exactly-sized buffers at float offset `mis`; alias: output o written over input o */
static void run_alias(const facet_sampler *k, float src[][MAXN], int first, int n, int mis, int alias,
                      float out[][MAXN])
{
    float *in[NIN], *o[NOUT];
    int i;
    for (i = 0; i < k->n_inputs; i++) {
        in[i] = malloc((n + mis) * sizeof(float) + 1);
        memcpy(in[i] + mis, &src[i][first], n * sizeof(float));
        in[i] += mis;
    }
    for (i = 0; i < k->n_outputs; i++)
        o[i] = alias && i < k->n_inputs ? in[i] : (float *)malloc((n + mis) * sizeof(float) + 1) + mis;
    (tier ? k->f32_fast_batch : k->f32_batch)(o, (const float *const *)in, (size_t)n);
    for (i = 0; i < k->n_outputs; i++) {
        memcpy(out[i], o[i], n * sizeof(float));
        if (!(alias && i < k->n_inputs))
            free(o[i] - mis);
    }
    for (i = 0; i < k->n_inputs; i++)
        free(in[i] - mis);
}

/* the same without aliasing (tests/lib/batch_check.h's run) */
static void run(const void *ctx, float src[][MAXN], int first, int n, int mis, float out[][MAXN])
{
    run_alias(ctx, src, first, n, mis, 0, out);
}

static float bad_value(smp_rng *r)
{
    static const float v[] = { 0.0f, -0.0f, 1.0f, -1.0f, 0x1.fffffep-1f, 1.5f, -0.5f, 1e30f, -1e30f,
                               FLT_MIN, 1e-40f, -1e-40f, 0.5f, 2.0f };
    unsigned k = (unsigned)(smp_next(r) % 18);
    if (k < sizeof v / sizeof v[0])
        return v[k];
    if (k == 14) return (float)INFINITY;
    if (k == 15) return -(float)INFINITY;
    if (k == 16) return (float)NAN;
    return -(float)NAN;
}

/* the documented substitute of input i's value x (facet.h): u to
 * [0, 1 - 2^-24], alpha to [alpha_min, 1], gamma to 1 or 2, dots and the z
 * of v and h (but in reflect) to [0, 1], other components to [-1, 1]; NaN
 * to the low end (gamma NaN to 2) */
static float substitute(const facet_sampler *k, int i, float x)
{
    const char *n = k->inputs[i];
    float lo = -1.0f, hi = 1.0f;
    if (!strcmp(n, "gamma"))
        return x < 1.5f ? 1.0f : 2.0f;
    if (n[0] == 'u') {
        lo = 0.0f;
        hi = 0x1.fffffep-1f;
    } else if (!strncmp(n, "alpha", 5)) {
        lo = FACET_ALPHA_MIN;
    } else if (!strcmp(n, "nov") || !strcmp(n, "noh") || !strcmp(n, "voh") ||
               (n[1] == 'z' && strcmp(k->name, "reflect"))) {
        lo = 0.0f;
    }
    if (!(x > lo))
        return lo;
    return x < hi ? x : hi;
}

static void test_port(const char *port, int lanes)
{
    static float src[NIN][MAXN], ref[NOUT][MAXN], out[NOUT][MAXN];
    size_t ki;
    for (ki = 0; ki < facet_sampler_count(); ki++) {
        const facet_sampler *k = facet_sampler_at(ki);
        smp_rng rng = { 4242 + ki };
        long bad_fin = 0, bad_unit = 0, bad_z = 0, bad_neg = 0, bad_sub = 0, bad_alias = 0, rep;
        bc_counts bc;
        int i, j, o;
        /* the bad-input contract: 64 batches of mixed special and valid values */
        for (rep = 0; rep < 64; rep++) {
            for (j = 0; j < MAXN; j++) {
                float x[NIN];
                ss_inputs(&rng, k, x);
                for (i = 0; i < k->n_inputs; i++)
                    src[i][j] = (smp_next(&rng) & 1) ? bad_value(&rng) : x[i];
            }
            run(k, src, 0, MAXN, 0, out);
            for (j = 0; j < MAXN; j++) {
                double l2 = 0;
                for (o = 0; o < k->n_outputs; o++) {
                    bad_fin += !(fabsf(out[o][j]) <= FLT_MAX);
                    l2 += (double)out[o][j] * out[o][j];
                }
                if (is_sampler(k)) {
                    bad_unit += !(fabs(sqrt(l2) - 1) <= 0x1p-22);
                    bad_z += !(out[2][j] > 0);
                }
                if (k->n_outputs == 1)
                    bad_neg += !(out[0][j] >= 0);
            }
            /* ... and each equals the sampler at the documented substitute, to the bit */
            for (j = 0; j < MAXN; j++)
                for (i = 0; i < k->n_inputs; i++)
                    src[i][j] = substitute(k, i, src[i][j]);
            run(k, src, 0, MAXN, 0, ref);
            for (j = 0; j < MAXN; j++)
                for (o = 0; o < k->n_outputs; o++)
                    bad_sub += !same(out[o][j], ref[o][j]);
        }
        CHECK(bad_fin == 0 && bad_unit == 0 && bad_z == 0 && bad_neg == 0,
              "%s%s on %s, bad inputs: %ld not finite, %ld not unit, %ld with h.z <= 0, %ld negative",
              k->name, tier ? " (fast)" : "", port, bad_fin, bad_unit, bad_z, bad_neg);
        CHECK(bad_sub == 0, "%s%s on %s: %ld bad-input results differ from the substitute's", k->name,
              tier ? " (fast)" : "", port, bad_sub);

        /* in-domain samples for the batch mechanics */
        for (j = 0; j < MAXN; j++) {
            float x[NIN];
            ss_inputs(&rng, k, x);
            for (i = 0; i < k->n_inputs; i++)
                src[i][j] = x[i];
        }
        run(k, src, 0, MAXN, 0, ref);
        bc = bc_mechanics(run, k, k->n_inputs, k->n_outputs, lanes, src, ref);
        run_alias(k, src, 0, MAXN, 0, 1, out);
        for (i = 0; i < MAXN; i++)
            for (o = 0; o < k->n_outputs; o++)
                bad_alias += !same(out[o][i], ref[o][i]);
        CHECK(bc.lane + bc.tail + bc.align + bad_alias == 0,
              "%s%s on %s: lane %ld, tail %ld, alignment %ld, aliasing %ld mismatches", k->name,
              tier ? " (fast)" : "", port, bc.lane, bc.tail, bc.align, bad_alias);
    }

    /* v below the horizon is sampled as v.z = 0; gamma NaN as gamma = 2 */
    {
        const facet_sampler *k = facet_sampler_find("ggx_sample_vndf");
        const facet_sampler *g = facet_sampler_find("gtr_sample_d");
        smp_rng rng = { 77 };
        long bad = 0;
        int j, o;
        for (j = 0; j < MAXN; j++) {
            float x[NIN];
            ss_inputs(&rng, k, x);
            src[0][j] = x[0];
            src[1][j] = x[1];
            src[2][j] = (j & 1) ? -(float)smp_u01(&rng) : -0.0f;
            src[3][j] = x[3];
            src[4][j] = x[4];
            src[5][j] = x[5];
        }
        run(k, src, 0, MAXN, 0, out);
        for (j = 0; j < MAXN; j++)
            src[2][j] = 0.0f;
        run(k, src, 0, MAXN, 0, ref);
        for (j = 0; j < MAXN; j++)
            for (o = 0; o < 3; o++)
                bad += !same(out[o][j], ref[o][j]);
        CHECK(bad == 0, "%s%s: v below the horizon is not sampled as v.z = 0 (%ld)", port, tier ? " fast" : "", bad);
        bad = 0;
        for (j = 0; j < MAXN; j++) {
            src[0][j] = ss_u(&rng);
            src[1][j] = ss_u(&rng);
            src[2][j] = smp_alpha(&rng);
            src[3][j] = (float)NAN;
        }
        run(g, src, 0, MAXN, 0, out);
        for (j = 0; j < MAXN; j++)
            src[3][j] = 2.0f;
        run(g, src, 0, MAXN, 0, ref);
        for (j = 0; j < MAXN; j++)
            for (o = 0; o < 3; o++)
                bad += !same(out[o][j], ref[o][j]);
        CHECK(bad == 0, "%s%s: gtr_sample_d with gamma NaN differs from gamma 2 (%ld)", port, tier ? " fast" : "", bad);
    }
}

int main(void)
{
    size_t pi;
    th_name = "sample_ports";
    for (pi = 0; pi < facet_port_count(); pi++) {
        int sup, lanes;
        const char *pn = facet_port_at(pi, &sup, &lanes);
        if (!sup) {
            SKIP("port %s is compiled in but this CPU cannot run it", pn);
            continue;
        }
        CHECK(facet_set_port(pn) == 0, "cannot select %s", pn);
        for (tier = 0; tier < 2; tier++)
            test_port(pn, lanes);
    }
    facet_set_port("auto");
    (void)smp_inputs;
    return th_done();
}
