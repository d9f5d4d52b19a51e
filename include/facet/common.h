/* facet/common.h - the domain constants every format and port shares. */
#ifndef FACET_COMMON_H
#define FACET_COMMON_H

#include <stddef.h>

/* Smallest GGX alpha (alpha = perceptual roughness^2) the kernels evaluate:
 * 2^-10, i.e. perceptual roughness 1/32.  Smaller alpha (and 0, NaN) is
 * raised to it; alpha above 1 is lowered to 1. */
#define FACET_ALPHA_MIN 0.0009765625f

/* Smallest N.L and N.V the two-cosine kernels evaluate: 2^-20 (about
 * 9.5e-7, 89.99995 degrees).  It keeps 1/(N.L N.V)-type terms finite; a
 * rasterizer multiplies the BRDF by N.L, so the product still goes to 0. */
#define FACET_COS_MIN 9.5367431640625e-07f

/* Kernels and port ops are always inlined: a caller's SIMD loop then keeps
 * constants in registers and pays no call. */
#if defined(__GNUC__) || defined(__clang__)
#define FACET_INLINE static inline __attribute__((always_inline))
#else
#define FACET_INLINE static inline
#endif

/* The staged tail of a port without masked loads (sse2, neon): a tail of
 * r floats (r < lanes) is copied through a lanes-wide buffer, touching
 * nothing past p + r; the unused lanes hold 0.5, inside every kernel's
 * domain.  The port loads the buffer after facet_tail_in_ and stores into
 * it before facet_tail_out_. */
FACET_INLINE void facet_tail_in_(float *t, size_t lanes, const float *p, size_t r)
{
    size_t j;
    for (j = 0; j < lanes; j++)
        t[j] = j < r ? p[j] : 0.5f;
}
FACET_INLINE void facet_tail_out_(float *p, const float *t, size_t lanes, size_t r)
{
    size_t j;
    for (j = 0; j < r && j < lanes; j++)
        p[j] = t[j];
}

#endif
