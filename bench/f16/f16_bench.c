/* f16_bench.c - build/facet-f16-bench: the f16 kernels' speed beside f32
 * and f32_fast at the same register width (the avx512 port: 16 f32 lanes
 * per zmm; avx512fp16: 32 binary16 lanes), and the binary16 shader-style
 * peer (peer_f16_shader.c), measured in one run, interleaved: each round
 * times every variant once (R batch calls of N samples), 21 rounds, the
 * median per variant; ratios are of those medians.  Then the peer's
 * accuracy at the same binary16 inputs against the oracle (Inf results,
 * samples beyond 2^-8 relative, max).  Clock: bench/harness/cycles.h.
 * Needs a CPU with AVX-512 FP16 (else it says so and exits 0). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "facet.h"
#include "facet/f16.h"
#include "harness/cycles.h"
#include "f16/f16_peer.h"
#include "../../tests/f16/f16_test.h"

#define N_ 1024
#define ROUNDS_ 21

static int cmp_(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

int main(int argc, char **argv)
{
    long reps = argc > 1 ? atol(argv[1]) : 400;
    size_t ki;
    static float fin[FACET_MAX_INPUTS][N_], fout[N_];
    static facet_f16 hin[FACET_MAX_INPUTS][N_], hout[N_];
    if (!facet_f16_port_supported("avx512fp16") || facet_set_port("avx512") != 0) {
        printf("facet-f16-bench: this CPU cannot run avx512fp16 (%s); nothing measured\n",
               facet_f16_port_refusal("avx512fp16") ? facet_f16_port_refusal("avx512fp16") : "not in this build");
        return 0;
    }
    cyc_init();
    printf("# %s (%s), %d samples per call, %ld calls per timing, %d interleaved rounds, median\n", cyc_unit(),
           cyc_source(), N_, reps, ROUNDS_);
    printf("%-18s %9s %9s %9s %9s  %8s %8s %8s\n", "kernel", "f32", "f32_fast", "f16", "f16_peer", "f16/f32",
           "f16/fast", "f16/peer");
    for (ki = 0; ki < facet_f16_kernel_count(); ki++) {
        const facet_f16_kernel *h = facet_f16_kernel_at(ki);
        const facet_kernel *k = facet_kernel_find(h->name);
        const f16_peer_entry *pe = f16_peer_find(h->name);
        const float *fp[FACET_MAX_INPUTS];
        const facet_f16 *hp[FACET_MAX_INPUTS];
        double t[4][ROUNDS_], med[4];
        smp_rng r;
        int i, v, rd;
        long s;
        if (!h->f16 || !k)
            continue;
        r.s = 42;
        for (s = 0; s < N_; s++) {
            facet_f16 x[FACET_MAX_INPUTS];
            f16t_inputs(&r, k, x);
            for (i = 0; i < k->n_inputs; i++) {
                hin[i][s] = x[i];
                fin[i][s] = facet_f32_from_f16(x[i]);
            }
        }
        for (i = 0; i < k->n_inputs; i++) {
            fp[i] = fin[i];
            hp[i] = hin[i];
        }
        for (rd = 0; rd < ROUNDS_; rd++)
            for (v = 0; v < 4; v++) {
                uint64_t t0;
                long q;
                if (v == 3 && !pe) {
                    t[v][rd] = 0;
                    continue;
                }
                t0 = cyc_now();
                for (q = 0; q < reps; q++) {
                    if (v == 0) k->f32_batch(fout, fp, N_);
                    else if (v == 1) k->f32_fast_batch(fout, fp, N_);
                    else if (v == 2) h->f16_batch(hout, hp, N_);
                    else pe->fn(hout, hp, N_);
                }
                t[v][rd] = (double)(cyc_now() - t0) / ((double)reps * N_);
            }
        for (v = 0; v < 4; v++) {
            qsort(t[v], ROUNDS_, sizeof(double), cmp_);
            med[v] = t[v][ROUNDS_ / 2];
        }
        printf("%-18s %9.3f %9.3f %9.3f %9.3f  %8.2f %8.2f %8.2f\n", h->name, med[0], med[1], med[2], med[3],
               med[0] / med[2], med[1] / med[2], pe ? med[3] / med[2] : 0.0);
    }
    /* the peer's accuracy at binary16 inputs, against the oracle */
    printf("\n# accuracy at binary16 inputs (alpha, N.L, N.V >= 2^-7), 200000 samples; error as facet/f16.h\n");
    printf("%-18s %-9s %8s %10s %10s\n", "kernel", "variant", "Inf/NaN", ">2^-8", "max err");
    for (ki = 0; ki < facet_f16_kernel_count(); ki++) {
        const facet_f16_kernel *h = facet_f16_kernel_at(ki);
        const facet_kernel *k = facet_kernel_find(h->name);
        const f16_peer_entry *pe = f16_peer_find(h->name);
        int i, v;
        if (!h->f16 || !k)
            continue;
        for (v = 0; v < 2; v++) {
            smp_rng r;
            long s, inf = 0, over = 0, total = 200000;
            double max = 0;
            if (v == 1 && !pe)
                continue;
            r.s = 99;
            for (s = 0; s < total; s += N_) {
                const facet_f16 *hp[FACET_MAX_INPUTS];
                double want[N_];
                long j;
                for (j = 0; j < N_; j++) {
                    facet_f16 x[FACET_MAX_INPUTS];
                    double d[FACET_MAX_INPUTS];
                    f16t_inputs(&r, k, x);
                    for (i = 0; i < k->n_inputs; i++) {
                        hin[i][j] = x[i];
                        d[i] = f16t_clamp(k->inputs[i], facet_f32_from_f16(x[i]));
                    }
                    want[j] = k->oracle(d);
                }
                for (i = 0; i < k->n_inputs; i++)
                    hp[i] = hin[i];
                if (v == 0) h->f16_batch(hout, hp, N_);
                else pe->fn(hout, hp, N_);
                for (j = 0; j < N_; j++) {
                    double e;
                    if ((hout[j] & 0x7c00u) == 0x7c00u) {
                        inf++;
                        continue;
                    }
                    e = f16t_err(facet_f32_from_f16(hout[j]), want[j]);
                    over += e > 0x1p-8;
                    if (e > max) max = e;
                }
            }
            printf("%-18s %-9s %7.3f%% %9.3f%% %10.3e\n", h->name, v ? "peer" : "facet", 100.0 * inf / total,
                   100.0 * over / total, max);
        }
    }
    return 0;
}
