/* batch_check.h - the batch mechanics every SoA batch API is held to on a
 * port (tests/f32/test_f32_ports.c for the kernels, tests/sample/
 * test_sample_ports.c for the samplers), to the bit against the full batch:
 * lane independence (sample 0 in every lane position of a short batch,
 * neighbours random), every tail length 0 .. 3W+1 from several starting
 * points, and unaligned buffers.  The caller's run() evaluates n samples
 * of src (SoA, stride BC_MAXN) from `first`, each input copied to a buffer
 * of exactly n floats at float offset `misalign` (so that a sanitizer sees
 * any access past the end), into out[o][0 .. n - 1]. */
#ifndef FACET_TEST_BATCH_CHECK_H
#define FACET_TEST_BATCH_CHECK_H

#include <string.h>

#define BC_MAXN 256
#define BC_MAX_INPUTS 8
#define BC_MAX_OUTPUTS 3

typedef void (*bc_run_fn)(const void *ctx, float src[][BC_MAXN], int first, int n, int misalign,
                          float out[][BC_MAXN]);

typedef struct {
    long lane, tail, align; /* values that differ from the full batch's */
} bc_counts;

static inline int bc_same(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

/* ref holds run(src, 0, BC_MAXN, 0); src is restored */
static inline bc_counts bc_mechanics(bc_run_fn run, const void *ctx, int n_in, int n_out, int lanes,
                                     float src[][BC_MAXN], float ref[][BC_MAXN])
{
    static float out[BC_MAX_OUTPUTS][BC_MAXN];
    bc_counts c = { 0, 0, 0 };
    int i, j, n, o;
    for (j = 0; j < 3 * lanes; j++) {
        float save[BC_MAX_INPUTS];
        for (i = 0; i < n_in; i++) {
            save[i] = src[i][100 + j];
            src[i][100 + j] = src[i][0];
        }
        run(ctx, src, 100, 3 * lanes + 1, 0, out);
        for (o = 0; o < n_out; o++)
            c.lane += !bc_same(out[o][j], ref[o][0]);
        for (i = 0; i < n_in; i++)
            src[i][100 + j] = save[i];
    }
    for (n = 0; n <= 3 * lanes + 1; n++)
        for (j = 0; j < 3; j++) {
            int first = j * 37 % (BC_MAXN - n);
            run(ctx, src, first, n, 0, out);
            for (i = 0; i < n; i++)
                for (o = 0; o < n_out; o++)
                    c.tail += !bc_same(out[o][i], ref[o][first + i]);
        }
    for (j = 1; j < 8; j++) {
        run(ctx, src, 0, 61, j, out);
        for (i = 0; i < 61; i++)
            for (o = 0; o < n_out; o++)
                c.align += !bc_same(out[o][i], ref[o][i]);
    }
    return c;
}

#endif
