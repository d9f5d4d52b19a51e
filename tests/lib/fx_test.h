/* fx_test.h - helpers of the fixed-point tests: a seeded PRNG (splitmix64)
 * and the reference rounding of the oracle to an output format. */
#ifndef FACET_FX_TEST_H
#define FACET_FX_TEST_H

#include <stdint.h>
#include <math.h>

typedef struct { uint64_t s; } fx_rng;

static inline uint64_t fx_next(fx_rng *r)
{
    uint64_t z = (r->s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/* uniform integer in [lo, hi] */
static inline int32_t fx_range(fx_rng *r, int32_t lo, int32_t hi)
{
    return (int32_t)(lo + (int64_t)(fx_next(r) % (uint64_t)((int64_t)hi - lo + 1)));
}

#endif
