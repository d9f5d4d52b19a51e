/* test_threads.c - the batch API's port choice is made once, thread-safely:
 * threads that all make their first batch call at the same moment (and
 * others that force ports meanwhile) get correct results and no data race
 * (tests/suites/35-tsan.sh runs this under ThreadSanitizer); and a
 * facet_set_port() racing another thread's first batch call is never undone
 * by it (2000 fresh processes, each racing the two once). */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <sys/wait.h>
#include <unistd.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../lib/harness.h"
#include "../lib/sample.h"
#include "facet/fx.h"

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

/* ---- facet_set_port vs another thread's first use -------------------------
 * In a fresh process (nothing chosen yet) thread A makes the first batch
 * call, which computes the automatic choice, while thread B forces "scalar".
 * Whatever the order, B's choice must stand: A may install its choice only
 * over "not chosen".  B waits a round-dependent few iterations so that over
 * the rounds its store lands before, inside and after A's pick. */
/* 2000 rounds; 200 under FACET_TEST_QUICK (sanitizers, qemu-user, where a
 * fork costs 20 ms: the gcc, clang and TSan suites run all 2000) */
static int rounds_(void)
{
    const char *q = getenv("FACET_TEST_QUICK");
    return q && *q && strcmp(q, "0") ? 200 : 2000;
}

static pthread_barrier_t pair;
static volatile unsigned spin_sink;
static unsigned delay;

static void *first_use(void *arg)
{
    float a = 0.5f, o;
    (void)arg;
    pthread_barrier_wait(&pair);
    facet_lambert_f32_batch(&o, &a, 1);
    return NULL;
}

static void *force_scalar(void *arg)
{
    unsigned i;
    (void)arg;
    pthread_barrier_wait(&pair);
    for (i = 0; i < delay; i++)
        spin_sink += i;
    facet_set_port("scalar");
    return NULL;
}

/* the child: 0 if "scalar" stood, 1 if it was lost, 2 on a setup failure */
static int race_once(unsigned round)
{
    pthread_t a, b;
    delay = round % 97;
    if (pthread_barrier_init(&pair, NULL, 2) != 0)
        return 2;
    if (pthread_create(&a, NULL, first_use, NULL) || pthread_create(&b, NULL, force_scalar, NULL))
        return 2;
    pthread_join(a, NULL);
    pthread_join(b, NULL);
    return strcmp(facet_port_name(), "scalar") || strcmp(facet_fx_port_name(), "scalar") ? 1 : 0;
}

static void test_set_port_not_lost(void)
{
    unsigned r, lost = 0, failed = 0, rounds = (unsigned)rounds_();
    for (r = 0; r < rounds; r++) {
        int st = 0;
        pid_t pid;
        fflush(stdout);
        pid = fork();
        if (pid == 0)
            _exit(race_once(r));
        if (pid < 0 || waitpid(pid, &st, 0) != pid || !WIFEXITED(st) || WEXITSTATUS(st) == 2)
            failed++;
        else if (WEXITSTATUS(st) == 1)
            lost++;
    }
    CHECK(failed == 0, "%u of %u race rounds could not run", failed, rounds);
    CHECK(lost == 0, "facet_set_port(\"scalar\") undone by a racing first use in %u of %u rounds",
          lost, rounds);
}

int main(void)
{
    pthread_t t[THREADS];
    smp_rng rng = { 99 };
    const facet_kernel *k = facet_kernel_find("brdf_hammon");
    int i, total = 0;
    th_name = "threads";
    /* first, while this process has chosen nothing: its children start fresh */
    CHECK(strcmp(smp_best_port(), "scalar") != 0 || getenv("FACET_PORT"),
          "the automatic choice differs from scalar, so a lost facet_set_port shows");
    test_set_port_not_lost();
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
