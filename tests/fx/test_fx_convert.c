/* test_fx_convert.c - the float <-> fixed-point conversions of facet/fx.h
 * hold their contract:
 *   facet_q15_from_f32: floor(x 32768 + 1/2) computed in double (exact
 *     there) after NaN -> 0 and the clamp to [-4, 4], over every float
 *     whose exponent puts it within [-8, 8] at a stride of the bit
 *     patterns, every Q15 value and its neighbours a float ulp and half an
 *     LSB away, the specials (NaN of both signs, +-inf, +-0, denormals,
 *     +-FLT_MAX); and the round trip q -> float -> q is the identity over
 *     [-131072, 131072]; the batch equals the scalar;
 *   facet_f32_from_q15: q / 32768 exactly;
 *   facet_f32_from_fx: raw 2^-frac correctly rounded, for raw < 2^53 (the
 *     double is exact) at every frac the outputs use and a few more, and at
 *     known values past 2^53. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "../lib/harness.h"
#include "facet/fx.h"

static float from_bits(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

/* the contract in double: NaN 0, clamp, floor(v + 1/2) */
static int32_t want_q15(float x)
{
    double v;
    if (x != x)
        return 0;
    v = x < -4.0f ? -4.0 : x > 4.0f ? 4.0 : (double)x;
    return (int32_t)floor(v * 32768.0 + 0.5);
}

static long n_bad;
static void one(float x)
{
    int32_t got = facet_q15_from_f32(x), want = want_q15(x);
    if (got != want && n_bad++ < 5)
        CHECK(0, "facet_q15_from_f32(%.9g) = %ld, want %ld", x, (long)got, (long)want);
}

int main(void)
{
    uint32_t u;
    int32_t q;
    long n_rt = 0, n_q = 0;
    th_name = "fx_convert";
    /* specials */
    CHECK(facet_q15_from_f32(NAN) == 0 && facet_q15_from_f32(-NAN) == 0, "NaN does not give 0");
    CHECK(facet_q15_from_f32(INFINITY) == 131072 && facet_q15_from_f32(-INFINITY) == -131072, "+-inf not clamped to +-4");
    CHECK(facet_q15_from_f32(FLT_MAX) == 131072 && facet_q15_from_f32(-FLT_MAX) == -131072, "+-FLT_MAX not clamped");
    CHECK(facet_q15_from_f32(0.0f) == 0 && facet_q15_from_f32(-0.0f) == 0, "+-0 does not give 0");
    CHECK(facet_q15_from_f32(1.0f) == 32768 && facet_q15_from_f32(-1.0f) == -32768, "+-1 is not +-32768");
    CHECK(facet_q15_from_f32(0.5f / 32768) == 1 && facet_q15_from_f32(-0.5f / 32768) == 0, "a tie does not round up");
    CHECK(facet_q15_from_f32(from_bits(1)) == 0 && facet_q15_from_f32(-from_bits(1)) == 0, "a denormal is not 0");
    /* a stride over the bit patterns of [-8, 8] (exponents to 2^-149) */
    for (u = 0; u < 0x41000000u; u += 997) {
        one(from_bits(u));
        one(from_bits(u | 0x80000000u));
    }
    /* every Q15 value, a float ulp either side and half an LSB either side */
    for (q = -131072 - 4; q <= 131072 + 4; q++) {
        float x = (float)q / 32768.0f;
        one(x);
        one(nextafterf(x, 1e9f));
        one(nextafterf(x, -1e9f));
        one(((float)q + 0.5f) / 32768.0f);
        one(nextafterf(((float)q + 0.5f) / 32768.0f, -1e9f));
        n_q++;
    }
    CHECK(n_bad == 0, "facet_q15_from_f32: %ld values differ from floor(x 32768 + 1/2)", n_bad);
    /* the round trip and facet_f32_from_q15's exactness */
    for (q = -131072; q <= 131072; q++) {
        float f = facet_f32_from_q15(q);
        if ((double)f != (double)q / 32768.0 || facet_q15_from_f32(f) != q)
            n_rt++;
    }
    CHECK(n_rt == 0, "q -> facet_f32_from_q15 -> facet_q15_from_f32 is not q (or not exact) for %ld values", n_rt);
    {
        float x[11] = { -5.0f, -1.0f, -0.3f, 0.0f, 1e-6f, 0.25f, 0.5f, 0.99999994f, 1.0f, 3.9f, NAN };
        int32_t o[11];
        int i, same = 1;
        facet_q15_from_f32_batch(o, x, 11);
        for (i = 0; i < 11; i++)
            same &= o[i] == facet_q15_from_f32(x[i]);
        CHECK(same, "facet_q15_from_f32_batch differs from the scalar");
    }
    /* facet_f32_from_fx: correctly rounded raw 2^-frac */
    {
        static const int fracs[] = { 0, 1, 13, 15, 16, 24, 31, 40, 63 };
        uint64_t r = 0x9e3779b97f4a7c15ull;
        long n_fx = 0, i, k;
        for (k = 0; k < (long)(sizeof fracs / sizeof fracs[0]); k++)
            for (i = 0; i < 20000; i++) {
                uint64_t raw;
                r ^= r << 13, r ^= r >> 7, r ^= r << 17;
                raw = r >> (11 + (i % 53)); /* < 2^53: exact in double */
                if (facet_f32_from_fx(raw, fracs[k]) != (float)ldexp((double)raw, -fracs[k]))
                    n_fx++;
            }
        CHECK(n_fx == 0, "facet_f32_from_fx: %ld values are not raw 2^-frac correctly rounded", n_fx);
        CHECK(facet_f32_from_fx(0xFFFFFFFFFFFFFFFFull, 24) == 1099511627776.0f, "UQ40.24 max is not 2^40");
        CHECK(facet_f32_from_fx((1ull << 63) + 1, 63) == 1.0f, "2^63 + 1 at frac 63 is not 1");
        CHECK(facet_f32_from_fx(32768u, FACET_FX_Q15_FRAC) == 1.0f && facet_f32_from_fx(1u << 24, FACET_FX_BRDF_FRAC) == 1.0f,
              "one is not 1.0");
    }
    (void)n_q;
    return th_done();
}
