/* fx_prims.c - the one reciprocal, division and square root every
 * fixed-point kernel shares.  Integer only; see fx_prims.h for the rounding
 * rule and facet/fx.h for the contracts. */
#include "facet/fx.h"
#include "fx_prims.h"

/* Reciprocal seeds: RCP_SEED[i] = round(2^15 * 64 / (i + 32.5)), 1/x at the
 * midpoint of [(i + 32)/64, (i + 33)/64) in Q1.15, for d = x 2^32 with
 * i = (d >> 26) - 32.  Relative error <= 2^-7 (half a bin at x = 1/2). */
static const uint16_t RCP_SEED[32] = { FXP_RCP_SEED_VALUES };

/* rsqrt seeds: RSQRT_SEED[i] = round(2^15 / sqrt((i + 8.5) / 32)), 1/sqrt(X)
 * at the bin midpoint in Q1.15, for x = X 2^32 with i = (x >> 27) - 8.
 * Relative error <= 2^-6.5 (half a bin at X = 1/4). */
static const uint16_t RSQRT_SEED[24] = { FXP_RSQRT_SEED_VALUES };

/* r in Q1.31 ~ 2^63 / d; Newton r' = r + r (1 - d r / 2^63).  Error 2^-7 ->
 * 2^-14 -> 2^-28 -> arithmetic limit (~2 ulp); the exact fix-up follows. */
uint32_t facet_fx_rcp32(uint32_t d)
{
    uint64_t r = (uint64_t)RCP_SEED[(d >> 26) - 32u] << 16, n, p;
    uint32_t v;
    int i;
    for (i = 0; i < 3; i++) {
        uint32_t h = (uint32_t)(fxp_mul64(d, (uint32_t)r) >> 32); /* ~ 2^31 */
        if (h <= 0x80000000u) {
            r += fxp_mul64((uint32_t)r, 0x80000000u - h) >> 31;
        } else {
            r -= fxp_mul64((uint32_t)r, h - 0x80000000u) >> 31;
        }
        if (r > 0xFFFFFFFFu) {
            r = 0xFFFFFFFFu;
        }
    }
    /* v ~ 2 r - 2^32; then make it exact: v = floor(N / d) with
     * N = 2^64 - 1 - 2^32 d = (~d) 2^32 + (2^32 - 1) */
    v = (uint32_t)(r << 1);
    n = ((uint64_t)(uint32_t)~d << 32) | 0xFFFFFFFFu;
    p = fxp_mul64(v, d);
    while (p > n) {
        v--;
        p -= d;
    }
    while (n - p >= d && v != 0xFFFFFFFFu) {
        v++;
        p += d;
    }
    return v;
}

/* Moller & Granlund, "Improved division by invariant integers" (2011),
 * the 2-by-1 division with a precomputed reciprocal: one 32x32->64
 * multiply, one low multiply and at most two fix-ups. */
uint32_t facet_fx_div2by1(uint32_t u1, uint32_t u0, uint32_t d, uint32_t v, uint32_t *r)
{
    uint32_t u1p = u1 + 1u; /* mod 2^32 */
    uint64_t q = fxp_mul64(v, u1) + (((uint64_t)u1p << 32) | u0); /* mod 2^64 */
    uint32_t q1 = (uint32_t)(q >> 32), q0 = (uint32_t)q;
    uint32_t rem = u0 - q1 * d;
    if (rem > q0) {
        q1--;
        rem += d;
    }
    if (rem >= d) {
        q1++;
        rem -= d;
    }
    *r = rem;
    return q1;
}

/* y in Q1.31 ~ 1/sqrt(X), X = x / 2^32 in [1/4, 1); Newton
 * y' = y (3 - X y^2) / 2.  Error 2^-6.5 -> 2^-12 -> 2^-23 -> ~2^-30. */
uint32_t facet_fx_rsqrt32(uint32_t x)
{
    uint32_t y = (uint32_t)RSQRT_SEED[(x >> 27) - 8u] << 16;
    int i;
    for (i = 0; i < 3; i++) {
        uint32_t y2 = (uint32_t)(fxp_mul64(y, y) >> 32);   /* (1/X) 2^30 (y < 2^32) */
        uint32_t xy2 = (uint32_t)(fxp_mul64(x, y2) >> 32); /* X y^2 2^30 ~ 2^30 */
        uint32_t h = 0xC0000000u - xy2;                   /* (3 - X y^2) 2^30 > 0 */
        uint32_t m = (uint32_t)(fxp_mul64(y, h) >> 32);    /* y' 2^-1 in Q1.31 */
        y = m >> 31 ? 0xFFFFFFFFu : m << 1;
    }
    return y;
}

/* floor(sqrt(x)): normalise x to [2^62, 2^64) by an even shift 2k,
 * g ~ t rsqrt(t) 2^16 from the top word t, scale back by k, then fix g
 * exactly with g^2 <= x < (g + 1)^2, stepping the square p = g^2 by
 * additions ((g -+ 1)^2 = g^2 -+ 2g + 1: one multiply in all).  The
 * remainder x - g^2 comes out with it (fxp_isqrt64_rnd's rounding). */
uint32_t facet_fx_isqrt64_rem(uint64_t x, uint64_t *rem)
{
    int s;
    uint32_t t, g;
    uint64_t xn, gg, p;
    if (!x) {
        *rem = 0;
        return 0;
    }
    s = fxp_clz64(x) & ~1;
    xn = fxp_shl64(x, s);
#ifdef FXP_HAVE_UDIV32
    /* a divide instruction: the exact root of xn by two 16-bit digits,
     * scaled back (floor(floor(sqrt(xn)) / 2^k) = floor(sqrt(x))) */
    (void)t;
    (void)gg;
    (void)p;
    /* two statements: pcc 1.2 drops bits when the call and the shift are
     * one expression (tests/suites/26-compilers.sh) */
    g = fxp_sqrtrem64n_udiv((uint32_t)(xn >> 32), (uint32_t)xn, rem, RSQRT_SEED);
    g >>= s / 2;
    if (s != 0) {
        *rem = x - fxp_mul64(g, g);
    }
    return g;
#else
    t = (uint32_t)(xn >> 32);                                  /* [2^30, 2^32) */
    gg = fxp_mul64(t, facet_fx_rsqrt32(t)) >> 31;               /* sqrt(xn) ~ t 2^47/sqrt(t) / 2^31 */
    gg = fxp_shr64(gg, s / 2);
    g = gg > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)gg;
    p = fxp_mul64(g, g);
    while (p > x) { /* g >= 1 here */
        p -= ((uint64_t)g << 1) - 1u;
        g--;
    }
    while (g != 0xFFFFFFFFu && x - p > (uint64_t)g << 1) { /* (g + 1)^2 <= x */
        p += ((uint64_t)g << 1) + 1u;
        g++;
    }
    *rem = x - p;
    return g;
#endif
}

uint32_t facet_fx_isqrt64(uint64_t x)
{
    uint64_t rem;
    return facet_fx_isqrt64_rem(x, &rem);
}
