/* op_count.h - the counting op layer: the f32 kernel bodies
 * (facet/detail/f32_body.h) and the sampler bodies (f32_sample_body.h)
 * instantiated as count_<name> on scalar floats whose every op is tallied,
 * so that a test can compare one evaluation's count with the "Cost:" of the
 * contract in facet.h (tests/f32/test_op_counts.c, tests/sample/
 * test_sample_prims.c).  Counting rules, as a port with FMA executes them:
 * add, sub, mul, fma, fnma, min, max, sqr_err = 1; clamp = 2 (max, min);
 * sel_lt = 2 (compare, blend); keep_ord = 2 (ordered compare, mask: the NaN
 * rule); the exponent-bit ops exp2i, getexp, getmant = 1; rcp and rsqrt =
 * 1 each, tallied apart (their refinement steps are the port's: see each
 * port header).  The bodies are branch-free, so one evaluation at any
 * inputs gives the count. */
#ifndef FACET_TEST_OP_COUNT_H
#define FACET_TEST_OP_COUNT_H

#include <math.h>
#include "facet.h"

static long n_ops, n_rcp, n_rsqrt;

static float cnt_set(float x) { return x; }
static float cnt_add(float a, float b) { n_ops++; return a + b; }
static float cnt_sub(float a, float b) { n_ops++; return a - b; }
static float cnt_mul(float a, float b) { n_ops++; return a * b; }
static float cnt_fma(float a, float b, float c) { n_ops++; return a * b + c; }
static float cnt_fnma(float a, float b, float c) { n_ops++; return c - a * b; }
static float cnt_min(float a, float b) { n_ops++; return a < b ? a : b; }
static float cnt_max(float a, float b) { n_ops++; return a > b ? a : b; }
static float cnt_sel_lt(float a, float b, float x, float y) { n_ops += 2; return a < b ? x : y; }
static float cnt_clamp(float x, float lo, float hi) { n_ops += 2; x = x > lo ? x : lo; return x < hi ? x : hi; }
static float cnt_keep_ord(float r, float a, float b) { n_ops += 2; return a == a && b == b ? r : 0.0f; }
static float cnt_rcp(float x) { n_rcp++; return 1.0f / x; }
static float cnt_rsqrt(float x) { n_rsqrt++; return 1.0f / (float)sqrt(x); }
static float cnt_sqr_err(float a, float p) { n_ops++; return (float)((double)a * a - p); }
static float cnt_exp2i(float k) { n_ops++; return (float)ldexp(1.0, (int)k); }
static float cnt_getexp(float x) { int e; n_ops++; frexp(x, &e); return (float)(e - 1); }
static float cnt_getmant(float x) { int e; n_ops++; return 2.0f * (float)frexp(x, &e); }

#define FACET_V float
#define FACET_OP(op) cnt_##op
#define FACET_K(k) count_##k
#include "facet/detail/f32_body.h"
#include "facet/detail/f32_sample_body.h"
#undef FACET_V
#undef FACET_OP
#undef FACET_K

/* zero the tallies before an evaluation */
static inline void opc_reset(void) { n_ops = n_rcp = n_rsqrt = 0; }

#endif
