/* test_tails.c - the tail helpers of the inline port headers
 * (facet_<port>_load_n / _store_n): a caller's loop over any n, whole
 * vectors then one masked or scalar-finished tail, gives the library's
 * batch on the same port bit for bit, at every n mod the lane count (0 to
 * 4W + 1), from exact-size buffers (nothing read or written past n: a
 * guard after the output, and the sanitizer builds), with out == an input.
 * Built once per port: TAILS_AVX2 / TAILS_AVX512 with their ISA flags
 * (tests/ports/tails.mk), otherwise the baseline vector port of the target
 * (sse2 on x86-64, neon where __ARM_NEON with FMA); for rvv: its
 * strip-mined loop (facet_rvv_vl / load / store), built by tests/ports/rvv.mk. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../lib/harness.h"
#include "facet.h"

#if defined(TAILS_AVX512)
#include "facet/avx512.h"
#define PORT "avx512"
#define W 16
#define V __m512
#define LOAD _mm512_loadu_ps
#define STORE _mm512_storeu_ps
#define LOAD_N facet_avx512_load_n
#define STORE_N facet_avx512_store_n
#define BRDF facet_brdf_hammon_f32_avx512
#define GGX facet_ggx_d_f32_fast_avx512
#elif defined(TAILS_AVX2)
#include "facet/avx2.h"
#define PORT "avx2"
#define W 8
#define V __m256
#define LOAD _mm256_loadu_ps
#define STORE _mm256_storeu_ps
#define LOAD_N facet_avx2_load_n
#define STORE_N facet_avx2_store_n
#define BRDF facet_brdf_hammon_f32_avx2
#define GGX facet_ggx_d_f32_fast_avx2
#elif defined(__SSE2__)
#include "facet/sse2.h"
#define PORT "sse2"
#define W 4
#define V __m128
#define LOAD _mm_loadu_ps
#define STORE _mm_storeu_ps
#define LOAD_N facet_sse2_load_n
#define STORE_N facet_sse2_store_n
#define BRDF facet_brdf_hammon_f32_sse2
#define GGX facet_ggx_d_f32_fast_sse2
#elif defined(__ARM_FEATURE_MVE) && (__ARM_FEATURE_MVE & 2)
#include "facet/helium.h"
#define PORT "helium"
#define W 4
#define V float32x4_t
#define LOAD vld1q_f32
#define STORE vst1q_f32
#define LOAD_N facet_helium_load_n
#define STORE_N facet_helium_store_n
#define BRDF facet_brdf_hammon_f32_helium
#define GGX facet_ggx_d_f32_fast_helium
#elif defined(__riscv_vector)
/* vector-length agnostic: W is VLMAX, read at run time (after the CPU
 * check); the caller's loop is strip-mined, each strip loaded and stored
 * with its own vl, so there is no separate tail (tests/ports/rvv.mk, clang) */
#include "facet/rvv.h"
#define PORT "rvv"
#define W ((size_t)facet_rvv_vlmax())
#define STRIP_MINED 1
#define BRDF facet_brdf_hammon_f32_rvv
#define GGX facet_ggx_d_f32_fast_rvv
#elif defined(__ARM_NEON) && (defined(__aarch64__) || defined(__ARM_FEATURE_FMA))
#include "facet/neon.h"
#define PORT "neon"
#define W 4
#define V float32x4_t
#define LOAD vld1q_f32
#define STORE vst1q_f32
#define LOAD_N facet_neon_load_n
#define STORE_N facet_neon_store_n
#define BRDF facet_brdf_hammon_f32_neon
#define GGX facet_ggx_d_f32_fast_neon
#endif

#ifdef PORT
static int same(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

static float frand_(unsigned *s, float lo, float hi)
{
    *s = *s * 1664525u + 1013904223u;
    return lo + (hi - lo) * (float)(*s >> 8) / 16777216.0f;
}

#if defined(STRIP_MINED)
#define LD_(q) facet_rvv_load(x[q] + i, vl)
static void loop6(float *out, float *const x[6], size_t n)
{
    size_t i, vl;
    for (i = 0; i < n; i += vl) {
        vl = facet_rvv_vl(n - i);
        facet_rvv_store(out + i, BRDF(LD_(0), LD_(1), LD_(2), LD_(3), LD_(4), LD_(5)), vl);
    }
}

static void loop2(float *out, float *const x[2], size_t n)
{
    size_t i, vl;
    for (i = 0; i < n; i += vl) {
        vl = facet_rvv_vl(n - i);
        facet_rvv_store(out + i, GGX(LD_(0), LD_(1)), vl);
    }
}
#else
/* the caller's loop: brdf_hammon over n samples */
static void loop6(float *out, float *const x[6], size_t n)
{
    size_t i;
    for (i = 0; i + W <= n; i += W)
        STORE(out + i, BRDF(LOAD(x[0] + i), LOAD(x[1] + i), LOAD(x[2] + i), LOAD(x[3] + i), LOAD(x[4] + i),
                            LOAD(x[5] + i)));
    if (i < n) {
        size_t r = n - i;
        STORE_N(out + i, BRDF(LOAD_N(x[0] + i, r), LOAD_N(x[1] + i, r), LOAD_N(x[2] + i, r),
                              LOAD_N(x[3] + i, r), LOAD_N(x[4] + i, r), LOAD_N(x[5] + i, r)), r);
    }
}

static void loop2(float *out, float *const x[2], size_t n)
{
    size_t i;
    for (i = 0; i + W <= n; i += W)
        STORE(out + i, GGX(LOAD(x[0] + i), LOAD(x[1] + i)));
    if (i < n)
        STORE_N(out + i, GGX(LOAD_N(x[0] + i, n - i), LOAD_N(x[1] + i, n - i)), n - i);
}
#endif

int main(void)
{
    unsigned seed = 7;
    size_t n;
    int bad = 0, guard = 0, alias = 0, k;
    th_name = "tails_" PORT;
    if (!facet_port_supported(PORT) || facet_set_port(PORT) != 0) {
        SKIP("port %s: this CPU cannot run it", PORT);
        return th_done();
    }
    for (n = 0; n <= 4 * W + 1; n++) {
        float *x[6], *out = malloc((n + 1) * sizeof(float)), *ref = malloc((n + 1) * sizeof(float));
        for (k = 0; k < 6; k++) {
            size_t i;
            x[k] = malloc(n * sizeof(float) + 1); /* exact size: nothing may be read past n */
            for (i = 0; i < n; i++)
                x[k][i] = k == 2 ? frand_(&seed, -1.0f, 1.0f) : frand_(&seed, 0.0f, 1.0f);
        }
        out[n] = 1234.5f;
        loop6(out, x, n);
        facet_brdf_hammon_f32_batch(ref, x[0], x[1], x[2], x[3], x[4], x[5], n);
        for (k = 0; k < (int)n; k++)
            bad += !same(out[k], ref[k]);
        guard += !same(out[n], 1234.5f);
        loop2(out, x, n);
        facet_ggx_d_f32_fast_batch(ref, x[0], x[1], n);
        for (k = 0; k < (int)n; k++)
            bad += !same(out[k], ref[k]);
        guard += !same(out[n], 1234.5f);
        /* out is the first input */
        facet_brdf_hammon_f32_batch(ref, x[0], x[1], x[2], x[3], x[4], x[5], n);
        loop6(x[0], x, n);
        for (k = 0; k < (int)n; k++)
            alias += !same(x[0][k], ref[k]);
        for (k = 0; k < 6; k++)
            free(x[k]);
        free(out);
        free(ref);
    }
    CHECK(bad == 0, "%s: a caller's loop with the tail helpers differs from the batch (%d values)", PORT, bad);
    CHECK(guard == 0, "%s: store_n wrote past n (%d)", PORT, guard);
    CHECK(alias == 0, "%s: out == an input changes results (%d)", PORT, alias);
    return th_done();
}
#else
int main(void)
{
    th_name = "tails";
    SKIP("no vector port header for this target's baseline flags");
    return th_done();
}
#endif
