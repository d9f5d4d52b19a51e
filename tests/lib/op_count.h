/* op_count.h - the counting op layer: the f32 kernel bodies
 * (facet/detail/f32_body.h, both tiers) and the sampler bodies
 * (f32_sample_body.h) instantiated on scalar floats whose every op is
 * tallied, so that a test can compare one evaluation's count with the
 * "Cost:" and "Budget:" of the contract in facet.h (tests/f32/
 * test_op_counts.c, tests/sample/test_sample_prims.c): count_<name> is the
 * precise tier and the samplers, countf_<name> the fast tier (f32_fast).
 * Counting rules, as a port with FMA executes them:
 * add, sub, mul, fma, fnma, min, max, sqr_err, sqr_sub = 1; clamp = 2 (max, min);
 * sel_lt = 2 (compare, blend); keep_ord = 2 (ordered compare, mask: the NaN
 * rule), keep_ord4 = 3 (two compares, the second under the first one's mask
 * as on avx512, and the mask); the exponent-bit ops exp2i, getexp, getmant
 * = 1; rcp and rsqrt = 1 each in their own tallies (their refinement steps
 * are the port's: see each port header); a quotient div(a, b) and a root
 * sqrt(x) count as what they are on a port without a divide/sqrt unit:
 * 1 op plus a rcp (a * rcp(b)) or an rsqrt (x * rsqrt(x)), and in their
 * own tallies too (n_div, n_sqrt: avx2 and avx512 run them on the divider).
 * The bodies are branch-free, so one evaluation at any inputs gives the
 * count. */
#ifndef FACET_TEST_OP_COUNT_H
#define FACET_TEST_OP_COUNT_H

#include <math.h>
#include "facet.h"

static long n_ops, n_rcp, n_rsqrt, n_div, n_sqrt, n_clamp_ops, n_nan_ops;

/* zero the tallies before an evaluation */
static inline void opc_reset(void) { n_ops = n_rcp = n_rsqrt = n_div = n_sqrt = n_clamp_ops = n_nan_ops = 0; }

static inline float cnt_set(float x) { return x; }
static inline float cnt_add(float a, float b) { n_ops++; return a + b; }
static inline float cnt_sub(float a, float b) { n_ops++; return a - b; }
static inline float cnt_mul(float a, float b) { n_ops++; return a * b; }
static inline float cnt_fma(float a, float b, float c) { n_ops++; return a * b + c; }
static inline float cnt_fnma(float a, float b, float c) { n_ops++; return c - a * b; }
static inline float cnt_min(float a, float b) { n_ops++; return a < b ? a : b; }
static inline float cnt_max(float a, float b) { n_ops++; return a > b ? a : b; }
static inline float cnt_sel_lt(float a, float b, float x, float y) { n_ops += 2; return a < b ? x : y; }
static inline float cnt_clamp(float x, float lo, float hi)
{
    n_ops += 2;
    n_clamp_ops += 2;
    x = x > lo ? x : lo;
    return x < hi ? x : hi;
}
static inline float cnt_keep_ord(float r, float a, float b)
{
    n_ops += 2;
    n_nan_ops += 2;
    return a == a && b == b ? r : 0.0f;
}
static inline float cnt_keep_ord4(float r, float a, float b, float c, float d)
{
    n_ops += 3;
    n_nan_ops += 3;
    return a == a && b == b && c == c && d == d ? r : 0.0f;
}
static inline float cnt_rcp(float x) { n_rcp++; return 1.0f / x; }
static inline float cnt_rsqrt(float x) { n_rsqrt++; return 1.0f / (float)sqrt(x); }
static inline float cnt_div(float a, float b) { n_ops++; n_rcp++; n_div++; return a / b; }
static inline float cnt_sqrt(float x) { n_ops++; n_rsqrt++; n_sqrt++; return (float)sqrt(x); }
/* the fast tier's (the same counts: which estimate it is, is the port's) */
static inline float cnt_rcp_fast(float x) { return cnt_rcp(x); }
static inline float cnt_rsqrt_fast(float x) { return cnt_rsqrt(x); }
static inline float cnt_div_fast(float a, float b) { return cnt_div(a, b); }
static inline float cnt_sqrt_fast(float x) { return cnt_sqrt(x); }
static inline float cnt_sqr_err(float a, float p) { n_ops++; return (float)((double)a * a - p); }
static inline float cnt_sqr_sub(float a, float c) { n_ops++; return (float)(c - (double)a * a); }
static inline float cnt_exp2i(float k) { n_ops++; return (float)ldexp(1.0, (int)k); }
static inline float cnt_getexp(float x) { int e; n_ops++; frexp(x, &e); return (float)(e - 1); }
static inline float cnt_getmant(float x) { int e; n_ops++; return 2.0f * (float)frexp(x, &e); }

#define FACET_V float
#define FACET_OP(op) cnt_##op
#define FACET_K(k) count_##k
#include "facet/detail/f32_body.h"
#include "facet/detail/f32_sample_body.h"
#undef FACET_K
#define FACET_TIER_FAST 1
#define FACET_K(k) countf_##k
#include "facet/detail/f32_body.h"
#undef FACET_TIER_FAST
#undef FACET_V
#undef FACET_OP
#undef FACET_K

#endif
