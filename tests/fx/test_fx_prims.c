/* test_fx_prims.c - the shared integer primitives of the fixed-point kernels
 * against exact references: the portable 16x16 multiply and clz (the
 * Cortex-M0 / RV32 paths) against the native ones, the reciprocal, the
 * 2-by-1 division and the integer square root against 128-bit or exhaustive
 * checks, and the Newton fix-up counts that the docs state. */
#include <stdio.h>
#include <stdlib.h>
#include "../lib/harness.h"
#include "../lib/fx_test.h"
#include "facet/fx.h"
#include "../../src/fx/fx_prims.h"
#include "../../src/fx/fx_ops_scalar.h"
#include "../../src/fx/fx_body.h"
#include "../../src/fx/fx_fast_body.h" /* the fast tier's integer log2 and 2^f */
#include <math.h>

int main(void)
{
    fx_rng r = { 0xf1c0 };
    long i, n = getenv("FACET_TEST_QUICK") ? 200000 : 3000000, bad;
    th_name = "fx_prims";

    /* mul64: portable == native */
    for (bad = 0, i = 0; i < n; i++) {
        uint32_t a = (uint32_t)fx_next(&r), b = (uint32_t)fx_next(&r);
        if (i < 64) { a = i & 1 ? 0xFFFFFFFFu : a; b = i & 2 ? 0xFFFFFFFFu : i & 4 ? 0 : b; }
        bad += fxp_mul64_portable(a, b) != (uint64_t)a * b;
    }
    CHECK(bad == 0, "portable mul64 differs from native in %ld cases", bad);

    /* clz: portable == native for every bit length and random values */
    for (bad = 0, i = 0; i < 32; i++) {
        uint32_t x = 1u << i;
        bad += fxp_clz32_portable(x) != 31 - i || fxp_clz32_portable(x | (x - 1)) != 31 - i;
    }
    for (i = 0; i < n; i++) {
        uint32_t x = (uint32_t)fx_next(&r) >> (fx_next(&r) % 32);
        if (x)
            bad += fxp_clz32_portable(x) != fxp_clz32(x);
    }
    CHECK(bad == 0, "portable clz wrong in %ld cases", bad);

#ifdef __SIZEOF_INT128__
    /* rcp32: exact floor((2^64-1)/d) - 2^32 at the ends, every table bin edge, random */
    for (bad = 0, i = 0; i < n + 64 * 4; i++) {
        uint32_t d;
        unsigned __int128 want;
        if (i < 64 * 4)
            d = (uint32_t)((32 + i / 4) << 26) + (uint32_t)(i % 4 == 0 ? 0 : i % 4 == 1 ? 1 : i % 4 == 2 ? (1 << 26) - 1 : (1 << 25));
        else
            d = (uint32_t)fx_next(&r) | 0x80000000u;
        if (i / 4 >= 32 && i < 64 * 4)
            d = 0xFFFFFFFFu - (uint32_t)i;
        want = (((unsigned __int128)1 << 64) - 1) / d - ((unsigned __int128)1 << 32);
        bad += facet_fx_rcp32(d) != (uint32_t)want;
    }
    CHECK(bad == 0, "rcp32 not exact in %ld cases", bad);

    /* div2by1: exact quotient and remainder */
    for (bad = 0, i = 0; i < n; i++) {
        uint32_t d = (uint32_t)fx_next(&r) | 0x80000000u, u1 = (uint32_t)fx_next(&r), u0 = (uint32_t)fx_next(&r), rem, q;
        uint64_t u;
        if (i & 1)
            d = 0x80000000u + (uint32_t)(fx_next(&r) % 1024);
        u1 = (uint32_t)(u1 % d);
        if (i % 5 == 0)
            u1 = d - 1;
        u = ((uint64_t)u1 << 32) | u0;
        q = facet_fx_div2by1(u1, u0, d, facet_fx_rcp32(d), &rem);
        bad += q != (uint32_t)(((unsigned __int128)u) / d) || rem != (uint32_t)(u % d);
    }
    CHECK(bad == 0, "div2by1 wrong in %ld cases", bad);

    /* fxp_div64_udiv (the Cortex-M3/M4 path, built here with the host's
     * 32-bit division) and fxp_div64 (this host's path): exact quotient and
     * remainder, including the digit-correction corners (u1 = d - 1,
     * d = 2^31, d with a small or all-ones low half) */
    for (bad = 0, i = 0; i < n; i++) {
        uint32_t d = (uint32_t)fx_next(&r) | 0x80000000u, u1 = (uint32_t)fx_next(&r), u0 = (uint32_t)fx_next(&r);
        uint32_t rem, rem2, q, q2;
        uint64_t u;
        switch (i % 7) {
        case 1: d = 0x80000000u + (uint32_t)(fx_next(&r) % 1024); break;
        case 2: d = (d & 0xFFFF0000u) | 0xFFFFu; break;
        case 3: d = d & 0xFFFF0000u; break;
        case 4: d = 0xFFFFFFFFu - (uint32_t)(fx_next(&r) % 1024); break;
        default: break;
        }
        u1 = (uint32_t)(u1 % d);
        if (i % 5 == 0)
            u1 = d - 1;
        if (i % 11 == 0)
            u0 = i & 1 ? 0xFFFFFFFFu : 0;
        u = ((uint64_t)u1 << 32) | u0;
        q = fxp_div64_udiv(u1, u0, d, &rem);
        q2 = fxp_div64(u1, u0, d, &rem2);
        bad += q != (uint32_t)(((unsigned __int128)u) / d) || rem != (uint32_t)(u % d) || q2 != q || rem2 != rem;
    }
    CHECK(bad == 0, "fxp_div64_udiv / fxp_div64 wrong in %ld cases", bad);
#else
    SKIP("no 128-bit integer type for the rcp/div references");
#endif

    /* isqrt64: floor root, exact, all bit lengths */
    for (bad = 0, i = 0; i < n; i++) {
        uint64_t x = fx_next(&r) >> (fx_next(&r) % 64), g;
        if (i < 64)
            x = (i & 1) ? ((uint64_t)1 << (i / 2)) - 1 : (uint64_t)1 << (i / 2);
        if (i == 64)
            x = 0xFFFFFFFFFFFFFFFFull;
        if (i == 65)
            x = 0xFFFFFFFE00000001ull; /* (2^32 - 1)^2 */
        g = facet_fx_isqrt64(x);
        bad += g * g > x || (g < 0xFFFFFFFFu && (g + 1) * (g + 1) <= x);
        {
            uint64_t rem;
            bad += facet_fx_isqrt64_rem(x, &rem) != g || rem != x - g * g;
        }
    }
    CHECK(bad == 0, "isqrt64 wrong in %ld cases", bad);

    /* isqrt64 at and next to perfect squares (g^2 - 1, g^2, g^2 + 2g: the
     * digit-correction corners of the divide-based root) and every
     * normalised top-word range */
    for (bad = 0, i = 0; i < n; i++) {
        uint64_t g = (uint32_t)fx_next(&r) >> (fx_next(&r) % 32), x, want, rem;
        int k = (int)(i % 3);
        if (i < 4096)
            g = 0xFFFFFFFFu - (uint64_t)i;
        if (g == 0)
            g = 1;
        x = k == 0 ? g * g - 1 : k == 1 ? g * g : g * g + 2 * g;
        want = k == 0 ? g - 1 : g;
        bad += facet_fx_isqrt64_rem(x, &rem) != want || rem != x - want * want;
    }
    CHECK(bad == 0, "isqrt64 wrong next to perfect squares in %ld cases", bad);

    /* rsqrt32 accuracy: the documented 2^-29 relative bound, every seed bin */
    {
        double worst = 0;
        for (i = 0; i < n; i++) {
            uint32_t x = (uint32_t)(0x40000000u + fx_next(&r) % 0xC0000000u);
            double y = facet_fx_rsqrt32(x), want = ldexp(1.0, 47) / sqrt((double)x);
            if (fabs(y - want) / want > worst)
                worst = fabs(y - want) / want;
        }
        printf("rsqrt32 max relative error 2^%.2f\n", log2(worst));
        CHECK(worst <= ldexp(1.0, -29), "rsqrt32 error 2^%.2f exceeds 2^-29", log2(worst));
    }
    /* the GTR terms' integer log2 (fxq_log2m31: Q31 of log2 m, x = m 2^31)
     * and 2^f (fxq_exp2f30: Q30 of 2^f, f = F 2^-32) against libm, every
     * table bin's ends and random mantissas: the bounds src/fx/fx_fast_body.h
     * states (2^-25.5 absolute, 2^-22.9 relative) */
    {
        double el = 0, ee = 0;
        for (i = 0; i < n; i++) {
            /* i < 32: the ends of the 16 bins (the leading one and 4 index bits) */
            uint32_t x = i < 32 ? 0x80000000u + ((uint32_t)(i >> 1) << 27) + (i & 1 ? (1u << 27) - 1u : 0u)
                                : (uint32_t)fx_next(&r) | 0x80000000u;
            uint32_t f = i < 4 ? (uint32_t)(0u - (uint32_t)i) : (uint32_t)fx_next(&r);
            double dl = fabs(fxq_log2m31(x) * 0x1p-31 - log2(x * 0x1p-31));
            double de = fabs(fxq_exp2f30(f) * 0x1p-30 / exp2(f * 0x1p-32) - 1.0);
            el = dl > el ? dl : el;
            ee = de > ee ? de : ee;
        }
        printf("fx_fast log2: max |error| 2^%.2f; 2^f: max relative error 2^%.2f\n", log2(el), log2(ee));
        CHECK(el <= exp2(-25.5) && ee <= exp2(-22.9), "fast log2 error 2^%.2f (bound 2^-25.5), 2^f 2^%.2f (bound 2^-22.9)",
              log2(el), log2(ee));
    }
    return th_done();
}
