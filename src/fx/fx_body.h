/* fx_body.h - the precise fixed-point tier (facet/fx.h), every kernel
 * written once over the integer lane op layer (src/fx/fx_ops.h) with the
 * fxe pseudo-float (src/fx/fx_pfloat.h): the scalar specification
 * (src/fx/fx_kernels.c over src/fx/fx_ops_scalar.h) and any SIMD port
 * (ports/<isa>/fx_<isa>.c over its own ops) instantiate these same bodies.
 * Private to the library.  Branch-free: every case is computed and
 * selected (a case that needs a division shares the one division by
 * selecting its operands); the 64/32 divisions and the integer roots are
 * exact (fxv_div64, fxv_isqrt64).
 *
 * Notation: capitals are raw Q15 inputs after clamping (N = N.H 2^15, A =
 * alpha 2^15, NL, NV, F0, ...), S = NL + NV (Q15, <= 2^16), T = 2^15 + LOV
 * = (1 + L.V) 2^15 (<= 2^16).  "Q60 exact" means an integer that equals the
 * real value times 2^60 with no rounding; bounds in brackets are the reason
 * it fits its container.  fxe values (m 2^e, 32-bit m) carry the wide-range
 * intermediates; each fxe operation rounds once (<= 2^-32 relative). */
#ifndef FACET_FX_BODY_H
#define FACET_FX_BODY_H

#include "fx_pfloat.h"

/* floor(p Y^4 / 2^32), Y^4 = (Y^2)^2 Q60 exact [Y <= 2^15, p <= 2^30]: the
 * 90-bit product kept as high and low words, so the caller's one rounding
 * is of the exact value.  Result < 2^58. */
FXV_BODY fxv_u64 fxb_p_y4_hi(fxv_u32 p, fxv_u32 y)
{
    fxv_u32 y2 = fxv_mul32(y, y);              /* <= 2^30 */
    fxv_u64 y4 = fxv_mulw(y2, y2);             /* Q60 */
    fxv_u64 lo = fxv_mulw(p, fxv_lo(y4));      /* < 2^62 */
    return fxv_add64(fxv_mulw(p, fxv_hi(y4)), fxv_shr64(lo, 32));
}

/* (1 + L.V) in Q31, raised to (N.L + N.V)^2 / 2 (the facet.h extension):
 * max(T 2^16, S^2) [<= 2^32: t <= 2 and s^2/2 <= 2]. */
FXV_BODY fxv_u64 fxb_t31(fxv_u32 t, fxv_u32 s)
{
    return fxv_max64(fxv_shl64(fxv_wide(t), 16), fxv_mulw(s, s));
}

/* a 64-bit a == b */
FXV_BODY fxv_u32 fxb_eq64(fxv_u64 a, fxv_u64 b)
{
    return fxv_and(fxv_not(fxv_lt64(a, b)), fxv_not(fxv_lt64(b, a)));
}

/* ---- noh_from_dots ----------------------------------------------------------
 * N.H = s / sqrt(2t), correctly rounded: raw = round(2^7 S / sqrt(T)) is the
 * largest k with (2k - 1)^2 T <= 2^16 S^2 [both sides <= 2^48].  If
 * 2^16 S^2 >= 2^32 T the triple is at or beyond N.H = 1 and the result is 1.
 * The estimate k0 (fxe sqrt and divide) is within 1: one exact compare
 * down, then one up, fix it (exhaustively: of the 2846599468 (S, T) below
 * the N.H = 1 case, S in [2^8, 2^16] and T in [1, 2^16], 1714 need one step
 * down, 1597 one up, none two or both).  T = 0 is the N.H = 1 case; its
 * lanes divide by T = 1 (dropped).
 * Error: 0 LSB (correctly rounded).  Cost: 1 sqrt, 1 division, ~8 mul64. */
FXV_BODY fxv_u32 fxb_noh_from_dots(fxv_i32 nol, fxv_i32 nov, fxv_i32 lov)
{
    fxv_u32 s = fxv_add32(fxv_cosine(nol), fxv_cosine(nov)), t = fxv_lov_t(lov), k, kd, ku, down, up;
    fxv_u32 FXE(sf), FXE(tf), FXE(rt);
    fxv_u64 s2 = fxv_shl64(fxv_mulw(s, s), 16); /* 2^16 S^2 <= 2^48 */
    fxv_u32 one = fxv_not(fxv_lt64(s2, fxv_shl64(fxv_wide(t), 32)));
    fxe_from32(s, 7, FXE_TO(sf));
    fxe_from32(fxv_max(t, fxv_k32(1)), 0, FXE_TO(tf));
    fxe_sqrt(FXE(tf), FXE_TO(rt));
    k = fxe_div_fixed(FXE(sf), FXE(rt), 0, FACET_FX_ONE);
    /* k > 0 and (2k - 1)^2 T > 2^16 S^2: k - 1 [(2k - 1)^2 < 2^32] */
    kd = fxv_sub32(fxv_shl(fxv_max(k, fxv_k32(1)), 1), fxv_k32(1));
    down = fxv_and(fxv_lt(fxv_k32(0), k), fxv_lt64(s2, fxv_mulw(fxv_mul32(kd, kd), t)));
    k = fxv_sub32(k, fxv_bit(down));
    /* k < 2^15 and (2k + 1)^2 T <= 2^16 S^2: k + 1 */
    ku = fxv_add32(fxv_shl(fxv_min(k, fxv_k32(FACET_FX_ONE - 1)), 1), fxv_k32(1));
    up = fxv_and(fxv_lt(k, fxv_k32(FACET_FX_ONE)), fxv_not(fxv_lt64(s2, fxv_mulw(fxv_mul32(ku, ku), t))));
    k = fxv_add32(k, fxv_bit(up));
    return fxv_sel(one, fxv_k32(FACET_FX_ONE), k);
}

/* ---- loh_from_dots ----------------------------------------------------------
 * L.H = sqrt((1 + L.V) / 2): raw = round(sqrt(T 2^14)) [T 2^14 <= 2^30],
 * an exact integer square root.  L.V = -1 gives 0.
 * Error: 0 LSB (correctly rounded).  Cost: 1 isqrt. */
FXV_BODY fxv_u32 fxb_loh_from_dots(fxv_i32 lov)
{
    fxv_u64 rem;
    fxv_u32 g = fxv_isqrt64(fxv_shl64(fxv_wide(fxv_lov_t(lov)), 14), &rem);
    return fxv_add32(g, fxv_bit(fxv_lt64(fxv_wide(g), rem)));
}

/* ---- Fresnel -----------------------------------------------------------------
 * F = f0 + (1 - f0) y^5, y = 1 - cos.  With Y = 2^15 - C exact:
 *   raw = F0 + round((2^15 - F0) Y^5 / 2^75),
 * Z = P Y^4 with P = Y (2^15 - F0) <= 2^30 (fxb_p_y4_hi), so the one
 * rounding is of the exact value.  F(f0, 1) = f0 and F(f0, 0) = 1 exactly.
 * Error: 0 LSB (correctly rounded).  Cost: 2 mul32, 3 mulw. */
FXV_BODY fxv_u32 fxb_fresnel_schlick(fxv_i32 f0_in, fxv_i32 cos_in)
{
    fxv_u32 f0 = fxv_unit(f0_in);
    fxv_u32 y = fxv_sub32(fxv_k32(FACET_FX_ONE), fxv_unit(cos_in));
    fxv_u32 p = fxv_mul32(y, fxv_sub32(fxv_k32(FACET_FX_ONE), f0));
    return fxv_add32(f0, fxv_narrow(fxv_rshr64(fxb_p_y4_hi(p, y), 43))); /* Z / 2^32 < 2^59 */
}

/* ---- GGX D --------------------------------------------------------------------
 * D = alpha^2 / (pi d^2), d = 1 - n^2 (1 - alpha^2) = (1-n)(1+n) + (n alpha)^2.
 *   d60 = (2^15 - N)(2^15 + N) 2^30 + (N A)^2   Q60 exact [d <= 1: <= 2^60]
 *   raw = round(2^13 A^2 2^-30 / (pi (d60 2^-60)^2)), one rounded division
 *         of A^2 by the fxe pi d^2.
 * N.H = 1: D = 1/(pi alpha^2) and raw = round(2^43 / (pi A^2)) up to 2^31.3,
 * more than 32-bit intermediates can round exactly; computed as
 * floor(floor(2^64/pi) / 2^(21-s)) / (A^2 2^s), s = clz(A^2) in [1, 21], by
 * the exact 2-by-1 division: correctly rounded unless 2^43/(pi A^2) lies
 * within 2^-31 LSB of a rounding boundary (tested: never, all alpha).  Both
 * cases share one division (its operands selected).
 * Below the peak d >= 2^-14, so raw <= 2^23.3 and the fxe error (<= 4 roundings
 * of 2^-32) is < 2^-6 LSB.  Monotone in N (d exact and decreasing).
 * Cost: 1 division, 3 fxe mul, 2 mul64. */
#define FXB_INV_PI_2_64 0x517CC1B727220A94ull /* floor(2^64 / pi) */
#define FXB_PI_M 0xC90FDAA2u                  /* round(pi 2^30), pi = FXB_PI_M 2^-30 */
#define FXB_INV_PI_M 0xA2F9836Eu              /* round(2^33 / pi), 1/pi = FXB_INV_PI_M 2^-33 */

/* the peak's dividend floor(2^64/pi) / 2^(21 - s) and divisor x 2^s of
 * x = A^2 (or ax ay), s = clz(x) in [1, 21] [x in [2^10, 2^30]] */
FXV_BODY fxv_u32 fxb_peak_args(fxv_u32 x, fxv_u64 *u)
{
    fxv_u32 s = fxv_clz(x);
    *u = fxv_shrv64(fxv_k64(FXB_INV_PI_2_64), fxv_sub32(fxv_k32(21), s));
    return fxv_shlv(x, s);
}

FXV_BODY fxv_u32 fxb_ggx_d(fxv_i32 noh, fxv_i32 alpha)
{
    fxv_u32 n = fxv_unit(noh), a = fxv_alpha(alpha), a2 = fxv_mul32(a, a), na = fxv_mul32(n, a); /* <= 2^30 */
    fxv_u32 peak = fxv_is0(fxv_sub32(fxv_k32(FACET_FX_ONE), n)), dp, d, q, rem;
    fxv_u32 FXE(df), FXE(d2), FXE(pi), FXE(den), FXE(af);
    fxv_u64 u, d60 = fxv_add64(fxv_shl64(fxv_wide(fxv_mul32(fxv_sub32(fxv_k32(FACET_FX_ONE), n),
                                                              fxv_add32(fxv_k32(FACET_FX_ONE), n))), 30),
                               fxv_mulw(na, na));
    fxe_from64(d60, -60, FXE_TO(df));
    fxe_mul(FXE(df), FXE(df), FXE_TO(d2));
    fxe_k(FXB_PI_M, -30, FXE_TO(pi));
    fxe_mul(FXE(pi), FXE(d2), FXE_TO(den));
    fxe_from32(a2, -30, FXE_TO(af));
    dp = fxb_peak_args(a2, &u);
    d = fxv_sel(peak, dp, den_m);
    q = fxv_div64(fxv_sel(peak, fxv_hi(u), fxv_shr(af_m, 1)), fxv_sel(peak, fxv_lo(u), fxv_shl(af_m, 31)), d, &rem);
    return fxv_sel(peak, fxv_add32(q, fxv_bit(fxv_ge(rem, fxv_sub32(d, rem)))), /* q < 2^31.4: no wrap */
                   fxe_div_fixed_from_q(q, rem, FXE(af), FXE(den), FACET_FX_D_FRAC, FACET_FX_MAX_D));
}

/* ---- anisotropic GGX D ------------------------------------------------------
 * D = (ax ay)^3 / (pi K^2), K = (t ay)^2 + (b ax)^2 + (n ax ay)^2 (facet.h),
 * with P = AX AY Q30 exact [<= 2^30, >= 2^10], u = |T| AY, v = |B| AX Q30
 * exact [<= 2^30]:
 *   K90 = (u^2 + v^2) 2^30 + N^2 P^2    Q90 exact, held as hi 2^32 + lo
 *         [K <= 3: hi < 2^60], then rounded once to an fxe (hi >= 2^32:
 *         the rounding of hi alone is the rounding of the whole, lo below
 *         its last place; else the 64-bit value itself);
 *   floor K >= P^2 / 2 (k = K / P^2 >= 1/2, facet.h) by an exact compare;
 *   raw = round(2^13 (P / K)^2 P / pi): P/K, its square, times P, times
 *         1/pi (4 fxe roundings; the constant 2^-33.1), one rounding to
 *         the format (fxe_fixed, saturating).
 * The exact peak (N = 2^15, T = B = 0: D = 1/(pi ax ay)) is ggx_d's peak
 * with A^2 replaced by P: correctly rounded by the exact division (the one
 * division, shared with P / K).
 * Error: <= 5 K-and-fxe roundings of 2^-33 relative (1/pi's included),
 * 2^-30.7, plus the final half LSB: <= 1 LSB below raw 2^30; above (ax ay
 * < 2^-18, inputs near the peak) up to 2 LSB; measured in facet/fx.h.
 * Cost: 1 division, ~5 fxe, ~8 mul64. */
FXV_BODY fxv_u32 fxb_ggx_aniso_d(fxv_i32 noh, fxv_i32 toh, fxv_i32 boh, fxv_i32 alpha_x, fxv_i32 alpha_y)
{
    fxv_u32 n = fxv_unit(noh), t = fxv_lov_t(toh), b = fxv_lov_t(boh), ax = fxv_alpha(alpha_x);
    fxv_u32 ay = fxv_alpha(alpha_y), p = fxv_mul32(ax, ay), n2 = fxv_mul32(n, n), u, v, lo, fl_lo, peak, big;
    fxv_u32 below, dp, d, qq, rem, FXE(k), FXE(pf), FXE(q), FXE(q2), FXE(q3), FXE(ipi), FXE(r);
    fxv_u64 s, p2 = fxv_mulw(p, p), a, hi, fl_hi, low, w;
    t = fxv_sub32(fxv_max(t, fxv_k32(FACET_FX_ONE)), fxv_min(t, fxv_k32(FACET_FX_ONE))); /* |T| */
    b = fxv_sub32(fxv_max(b, fxv_k32(FACET_FX_ONE)), fxv_min(b, fxv_k32(FACET_FX_ONE)));
    peak = fxv_and(fxv_is0(fxv_sub32(fxv_k32(FACET_FX_ONE), n)), fxv_is0(fxv_or(t, b)));
    u = fxv_mul32(t, ay);
    v = fxv_mul32(b, ax);
    s = fxv_add64(fxv_mulw(u, u), fxv_mulw(v, v)); /* Q60 <= 2^61 */
    /* K90 = s 2^30 + n2 p2: p2 = H 2^32 + L; n2 L < 2^62, n2 H < 2^58 */
    a = fxv_mulw(n2, fxv_lo(p2));
    low = fxv_add64(fxv_wide(fxv_lo(a)), fxv_shl64(fxv_wide(fxv_and(fxv_lo(s), fxv_k32(3))), 30)); /* < 2^33 */
    lo = fxv_lo(low);
    hi = fxv_add64(fxv_add64(fxv_mulw(n2, fxv_hi(p2)), fxv_shr64(a, 32)), fxv_add64(fxv_shr64(s, 2), fxv_shr64(low, 32)));
    /* the floor P^2 / 2 in Q90: P^2 2^29 */
    fl_hi = fxv_shr64(p2, 3);
    fl_lo = fxv_shl(fxv_and(fxv_lo(p2), fxv_k32(7)), 29);
    below = fxv_or(fxv_lt64(hi, fl_hi), fxv_and(fxb_eq64(hi, fl_hi), fxv_lt(lo, fl_lo)));
    hi = fxv_sel64(below, fl_hi, hi);
    lo = fxv_sel(below, fl_lo, lo);
    big = fxv_not(fxv_is0(fxv_hi(hi)));
    fxe_from64(fxv_sel64(big, hi, fxv_join(fxv_lo(hi), lo)), -90, FXE_TO(k));
    k_e = fxv_add32(k_e, fxv_and(big, fxv_k32(32))); /* hi alone: x 2^-58 */
    fxe_from32(p, -30, FXE_TO(pf));
    /* P / K, or the peak's division */
    dp = fxb_peak_args(p, &w);
    d = fxv_sel(peak, dp, k_m);
    qq = fxv_div64(fxv_sel(peak, fxv_hi(w), fxv_shr(pf_m, 1)), fxv_sel(peak, fxv_lo(w), fxv_shl(pf_m, 31)), d, &rem);
    fxe_div_from_q(qq, rem, FXE(pf), FXE(k), FXE_TO(q));
    fxe_mul(FXE(q), FXE(q), FXE_TO(q2));
    fxe_mul(FXE(q2), FXE(pf), FXE_TO(q3));
    fxe_k(FXB_INV_PI_M, -33, FXE_TO(ipi));
    fxe_mul(FXE(q3), FXE(ipi), FXE_TO(r));
    /* fxe_fixed, not fxe_div_fixed: raw reaches 2^31.3 (fxe_div_fixed stops below 2^31.6 - 2^30) */
    return fxv_sel(peak, fxv_add32(qq, fxv_bit(fxv_ge(rem, fxv_sub32(d, rem)))), /* < 2^31.4: no wrap */
                   fxv_narrow(fxe_fixed(FXE(r), FACET_FX_D_FRAC, FACET_FX_MAX_D)));
}

/* ---- Smith, exact ----------------------------------------------------------
 * w = alpha^2 (1 - n^2) + n^2 = A^2 (2^15-N)(2^15+N) + N^2 2^30   Q60 exact
 * [w <= 1]; sqrt(w) = fxe_sqrt64(w60): the root of the exact w, correctly
 * rounded to 32 significant bits (a fixed Q30 root would lose 2^-20
 * relative at sqrt(w) ~ alpha_min, 2^7 LSB of Vis at the grazing corner). */
FXV_BODY void fxb_smith_r(fxv_u32 n, fxv_u32 a2, FXE_OUT(r))
{
    fxv_u32 w = fxv_mul32(fxv_sub32(fxv_k32(FACET_FX_ONE), n), fxv_add32(fxv_k32(FACET_FX_ONE), n));
    fxe_sqrt64(fxv_add64(fxv_mulw(a2, w), fxv_shl64(fxv_wide(fxv_mul32(n, n)), 30)), -60, r_m, r_e);
}

/* G1 = 2n / (n + sqrt(w)), one rounded division of 2N by the fxe sum.
 * G1(0) = 0, G1(1) = 1 exactly (w = 1, the sum is 2).
 * Cost: 1 sqrt, 1 division, 1 fxe add, 3 mul. */
FXV_BODY fxv_u32 fxb_smith_g1(fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 n = fxv_unit(nov), a = fxv_alpha(alpha), FXE(nf), FXE(r), FXE(den), FXE(num);
    fxe_from32(n, -15, FXE_TO(nf));
    fxb_smith_r(n, fxv_mul32(a, a), FXE_TO(r));
    fxe_add(FXE(nf), FXE(r), FXE_TO(den));
    fxe_from32(fxv_shl(n, 1), -15, FXE_TO(num));
    return fxe_div_fixed(FXE(num), FXE(den), 15, FACET_FX_ONE);
}

/* nv sqrt(w(nl)) + nl sqrt(w(nv)) */
FXV_BODY void fxb_g2_den(fxv_u32 nl, fxv_u32 nv, fxv_u32 a2, FXE_OUT(r))
{
    fxv_u32 FXE(rl), FXE(rv), FXE(fl), FXE(fv), FXE(x), FXE(y);
    fxb_smith_r(nl, a2, FXE_TO(rl));
    fxb_smith_r(nv, a2, FXE_TO(rv));
    fxe_from32(nv, -15, FXE_TO(fv));
    fxe_from32(nl, -15, FXE_TO(fl));
    fxe_mul(FXE(fv), FXE(rl), FXE_TO(x));
    fxe_mul(FXE(fl), FXE(rv), FXE_TO(y));
    fxe_add(FXE(x), FXE(y), r_m, r_e);
}

/* G2 = 2 nl nv / den, one rounded division [2 NL NV <= 2^31 exact].
 * Cost: 2 sqrt, 1 division, 3 fxe ops, ~8 mul. */
FXV_BODY fxv_u32 fxb_smith_g2(fxv_i32 nol, fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 nl = fxv_cosine(nol), nv = fxv_cosine(nov), a = fxv_alpha(alpha), FXE(num), FXE(den);
    fxe_from32(fxv_shl(fxv_mul32(nl, nv), 1), -30, FXE_TO(num));
    fxb_g2_den(nl, nv, fxv_mul32(a, a), FXE_TO(den));
    return fxe_div_fixed(FXE(num), FXE(den), 15, FACET_FX_ONE);
}

/* 0.5 as an fxe */
FXV_BODY void fxb_half(FXE_OUT(r)) { fxe_k(0x80000000u, -32, r_m, r_e); }

/* Vis = 0.5 / den: UQ16.16, <= 0.5 / (2 c sqrt(a^2 + c^2 (1 - a^2))) =
 * 15894.3 at c = 2^-8, a = 2^-10 [raw < 2^30].  Cost: as smith_g2. */
FXV_BODY fxv_u32 fxb_smith_vis(fxv_i32 nol, fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 nl = fxv_cosine(nol), nv = fxv_cosine(nov), a = fxv_alpha(alpha), FXE(h), FXE(den);
    fxb_half(FXE_TO(h));
    fxb_g2_den(nl, nv, fxv_mul32(a, a), FXE_TO(den));
    return fxe_div_fixed(FXE(h), FXE(den), FACET_FX_VIS_FRAC, FACET_FX_MAX_VIS);
}

/* G1(L) G1(V) = 4 nl nv / ((nl + sqrt w(nl)) (nv + sqrt w(nv))), one
 * division.  Cost: 2 sqrt, 1 division, 3 fxe ops, ~8 mul. */
FXV_BODY fxv_u32 fxb_smith_g2_uncorrelated(fxv_i32 nol, fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 nl = fxv_cosine(nol), nv = fxv_cosine(nov), a = fxv_alpha(alpha), a2 = fxv_mul32(a, a);
    fxv_u32 FXE(fl), FXE(fv), FXE(rl), FXE(rv), FXE(dl), FXE(dv), FXE(den), FXE(num);
    fxe_from32(nl, -15, FXE_TO(fl));
    fxb_smith_r(nl, a2, FXE_TO(rl));
    fxe_add(FXE(fl), FXE(rl), FXE_TO(dl));
    fxe_from32(nv, -15, FXE_TO(fv));
    fxb_smith_r(nv, a2, FXE_TO(rv));
    fxe_add(FXE(fv), FXE(rv), FXE_TO(dv));
    fxe_from64(fxv_shl64(fxv_mulw(nl, nv), 2), -30, FXE_TO(num)); /* 4 NL NV <= 2^32 */
    fxe_mul(FXE(dl), FXE(dv), FXE_TO(den));
    return fxe_div_fixed(FXE(num), FXE(den), 15, FACET_FX_ONE);
}

/* ---- Smith, Hammon's approximation ----------------------------------------
 * G1 ~ 2n / (n (2 - alpha) + alpha): den30 = N (2^16 - A) + A 2^15 exact
 * [<= 2^31]; raw = round(2N 2^30 / den30): both operands exact, so the result
 * is correctly rounded.  Cost: 1 division, 2 mul. */
FXV_BODY fxv_u32 fxb_smith_g1_hammon(fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 n = fxv_unit(nov), a = fxv_alpha(alpha), FXE(num), FXE(den);
    fxv_u32 den30 = fxv_add32(fxv_mul32(n, fxv_sub32(fxv_k32(2 * FACET_FX_ONE), a)), fxv_shl(a, 15));
    fxe_from32(fxv_shl(n, 1), -15, FXE_TO(num));
    fxe_from32(den30, -30, FXE_TO(den));
    return fxe_div_fixed(FXE(num), FXE(den), 15, FACET_FX_ONE);
}

/* m = (1 - alpha) 2 nl nv + alpha (nl + nv) in Q45 exact
 * [(2^15 - A) 2 NL NV <= 2^46, A S 2^15 <= 2^46, m <= 2], as an fxe. */
FXV_BODY void fxb_hammon_m(fxv_u32 nl, fxv_u32 nv, fxv_u32 a, FXE_OUT(r))
{
    fxv_u64 m45 = fxv_add64(fxv_mul64x32(fxv_shl64(fxv_mulw(nl, nv), 1), fxv_sub32(fxv_k32(FACET_FX_ONE), a)),
                            fxv_shl64(fxv_mulw(a, fxv_add32(nl, nv)), 15));
    fxe_from64(m45, -45, r_m, r_e);
}

/* G2 ~ 2 nl nv / m.  m45 rounded once to 32 bits (<= 2^-32), then one
 * rounded division.  Cost: 1 division, ~6 mul. */
FXV_BODY fxv_u32 fxb_smith_g2_hammon(fxv_i32 nol, fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 nl = fxv_cosine(nol), nv = fxv_cosine(nov), a = fxv_alpha(alpha), FXE(num), FXE(m);
    fxe_from32(fxv_shl(fxv_mul32(nl, nv), 1), -30, FXE_TO(num));
    fxb_hammon_m(nl, nv, a, FXE_TO(m));
    return fxe_div_fixed(FXE(num), FXE(m), 15, FACET_FX_ONE);
}

/* Vis ~ 0.5 / m: UQ16.16, <= 0.5 / (2 c^2 (1-a) + 2 a c) = 13117 [raw < 2^30]. */
FXV_BODY fxv_u32 fxb_smith_vis_hammon(fxv_i32 nol, fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 FXE(h), FXE(m);
    fxb_half(FXE_TO(h));
    fxb_hammon_m(fxv_cosine(nol), fxv_cosine(nov), fxv_alpha(alpha), FXE_TO(m));
    return fxe_div_fixed(FXE(h), FXE(m), FACET_FX_VIS_FRAC, FACET_FX_MAX_VIS);
}

/* ---- shadowing and visibility: the rest of the menu ----------------------
 * Q15 inputs; the G terms are Q15 (max 1), the Vis terms UQ16.16. */

/* N.L N.V: Q30 exact [<= 2^30], rounded once. */
FXV_BODY fxv_u32 fxb_g_implicit(fxv_i32 nol, fxv_i32 nov)
{
    return fxv_shr(fxv_add32(fxv_mul32(fxv_unit(nol), fxv_unit(nov)), fxv_k32(1u << 14)), 15);
}

/* N.L N.V / max(N.L, N.V) = min(N.L, N.V): exact. */
FXV_BODY fxv_u32 fxb_g_neumann(fxv_i32 nol, fxv_i32 nov) { return fxv_min(fxv_unit(nol), fxv_unit(nov)); }

/* min(1, g / V.H), g = 2 N.H min(N.L, N.V) Q30 exact [<= 2^31]; g >= V.H
 * (V.H = 0 included: its lanes divide by 1, dropped) gives 1, else one
 * rounded division. */
FXV_BODY fxv_u32 fxb_g_cook_torrance(fxv_i32 nol, fxv_i32 nov, fxv_i32 noh, fxv_i32 voh)
{
    fxv_u32 vh = fxv_unit(voh), FXE(gf), FXE(vf);
    fxv_u32 g = fxv_mul32(fxv_shl(fxv_unit(noh), 1), fxv_min(fxv_cosine(nol), fxv_cosine(nov)));
    fxe_from32(g, -30, FXE_TO(gf));
    fxe_from32(fxv_max(vh, fxv_k32(1)), -15, FXE_TO(vf));
    return fxv_sel(fxv_ge(g, fxv_shl(vh, 15)), fxv_k32(FACET_FX_ONE),
                   fxe_div_fixed(FXE(gf), FXE(vf), 15, FACET_FX_ONE));
}

/* min(1, N.L N.V / V.H^2): both Q30 exact [<= 2^30]; V.H = 0 is the 1
 * case (its lanes divide by 1, dropped). */
FXV_BODY fxv_u32 fxb_g_kelemen(fxv_i32 nol, fxv_i32 nov, fxv_i32 voh)
{
    fxv_u32 p = fxv_mul32(fxv_cosine(nol), fxv_cosine(nov)), vh = fxv_unit(voh), q = fxv_mul32(vh, vh);
    fxv_u32 FXE(pf), FXE(qf);
    fxe_from32(p, -30, FXE_TO(pf));
    fxe_from32(fxv_max(q, fxv_k32(1)), -30, FXE_TO(qf));
    return fxv_sel(fxv_ge(p, q), fxv_k32(FACET_FX_ONE), fxe_div_fixed(FXE(pf), FXE(qf), 15, FACET_FX_ONE));
}

/* Walter's Beckmann G1 (facet.h), with p = a sqrt(1 - n^2), q = n:
 * q < 1.6 p decided exactly as 25 N^2 2^24 < A^2 W, W = (2^15 - N)(2^15 + N)
 * [both < 2^60]; then G1 = min(1, q (3.535 p + 2.181 q) / (p (p + 2.276 q)
 * + 2.577 q^2)) in fxe (every term >= 0; the denominator > 0 on every lane:
 * p > 0 at N < 2^15, q > 0 at N > 0), the constants rounded to Q30. */
#define FXB_WALTER_A 3795677348u /* round(3.535 2^30) */
#define FXB_WALTER_B 2341830918u /* round(2.181 2^30) */
#define FXB_WALTER_C 2443836391u /* round(2.276 2^30) */
#define FXB_WALTER_D 2767032680u /* round(2.577 2^30) */
FXV_BODY fxv_u32 fxb_smith_g1_beckmann(fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 n = fxv_unit(nov), a = fxv_alpha(alpha);
    fxv_u32 w = fxv_mul32(fxv_sub32(fxv_k32(FACET_FX_ONE), n), fxv_add32(fxv_k32(FACET_FX_ONE), n));
    fxv_u32 lt = fxv_lt64(fxv_shl64(fxv_mulw(fxv_mul32(fxv_k32(25), n), n), 24), fxv_mul64x32(fxv_mulw(a, a), w));
    fxv_u32 FXE(af), FXE(sw), FXE(p), FXE(q), FXE(ka), FXE(kb), FXE(kc), FXE(kd), FXE(x), FXE(y), FXE(z);
    fxv_u32 FXE(num), FXE(den);
    fxe_from32(a, -15, FXE_TO(af));
    fxe_sqrt64(fxv_wide(w), -30, FXE_TO(sw));
    fxe_mul(FXE(af), FXE(sw), FXE_TO(p));
    fxe_from32(n, -15, FXE_TO(q));
    fxe_from32(fxv_k32(FXB_WALTER_A), -30, FXE_TO(ka));
    fxe_from32(fxv_k32(FXB_WALTER_B), -30, FXE_TO(kb));
    fxe_from32(fxv_k32(FXB_WALTER_C), -30, FXE_TO(kc));
    fxe_from32(fxv_k32(FXB_WALTER_D), -30, FXE_TO(kd));
    fxe_mul(FXE(ka), FXE(p), FXE_TO(x));
    fxe_mul(FXE(kb), FXE(q), FXE_TO(y));
    fxe_add(FXE(x), FXE(y), FXE_TO(z));
    fxe_mul(FXE(q), FXE(z), FXE_TO(num));
    fxe_mul(FXE(kc), FXE(q), FXE_TO(x));
    fxe_add(FXE(p), FXE(x), FXE_TO(y));
    fxe_mul(FXE(p), FXE(y), FXE_TO(z));           /* p (p + 2.276 q) */
    fxe_mul(FXE(q), FXE(q), FXE_TO(x));
    fxe_mul(FXE(kd), FXE(x), FXE_TO(y));          /* 2.577 q^2 */
    fxe_add(FXE(z), FXE(y), FXE_TO(den));
    return fxv_sel(lt, fxe_div_fixed(FXE(num), FXE(den), 15, FACET_FX_ONE), fxv_k32(FACET_FX_ONE));
}

/* n / (n (1 - k) + k), k = a sqrt(2/pi): k Q47 = A round(sqrt(2/pi) 2^32)
 * [< 2^47]; den Q62 = N (2^47 - k) + k 2^15 exact [< 2^63]. */
#define FXB_SQRT_2_PI_32 3426888095u /* round(sqrt(2/pi) 2^32) */
FXV_BODY fxv_u32 fxb_smith_g1_schlick_beckmann(fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 n = fxv_unit(nov), FXE(nf), FXE(df);
    fxv_u64 k = fxv_mulw(fxv_alpha(alpha), fxv_k32(FXB_SQRT_2_PI_32));
    fxv_u64 den = fxv_add64(fxv_mul64x32(fxv_sub64(fxv_k64(1ull << 47), k), n), fxv_shl64(k, 15));
    fxe_from32(n, -15, FXE_TO(nf));
    fxe_from64(den, -62, FXE_TO(df));
    return fxe_div_fixed(FXE(nf), FXE(df), 15, FACET_FX_ONE);
}

/* 0.5 / (nl (nv (1 - a) + a) + nv (nl (1 - a) + a)) = 0.5 / m, Hammon's m:
 * the same function, the same exact m45, the same bits. */
FXV_BODY fxv_u32 fxb_smith_vis_joint_approx(fxv_i32 nol, fxv_i32 nov, fxv_i32 alpha)
{
    return fxb_smith_vis_hammon(nol, nov, alpha);
}

/* The fitted visibility: 1 / (nv R(nl) + nl R(nv)), R(x) = max(K1 a, K2 a +
 * K3 t, K4 a + K5 t), t = x sigma, sigma = 1 + C1 a - |C2| a^2 (the float
 * constants of facet/detail/vis_fit.h are exact in Q30).  sigma Q60 exact
 * [2^60 + C1 A 2^15 - |C2| A^2, in (0.35, 1.08) 2^60]; the rest fxe (all
 * terms > 0). */
#define FXB_VFIT_K1 2215746816u
#define FXB_VFIT_K2 648049856u
#define FXB_VFIT_K3 2104759296u
#define FXB_VFIT_K4 1724301312u
#define FXB_VFIT_K5 1380932736u
#define FXB_VFIT_C1 82209328u
#define FXB_VFIT_C2 779814784u /* |C2| (C2 < 0) */
FXV_BODY void fxb_vis_fit_r(fxv_u32 x, FXE_IN(ka1), FXE_IN(ka2), FXE_IN(ka4), FXE_IN(s3), FXE_IN(s5), FXE_OUT(r))
{
    fxv_u32 FXE(xf), FXE(t3), FXE(t5), FXE(b3), FXE(b5), FXE(mx);
    fxe_from32(x, -15, FXE_TO(xf));
    fxe_mul(FXE(s3), FXE(xf), FXE_TO(t3));
    fxe_add(FXE(ka2), FXE(t3), FXE_TO(b3));
    fxe_mul(FXE(s5), FXE(xf), FXE_TO(t5));
    fxe_add(FXE(ka4), FXE(t5), FXE_TO(b5));
    fxe_max(FXE(b3), FXE(b5), FXE_TO(mx));
    fxe_max(FXE(ka1), FXE(mx), r_m, r_e);
}
FXV_BODY fxv_u32 fxb_smith_vis_fit(fxv_i32 nol, fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 nl = fxv_cosine(nol), nv = fxv_cosine(nov), a = fxv_alpha(alpha);
    fxv_u32 FXE(sgf), FXE(ka1), FXE(ka2), FXE(ka4), FXE(k3), FXE(k5), FXE(s3), FXE(s5), FXE(rl), FXE(rv);
    fxv_u32 FXE(fl), FXE(fv), FXE(x), FXE(y), FXE(den), FXE(one);
    fxv_u64 sg = fxv_sub64(fxv_add64(fxv_k64(1ull << 60), fxv_shl64(fxv_mulw(fxv_k32(FXB_VFIT_C1), a), 15)),
                           fxv_mul64x32(fxv_mulw(a, a), fxv_k32(FXB_VFIT_C2)));
    fxe_from64(sg, -60, FXE_TO(sgf));
    fxe_from64(fxv_mulw(fxv_k32(FXB_VFIT_K1), a), -45, FXE_TO(ka1));
    fxe_from64(fxv_mulw(fxv_k32(FXB_VFIT_K2), a), -45, FXE_TO(ka2));
    fxe_from64(fxv_mulw(fxv_k32(FXB_VFIT_K4), a), -45, FXE_TO(ka4));
    fxe_from32(fxv_k32(FXB_VFIT_K3), -30, FXE_TO(k3));
    fxe_from32(fxv_k32(FXB_VFIT_K5), -30, FXE_TO(k5));
    fxe_mul(FXE(k3), FXE(sgf), FXE_TO(s3));
    fxe_mul(FXE(k5), FXE(sgf), FXE_TO(s5));
    fxb_vis_fit_r(nl, FXE(ka1), FXE(ka2), FXE(ka4), FXE(s3), FXE(s5), FXE_TO(rl));
    fxb_vis_fit_r(nv, FXE(ka1), FXE(ka2), FXE(ka4), FXE(s3), FXE(s5), FXE_TO(rv));
    fxe_from32(nv, -15, FXE_TO(fv));
    fxe_from32(nl, -15, FXE_TO(fl));
    fxe_mul(FXE(fv), FXE(rl), FXE_TO(x));
    fxe_mul(FXE(fl), FXE(rv), FXE_TO(y));
    fxe_add(FXE(x), FXE(y), FXE_TO(den));
    fxe_from32(fxv_k32(1), 0, FXE_TO(one));
    return fxe_div_fixed(FXE(one), FXE(den), FACET_FX_VIS_FRAC, FACET_FX_MAX_VIS);
}

/* ---- Hammon's diffuse -------------------------------------------------------
 * With t = 1 + L.V (raised, t31 Q31 exact) and s = nl + nv:
 *   facing (0.9 - 0.4 facing) = t (4.5 - t) / 10    (facing = t/2)
 *   1 + 0.5 / N.H = (2s + sqrt(2t)) / (2s)          (N.H = s / sqrt(2t) <= 1)
 *   rough  = t (4.5 - t) (2s + sqrt(2t)) / (20 s)
 *   smooth = 1.05 P(nl) P(nv),  P(x) = 1 - (1 - x)^5
 *   result = albedo / pi ((1 - alpha) smooth + alpha rough + albedo 0.1159 pi alpha)
 * 4.5 - t = (9 2^30 - t31) 2^-31 and 2 - t are exact; P(x) is exact to Q30
 * (fxb_p_y4_hi's 90-bit product), everything else fxe (all terms >= 0: no
 * cancellation).  Max 20.65 at nl = nv = FACET_FX_COS_MIN, L.V = 1, alpha =
 * albedo = 1 (N.H = 2^-8) [UQ8.24 raw < 2^28.4]. */
#define FXB_C105_M 0x86666666u    /* round(1.05 2^31), e = -31 */
#define FXB_MULTI_M 0xBA6CB3FCu   /* round(0.1159 pi 2^33) (0.36411058855), e = -33 */

/* 1 - (1 - x)^5 in Q30: 2^30 - round(Y^5 / 2^45) [Y^5 Q75 exact as in
 * Fresnel: fxb_p_y4_hi(Y, Y) = Y^5 / 2^32 < 2^44] */
FXV_BODY fxv_u32 fxb_one_minus_pow5_q30(fxv_u32 x)
{
    fxv_u32 y = fxv_sub32(fxv_k32(FACET_FX_ONE), x);
    return fxv_sub32(fxv_k32(1u << 30), fxv_narrow(fxv_rshr64(fxb_p_y4_hi(y, y), 13)));
}

/* the diffuse as fxe from the shared pieces, in two parts for the RGB
 * form: the single-scattering bracket (no albedo), then the albedo part;
 * nl, nv, a raw, t31 raised */
FXV_BODY void fxb_diffuse_single(fxv_u32 nl, fxv_u32 nv, fxv_u64 t31, fxv_u32 a, FXE_OUT(r))
{
    fxv_u32 s = fxv_add32(nl, nv);
    fxv_u32 FXE(t), FXE(u), FXE(tt), FXE(sf), FXE(rt), FXE(q), FXE(sum), FXE(x), FXE(d), FXE(rough);
    fxv_u32 FXE(pl), FXE(pv), FXE(k), FXE(smooth), FXE(fa), FXE(fb);
    fxe_from64(t31, -31, FXE_TO(t));
    fxe_from64(fxv_sub64(fxv_k64(9ull << 30), t31), -31, FXE_TO(u));
    fxe_mul(FXE(t), FXE(u), FXE_TO(tt));                  /* t (4.5 - t) */
    fxe_from32(s, -14, FXE_TO(sf));
    fxe_from64(t31, -30, FXE_TO(q));
    fxe_sqrt(FXE(q), FXE_TO(rt));
    fxe_add(FXE(sf), FXE(rt), FXE_TO(sum));               /* 2s + sqrt(2t) */
    fxe_mul(FXE(tt), FXE(sum), FXE_TO(x));
    fxe_from32(fxv_mul32(fxv_k32(20), s), -15, FXE_TO(d));
    fxe_div(FXE(x), FXE(d), FXE_TO(rough));
    fxe_from32(fxb_one_minus_pow5_q30(nl), -30, FXE_TO(pl));
    fxe_from32(fxb_one_minus_pow5_q30(nv), -30, FXE_TO(pv));
    fxe_mul(FXE(pl), FXE(pv), FXE_TO(x));
    fxe_k(FXB_C105_M, -31, FXE_TO(k));
    fxe_mul(FXE(x), FXE(k), FXE_TO(smooth));
    fxe_from32(fxv_sub32(fxv_k32(FACET_FX_ONE), a), -15, FXE_TO(fa));
    fxe_mul(FXE(fa), FXE(smooth), FXE_TO(x));
    fxe_from32(a, -15, FXE_TO(fb));
    fxe_mul(FXE(fb), FXE(rough), FXE_TO(u));
    fxe_add(FXE(x), FXE(u), r_m, r_e);
}

FXV_BODY void fxb_diffuse_albedo(FXE_IN(single), fxv_u32 a, fxv_u32 alb, FXE_OUT(r))
{
    fxv_u32 FXE(fl), FXE(fa), FXE(k), FXE(x), FXE(multi), FXE(y);
    fxe_from32(alb, -15, FXE_TO(fl));
    fxe_from32(a, -15, FXE_TO(fa));
    fxe_mul(FXE(fl), FXE(fa), FXE_TO(x));
    fxe_k(FXB_MULTI_M, -33, FXE_TO(k));
    fxe_mul(FXE(x), FXE(k), FXE_TO(multi));
    fxe_k(FXB_INV_PI_M, -33, FXE_TO(k));
    fxe_mul(FXE(fl), FXE(k), FXE_TO(x));
    fxe_add(FXE(single), FXE(multi), FXE_TO(y));
    fxe_mul(FXE(x), FXE(y), r_m, r_e);
}

/* Error: FACET_FX_ERR_DIFFUSE_HAMMON (measured).  Cost: 1 sqrt, 1 division,
 * ~12 fxe ops, ~10 mul64. */
FXV_BODY fxv_u32 fxb_diffuse_hammon(fxv_i32 nol, fxv_i32 nov, fxv_i32 lov, fxv_i32 alpha, fxv_i32 albedo)
{
    fxv_u32 nl = fxv_cosine(nol), nv = fxv_cosine(nov), a = fxv_alpha(alpha), FXE(single), FXE(r);
    fxb_diffuse_single(nl, nv, fxb_t31(fxv_lov_t(lov), fxv_add32(nl, nv)), a, FXE_TO(single));
    fxb_diffuse_albedo(FXE(single), a, fxv_unit(albedo), FXE_TO(r));
    return fxv_narrow(fxe_fixed(FXE(r), FACET_FX_BRDF_FRAC, FACET_FX_MAX_DIFF));
}

/* ---- the whole model --------------------------------------------------------
 * brdf = D Vis_hammon F(f0, L.H) + diffuse, from the dots, N.H never formed:
 *   N.H^2 = s^2 / 2t, so d = 1 - N.H^2 (1 - alpha^2) = e / 2t with
 *   e60 = (t31 - S^2) 2^30 + A^2 S^2   Q60 exact [each term <= 2^62]
 *   (t31 - S^2 = (2t - s^2) 2^30 >= 0: the peak's cancellation is exact),
 *   D = alpha^2 (2t)^2 / (pi e^2),  Vis = 0.5 / m (m as fxb_hammon_m),
 *   L.H = sqrt(t/2), 1 - L.H = (2 - t) / (2 (1 + L.H)) [2 - t exact]:
 *   spec = (alpha 2t)^2 F / (2 pi e^2 m).
 * Max 4.38e9 (D 333772 x Vis 13117 at the grazing peak) [UQ40.24 < 2^57].
 * Error: FACET_FX_ERR_BRDF_HAMMON (LSB where brdf < 16; relative above).
 * Cost: 2 sqrt, 3 division, ~30 fxe ops. */
#define FXB_TWO_PI_M 0xC90FDAA2u /* round(2 pi 2^29), e = -29 */

/* What brdf_hammon computes before f0 and albedo enter, shared by the RGB
 * form; per channel the same fxe operations in the same order, so each
 * channel is brdf_hammon's bits.  Its lanes as out-parameters, then values
 * (sizeless vector types: no struct). */
#define FXB_BRDF_GEOM_PARAMS_(T, P) T P##y5_m, T P##y5_e, T P##a2t2_m, T P##a2t2_e, T P##den_m, T P##den_e, \
                                    T P##single_m, T P##single_e, T P##a
#define FXB_BRDF_GEOM_ARGS_(P) P##y5_m, P##y5_e, P##a2t2_m, P##a2t2_e, P##den_m, P##den_e, P##single_m, \
                               P##single_e, P##a

FXV_BODY void fxb_brdf_geometry(fxv_i32 nol, fxv_i32 nov, fxv_i32 lov, fxv_i32 alpha,
                                  FXB_BRDF_GEOM_PARAMS_(fxv_u32 *, G_))
{
    fxv_u32 nl = fxv_cosine(nol), nv = fxv_cosine(nov), a = fxv_alpha(alpha), s = fxv_add32(nl, nv);
    fxv_u32 FXE(e), FXE(af), FXE(tf), FXE(a2t), FXE(lf), FXE(lh), FXE(nf), FXE(one), FXE(df), FXE(y), FXE(y2);
    fxv_u32 FXE(y4), FXE(e2), FXE(m), FXE(x), FXE(k);
    fxv_u64 s2 = fxv_mulw(s, s), t31 = fxb_t31(fxv_lov_t(lov), s);
    fxv_u64 e60 = fxv_add64(fxv_shl64(fxv_sub64(t31, s2), 30), fxv_mul64x32(s2, fxv_mul32(a, a)));
    fxe_from64(e60, -60, FXE_TO(e));
    fxe_from32(a, -15, FXE_TO(af));
    fxe_from64(t31, -30, FXE_TO(tf));
    fxe_mul(FXE(af), FXE(tf), FXE_TO(a2t));
    fxe_from64(t31, -32, FXE_TO(lf));
    fxe_sqrt(FXE(lf), FXE_TO(lh));
    fxe_from64(fxv_sub64(fxv_k64(1ull << 32), t31), -32, FXE_TO(nf));
    fxe_k(0x80000000u, -31, FXE_TO(one));
    fxe_add(FXE(one), FXE(lh), FXE_TO(df));
    fxe_div(FXE(nf), FXE(df), FXE_TO(y));
    fxe_mul(FXE(y), FXE(y), FXE_TO(y2));
    fxe_mul(FXE(y2), FXE(y2), FXE_TO(y4));
    fxe_mul(FXE(y4), FXE(y), G_y5_m, G_y5_e);
    fxe_mul(FXE(e), FXE(e), FXE_TO(e2));
    fxb_hammon_m(nl, nv, a, FXE_TO(m));
    fxe_mul(FXE(e2), FXE(m), FXE_TO(x));
    fxe_k(FXB_TWO_PI_M, -29, FXE_TO(k));
    fxe_mul(FXE(x), FXE(k), G_den_m, G_den_e);
    fxe_mul(FXE(a2t), FXE(a2t), G_a2t2_m, G_a2t2_e);
    fxb_diffuse_single(nl, nv, t31, a, G_single_m, G_single_e);
    *G_a = a;
}

FXV_BODY fxv_u64 fxb_brdf_channel(FXB_BRDF_GEOM_PARAMS_(fxv_u32, G_), fxv_i32 f0, fxv_i32 albedo)
{
    fxv_u32 f0r = fxv_unit(f0), FXE(ff), FXE(fo), FXE(x), FXE(f), FXE(sp), FXE(spec), FXE(dif), FXE(r);
    fxe_from32(f0r, -15, FXE_TO(ff));
    fxe_from32(fxv_sub32(fxv_k32(FACET_FX_ONE), f0r), -15, FXE_TO(fo));
    fxe_mul(FXE(fo), FXE(G_y5), FXE_TO(x));
    fxe_add(FXE(ff), FXE(x), FXE_TO(f));
    fxe_mul(FXE(G_a2t2), FXE(f), FXE_TO(sp));
    fxe_div(FXE(sp), FXE(G_den), FXE_TO(spec));
    fxb_diffuse_albedo(FXE(G_single), G_a, fxv_unit(albedo), FXE_TO(dif));
    fxe_add(FXE(spec), FXE(dif), FXE_TO(r));
    return fxe_fixed(FXE(r), FACET_FX_BRDF_FRAC, FACET_FX_MAX_BRDF);
}

FXV_BODY fxv_u64 fxb_brdf_hammon(fxv_i32 nol, fxv_i32 nov, fxv_i32 lov, fxv_i32 alpha, fxv_i32 f0,
                                   fxv_i32 albedo)
{
    fxv_u32 FXB_BRDF_GEOM_ARGS_(G_);
    fxb_brdf_geometry(nol, nov, lov, alpha, FXB_BRDF_GEOM_ARGS_(&G_));
    return fxb_brdf_channel(FXB_BRDF_GEOM_ARGS_(G_), f0, albedo);
}

#endif
