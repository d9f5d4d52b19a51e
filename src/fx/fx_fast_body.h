/* fx_fast_body.h - the fx_fast tier (facet/fx.h "fast tier"), every kernel
 * written once (fxq_<kernel>) over the lane op layer (src/fx/fx_ops.h): the
 * scalar specification (src/fx/fx_fast.c over src/fx/fx_ops_scalar.h) and
 * the SIMD ports (ports/<isa>/fx_<isa>.c over their own ops) instantiate
 * these same bodies.  Branch-free (selects, min/max, per-lane shifts, table
 * lookups), integer only, no division and no root.
 *
 * The datapath (facet/fx.h's "datapath" paragraph says it in short):
 *   - raw Q15 inputs are clamped to the domain first;
 *   - products of small operands are 16 x 16 -> 32 bit (fxv_mul32: the
 *     operands and the product below 2^32 as the brackets show), wider
 *     ones the high word of one 32 x 32 -> 64 product (fxq_mulhi); a chain
 *     of high words keeps every factor >= 2^21, so no renormalisation is
 *     needed inside it and each truncation is <= 2^-21 relative;
 *   - the quantities exact in 64 bits (d of D, w of the Smith roots, e and
 *     the Smith denominators) give their top 32 bits (fxq_top: one clz);
 *   - each value carries a scale 2^-E, E a constant or, where the range is
 *     wide, an exponent lane (a sum of clz counts and constants);
 *   - 1/x and sqrt(x): 129- and 97-entry Q20 tables of the function on the
 *     normalised mantissa, 7 index bits, 15 bits of linear interpolation
 *     (one multiply): 1/x to 2^-16, sqrt to 2^-15 relative; no iteration
 *     (and a 257-entry table of the diffuse's 1 + y + ... + y^4);
 *   - every rounding is a truncation (floor) except the final one of each
 *     kernel (round to nearest, ties up) and the few marked "+ half";
 *     results saturate at the format's maximum (fxq_div).
 * Bounds in brackets say why a value fits its 32 (or 64) bits. */
#ifndef FACET_FX_FAST_BODY_H
#define FACET_FX_FAST_BODY_H

#include "fx_body.h" /* the exact kernels and the formulas' constants both tiers share */

/* the bodies are meant to be one straight-line sequence per kernel */
#if defined(__GNUC__)
#define FXQ_INLINE static inline __attribute__((always_inline))
#else
#define FXQ_INLINE static inline
#endif


/* floor(a b / 2^32): one UMULL's high word (four 16x16 MULS on ARMv6-M) */
FXQ_INLINE fxv_u32 fxq_mulhi(fxv_u32 a, fxv_u32 b) { return fxv_hi(fxv_mulw(a, b)); }

/* 1 / x on [1, 2): fxq_rcp_tab[i] = round(2^35 / (2^15 + 2^8 i)), i = 0..128,
 * the first (2^20) held at 2^20 - 1 so every result is below 2^20 */
static const uint32_t fxq_rcp_tab[129] = {
    1048575, 1040448, 1032444, 1024563, 1016801, 1009156, 1001625, 994205, 986895, 979691,
    972592, 965595, 958698, 951899, 945195, 938586, 932068, 925640, 919300, 913046, 906877,
    900790, 894785, 888859, 883011, 877240, 871544, 865921, 860370, 854890, 849479, 844137,
    838861, 833650, 828504, 823422, 818401, 813441, 808541, 803699, 798915, 794188, 789516,
    784899, 780336, 775825, 771366, 766958, 762601, 758292, 754032, 749820, 745654, 741534,
    737460, 733430, 729444, 725501, 721601, 717742, 713924, 710147, 706409, 702711, 699051,
    695429, 691844, 688296, 684784, 681308, 677867, 674461, 671089, 667750, 664444, 661171,
    657930, 654721, 651542, 648395, 645278, 642190, 639132, 636103, 633102, 630130, 627186,
    624269, 621378, 618515, 615678, 612866, 610081, 607320, 604584, 601873, 599186, 596523,
    593884, 591268, 588674, 586104, 583555, 581029, 578525, 576042, 573580, 571139, 568719,
    566320, 563940, 561580, 559241, 556920, 554619, 552336, 550073, 547827, 545601, 543392,
    541201, 539027, 536871, 534732, 532610, 530505, 528416, 526344, 524288,
};

/* sqrt on [1/4, 1]: fxq_sqrt_tab[j] = round(2^20 sqrt((32 + j) / 128)), j = 0..96,
 * the last (2^20) held at 2^20 - 1 so every result is below 2^20 */
static const uint32_t fxq_sqrt_tab[97] = {
    524288, 532417, 540424, 548314, 556091, 563762, 571330, 578798, 586172, 593454, 600647,
    607756, 614782, 621729, 628599, 635395, 642119, 648773, 655360, 661881, 668339, 674734,
    681070, 687347, 693568, 699733, 705844, 711903, 717911, 723869, 729778, 735640, 741455,
    747225, 752951, 758634, 764275, 769874, 775432, 780952, 786432, 791875, 797280, 802649,
    807982, 813280, 818544, 823775, 828972, 834137, 839270, 844372, 849444, 854485, 859497,
    864479, 869433, 874359, 879258, 884129, 888974, 893792, 898584, 903351, 908093, 912811,
    917504, 922173, 926819, 931442, 936041, 940619, 945174, 949707, 954219, 958709, 963179,
    967627, 972056, 976464, 980853, 985222, 989572, 993903, 998215, 1002508, 1006783,
    1011040, 1015279, 1019501, 1023705, 1027892, 1032062, 1036215, 1040352, 1044472,
    1048575,
};

/* r ~ 2^51 / m for m in [2^31, 2^32): r in [2^19, 2^20).  The top 7 bits
 * below the leading one index the table, the next 15 interpolate linearly
 * [(R[i] - R[i+1]) < 2^13, f < 2^15: the product < 2^28]; relative error
 * <= 2^-16 (interpolation h^2/8 max|f''| = 2^-16 absolute at 1/x ~ 1,
 * table and step roundings 2^-21; measured 2^-15.95). */
FXQ_INLINE fxv_u32 fxq_rcp20(fxv_u32 m)
{
    fxv_u32 i = fxv_sub32(fxv_shr(m, 24), fxv_k32(128)), f = fxv_and(fxv_shr(m, 9), fxv_k32(0x7FFF));
    fxv_u32 r0 = fxv_lut(fxq_rcp_tab, i), r1 = fxv_lut(fxq_rcp_tab, fxv_add32(i, fxv_k32(1)));
    return fxv_sub32(r0, fxv_shr(fxv_add32(fxv_mul32(fxv_sub32(r0, r1), f), fxv_k32(1u << 14)), 15));
}

/* s ~ 2^20 sqrt(x / 2^32) for x in [2^30, 2^32): s in [2^19, 2^20).  7
 * index bits, 15 interpolation bits [(S[j+1] - S[j]) < 2^13]; relative
 * error <= 2^-15 (h^2/8 max|f''| at 1/4: 2^-16 absolute on sqrt = 1/2;
 * measured 2^-14.98). */
FXQ_INLINE fxv_u32 fxq_sqrt20(fxv_u32 x)
{
    fxv_u32 j = fxv_sub32(fxv_shr(x, 25), fxv_k32(32)), f = fxv_and(fxv_shr(x, 10), fxv_k32(0x7FFF));
    fxv_u32 s0 = fxv_lut(fxq_sqrt_tab, j), s1 = fxv_lut(fxq_sqrt_tab, fxv_add32(j, fxv_k32(1)));
    return fxv_add32(s0, fxv_shr(fxv_add32(fxv_mul32(fxv_sub32(s1, s0), f), fxv_k32(1u << 14)), 15));
}

/* ---- shared pieces (the input clamps: src/fx/fx_ops.h) --------------------- */

/* The dot triple.  With S = NL + NV and lov clamped to [-32767, 32768]
 * (L.V = -1 and -1 + 2^-15 give the same raised t: s^2/2 >= 2^-15):
 *   P = (2^16 - S)(2^16 + S)  = (4 - s^2) 2^30            [<= 2^32 - 2^16]
 *   Q = (2^15 - LOV) 2^16     = (4 - 2t) 2^30             [<= 2^32 - 2^16]
 *   u = min(P, Q)             = (4 - 2 t_r) 2^30, t_r = max(t, s^2/2), the
 *                               facet.h raise, exact
 *   w = P - u                 = (2 t_r - s^2) 2^30, exact (the peak's
 *                               cancellation without rounding)
 *   c = ~u = 2^32 - 1 - u     = (t_r / 2) 2^32 - 1 = L.H^2 2^32 - 1
 *                               [c >= 2^16 - 1: t_r >= s^2/2 >= 2^-15] */
/* Results through out-parameters, here and below, not structs: RVV's
 * vector types are sizeless (no struct members), and one body serves
 * every port. */
FXQ_INLINE void fxq_dots_of(fxv_u32 nl, fxv_u32 nv, fxv_i32 lov, fxv_u32 *s, fxv_u32 *u, fxv_u32 *w,
                            fxv_u32 *c)
{
    fxv_u32 t = fxv_clamp_off(lov, -FACET_FX_ONE + 1, FACET_FX_ONE); /* LOV + 32767 */
    fxv_u32 p, q;
    *s = fxv_add32(nl, nv);
    p = fxv_mul32(fxv_sub32(fxv_k32(65536), *s), fxv_add32(fxv_k32(65536), *s));
    q = fxv_shl(fxv_sub32(fxv_k32(65535), t), 16); /* 2^15 - LOV in [0, 65535] */
    *u = fxv_min(p, q);
    *w = fxv_sub32(p, *u);
    *c = fxv_not(*u);
}

/* sqrt(c 2^-32) for c in [2^16 - 1, 2^32): an even normalising shift 2h
 * [h <= 8], the table: sqrt = s 2^-(20 + h), s in [2^19, 2^20); returns s,
 * *h = h */
FXQ_INLINE fxv_u32 fxq_sqrt32(fxv_u32 c, fxv_u32 *h)
{
    fxv_u32 k = fxv_and(fxv_clz(c), fxv_k32(30));
    *h = fxv_shr(k, 1);
    return fxq_sqrt20(fxv_shlv(c, k));
}

/* ---- loh_from_dots ------------------------------------------------------------
 * L.H = sqrt(T / 2^16), T = 2^15 + LOV: c = T 2^16 - 1 (exact for T >= 1,
 * [(T - 1) 2^16 <= 2^32 - 2^16]), raw = round(s / 2^(5 + h)); T = 0 gives 0. */
FXQ_INLINE fxv_u32 fxq_loh_from_dots(fxv_i32 lov)
{
    fxv_u32 t = fxv_lov_t(lov);
    fxv_u32 c = fxv_add32(fxv_shl(fxv_sub32(fxv_max(t, fxv_k32(1)), fxv_k32(1)), 16), fxv_k32(0xFFFF));
    fxv_u32 rh, rs = fxq_sqrt32(c, &rh);
    fxv_u32 v = fxv_shr(fxv_add32(fxv_shrv(rs, fxv_add32(rh, fxv_k32(4))), fxv_k32(1)), 1);
    return fxv_sel(fxv_lt(t, fxv_k32(1)), fxv_k32(0), v);
}

/* ---- noh_from_dots ------------------------------------------------------------
 * N.H = s / sqrt(2 t_r) = s / (2 L.H) = S 2^(4 + h) / s_c; with r =
 * rcp20(s_c 2^12) ~ 2^39 / s_c: x = hi(S 2^15, r 2^12) = S r 2^-5 [S 2^15
 * <= 2^31], raw = round(x / 2^(15 - h)), at most 2^15; w = 0 (at or past
 * N.H = 1) gives 2^15. */
FXQ_INLINE fxv_u32 fxq_noh_from_dots(fxv_i32 nol, fxv_i32 nov, fxv_i32 lov)
{
    fxv_u32 gs, gu, gw, gc, rh, rs, x, v;
    fxq_dots_of(fxv_cosine(nol), fxv_cosine(nov), lov, &gs, &gu, &gw, &gc);
    rs = fxq_sqrt32(gc, &rh);
    x = fxq_mulhi(fxv_shl(gs, 15), fxv_shl(fxq_rcp20(fxv_shl(rs, 12)), 12));
    v = fxv_shr(fxv_add32(fxv_shrv(x, fxv_sub32(fxv_k32(14), rh)), fxv_k32(1)), 1);
    v = fxv_min(v, fxv_k32(FACET_FX_ONE));
    return fxv_sel(fxv_lt(gw, fxv_k32(1)), fxv_k32(FACET_FX_ONE), v);
}

/* ---- 32-bit fixed helpers ---------------------------------------------------
 * (fxq_mulhi: at the top.) */

/* the top 32 bits of a 64-bit x with 2^26 <= x < 2^63: top = floor(x /
 * 2^(32 - kk)), kk = min(clz(hi), 31) in [1, 31], so top >= 2^31 when x >=
 * 2^32 and top = floor(x / 2) >= 2^25 below (every user normalises again,
 * or squares it: >= 2^18); x ~ top 2^(32 - e), truncated <= 2^-25 */
FXQ_INLINE fxv_u32 fxq_top(fxv_u64 v, fxv_u32 *e)
{
    fxv_u32 hi = fxv_hi(v), kk = fxv_min(fxv_clz(hi), fxv_k32(31));
    *e = kk;
    return fxv_or(fxv_shlv(hi, kk), fxv_shrv(fxv_lo(v), fxv_sub32(fxv_k32(32), kk)));
}

/* the top word of v at fxq_top's shift kk of another value (kk in [1, 31]) */
FXQ_INLINE fxv_u32 fxq_top_at(fxv_u64 v, fxv_u32 kk)
{
    return fxv_or(fxv_shlv(fxv_hi(v), kk), fxv_shrv(fxv_lo(v), fxv_sub32(fxv_k32(32), kk)));
}

/* the quotient's normalising shift, rounding and saturation, shared by
 * fxq_divb and fxq_divbn (below): q = hi(n 2^kn, 1/(d 2^kd)) in [2^30, 2^32) */
FXQ_INLINE fxv_u32 fxq_div_round(fxv_u32 q, fxv_u32 kn, fxv_u32 kd, fxv_u32 b, uint32_t max)
{
    fxv_u32 kq = fxv_sub32(fxv_k32(1), fxv_shr(q, 31)); /* q 2^kq in [2^31, 2^32) */
    fxv_u32 srb = fxv_add32(fxv_sub32(fxv_add32(b, kn), kd), kq); /* sr + 64 */
    fxv_u32 qn = fxv_shlv(q, kq);
    fxv_u32 t = fxv_shrv(qn, fxv_min(fxv_sub32(fxv_max(srb, fxv_k32(65)), fxv_k32(65)), fxv_k32(31)));
    fxv_u32 v = fxv_sel(fxv_lt(srb, fxv_k32(65)), t, fxv_shr(fxv_add32(t, fxv_k32(1)), 1));
    v = fxv_sel(fxv_lt(srb, fxv_k32(64)), fxv_k32(max), fxv_sel(fxv_lt(srb, fxv_k32(97)), v, fxv_k32(0)));
    return fxv_min(v, fxv_k32(max));
}

/* round(n / d 2^s) (ties up), saturated at max, with s given biased as the
 * lane b = 95 - s (so a per-lane s works too); n < 2^32 (0 gives 0), d >= 1:
 *   kn, kd normalise n and d; r = rcp20(d 2^kd) ~ 2^51 / (d 2^kd);
 *   q = hi(n 2^kn, r 2^12) ~ n / d 2^(31 + kn - kd), in [2^30, 2^32) for n > 0
 *   (relative error <= 2^-15.9: the table, the truncations), then shifted
 *   by kq = 1 - (bit 31 of q) into [2^31, 2^32);
 *   the result q 2^-sr, sr = 31 + kn - kd + kq - s: a rounded right shift;
 *   sr < 0 means >= 2^32 and saturates, sr > 32 gives 0 [every shift count
 *   in [0, 31]]. */
FXQ_INLINE fxv_u32 fxq_divb(fxv_u32 n, fxv_u32 d, fxv_u32 b, uint32_t max)
{
    fxv_u32 kn = fxv_min(fxv_clz(n), fxv_k32(31)), kd = fxv_clz(d);
    fxv_u32 q = fxq_mulhi(fxv_shlv(n, kn), fxv_shl(fxq_rcp20(fxv_shlv(d, kd)), 12));
    return fxq_div_round(q, kn, kd, b, max);
}
#define fxq_div(n, d, s, max) fxq_divb(n, d, fxv_k32(95u - (s)), max)

/* ~ 2^63 / m for m in [2^31, 2^32): rcp20 (2^-16) and one Newton step,
 * r1 = 2 hi(r, ~t), r = rcp20(m) 2^12, t = hi(m, r) ~ 2^31 (1 + e) [~t =
 * 2^32 - 1 - t = 2^31 (1 - e) - 1 + (t's floor), in (2^31 - 2^17, 2^31 +
 * 2^13); hi(r, ~t) < 2^31]: relative error <= 2^-30 (e^2 <= 2^-32 and the
 * two floors).  The G terms divide by it (fxq_divbn): with the table's
 * 2^-16, a ratio near 1 whose numerator and denominator move together
 * (G ~ 1) steps backwards where the interpolation's chord slope is off
 * (issue 25 item 4); at 2^-30 its output is monotone. */
FXQ_INLINE fxv_u32 fxq_rcpn(fxv_u32 m)
{
    fxv_u32 r = fxv_shl(fxq_rcp20(m), 12);
    return fxv_shl(fxq_mulhi(r, fxv_not(fxq_mulhi(m, r))), 1);
}

/* fxq_divb with the refined reciprocal: the quotient q to 2^-30, then the
 * same normalising shift, rounding and saturation */
FXQ_INLINE fxv_u32 fxq_divbn(fxv_u32 n, fxv_u32 d, fxv_u32 b, uint32_t max)
{
    fxv_u32 kn = fxv_min(fxv_clz(n), fxv_k32(31)), kd = fxv_clz(d);
    fxv_u32 q = fxq_mulhi(fxv_shlv(n, kn), fxq_rcpn(fxv_shlv(d, kd)));
    return fxq_div_round(q, kn, kd, b, max);
}

/* ---- Fresnel ------------------------------------------------------------------
 * F = f0 + (1 - f0) y^5, Y = 2^15 - C (Q15), hi = fxq_mulhi:
 *   y2 = Y^2                            Q30 exact   [<= 2^30]
 *   y4 = hi(2 y2, 2 y2)                 Q30         [<= 2^30]
 *   y5 = hi(2 y4, Y 2^16)               Q30         [<= 2^30]
 *   F30 = F0 2^15 + hi(2 y5, (2^15 - F0) 2^16)    Q30 [<= 2^30]
 *   raw = round(F30 / 2^15).
 * Every operand <= 2^31; truncations <= 2^-30 each, so the error is the
 * final rounding; F(f0, 1) = f0 and F(f0, 0) = 1 exactly. */
FXQ_INLINE fxv_u32 fxq_fresnel_schlick(fxv_i32 f0_in, fxv_i32 cos_in)
{
    fxv_u32 f0 = fxv_unit(f0_in), y = fxv_sub32(fxv_k32(FACET_FX_ONE), fxv_unit(cos_in));
    fxv_u32 y2 = fxv_shl(fxv_mul32(y, y), 1);
    fxv_u32 y4 = fxq_mulhi(y2, y2);
    fxv_u32 y5 = fxq_mulhi(fxv_shl(y4, 1), fxv_shl(y, 16));
    fxv_u32 t = fxq_mulhi(fxv_shl(y5, 1), fxv_shl(fxv_sub32(fxv_k32(FACET_FX_ONE), f0), 16));
    return fxv_shr(fxv_add32(fxv_add32(fxv_shl(f0, 15), t), fxv_k32(1u << 14)), 15);
}

/* ---- GGX D ----------------------------------------------------------------------
 * d = (1 - n)(1 + n) + (n a)^2: d60 = (2^15 - N)(2^15 + N) 2^30 + (N A)^2 Q60
 * exact [<= 2^60, >= a^2 2^60 >= 2^40]; its top 32 bits dt (fxq_top, d =
 * dt 2^-(28 + e)); pi d^2 = pd 2^-(22 + 2e), pd = hi(hi(dt, dt), pi 2^30)
 * [>= 2^29.6]; D 2^13 = A^2 / pd 2^(5 + 2e), one fxq_div. */

FXQ_INLINE fxv_u32 fxq_ggx_d(fxv_i32 noh, fxv_i32 alpha)
{
    fxv_u32 n = fxv_unit(noh), a = fxv_alpha(alpha), na = fxv_mul32(n, a), e;
    fxv_u64 d60 = fxv_add64(fxv_mulw(fxv_mul32(fxv_sub32(fxv_k32(FACET_FX_ONE), n), fxv_add32(fxv_k32(FACET_FX_ONE), n)),
                                     fxv_k32(1u << 30)),
                            fxv_mulw(na, na));
    fxv_u32 dt = fxq_top(d60, &e);
    fxv_u32 pd = fxq_mulhi(fxq_mulhi(dt, dt), fxv_k32(FXB_PI_M));
    return fxq_divb(fxv_mul32(a, a), pd, fxv_sub32(fxv_k32(90), fxv_shl(e, 1)), FACET_FX_MAX_D);
}

/* ---- anisotropic GGX D ------------------------------------------------------
 * The top 32 bits of x = hi 2^32 + lo (x != 0), normalised: top in [2^31,
 * 2^32), x ~ top 2^(32 - e), e = the leading zeros of x in [0, 63]
 * (truncated <= 2^-31); both cases computed, one selected [every shift
 * count in [0, 31]]. */
FXQ_INLINE fxv_u32 fxq_norm_hl(fxv_u32 hi, fxv_u32 lo, fxv_u32 *e)
{
    fxv_u32 ch = fxv_min(fxv_clz(hi), fxv_k32(31)), cl = fxv_min(fxv_clz(lo), fxv_k32(31));
    fxv_u32 th = fxv_or(fxv_shlv(hi, ch), fxv_shrv(fxv_shr(lo, 1), fxv_sub32(fxv_k32(31), ch)));
    fxv_u32 zero = fxv_lt(hi, fxv_k32(1));
    *e = fxv_sel(zero, fxv_add32(cl, fxv_k32(32)), ch);
    return fxv_sel(zero, fxv_shlv(lo, cl), th);
}

/* D = (ax ay)^3 / (pi K^2), K = (t ay)^2 + (b ax)^2 + (n ax ay)^2:
 *   P = AX AY Q30 exact [2^10 .. 2^30]; u = |T| AY, v = |B| AX Q30 exact [<= 2^30];
 *   K61 = 2 u^2 + 2 v^2 + floor(N^2 P^2 / 2^29) in 64 bits [each term
 *         <= 2^61: < 2^63]: with P^2 = H 2^32 + L (mulw, exact),
 *         N^2 P^2 / 2^29 = N^2 (H 2^3) + N^2 L / 2^29 [H 2^3 < 2^31];
 *         truncated by < 1 against K61 >= P^2 >= 2^20 (2^-20 relative);
 *   the floor K >= P^2 / 2 (P^2 in Q61) as an exact 64-bit max from the
 *         32-bit halves, normalised (fxq_norm_hl): K = kt 2^(-29 - eK)
 *         [eK <= 2 kp + 1: K61 >= P^2 >= 2^(62 - 2 kp)];
 *   pi K^2 = pd 2^(-24 - 2 eK), pd = hi(hi(kt, kt), pi 2^30) [>= 2^29.6];
 *   P^3: kp = clz(P), Pn = P 2^kp, p3 = hi(hi(Pn, Pn), Pn) [>= 2^29],
 *         (ax ay)^3 = p3 2^(-26 - 3 kp);
 *   D 2^13 = p3 / pd 2^(11 - 3 kp + 2 eK), one fxq_div (b = 84 + 3 kp -
 *         2 eK >= 60: no wrap). */
FXQ_INLINE fxv_u32 fxq_ggx_aniso_d(fxv_i32 noh, fxv_i32 toh, fxv_i32 boh, fxv_i32 alpha_x,
                                       fxv_i32 alpha_y)
{
    fxv_u32 n = fxv_unit(noh), ax = fxv_alpha(alpha_x), ay = fxv_alpha(alpha_y);
    fxv_u32 t = fxv_lov_t(toh), b = fxv_lov_t(boh);
    fxv_u32 p = fxv_mul32(ax, ay), n2 = fxv_mul32(n, n), u, v, kh, kl, fh, fl, m, kt, ek, kp, pn, pd, p3;
    fxv_u64 p2 = fxv_mulw(p, p), k61;
    /* |T| = |t - 2^15| from t in [0, 2^16] */
    t = fxv_sub32(fxv_max(t, fxv_k32(FACET_FX_ONE)), fxv_min(t, fxv_k32(FACET_FX_ONE)));
    b = fxv_sub32(fxv_max(b, fxv_k32(FACET_FX_ONE)), fxv_min(b, fxv_k32(FACET_FX_ONE)));
    u = fxv_mul32(t, ay);
    v = fxv_mul32(b, ax);
    k61 = fxv_add64(fxv_add64(fxv_mulw(u, fxv_shl(u, 1)), fxv_mulw(v, fxv_shl(v, 1))),
                    fxv_add64(fxv_mulw(n2, fxv_shl(fxv_hi(p2), 3)), fxv_shr64(fxv_mulw(n2, fxv_lo(p2)), 29)));
    kh = fxv_hi(k61);
    kl = fxv_lo(k61);
    fh = fxv_hi(p2);
    fl = fxv_lo(p2);
    /* K < floor: hi below, or hi equal and lo below */
    m = fxv_or(fxv_lt(kh, fh), fxv_and(fxv_not(fxv_lt(fh, kh)), fxv_lt(kl, fl)));
    kt = fxq_norm_hl(fxv_sel(m, fh, kh), fxv_sel(m, fl, kl), &ek);
    pd = fxq_mulhi(fxq_mulhi(kt, kt), fxv_k32(FXB_PI_M));
    kp = fxv_clz(p);
    pn = fxv_shlv(p, kp);
    p3 = fxq_mulhi(fxq_mulhi(pn, pn), pn);
    return fxq_divb(p3, pd, fxv_sub32(fxv_add32(fxv_k32(84), fxv_mul32(kp, fxv_k32(3))), fxv_shl(ek, 1)),
                    FACET_FX_MAX_D);
}

/* ---- log2 and 2^f on integers (the GTR terms) -------------------------------
 * log2 m for a normalised mantissa x = m 2^31, m in [1, 2): Q31 in [0, 2^31].
 *   i = the 4 bits below the leading one; r_i = ceil(2^35 / (16 + i)) ~
 *   2^31 / (1 + i/16) [2^30 .. 2^31]; (1 + u) 2^30 = hi(x, r_i), u in [0,
 *   1/16 + 2^-30] (r_i rounded up: never below 1, exact product >= 2^62);
 *   log2 m = L_i + log2(1 + u), L_i = round(-log2(r_i / 2^31) 2^31) the
 *   table of the rounded r_i (so r_i's rounding cancels);
 *   log2(1 + u) = u (c1 - u (c2 - u (c3 - u (c4 - u c5)))), c_k = 1/(k ln 2)
 *   Q31 [c1 < 2^31.53]: the alternating Taylor series, every bracket
 *   positive (u <= 1/16), truncated after u^5: error <= u^6 / (6 ln 2) <=
 *   2^-26; with U = u 2^35 [< 2^31 + 2^6], hi(U, p) >> 3 = u p Q31, the
 *   truncations 5 x 2^-31.  Total |error| <= 2^-25.5 (+ L_i's 2^-32);
 *   measured 2^-26.13 (tests/fx/test_fx_prims.c, which enforces 2^-25.5). */
static const uint32_t fxq_log2_rcp_tab[16] = {
    2147483648u, 2021161081u, 1908874354u, 1808407283u, 1717986919u, 1636178018u, 1561806290u, 1493901669u,
    1431655766u, 1374389535u, 1321528399u, 1272582903u, 1227133514u, 1184818565u, 1145324613u, 1108378658u,
};
static const uint32_t fxq_log2_tab[16] = {
    0u, 187825021u, 364911162u, 532420280u, 691335319u, 842495249u, 986621887u, 1124340738u,
    1256197404u, 1382670639u, 1504182841u, 1621108566u, 1733781491u, 1842500156u, 1947532723u, 2049120971u,
};
#define FXQ_LOG2_C1 3098164009u /* round(2^31 / (k ln 2)), k = 1..5 */
#define FXQ_LOG2_C2 1549082005u
#define FXQ_LOG2_C3 1032721336u
#define FXQ_LOG2_C4 774541002u
#define FXQ_LOG2_C5 619632802u
FXQ_INLINE fxv_u32 fxq_log2m31(fxv_u32 x)
{
    fxv_u32 i = fxv_and(fxv_shr(x, 27), fxv_k32(15));
    fxv_u32 uu = fxv_shl(fxv_sub32(fxq_mulhi(x, fxv_lut(fxq_log2_rcp_tab, i)), fxv_k32(1u << 30)), 5);
    fxv_u32 p = fxv_sub32(fxv_k32(FXQ_LOG2_C4), fxv_shr(fxq_mulhi(uu, fxv_k32(FXQ_LOG2_C5)), 3));
    p = fxv_sub32(fxv_k32(FXQ_LOG2_C3), fxv_shr(fxq_mulhi(uu, p), 3));
    p = fxv_sub32(fxv_k32(FXQ_LOG2_C2), fxv_shr(fxq_mulhi(uu, p), 3));
    p = fxv_sub32(fxv_k32(FXQ_LOG2_C1), fxv_shr(fxq_mulhi(uu, p), 3));
    return fxv_add32(fxv_lut(fxq_log2_tab, i), fxv_shr(fxq_mulhi(uu, p), 3));
}

/* 2^f for f = F 2^-32 in [0, 1): Q30 in [2^30 - 2^7, 2^31].  Degree 5,
 * interpolated at the Chebyshev nodes of [0, 1] (relative error 2^-23.2;
 * every coefficient positive: Horner on unsigned words), p = c_k + hi(F,
 * p) Q30 [p <= 2^31], truncations 5 x 2^-30: total <= 2^-22.9 relative;
 * measured 2^-23.22 (tests/fx/test_fx_prims.c enforces 2^-22.9). */
#define FXQ_EXP2_C0 1073741715u
#define FXQ_EXP2_C1 744268966u
#define FXQ_EXP2_C2 257850314u
#define FXQ_EXP2_C3 59979580u
#define FXQ_EXP2_C4 9609550u
#define FXQ_EXP2_C5 2033403u
FXQ_INLINE fxv_u32 fxq_exp2f30(fxv_u32 f)
{
    fxv_u32 p = fxv_add32(fxv_k32(FXQ_EXP2_C4), fxq_mulhi(f, fxv_k32(FXQ_EXP2_C5)));
    p = fxv_add32(fxv_k32(FXQ_EXP2_C3), fxq_mulhi(f, p));
    p = fxv_add32(fxv_k32(FXQ_EXP2_C2), fxq_mulhi(f, p));
    p = fxv_add32(fxv_k32(FXQ_EXP2_C1), fxq_mulhi(f, p));
    return fxv_add32(fxv_k32(FXQ_EXP2_C0), fxq_mulhi(f, p));
}

/* g(m) = m / (1 - 2^-m) (g(0) = 1/ln 2) as a fraction *n / *d, n Q26, d
 * Q31, for m = M 2^-26 in [0, 60]:
 *   m >= 1/2: n = M [<= 60 2^26 < 2^32], d = (1 - 2^-m) 2^31 [>= 0.29
 *     2^31]: m = k + f, 2^-m 2^31 = 2^(1 - f) 2^30 >> k with 1 - f read
 *     as ~F (2^-32 low: no 2^32), k clamped to 31 (2^-m 2^31 <= 1 there);
 *   m < 1/2: n = (1/ln 2)(1 + x/2 + x^2/12 - x^4/720) Q26, x = m ln 2
 *     (the series of x / (1 - e^-x), next term x^6/30240 < 2^-24), d = 2^31:
 *     no cancellation in 1 - 2^-m near 0.  Terms: mq = m Q32 [< 2^31],
 *     m^2, m^4 Q32 by hi. */
#define FXQ_INV_LN2_26 96817625u /* round(2^26 / ln 2) */
#define FXQ_LN2_12     248087039u /* round(ln 2 / 12 2^32) */
#define FXQ_LN2C_720   1986569u   /* round((ln 2)^3 / 720 2^32) */
FXQ_INLINE void fxq_gtr_g(fxv_u32 m, fxv_u32 *n, fxv_u32 *d)
{
    fxv_u32 mq = fxv_shl(fxv_min(m, fxv_k32((1u << 25) - 1)), 6);
    fxv_u32 m2 = fxq_mulhi(mq, mq), m4 = fxq_mulhi(m2, m2);
    fxv_u32 ns = fxv_sub32(fxv_add32(fxv_add32(fxv_k32(FXQ_INV_LN2_26), fxv_shr(m, 1)),
                                     fxv_shr(fxq_mulhi(m2, fxv_k32(FXQ_LN2_12)), 6)),
                           fxv_shr(fxq_mulhi(m4, fxv_k32(FXQ_LN2C_720)), 6));
    fxv_u32 k = fxv_min(fxv_shr(m, 26), fxv_k32(31));
    fxv_u32 e = fxv_shrv(fxq_exp2f30(fxv_not(fxv_shl(m, 6))), k); /* 2^-m 2^31 */
    fxv_u32 small = fxv_lt(m, fxv_k32(1u << 25));
    *n = fxv_sel(small, ns, m);
    *d = fxv_sel(small, fxv_k32(1u << 31), fxv_sub32(fxv_k32(1u << 31), fxv_min(e, fxv_k32(1u << 31))));
}

/* ---- GTR D -------------------------------------------------------------------
 * D = c / d^gamma (facet.h), with L = log2 alpha^2 <= 0, M = (1 - gamma) L
 * and g above: c = 2^-max(M, 0) g(|M|) / (pi g(|L|)), so
 *   D = 2^Z g(|M|) / (pi g(|L|)),  Z = -gamma log2 d - max(M, 0) in [-60, 20]
 * (-log2 d <= |L|: d >= alpha^2).  Stages:
 *   d60 exact as ggx_d's [2^40 .. 2^60], normalised (fxq_norm_hl: e in
 *     [3, 23]); -log2 d Q26 = (e - 3) 2^26 - log2m >> 5 [<= 20 2^26];
 *   |L| Q26 = 2 (clz(A) - 16) 2^26 - log2m(A normalised) >> 4 [<= 20 2^26];
 *   |M| Q26 = |G - 2^15| |L| >> 15 (64-bit product < 2^47) [<= 60 2^26];
 *   Z + 64 in Q24 = (G (-log2 d)) >> 17 + 2^30 - (gamma > 1 ? |M| >> 2 : 0)
 *     [in [4, 84] 2^24: < 2^31]; zi its integer part, F = its fraction Q32;
 *   numerator n_M d_L (Q57, < 2^63), denominator d_M n_L, their top words
 *     tn, td (fxq_top); nn = hi(2^F Q30, tn) [>= 2^29], dd = hi(td, pi 2^30);
 *   D 2^13 = nn / dd 2^(zi + ed - en - 51), one fxq_div (b = 146 - zi - ed
 *     + en >= 32: no wrap).
 * gamma = 2 gives GGX, gamma = 1 GTR1 (the series at m = 0), alpha = 1
 * and gamma = 0 give 1/pi, with no special case. */
FXQ_INLINE fxv_u32 fxq_gtr_d(fxv_i32 noh, fxv_i32 alpha, fxv_i32 gamma)
{
    fxv_u32 n = fxv_unit(noh), a = fxv_alpha(alpha), g = fxv_clamp(gamma, 0, 4 * FACET_FX_ONE);
    fxv_u32 na = fxv_mul32(n, a), e, ka, nld, la, gm, ma, z, nM, dM, nL, dL, tn, td, en, ed, nn, dd;
    fxv_u64 d60 = fxv_add64(fxv_mulw(fxv_mul32(fxv_sub32(fxv_k32(FACET_FX_ONE), n), fxv_add32(fxv_k32(FACET_FX_ONE), n)),
                                     fxv_k32(1u << 30)),
                            fxv_mulw(na, na));
    fxv_u32 dt = fxq_norm_hl(fxv_hi(d60), fxv_lo(d60), &e);
    nld = fxv_sub32(fxv_shl(fxv_sub32(e, fxv_k32(3)), 26), fxv_shr(fxq_log2m31(dt), 5));
    ka = fxv_clz(a);
    la = fxv_sub32(fxv_shl(fxv_sub32(ka, fxv_k32(16)), 27), fxv_shr(fxq_log2m31(fxv_shlv(a, ka)), 4));
    gm = fxv_sub32(fxv_max(g, fxv_k32(FACET_FX_ONE)), fxv_min(g, fxv_k32(FACET_FX_ONE))); /* |gamma - 1| Q15 */
    ma = fxv_narrow(fxv_shr64(fxv_mulw(gm, la), 15));
    z = fxv_sub32(fxv_add32(fxv_narrow(fxv_shr64(fxv_mulw(g, nld), 17)), fxv_k32(1u << 30)),
                  fxv_sel(fxv_lt(fxv_k32(FACET_FX_ONE), g), fxv_shr(ma, 2), fxv_k32(0)));
    fxq_gtr_g(ma, &nM, &dM);
    fxq_gtr_g(la, &nL, &dL);
    tn = fxq_top(fxv_mulw(nM, dL), &en);
    td = fxq_top(fxv_mulw(dM, nL), &ed);
    nn = fxq_mulhi(fxq_exp2f30(fxv_shl(z, 8)), tn);
    dd = fxq_mulhi(td, fxv_k32(FXB_PI_M));
    return fxq_divb(nn, dd, fxv_sub32(fxv_add32(fxv_k32(146), en), fxv_add32(fxv_shr(z, 24), ed)), FACET_FX_MAX_D);
}

/* ---- Blinn-Phong and Beckmann D ---------------------------------------------
 * Both are 2^-y times a prefactor whose peak is 1/(pi alpha^2) <= 2^20/pi,
 * ggx_d's: UQ19.13 holds them.  The exponent y must be good to ~2^-20
 * absolute (2^-y's relative error is ln 2 dy) wherever D is above the LSB,
 * which is y < 64 (beyond, D 2^13 < 2^-29: 0): y is formed from exact
 * products and reciprocals refined to 2^-30, with log2 keeping its
 * relative precision near N.H = 1, then held in Q24 saturated at 128. */

/* ~ 2^63 / m for m in [2^31, 2^32): the table reciprocal (2^-16) and one
 * Newton step r (1 + (2^31 - t) / 2^31), t = hi(m, r) ~ 2^31 (one of the
 * two corrections is 0): relative error <= 2^-29.5; result < 2^32 (at m =
 * 2^31 the floor keeps it at 2^32 - 1). */
FXQ_INLINE fxv_u32 fxq_rcp32(fxv_u32 m)
{
    fxv_u32 r = fxv_shl(fxq_rcp20(m), 12), t = fxq_mulhi(m, r), h = fxv_k32(1u << 31);
    fxv_u32 up = fxq_mulhi(r, fxv_shl(fxv_sub32(h, fxv_min(t, h)), 1));
    fxv_u32 dn = fxq_mulhi(r, fxv_shl(fxv_sub32(fxv_max(t, h), h), 1));
    return fxv_sub32(fxv_add32(r, up), dn);
}

/* round(v 2^(sb - 256)), ties up, for v < 2^31.5 and sb in [0, 2^10):
 * a left shift (sb > 256; saturating at max) or a rounded right shift (0
 * past 33) [every shift count in [0, 31]]. */
FXQ_INLINE fxv_u32 fxq_scale(fxv_u32 v, fxv_u32 sb, uint32_t max)
{
    fxv_u32 l = fxv_min(fxv_sub32(fxv_max(sb, fxv_k32(256)), fxv_k32(256)), fxv_k32(31));
    fxv_u32 r = fxv_min(fxv_sub32(fxv_k32(256), fxv_min(sb, fxv_k32(256))), fxv_k32(33));
    fxv_u32 rr = fxv_shr(fxv_add32(fxv_shrv(v, fxv_min(fxv_sub32(fxv_max(r, fxv_k32(1)), fxv_k32(1)), fxv_k32(31))),
                                   fxv_k32(1)), 1);
    fxv_u32 lv = fxv_sel(fxv_lt(fxv_shrv(fxv_k32(max), l), v), fxv_k32(max), fxv_shlv(v, l));
    rr = fxv_sel(fxv_lt(r, fxv_k32(33)), rr, fxv_k32(0));
    return fxv_sel(fxv_lt(sb, fxv_k32(256)), rr, lv);
}

/* 2^-y for y = y24 2^-24 in [0, 128]: 2^-(yi + 1) 2^(1 - f), 1 - f read as
 * ~F (2^-32 low): returns 2^(1 - f) Q30 [2^30 .. 2^31], *yi the integer part */
FXQ_INLINE fxv_u32 fxq_exp2neg(fxv_u32 y24, fxv_u32 *yi)
{
    *yi = fxv_shr(y24, 24);
    return fxq_exp2f30(fxv_not(fxv_shl(y24, 8)));
}

#define FXQ_INV_PI_32 1367130551u /* round(2^32 / pi) */

/* Blinn-Phong D = n^p / (pi alpha^2), p = 2 (1 - alpha^2) / alpha^2:
 *   1/alpha^2 = rr 2^(ka - 33): A^2 Q30 exact, normalised (ka = clz), rr =
 *     fxq_rcp32;
 *   p = pq 2^(ka - 31 - kk): k2 = 2 (2^30 - A^2) Q30 exact [<= 2^31],
 *     normalised by kk, pq = hi(k2 2^kk, rr) [>= 2^30, or 0 at alpha = 1];
 *   lambda = -log2 n, relative precision everywhere: x = 1 - n = X 2^-15
 *     exact; x < 1/32: (x + x^2/2 + ... + x^5/5) / ln 2 (Horner with
 *     xq = X 2^17 Q32, the c_k of log2; relative error x^5/6 < 2^-27),
 *     lambda = X ps 2^-46 (64-bit, exact product); else lambda = c - 16 -
 *     log2 m (c = clz N, N 2^c = m 2^31), Q26 [<= 15 2^26] with absolute
 *     error 2^-25.5, relative 2^-21 (lambda >= 0.046 there), as X ps
 *     2^-46's scale (a product by 2^20); the two 64-bit values' halves
 *     selected, normalised (fxq_norm_hl): lambda = lt 2^(-14 - el);
 *   y = p lambda = yq 2^(ka - 13 - kk - el), yq = hi(pq, lt); Q24 by a
 *     right shift, saturated at 128 where it would be a left one (y >= 64);
 *   D 2^13 = 2^-y rr 2^(ka - 33) 2^13 / pi = v 2^(ka - yi - 19),
 *     v = hi(hi(2^(1 - f) Q30, rr), 2^32/pi) [< 2^29.4]: fxq_scale.
 * N.H = 0 gives 0 (n^p = 0) for alpha < 1; alpha = 1 is 1/pi everywhere. */
FXQ_INLINE fxv_u32 fxq_blinn_phong_d(fxv_i32 noh, fxv_i32 alpha)
{
    fxv_u32 n = fxv_unit(noh), a = fxv_alpha(alpha), a2 = fxv_mul32(a, a);
    fxv_u32 ka = fxv_clz(a2), rr = fxq_rcp32(fxv_shlv(a2, ka));
    fxv_u32 k2 = fxv_shl(fxv_sub32(fxv_k32(1u << 30), a2), 1), kk = fxv_min(fxv_clz(k2), fxv_k32(31));
    fxv_u32 pq = fxq_mulhi(fxv_shlv(k2, kk), rr);
    fxv_u32 x = fxv_sub32(fxv_k32(FACET_FX_ONE), n), xq = fxv_shl(fxv_min(x, fxv_k32(1023)), 17);
    fxv_u32 ps = fxv_add32(fxv_k32(FXQ_LOG2_C4), fxq_mulhi(xq, fxv_k32(FXQ_LOG2_C5)));
    fxv_u32 c = fxv_clz(fxv_max(n, fxv_k32(1))), l26, el, lt, sh, yq, y24, yi, e2, v;
    fxv_u64 ls, ll;
    fxv_u32 small = fxv_lt(x, fxv_k32(1024));
    ps = fxv_add32(fxv_k32(FXQ_LOG2_C3), fxq_mulhi(xq, ps));
    ps = fxv_add32(fxv_k32(FXQ_LOG2_C2), fxq_mulhi(xq, ps));
    ps = fxv_add32(fxv_k32(FXQ_LOG2_C1), fxq_mulhi(xq, ps));
    ls = fxv_mulw(x, ps);
    l26 = fxv_sub32(fxv_shl(fxv_sub32(c, fxv_k32(16)), 26), fxv_shr(fxq_log2m31(fxv_shlv(fxv_max(n, fxv_k32(1)), c)), 5));
    ll = fxv_mulw(l26, fxv_k32(1u << 20));
    lt = fxq_norm_hl(fxv_sel(small, fxv_hi(ls), fxv_hi(ll)), fxv_sel(small, fxv_lo(ls), fxv_lo(ll)), &el);
    yq = fxq_mulhi(pq, lt);
    sh = fxv_sub32(fxv_add32(fxv_add32(kk, el), fxv_k32(21)), ka); /* the right shift + 32 */
    y24 = fxv_sel(fxv_lt(sh, fxv_k32(32)), fxv_k32(1u << 31),
                  fxv_shrv(yq, fxv_min(fxv_sub32(fxv_max(sh, fxv_k32(32)), fxv_k32(32)), fxv_k32(31))));
    y24 = fxv_min(y24, fxv_k32(1u << 31));
    e2 = fxq_exp2neg(y24, &yi);
    v = fxq_mulhi(fxq_mulhi(e2, rr), fxv_k32(FXQ_INV_PI_32));
    v = fxq_scale(fxv_shl(v, 2), fxv_sub32(fxv_add32(fxv_k32(256 - 21), ka), yi), FACET_FX_MAX_D);
    return fxv_sel(fxv_and(fxv_lt(n, fxv_k32(1)), fxv_lt(a2, fxv_k32(1u << 30))), fxv_k32(0), v);
}

/* Beckmann D = 2^-z / (pi alpha^2 n^4), z = log2(e) (1 - n^2) / (n alpha)^2:
 *   1/(n alpha) = rq 2^(kn - 33): N A Q30 exact [>= 32 for N >= 1],
 *     normalised (kn = clz), rq = fxq_rcp32; r = 1/(n alpha)^2 = r2
 *     2^(2 kn - 34), r2 = hi(rq, rq) [>= 2^30];
 *   z = zq 2^(2 kn - kw - 31): W = (2^15 - N)(2^15 + N) Q30 exact,
 *     normalised by kw, zq = hi(hi(W 2^kw, r2), log2(e) 2^31) [>= 2^28];
 *     Q24 by a right shift, saturated at 128 where it would be a left one
 *     (z >= 64: D 2^13 < 2^(13 + 21 - 64), the prefactor being <= 2^21
 *     wherever z >= 64); W = 0 (N.H = 1) gives z = 0;
 *   D 2^13 = 2^-z alpha^2 r^2 2^13 / pi: alpha^2 = am 2^(-ka - 30) (A^2
 *     normalised), r^2 = r4 2^(4 kn - 36), r4 = hi(r2, r2) [>= 2^28];
 *     v = hi(hi(hi(2^(1 - f) Q30, am), r4), 2^32/pi) [< 2^30.4]:
 *     D 2^13 = v 2^(4 kn - zi - ka - 20) (<= 2^31.35: the shift is at most
 *     8 left, where v is small), fxq_scale.
 * N.H = 0 gives 0. */
FXQ_INLINE fxv_u32 fxq_beckmann_d(fxv_i32 noh, fxv_i32 alpha)
{
    fxv_u32 n = fxv_unit(noh), a = fxv_alpha(alpha), a2 = fxv_mul32(a, a);
    fxv_u32 na = fxv_mul32(fxv_max(n, fxv_k32(1)), a), kn = fxv_clz(na), rq = fxq_rcp32(fxv_shlv(na, kn));
    fxv_u32 r2 = fxq_mulhi(rq, rq), r4 = fxq_mulhi(r2, r2);
    fxv_u32 w = fxv_mul32(fxv_sub32(fxv_k32(FACET_FX_ONE), n), fxv_add32(fxv_k32(FACET_FX_ONE), n));
    fxv_u32 kw = fxv_min(fxv_clz(w), fxv_k32(31)), ka = fxv_clz(a2), zq, sh, z24, zi, e2, v;
    zq = fxq_mulhi(fxq_mulhi(fxv_shlv(w, kw), r2), fxv_k32(FXQ_LOG2_C1));
    sh = fxv_sub32(fxv_add32(kw, fxv_k32(7 + 64)), fxv_shl(kn, 1)); /* the right shift + 64 */
    z24 = fxv_sel(fxv_lt(sh, fxv_k32(64)), fxv_k32(1u << 31),
                  fxv_shrv(zq, fxv_min(fxv_sub32(fxv_max(sh, fxv_k32(64)), fxv_k32(64)), fxv_k32(31))));
    z24 = fxv_sel(fxv_lt(w, fxv_k32(1)), fxv_k32(0), fxv_min(z24, fxv_k32(1u << 31)));
    e2 = fxq_exp2neg(z24, &zi);
    v = fxq_mulhi(fxq_mulhi(fxq_mulhi(e2, fxv_shlv(a2, ka)), r4), fxv_k32(FXQ_INV_PI_32));
    v = fxq_scale(v, fxv_sub32(fxv_add32(fxv_k32(256 - 20), fxv_shl(kn, 2)), fxv_add32(zi, ka)), FACET_FX_MAX_D);
    return fxv_sel(fxv_lt(n, fxv_k32(1)), fxv_k32(0), v);
}

/* ---- Smith, exact ------------------------------------------------------------
 * r(x) = sqrt(w), w = a^2 (1 - x)(1 + x) + x^2: w60 = A^2 (2^15 - X)(2^15 + X)
 * + X^2 2^30 Q60 exact [<= 2^60, >= a^2 2^60 >= 2^40]; its top 32 bits
 * (w = top 2^-E, E = 28 + e in [31, 52]); the exponent made even by
 * top >> (E & 1), the table: r = sq 2^-(4 + H), H = E >> 1 in [15, 26],
 * sq in [2^19, 2^20); returned as Q30: sq 2^(26 - H) [r <= 1: <= 2^30;
 * r >= alpha >= 2^-10: >= 2^20]. */
FXQ_INLINE fxv_u32 fxq_s2(fxv_u32 x) { return fxv_mul32(fxv_sub32(fxv_k32(FACET_FX_ONE), x), fxv_add32(fxv_k32(FACET_FX_ONE), x)); }
/* r from y60 = A^2 (2^15 - X)(2^15 + X) */
FXQ_INLINE fxv_u32 fxq_smith_r30y(fxv_u32 x, fxv_u64 y60)
{
    fxv_u32 e, top, ee, hh;
    top = fxq_top(fxv_add64(y60, fxv_mulw(fxv_mul32(x, x), fxv_k32(1u << 30))), &e);
    ee = fxv_add32(e, fxv_k32(28));
    hh = fxv_shr(ee, 1);
    return fxv_shlv(fxq_sqrt20(fxv_shrv(top, fxv_and(ee, fxv_k32(1)))), fxv_sub32(fxv_k32(26), hh));
}
FXQ_INLINE fxv_u32 fxq_smith_r30(fxv_u32 x, fxv_u32 a2) { return fxq_smith_r30y(x, fxv_mulw(a2, fxq_s2(x))); }

/* The monotone form of the GGX Smith terms (issue 25 item 4).  2 n / (n +
 * r) steps backwards where n >> alpha: r's table root and the 1/x table
 * have chord slopes off by up to 2^-7, more than the ratio's own slope.
 * With X = 2 n (n + r) and Y = r^2 - n^2 = a^2 (1 - n^2) (exact):
 *   G1 = X / (X + Y)      (n + r)^2 = 2 n (n + r) + a^2 (1 - n^2)
 * X60 = hi-exact N 2^16 (N 2^15 + r30) Q60 [<= 2^62], Y60 = A^2 (2^15 -
 * N)(2^15 + N) Q60 [<= 2^60], D60 = X60 + Y60 [< 2^63, >= a^2 2^60 >=
 * 2^40]; *d = top(D60) in [2^31, 2^32), *x = X60 at the same shift [<= *d].
 * X / (X + Y) increases with X and decreases with Y, X increases with n
 * (r's table is non-decreasing) and Y decreases: monotone in n whatever r's
 * error; in alpha Y's relative step 2 / alpha outruns X's (<= 1 / alpha).
 * r's error enters G1 times (r - n) / (n + r)^2 <= 1: near G1 = 1 it
 * vanishes. */
FXQ_INLINE void fxq_smith_xd(fxv_u32 n, fxv_u32 a2, fxv_u32 *x, fxv_u32 *d)
{
    fxv_u64 y60 = fxv_mulw(a2, fxq_s2(n));
    fxv_u32 den = fxv_add32(fxv_shl(n, 15), fxq_smith_r30y(n, y60));
    fxv_u64 x60 = fxv_mulw(fxv_shl(n, 16), den);
    fxv_u32 e;
    *d = fxq_top(fxv_add64(x60, y60), &e);
    *x = fxq_top_at(x60, e);
}

/* round(2^15 (1 - q / d)) for q <= d, d >= 2^23: the complement Q31 = round(q
 * / d 2^31) by fxq_divbn [<= 2^31], then round((2^31 - Q31) / 2^16).  Near
 * G = 1, where the G terms' steps are smallest, Q is small and its error
 * (2^-30 relative) with it: the rounding of Q31 (2^-32) is what is left. */
FXQ_INLINE fxv_u32 fxq_one_minus15(fxv_u32 q, fxv_u32 d)
{
    fxv_u32 c = fxq_divbn(q, d, fxv_k32(64), 1u << 31);
    return fxv_shr(fxv_add32(fxv_sub32(fxv_k32(1u << 31), c), fxv_k32(1u << 15)), 16);
}

/* G1 = 2 n / (n + r(n)) = X / (X + Y) (fxq_smith_xd): G1 2^15 = x 2^15 /
 * d, one fxq_divbn [x <= d: at most 2^15].  G1(0) = 0, G1(1) = 1. */
FXQ_INLINE fxv_u32 fxq_smith_g1(fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 n = fxv_unit(nov), a = fxv_alpha(alpha), x, d;
    fxq_smith_xd(n, fxv_mul32(a, a), &x, &d);
    return fxq_one_minus15(fxv_sub32(d, x), d);
}

/* nv r(nl) + nl r(nv) in Q45, in 64 bits [< 2^46, >= 2^28], top 32 bits:
 * ~ dt 2^(32 - e) */
FXQ_INLINE fxv_u32 fxq_g2_den(fxv_u32 nl, fxv_u32 nv, fxv_u32 a2, fxv_u32 *e)
{
    return fxq_top(fxv_add64(fxv_mulw(nv, fxq_smith_r30(nl, a2)), fxv_mulw(nl, fxq_smith_r30(nv, a2))), e);
}

/* G2 = 2 nl nv / (nv r(nl) + nl r(nv)) = 1 / (1 / g_l + 1 / g_v - 1), g =
 * x / d = G1 of each cosine (fxq_smith_xd), y = d - x: G2 = x_l x_v / (d_l
 * d_v - y_l y_v) [64-bit products < 2^64; the difference >= x_l d_v >=
 * 2^55]; their high words [the denominator's >= 2^23; truncations <= 2^-23
 * relative, G2 < 2^-7 there], one fxq_divbn: G2 2^15.  Monotone as G1:
 * increasing in each g, each g monotone. */
FXQ_INLINE fxv_u32 fxq_smith_g2(fxv_i32 nol, fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 nl = fxv_cosine(nol), nv = fxv_cosine(nov), a = fxv_alpha(alpha), a2 = fxv_mul32(a, a);
    fxv_u32 xl, dl, xv, dv;
    fxq_smith_xd(nl, a2, &xl, &dl);
    fxq_smith_xd(nv, a2, &xv, &dv);
    fxv_u64 den = fxv_sub64(fxv_mulw(dl, dv), fxv_mulw(fxv_sub32(dl, xl), fxv_sub32(dv, xv)));
    return fxq_one_minus15(fxv_hi(fxv_sub64(den, fxv_mulw(xl, xv))), fxv_hi(den));
}

/* Vis = 0.5 / den: Vis 2^16 = 2^60 / den45 = 2^31 / dt 2^(e - 3) [< 2^30] */
FXQ_INLINE fxv_u32 fxq_smith_vis(fxv_i32 nol, fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 nl = fxv_cosine(nol), nv = fxv_cosine(nov), a = fxv_alpha(alpha), e;
    fxv_u32 dt = fxq_g2_den(nl, nv, fxv_mul32(a, a), &e);
    return fxq_divb(fxv_k32(1u << 31), dt, fxv_sub32(fxv_k32(98), e), FACET_FX_MAX_VIS);
}

/* G1(nl) G1(nv) = (x_l x_v) / (d_l d_v) (fxq_smith_xd) [d_l d_v >= 2^62]:
 * the products' high words [the denominator's >= 2^30], one fxq_divbn: G
 * 2^15.  A product of two monotone G1. */
FXQ_INLINE fxv_u32 fxq_smith_g2_uncorrelated(fxv_i32 nol, fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 nl = fxv_cosine(nol), nv = fxv_cosine(nov), a = fxv_alpha(alpha), a2 = fxv_mul32(a, a);
    fxv_u32 xl, dl, xv, dv;
    fxq_smith_xd(nl, a2, &xl, &dl);
    fxq_smith_xd(nv, a2, &xv, &dv);
    fxv_u64 den = fxv_mulw(dl, dv);
    return fxq_one_minus15(fxv_hi(fxv_sub64(den, fxv_mulw(xl, xv))), fxv_hi(den));
}

/* ---- Smith G1 for GTR (Dimov) ------------------------------------------------
 * Q15 output, so every stage is held to an absolute error (~2^-20 in Q30).
 * The five closed forms of facet.h divided through by powers of W
 * (smith_g1's root) are functions of nu = n / W in [0, 1] and alpha^2, O(1)
 * at every alpha (the undivided forms go as alpha^4 at small n):
 *   y0 = 2n / (1 + n)
 *   y1 = nu D / (nu D + e s2 T), D = (W + 1)(n + W), T = 1 + nu (1 - R(u)),
 *        u = (1 - alpha^2) s2 / D, e = (alpha^2 - 1) / ln alpha^2
 *   y2 = 2 nu / (1 + nu)
 *   y3 = 4 b nu / ((3 alpha^2 + 1)(1 - nu^2) + 2 b nu (1 + nu)), b = 1 + alpha^2
 *   y4 = 2 nu / (nu (1 + nu^3) + 3 / (8 K) (1 - nu^2)(P5 (1 - nu^2) + 4 P2 nu^2)),
 *        K = alpha^4 + alpha^2 + 1 (facet.h's K / 8), P5, P2 as facet.h
 * (W^2 = n^2 + alpha^2 s2, so alpha^2 s2 / W^2 = 1 - nu^2).  The y are
 * non-decreasing in gamma (checked against the oracle on a 401 x 4001 grid
 * of (alpha, N.V): min difference -2e-16), so the monotone cubic works on
 * differences d_j >= 0 (formed as max(y_j+1, y_j) - y_j) and no stage is
 * signed. */

/* num / den in Q30 for values with num / den < 2 (num, den < 2^32, den
 * >= 1): both normalised, one refined reciprocal (fxq_rcp32): q = hi(num
 * 2^kn, rcp) in [2^30, 2^32), the quotient q 2^(kd - kn - 1); relative
 * error <= 2^-29, truncated.  num = 0 gives 0. */
FXQ_INLINE fxv_u32 fxq_div30(fxv_u32 num, fxv_u32 den)
{
    fxv_u32 kn = fxv_min(fxv_clz(num), fxv_k32(31)), kd = fxv_clz(den);
    fxv_u32 q = fxq_mulhi(fxv_shlv(num, kn), fxq_rcp32(fxv_shlv(den, kd)));
    fxv_u32 sb = fxv_sub32(fxv_add32(kn, fxv_k32(33)), kd); /* the right shift + 32 */
    return fxv_sel(fxv_lt(sb, fxv_k32(32)), fxv_k32(1u << 31),
                   fxv_shrv(q, fxv_min(fxv_sub32(fxv_max(sb, fxv_k32(32)), fxv_k32(32)), fxv_k32(31))));
}

/* x y for Q30 x, y <= 2^31: Q30 [x y < 2^32 there] */
FXQ_INLINE fxv_u32 fxq_mul30(fxv_u32 x, fxv_u32 y) { return fxq_mulhi(fxv_shl(x, 1), fxv_shl(y, 1)); }

#define FXQ_LN2_32   2977044472u /* round(ln 2 2^32) */
#define FXQ_THIRD_32 1431655765u /* round(2^32 / 3) */
#define FXQ_FIFTH_32 858993459u  /* round(2^32 / 5) */

FXQ_INLINE fxv_u32 fxq_smith_g1_gtr(fxv_i32 nov, fxv_i32 alpha, fxv_i32 gamma)
{
    fxv_u32 n = fxv_unit(nov), a = fxv_alpha(alpha), gg = fxv_clamp(gamma, 0, 4 * FACET_FX_ONE);
    fxv_u32 a2 = fxv_mul32(a, a), s2 = fxv_mul32(fxv_sub32(fxv_k32(FACET_FX_ONE), n), fxv_add32(fxv_k32(FACET_FX_ONE), n));
    fxv_u32 n30 = fxv_shl(n, 15), ew, kw, w0, w1, nu, nu2, om, nu3, b, y0, y1, y2, y3, y4;
    fxv_u32 wt, q, d28, kd, u20, uq, omr, xl, cl, l26, ku, r32, t30, ka, la, nL, dL, e30, es2t, nud;
    fxv_u32 a4, k28, p5, p2, inner, k32, t1, t2, d0, d1, d2, d3, m0, m1, m2, m3, m4, f;
    fxv_u32 j, t, omt, t2q, h01, h10, h11, yj, dj, mj, mk, pos, neg, s;
    fxv_u64 w60 = fxv_add64(fxv_mulw(a2, s2), fxv_mulw(fxv_mul32(n, n), fxv_k32(1u << 30)));
    /* W = sqrt(w): the table root, one Heron step (W + w / W) / 2 with w /
     * W = hi(wt, rcp(W)) 2^(kw - ew + 1) Q30 (w normalised by fxq_norm_hl,
     * w60 >= 2^40): error <= 2^-28 relative */
    w0 = fxq_smith_r30(n, a2);
    wt = fxq_norm_hl(fxv_hi(w60), fxv_lo(w60), &ew);
    kw = fxv_clz(w0);
    q = fxq_mulhi(wt, fxq_rcp32(fxv_shlv(w0, kw)));
    q = fxv_shrv(q, fxv_min(fxv_sub32(fxv_max(fxv_add32(ew, fxv_k32(31)), fxv_add32(kw, fxv_k32(32))),
                                      fxv_add32(kw, fxv_k32(32))), fxv_k32(31)));
    w1 = fxv_min(fxv_shr(fxv_add32(fxv_add32(w0, q), fxv_k32(1)), 1), fxv_k32(1u << 30));
    nu = fxv_min(fxq_div30(n30, w1), fxv_k32(1u << 30));
    nu2 = fxq_mul30(nu, nu);
    om = fxv_sub32(fxv_k32(1u << 30), nu2);                     /* 1 - nu^2 */
    nu3 = fxq_mul30(nu2, nu);
    b = fxv_add32(fxv_k32(1u << 30), a2);                       /* <= 2^31 */
    /* y0, y2 */
    y0 = fxq_div30(fxv_shl(n, 16), fxv_add32(fxv_k32(1u << 30), n30));
    y2 = fxq_div30(fxv_shl(nu, 1), fxv_add32(fxv_k32(1u << 30), nu));
    /* y3 in Q27 stages [num <= 8, den <= 12 ... both < 2^31] */
    {
        fxv_u32 bnu = fxq_mulhi(b, nu);                                   /* b nu Q28 */
        fxv_u32 c28 = fxv_add32(fxv_mul32(fxv_shr(a2, 2), fxv_k32(3)), fxv_k32(1u << 28));
        fxv_u32 den = fxv_add32(fxv_shl(fxq_mulhi(c28, om), 1),
                                fxv_shl(fxq_mulhi(bnu, fxv_add32(fxv_k32(1u << 30), nu)), 2));
        y3 = fxv_min(fxq_div30(fxv_shl(bnu, 1), den), fxv_k32(1u << 30));
    }
    /* y4 in Q28 stages: K, P5, P2 Q28 [<= 3, 8, 4]; inner = P5 (1 - nu^2) +
     * 4 P2 nu^2 Q26 [<= 16]; k = 3 / (8 K) Q32 [<= 3/8]; den Q28 [<= 8] */
    a4 = fxq_mul30(a2, a2);
    k28 = fxv_add32(fxv_add32(fxv_shr(a4, 2), fxv_shr(a2, 2)), fxv_k32(1u << 28));
    p5 = fxv_add32(fxv_add32(fxv_mul32(fxv_shr(a4, 2), fxv_k32(5)), fxv_shr(a2, 1)), fxv_k32(1u << 28));
    p2 = fxv_add32(fxv_add32(fxv_shr(a4, 1), fxv_shr(a2, 2)), fxv_k32(1u << 28));
    inner = fxv_add32(fxq_mulhi(p5, om), fxv_shl(fxq_mulhi(p2, nu2), 2));
    k32 = fxv_shl(fxq_div30(fxv_k32(3u << 25), k28), 2);
    t1 = fxv_shr(fxq_mulhi(fxv_shl(nu, 1), fxv_add32(fxv_k32(1u << 30), nu3)), 1);      /* nu (1 + nu^3) Q28 */
    t2 = fxv_shl(fxq_mulhi(fxv_shl(fxq_mulhi(k32, om), 1), fxv_shl(inner, 1)), 2);     /* Q28 */
    y4 = fxv_min(fxq_div30(fxv_shr(nu, 1), fxv_add32(t1, t2)), fxv_k32(1u << 30));
    /* y1: D = (W + 1)(n + W) Q28 [<= 4, >= alpha]; u = (1 - a^2) s2 / D Q20
     * [<= 2^10]; 1 - R(u) Q32 by the series u (1/2 - u (1/3 - u (1/4 - u/5)))
     * below u = 1/16 (error u^5/6 < 2^-22), else 1 - ln 2 log2(1 + u) / u
     * (log2 by clz + fxq_log2m31, 1/u refined); e = 1 / (ln 2 g(|L|)) from
     * gtr_d's g. */
    d28 = fxq_mulhi(fxv_add32(fxv_k32(1u << 30), w1), fxv_add32(n30, w1));
    kd = fxv_clz(d28);
    u20 = fxq_mulhi(fxq_mul30(fxv_sub32(fxv_k32(1u << 30), a2), s2), fxq_rcp32(fxv_shlv(d28, kd)));
    u20 = fxv_shrv(u20, fxv_sub32(fxv_k32(13), fxv_min(kd, fxv_k32(13))));
    uq = fxv_shl(fxv_min(u20, fxv_k32(0xFFFF)), 12);
    omr = fxv_sub32(fxv_k32(1u << 30), fxq_mulhi(uq, fxv_k32(FXQ_FIFTH_32)));
    omr = fxv_sub32(fxv_k32(FXQ_THIRD_32), fxq_mulhi(uq, omr));
    omr = fxv_sub32(fxv_k32(1u << 31), fxq_mulhi(uq, omr));
    omr = fxq_mulhi(uq, omr);
    xl = fxv_add32(fxv_k32(1u << 20), u20);
    cl = fxv_clz(xl);
    l26 = fxv_add32(fxv_shl(fxv_sub32(fxv_k32(11), fxv_min(cl, fxv_k32(11))), 26), fxv_shr(fxq_log2m31(fxv_shlv(xl, cl)), 5));
    ku = fxv_clz(fxv_max(u20, fxv_k32(1)));
    r32 = fxq_mulhi(fxq_mulhi(l26, fxq_rcp32(fxv_shlv(fxv_max(u20, fxv_k32(1)), ku))), fxv_k32(FXQ_LN2_32));
    r32 = fxv_shlv(r32, fxv_sub32(fxv_max(ku, fxv_k32(5)), fxv_k32(5)));   /* u >= 1/16: ku <= 11 */
    r32 = fxv_shrv(r32, fxv_sub32(fxv_k32(5), fxv_min(ku, fxv_k32(5))));
    omr = fxv_sel(fxv_lt(u20, fxv_k32(1u << 16)), omr, fxv_not(r32));
    t30 = fxv_add32(fxv_k32(1u << 30), fxq_mulhi(nu, omr));
    ka = fxv_clz(a);
    la = fxv_sub32(fxv_shl(fxv_sub32(ka, fxv_k32(16)), 27), fxv_shr(fxq_log2m31(fxv_shlv(a, ka)), 4));
    fxq_gtr_g(la, &nL, &dL);
    e30 = fxv_min(fxq_div30(fxv_shr(dL, 5), fxq_mulhi(nL, fxv_k32(FXQ_LN2_32))), fxv_k32(1u << 30));
    es2t = fxq_mulhi(fxq_mul30(e30, s2), t30);                    /* Q28 <= 2 */
    nud = fxq_mulhi(fxv_shl(nu, 1), fxv_shl(d28, 1));               /* nu D Q28 <= 4 */
    y1 = fxv_min(fxq_div30(nud, fxv_add32(nud, es2t)), fxv_k32(1u << 30));
    /* the monotone cubic (Fritsch-Carlson) on d_j >= 0 */
    d0 = fxv_sub32(fxv_max(y1, y0), y0);
    d1 = fxv_sub32(fxv_max(y2, y1), y1);
    d2 = fxv_sub32(fxv_max(y3, y2), y2);
    d3 = fxv_sub32(fxv_max(y4, y3), y3);
    m0 = fxv_shr(fxv_sub32(fxv_max(fxv_mul32(d0, fxv_k32(3)), d1), d1), 1);
    m4 = fxv_shr(fxv_sub32(fxv_max(fxv_mul32(d3, fxv_k32(3)), d2), d2), 1);
    /* 2 a b / (a + b) = 2 a f, f = b / (a + b) */
    f = fxq_div30(d1, fxv_max(fxv_add32(d0, d1), fxv_k32(1)));
    m1 = fxv_shl(fxq_mul30(d0, f), 1);
    f = fxq_div30(d2, fxv_max(fxv_add32(d1, d2), fxv_k32(1)));
    m2 = fxv_shl(fxq_mul30(d1, f), 1);
    f = fxq_div30(d3, fxv_max(fxv_add32(d2, d3), fxv_k32(1)));
    m3 = fxv_shl(fxq_mul30(d2, f), 1);
    j = fxv_min(fxv_shr(gg, 15), fxv_k32(3));
    t = fxv_sub32(gg, fxv_shl(j, 15));                              /* Q15 in [0, 2^15] */
    omt = fxv_sub32(fxv_k32(FACET_FX_ONE), t);
    t2q = fxv_mul32(t, t);                                          /* Q30 */
    h01 = fxv_shl(fxq_mulhi(fxv_shl(t2q, 1), fxv_shl(fxv_sub32(fxv_k32(3 * FACET_FX_ONE), fxv_shl(t, 1)), 15)), 1);
    h10 = fxq_mulhi(fxv_shl(fxv_mul32(omt, omt), 1), fxv_shl(t, 16));
    h11 = fxq_mulhi(fxv_shl(t2q, 1), fxv_shl(omt, 16));
    {
        fxv_u32 i1 = fxv_lt(j, fxv_k32(1)), i2 = fxv_lt(j, fxv_k32(2)), i3 = fxv_lt(j, fxv_k32(3));
        yj = fxv_sel(i1, y0, fxv_sel(i2, y1, fxv_sel(i3, y2, y3)));
        dj = fxv_sel(i1, d0, fxv_sel(i2, d1, fxv_sel(i3, d2, d3)));
        mj = fxv_sel(i1, m0, fxv_sel(i2, m1, fxv_sel(i3, m2, m3)));
        mk = fxv_sel(i1, m1, fxv_sel(i2, m2, fxv_sel(i3, m3, m4)));
    }
    pos = fxv_add32(fxv_add32(yj, fxq_mul30(h01, dj)), fxq_mul30(h10, mj));
    neg = fxq_mul30(h11, mk);
    s = fxv_min(fxv_sub32(pos, fxv_min(pos, neg)), fxv_k32(1u << 30));
    return fxv_shr(fxv_add32(s, fxv_k32(1u << 14)), 15);
}

/* ---- Smith, Hammon ------------------------------------------------------------
 * G1 ~ 2 n / (n (2 - a) + a): den30 = N (2^16 - A) + A 2^15 exact [2^20 ..
 * 2^31]; G1 2^15 = 2N 2^30 / den30, one fxq_div. */
FXQ_INLINE fxv_u32 fxq_smith_g1_hammon(fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 n = fxv_unit(nov), a = fxv_alpha(alpha);
    fxv_u32 den = fxv_add32(fxv_mul32(n, fxv_sub32(fxv_k32(65536), a)), fxv_shl(a, 15));
    return fxq_divbn(fxv_shl(n, 1), den, fxv_k32(65), FACET_FX_ONE);
}

/* m = (1 - a) 2 nl nv + a (nl + nv): m45 = 2 NL NV (2^15 - A) + A S 2^15
 * Q45 exact [< 2^47, >= a s 2^45 >= 2^28], its top 32 bits mt:
 * m45 ~ mt 2^(32 - e). */
FXQ_INLINE fxv_u32 fxq_hammon_m(fxv_u32 nl, fxv_u32 nv, fxv_u32 a, fxv_u32 nlnv, fxv_u32 *e)
{
    return fxq_top(fxv_add64(fxv_mulw(fxv_shl(nlnv, 1), fxv_sub32(fxv_k32(FACET_FX_ONE), a)),
                             fxv_mulw(fxv_mul32(a, fxv_add32(nl, nv)), fxv_k32(1u << 15))), e);
}

/* G2 2^15 = 2 NL NV 2^30 / m45 = NL NV / mt 2^(e - 1) */
FXQ_INLINE fxv_u32 fxq_smith_g2_hammon(fxv_i32 nol, fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 nl = fxv_cosine(nol), nv = fxv_cosine(nov), a = fxv_alpha(alpha), p = fxv_mul32(nl, nv), e;
    fxv_u32 mt = fxq_hammon_m(nl, nv, a, p, &e);
    return fxq_divbn(p, mt, fxv_sub32(fxv_k32(96), e), FACET_FX_ONE);
}

/* Vis 2^16 = 0.5 2^16 2^45 / m45 = 2^31 / mt 2^(e - 3) [< 2^30] */
FXQ_INLINE fxv_u32 fxq_smith_vis_hammon(fxv_i32 nol, fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 nl = fxv_cosine(nol), nv = fxv_cosine(nov), a = fxv_alpha(alpha), e;
    fxv_u32 mt = fxq_hammon_m(nl, nv, a, fxv_mul32(nl, nv), &e);
    return fxq_divb(fxv_k32(1u << 31), mt, fxv_sub32(fxv_k32(98), e), FACET_FX_MAX_VIS);
}

/* ---- shadowing and visibility: the rest of the menu ---------------------------
 * G terms Q15 (max 1), Vis terms UQ16.16, as the precise tier. */

/* N.L N.V rounded once, and min(N.L, N.V): the precise kernels
 * (src/fx/fx_body.h), exact and as cheap as anything. */
FXQ_INLINE fxv_u32 fxq_g_implicit(fxv_i32 nol, fxv_i32 nov) { return fxb_g_implicit(nol, nov); }
FXQ_INLINE fxv_u32 fxq_g_neumann(fxv_i32 nol, fxv_i32 nov) { return fxb_g_neumann(nol, nov); }

/* min(1, g / V.H): g = 2 NH min(NL, NV) Q30 exact [<= 2^31]; g / V.H Q15 =
 * round(g / VH) (s = 0), taken where g < VH 2^15 [VH 2^15 <= 2^30], else 1. */
FXQ_INLINE fxv_u32 fxq_g_cook_torrance(fxv_i32 nol, fxv_i32 nov, fxv_i32 noh, fxv_i32 voh)
{
    fxv_u32 vh = fxv_unit(voh);
    fxv_u32 g = fxv_mul32(fxv_shl(fxv_unit(noh), 1), fxv_min(fxv_cosine(nol), fxv_cosine(nov)));
    fxv_u32 q = fxq_div(g, fxv_max(vh, fxv_k32(1)), 0, FACET_FX_ONE);
    return fxv_sel(fxv_lt(g, fxv_shl(vh, 15)), q, fxv_k32(FACET_FX_ONE));
}

/* min(1, p / q), p = NL NV, q = VH^2, both Q30 exact [<= 2^30]. */
FXQ_INLINE fxv_u32 fxq_g_kelemen(fxv_i32 nol, fxv_i32 nov, fxv_i32 voh)
{
    fxv_u32 vh = fxv_unit(voh), p = fxv_mul32(fxv_cosine(nol), fxv_cosine(nov)), q = fxv_mul32(vh, vh);
    fxv_u32 g = fxq_div(p, fxv_max(q, fxv_k32(1)), 15, FACET_FX_ONE);
    return fxv_sel(fxv_lt(p, q), g, fxv_k32(FACET_FX_ONE));
}

/* Walter's Beckmann G1 in c = q / p, p = a sqrt(1 - n^2), q = n:
 *   W = (2^15 - N)(2^15 + N) Q30 exact; the branch c < 1.6 from the high
 *   words (p^2 Q30 = hi(2 A^2, 2 W), 25 q^2 / 64 = 25 (N^2 >> 6)): where it
 *   is misjudged, c is within 2^-20 of 1.6, where both pieces are 1 (the
 *   cap holds for c in (1.548, 1.631));
 *   sqrt(1 - n^2) = s 2^-(20 + h) from the table (c = 4W, floored at 2^16:
 *   only N = 2^15 is below, and it takes the other branch);
 *   pm = hi(A 2^16, s 2^12) = A s / 16, p = pm 2^-(31 + h) [pm >= 2^20];
 *   c Q29 = N / pm 2^(45 + h), one fxq_div saturated at 1.6 2^29;
 *   num Q59 = 3.535 c + 2.181 c^2, den Q59 = 1 + 2.276 c + 2.577 c^2, in
 *   64 bits [c Q29, c^2 Q29 = hi(4 c, 2 c) <= 2.56 2^29, constants Q30:
 *   each sum < 2^63], their top words, one fxq_div: G1 Q15 =
 *   nt / dt 2^(15 + ed - en), saturated at 1. */
FXQ_INLINE fxv_u32 fxq_smith_g1_beckmann(fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 n = fxv_unit(nov), a = fxv_alpha(alpha);
    fxv_u32 w = fxv_mul32(fxv_sub32(fxv_k32(FACET_FX_ONE), n), fxv_add32(fxv_k32(FACET_FX_ONE), n));
    fxv_u32 p2 = fxq_mulhi(fxv_shl(fxv_mul32(a, a), 1), fxv_shl(w, 1));
    fxv_u32 branch = fxv_lt(fxv_mul32(fxv_shr(fxv_mul32(n, n), 6), fxv_k32(25)), p2);
    fxv_u32 rh, rs = fxq_sqrt32(fxv_max(fxv_shl(w, 2), fxv_k32(1u << 16)), &rh);
    fxv_u32 pm = fxq_mulhi(fxv_shl(a, 16), fxv_shl(rs, 12));
    fxv_u32 c = fxq_divbn(n, pm, fxv_sub32(fxv_k32(50), rh), 858993459u); /* 1.6 2^29 */
    fxv_u32 cc = fxq_mulhi(fxv_shl(c, 2), fxv_shl(c, 1));
    fxv_u32 en, ed, nt, dt, g;
    nt = fxq_top(fxv_add64(fxv_mulw(c, fxv_k32(FXB_WALTER_A)), fxv_mulw(cc, fxv_k32(FXB_WALTER_B))), &en);
    dt = fxq_top(fxv_add64(fxv_add64(fxv_mulw(fxv_k32(1u << 29), fxv_k32(1u << 30)), fxv_mulw(c, fxv_k32(FXB_WALTER_C))),
                           fxv_mulw(cc, fxv_k32(FXB_WALTER_D))), &ed);
    g = fxq_divbn(nt, dt, fxv_sub32(fxv_add32(fxv_k32(80), en), ed), FACET_FX_ONE);
    return fxv_sel(branch, g, fxv_k32(FACET_FX_ONE));
}

/* n / (n (1 - k) + k), k = a sqrt(2/pi): k Q31 = hi(A 2^16, round(sqrt(2/pi)
 * 2^32)) [<= 0.8 2^31]; den Q46 = N (2^31 - k) + k 2^15 exact in 64 bits
 * [< 2^47, >= k 2^15 >= 2^36], its top word dt (den ~ dt 2^(32 - e)); G1
 * Q15 = N 2^46 / den = N / dt 2^(14 + e). */
FXQ_INLINE fxv_u32 fxq_smith_g1_schlick_beckmann(fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 n = fxv_unit(nov), e;
    fxv_u32 k = fxq_mulhi(fxv_shl(fxv_alpha(alpha), 16), fxv_k32(FXB_SQRT_2_PI_32));
    fxv_u32 dt = fxq_top(fxv_add64(fxv_mulw(n, fxv_sub32(fxv_k32(1u << 31), k)), fxv_mulw(k, fxv_k32(1u << 15))), &e);
    return fxq_divbn(n, dt, fxv_sub32(fxv_k32(81), e), FACET_FX_ONE);
}

/* The joint approximation is Hammon's visibility: the same code and bits. */
FXQ_INLINE fxv_u32 fxq_smith_vis_joint_approx(fxv_i32 nol, fxv_i32 nov, fxv_i32 alpha)
{
    return fxq_smith_vis_hammon(nol, nov, alpha);
}

/* The fitted visibility, 1 / (nv R(nl) + nl R(nv)), in Q30 stages (a
 * product by a Q15 value y is hi(v, Y 2^16) 2 = v y, Q30 in, Q30 out, its
 * lowest bit 0 [Y 2^16 <= 2^31; every v below < 2^32]):
 *   K_i a Q30 [K_i Q30 < 2^31.05: <= 2.07 2^30];
 *   sigma Q30 = 2^30 + C1 a - |C2| a a [in (0.35, 1.08) 2^30];
 *   S_i = K_i sigma = hi(2 K_i, 2 sigma) Q30 [<= 2.12 2^30];
 *   R(x) = max(K1 a, K2 a + S3 x, K4 a + S5 x) Q30 [<= 3.3 2^30 < 2^32;
 *   >= K1 a >= 2^21: truncations <= 2^-19 relative];
 *   den Q45 = NV R(NL) + NL R(NV) in 64 bits [< 2^48, >= 2^29], its top
 *   word dt: Vis 2^16 = 2^61 / den45 = 2^31 / dt 2^(e - 2). */
FXQ_INLINE fxv_u32 fxq_by_q15(fxv_u32 v, fxv_u32 y16) { return fxv_shl(fxq_mulhi(v, y16), 1); }

FXQ_INLINE fxv_u32 fxq_vis_fit_r(fxv_u32 x, fxv_u32 ka1, fxv_u32 ka2, fxv_u32 ka4, fxv_u32 s3, fxv_u32 s5)
{
    fxv_u32 x16 = fxv_shl(x, 16);
    return fxv_max(ka1, fxv_max(fxv_add32(ka2, fxq_by_q15(s3, x16)), fxv_add32(ka4, fxq_by_q15(s5, x16))));
}

FXQ_INLINE fxv_u32 fxq_smith_vis_fit(fxv_i32 nol, fxv_i32 nov, fxv_i32 alpha)
{
    fxv_u32 nl = fxv_cosine(nol), nv = fxv_cosine(nov), a16 = fxv_shl(fxv_alpha(alpha), 16), e;
    fxv_u32 c2a = fxq_by_q15(fxv_k32(FXB_VFIT_C2), a16);
    fxv_u32 sg = fxv_sub32(fxv_add32(fxv_k32(1u << 30), fxq_by_q15(fxv_k32(FXB_VFIT_C1), a16)), fxq_by_q15(c2a, a16));
    fxv_u32 ka1 = fxq_by_q15(fxv_k32(FXB_VFIT_K1), a16), ka2 = fxq_by_q15(fxv_k32(FXB_VFIT_K2), a16);
    fxv_u32 ka4 = fxq_by_q15(fxv_k32(FXB_VFIT_K4), a16);
    fxv_u32 s3 = fxq_mulhi(fxv_k32(2 * FXB_VFIT_K3), fxv_shl(sg, 1));
    fxv_u32 s5 = fxq_mulhi(fxv_k32(2 * FXB_VFIT_K5), fxv_shl(sg, 1));
    fxv_u32 rl = fxq_vis_fit_r(nl, ka1, ka2, ka4, s3, s5), rv = fxq_vis_fit_r(nv, ka1, ka2, ka4, s3, s5);
    fxv_u32 dt = fxq_top(fxv_add64(fxv_mulw(nv, rl), fxv_mulw(nl, rv)), &e);
    return fxq_divb(fxv_k32(1u << 31), dt, fxv_sub32(fxv_k32(97), e), FACET_FX_MAX_VIS);
}

/* ---- Hammon's diffuse and the whole model: 32-bit fixed stages -----------------
 * Here every stage is a 32-bit value x with a scale 2^-E, E a compile-time
 * constant or an exponent lane; a product is the high word of one 32x32->64
 * multiply (fxq_mulhi, one UMULL on Cortex-M3/M4), and a chain of such
 * products needs no renormalisation as long as each factor keeps >= 2^21
 * (the bounds in brackets); clz-normalisations only where a range is wide.
 * Truncations are absolute (<= 2^-E) and small against the bound. */

/* 1 - (1 - x)^5 = x (1 + y + y^2 + y^3 + y^4), y = 1 - x (no cancellation at
 * grazing): the sum from a table of it on x = i/256, fxq_p5_tab[i] =
 * round(2^16 sum), i = 0..256 (and a copy of the last), linearly
 * interpolated by the 7 bits of X below the index [steps < 2^12: the
 * product < 2^19]; error h^2/8 max|sum''| = 2^-16.7 on a sum >= 1 (the
 * chord of a convex function: never below it), with the roundings
 * 2^-15.8 relative (measured).  P = X sum Q31 [x sum = P
 * <= 1, the chord's excess < 2^-16: < 2^31 + 2^15]. */
static const uint32_t fxq_p5_tab[258] = {
    327680, 325130, 322600, 320089, 317599, 315128, 312676, 310243, 307830, 305436, 303061,
    300704, 298367, 296048, 293747, 291465, 289201, 286955, 284728, 282518, 280326, 278152,
    275996, 273857, 271735, 269631, 267544, 265474, 263421, 261384, 259365, 257362, 255376,
    253406, 251453, 249515, 247594, 245689, 243800, 241927, 240069, 238227, 236400, 234589,
    232793, 231013, 229247, 227497, 225761, 224040, 222334, 220642, 218965, 217303, 215654,
    214020, 212400, 210794, 209202, 207624, 206059, 204508, 202971, 201447, 199936, 198439,
    196954, 195483, 194025, 192580, 191147, 189727, 188320, 186925, 185543, 184173, 182815,
    181470, 180136, 178815, 177505, 176207, 174921, 173646, 172383, 171132, 169892, 168663,
    167445, 166238, 165043, 163858, 162684, 161521, 160369, 159227, 158096, 156975, 155865,
    154765, 153675, 152595, 151525, 150465, 149415, 148375, 147344, 146323, 145312, 144310,
    143318, 142335, 141361, 140396, 139441, 138494, 137557, 136628, 135708, 134797, 133894,
    133000, 132115, 131237, 130369, 129508, 128656, 127812, 126976, 126148, 125328, 124516,
    123711, 122915, 122125, 121344, 120570, 119804, 119044, 118293, 117548, 116811, 116080,
    115357, 114641, 113932, 113229, 112534, 111845, 111162, 110487, 109818, 109155, 108499,
    107849, 107205, 106568, 105937, 105312, 104693, 104080, 103473, 102872, 102276, 101687,
    101103, 100525, 99952, 99385, 98823, 98267, 97716, 97171, 96631, 96096, 95566, 95041,
    94521, 94007, 93497, 92992, 92492, 91996, 91506, 91020, 90539, 90062, 89590, 89123,
    88659, 88201, 87746, 87296, 86850, 86408, 85971, 85538, 85108, 84683, 84261, 83844,
    83431, 83021, 82615, 82213, 81814, 81420, 81029, 80641, 80257, 79877, 79500, 79126,
    78756, 78389, 78025, 77665, 77308, 76954, 76603, 76256, 75911, 75570, 75231, 74896,
    74563, 74234, 73907, 73583, 73262, 72944, 72628, 72315, 72005, 71697, 71392, 71090,
    70790, 70492, 70197, 69905, 69615, 69327, 69042, 68759, 68478, 68200, 67924, 67650,
    67378, 67109, 66841, 66576, 66313, 66052, 65793, 65536, 65536,
};

FXQ_INLINE fxv_u32 fxq_p5(fxv_u32 x)
{
    fxv_u32 i = fxv_shr(x, 7), f = fxv_and(x, fxv_k32(127));
    fxv_u32 t0 = fxv_lut(fxq_p5_tab, i), t1 = fxv_lut(fxq_p5_tab, fxv_add32(i, fxv_k32(1)));
    return fxv_mul32(x, fxv_sub32(t0, fxv_shr(fxv_add32(fxv_mul32(fxv_sub32(t0, t1), f), fxv_k32(64)), 7)));
}

#define FXQ_C105     34406u      /* round(1.05 2^15) */
#define FXQ_TENTH    104857u     /* floor(2^20 / 10) */
#define FXQ_MULTI    1563843070u /* round(0.1159 pi 2^32) */
#define FXQ_INV_PI   83443u      /* round(2^18 / pi) */
#define FXQ_INV_2PI  683565276u  /* round(2^32 / (2 pi)) */

/* The diffuse bracket B = (1 - a) 1.05 P(nl) P(nv) + a rough + albedo a
 * 0.1159 pi in Q25 [B <= 64.9: < 2^31.02], times albedo / pi (Q33): Q26
 * [<= 20.65: < 2^30.4].
 * With t = t_r = x 2^-(31 + k) (x = c 2^k in [2^30, 2^32), the sqrt's
 * normalised c) and L.H = ls 2^-(20 + h):
 *   rough = t (4.5 - t) / 10 (1 + L.H / s)
 *   t (4.5 - t) = mh 2^-(28 + k), mh = hi(x t45), t45 = (4.5 - t) Q29
 *                 [2.5 2^29 .. 4.5 2^29; mh >= 2^28.3]
 *   1 / s = rS 2^(kS - 36), kS = clz(S) in [15, 23], rS = rcp20(S 2^kS)
 *   q = 1 + L.H / s  Q24 = 2^24 + hi(ls 2^12, rS 2^12) >> (24 + h - kS)  [shift 1..17;
 *                 L.H / s <= 128: q < 2^31.01]
 *   a rough = x2 2^-(24 + k), x2 = hi(2 hi(mh, A floor(2^20/10)), q), to Q25.
 * Each term's relative error <= 2^-14.8 (the P sums), its truncations
 * <= 2^-25 absolute: below the output's LSB (2^-24) even at albedo = 1. */
/* the rough term, a rough Q25, from c = L.H^2 2^32 - 1 normalised (x = c
 * << k, k even), L.H = lh_s 2^-(20 + lh_h) and s = NL + NV */
FXQ_INLINE fxv_u32 fxq_diffuse26_rough(fxv_u32 a, fxv_u32 s, fxv_u32 c, fxv_u32 x, fxv_u32 k, fxv_u32 lh_s,
                                       fxv_u32 lh_h)
{
    fxv_u32 t45 = fxv_sub32(fxv_k32(9u << 28), fxv_shr(c, 2));                       /* Q29 */
    fxv_u32 mh = fxq_mulhi(x, t45);
    fxv_u32 ks = fxv_clz(s), rs = fxq_rcp20(fxv_shlv(s, ks));
    fxv_u32 q = fxv_add32(fxv_k32(1u << 24), fxv_shrv(fxq_mulhi(fxv_shl(lh_s, 12), fxv_shl(rs, 12)),
                                                      fxv_sub32(fxv_add32(lh_h, fxv_k32(24)), ks)));
    /* a t (4.5 - t) / 10 = x1 2^-(31 + k) [mh < 4.5 2^29: t < 2^(1 - k);
     * A floor(2^20 / 10) < 2^31.68: x1 < 2^30.85]; a rough = x2 2^-(24 + k),
     * x2 = hi(2 x1, q); Q25: 2 x2 >> k [a rough 2^(25 + k) < 2^31.9: rough
     * <= 0.45 t (1 + 128 sqrt(t/2)) with t < 2^(1 - k)] */
    fxv_u32 x1 = fxq_mulhi(mh, fxv_mul32(a, fxv_k32(FXQ_TENTH)));
    return fxv_shrv(fxv_shl(fxq_mulhi(fxv_shl(x1, 1), q), 1), k);
}

/* split in two for the RGB form (the shape before albedo enters, then the
 * albedo part); integer sums, so the same bits as one expression */
FXQ_INLINE fxv_u32 fxq_diffuse26_shape(fxv_u32 nl, fxv_u32 nv, fxv_u32 a, fxv_u32 s,
                                       fxv_u32 c, fxv_u32 x, fxv_u32 k, fxv_u32 lh_s, fxv_u32 lh_h)
{
    fxv_u32 pp = fxq_mulhi(fxq_p5(nl), fxq_p5(nv));                                   /* Q30 */
    fxv_u32 k1 = fxv_mul32(fxv_sub32(fxv_k32(FACET_FX_ONE), a), fxv_k32(FXQ_C105));       /* Q30 <= 2^30.07 */
    fxv_u32 smooth = fxq_mulhi(pp, fxv_shl(k1, 1));                                   /* Q29 */
    return fxv_add32(fxv_shr(fxv_add32(smooth, fxv_k32(8)), 4), fxq_diffuse26_rough(a, s, c, x, k, lh_s, lh_h));
}

FXQ_INLINE fxv_u32 fxq_diffuse26_albedo(fxv_u32 shape, fxv_u32 a, fxv_u32 alb)
{
    fxv_u32 multi = fxq_mulhi(fxv_shl(fxv_mul32(alb, a), 1), fxv_k32(FXQ_MULTI));    /* Q31 */
    fxv_u32 b = fxv_add32(shape, fxv_shr(fxv_add32(multi, fxv_k32(32)), 6));
    return fxq_mulhi(b, fxv_mul32(alb, fxv_k32(FXQ_INV_PI)));                         /* alb/pi Q33 -> Q26 */
}

FXQ_INLINE fxv_u32 fxq_diffuse26(fxv_u32 nl, fxv_u32 nv, fxv_u32 a, fxv_u32 alb, fxv_u32 s,
                                    fxv_u32 c, fxv_u32 x, fxv_u32 k, fxv_u32 lh_s, fxv_u32 lh_h)
{
    return fxq_diffuse26_albedo(fxq_diffuse26_shape(nl, nv, a, s, c, x, k, lh_s, lh_h), a, alb);
}

FXQ_INLINE fxv_u32 fxq_diffuse_hammon(fxv_i32 nol, fxv_i32 nov, fxv_i32 lov, fxv_i32 alpha,
                                              fxv_i32 albedo)
{
    fxv_u32 nl = fxv_cosine(nol), nv = fxv_cosine(nov);
    fxv_u32 gs, gu, gw, gc, lh_h, lh_s, k, d;
    fxq_dots_of(nl, nv, lov, &gs, &gu, &gw, &gc);
    lh_s = fxq_sqrt32(gc, &lh_h);
    k = fxv_shl(lh_h, 1);
    d = fxq_diffuse26(nl, nv, fxv_alpha(alpha), fxv_unit(albedo), gs, gc, fxv_shlv(gc, k), k, lh_s, lh_h);
    return fxv_shr(fxv_add32(fxv_shl(d, 1), fxv_k32(5)), 3); /* (d + 2.5) / 4: + half the mean floor */
}

/* ---- the whole model ------------------------------------------------------------
 * brdf = spec + diffuse, spec = (a 2t)^2 F / (2 pi e^2 m) (fx_body.h):
 *   y = 1 - L.H = u 2^-32 / (1 + L.H): (1 + L.H) Q31 is a normalised
 *     mantissa [2^31, 2^32), r1 = rcp20 ~ 2^20 / (1 + L.H); u 2^ku in
 *     [2^31, 2^32) (u = 0 read as 1: y ~ 2^-32, its y^5 vanishes);
 *     y = ym 2^-(32 + ku), y^5 = y5 2^-(32 + 5 ku) [ym >= 2^30, y5 >= 2^22]
 *   F = f0 + (1 - f0) y^5 = Fs 2^-(30 + j), j = min(5 ku, clz(F0) - 16)
 *     [F0 2^(15 + j) < 2^31, the tail < 2^30], then normalised (kF); f0 = 0
 *     gives j <= 16: F to 2^-46 absolute, which is what the output needs,
 *     since F < 2^-16 means L.H ~ 1, so H ~ L ~ V off grazing: D Vis <=
 *     2^16.3 and the error D Vis 2^-46 < 2^-29
 *   a 2t = hi(A 2^ka, x) 2^-(13 + ka + k)   [>= 2^29], squared [>= 2^26]
 *   e60 = (A S)^2 + w 2^30 (exact, < 2^63): its top 32 bits [>= 2^25]
 *   m30 = (1 - a) 2 nl nv 2^30 + A S [<= 2^31, >= 2^15], normalised
 *   1 / (e^2 m): rcp20 of the normalised product [>= 2^29 before]
 *   spec = sp 2^-Es, Es an exponent lane (biased by 256; spec < 2^33)
 * brdf Q29 in 64 bits = spec sp 2^(29 - Es) (one 32x32->64 product by a
 * power of two <= 2^31) + diffuse Q26 2^3, rounded once to UQ40.24. */
/* What brdf_hammon computes before f0 and albedo enter; the RGB form
 * (facet_brdf_hammon_rgb_fx_fast) shares it across channels, and per
 * channel runs the same operations, so each channel is brdf_hammon's bits. */
/* the geometry's 11 lanes, passed as out-parameters
 * and then as values (sizeless vector types: no struct) */
#define FXQ_BRDF_GEOM_PARAMS_(T, P) \
    T P##a, T P##y5, T P##k5, T P##ka, T P##k, T P##g2, T P##ee, T P##em, T P##kd, T P##rd, T P##shape
#define FXQ_BRDF_GEOM_ARGS_(P) P##a, P##y5, P##k5, P##ka, P##k, P##g2, P##ee, P##em, P##kd, P##rd, P##shape

FXQ_INLINE void fxq_brdf_geometry(fxv_i32 nol, fxv_i32 nov, fxv_i32 lov, fxv_i32 alpha,
                                       FXQ_BRDF_GEOM_PARAMS_(fxv_u32 *, G_))
{
    fxv_u32 nl = fxv_cosine(nol), nv = fxv_cosine(nov), a = fxv_alpha(alpha);
    fxv_u32 gs, gu, gw, gc, lh_s, lh_h, k, x;
    fxv_u32 r1, uu, ku, ym, y2, y4, a2t;
    fxv_u32 as, ee, em, etop, mtop, e2, dm;
    fxq_dots_of(nl, nv, lov, &gs, &gu, &gw, &gc);
    lh_s = fxq_sqrt32(gc, &lh_h);
    k = fxv_shl(lh_h, 1);
    x = fxv_shlv(gc, k); /* 2t = x 2^-(30 + k) */
    /* Fresnel's y^5 */
    r1 = fxq_rcp20(fxv_add32(fxv_k32(1u << 31), fxv_shlv(lh_s, fxv_sub32(fxv_k32(11), lh_h)))); /* (1 + L.H) Q31 */
    uu = fxv_max(gu, fxv_k32(1));
    ku = fxv_clz(uu);
    ym = fxq_mulhi(fxv_shlv(uu, ku), fxv_shl(r1, 12));
    y2 = fxq_mulhi(ym, ym);
    y4 = fxq_mulhi(y2, y2);
    *G_y5 = fxq_mulhi(y4, ym);
    *G_k5 = fxv_add32(fxv_shl(ku, 2), ku);
    /* (a 2t)^2 */
    *G_ka = fxv_clz(a);
    a2t = fxq_mulhi(fxv_shlv(a, *G_ka), x);
    *G_g2 = fxq_mulhi(a2t, a2t);
    /* e^2 m */
    as = fxv_mul32(a, gs);
    etop = fxq_top(fxv_add64(fxv_mulw(as, as), fxv_mulw(gw, fxv_k32(1u << 30))), &ee);
    /* m30 = (1 - a) 2 nl nv 2^30 + A S = hi(2 NL NV, (2^15 - A) 2^17) + A S
     * [(2^15 - 32) 2^17 < 2^32; m <= 2: m30 <= 2^31; m >= 2^-15: m30 >= 2^15,
     * truncation <= 2^-15 relative], normalised: m = mtop 2^-(30 + km) */
    mtop = fxv_add32(fxq_mulhi(fxv_shl(fxv_mul32(nl, nv), 1), fxv_shl(fxv_sub32(fxv_k32(FACET_FX_ONE), a), 17)), as);
    em = fxv_clz(mtop);
    mtop = fxv_shlv(mtop, em);
    *G_em = fxv_add32(em, fxv_k32(17));
    *G_ee = ee;
    /* e = etop 2^-(28 + ee), m = mtop 2^-(13 + em) */
    e2 = fxq_mulhi(etop, etop);                        /* 2^-(24 + 2 ee) */
    dm = fxq_mulhi(e2, mtop);                          /* 2^-(5 + 2 ee + em) [>= 2^29] */
    *G_kd = fxv_clz(dm);
    *G_rd = fxq_rcp20(fxv_shlv(dm, *G_kd));   /* 1/(e^2 m) = rd 2^(2ee + em + kd - 46) */
    *G_a = a;
    *G_k = k;
    *G_shape = fxq_diffuse26_shape(nl, nv, a, gs, gc, x, k, lh_s, lh_h);
}

FXQ_INLINE fxv_u64 fxq_brdf_channel(FXQ_BRDF_GEOM_PARAMS_(fxv_u32, G_), fxv_i32 f0_in, fxv_i32 albedo)
{
    fxv_u32 f0 = fxv_unit(f0_in);
    fxv_u32 kf, jj, ft, fs, kF, num, sp, ks, es, sl, sr;
    fxv_u64 spec, d64;
    /* F = f0 + (1 - f0) y^5 */
    kf = fxv_sub32(fxv_clz(f0), fxv_k32(16));            /* f0 = 0: 16 */
    jj = fxv_min(G_k5, kf);
    ft = fxq_mulhi(G_y5, fxv_shl(fxv_sub32(fxv_k32(FACET_FX_ONE), f0), 16));
    fs = fxv_add32(fxv_shlv(f0, fxv_add32(jj, fxv_k32(15))),
                   fxv_shrv(ft, fxv_min(fxv_sub32(fxv_add32(G_k5, fxv_k32(1)), jj), fxv_k32(31))));
    kF = fxv_min(fxv_clz(fs), fxv_k32(31)); /* fs = 0 (F < 2^-46): spec 0 */
    num = fxq_mulhi(G_g2, fxv_shlv(fs, kF));              /* 2^-(2ka + 2k + jj + kF - 8) */
    sp = fxq_mulhi(fxq_mulhi(num, fxv_shl(G_rd, 12)), fxv_k32(FXQ_INV_2PI));
    /* spec = sp 2^-Es, Es = 2ka + 2k + jj + kF + 18 - 2ee - em - kd [sp >=
     * 2^21], normalised: + ks, held biased by 256 [Es >= -2: spec < 2^33];
     * Q29: sp 2^(29 - Es) < 2^62, a left shift sl <= 30 or a right one */
    ks = fxv_min(fxv_clz(sp), fxv_k32(31));
    sp = fxv_shlv(sp, ks);
    es = fxv_sub32(fxv_add32(fxv_add32(fxv_add32(fxv_shl(fxv_add32(G_ka, G_k), 1), jj), fxv_add32(kF, ks)),
                             fxv_k32(274)),
                   fxv_add32(fxv_add32(fxv_shl(G_ee, 1), G_em), G_kd));
    sl = fxv_sub32(fxv_k32(285), fxv_min(es, fxv_k32(285)));
    sr = fxv_min(fxv_sub32(fxv_max(es, fxv_k32(285)), fxv_k32(285)), fxv_k32(31));
    spec = fxv_mulw(fxv_shrv(sp, sr), fxv_shlv(fxv_k32(1), sl));
    /* diffuse Q26 to Q29 plus half a Q26 unit: the mean of its last floor */
    d64 = fxv_mulw(fxv_add32(fxv_shl(fxq_diffuse26_albedo(G_shape, G_a, fxv_unit(albedo)), 1), fxv_k32(1)),
                   fxv_k32(4));
    return fxv_rshr64(fxv_add64(spec, d64), 5);
}

FXQ_INLINE fxv_u64 fxq_brdf_hammon(fxv_i32 nol, fxv_i32 nov, fxv_i32 lov, fxv_i32 alpha,
                                           fxv_i32 f0_in, fxv_i32 albedo)
{
    fxv_u32 FXQ_BRDF_GEOM_ARGS_(G_);
    fxq_brdf_geometry(nol, nov, lov, alpha, FXQ_BRDF_GEOM_ARGS_(&G_));
    return fxq_brdf_channel(FXQ_BRDF_GEOM_ARGS_(G_), f0_in, albedo);
}

/* ---- Fresnel and diffuse: the rest of the menu (the fast tier only) -------------
 * No precise fixed-point kernel (kernels.def fx_code fast).  Fresnel Q15,
 * the diffuse terms UQ8.24 as diffuse_hammon.  No vector here is a struct
 * member or an array element: the helpers return one value, the others
 * through out-parameters. */

/* y^5 Q30 for Y = 2^15 (1 - x) Q15, as fresnel_schlick's: y2 = 2 Y^2 Q31
 * exact [<= 2^31], y4 = hi(y2, y2) Q30, y5 = hi(2 y4, Y 2^16) Q30 [every
 * operand <= 2^31, each truncation <= 2^-30]; Y = 0 gives 0, Y = 2^15 2^30. */
FXQ_INLINE fxv_u32 fxq_y5(fxv_u32 y)
{
    fxv_u32 y2 = fxv_shl(fxv_mul32(y, y), 1);
    fxv_u32 y4 = fxq_mulhi(y2, y2);
    return fxq_mulhi(fxv_shl(y4, 1), fxv_shl(y, 16));
}

/* Schlick with f90: f0 (1 - y^5) + f90 y^5 (the convex combination: no
 * signed difference), y = 1 - V.H:
 *   F30 = hi(2 (2^30 - y5), F0 2^16) + hi(2 y5, F90 2^16)   Q30 [<= 2^30:
 *         a convex combination of two values <= 1; operands <= 2^31]
 *   raw = round(F30 / 2^15).
 * Two truncations <= 2^-30 each: the error is the final rounding.  V.H = 1
 * gives f0 exactly (y5 = 0), V.H = 0 f90 exactly (y5 = 2^30). */
FXQ_INLINE fxv_u32 fxq_fresnel_schlick_f90(fxv_i32 f0_in, fxv_i32 f90_in, fxv_i32 voh)
{
    fxv_u32 y5 = fxq_y5(fxv_sub32(fxv_k32(FACET_FX_ONE), fxv_unit(voh)));
    fxv_u32 f = fxv_add32(fxq_mulhi(fxv_shl(fxv_sub32(fxv_k32(1u << 30), y5), 1), fxv_shl(fxv_unit(f0_in), 16)),
                          fxq_mulhi(fxv_shl(y5, 1), fxv_shl(fxv_unit(f90_in), 16)));
    return fxv_shr(fxv_add32(f, fxv_k32(1u << 14)), 15);
}

/* 2^(-i/256) Q31, i = 0..256: fxq_exp2_tab[i] = round(2^31 2^(-i/256))
 * [2^30 .. 2^31; steps < 2^23] */
static const uint32_t fxq_exp2_tab[257] = {
    2147483648u, 2141676973, 2135885998, 2130110682, 2124350982, 2118606857, 2112878262, 2107165158,
    2101467502, 2095785251, 2090118366, 2084466803, 2078830522, 2073209480, 2067603638, 2062012954,
    2056437387, 2050876895, 2045331439, 2039800978, 2034285470, 2028784876, 2023299156, 2017828268,
    2012372174, 2006930832, 2001504204, 1996092249, 1990694927, 1985312200, 1979944027, 1974590370,
    1969251188, 1963926443, 1958616096, 1953320108, 1948038440, 1942771053, 1937517909, 1932278970,
    1927054196, 1921843549, 1916646992, 1911464486, 1906295993, 1901141476, 1896000896, 1890874216,
    1885761398, 1880662405, 1875577199, 1870505744, 1865448001, 1860403934, 1855373507, 1850356681,
    1845353420, 1840363688, 1835387448, 1830424663, 1825475297, 1820539314, 1815616678, 1810707353,
    1805811301, 1800928489, 1796058879, 1791202437, 1786359126, 1781528911, 1776711757, 1771907628,
    1767116489, 1762338305, 1757573041, 1752820662, 1748081133, 1743354420, 1738640488, 1733939301,
    1729250827, 1724575029, 1719911875, 1715261330, 1710623359, 1705997930, 1701385007, 1696784557,
    1692196547, 1687620943, 1683057710, 1678506817, 1673968228, 1669441912, 1664927835, 1660425963,
    1655936265, 1651458706, 1646993254, 1642539877, 1638098541, 1633669214, 1629251865, 1624846459,
    1620452965, 1616071351, 1611701585, 1607343634, 1602997467, 1598663052, 1594340357, 1590029350,
    1585730000, 1581442275, 1577166143, 1572901575, 1568648537, 1564406999, 1560176931, 1555958300,
    1551751076, 1547555228, 1543370725, 1539197537, 1535035634, 1530884983, 1526745556, 1522617322,
    1518500250, 1514394310, 1510299473, 1506215708, 1502142985, 1498081275, 1494030547, 1489990772,
    1485961921, 1481943963, 1477936870, 1473940611, 1469955159, 1465980482, 1462016553, 1458063343,
    1454120821, 1450188960, 1446267730, 1442357104, 1438457051, 1434567544, 1430688553, 1426820052,
    1422962010, 1419114401, 1415277195, 1411450365, 1407633882, 1403827719, 1400031848, 1396246240,
    1392470869, 1388705706, 1384950723, 1381205894, 1377471191, 1373746586, 1370032052, 1366327563,
    1362633090, 1358948606, 1355274085, 1351609500, 1347954824, 1344310030, 1340675091, 1337049980,
    1333434672, 1329829140, 1326233356, 1322647296, 1319070932, 1315504238, 1311947188, 1308399756,
    1304861917, 1301333643, 1297814910, 1294305692, 1290805962, 1287315695, 1283834865, 1280363448,
    1276901417, 1273448747, 1270005413, 1266571390, 1263146652, 1259731174, 1256324931, 1252927899,
    1249540052, 1246161366, 1242791816, 1239431376, 1236080024, 1232737732, 1229404479, 1226080238,
    1222764986, 1219458698, 1216161350, 1212872918, 1209593378, 1206322705, 1203060876, 1199807867,
    1196563654, 1193328213, 1190101520, 1186883552, 1183674286, 1180473697, 1177281762, 1174098458,
    1170923762, 1167757650, 1164600099, 1161451085, 1158310587, 1155178580, 1152055042, 1148939949,
    1145833280, 1142735011, 1139645120, 1136563583, 1133490379, 1130425485, 1127368878, 1124320536,
    1121280436, 1118248556, 1115224875, 1112209370, 1109202018, 1106202798, 1103211687, 1100228665,
    1097253708, 1094286796, 1091327906, 1088377016, 1085434106, 1082499153, 1079572136, 1076653033,
    1073741824,
};

/* Schlick with the spherical-Gaussian power: f0 + (1 - f0) 2^-p,
 * p = (5.55473 c + 6.98316) c in [0, 12.54]:
 *   p Q28 = hi(2 C^2, K1) + hi(C 2^16, K2), K1 = round(5.55473 2^29),
 *           K2 = round(6.98316 2^29) [C^2 Q30 <= 2^30; p < 12.54 2^28 <
 *           2^31.65; truncations 2^-28 each]
 *   2^-p = 2^-n 2^-f: n = p >> 28 in [0, 12]; f's top 8 bits index
 *           fxq_exp2_tab, its next 20 interpolate linearly (one high word:
 *           hi(step < 2^23, f 2^12 < 2^32)); E = the Q31 value >> n
 *           [<= 2^31; chord error h^2/8 (ln 2)^2 = 2^-20.1 relative]
 *   F30 = F0 2^15 + hi((2^15 - F0) 2^16, E)   Q30 [<= 2^30]
 *   raw = round(F30 / 2^15).
 * cos = 0 gives 1 exactly (p = 0, E = 2^31). */
#define FXQ_SG_K1 2982172961u /* round(5.55473 2^29) */
#define FXQ_SG_K2 3749055478u /* round(6.98316 2^29) */
FXQ_INLINE fxv_u32 fxq_fresnel_schlick_sg(fxv_i32 f0_in, fxv_i32 cos_in)
{
    fxv_u32 f0 = fxv_unit(f0_in), c = fxv_unit(cos_in);
    fxv_u32 p = fxv_add32(fxq_mulhi(fxv_shl(fxv_mul32(c, c), 1), fxv_k32(FXQ_SG_K1)),
                          fxq_mulhi(fxv_shl(c, 16), fxv_k32(FXQ_SG_K2)));
    fxv_u32 i = fxv_and(fxv_shr(p, 20), fxv_k32(255)), fr = fxv_shl(fxv_and(p, fxv_k32(0xFFFFF)), 12);
    fxv_u32 e0 = fxv_lut(fxq_exp2_tab, i), e1 = fxv_lut(fxq_exp2_tab, fxv_add32(i, fxv_k32(1)));
    fxv_u32 e = fxv_shrv(fxv_sub32(e0, fxq_mulhi(fxv_sub32(e0, e1), fr)), fxv_shr(p, 28));
    fxv_u32 f = fxv_add32(fxv_shl(f0, 15), fxq_mulhi(fxv_shl(fxv_sub32(fxv_k32(FACET_FX_ONE), f0), 16), e));
    return fxv_shr(fxv_add32(f, fxv_k32(1u << 14)), 15);
}

/* The exact dielectric Fresnel (facet.h's fresnel_cook_torrance), with
 * u = 1/eta = (1 - s)/(1 + s), s = sqrt(f0), and the refracted cosine
 * ct = sqrt(1 - u^2 (1 - c^2)) = sqrt(v + u^2 c^2), v = 1 - u^2 = 4 s t^2,
 * t = 1/(1 + s):
 *   rs = (u c - ct)/(u c + ct),  rp = (c - u ct)/(c + u ct),  F = (rs^2 + rp^2)/2
 * (the Fresnel equations divided by eta: every term in [0, 1]; a difference
 * costs only its operands' absolute error, since each is divided by the
 * matching sum).  f0 = 0 gives 0 and f0 = 1 gives 1 (selected); the body
 * runs on f0 clamped to [2^-15, 1 - 2^-15] (s >= 2^-7.5, u >= 2^-17.6):
 *   s Q31 = the sqrt table at F0 2^ks (ks = (clz - 1) | 1, odd in [17, 31]),
 *         >> (ks - 17)/2
 *         [< 2^31; 2^-15 relative]
 *   t Q31 = rcp20(2^31 + s) 2^11 [(1 + s) Q31 in [2^31, 2^32); <= 2^31]
 *   t^2 Q32 = hi(2t, 2t) [< 2^32: s > 0];  v Q30 = hi(2s, t^2) [<= 2^30]
 *   u = (1 - f0) t^2 exactly scaled: (2^15 - F0) 2^ku in [2^31, 2^32), ku =
 *         clz in [17, 31], um = hi(that, t^2) [>= 2^29]: u = um 2^-(ku + 15)
 *         (u to 2^-14 relative however small)
 *   u c Q31 = hi(um, C 2^16) >> (ku - 17) [< 2^31]
 *   ct^2 Q30 = v + hi(2 uc, 2 uc) / 4 [<= 2^30, >= v >= 2^24.4]; ct Q31 from
 *         the sqrt table (an even shift 2h <= 6): (sq 2^12) >> h [<= 2^31]
 *   |rs| Q31 = (ct - uc) / (ct + uc) [the sum < 2^32], one fxq_div,
 *         saturated at 2^31 - 1
 *   rp: c + u ct and |c - u ct| at the scale 2^(ku + 30) in 64 bits (c
 *         2^31 times 2^(ku - 1); um ct >> 16) [each < 2^61, the sum >= 2^41],
 *         the sum's top word and the difference at the same shift, one
 *         fxq_div: |rp| Q31
 *   F Q31 = hi(2|rs|, 2|rs|) / 4 + hi(2|rp|, 2|rp|) / 4 [<= 2^31]
 *   raw = round(F / 2^16). */

FXQ_INLINE fxv_u32 fxq_sq31(fxv_u32 q) { return fxq_mulhi(fxv_shl(q, 1), fxv_shl(q, 1)); }

FXQ_INLINE fxv_u32 fxq_fresnel_cook_torrance(fxv_i32 f0_in, fxv_i32 voh)
{
    fxv_u32 f0 = fxv_unit(f0_in), c = fxv_unit(voh);
    fxv_u32 fc = fxv_min(fxv_max(f0, fxv_k32(1)), fxv_k32(FACET_FX_ONE - 1));
    fxv_u32 ks = fxv_or(fxv_sub32(fxv_clz(fc), fxv_k32(1)), fxv_k32(1)); /* odd: F0 2^ks in [2^30, 2^32) */
    fxv_u32 s = fxv_shrv(fxv_shl(fxq_sqrt20(fxv_shlv(fc, ks)), 11), fxv_shr(fxv_sub32(ks, fxv_k32(17)), 1));
    fxv_u32 t = fxv_shl(fxq_rcp20(fxv_add32(fxv_k32(1u << 31), s)), 11);
    fxv_u32 t2 = fxq_mulhi(fxv_shl(t, 1), fxv_shl(t, 1));
    fxv_u32 v = fxq_mulhi(fxv_shl(s, 1), t2);
    fxv_u32 om = fxv_sub32(fxv_k32(FACET_FX_ONE), fc), ku = fxv_clz(om);
    fxv_u32 um = fxq_mulhi(fxv_shlv(om, ku), t2);
    fxv_u32 uc = fxv_shrv(fxq_mulhi(um, fxv_shl(c, 16)), fxv_sub32(ku, fxv_k32(17)));
    fxv_u32 ct2 = fxv_add32(v, fxv_shr(fxq_sq31(uc), 2));
    fxv_u32 k2 = fxv_and(fxv_clz(ct2), fxv_k32(30));
    fxv_u32 ct = fxv_shrv(fxv_shl(fxq_sqrt20(fxv_shlv(ct2, k2)), 12), fxv_shr(k2, 1));
    fxv_u32 rs = fxq_div(fxv_sub32(fxv_max(ct, uc), uc), fxv_add32(ct, uc), 31, 0x7FFFFFFFu);
    fxv_u64 cp = fxv_mulw(fxv_shl(c, 16), fxv_shlv(fxv_k32(1), fxv_sub32(ku, fxv_k32(1))));
    fxv_u64 up = fxv_shr64(fxv_mulw(um, ct), 16);
    fxv_u32 e, dt = fxq_top(fxv_add64(cp, up), &e);
    fxv_u32 ct_ = fxq_top_at(cp, e), ut_ = fxq_top_at(up, e);
    fxv_u32 rp = fxq_div(fxv_sub32(fxv_max(ct_, ut_), fxv_min(ct_, ut_)), dt, 31, 0x7FFFFFFFu);
    fxv_u32 f = fxv_add32(fxv_shr(fxq_sq31(rs), 2), fxv_shr(fxq_sq31(rp), 2));
    fxv_u32 raw = fxv_shr(fxv_add32(f, fxv_k32(1u << 15)), 16);
    raw = fxv_sel(fxv_lt(f0, fxv_k32(1)), fxv_k32(0), raw);
    return fxv_sel(fxv_lt(fxv_k32(FACET_FX_ONE - 1), f0), fxv_k32(FACET_FX_ONE), raw);
}

/* Burley: albedo / pi (1 + (fd - 1) yl^5)(1 + (fd - 1) yv^5), fd = 0.5 +
 * 2 sqrt(a) L.H^2, each factor the convex combination (1 - y^5) + fd y^5:
 *   sqrt(a) Q19: A 2^ka in [2^30, 2^32), ka odd in [15, 25], the sqrt
 *         table, >> (ka - 15) / 2 [<= 2^19; 2^-15 relative]
 *   fd Q29 = 2^28 + hi(sq 2^12, LH^2 2^1)   [<= 2.5 2^29]
 *   fl Q29 = (2^30 - y5) / 2 + hi(2 fd, 2 y5)   [in [0.5, 2.5] 2^29]
 *   pr Q28 = hi(2 fl, 2 fv)   [<= 6.25 2^28 < 2^31]
 *   d Q30 = hi(2 pr, alb / pi Q33)   [alb round(2^18 / pi) < 2^31.4;
 *         d <= 1.99 2^30]
 *   raw UQ8.24 = round(d / 2^6). */
FXQ_INLINE fxv_u32 fxq_diffuse_out30(fxv_u32 pr28, fxv_u32 alb)
{
    fxv_u32 d = fxq_mulhi(fxv_shl(pr28, 1), fxv_mul32(alb, fxv_k32(FXQ_INV_PI)));
    return fxv_shr(fxv_add32(d, fxv_k32(32)), 6);
}

FXQ_INLINE fxv_u32 fxq_burley_factor(fxv_u32 fd, fxv_u32 x)
{
    fxv_u32 y5 = fxq_y5(fxv_sub32(fxv_k32(FACET_FX_ONE), x));
    return fxv_add32(fxv_shr(fxv_sub32(fxv_k32(1u << 30), y5), 1), fxq_mulhi(fxv_shl(fd, 1), fxv_shl(y5, 1)));
}

FXQ_INLINE fxv_u32 fxq_diffuse_burley(fxv_i32 nol, fxv_i32 nov, fxv_i32 loh, fxv_i32 alpha,
                                           fxv_i32 albedo)
{
    fxv_u32 a = fxv_alpha(alpha), lh = fxv_unit(loh);
    fxv_u32 ka = fxv_sub32(fxv_and(fxv_add32(fxv_clz(a), fxv_k32(1)), fxv_k32(30)), fxv_k32(1));
    fxv_u32 sq = fxv_shrv(fxq_sqrt20(fxv_shlv(a, ka)), fxv_shr(fxv_sub32(ka, fxv_k32(15)), 1));
    fxv_u32 fd = fxv_add32(fxv_k32(1u << 28), fxq_mulhi(fxv_shl(sq, 12), fxv_shl(fxv_mul32(lh, lh), 1)));
    fxv_u32 pr = fxq_mulhi(fxv_shl(fxq_burley_factor(fd, fxv_cosine(nol)), 1),
                           fxv_shl(fxq_burley_factor(fd, fxv_cosine(nov)), 1));
    return fxq_diffuse_out30(pr, fxv_unit(albedo));
}

/* Hammon's rough and multi with another smooth term (hybrid, cheap): the
 * dot triple of diffuse_hammon (fxq_dots_of) and its rough term
 * (fxq_diffuse26_rough, the same code and bounds):
 *   c = ~min(P, Q) = L.H^2 2^32 - 1 (the raised triple), L.H = ls 2^-(20 + h)
 *   a rough Q25 as there; the bracket (1 - a) smooth Q29 / 16 + a rough Q25
 *   [smooth <= 1 here: B <= 64.9 as there], then fxq_diffuse26_albedo and
 *   diffuse_hammon's final (d + 2.5) / 4. */
FXQ_INLINE fxv_u32 fxq_rough25(fxv_u32 a, fxv_u32 s, fxv_u32 c)
{
    fxv_u32 k = fxv_and(fxv_clz(c), fxv_k32(30)), h, ls = fxq_sqrt32(c, &h);
    return fxq_diffuse26_rough(a, s, c, fxv_shlv(c, k), k, ls, h);
}

FXQ_INLINE fxv_u32 fxq_hammon_variant(fxv_u32 smooth29, fxv_u32 nl, fxv_u32 nv, fxv_i32 lov, fxv_u32 a,
                                      fxv_u32 alb)
{
    fxv_u32 s, u, w, c, shape;
    fxq_dots_of(nl, nv, lov, &s, &u, &w, &c);
    shape = fxv_add32(fxv_shr(fxv_add32(smooth29, fxv_k32(8)), 4), fxq_rough25(a, s, c));
    fxv_u32 d = fxq_diffuse26_albedo(shape, a, alb);
    return fxv_shr(fxv_add32(fxv_shl(d, 1), fxv_k32(5)), 3);
}

/* hybrid: smooth = (1 - yl^5 / 2)(1 - yv^5 / 2), each Q30 [<= 2^30], their
 * product hi(2 fl, 2 fv) Q30, times (1 - a) Q31 [(2^15 - A) 2^16 <= 2^31]:
 * Q29 */
FXQ_INLINE fxv_u32 fxq_diffuse_hammon_hybrid(fxv_i32 nol, fxv_i32 nov, fxv_i32 lov, fxv_i32 alpha,
                                                  fxv_i32 albedo)
{
    fxv_u32 nl = fxv_cosine(nol), nv = fxv_cosine(nov), a = fxv_alpha(alpha);
    fxv_u32 fl = fxv_sub32(fxv_k32(1u << 30), fxv_shr(fxq_y5(fxv_sub32(fxv_k32(FACET_FX_ONE), nl)), 1));
    fxv_u32 fv = fxv_sub32(fxv_k32(1u << 30), fxv_shr(fxq_y5(fxv_sub32(fxv_k32(FACET_FX_ONE), nv)), 1));
    fxv_u32 sm = fxq_mulhi(fxq_mulhi(fxv_shl(fl, 1), fxv_shl(fv, 1)), fxv_shl(fxv_sub32(fxv_k32(FACET_FX_ONE), a), 16));
    return fxq_hammon_variant(sm, nl, nv, lov, a, fxv_unit(albedo));
}

/* cheap: smooth = 1, (1 - a) Q29 exact */
FXQ_INLINE fxv_u32 fxq_diffuse_hammon_cheap(fxv_i32 nol, fxv_i32 nov, fxv_i32 lov, fxv_i32 alpha,
                                                 fxv_i32 albedo)
{
    fxv_u32 a = fxv_alpha(alpha);
    return fxq_hammon_variant(fxv_shl(fxv_sub32(fxv_k32(FACET_FX_ONE), a), 14), fxv_cosine(nol), fxv_cosine(nov), lov, a,
                              fxv_unit(albedo));
}

/* Oren-Nayar: albedo / pi (A + B max(0, L.V - nl nv) / max(nl, nv)) (facet.h's
 * identity, no raise), sigma^2 = a^2 / 4:
 *   s2 = A^2 = sigma^2 Q32 exact [<= 2^30]
 *   A Q31 = 2^31 - (s2 / (s2 + 0.33 2^32) Q31) / 2,  B Q31 = hi(s2 / (s2 +
 *         0.09 2^32) Q31, 0.45 2^32)   [two fxq_div, 2^-15.9 relative;
 *         A in [0.785, 1], B <= 0.331]
 *   num Q30 = max(T 2^15, 2^30 + NL NV) - (2^30 + NL NV), T = LOV + 2^15
 *         [(1 + L.V) and (1 + nl nv) 2^30 <= 2^31; num < 2^31]
 *   term Q22 = num / max(NL, NV) 2^7, one fxq_div   [term <= 256: < 2^30]
 *   sum Q21 = A / 2^10 + hi(B, term)   [<= 85.7 2^21 < 2^27.5]
 *   d Q26 = hi(16 sum, alb / pi Q33)   [<= 27.3 2^26 < 2^30.8]
 *   raw UQ8.24 = round(d / 4). */
#define FXQ_ON_033 1417339208u /* round(0.33 2^32) */
#define FXQ_ON_009 386547057u  /* round(0.09 2^32) */
#define FXQ_ON_045 1932735283u /* round(0.45 2^32) */
FXQ_INLINE fxv_u32 fxq_diffuse_oren_nayar(fxv_i32 nol, fxv_i32 nov, fxv_i32 lov, fxv_i32 alpha,
                                               fxv_i32 albedo)
{
    fxv_u32 nl = fxv_cosine(nol), nv = fxv_cosine(nov), a = fxv_alpha(alpha), s2 = fxv_mul32(a, a);
    fxv_u32 ra = fxq_div(s2, fxv_add32(s2, fxv_k32(FXQ_ON_033)), 31, 1u << 31);
    fxv_u32 rb = fxq_div(s2, fxv_add32(s2, fxv_k32(FXQ_ON_009)), 31, 1u << 31);
    fxv_u32 bb = fxq_mulhi(rb, fxv_k32(FXQ_ON_045));
    fxv_u32 p = fxv_add32(fxv_k32(1u << 30), fxv_mul32(nl, nv));
    fxv_u32 num = fxv_sub32(fxv_max(fxv_shl(fxv_lov_t(lov), 15), p), p);
    fxv_u32 term = fxq_div(num, fxv_max(nl, nv), 7, 1u << 30);
    fxv_u32 sum = fxv_add32(fxv_shr(fxv_sub32(fxv_k32(1u << 31), fxv_shr(ra, 1)), 10), fxq_mulhi(bb, term));
    fxv_u32 d = fxq_mulhi(fxv_shl(sum, 4), fxv_mul32(fxv_unit(albedo), fxv_k32(FXQ_INV_PI)));
    return fxv_shr(fxv_add32(d, fxv_k32(2)), 2);
}

#endif
