/* percall.h - the per-call comparison of `facet-bench api` (issue 26): one
 * sample per iteration of a loop of independent calls, brdf_hammon's
 * inputs as six arrays (in[0..5] = N.L, N.V, L.V, alpha, f0, albedo).
 * Each loop lives in an object built with its own flags (bench/bench.mk),
 * none vectorized (-fno-tree-vectorize: a rasterizer's per-pixel shading
 * is not), on x86 for -march=x86-64-v3, elsewhere -march=native:
 *   percall_peer          the engine-style formula (peers_shader.c's
 *                         brdf_hammon peer), -O2 -ffast-math
 *   percall_scalar_h[_fast]  facet/scalar.h inline, -O2 (no fast-math)
 * The library's per-sample calls are timed from api_bench.c. */
#ifndef FACET_BENCH_PERCALL_H
#define FACET_BENCH_PERCALL_H

#include <stddef.h>

void percall_peer(float *out, const float *const *in, size_t n);
void percall_scalar_h(float *out, const float *const *in, size_t n);
void percall_scalar_h_fast(float *out, const float *const *in, size_t n);
extern const char percall_march[]; /* the -march of both objects */

#endif
