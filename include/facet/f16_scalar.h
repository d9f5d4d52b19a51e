/* facet/f16_scalar.h - the scalar binary16 port, the specification of the
 * f16 format: every f16 kernel as a static inline function on float,
 * named facet_<kernel>_f16_scalar, whose arguments and result are binary16
 * values held in a float (facet_f16_scalar_from_bits /
 * facet_f16_scalar_to_bits convert the storage bit patterns).
 *
 * Portable C99, no binary16 type needed: every binary16 operation is
 * computed in double and rounded once to binary16 (round to nearest even;
 * facet_f16_scalar_round).  For + - * / and sqrt of binary16 operands that
 * is the correctly rounded binary16 result (the double result is exact for
 * + - *, and double has at least 2 p + 2 bits of binary16's p = 11, so the
 * double rounding of / and sqrt is innocuous); fma a b + c is exact in
 * double (a b has 22 bits) wherever |a b| < 2^29 |c|-free, i.e. for every fma
 * of the kernels (their products are below 2^12).  The few f32 operations
 * of the body (FACET_W, f16_body.h) are the scalar f32 port's
 * (facet/scalar.h).  The reciprocal, rsqrt and sqrt are correctly rounded
 * here; a SIMD port's estimates may differ from them by a rounding, within
 * the bounds of facet/f16.h.  No libm. */
#ifndef FACET_F16_SCALAR_H
#define FACET_F16_SCALAR_H

#include <stdint.h>
#include "facet/common.h"
#include "facet/f16.h"
#include "facet/scalar.h"

/* x rounded to binary16 (nearest, ties to even), as a double: binary16's
 * subnormals (quantum 2^-24) included, |x| >= 65520 to +-Inf, NaN kept. */
FACET_INLINE double facet_f16_scalar_round(double x)
{
    union { double d; uint64_t u; } b, q;
    double a = x < 0.0 ? -x : x, y, f;
    int64_t n;
    int e;
    if (!(a < 65520.0)) /* NaN, Inf, overflow */
        return a != a ? x : (x < 0.0 ? -a * 1e300 * 1e300 : a * 1e300 * 1e300);
    if (a == 0.0)
        return x;
    b.d = a;
    e = FACET_CAST(int, b.u >> 52) - 1023;
    if (e < -14)
        e = -14;
    q.u = FACET_CAST(uint64_t, e - 10 + 1023) << 52; /* the quantum 2^(e-10) */
    y = a / q.d;                                      /* exact: a power of two */
    n = FACET_CAST(int64_t, y);                       /* < 2^12, exact */
    f = y - FACET_CAST(double, n);                    /* exact */
    if (f > 0.5 || (f == 0.5 && (n & 1)))
        n++;
    y = FACET_CAST(double, n) * q.d;
    return x < 0.0 ? -y : y;
}

FACET_INLINE float facet_f16_scalar_r_(double x) { return FACET_CAST(float, facet_f16_scalar_round(x)); }

/* binary16 bits to their value, exactly (NaN stays NaN, Inf Inf) */
FACET_INLINE float facet_f16_scalar_from_bits(uint16_t h)
{
    union { float f; uint32_t u; } b;
    uint32_t s = FACET_CAST(uint32_t, h & 0x8000u) << 16, e = (h >> 10) & 0x1fu, m = h & 0x3ffu;
    float v;
    if (e == 0x1fu) {
        b.u = s | 0x7f800000u | (m << 13);
        return b.f;
    }
    if (e == 0)
        v = FACET_CAST(float, m) * 5.9604644775390625e-08f; /* m 2^-24, exact */
    else {
        b.u = ((e + 112u) << 23) | (m << 13);
        v = b.f;
    }
    return s ? -v : v;
}

/* a float to binary16 bits, rounded to nearest even (IEEE conversion:
 * overflow to Inf, NaN to a quiet NaN with the sign) */
FACET_INLINE uint16_t facet_f16_scalar_to_bits(float x)
{
    union { float f; uint32_t u; } b;
    double r;
    uint16_t s;
    uint32_t e;
    b.f = x;
    s = FACET_CAST(uint16_t, (b.u >> 16) & 0x8000u);
    if (x != x)
        return FACET_CAST(uint16_t, s | 0x7e00u);
    r = facet_f16_scalar_round(FACET_CAST(double, x));
    r = r < 0.0 ? -r : r;
    if (r > 65504.0)
        return FACET_CAST(uint16_t, s | 0x7c00u);
    if (r < 6.103515625e-05) /* subnormal or zero: r / 2^-24 */
        return FACET_CAST(uint16_t, s | FACET_CAST(uint16_t, r * 16777216.0));
    b.f = FACET_CAST(float, r);
    e = (b.u >> 23) - 112u;
    return FACET_CAST(uint16_t, s | (e << 10) | ((b.u >> 13) & 0x3ffu));
}

/* ---- the binary16 op layer (FACET_V float, values binary16) ---- */
FACET_INLINE float facet_scalar_h_set(float x) { return facet_f16_scalar_r_(x); }
FACET_INLINE float facet_scalar_h_add(float a, float b) { return facet_f16_scalar_r_(FACET_CAST(double, a) + b); }
FACET_INLINE float facet_scalar_h_sub(float a, float b) { return facet_f16_scalar_r_(FACET_CAST(double, a) - b); }
FACET_INLINE float facet_scalar_h_mul(float a, float b) { return facet_f16_scalar_r_(FACET_CAST(double, a) * b); }
FACET_INLINE float facet_scalar_h_fma(float a, float b, float c)
{
    return facet_f16_scalar_r_(FACET_CAST(double, a) * b + c);
}
FACET_INLINE float facet_scalar_h_fnma(float a, float b, float c)
{
    return facet_f16_scalar_r_(c - FACET_CAST(double, a) * b);
}
FACET_INLINE float facet_scalar_h_min(float a, float b) { return a < b ? a : b; }
FACET_INLINE float facet_scalar_h_max(float a, float b) { return a > b ? a : b; }
FACET_INLINE float facet_scalar_h_clamp(float x, float lo, float hi)
{
    x = x > lo ? x : lo;
    return x < hi ? x : hi;
}
FACET_INLINE float facet_scalar_h_keep_ord(float r, float a, float b)
{
    return (a == a && b == b) ? r : 0.0f;
}
FACET_INLINE float facet_scalar_h_keep_ord4(float r, float a, float b, float c, float d)
{
    return (a == a && b == b && c == c && d == d) ? r : 0.0f;
}
/* sqrt in double without libm: the bit seed and Newton steps to about
 * 2^-50, far below binary16's rounding (a binary16 square root is never
 * within 2^-24 relative of a rounding midpoint, so the result is the
 * correctly rounded one) */
FACET_INLINE double facet_f16_scalar_rsqrt_d_(double x)
{
    union { double d; uint64_t u; } b;
    double y;
    int i;
    b.d = x;
    b.u = 0x5fe6eb50c7b537a9ull - (b.u >> 1);
    y = b.d;
    for (i = 0; i < 5; i++)
        y = y * (1.5 - 0.5 * x * y * y);
    return y;
}
FACET_INLINE float facet_scalar_h_div(float a, float b) { return facet_f16_scalar_r_(FACET_CAST(double, a) / b); }
FACET_INLINE float facet_scalar_h_rcp(float x) { return facet_f16_scalar_r_(1.0 / x); }
FACET_INLINE float facet_scalar_h_rsqrt(float x) { return facet_f16_scalar_r_(facet_f16_scalar_rsqrt_d_(x)); }
FACET_INLINE float facet_scalar_h_sqrt(float x)
{
    return facet_f16_scalar_r_(x * facet_f16_scalar_rsqrt_d_(x));
}

/* ---- the f32 lanes (FACET_W float): the scalar f32 port's ops ---- */
FACET_INLINE float facet_scalar_h_w_set(float x) { return x; }
FACET_INLINE float facet_scalar_h_w_add(float a, float b) { return a + b; }
FACET_INLINE float facet_scalar_h_w_sub(float a, float b) { return a - b; }
FACET_INLINE float facet_scalar_h_w_mul(float a, float b) { return a * b; }
FACET_INLINE float facet_scalar_h_w_fma(float a, float b, float c) { return facet_scalar_fma(a, b, c); }
FACET_INLINE float facet_scalar_h_w_fnma(float a, float b, float c) { return facet_scalar_fnma(a, b, c); }
FACET_INLINE float facet_scalar_h_w_min(float a, float b) { return a < b ? a : b; }
FACET_INLINE float facet_scalar_h_w_max(float a, float b) { return a > b ? a : b; }
FACET_INLINE float facet_scalar_h_w_sqr_err(float a, float p) { return facet_scalar_sqr_err(a, p); }
FACET_INLINE float facet_scalar_h_w_rcp(float x) { return 1.0f / x; }
FACET_INLINE float facet_scalar_h_w_rsqrt(float x) { return facet_scalar_rsqrt(x); }
FACET_INLINE float facet_scalar_h_widen(float x) { return x; }
/* x >= 0, rounded to binary16 (from 65520 on: +Inf, as IEEE converts) */
FACET_INLINE float facet_scalar_h_narrow(float x) { return facet_f16_scalar_r_(x); }

#define FACET_V float
#define FACET_W float
#define FACET_OP(op) facet_scalar_h_##op
#define FACET_K(k) facet_##k##_f16_scalar
#include "facet/detail/f16_body.h"
#undef FACET_V
#undef FACET_W
#undef FACET_OP
#undef FACET_K

#endif
