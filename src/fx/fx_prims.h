/* fx_prims.h - the exact scalar integer primitives of the fixed-point
 * kernels (fxp_*; the out-of-line ones facet_fx_* in src/fx/fx_prims.c).
 * Private to the library.  Integer arithmetic only: no float, no libgcc
 * helper (so a freestanding RV32IMC or ARMv6-M link needs nothing but this
 * code), a division instruction only where the core has one (fxp_div64).
 * The one-lane op layer (src/fx/fx_ops_scalar.h) is built from these; the
 * bodies never call them directly.
 *
 * Rounding rule, the only one used anywhere in the fx kernels:
 *   every value that loses bits is rounded to nearest, ties up (toward
 *   +infinity): round(x / 2^k) = (x >> k) + ((x >> (k - 1)) & 1), which is
 *   floor(x / 2^k + 1/2) and cannot overflow.  Quotients and square roots
 *   are computed exactly (floor + remainder) and rounded by the same rule.
 * Every helper is monotone non-decreasing in each argument (the reciprocal
 * non-increasing), so a formula built from monotone pieces stays monotone.
 */
#ifndef FACET_FX_PRIMS_H
#define FACET_FX_PRIMS_H

#include <stdint.h>

/* ---- 32x32 -> 64 multiply ---------------------------------------------
 * ARMv6-M (Cortex-M0) has only MULS (32x32 -> low 32): there the product
 * is assembled from four 16x16 partial products, so no __aeabi_lmul call.
 * Both versions return the exact product; tests/fx/test_fx_prims.c checks it. */
static inline uint64_t fxp_mul64_portable(uint32_t a, uint32_t b)
{
    uint32_t al = a & 0xFFFFu, ah = a >> 16, bl = b & 0xFFFFu, bh = b >> 16;
    uint32_t ll = al * bl, lh = al * bh, hl = ah * bl, hh = ah * bh;
    uint32_t mid = lh + (ll >> 16);          /* < 2^32: (2^16-1)^2 + 2^16 */
    uint32_t mid2 = hl + (mid & 0xFFFFu);    /* < 2^32 likewise */
    uint32_t hi = hh + (mid >> 16) + (mid2 >> 16);
    uint32_t lo = (mid2 << 16) | (ll & 0xFFFFu);
    return ((uint64_t)hi << 32) | lo;
}

#if defined(__ARM_ARCH_6M__) || defined(__ARM_ARCH_6SM__) || defined(FACET_FX_PORTABLE)
#define fxp_mul64 fxp_mul64_portable
#else
static inline uint64_t fxp_mul64_native(uint32_t a, uint32_t b) { return (uint64_t)a * b; }
#define fxp_mul64 fxp_mul64_native
#endif

/* ---- count leading zeros (x != 0) ------------------------------------------
 * The builtin only where it is one instruction; ARMv6-M and RV32IMC have
 * none (the builtin would call __clzsi2), so they take the portable binary
 * search. */
static inline int fxp_clz32_portable(uint32_t x)
{
    int n = 0;
    if (!(x & 0xFFFF0000u)) { n += 16; x <<= 16; }
    if (!(x & 0xFF000000u)) { n += 8; x <<= 8; }
    if (!(x & 0xF0000000u)) { n += 4; x <<= 4; }
    if (!(x & 0xC0000000u)) { n += 2; x <<= 2; }
    if (!(x & 0x80000000u)) { n += 1; }
    return n;
}

#if !defined(FACET_FX_PORTABLE) && defined(__GNUC__) && \
    (defined(__x86_64__) || defined(__i386__) || defined(__aarch64__) || defined(__ARM_FEATURE_CLZ))
static inline int fxp_clz32_builtin(uint32_t x) { return __builtin_clz(x); }
#define fxp_clz32 fxp_clz32_builtin
#else
#define fxp_clz32 fxp_clz32_portable
#endif

static inline int fxp_clz64(uint64_t x) /* x != 0 */
{
    uint32_t hi = (uint32_t)(x >> 32);
    return hi ? fxp_clz32(hi) : 32 + fxp_clz32((uint32_t)x);
}

/* 64-bit shifts by a variable amount built from 32-bit ones (a variable
 * 64-bit shift is a libgcc call on Thumb-1).  0 <= k <= 63. */
static inline uint64_t fxp_shl64(uint64_t x, int k)
{
    uint32_t hi = (uint32_t)(x >> 32), lo = (uint32_t)x;
    if (k == 0)
        return x;
    if (k >= 32)
        return (uint64_t)(lo << (k - 32)) << 32;
    return ((uint64_t)((hi << k) | (lo >> (32 - k))) << 32) | (uint32_t)(lo << k);
}

static inline uint64_t fxp_shr64(uint64_t x, int k)
{
    uint32_t hi = (uint32_t)(x >> 32), lo = (uint32_t)x;
    if (k == 0)
        return x;
    if (k >= 32)
        return hi >> (k - 32);
    return ((uint64_t)(hi >> k) << 32) | ((lo >> k) | (hi << (32 - k)));
}

/* round(x / 2^k), ties up, 1 <= k <= 63 */
static inline uint64_t fxp_rshr64(uint64_t x, int k)
{
    return fxp_shr64(x, k) + (fxp_shr64(x, k - 1) & 1u);
}

/* ---- the shared reciprocal, division and square root (src/fx/fx_prims.c) ---- */

/* v = floor((2^64 - 1) / d) - 2^32 for d in [2^31, 2^32): the reciprocal in
 * the form the 2-by-1 division uses.  Table + 3 Newton steps + exact fix. */
uint32_t facet_fx_rcp32(uint32_t d);

/* y ~ 2^47 / sqrt(x) for x in [2^30, 2^32), |error| <= 2^-29 relative.
 * Table + 3 Newton steps (the square root is then fixed exactly). */
uint32_t facet_fx_rsqrt32(uint32_t x);

/* q = floor((u1 2^32 + u0) / d), *r = the remainder; needs d in [2^31, 2^32),
 * u1 < d and v = facet_fx_rcp32(d).  Exact (Moller-Granlund, 2 fix-ups). */
uint32_t facet_fx_div2by1(uint32_t u1, uint32_t u0, uint32_t d, uint32_t v, uint32_t *r);

/* floor(sqrt(x)), exact, any x. */
uint32_t facet_fx_isqrt64(uint64_t x);

/* floor(sqrt(x)) and the remainder x - g^2 in *rem. */
uint32_t facet_fx_isqrt64_rem(uint64_t x, uint64_t *rem);

/* round(sqrt(x)), ties up (sqrt is never exactly k + 1/2 for integer x). */
static inline uint64_t fxp_isqrt64_rnd(uint64_t x)
{
    uint64_t rem;
    uint32_t g = facet_fx_isqrt64_rem(x, &rem);
    return (uint64_t)g + (rem > g);
}

/* ---- the exact 2-by-1 division the kernels use ---------------------------
 * fxp_div64(u1, u0, d, &r) = floor((u1 2^32 + u0) / d), r the remainder, for
 * d in [2^31, 2^32) and u1 < d: the same exact quotient and remainder on
 * every target, computed the cheapest way the core allows:
 *   64-bit hosts (x86-64, aarch64)   the native 64-by-64 division
 *   a 32-bit UDIV (Cortex-M3/M4/M7/M33: __ARM_FEATURE_IDIV)
 *                                    fxp_div64_udiv: schoolbook with two
 *                                    16-bit quotient digits (Knuth's D,
 *                                    Hacker's Delight divlu), each digit
 *                                    from one UDIV and at most 2 corrections
 *   otherwise (Cortex-M0, armv7-A without IDIV, RV32, FACET_FX_PORTABLE)
 *                                    facet_fx_rcp32 + facet_fx_div2by1
 * A quotient computed exactly has the same bits however it is computed;
 * tests/fx/test_fx_prims.c checks fxp_div64_udiv (host UDIV) against 128-bit
 * references and the pinned hashes run every variant. */
static inline uint32_t fxp_div64_udiv(uint32_t u1, uint32_t u0, uint32_t d, uint32_t *r)
{
    uint32_t dh = d >> 16, dl = d & 0xFFFFu, n1 = u0 >> 16, n0 = u0 & 0xFFFFu;
    uint32_t q1, q0, rhat, u21;
    q1 = u1 / dh; /* u1 < d: the true digit is < 2^16, q1 exceeds it by <= 2 */
    rhat = u1 - q1 * dh;
    while (q1 > 0xFFFFu || q1 * dl > ((rhat << 16) | n1)) {
        q1--;
        rhat += dh;
        if (rhat > 0xFFFFu)
            break;
    }
    u21 = ((u1 << 16) | n1) - q1 * d; /* the partial remainder, < d (mod 2^32) */
    q0 = u21 / dh;
    rhat = u21 - q0 * dh;
    while (q0 > 0xFFFFu || q0 * dl > ((rhat << 16) | n0)) {
        q0--;
        rhat += dh;
        if (rhat > 0xFFFFu)
            break;
    }
    *r = ((u21 << 16) | n0) - q0 * d;
    return (q1 << 16) | q0;
}

/* floor(sqrt(x)) and x - g^2 (*rem) for x = hi 2^32 + lo in [2^62, 2^64)
 * with 32-bit divisions: the 16-bit root s1 of hi (seed from the rsqrt
 * table, two integer Newton steps, which approach floor(sqrt(hi)) from
 * above, then a final decrement check), then one more 16-bit digit by
 * Zimmermann's Karatsuba square root step: q = (r1 2^16 + x1) / (2 s1),
 * S = s1 2^16 + q, R = u 2^16 + x0 - q^2, and one correction if R < 0
 * (exact for hi >= 2^30).  Checked against facet_fx_isqrt64's reference
 * path in tests/fx/test_fx_prims.c. */
static inline uint32_t fxp_sqrtrem64n_udiv(uint32_t hi, uint32_t lo, uint64_t *rem, const uint16_t *seed)
{
    uint32_t s1, r1, h, q, u;
    uint64_t S;
    uint64_t top, qq;
    int64_t R;
    s1 = ((hi >> 16) * seed[(hi >> 27) - 8u]) >> 15; /* ~ sqrt(hi), 2^-6.5 relative */
    s1 = (s1 + hi / s1) >> 1;                        /* >= floor(sqrt(hi)) */
    s1 = (s1 + hi / s1) >> 1;
    if (s1 > 0xFFFFu)
        s1 = 0xFFFFu; /* floor(sqrt(hi)) <= 2^16 - 1 */
    while (s1 * s1 > hi)
        s1--;
    r1 = hi - s1 * s1; /* <= 2 s1 */
    h = (r1 << 15) | (lo >> 17); /* floor((r1 2^16 + x1) / 2) < 2^32 */
    q = h / s1;
    u = ((h - q * s1) << 1) | ((lo >> 16) & 1u); /* (r1 2^16 + x1) mod 2 s1 */
    S = ((uint64_t)s1 << 16) + q;
    top = ((uint64_t)u << 16) | (lo & 0xFFFFu); /* named: a composite cast (MISRA 10.8) */
    qq = (uint64_t)q * q;
    R = (int64_t)top - (int64_t)qq;
    if (R < 0) {
        R += (int64_t)(S << 1) - 1;
        S--;
    }
    *rem = (uint64_t)R;
    return (uint32_t)S;
}

#if !defined(FACET_FX_PORTABLE) && (defined(__x86_64__) || defined(__aarch64__) || defined(__ARM_FEATURE_IDIV))
#define FXP_HAVE_UDIV32 1 /* a 32-bit divide instruction (facet_fx_isqrt64_rem) */
#endif

#if !defined(FACET_FX_PORTABLE) && (defined(__x86_64__) || defined(__aarch64__))
static inline uint32_t fxp_div64_native(uint32_t u1, uint32_t u0, uint32_t d, uint32_t *r)
{
    uint64_t u = ((uint64_t)u1 << 32) | u0;
    *r = (uint32_t)(u % d);
    return (uint32_t)(u / d);
}
#define fxp_div64 fxp_div64_native
#elif !defined(FACET_FX_PORTABLE) && defined(__ARM_FEATURE_IDIV)
#define fxp_div64 fxp_div64_udiv
#else
static inline uint32_t fxp_div64_rcp(uint32_t u1, uint32_t u0, uint32_t d, uint32_t *r)
{
    return facet_fx_div2by1(u1, u0, d, facet_fx_rcp32(d), r);
}
#define fxp_div64 fxp_div64_rcp
#endif

/* ---- seed tables (src/fx/fx_prims.c), the one list of their values: the
 * scalar primitives and any table a port keeps initialise
 * from these.  FXP_RCP_SEED_VALUES[i] = round(2^15 / ((i + 32.5) / 64)),
 * FXP_RSQRT_SEED_VALUES[i] = round(2^15 / sqrt((i + 8.5) / 32)). */
#define FXP_RCP_SEED_VALUES                                                                  \
    64528, 62602, 60787, 59075, 57456, 55924, 54471, 53092, 51782, 50534, 49345, 48210,     \
    47127, 46091, 45100, 44151, 43240, 42367, 41528, 40721, 39946, 39199, 38480, 37787,     \
    37118, 36472, 35849, 35246, 34664, 34100, 33554, 33026
#define FXP_RSQRT_SEED_VALUES                                                                \
    63579, 60140, 57205, 54661, 52429, 50450, 48679, 47082, 45633, 44310, 43096, 41977,     \
    40940, 39977, 39078, 38238, 37449, 36708, 36008, 35347, 34722, 34128, 33564, 33027

#endif
