/* fuzz_f32_batch.c - libFuzzer target for the f32 batch API.
 * Input: kernel (byte 0), n (byte 1), misalignment and aliasing (byte 2),
 * then raw float bit patterns (every 32-bit pattern: NaNs, infinities,
 * denormals, negative zero).  On every port this CPU runs:
 *   - every output is finite, >= 0 and not -0 (facet.h: nothing traps);
 *   - it equals the port's own result for that sample alone (n = 1), so
 *     tails, lanes and alignment change nothing;
 *   - out == an input array (the permitted aliasing) changes nothing;
 *   - a sample with a NaN input gives +0 (the NaN rule); any other equals
 *     the result at the clamped inputs (the domain rule);
 *   - swapping N.L and N.V changes nothing (reciprocity);
 *   - it is within the kernel's bound FACET_ERR_* of the double oracle at
 *     the clamped inputs (values below 2^-100 compared absolutely; the
 *     flushing ports' larger floor does not apply on the x86 hosts this
 *     runs on, and a port that flushes denormals is judged as
 *     tests/f32/test_f32_accuracy.c does). */
#include <float.h>
#include <math.h>
#include "facet.h"
#include "fuzz_common.h"
#include "../lib/sample.h"

#define MAX_N 80

static int same(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

/* each input's domain, from the list's domain classes: the one table the
 * tests share (tests/lib/sample.h) */
static float clamp_in(const facet_kernel *k, int i, float v)
{
    float lo = smp_domain_lo(k, i), hi = smp_domain_hi(k, i);
    return v < lo ? lo : v > hi ? hi : v;
}

static void run_port(const facet_kernel *k, const char *port, float in[][MAX_N], size_t n, size_t off, int alias)
{
    void *base[FACET_MAX_INPUTS + 1];
    float *buf[FACET_MAX_INPUTS], *out, one, cl[FACET_MAX_INPUTS][1];
    const float *ptr[FACET_MAX_INPUTS];
    int i, ftz = smp_port_flushes_denormals();
    size_t j;
    for (i = 0; i < k->n_inputs; i++) {
        buf[i] = fuzz_buf(n, sizeof(float), off, &base[i]);
        memcpy(buf[i], in[i], n * sizeof(float));
        ptr[i] = buf[i];
    }
    out = fuzz_buf(n, sizeof(float), (off + 3) % 8, &base[FACET_MAX_INPUTS]);
    k->f32_batch(out, ptr, n);
    for (j = 0; j < n; j++) {
        const float *p1[FACET_MAX_INPUTS];
        float single[FACET_MAX_INPUTS][1], got = out[j];
        double din[FACET_MAX_INPUTS], want, floor_ = ftz ? SMP_ERR_FLOOR_FTZ : SMP_ERR_FLOOR;
        if (!(got >= 0.0f && got <= FLT_MAX) || same(got, -0.0f))
            FUZZ_FAIL("%s/%s: sample %zu gives %a", port, k->name, j, got);
        for (i = 0; i < k->n_inputs; i++) {
            single[i][0] = in[i][j];
            p1[i] = single[i];
        }
        k->f32_batch(&one, p1, 1);
        if (!same(one, got))
            FUZZ_FAIL("%s/%s: sample %zu of %zu gives %a, alone %a", port, k->name, j, n, got, one);
        {
            int has_nan = 0;
            for (i = 0; i < k->n_inputs; i++)
                has_nan |= in[i][j] != in[i][j];
            if (has_nan) {
                if (!same(got, 0.0f))
                    FUZZ_FAIL("%s/%s: sample %zu has a NaN input but gives %a, not +0", port, k->name, j, got);
                continue;
            }
        }
        for (i = 0; i < k->n_inputs; i++) {
            cl[i][0] = clamp_in(k, i, in[i][j]);
            if (ftz && cl[i][0] != 0.0f && fabsf(cl[i][0]) < FLT_MIN)
                cl[i][0] = 0.0f; /* judged at the flushed input */
            p1[i] = cl[i];
            din[i] = cl[i][0];
        }
        k->f32_batch(&one, p1, 1);
        if (!ftz && !same(one, got))
            FUZZ_FAIL("%s/%s: sample %zu gives %a, at the clamped inputs %a", port, k->name, j, got, one);
        if (k->n_inputs >= 3 && !strcmp(k->inputs[0], "nol") && !strcmp(k->inputs[1], "nov")) {
            p1[0] = single[1];
            p1[1] = single[0];
            for (i = 2; i < k->n_inputs; i++)
                p1[i] = single[i];
            k->f32_batch(&one, p1, 1);
            if (!same(one, got))
                FUZZ_FAIL("%s/%s: sample %zu: %a, with N.L and N.V swapped %a", port, k->name, j, got, one);
        }
        want = k->oracle(din);
        if (!(fabs(got - want) <= k->err_f32 * fmax(fabs(want), floor_)))
            FUZZ_FAIL("%s/%s: sample %zu, inputs %a %a %a %a %a %a: %.9g vs oracle %.17g, rel %.3g > bound %.3g",
                      port, k->name, j, (double)cl[0][0], k->n_inputs > 1 ? (double)cl[1][0] : 0.0,
                      k->n_inputs > 2 ? (double)cl[2][0] : 0.0, k->n_inputs > 3 ? (double)cl[3][0] : 0.0,
                      k->n_inputs > 4 ? (double)cl[4][0] : 0.0, k->n_inputs > 5 ? (double)cl[5][0] : 0.0, got,
                      want, fabs(got - want) / fmax(fabs(want), floor_), k->err_f32);
    }
    if (alias && n > 0) { /* out is the very same array as input alias - 1 */
        int w = (alias - 1) % k->n_inputs;
        k->f32_batch(buf[w], ptr, n);
        for (j = 0; j < n; j++)
            if (!same(buf[w][j], out[j]))
                FUZZ_FAIL("%s/%s: out aliasing input %d: sample %zu %a vs %a", port, k->name, w, j, buf[w][j],
                          out[j]);
    }
    for (i = 0; i < k->n_inputs; i++)
        free(base[i]);
    free(base[FACET_MAX_INPUTS]);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static float in[FACET_MAX_INPUTS][MAX_N];
    const facet_kernel *k;
    size_t n, off, j, p;
    int i, alias;
    if (size < 3)
        return 0;
    k = facet_kernel_at(data[0] % facet_kernel_count());
    n = data[1] % (MAX_N + 1);
    off = data[2] & 7;
    alias = (data[2] >> 3) % (FACET_MAX_INPUTS + 1);
    for (j = 0; j < n; j++)
        for (i = 0; i < k->n_inputs; i++) {
            uint32_t w = fuzz_word(data + 3, size - 3, 4 * (j * (size_t)k->n_inputs + (size_t)i));
            memcpy(&in[i][j], &w, sizeof w);
        }
    for (p = 0; p < facet_port_count(); p++) {
        int sup;
        const char *port = facet_port_at(p, &sup, NULL);
        if (!sup)
            continue;
        if (facet_set_port(port) != 0)
            FUZZ_FAIL("%s: supported but not selectable", port);
        run_port(k, port, in, n, off, alias);
    }
    return 0;
}
