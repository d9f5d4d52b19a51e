/* fx_core.h - integer primitives shared by the fixed-point kernels
 * (src/fx_*.c only; not installed).  Integer arithmetic only: no float, no
 * libgcc helper (so a freestanding RV32IMC or ARMv6-M link needs nothing but
 * this code), a division instruction only where the core has one (fx_div64).
 *
 * Rounding rule, the only one used anywhere in the fx kernels:
 *   every value that loses bits is rounded to nearest, ties up (toward
 *   +infinity): round(x / 2^k) = (x >> k) + ((x >> (k - 1)) & 1), which is
 *   floor(x / 2^k + 1/2) and cannot overflow.  Quotients and square roots
 *   are computed exactly (floor + remainder) and rounded by the same rule.
 * Every helper is monotone non-decreasing in each argument (the reciprocal
 * non-increasing), so a formula built from monotone pieces stays monotone.
 *
 * fxf: an unsigned pseudo-float m * 2^e with m in [2^31, 2^32) (or m = 0 for
 * zero), the intermediate of the kernels whose ranges are too wide for one
 * Q format; each fxf operation has relative error <= 2^-32 (half an ulp).
 */
#ifndef FACET_FX_CORE_H
#define FACET_FX_CORE_H

#include <stdint.h>

/* ---- 32x32 -> 64 multiply ---------------------------------------------
 * ARMv6-M (Cortex-M0) has only MULS (32x32 -> low 32): there the product
 * is assembled from four 16x16 partial products, so no __aeabi_lmul call.
 * Both versions return the exact product; tests/fx/test_fx_prims.c checks it. */
static inline uint64_t fx_mul64_portable(uint32_t a, uint32_t b)
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
#define fx_mul64 fx_mul64_portable
#else
static inline uint64_t fx_mul64(uint32_t a, uint32_t b) { return (uint64_t)a * b; }
#endif

/* ---- count leading zeros (x != 0) ------------------------------------------
 * The builtin only where it is one instruction; ARMv6-M and RV32IMC have
 * none (the builtin would call __clzsi2), so they take the portable binary
 * search. */
static inline int fx_clz32_portable(uint32_t x)
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
static inline int fx_clz32(uint32_t x) { return __builtin_clz(x); }
#else
#define fx_clz32 fx_clz32_portable
#endif

static inline int fx_clz64(uint64_t x) /* x != 0 */
{
    uint32_t hi = (uint32_t)(x >> 32);
    return hi ? fx_clz32(hi) : 32 + fx_clz32((uint32_t)x);
}

/* 64-bit shifts by a variable amount built from 32-bit ones (a variable
 * 64-bit shift is a libgcc call on Thumb-1).  0 <= k <= 63. */
static inline uint64_t fx_shl64(uint64_t x, int k)
{
    uint32_t hi = (uint32_t)(x >> 32), lo = (uint32_t)x;
    if (k == 0)
        return x;
    if (k >= 32)
        return (uint64_t)(lo << (k - 32)) << 32;
    return ((uint64_t)((hi << k) | (lo >> (32 - k))) << 32) | (uint32_t)(lo << k);
}

static inline uint64_t fx_shr64(uint64_t x, int k)
{
    uint32_t hi = (uint32_t)(x >> 32), lo = (uint32_t)x;
    if (k == 0)
        return x;
    if (k >= 32)
        return hi >> (k - 32);
    return ((uint64_t)(hi >> k) << 32) | ((lo >> k) | (hi << (32 - k)));
}

/* round(x / 2^k), ties up, 1 <= k <= 63 */
static inline uint64_t fx_rshr64(uint64_t x, int k)
{
    return fx_shr64(x, k) + (fx_shr64(x, k - 1) & 1u);
}

/* ---- the shared reciprocal, division and square root (fx_core.c) ---- */

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

/* floor(sqrt(x)) and the remainder x - g^2 in *rem (fx_core.c). */
uint32_t facet_fx_isqrt64_rem(uint64_t x, uint64_t *rem);

/* round(sqrt(x)), ties up (sqrt is never exactly k + 1/2 for integer x). */
static inline uint64_t fx_isqrt64_rnd(uint64_t x)
{
    uint64_t rem;
    uint32_t g = facet_fx_isqrt64_rem(x, &rem);
    return (uint64_t)g + (rem > g);
}

/* ---- the exact 2-by-1 division the kernels use ---------------------------
 * fx_div64(u1, u0, d, &r) = floor((u1 2^32 + u0) / d), r the remainder, for
 * d in [2^31, 2^32) and u1 < d: the same exact quotient and remainder on
 * every target, computed the cheapest way the core allows:
 *   64-bit hosts (x86-64, aarch64)   the native 64-by-64 division
 *   a 32-bit UDIV (Cortex-M3/M4/M7/M33: __ARM_FEATURE_IDIV)
 *                                    fx_div64_udiv: schoolbook with two
 *                                    16-bit quotient digits (Knuth's D,
 *                                    Hacker's Delight divlu), each digit
 *                                    from one UDIV and at most 2 corrections
 *   otherwise (Cortex-M0, armv7-A without IDIV, RV32, FACET_FX_PORTABLE)
 *                                    facet_fx_rcp32 + facet_fx_div2by1
 * A quotient computed exactly has the same bits however it is computed;
 * tests/fx/test_fx_prims.c checks fx_div64_udiv (host UDIV) against 128-bit
 * references and the pinned hashes run every variant. */
static inline uint32_t fx_div64_udiv(uint32_t u1, uint32_t u0, uint32_t d, uint32_t *r)
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
static inline uint32_t fx_sqrtrem64n_udiv(uint32_t hi, uint32_t lo, uint64_t *rem, const uint16_t *seed)
{
    uint32_t s1, r1, h, q, u;
    uint64_t S;
    int64_t R;
    s1 = ((hi >> 16) * seed[(hi >> 27) - 8]) >> 15; /* ~ sqrt(hi), 2^-6.5 relative */
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
    R = (int64_t)(((uint64_t)u << 16) | (lo & 0xFFFFu)) - (int64_t)((uint64_t)q * q);
    if (R < 0) {
        R += (int64_t)(S << 1) - 1;
        S--;
    }
    *rem = (uint64_t)R;
    return (uint32_t)S;
}

#if !defined(FACET_FX_PORTABLE) && (defined(__x86_64__) || defined(__aarch64__) || defined(__ARM_FEATURE_IDIV))
#define FX_HAVE_UDIV32 1 /* a 32-bit divide instruction (fx_core.c's isqrt) */
#endif

#if !defined(FACET_FX_PORTABLE) && (defined(__x86_64__) || defined(__aarch64__))
static inline uint32_t fx_div64(uint32_t u1, uint32_t u0, uint32_t d, uint32_t *r)
{
    uint64_t u = ((uint64_t)u1 << 32) | u0;
    *r = (uint32_t)(u % d);
    return (uint32_t)(u / d);
}
#elif !defined(FACET_FX_PORTABLE) && defined(__ARM_FEATURE_IDIV)
#define fx_div64 fx_div64_udiv
#else
static inline uint32_t fx_div64(uint32_t u1, uint32_t u0, uint32_t d, uint32_t *r)
{
    return facet_fx_div2by1(u1, u0, d, facet_fx_rcp32(d), r);
}
#endif

/* ---- seed tables (src/fx/fx_prims.c), the one list of their values: the
 * scalar primitives and the SIMD ports (src/fx_vbody.h) both initialise
 * from these.  FX_RCP_SEED_VALUES[i] = round(2^15 / ((i + 32.5) / 64)),
 * FX_RSQRT_SEED_VALUES[i] = round(2^15 / sqrt((i + 8.5) / 32)). */
#define FX_RCP_SEED_VALUES                                                                  \
    64528, 62602, 60787, 59075, 57456, 55924, 54471, 53092, 51782, 50534, 49345, 48210,     \
    47127, 46091, 45100, 44151, 43240, 42367, 41528, 40721, 39946, 39199, 38480, 37787,     \
    37118, 36472, 35849, 35246, 34664, 34100, 33554, 33026
#define FX_RSQRT_SEED_VALUES                                                                \
    63579, 60140, 57205, 54661, 52429, 50450, 48679, 47082, 45633, 44310, 43096, 41977,     \
    40940, 39977, 39078, 38238, 37449, 36708, 36008, 35347, 34722, 34128, 33564, 33027

/* ---- fxf: m 2^e --------------------------------------------------------- */
typedef struct { uint32_t m; int32_t e; } fxf;

/* m 2^e plus the rounding bit rb (ties up), m normalised (bit 31 set) */
static inline fxf fxf_round_(uint32_t m, uint32_t rb, int32_t e)
{
    fxf r;
    m += rb;
    if (!m) { /* rounded up to 2^32 */
        m = 0x80000000u;
        e++;
    }
    r.m = m;
    r.e = e;
    return r;
}

/* round(x / 2^32) or round(x / 2^31) of x = hi 2^32 + lo in [2^62, 2^64)
 * (whichever keeps 32 bits) times 2^e, normalised; 32-bit operations only */
static inline fxf fxf_from_w(uint32_t hi, uint32_t lo, int32_t e)
{
    if (hi >> 31)
        return fxf_round_(hi, lo >> 31, e + 32);
    return fxf_round_((hi << 1) | (lo >> 31), (lo >> 30) & 1u, e + 31);
}

/* x 2^e, rounded to 32 significant bits (32-bit operations: no 64-bit
 * variable shift, and a 32-bit x, the usual case, is one clz and a shift) */
static inline fxf fxf_u64(uint64_t x, int32_t e)
{
    fxf r;
    uint32_t hi = (uint32_t)(x >> 32), lo = (uint32_t)x;
    int lz;
    if (!hi) {
        if (!lo) {
            r.m = 0;
            r.e = 0;
            return r;
        }
        lz = fx_clz32(lo);
        r.m = lo << lz;
        r.e = e - lz;
        return r;
    }
    lz = fx_clz32(hi); /* round(x / 2^(32 - lz)) */
    if (lz == 0)
        return fxf_round_(hi, lo >> 31, e + 32);
    return fxf_round_((hi << lz) | (lo >> (32 - lz)), (lo >> (31 - lz)) & 1u, e + (32 - lz));
}

/* round(p / 2^32) of a product p in [2^62, 2^64) as a normalised fxf */
static inline fxf fxf_from_prod(uint64_t p, int32_t e)
{
    return fxf_from_w((uint32_t)(p >> 32), (uint32_t)p, e);
}

static inline fxf fxf_mul(fxf a, fxf b)
{
    if (!a.m || !b.m) {
        a.m = 0;
        a.e = 0;
        return a;
    }
    return fxf_from_prod(fx_mul64(a.m, b.m), a.e + b.e);
}

/* a + b, both >= 0 */
static inline fxf fxf_add(fxf a, fxf b)
{
    int32_t d;
    uint32_t hi, lo, bhi, blo;
    if (!b.m)
        return a;
    if (!a.m)
        return b;
    if (a.e < b.e) {
        fxf t = a;
        a = b;
        b = t;
    }
    d = a.e - b.e;
    if (d > 32)
        return a; /* b < half an ulp of a */
    /* s = a.m 2^31 + b.m 2^(31 - d) in [2^62, 2^64) (a.m >= 2^31), as two
     * words; the bit b loses at d = 32 is below the rounding position and
     * the truncation is monotone.  s has its top bit at 62 or 63, so its
     * rounding to 32 bits is fxf_from_w's. */
    if (d == 32) {
        bhi = 0;
        blo = b.m >> 1;
    } else if (d == 0) {
        bhi = b.m >> 1;
        blo = b.m << 31;
    } else if (d == 31) {
        bhi = 0;
        blo = b.m;
    } else { /* 1 <= d <= 30 */
        bhi = b.m >> (d + 1);
        blo = b.m << (31 - d);
    }
    lo = (a.m << 31) + blo;
    hi = (a.m >> 1) + bhi + (lo < blo);
    return fxf_from_w(hi, lo, a.e - 31);
}

/* 1 / a, a > 0: (2^32 + v) / 2^64 rounded to 32 bits */
static inline fxf fxf_rcp(fxf a)
{
    fxf r;
    uint32_t v = facet_fx_rcp32(a.m);
    r.e = -a.e - 63;
    if (v == 0xFFFFFFFFu) { /* a.m = 2^31: 1/a.m = 2^-31 exactly */
        r.m = 0x80000000u;
        r.e++;
    } else {
        r.m = 0x80000000u + (v >> 1) + (v & 1u);
    }
    return r;
}

/* a / b (b > 0), correctly rounded to 32 bits */
static inline fxf fxf_div(fxf a, fxf b)
{
    fxf r;
    uint32_t q, rem;
    if (!a.m)
        return a;
    q = fx_div64(a.m >> 1, a.m << 31, b.m, &rem); /* a.m 2^31 / b.m */
    r.e = a.e - b.e - 31;
    if (q >> 31) {
        uint64_t m = (uint64_t)q + (rem >= b.m - rem);
        if (m >> 32) {
            m >>= 1;
            r.e++;
        }
        r.m = (uint32_t)m;
    } else {
        /* one more quotient bit: 2 rem / b.m */
        uint32_t bit = rem >= b.m - rem;
        uint32_t rem2 = bit ? rem - (b.m - rem) : 2 * rem;
        uint64_t m = ((uint64_t)q << 1 | bit) + (rem2 >= b.m - rem2);
        r.e--;
        if (m >> 32) {
            m >>= 1;
            r.e++;
        }
        r.m = (uint32_t)m;
    }
    return r;
}

/* sqrt(a), correctly rounded to 32 bits */
static inline fxf fxf_sqrt(fxf a)
{
    fxf r;
    uint64_t x, g;
    int32_t e2;
    if (!a.m)
        return a;
    if ((uint32_t)a.e & 1u) { /* odd exponent: m 2^31 (e - 31 even) */
        x = (uint64_t)a.m << 31;
        e2 = a.e - 31;
    } else {
        x = (uint64_t)a.m << 32;
        e2 = a.e - 32;
    }
    g = fx_isqrt64_rnd(x); /* in [2^31, 2^32] */
    r.e = e2 / 2; /* e2 is even: exact */
    if (g >> 32) {
        g >>= 1;
        r.e++;
    }
    r.m = (uint32_t)g;
    return r;
}

/* sqrt(x 2^e) of an exact 64-bit x, correctly rounded to 32 bits: x is
 * normalised by an even shift to [2^62, 2^64) before the integer root, so
 * no bit of x is lost first. */
static inline fxf fxf_sqrt64(uint64_t x, int32_t e)
{
    fxf r;
    uint64_t g;
    int s;
    if (!x) {
        r.m = 0;
        r.e = 0;
        return r;
    }
    s = fx_clz64(x);
    if ((uint32_t)(e - s) & 1u) /* keep the exponent even */
        s--;
    if (s >= 0) {
        x = fx_shl64(x, s);
    } else { /* s = -1: x >= 2^63 with an odd exponent; drop one bit, rounded */
        uint64_t lost = x & 1u;
        x = (x >> 1) + lost; /* x < 2^64 - 1: no wrap; monotone */
    }
    g = fx_isqrt64_rnd(x);
    r.e = (e - s) / 2;
    if (g >> 32) {
        g >>= 1;
        r.e++;
    }
    r.m = (uint32_t)g;
    return r;
}

/* round(a 2^f), saturated at max */
static inline uint64_t fxf_fixed(fxf a, int32_t f, uint64_t max)
{
    int32_t k = -(a.e + f);
    uint64_t v;
    if (!a.m)
        return 0;
    if (k <= 0) {
        if (-k > 31 || (uint64_t)a.m > fx_shr64(max, -k))
            return max;
        v = fx_shl64(a.m, -k);
    } else if (k > 32) {
        return 0;
    } else {
        v = fx_rshr64(a.m, k);
    }
    return v > max ? max : v;
}

/* round(a / b 2^f) with a single rounding, saturated at max (< 2^31 + 2^30). */
static inline uint32_t fxf_div_fixed(fxf a, fxf b, int32_t f, uint32_t max)
{
    uint32_t q, rem, raw;
    int32_t k;
    if (!a.m)
        return 0;
    /* a/b 2^f = (q31 + rem/b.m) 2^-k, q31 = floor(a.m 2^31 / b.m) in [2^30, 2^32) */
    k = 31 - (a.e - b.e + f);
    if (k < 0)
        return max; /* >= 2^31 */
    if (k > 32)
        return 0;   /* < 2^32 2^-33 = 1/2 */
    q = fx_div64(a.m >> 1, a.m << 31, b.m, &rem);
    if (k == 0) {
        if (q == 0xFFFFFFFFu)
            return max;
        raw = q + (rem >= b.m - rem);
    } else if (k == 32) {
        raw = q >> 31;
    } else {
        /* rem/b.m < 1 cannot move q across a rounding boundary (integers) */
        raw = (q >> k) + ((q >> (k - 1)) & 1u);
    }
    return raw > max ? max : raw;
}

#endif
