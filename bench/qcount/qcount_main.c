/* qcount_main.c - brdf_hammon's batch functions, one port and tier at a
 * time, each call between two marker functions, for counting executed
 * instructions under qemu (bench/qcount/qcount.sh cuts the trace at the
 * markers).  Calls the port tables directly (src/core/port.h), so the
 * dispatcher's pointer load is not counted.  N samples per call. */
#include <stdint.h>
#include <stdio.h>
#include "facet.h"
#include "facet/fx.h"
#include "../../src/core/port.h"

#define N 64

/* one marker call before and after each counted batch call: qcount.sh
 * counts the instructions executed from the first to the second */
__attribute__((noinline)) void qcount_begin(int id);
__attribute__((noinline)) void qcount_end(int id);
__attribute__((noinline)) void qcount_begin(int id) { __asm__ volatile("" : : "r"(id) : "memory"); }
__attribute__((noinline)) void qcount_end(int id) { __asm__ volatile("" : : "r"(id) : "memory"); }

static float in[6][N], out[N];
static int32_t qin[6][N];
static uint64_t qout[N];

int main(void)
{
    uint32_t s = 12345;
    int i, j;
    for (j = 0; j < 6; j++)
        for (i = 0; i < N; i++) {
            float u;
            s = s * 1664525u + 1013904223u;
            u = (float)(s >> 8) / 16777216.0f;
            in[j][i] = j == 2 ? 2.0f * u - 1.0f : j == 3 ? 0.02f + 0.98f * u : 0.05f + 0.95f * u;
            qin[j][i] = (int32_t)(in[j][i] * 32768.0f);
        }
    /* 0 f32 scalar, 1 f32_fast scalar, 2 fx_fast scalar, then the vector
     * port's f32, f32_fast, fx_fast (QCOUNT_F32 / QCOUNT_FX name its tables) */
    qcount_begin(0);
    facet_port_scalar_f32.brdf_hammon(out, in[0], in[1], in[2], in[3], in[4], in[5], N);
    qcount_end(0);
    qcount_begin(1);
    facet_port_scalar_f32_fast.brdf_hammon(out, in[0], in[1], in[2], in[3], in[4], in[5], N);
    qcount_end(1);
    qcount_begin(2);
    facet_fx_fast_port_scalar.brdf_hammon(qout, qin[0], qin[1], qin[2], qin[3], qin[4], qin[5], N);
    qcount_end(2);
    qcount_begin(3);
    QCOUNT_F32.brdf_hammon(out, in[0], in[1], in[2], in[3], in[4], in[5], N);
    qcount_end(3);
    qcount_begin(4);
    QCOUNT_F32_FAST.brdf_hammon(out, in[0], in[1], in[2], in[3], in[4], in[5], N);
    qcount_end(4);
    qcount_begin(5);
    QCOUNT_FX_FAST.brdf_hammon(qout, qin[0], qin[1], qin[2], qin[3], qin[4], qin[5], N);
    qcount_end(5);
    printf("qcount: %g %llu\n", (double)out[0], (unsigned long long)qout[0]);
    return 0;
}
