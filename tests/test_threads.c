/* test_threads.c - the batch API's port choice is made once, thread-safely:
 * threads that all make their first batch call at the same moment (and
 * others that force ports meanwhile) get correct results and no data race
 * (tests/suites/35-tsan.sh runs this under ThreadSanitizer). */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "harness.h"
#include "sample.h"

#define N 4096
#define THREADS 8

static float nl[N], nv[N], lv[N], al[N], f0[N], alb[N], ref[N];
static pthread_barrier_t start;
static int bad[THREADS];

static void *worker(void *arg)
{
    int id = (int)(size_t)arg, rep, i;
    float out[N];
    pthread_barrier_wait(&start);
    for (rep = 0; rep < 20; rep++) {
        if (id == THREADS - 1 && rep % 2) /* one thread keeps switching ports */
            facet_set_port(rep % 4 == 1 ? "scalar" : "auto");
        facet_brdf_hammon_f32_batch(out, nl, nv, lv, al, f0, alb, N);
        for (i = 0; i < N; i++)
            if (!(fabsf(out[i] - ref[i]) <= 2 * FACET_ERR_BRDF_HAMMON_F32 * ref[i] + 1e-30f))
                bad[id]++;
        (void)facet_port_name();
    }
    return NULL;
}

int main(void)
{
    pthread_t t[THREADS];
    smp_rng rng = { 99 };
    const facet_kernel *k = facet_kernel_find("brdf_hammon");
    int i, total = 0;
    th_name = "threads";
    for (i = 0; i < N; i++) {
        float in[6] = { 0 };
        smp_inputs(&rng, k, in);
        nl[i] = in[0]; nv[i] = in[1]; lv[i] = in[2]; al[i] = in[3]; f0[i] = in[4]; alb[i] = in[5];
        ref[i] = facet_brdf_hammon_f32(in[0], in[1], in[2], in[3], in[4], in[5]);
    }
    /* no batch call before the threads start: they race on the first choice */
    pthread_barrier_init(&start, NULL, THREADS);
    for (i = 0; i < THREADS; i++)
        CHECK(pthread_create(&t[i], NULL, worker, (void *)(size_t)i) == 0, "thread %d starts", i);
    for (i = 0; i < THREADS; i++) {
        pthread_join(t[i], NULL);
        total += bad[i];
    }
    pthread_barrier_destroy(&start);
    CHECK(total == 0, "%d results out of bound across %d threads racing on the first call", total, THREADS);
    facet_set_port("auto");
    CHECK(strcmp(facet_port_name(), smp_best_port()) == 0 || getenv("FACET_PORT"),
          "after the race the automatic choice is the best port (%s)", facet_port_name());
    return th_done();
}
