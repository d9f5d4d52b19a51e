/* fx_ops_scalar.h - the integer lane op layer (src/fx/fx_ops.h lists the
 * ops and their contracts) on one lane: plain uint32_t / uint64_t C, so the
 * bodies instantiated on it (src/fx/fx_kernels.c, src/fx/fx_fast.c) are the
 * fixed-point specification.  Built from the exact primitives of
 * src/fx/fx_prims.h: products through fxp_mul64 (one UMULL, or four 16x16
 * MULS on ARMv6-M), variable 64-bit shifts from 32-bit ones (no libgcc
 * call on Thumb-1), the 64/32 division and the integer square root the
 * primitives' exact methods (any exact method gives the same bits). */
#ifndef FACET_FX_OPS_SCALAR_H
#define FACET_FX_OPS_SCALAR_H

#include <stdint.h>
#include "fx_prims.h"

typedef int32_t fxv_i32;
typedef uint32_t fxv_u32;
typedef uint64_t fxv_u64;

/* FXV_INLINE the ops, FXV_BODY the precise body's functions (src/fx/fx_ops.h).
 * A kernel inlined whole is the fastest on one lane; at -Os (a firmware
 * build) the pseudo-float ops stay functions, one copy each (fx_kernels.o
 * -Os on Cortex-M4: 8.4 KB against 21 KB inlined). */
#if defined(__GNUC__)
#define FXV_INLINE static inline __attribute__((unused))
#if defined(__OPTIMIZE_SIZE__)
#define FXV_BODY FXV_INLINE
#else
#define FXV_BODY static inline __attribute__((always_inline, unused))
#endif
#else
#define FXV_INLINE static inline
#define FXV_BODY static inline
#endif

/* FXV_T2: M-profile Thumb-2 (Cortex-M3/M4/M7/M33: ARMv7-M, ARMv7E-M,
 * ARMv8-M mainline).  clz and the compare masks (fxv_lt, fxv_lt64) are
 * inline asm (CLZ; CMP [SBCS] SBC), opaque to the optimiser: otherwise
 * gcc 12 turns selects into data-dependent branches (jump threading, e.g.
 * min(clz(x), 31) split at x = 0; sel(lt(a, b), ..) split on a < b: 90
 * conditional branches in the fast kernels at -O2, Cortex-M4).  With them
 * the compiler keeps min, max and the clamps as IT blocks and the fast
 * kernels' machine code has no conditional branch (constant time,
 * checked on the disassembly by tests/suites/51-fx-wcet.sh).  The clamps
 * start with USAT / SSAT (no signed compare).  Each is the same
 * function of its operands as the plain C (exact; the pinned hashes).
 * Measured and not taken (Cortex-M4, arm-none-eabi-gcc 12.2, -O2): min /
 * max / clamp as asm (+3 to +11 instructions in brdf_hammon: the "+r"
 * operands add moves); SMMUL for a high word whose factors the compiler
 * proves below 2^31 (__builtin_constant_p on the range): 3 products in the
 * whole fast tier, none in brdf_hammon, and the guard let jump threading
 * add branches back.  Only where the includer asks for constant time
 * (FXV_CONSTANT_TIME: src/fx/fx_fast.c, the fast tier): the precise tier
 * keeps its data-dependent fix-ups anyway, and the opaque forms cost it
 * 16-64% of its Cortex-M4 instructions (mean of bench/cortexm's inputs). */
#if defined(FXV_CONSTANT_TIME) && !defined(FACET_FX_PORTABLE) && defined(__GNUC__) && defined(__OPTIMIZE__) && \
    defined(__thumb2__) && defined(__ARM_ARCH_PROFILE) && __ARM_ARCH_PROFILE == 'M'
#define FXV_T2 1
#endif

FXV_INLINE fxv_u32 fxv_k32(uint32_t c) { return c; }
#if defined(FXV_T2)
/* USAT #31: max(x, 0) of a signed x; SSAT #31: x held in [-2^30, 2^30) */
FXV_INLINE uint32_t fxv_t2_usat31_(int32_t x)
{
    uint32_t r;
    __asm__("usat\t%0, #31, %1" : "=r"(r) : "r"(x));
    return r;
}
FXV_INLINE int32_t fxv_t2_ssat31_(int32_t x)
{
    int32_t r;
    __asm__("ssat\t%0, #31, %1" : "=r"(r) : "r"(x));
    return r;
}
/* a clamp: USAT #31 (lo = 0) or a signed max, then an unsigned min (gcc
 * branched on the nested signed compare of lov's [-1, 1]) */
FXV_INLINE fxv_u32 fxv_clamp(fxv_i32 x, int32_t lo, int32_t hi)
{
    uint32_t r = __builtin_constant_p(lo) && lo == 0 ? fxv_t2_usat31_(x) : (uint32_t)(x < lo ? lo : x);
    return r > (uint32_t)hi ? (uint32_t)hi : r;
}
/* SSAT #31 (so - lo cannot overflow: |lo|, |hi| < 2^29), - lo, USAT #31,
 * min; USAT #16 alone for a 2^16-wide domain */
FXV_INLINE fxv_u32 fxv_clamp_off(fxv_i32 x, int32_t lo, int32_t hi)
{
    if (__builtin_constant_p(lo) && __builtin_constant_p(hi) && lo > -0x20000000 && hi < 0x20000000) {
        int32_t t = fxv_t2_ssat31_(x) - lo;
        uint32_t r, w = (uint32_t)hi - (uint32_t)lo;
        if (w == 65535u) {
            __asm__("usat\t%0, #16, %1" : "=r"(r) : "r"(t));
            return r;
        }
        r = fxv_t2_usat31_(t);
        return r > w ? w : r;
    }
    return (uint32_t)(x < lo ? lo : x > hi ? hi : x) - (uint32_t)lo;
}
#else
FXV_INLINE fxv_u32 fxv_clamp(fxv_i32 x, int32_t lo, int32_t hi)
{
    return (uint32_t)(x < lo ? lo : x > hi ? hi : x);
}
FXV_INLINE fxv_u32 fxv_clamp_off(fxv_i32 x, int32_t lo, int32_t hi)
{
    return (uint32_t)(x < lo ? lo : x > hi ? hi : x) - (uint32_t)lo;
}
#endif
FXV_INLINE fxv_u32 fxv_add32(fxv_u32 a, fxv_u32 b) { return a + b; }
FXV_INLINE fxv_u32 fxv_sub32(fxv_u32 a, fxv_u32 b) { return a - b; }
FXV_INLINE fxv_u32 fxv_mul32(fxv_u32 a, fxv_u32 b) { return a * b; }
FXV_INLINE fxv_u32 fxv_shr(fxv_u32 a, int k) { return a >> k; }
FXV_INLINE fxv_u32 fxv_shl(fxv_u32 a, int k) { return a << k; }
FXV_INLINE fxv_u32 fxv_shrv(fxv_u32 a, fxv_u32 n) { return a >> n; }
FXV_INLINE fxv_u32 fxv_shlv(fxv_u32 a, fxv_u32 n) { return a << n; }
#if defined(FXV_T2)
/* CLZ gives 32 for 0 */
FXV_INLINE fxv_u32 fxv_clz(fxv_u32 a)
{
    uint32_t r;
    if (__builtin_constant_p(a) != 0)
        return a ? (uint32_t)__builtin_clz(a) : 32u;
    __asm__("clz\t%0, %1" : "=r"(r) : "r"(a));
    return r;
}
#elif !defined(FACET_FX_PORTABLE) && defined(__GNUC__) && \
    (defined(__x86_64__) || defined(__i386__) || defined(__aarch64__) || defined(__ARM_FEATURE_CLZ))
FXV_INLINE fxv_u32 fxv_clz(fxv_u32 a) { return a ? (uint32_t)fxp_clz32(a) : 32u; }
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
FXV_INLINE fxv_u32 fxv_clz(fxv_u32 a)
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
FXV_INLINE fxv_u32 fxv_min(fxv_u32 a, fxv_u32 b) { return a < b ? a : b; }
FXV_INLINE fxv_u32 fxv_max(fxv_u32 a, fxv_u32 b) { return a > b ? a : b; }
#if defined(FXV_T2)
/* CMP then SBC: all ones on a borrow (a < b), else 0 */
FXV_INLINE fxv_u32 fxv_lt(fxv_u32 a, fxv_u32 b)
{
    uint32_t m;
    if (__builtin_constant_p(a) && __builtin_constant_p(b))
        return a < b ? 0xFFFFFFFFu : 0u;
    __asm__("cmp\t%1, %2\n\tsbc\t%0, %0, %0" : "=r"(m) : "r"(a), "rI"(b) : "cc");
    return m;
}
#else
FXV_INLINE fxv_u32 fxv_lt(fxv_u32 a, fxv_u32 b) { return a < b ? 0xFFFFFFFFu : 0u; }
#endif
FXV_INLINE fxv_u32 fxv_sel(fxv_u32 m, fxv_u32 a, fxv_u32 b) { return (a & m) | (b & ~m); }
FXV_INLINE fxv_u32 fxv_and(fxv_u32 a, fxv_u32 b) { return a & b; }
FXV_INLINE fxv_u32 fxv_or(fxv_u32 a, fxv_u32 b) { return a | b; }
FXV_INLINE fxv_u32 fxv_not(fxv_u32 a) { return ~a; }
FXV_INLINE fxv_u32 fxv_lut(const uint32_t *t, fxv_u32 i) { return t[i]; }

FXV_INLINE fxv_u64 fxv_mulw(fxv_u32 a, fxv_u32 b) { return fxp_mul64(a, b); }
FXV_INLINE fxv_u64 fxv_wide(fxv_u32 a) { return a; }
FXV_INLINE fxv_u32 fxv_lo(fxv_u64 a) { return (uint32_t)a; }
FXV_INLINE fxv_u32 fxv_hi(fxv_u64 a) { return (uint32_t)(a >> 32); }
FXV_INLINE fxv_u32 fxv_narrow(fxv_u64 a) { return (uint32_t)a; }
FXV_INLINE fxv_u64 fxv_add64(fxv_u64 a, fxv_u64 b) { return a + b; }
FXV_INLINE fxv_u64 fxv_sub64(fxv_u64 a, fxv_u64 b) { return a - b; }
FXV_INLINE fxv_u64 fxv_shr64(fxv_u64 a, int k) { return a >> k; }
FXV_INLINE fxv_u64 fxv_shl64(fxv_u64 a, int k) { return a << k; }
FXV_INLINE fxv_u64 fxv_shrv64(fxv_u64 a, fxv_u32 n) { return fxp_shr64(a, (int)n); }
FXV_INLINE fxv_u64 fxv_shlv64(fxv_u64 a, fxv_u32 n) { return fxp_shl64(a, (int)n); }
FXV_INLINE fxv_u64 fxv_and64(fxv_u64 a, uint64_t c) { return a & c; }
#if defined(FXV_T2)
/* CMP, SBCS on the high words, SBC: all ones on a borrow */
FXV_INLINE fxv_u32 fxv_lt64(fxv_u64 a, fxv_u64 b)
{
    uint32_t m;
    if (__builtin_constant_p(a) && __builtin_constant_p(b))
        return a < b ? 0xFFFFFFFFu : 0u;
    __asm__("cmp\t%Q1, %Q2\n\tsbcs\t%0, %R1, %R2\n\tsbc\t%0, %0, %0" : "=&r"(m) : "r"(a), "r"(b) : "cc");
    return m;
}
#else
FXV_INLINE fxv_u32 fxv_lt64(fxv_u64 a, fxv_u64 b) { return a < b ? 0xFFFFFFFFu : 0u; }
#endif
/* by words (a 64-bit mask m 0x100000001 is a multiply on Thumb-1) */
FXV_INLINE fxv_u64 fxv_sel64(fxv_u32 m, fxv_u64 a, fxv_u64 b)
{
    uint32_t lo = ((uint32_t)a & m) | ((uint32_t)b & ~m);
    uint32_t hi = ((uint32_t)(a >> 32) & m) | ((uint32_t)(b >> 32) & ~m);
    return ((uint64_t)hi << 32) | lo;
}
FXV_INLINE fxv_u32 fxv_div64(fxv_u32 u1, fxv_u32 u0, fxv_u32 d, fxv_u32 *r) { return fxp_div64(u1, u0, d, r); }
FXV_INLINE fxv_u32 fxv_isqrt64(fxv_u64 x, fxv_u64 *rem) { return facet_fx_isqrt64_rem(x, rem); }

#endif
