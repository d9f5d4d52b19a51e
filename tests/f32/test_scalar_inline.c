/* test_scalar_inline.c - facet/scalar.h inline under the includer's own
 * flags gives, bit for bit, the library's per-sample entry compiled from it
 * with the same ops (src/f32/f32_one_body.h), which test_f32_accuracy and
 * test_f32_bad_input hold to the bounds and the domain contract: every
 * kernel, both tiers, random samples and every bad value in every input.
 * Built plain (the portable ops: against the scalar port's entries) and,
 * on x86-64, once more with -march=x86-64-v3 (SCALAR_INLINE_V3,
 * tests/ports/tails.mk: the FMA ops, rcpss / rsqrtss: against the avx2
 * port's entries; skipped where the CPU has no AVX2). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include "../lib/harness.h"
#include "../lib/sample.h"
#include "facet/scalar.h"
#include "../../src/core/kernel_list.h"

#ifdef SCALAR_INLINE_V3
#define PORT "avx2"
#if !FACET_SCALAR_X86_EST
#error "-march=x86-64-v3 should select scalar.h's x86 FMA ops"
#endif
#else
#define PORT "scalar"
#endif

static int same(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

#define IN_(q) in[q]
#define FACET_KERNEL(name, NAME, n, ...)                                                      \
    static float inl_##name(const float *in) { return facet_##name##_f32_scalar(FACET_EACH_INPUT(n, IN_)); } \
    static float inl_fast_##name(const float *in)                                             \
    {                                                                                         \
        return facet_##name##_f32_fast_scalar(FACET_EACH_INPUT(n, IN_));                      \
    }
#include "../../src/core/kernels.def"
#undef FACET_KERNEL

static const struct { const char *name; float (*f32)(const float *), (*fast)(const float *); } inl[] = {
#define FACET_KERNEL(name, ...) { #name, inl_##name, inl_fast_##name },
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
};

int main(void)
{
    static const float bad[] = { 0.0f, -0.0f, 1.4e-45f, 1e-39f, -1.0f, 2.0f, 1e30f, FLT_MAX, -FLT_MAX,
                                 1.0f / 0.0f, -1.0f / 0.0f, 0.0f / 0.0f };
    const int n_bad = (int)(sizeof bad / sizeof bad[0]);
    smp_rng rng = { 4242 };
    size_t ki;
    th_name = "scalar_inline (" PORT ")";
    if (!facet_port_supported(PORT)) {
        SKIP("port %s: this CPU cannot run it", PORT);
        return th_done();
    }
    CHECK(facet_set_port(PORT) == 0, "cannot select port %s", PORT);
    CHECK(facet_kernel_count() == sizeof inl / sizeof inl[0], "kernel list and table differ");
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const facet_kernel *k = facet_kernel_at(ki);
        int tier, j, pos, b;
        CHECK(!strcmp(k->name, inl[ki].name), "kernel %d: %s vs %s", (int)ki, k->name, inl[ki].name);
        for (tier = 0; tier < 2; tier++) {
            float (*lib)(const float *) = tier ? k->f32_fast : k->f32;
            float (*mine)(const float *) = tier ? inl[ki].fast : inl[ki].f32;
            long differ = 0;
            for (j = 0; j < 20000; j++) {
                float in[FACET_MAX_INPUTS];
                smp_inputs(&rng, k, in);
                if (j % 4 == 3) { /* a bad value in one position */
                    pos = j % k->n_inputs;
                    b = (j / 4) % n_bad;
                    in[pos] = bad[b];
                }
                differ += !same(lib(in), mine(in));
            }
            CHECK(differ == 0, "%s%s: facet/scalar.h inline differs from the %s per-sample entry in %ld of 20000",
                  k->name, tier ? "_fast" : "", PORT, differ);
        }
    }
    facet_set_port("auto");
    return th_done();
}
