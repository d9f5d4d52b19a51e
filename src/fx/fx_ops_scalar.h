/* fx_ops_scalar.h - the lane op layer of src/fx/fx_body.h on one lane: plain
 * uint32_t / uint64_t C, the fixed-point specification.  Products go
 * through fx_mul64 (one UMULL, or four 16x16 MULS on ARMv6-M). */
#ifndef FACET_FX_OPS_SCALAR_H
#define FACET_FX_OPS_SCALAR_H

#include <stdint.h>
#include "fx_prims.h"

typedef int32_t fxv_i32;
typedef uint32_t fxv_u32;
typedef uint64_t fxv_u64;

static inline fxv_u32 fxv_k32(uint32_t c) { return c; }
static inline fxv_u32 fxv_clamp(fxv_i32 x, int32_t lo, int32_t hi)
{
    return (uint32_t)(x < lo ? lo : x > hi ? hi : x);
}
static inline fxv_u32 fxv_add32(fxv_u32 a, fxv_u32 b) { return a + b; }
static inline fxv_u32 fxv_sub32(fxv_u32 a, fxv_u32 b) { return a - b; }
static inline fxv_u32 fxv_mul32(fxv_u32 a, fxv_u32 b) { return a * b; }
static inline fxv_u64 fxv_mulw(fxv_u32 a, fxv_u32 b) { return fx_mul64(a, b); }
static inline fxv_u64 fxv_add64(fxv_u64 a, fxv_u64 b) { return a + b; }
static inline fxv_u64 fxv_shr64(fxv_u64 a, int k) { return a >> k; }
static inline fxv_u64 fxv_and64(fxv_u64 a, uint64_t c) { return a & c; }
static inline fxv_u32 fxv_lo(fxv_u64 a) { return (uint32_t)a; }
static inline fxv_u32 fxv_hi(fxv_u64 a) { return (uint32_t)(a >> 32); }
static inline fxv_u32 fxv_narrow(fxv_u64 a) { return (uint32_t)a; }
/* the fast tier's ops (src/fx/fx_fast_body.h) */
static inline fxv_u32 fxv_shr(fxv_u32 a, int k) { return a >> k; }
static inline fxv_u32 fxv_shl(fxv_u32 a, int k) { return a << k; }
static inline fxv_u32 fxv_shrv(fxv_u32 a, fxv_u32 n) { return a >> n; }
static inline fxv_u32 fxv_shlv(fxv_u32 a, fxv_u32 n) { return a << n; }
#if !defined(FACET_FX_PORTABLE) && defined(__GNUC__) && \
    (defined(__x86_64__) || defined(__i386__) || defined(__aarch64__) || defined(__ARM_FEATURE_CLZ))
static inline fxv_u32 fxv_clz(fxv_u32 a) { return a ? (uint32_t)fx_clz32(a) : 32u; }
#else
/* no clz instruction (ARMv6-M, RV32IMC, FACET_FX_PORTABLE): two halving
 * steps and a byte table, the same counts (clz is exact) */
static const uint8_t fxv_clz8_[256] = {
    8, 7, 6, 6, 5, 5, 5, 5, 4, 4, 4, 4, 4, 4, 4, 4, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3,
    2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2,
    1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
    1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
};
static inline fxv_u32 fxv_clz(fxv_u32 a)
{
    uint32_t n = 0;
    if (a < 0x10000u) {
        n = 16;
        a <<= 16;
    }
    if (a < 0x1000000u) {
        n += 8;
        a <<= 8;
    }
    return n + fxv_clz8_[a >> 24];
}
#endif
static inline fxv_u32 fxv_min(fxv_u32 a, fxv_u32 b) { return a < b ? a : b; }
static inline fxv_u32 fxv_max(fxv_u32 a, fxv_u32 b) { return a > b ? a : b; }
static inline fxv_u32 fxv_lt(fxv_u32 a, fxv_u32 b) { return a < b ? 0xFFFFFFFFu : 0u; }
static inline fxv_u32 fxv_sel(fxv_u32 m, fxv_u32 a, fxv_u32 b) { return (a & m) | (b & ~m); }
static inline fxv_u32 fxv_and(fxv_u32 a, fxv_u32 b) { return a & b; }
static inline fxv_u32 fxv_not(fxv_u32 a) { return ~a; }
static inline fxv_u32 fxv_or(fxv_u32 a, fxv_u32 b) { return a | b; }
static inline fxv_u32 fxv_clamp_off(fxv_i32 x, int32_t lo, int32_t hi)
{
    return (uint32_t)(x < lo ? lo : x > hi ? hi : x) - (uint32_t)lo;
}
static inline fxv_u32 fxv_lut(const uint32_t *t, fxv_u32 i) { return t[i]; }

#endif
