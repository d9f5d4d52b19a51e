/* test_f32_ports.c - the batch API on every port this CPU runs: lane
 * independence, every tail length, unaligned pointers, aliasing, the
 * bad-input contract, and port selection.  (Accuracy of every port against
 * the oracle is tests/f32/test_f32_accuracy.c.)  Both tiers, f32 and f32_fast,
 * through the same checks. */
#include <stdio.h>
#include <stdlib.h>
#include <float.h>
#include <stdint.h>
#include "../lib/harness.h"
#include "../lib/sample.h"
#include "../lib/batch_check.h"

#define MAXN BC_MAXN

static int fast_tier; /* 0: facet_kernel.f32_batch, 1: f32_fast_batch */

static int same(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

/* runs k's batch on n samples taken from src (SoA, stride MAXN) starting at
 * index `first`, with each input copied to a buffer of exactly n floats at
 * float offset `misalign`, so a sanitizer sees any access past the end;
 * out[0] gets the results (tests/lib/batch_check.h's run) */
static void run(const void *ctx, float src[][MAXN], int first, int n, int misalign, float out[][MAXN])
{
    const facet_kernel *k = ctx;
    float *buf[FACET_MAX_INPUTS], *o;
    int i;
    for (i = 0; i < k->n_inputs; i++) {
        buf[i] = malloc((n + misalign) * sizeof(float) + 1);
        memcpy(buf[i] + misalign, &src[i][first], n * sizeof(float));
        buf[i] += misalign;
    }
    o = malloc((n + misalign) * sizeof(float) + 1);
    (fast_tier ? k->f32_fast_batch : k->f32_batch)(o + misalign, (const float *const *)buf, (size_t)n);
    memcpy(out[0], o + misalign, n * sizeof(float));
    free(o);
    for (i = 0; i < k->n_inputs; i++)
        free(buf[i] - misalign);
}

static void test_port(const char *port, int lanes)
{
    static float src[FACET_MAX_INPUTS][MAXN];
    smp_rng rng = { 777 };
    size_t ki;
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const facet_kernel *k = facet_kernel_at(ki);
        static float ref[1][MAXN], out[1][MAXN], sub[1][MAXN];
        int i, j, bad_alias = 0;
        bc_counts bc;
        for (j = 0; j < MAXN; j++) {
            float in[FACET_MAX_INPUTS];
            smp_inputs(&rng, k, in);
            for (i = 0; i < k->n_inputs; i++)
                src[i][j] = in[i];
        }
        run(k, src, 0, MAXN, 0, ref);
        /* lane independence, every tail length, unaligned buffers */
        bc = bc_mechanics(run, k, k->n_inputs, 1, lanes, src, ref);
        /* out aliases the first and the last input */
        for (j = 0; j < 2; j++) {
            float *a[FACET_MAX_INPUTS];
            int which = j ? k->n_inputs - 1 : 0;
            for (i = 0; i < k->n_inputs; i++) {
                a[i] = malloc(77 * sizeof(float));
                memcpy(a[i], src[i], 77 * sizeof(float));
            }
            (fast_tier ? k->f32_fast_batch : k->f32_batch)(a[which], (const float *const *)a, 77);
            for (i = 0; i < 77; i++)
                if (!same(a[which][i], ref[0][i]))
                    bad_alias++;
            for (i = 0; i < k->n_inputs; i++)
                free(a[i]);
        }
        /* reciprocity: swapping N.L and N.V gives the same bits */
        if (k->n_inputs >= 2 && !strcmp(k->inputs[0], "nol") && !strcmp(k->inputs[1], "nov")) {
            int bad_sym = 0;
            float *swapped[FACET_MAX_INPUTS];
            for (i = 0; i < k->n_inputs; i++)
                swapped[i] = src[i];
            swapped[0] = src[1];
            swapped[1] = src[0];
            (fast_tier ? k->f32_fast_batch : k->f32_batch)(out[0], (const float *const *)swapped, MAXN);
            for (i = 0; i < MAXN; i++)
                if (!same(out[0][i], ref[0][i]))
                    bad_sym++;
            CHECK(bad_sym == 0, "%s/%s: not symmetric in N.L and N.V (%d values)", port, k->name, bad_sym);
        }
        CHECK(bc.lane == 0, "%s/%s: result depends on the lane (%ld cases)", port, k->name, bc.lane);
        CHECK(bc.tail == 0, "%s/%s: tails differ from the full batch (%ld values)", port, k->name, bc.tail);
        CHECK(bc.align == 0, "%s/%s: unaligned buffers change results (%ld values)", port, k->name, bc.align);
        CHECK(bad_alias == 0, "%s/%s: out aliasing an input changes results (%d values)", port, k->name, bad_alias);

        /* bad input: finite, >= 0, equal to the port's value at the substitute */
        {
            /* NaN (every class: quiet, signalling, both signs, payloads) -> +0;
             * the other bad values -> the kernel at the clamped value */
            static const uint32_t bits[] = { 0x7fc00000u, 0xffc00000u, 0x7f800001u, 0xff800001u,
                                             0x7fa00000u, 0x7fc12345u, 0x7fbfffffu, 0x7fffffffu,
                                             0xffffffffu, 0xff812345u, 0x7f800000u, 0xff800000u };
            const float fin[] = { -0.0f, 1.4e-45f, -1e-30f, -1.0f, -2.0f, 1.0000001f, 2.0f, 1e30f,
                                  -FLT_MAX, FLT_MAX };
            float bad[sizeof bits / sizeof bits[0] + sizeof fin / sizeof fin[0]];
            const int n_bad = (int)(sizeof bad / sizeof bad[0]);
            int pos, bad_val = 0, bad_sub = 0, bad_nan = 0;
            /* every bad value in every lane position */
            const int nb = 3 * lanes + 1 > 2 * n_bad ? 3 * lanes + 1 : 2 * n_bad + 1;
            for (j = 0; j < (int)(sizeof bits / sizeof bits[0]); j++)
                memcpy(&bad[j], &bits[j], sizeof(float));
            for (i = 0; i < (int)(sizeof fin / sizeof fin[0]); i++)
                bad[j + i] = fin[i];
            for (pos = 0; pos < k->n_inputs; pos++) {
                float save[MAXN];
                memcpy(save, src[pos], sizeof save);
                for (j = 0; j < nb; j++)
                    src[pos][j] = bad[j % n_bad];
                run(k, src, 0, nb, 0, out);
                for (j = 0; j < nb; j++) {
                    float v = src[pos][j], lo = smp_domain_lo(k, pos), hi = smp_domain_hi(k, pos);
                    if (!(out[0][j] == out[0][j]) || out[0][j] > FLT_MAX || out[0][j] < 0.0f || same(out[0][j], -0.0f))
                        bad_val++;
                    if (v != v && !same(out[0][j], 0.0f))
                        bad_nan++;
                    src[pos][j] = v != v ? 0.5f : v < lo ? lo : v > hi ? hi : v;
                }
                run(k, src, 0, nb, 0, sub);
                for (j = 0; j < nb; j++)
                    if (!(bad[j % n_bad] != bad[j % n_bad]) && !same(out[0][j], sub[0][j]))
                        bad_sub++;
                memcpy(src[pos], save, sizeof save);
            }
            CHECK(bad_val == 0, "%s/%s: %d bad inputs gave NaN, Inf or a negative value", port, k->name, bad_val);
            CHECK(bad_sub == 0, "%s/%s: %d bad inputs differ from the clamped value", port, k->name, bad_sub);
            CHECK(bad_nan == 0, "%s/%s: %d samples with a NaN input are not +0", port, k->name, bad_nan);
        }
    }
}

int main(void)
{
    size_t pi;
    th_name = "f32_ports";
    CHECK(facet_set_port("no_such_port") == 1, "an unknown port name is refused with 1");
    CHECK(facet_set_port(NULL) == 0 && facet_set_port("auto") == 0, "auto is always accepted");
    for (pi = 0; pi < facet_port_count(); pi++) {
        int sup, lanes;
        const char *pn = facet_port_at(pi, &sup, &lanes);
        if (!sup) {
            CHECK(facet_set_port(pn) == 2, "%s: a port this CPU cannot run is refused with 2", pn);
            SKIP("port %s: compiled in, but this CPU cannot run it", pn);
            continue;
        }
        CHECK(facet_set_port(pn) == 0 && !strcmp(facet_port_name(), pn), "%s: selectable", pn);
        for (fast_tier = 0; fast_tier < 2; fast_tier++) {
            char label[32];
            snprintf(label, sizeof label, "%s%s", pn, fast_tier ? "/f32_fast" : "");
            test_port(label, lanes);
        }
    }
    CHECK(facet_port_at(facet_port_count(), NULL, NULL) == NULL, "facet_port_at past the end is NULL");
    facet_set_port("auto");
    CHECK(!strcmp(facet_port_name(), smp_best_port()) || getenv("FACET_PORT"),
          "auto picks the best supported port (%s)", facet_port_name());
    return th_done();
}
