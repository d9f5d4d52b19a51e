/* fx_pfloat.h - fxe: the unsigned pseudo-float of the precise fixed-point
 * tier, written once over the lane op layer (src/fx/fx_ops.h).  Private to
 * the library.  A value is m 2^e with m in [2^31, 2^32), or m = 0 for zero,
 * held as two lanes: the mantissa m and the exponent biased by FXE_BIAS
 * (E = e + FXE_BIAS, so exponent lanes stay in [0, 2^32) on every port).
 * It carries the intermediates whose ranges are too wide for one Q
 * format; each operation rounds once, to nearest with ties up, so its
 * relative error is <= 2^-32 (half an ulp).  Branch-free: every case is
 * computed and selected.  A zero's exponent is never read (every op that
 * can meet a zero masks it), and |e| < 2^13 for every value the kernels
 * form.
 *
 * Sizeless vector types (RVV) cannot be struct members, so a value is
 * passed as its two lanes: FXE(x) names x_m, x_e (declare with fxv_u32
 * FXE(x);), FXE_TO(x) their addresses, FXE_IN(x) / FXE_OUT(x) the
 * parameters. */
#ifndef FACET_FX_PFLOAT_H
#define FACET_FX_PFLOAT_H

#include "fx_ops.h"

#define FXE(x) x##_m, x##_e
#define FXE_TO(x) &x##_m, &x##_e
#define FXE_IN(x) fxv_u32 x##_m, fxv_u32 x##_e
#define FXE_OUT(x) fxv_u32 *x##_m, fxv_u32 *x##_e

#define FXE_BIAS 65536u /* even: a square root halves E - FXE_BIAS exactly */

/* the constant m 2^e (m normalised) */
FXV_BODY void fxe_k(uint32_t m, int32_t e, FXE_OUT(r))
{
    *r_m = fxv_k32(m);
    *r_e = fxv_k32(FXE_BIAS + (uint32_t)e);
}

/* (m + rb) 2^E for m normalised (or 0) and rb in {0, 1}: the round up out
 * of 32 bits (m = 2^32 - 1, rb = 1; its low word is then 0) gives 2^31
 * 2^(E + 1) */
FXV_BODY void fxe_round(fxv_u32 m, fxv_u32 rb, fxv_u32 e, FXE_OUT(r))
{
    fxv_u64 t = fxv_add64(fxv_wide(m), fxv_wide(rb));
    fxv_u32 c = fxv_hi(t);
    *r_m = fxv_or(fxv_lo(t), fxv_shl(c, 31));
    *r_e = fxv_add32(e, c);
}

/* round(x / 2^32) or round(x / 2^31) of x = hi 2^32 + lo in [2^62, 2^64)
 * (or 0), whichever keeps 32 bits, times 2^E */
FXV_BODY void fxe_from_w(fxv_u32 hi, fxv_u32 lo, fxv_u32 e, FXE_OUT(r))
{
    fxv_u32 top = fxv_shr(hi, 31), sh = fxv_sub32(fxv_k32(1), top); /* sh = 1: bit 63 clear */
    fxv_u32 m = fxv_or(fxv_shlv(hi, sh), fxv_and(fxv_shr(lo, 31), sh));
    fxv_u32 rb = fxv_and(fxv_shrv(lo, fxv_sub32(fxv_k32(31), sh)), fxv_k32(1));
    fxe_round(m, rb, fxv_add32(e, fxv_add32(top, fxv_k32(31))), r_m, r_e);
}

/* x 2^e, exact (x < 2^32: one clz and a shift) */
FXV_BODY void fxe_from32(fxv_u32 x, int32_t e, FXE_OUT(r))
{
    fxv_u32 lz = fxv_clz(x);
    *r_m = fxv_shlv(x, fxv_min(lz, fxv_k32(31)));
    *r_e = fxv_sub32(fxv_k32(FXE_BIAS + (uint32_t)e), lz);
}

/* x 2^e of a 64-bit x, rounded to 32 significant bits: x normalised (its
 * top word, and the round bit below it, from the two words: a 32-bit x
 * loses nothing) */
FXV_BODY void fxe_from64(fxv_u64 x, int32_t e, FXE_OUT(r))
{
    fxv_u32 hi = fxv_hi(x), lo = fxv_lo(x), z = fxv_is0(hi);
    fxv_u32 ch = fxv_min(fxv_clz(hi), fxv_k32(31)), cl = fxv_min(fxv_clz(lo), fxv_k32(31));
    fxv_u32 mh = fxv_or(fxv_shlv(hi, ch), fxv_shrv(fxv_shr(lo, 1), fxv_sub32(fxv_k32(31), ch)));
    fxv_u32 rb = fxv_sel(z, fxv_k32(0), fxv_shr(fxv_shlv(lo, ch), 31));
    fxv_u32 lz = fxv_sel(z, fxv_add32(fxv_k32(32), fxv_clz(lo)), ch);
    fxe_round(fxv_sel(z, fxv_shlv(lo, cl), mh), rb, fxv_sub32(fxv_k32(FXE_BIAS + 32u + (uint32_t)e), lz), r_m,
              r_e);
}

/* a b */
FXV_BODY void fxe_mul(FXE_IN(a), FXE_IN(b), FXE_OUT(r))
{
    fxv_u64 p = fxv_mulw(a_m, b_m); /* [2^62, 2^64), or 0 */
    fxe_from_w(fxv_hi(p), fxv_lo(p), fxv_sub32(fxv_add32(a_e, b_e), fxv_k32(FXE_BIAS)), r_m, r_e);
}

/* a + b, both >= 0: x the operand of the larger exponent, y the other, d
 * the difference; N = x m + floor(y m 2^-d) < 2^33 and the first bit of y
 * below it, y m's bit d - 1 (so y is kept to 32 bits below x's last place:
 * at d = 32 its bits below 2^-1 are lost, which is below the rounding
 * position, and the truncation is monotone).  N >= 2^32 rounds N / 2 by
 * its last bit (no carry out: N <= 2^33 - 2), N < 2^32 by y's bit.  A zero
 * takes exponent 0, so it is y and adds nothing; d > 32 gives x (y below
 * half an ulp). */
FXV_BODY void fxe_add(FXE_IN(a), FXE_IN(b), FXE_OUT(r))
{
    fxv_u32 ae = fxv_sel(fxv_is0(a_m), fxv_k32(0), a_e), be = fxv_sel(fxv_is0(b_m), fxv_k32(0), b_e);
    fxv_u32 sw = fxv_lt(ae, be);
    fxv_u32 xm = fxv_sel(sw, b_m, a_m), xe = fxv_max(ae, be), ym = fxv_sel(sw, a_m, b_m);
    fxv_u32 d = fxv_sub32(xe, fxv_min(ae, be));
    fxv_u32 in = fxv_and(fxv_lt(fxv_k32(0), d), fxv_lt(d, fxv_k32(33)));      /* 1 <= d <= 32 */
    fxv_u32 t = fxv_shrv(ym, fxv_sub32(fxv_min(fxv_max(d, fxv_k32(1)), fxv_k32(32)), fxv_k32(1))); /* y m >> (d - 1) */
    fxv_u32 q = fxv_sel(fxv_is0(d), ym, fxv_and(fxv_shr(t, 1), in));
    fxv_u64 n = fxv_add64(fxv_wide(xm), fxv_wide(q));
    fxv_u32 c = fxv_hi(n), lo = fxv_lo(n);
    fxe_round(fxv_or(fxv_shrv(lo, c), fxv_shl(c, 31)),
              fxv_sel(fxv_lt(fxv_k32(0), c), fxv_and(lo, fxv_k32(1)), fxv_and(fxv_and(t, fxv_k32(1)), in)),
              fxv_add32(xe, c), r_m, r_e);
}

/* max(a, b), both > 0 */
FXV_BODY void fxe_max(FXE_IN(a), FXE_IN(b), FXE_OUT(r))
{
    fxv_u32 ta = fxv_or(fxv_lt(b_e, a_e), fxv_and(fxv_ge(a_e, b_e), fxv_ge(a_m, b_m)));
    *r_m = fxv_sel(ta, a_m, b_m);
    *r_e = fxv_sel(ta, a_e, b_e);
}

/* The divisions: q = floor(a m 2^31 / b m) and its remainder, one fxv_div64
 * (a m / 2 < 2^31 <= b m); b > 0.  A kernel that shares one division
 * between two cases selects the operands, then finishes each case from q. */
FXV_BODY fxv_u32 fxe_div_q(fxv_u32 a_m, fxv_u32 b_m, fxv_u32 *rem)
{
    return fxv_div64(fxv_shr(a_m, 1), fxv_shl(a_m, 31), b_m, rem);
}

/* a / b correctly rounded to 32 bits from q, rem: q in [2^30, 2^32) (a >
 * 0); below 2^31 one more quotient bit, 2 rem / b m, and the round bit
 * from the remainder after it; a = 0 gives 0 */
FXV_BODY void fxe_div_from_q(fxv_u32 q, fxv_u32 rem, FXE_IN(a), FXE_IN(b), FXE_OUT(r))
{
    fxv_u32 top = fxv_lt(fxv_k32(0x7FFFFFFFu), q), sh = fxv_bit(fxv_not(top));
    fxv_u32 half = fxv_sub32(b_m, rem), bit = fxv_ge(rem, half);     /* rem >= b m - rem */
    fxv_u32 rem2 = fxv_sub32(fxv_add32(rem, fxv_sel(bit, fxv_k32(0), rem)), /* 2 rem - bit b m < b m */
                             fxv_sel(bit, half, fxv_k32(0)));
    fxv_u32 rb = fxv_sel(top, fxv_bit(bit), fxv_bit(fxv_ge(rem2, fxv_sub32(b_m, rem2))));
    (void)a_m;
    fxe_round(fxv_or(fxv_shlv(q, sh), fxv_and(bit, sh)), rb,
              fxv_sub32(fxv_sub32(fxv_add32(a_e, fxv_k32(FXE_BIAS)), b_e), fxv_add32(sh, fxv_k32(31))), r_m, r_e);
}

FXV_BODY void fxe_div(FXE_IN(a), FXE_IN(b), FXE_OUT(r))
{
    fxv_u32 rem, q = fxe_div_q(a_m, b_m, &rem);
    fxe_div_from_q(q, rem, FXE(a), FXE(b), r_m, r_e);
}

/* round(a / b 2^f) with a single rounding, saturated at max (< 2^31 +
 * 2^30), from q, rem: a / b 2^f = (q + rem / b m) 2^-k, k = 31 - (ea - eb
 * + f); k < 0 is >= 2^31 (max), k > 32 below 1/2 (0), k = 0 rounds by the
 * remainder, 1 <= k <= 32 by q's bits alone (rem / b m < 1 cannot move q
 * across a rounding boundary: integers); a = 0 gives 0 */
FXV_BODY fxv_u32 fxe_div_fixed_from_q(fxv_u32 q, fxv_u32 rem, FXE_IN(a), FXE_IN(b), int32_t f, uint32_t max)
{
    /* kb = k + 64, held >= 0 (k < -64 read as -64: saturated either way) */
    fxv_u32 top = fxv_add32(b_e, fxv_k32((uint32_t)(95 - f)));
    fxv_u32 kb = fxv_sub32(top, fxv_min(a_e, top));
    fxv_u32 qall = fxv_is0(fxv_not(q)); /* q = 2^32 - 1 */
    fxv_u32 v0 = fxv_sel(qall, fxv_k32(max),
                         fxv_add32(q, fxv_and(fxv_bit(fxv_ge(rem, fxv_sub32(b_m, rem))), fxv_not(qall))));
    fxv_u32 t = fxv_shrv(q, fxv_min(fxv_sub32(fxv_max(kb, fxv_k32(65)), fxv_k32(65)), fxv_k32(31))); /* q >> (k - 1) */
    fxv_u32 v = fxv_sel(fxv_lt(kb, fxv_k32(65)), v0, fxv_add32(fxv_shr(t, 1), fxv_and(t, fxv_k32(1))));
    v = fxv_sel(fxv_lt(kb, fxv_k32(64)), fxv_k32(max), fxv_sel(fxv_lt(fxv_k32(96), kb), fxv_k32(0), v));
    return fxv_sel(fxv_is0(a_m), fxv_k32(0), fxv_min(v, fxv_k32(max)));
}

FXV_BODY fxv_u32 fxe_div_fixed(FXE_IN(a), FXE_IN(b), int32_t f, uint32_t max)
{
    fxv_u32 rem, q = fxe_div_q(a_m, b_m, &rem);
    return fxe_div_fixed_from_q(q, rem, FXE(a), FXE(b), f, max);
}

/* sqrt(a), correctly rounded to 32 bits: x = m 2^32 (E even) or m 2^31 (E
 * odd) in [2^62, 2^64), so e - 32 or e - 31 is even and halves exactly;
 * round(sqrt(x)) in [2^31, 2^32] from the exact root and remainder (sqrt
 * is never k + 1/2) */
FXV_BODY void fxe_sqrt(FXE_IN(a), FXE_OUT(r))
{
    fxv_u32 odd = fxv_and(a_e, fxv_k32(1)), g;
    fxv_u64 rem, x = fxv_join(fxv_shrv(a_m, odd), fxv_shl(fxv_and(a_m, odd), 31));
    g = fxv_isqrt64(x, &rem);
    fxe_round(g, fxv_bit(fxv_lt64(fxv_wide(g), rem)),
              fxv_shr(fxv_add32(fxv_sub32(fxv_add32(a_e, fxv_k32(FXE_BIAS)), fxv_k32(32)), odd), 1), r_m, r_e);
}

/* sqrt(x 2^e) of an exact 64-bit x, correctly rounded to 32 bits: x is
 * normalised by an even shift s (e - s even) into [2^62, 2^64) before the
 * integer root, so no bit of x is lost first; s = -1 (x >= 2^63, e odd)
 * drops one bit, rounded (x < 2^64 - 1: no wrap; monotone) */
FXV_BODY void fxe_sqrt64(fxv_u64 x, int32_t e, FXE_OUT(r))
{
    fxv_u32 lz = fxv_clz64(x), g;
    fxv_u32 sp = fxv_sub32(fxv_add32(lz, fxv_k32(1)), fxv_and(fxv_add32(lz, fxv_k32((uint32_t)e & 1u)), fxv_k32(1)));
    fxv_u64 rem, y = fxv_sel64(fxv_is0(sp), fxv_add64(fxv_shr64(x, 1), fxv_and64(x, 1)), /* s = sp - 1 */
                              fxv_shlv64(x, fxv_min(fxv_sub32(fxv_max(sp, fxv_k32(1)), fxv_k32(1)), fxv_k32(63))));
    g = fxv_isqrt64(y, &rem);
    fxe_round(g, fxv_bit(fxv_lt64(fxv_wide(g), rem)),
              fxv_shr(fxv_sub32(fxv_k32(2u * FXE_BIAS + 1u + (uint32_t)e), sp), 1), r_m, r_e); /* (e - s) / 2 */
}

/* round(a 2^f), saturated at max (>= 2^31): k = -(e + f); k <= 0 a left
 * shift by l = -k (saturated for l > 31 or a m 2^l > max), 1 <= k <= 32 a
 * rounded right shift (< 2^31), k > 32 below 1/2 (0); a = 0 gives 0 */
FXV_BODY fxv_u64 fxe_fixed(FXE_IN(a), int32_t f, uint64_t max)
{
    /* kb = k + 64, held >= 0 (k < -64 read as -64: saturated either way) */
    fxv_u32 top = fxv_k32(FXE_BIAS + 64u - (uint32_t)f), kb = fxv_sub32(top, fxv_min(a_e, top));
    fxv_u32 l = fxv_sub32(fxv_k32(64), fxv_min(kb, fxv_k32(64)));
    fxv_u64 vl = fxv_mulw(a_m, fxv_shlv(fxv_k32(1), fxv_min(l, fxv_k32(31)))); /* m 2^l < 2^63 */
    fxv_u32 t = fxv_shrv(a_m, fxv_min(fxv_sub32(fxv_max(kb, fxv_k32(65)), fxv_k32(65)), fxv_k32(31)));
    fxv_u64 vr = fxv_wide(fxv_sel(fxv_lt(fxv_k32(96), kb), fxv_k32(0), fxv_add32(fxv_shr(t, 1), fxv_and(t, fxv_k32(1)))));
    fxv_u32 sat = fxv_or(fxv_lt(fxv_k32(31), l), fxv_lt64(fxv_k64(max), vl));
    fxv_u64 v = fxv_sel64(fxv_lt(fxv_k32(64), kb), vr, fxv_sel64(sat, fxv_k64(max), vl));
    return fxv_sel64(fxv_is0(a_m), fxv_k64(0), v);
}

#endif
