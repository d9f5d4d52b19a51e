/* facet/detail/f32_body.h - the one body of every f32 kernel.
 *
 * Deliberately without an include guard: each port header includes it once
 * per tier (through facet/detail/f32_tiers.h, which defines FACET_OP and
 * FACET_K from the port's name), after defining
 *   FACET_V        the vector (or scalar) type,
 *   FACET_OP(op)   the name of the port's op `op` (set add sub mul fma fnma
 *                  min max sel_lt clamp keep_ord rcp rsqrt sqr_err sqr_sub, and the
 *                  exponent-bit ops exp2i getexp getmant, see facet/scalar.h),
 *   FACET_K(k)     the name to give kernel `k` in this port and tier,
 * and optionally FACET_TIER_FAST 1 for the fast tier (f32_fast): the port's
 * rcp_fast / rsqrt_fast in place of rcp / rsqrt.
 * Contracts (formula, domain, measured error, cost) are in facet.h; the
 * comments here explain the numerics.
 */
#ifndef FACET_V
#error "include a port header (facet/scalar.h, facet/sse2.h, ...), not this file"
#endif

#define V_ FACET_V
#define C_(x) FACET_OP(set)(x)
#define ADD_ FACET_OP(add)
#define SUB_ FACET_OP(sub)
#define MUL_ FACET_OP(mul)
#define FMA_ FACET_OP(fma)
#define FNMA_ FACET_OP(fnma)
#define MIN_ FACET_OP(min)
#define MAX_ FACET_OP(max)
#define CLAMP_ FACET_OP(clamp)
#define KEEP_ORD_ FACET_OP(keep_ord)
#define KEEP_ORD4_ FACET_OP(keep_ord4)
/* the tier: the precise one, or with FACET_TIER_FAST 1 the fast one (the
 * same formulation, the port's cheaper rcp / rsqrt refinement) */
#if defined(FACET_TIER_FAST) && FACET_TIER_FAST
#define RCP_ FACET_OP(rcp_fast)
#define RSQRT_ FACET_OP(rsqrt_fast)
#define DIV_ FACET_OP(div_fast)
#define SQRT_ FACET_OP(sqrt_fast)
#define FAST_ 1
#else
#define RCP_ FACET_OP(rcp)
#define RSQRT_ FACET_OP(rsqrt)
#define DIV_ FACET_OP(div)
#define SQRT_ FACET_OP(sqrt)
#define FAST_ 0
#endif
/* where an error is raised to the fifth power (brdf_hammon's 1 - L.H), both
 * tiers refine fully: 5 times an unrefined estimate would exceed 2^-12 */
#define RCP_X5_ FACET_OP(rcp)
#define RSQRT_X5_ FACET_OP(rsqrt)
#define DIV_X5_ FACET_OP(div)
#define SQRT_X5_ FACET_OP(sqrt)
/* where an error is multiplied by an exponent (the power of Blinn-Phong, the
 * exponent of Beckmann, log2 in a pow: |y| up to 126), both tiers use the
 * precise reciprocal: an unrefined estimate times 126 would exceed 2^-12 */
#define RCP_EXP_ FACET_OP(rcp)

/* 1/pi rounded to float. */
#define FACET_INV_PI_ 0.318309886f

/* the internal helpers under this port's names, aliased once */
#define X_UNIT_ FACET_K(x_unit)
#define X_COS_ FACET_K(x_cos)
#define X_ALPHA_ FACET_K(x_alpha)
#define X_LOV_ FACET_K(x_lov)
#define X_ONE_MINUS_POW5_ FACET_K(x_one_minus_pow5)
#define X_SMITH_W_ FACET_K(x_smith_w)
#define X_SQRT_ FACET_K(x_sqrt)
#define X_EXP2M1R_POLY_ FACET_K(x_exp2m1r_poly)
#define X_EXP2M1R_ FACET_K(x_exp2m1r)
#define X_EXP2_ FACET_K(x_exp2)
#define X_LOG2_FOLD_ FACET_K(x_log2_fold)
#define X_LOG2_POLY_ FACET_K(x_log2_poly)
#define X_LOG2_ FACET_K(x_log2)
#define X_LOG2_X_ FACET_K(x_log2_x)
#define X_EXP2_SCALED_ FACET_K(x_exp2_scaled)
#define X_LN1PR_ FACET_K(x_ln1pr)
#define X_PCHIP_END_ FACET_K(x_pchip_end)
#define X_PCHIP_MID_ FACET_K(x_pchip_mid)
#define X_FRESNEL_Y_ FACET_K(x_fresnel_y)
#define X_FRESNEL_ FACET_K(x_fresnel)
#define X_G2_DEN_ FACET_K(x_g2_den)
#define X_HAMMON_DEN_ FACET_K(x_hammon_den)
#define X_DIFFUSE_SINGLE_ FACET_K(x_diffuse_single)
#define X_DIFFUSE_PI_ FACET_K(x_diffuse_pi)
#define X_HALF_INV_NH_ FACET_K(x_half_inv_nh)
#define X_BRDF_GEOMETRY_ FACET_K(x_brdf_geometry)
#define X_BRDF_PEAK_ FACET_K(x_brdf_peak)
#define X_ONE_MINUS_LH_ FACET_K(x_one_minus_lh)
#define X_BRDF_CHANNEL_ FACET_K(x_brdf_channel)

/* The NaN rule, shared by all kernels: a NaN in any input of a sample gives
 * +0 for that sample (a value that cannot light a pixel), every tier, every
 * port.  Every kernel ends with `return NAN0_(result, input, ...);`, which
 * keeps result where no input is NaN and gives +0 otherwise: the port ops
 * keep_ord(r, a, b) (an ordered compare of two inputs and a mask) and
 * keep_ord4(r, a, b, c, d) (four inputs: on avx512 the second compare runs
 * under the first one's mask, on neon one compare of the maximum).  The kernel itself runs on the clamped inputs (NaN clamps to the
 * low end below), so nothing traps and no NaN reaches the result; the mask
 * then replaces it.  tests/f32/test_f32_bad_input.c and tests/f32/test_f32_ports.c
 * check it from the kernel list for every kernel, input position, NaN class
 * and port, so a kernel without it fails. */
#define NAN0_(...) NAN0_SEL_(__VA_ARGS__, NAN0_8_, NAN0_7_, NAN0_6_, NAN0_5_, NAN0_4_, NAN0_3_, \
                             NAN0_2_, NAN0_1_, -)(__VA_ARGS__)
#define NAN0_SEL_(r, a, b, c, d, e, f, g, h, N, ...) N
#define NAN0_1_(r, a) KEEP_ORD_(r, a, a)
#define NAN0_2_(r, a, b) KEEP_ORD_(r, a, b)
#define NAN0_3_(r, a, b, c) KEEP_ORD4_(r, a, b, c, c)
#define NAN0_4_(r, a, b, c, d) KEEP_ORD4_(r, a, b, c, d)
#define NAN0_5_(r, a, b, c, d, e) KEEP_ORD_(NAN0_4_(r, a, b, c, d), e, e)
#define NAN0_6_(r, a, b, c, d, e, f) KEEP_ORD_(NAN0_4_(r, a, b, c, d), e, f)
#define NAN0_7_(r, a, b, c, d, e, f, g) KEEP_ORD4_(NAN0_4_(r, a, b, c, d), e, f, g, g)
#define NAN0_8_(r, a, b, c, d, e, f, g, h) KEEP_ORD4_(NAN0_4_(r, a, b, c, d), e, f, g, h)

/* Domain handling, shared by all kernels: out-of-domain values and -Inf go
 * to the low end, +Inf to the high end; NaN to the low end too, which only
 * keeps the arithmetic finite: NAN0_ then makes the result 0. */
FACET_INLINE V_ X_UNIT_(V_ x) { return CLAMP_(x, C_(0.0f), C_(1.0f)); }
FACET_INLINE V_ X_COS_(V_ x) { return CLAMP_(x, C_(FACET_COS_MIN), C_(1.0f)); }
FACET_INLINE V_ X_ALPHA_(V_ x) { return CLAMP_(x, C_(FACET_ALPHA_MIN), C_(1.0f)); }
FACET_INLINE V_ X_LOV_(V_ x) { return CLAMP_(x, C_(-1.0f), C_(1.0f)); }

/* 1 - (1 - x)^5 without cancellation at small x: with y = 1 - x it is
 * x (1 + y + y^2 + y^3 + y^4), a sum of positive terms. */
FACET_INLINE V_ X_ONE_MINUS_POW5_(V_ x)
{
    V_ y = SUB_(C_(1.0f), x);
    V_ p = ADD_(y, C_(1.0f));
    p = FMA_(p, y, C_(1.0f));
    p = FMA_(p, y, C_(1.0f));
    p = FMA_(p, y, C_(1.0f));
    return MUL_(x, p);
}

/* k Q(x), Q(x) = (1 - (1 - x)^5) / x = 1 + y + y^2 + y^3 + y^4 (y = 1 - x),
 * in [1, 5] on [0, 1] (k a constant, folded into the coefficients): those
 * positive terms summed by Horner in y, 1 rounding each, in both tiers.
 * Horner in x (k (x^4 - 5x^3 + 10x^2 - 10x + 5), no 1 - x) is one operation
 * less but four constants more, which RVV and the scalar RISC-V code
 * materialize: measured there 5 more instructions per brdf_hammon sample,
 * the fast tier slower than the precise one (qemu counts, VLEN 128). */
#define X_POW5_Q_(x, k) FACET_K(x_pow5_q)(x, C_(k))
FACET_INLINE V_ FACET_K(x_pow5_q)(V_ x, V_ k)
{
    V_ y = SUB_(C_(1.0f), x);
    V_ p = FMA_(y, k, k);
    p = FMA_(p, y, k);
    p = FMA_(p, y, k);
    return FMA_(p, y, k);
}

/* alpha^2 (1 - n^2) + n^2 = alpha^2 + (1 - alpha^2) n^2, the radicand of the
 * exact Smith terms, with 1 - n^2 formed as (1-n)(1+n): all terms >= 0. */
FACET_INLINE V_ X_SMITH_W_(V_ n, V_ a2)
{
    V_ q = MUL_(SUB_(C_(1.0f), n), ADD_(C_(1.0f), n));
    return FMA_(a2, q, MUL_(n, n));
}

FACET_INLINE V_ X_SQRT_(V_ w) { return SQRT_(w); }

/* ---- 2^y and log2 ------------------------------------------------------------
 * No libm: the exponent field (the port ops exp2i, getexp, getmant) and
 * polynomials.  Used by the exponential D terms and the GTR kernels here and
 * by the samplers (f32_sample_body.h).  Errors with the float coefficients
 * and exact arithmetic (fitted and checked in long double); the tests
 * (tests/sample/test_sample_prims.c, tests/f32/test_f32_accuracy.c) measure them with
 * the roundings of each port.
 *
 * E(y) = (2^y - 1) / y (E(0) = ln 2), the relative form of 2^y - 1, for
 * |y| <= 126:
 *   |y| < 1: E(y) = P(y), degree 7, interpolated at Chebyshev nodes of
 *            [-1, 1] (near minimax; float coefficients: relative error
 *            < 9.4e-9);
 *   else:    y = k + f, k = round(y) (adding and subtracting 1.5 * 2^23),
 *            f in [-1/2, 1/2], 2^y = 2^k (1 + f P(f)), E = (2^y - 1) / y:
 *            2^y - 1 has no cancellation for |y| >= 1. */
FACET_INLINE V_ X_EXP2M1R_POLY_(V_ y)
{
    V_ p = FMA_(y, C_(1.335729394e-06f), C_(1.545752275e-05f));
    p = FMA_(p, y, C_(1.540264202e-04f));
    p = FMA_(p, y, C_(1.333227614e-03f));
    p = FMA_(p, y, C_(9.618130513e-03f));
    p = FMA_(p, y, C_(5.550413579e-02f));
    p = FMA_(p, y, C_(2.402265072e-01f));
    return FMA_(p, y, C_(6.931471825e-01f));
}

FACET_INLINE V_ X_EXP2M1R_(V_ y)
{
    V_ ay = MAX_(y, SUB_(C_(0.0f), y));
    V_ k = SUB_(ADD_(y, C_(12582912.0f)), C_(12582912.0f));
    V_ f = SUB_(y, k);
    V_ e = MUL_(FMA_(f, X_EXP2M1R_POLY_(f), C_(1.0f)), FACET_OP(exp2i)(k));
    V_ big = MUL_(SUB_(e, C_(1.0f)), RCP_(FACET_OP(sel_lt)(ay, C_(1.0f), C_(1.0f), y)));
    return FACET_OP(sel_lt)(ay, C_(1.0f), X_EXP2M1R_POLY_(y), big);
}

/* 2^y for y in [-126, 126] (the caller keeps it there): 2^k (1 + f P(f)) as
 * above; relative error about 2 ulp (P's 9.4e-9 on [-1/2, 1/2] and the
 * roundings of 1 + f P and of the final product, which is exact). */
FACET_INLINE V_ X_EXP2_(V_ y)
{
    V_ k = SUB_(ADD_(y, C_(12582912.0f)), C_(12582912.0f));
    V_ f = SUB_(y, k);
    return MUL_(FMA_(f, X_EXP2M1R_POLY_(f), C_(1.0f)), FACET_OP(exp2i)(k));
}

/* c 2^y for y <= 0 down to -190 (the caller clamps), c 2^y below 2^-100
 * included: (c 2^(y + 64)) 2^-64, whose last product rounds once into the
 * denormals (a flush-to-zero port gives 0 there).  c <= 2^60. */
FACET_INLINE V_ X_EXP2_SCALED_(V_ c, V_ y)
{
    return MUL_(MUL_(c, X_EXP2_(ADD_(y, C_(64.0f)))), C_(5.42101086e-20f));
}

/* log2 x = e + log2 m: x = 2^e m, m folded into [sqrt(1/2), sqrt(2)] (m / 2,
 * e + 1 above sqrt 2); with s = (m - 1) / (m + 1) (m - 1 exact),
 * log2 m = s Q(s^2), Q(t) = (2 / ln 2) atanh(sqrt t) / sqrt t, degree 3 on
 * [0, 0.0295] (float coefficients: relative error < 1.4e-8), so log2 m
 * keeps its relative precision near m = 1 (x near 1 or near a power of 2).
 * The reciprocal 1 / (m + 1) is the caller's. */
FACET_INLINE V_ X_LOG2_FOLD_(V_ x, V_ *e)
{
    V_ m = FACET_OP(getmant)(x), big = C_(1.41421356f);
    *e = FACET_OP(getexp)(x);
    *e = FACET_OP(sel_lt)(big, m, ADD_(*e, C_(1.0f)), *e);
    return FACET_OP(sel_lt)(big, m, MUL_(m, C_(0.5f)), m);
}

FACET_INLINE V_ X_LOG2_POLY_(V_ m, V_ e, V_ r)
{
    V_ s = MUL_(SUB_(m, C_(1.0f)), r);
    V_ t = MUL_(s, s);
    V_ q = FMA_(t, C_(4.317176938e-01f), C_(5.767151713e-01f));
    q = FMA_(q, t, C_(9.617988467e-01f));
    q = FMA_(q, t, C_(2.885390043e+00f));
    return FMA_(s, q, e);
}

/* log2 x for a positive normal x, with the tier's reciprocal (the samplers) */
FACET_INLINE V_ X_LOG2_(V_ x)
{
    V_ e, m = X_LOG2_FOLD_(x, &e);
    return X_LOG2_POLY_(m, e, RCP_(ADD_(m, C_(1.0f))));
}

/* log2 x for any x in [0, 2^128): denormals scaled by 2^64 first (x = 0
 * gives -191, finite), the precise reciprocal in both tiers (the result is
 * multiplied by an exponent).  Error: the polynomial's 1.4e-8 and about
 * 3 ulp of roundings, relative to |log2 m|, plus e's half ulp of the sum. */
FACET_INLINE V_ X_LOG2_X_(V_ x)
{
    V_ tiny = C_(7.88860905e-31f); /* 2^-100 */
    V_ xs = FACET_OP(sel_lt)(x, tiny, MUL_(x, C_(1.84467441e+19f)), x);
    V_ e, m = X_LOG2_FOLD_(xs, &e);
    e = SUB_(e, FACET_OP(sel_lt)(x, tiny, C_(64.0f), C_(0.0f)));
    return X_LOG2_POLY_(m, e, RCP_EXP_(ADD_(m, C_(1.0f))));
}

/* ---- identities ------------------------------------------------------ */

/* N.H = (N.L + N.V) / |L + V|, |L + V|^2 = 2 + 2 L.V.  t = 1 + L.V is raised
 * to (N.L + N.V)^2 / 2 where the triple is inconsistent, which caps N.H at 1
 * and keeps 2t > 0 (N.L, N.V >= FACET_COS_MIN). */
FACET_INLINE V_ FACET_K(noh_from_dots)(V_ nol, V_ nov, V_ lov)
{
    V_ s = ADD_(X_COS_(nol), X_COS_(nov));
    V_ t = ADD_(C_(1.0f), X_LOV_(lov));
    V_ t2 = MAX_(ADD_(t, t), MUL_(s, s));
    return NAN0_(MIN_(MUL_(s, RSQRT_(t2)), C_(1.0f)), nol, nov, lov);
}

/* L.H = |L + V| / 2 = sqrt((1 + L.V) / 2) = t * rsqrt(2t); 2t is floored at
 * 2^-100 only so that L.V = -1 gives 0 * finite = 0. */
FACET_INLINE V_ FACET_K(loh_from_dots)(V_ lov)
{
    V_ t = ADD_(C_(1.0f), X_LOV_(lov));
    V_ t2 = MAX_(ADD_(t, t), C_(7.88860905e-31f));
    return NAN0_(MIN_(MUL_(t, RSQRT_(t2)), C_(1.0f)), lov);
}

/* ---- Fresnel ---------------------------------------------------------- */

/* f0 + (1 - f0) y^5 with y given as the unevaluated sum yh + yl:
 * y^5 ~ yh^4 (yh + 5 yl), so the rounding of y is not amplified five times. */
FACET_INLINE V_ X_FRESNEL_Y_(V_ f0, V_ yh, V_ yl)
{
    V_ y2 = MUL_(yh, yh);
    V_ y5 = MUL_(MUL_(y2, y2), FMA_(C_(5.0f), yl, yh));
    return FMA_(SUB_(C_(1.0f), f0), y5, f0);
}

/* y = 1 - c exactly as yh + yl (Fast2Sum: |1| >= |c|). */
FACET_INLINE V_ X_FRESNEL_(V_ f0, V_ c)
{
    V_ yh = SUB_(C_(1.0f), c);
    V_ yl = SUB_(SUB_(C_(1.0f), yh), c);
    return X_FRESNEL_Y_(f0, yh, yl);
}

FACET_INLINE V_ FACET_K(fresnel_schlick)(V_ f0, V_ c)
{
    return NAN0_(X_FRESNEL_(X_UNIT_(f0), X_UNIT_(c)), f0, c);
}

/* ---- Fresnel: Schlick with f90, and the exact dielectric ------------------- */

#define X_POW5_Y_ FACET_K(x_pow5_y)

/* (1 - c)^5 with y = 1 - c carried as yh + yl (Fast2Sum, |1| >= |c|):
 * y^5 ~ yh^4 (yh + 5 yl), so the rounding of 1 - c is not amplified. */
FACET_INLINE V_ X_POW5_Y_(V_ c)
{
    V_ yh = SUB_(C_(1.0f), c);
    V_ yl = SUB_(SUB_(C_(1.0f), yh), c);
    V_ y2 = MUL_(yh, yh);
    return MUL_(MUL_(y2, y2), FMA_(C_(5.0f), yl, yh));
}

/* f0 + (f90 - f0) (1 - c)^5 written as the convex combination
 * f0 (1 - y^5) + f90 y^5 (y = 1 - c): two non-negative terms, so f90 < f0
 * does not cancel, and 1 - y^5 = c (1 + y + ... + y^4) keeps its precision
 * at c -> 0.  c = 1 gives f0, c = 0 gives f90, exactly. */
FACET_INLINE V_ FACET_K(fresnel_schlick_f90)(V_ f0, V_ f90, V_ voh)
{
    V_ c = X_UNIT_(voh);
    return NAN0_(FMA_(X_UNIT_(f90), X_POW5_Y_(c), MUL_(X_UNIT_(f0), X_ONE_MINUS_POW5_(c))), f0, f90, voh);
}

/* Exact unpolarised Fresnel reflectance of a dielectric with relative index
 * eta = (1 + sqrt f0) / (1 - sqrt f0) (from f0 = ((eta - 1)/(eta + 1))^2):
 *   g = sqrt(eta^2 - 1 + c^2)
 *   F = (1/2) ((g - c)/(g + c))^2 (1 + (((g + c) c - 1) / ((g - c) c + 1))^2).
 * eta -> infinity as f0 -> 1, so everything is scaled by u = 1 - f0
 * = (1 - s)(1 + s), s = sqrt f0 (eta^2 - 1 = 4 s / (1 - s)^2):
 *   K = 4 s (1 + s)^2 = (eta^2 - 1) u^2,  G = g u = sqrt(K + (c u)^2),
 *   P = G + c u = (g + c) u,  G - c u = K / P  (no cancellation at f0 -> 0),
 *   r = (g - c)/(g + c) = K / P^2 in [0, 1],
 *   q = ((g + c) c - 1) / ((g - c) c + 1) = P (P c - u) / E,  E = K c + u P,
 *   F = r^2 (1 + q^2) / 2,
 * with one reciprocal R = 1 / (P^2 E): 1 / P^2 = E R, q = (P c - u) P^3 R,
 * and r^2 = K^2 (E R)^2 = 16 f0 (1 + s)^4 (E R)^2 (f0 itself, not the
 * rounded s^2; multiplied in that order, no intermediate over- or
 * underflows).
 * P^2 E >= 2^-109 unless f0 = 0 (then K = 0 and F = 0: eta = 1, no
 * interface) or f0 = 1 (F = 1 for every c, selected: eta = infinity, a
 * perfect mirror, where P^2 E = 256 c vanishes at c = 0); it is floored at
 * 2^-120 only to keep R finite at f0 = 0, c < 2^-40.  sqrt f0 is taken of
 * f0 2^64 (exact; normal even for denormal f0), floored at 2^-100 so that
 * f0 = 0 gives 0 * finite.  F(f0, 0) = 1 for f0 > 0, F(f0, 1) = f0.
 * F goes as P^-4 (r^2, r = K / P^2) and as R^2 (1 + q^2), so an error of
 * the estimates is multiplied by up to 4: both tiers refine fully
 * (RSQRT_X5_, RCP_X5_), as brdf_hammon does for its fifth power. */
FACET_INLINE V_ FACET_K(fresnel_cook_torrance)(V_ f0, V_ voh)
{
    V_ f = X_UNIT_(f0), c = X_UNIT_(voh);
    /* 2^64, 2^-100, 2^-32 (and below 2^-120, 2^-126) as exact decimals: hex
     * floats are C99 but not C++ before C++17 (the headers are C++11 too) */
    V_ fs = MUL_(f, C_(18446744073709551616.0f));
    V_ s = MUL_(MUL_(fs, RSQRT_X5_(MAX_(fs, C_(7.88860905221011805411728565283e-31f)))), C_(2.3283064365386962890625e-10f));
    V_ s1 = ADD_(C_(1.0f), s);
    V_ k = MUL_(MUL_(C_(4.0f), s), MUL_(s1, s1));
    V_ u = SUB_(C_(1.0f), f);
    V_ cu = MUL_(c, u);
    V_ g2 = FMA_(cu, cu, k);
    V_ p = ADD_(MUL_(g2, RSQRT_X5_(MAX_(g2, C_(7.88860905221011805411728565283e-31f)))), cu);
    V_ p2 = MUL_(p, p);
    V_ e = FMA_(k, c, MUL_(u, p));
    V_ rw = RCP_X5_(MAX_(MUL_(p2, e), C_(7.52316384526264005099991383822e-37f)));
    V_ er = MUL_(e, rw);                                   /* 1 / P^2 */
    V_ s2 = MUL_(s1, s1);
    V_ r2 = MUL_(MUL_(MUL_(MUL_(C_(16.0f), f), MUL_(s2, s2)), er), er);
    V_ q = MUL_(MUL_(FMA_(p, c, SUB_(f, C_(1.0f))), p), MUL_(p2, rw));
    V_ fr = MUL_(MUL_(C_(0.5f), r2), FMA_(q, q, C_(1.0f)));
    return NAN0_(FACET_OP(sel_lt)(f, C_(1.0f), MIN_(fr, C_(1.0f)), C_(1.0f)), f0, voh);
}

/* ---- Fresnel, spherical-Gaussian Schlick ----------------------------------- */

/* F = f0 + (1 - f0) 2^y, y = (-5.55473 c - 6.98316) c in [-12.54, 0]:
 * Schlick's (1 - c)^5 replaced by a spherical Gaussian (Karis).  One
 * 2^y; a rounding r of y costs |y| ln 2 r <= 8.7 r of the tail. */
FACET_INLINE V_ FACET_K(fresnel_schlick_sg)(V_ f0, V_ c)
{
    V_ f = X_UNIT_(f0), x = X_UNIT_(c);
    V_ y = MUL_(FMA_(C_(-5.55473f), x, C_(-6.98316f)), x);
    return NAN0_(FMA_(SUB_(C_(1.0f), f), X_EXP2_(y), f), f0, c);
}

/* ---- GGX D ------------------------------------------------------------ */

/* D = alpha^2 / (pi d^2), d = (1 - n^2) + (n alpha)^2 with 1 - n^2 as
 * (1-n)(1+n), so d keeps full relative precision at the peak (d -> alpha^2).
 * Written D = (1/pi) (alpha/d)^2: alpha/d <= 1/alpha_min, no overflow. */
/* (the samplers' pdfs use this core, without the NaN rule: they keep their
 * own input rules, facet.h) */
FACET_INLINE V_ FACET_K(x_ggx_d)(V_ noh, V_ alpha)
{
    V_ n = X_UNIT_(noh);
    V_ a = X_ALPHA_(alpha);
    V_ na = MUL_(n, a);
    V_ d = FMA_(SUB_(C_(1.0f), n), ADD_(C_(1.0f), n), MUL_(na, na));
    V_ k = DIV_(a, d);
    return MUL_(MUL_(k, k), C_(FACET_INV_PI_));
}

FACET_INLINE V_ FACET_K(ggx_d)(V_ noh, V_ alpha)
{
    return NAN0_(FACET_K(x_ggx_d)(noh, alpha), noh, alpha);
}

/* ---- D terms beyond GGX ---------------------------------------------------
 * Blinn-Phong, Beckmann, anisotropic GGX and GTR (facet.h has the
 * formulas and their derivation in short).  The exponential ones lose what
 * any float evaluation of an exponent loses: a relative error r in the
 * exponent y costs |y| ln 2 r in D, and |y| reaches about 120 before D
 * drops below the comparison floor 2^-100; so the exponent is formed with
 * as few roundings as the algebra allows (no cancellation, precise
 * reciprocals in both tiers), and D = c 2^y is scaled so that it stays
 * accurate into the denormals (X_EXP2_SCALED_). */

/* Blinn-Phong, normalised: D = (p + 2) / (2 pi) N.H^p, p = 2 / alpha^2 - 2,
 * i.e. D = N.H^p / (pi alpha^2).  p = 2 (1 - alpha)(1 + alpha) / alpha^2
 * (no cancellation near alpha = 1), y = p log2 N.H (log2 relative to
 * N.H - 1 near the peak, which is exact there), y >= -190 (D below
 * 2^-100 already).  N.H = 0: D = 0, except at p = 0 (alpha = 1: 1/pi). */
FACET_INLINE V_ FACET_K(blinn_phong_d)(V_ noh, V_ alpha)
{
    V_ n = X_UNIT_(noh);
    V_ a = X_ALPHA_(alpha);
    V_ ia2 = RCP_EXP_(MUL_(a, a));
    V_ p = MUL_(MUL_(SUB_(C_(1.0f), a), ADD_(C_(1.0f), a)), ADD_(ia2, ia2));
    V_ y = MAX_(MUL_(p, X_LOG2_X_(n)), C_(-190.0f));
    V_ d = X_EXP2_SCALED_(MUL_(ia2, C_(FACET_INV_PI_)), y);
    /* N.H = 0 tested as N.H 2^64 > 0: a port that flushes denormals (armv7
     * NEON) flushes this product as it flushed N.H for the log, so a
     * denormal N.H is 0 in both places (compares do not flush there) */
    V_ ns = MUL_(n, C_(1.84467441e+19f));
    return NAN0_(FACET_OP(sel_lt)(C_(0.0f), ns, d, FACET_OP(sel_lt)(C_(0.0f), p, C_(0.0f), d)), noh, alpha);
}

/* Beckmann: D = exp(-tan^2 / alpha^2) / (pi alpha^2 N.H^4)
 *   = (1/pi) (alpha r)^2 2^y,  r = 1 / (N.H alpha)^2,
 *   y = -log2(e) (1 - N.H)(1 + N.H) r  (= -log2(e) tan^2 / alpha^2).
 * Where y < -160, D < 2^-136 (facet.h), and 0 is returned: that also covers
 * N.H -> 0, where r and (alpha r)^2 overflow ((N.H alpha)^2 is floored at
 * 2^-120 so that r stays finite). */
FACET_INLINE V_ FACET_K(beckmann_d)(V_ noh, V_ alpha)
{
    V_ n = X_UNIT_(noh);
    V_ a = X_ALPHA_(alpha);
    V_ na = MUL_(n, a);
    V_ r = RCP_EXP_(MAX_(MUL_(na, na), C_(7.52316385e-37f)));
    V_ y = MUL_(MUL_(MUL_(SUB_(C_(1.0f), n), ADD_(C_(1.0f), n)), r), C_(-1.44269504f));
    V_ ar = MUL_(a, r);
    V_ d = X_EXP2_SCALED_(MUL_(MUL_(ar, ar), C_(FACET_INV_PI_)), MAX_(y, C_(-160.0f)));
    return NAN0_(FACET_OP(sel_lt)(y, C_(-160.0f), C_(0.0f), d), noh, alpha);
}

/* Anisotropic GGX: for a unit h with components (T.H, B.H, N.H) in the
 * tangent frame, D = 1 / (pi ax ay k^2), k = (T.H/ax)^2 + (B.H/ay)^2 + N.H^2.
 * Without dividing by the widths: K = ax^2 ay^2 k = T.H^2 ay^2 + B.H^2 ax^2 +
 * N.H^2 ax^2 ay^2, D = ax^3 ay^3 / (pi K^2): all terms >= 0, no 1 - N.H^2
 * (the peak is as accurate as the inputs).  k >= 1 for a unit h; K is
 * floored at ax^2 ay^2 / 2 (k at 1/2) for inputs no unit h has. */
FACET_INLINE V_ FACET_K(ggx_aniso_d)(V_ noh, V_ toh, V_ boh, V_ alpha_x, V_ alpha_y)
{
    V_ n = X_UNIT_(noh), t = X_LOV_(toh), b = X_LOV_(boh);
    V_ ax = X_ALPHA_(alpha_x), ay = X_ALPHA_(alpha_y);
    V_ ax2 = MUL_(ax, ax), ay2 = MUL_(ay, ay), a2 = MUL_(ax2, ay2);
    V_ K = FMA_(MUL_(t, t), ay2, FMA_(MUL_(b, b), ax2, MUL_(MUL_(n, n), a2)));
    V_ a3 = MUL_(a2, MUL_(ax, ay));
    K = MAX_(K, MUL_(C_(0.5f), a2));
    return NAN0_(DIV_(MUL_(a3, C_(FACET_INV_PI_)), MUL_(K, K)), noh, toh, boh, alpha_x, alpha_y);
}

/* GTR: D = c / d^gamma, d = 1 + (alpha^2 - 1) N.H^2 = (1 - N.H)(1 + N.H) +
 * (N.H alpha)^2 (as ggx_d), c = (gamma - 1)(alpha^2 - 1) / (pi (1 - alpha^(2 (1 - gamma)))).
 * With L = log2 alpha^2 and E(y) = (2^y - 1) / y: alpha^2 - 1 = L E(L),
 * 1 - alpha^(2 (1 - gamma)) = -(1 - gamma) L E((1 - gamma) L), so
 *   c = E(L) / (pi E((1 - gamma) L)),
 * which is the limit at gamma = 1 (E(0) = ln 2: GTR1) and at alpha = 1
 * (c = 1/pi) without a special case; gamma = 2 gives alpha^2 / pi (GGX),
 * gamma = 0 gives 1/pi.  d^-gamma = 2^(-gamma log2 d), up to 2^80. */
FACET_INLINE V_ FACET_K(gtr_d)(V_ noh, V_ alpha, V_ gamma)
{
    V_ n = X_UNIT_(noh);
    V_ a = X_ALPHA_(alpha);
    V_ g = CLAMP_(gamma, C_(0.0f), C_(4.0f));
    V_ na = MUL_(n, a);
    V_ d = FMA_(SUB_(C_(1.0f), n), ADD_(C_(1.0f), n), MUL_(na, na));
    V_ la = X_LOG2_X_(a);
    V_ L = ADD_(la, la);
    V_ c = MUL_(X_EXP2M1R_(L), RCP_EXP_(X_EXP2M1R_(MUL_(SUB_(C_(1.0f), g), L))));
    V_ y = MUL_(SUB_(C_(0.0f), g), X_LOG2_X_(d));
    return NAN0_(MUL_(MUL_(c, C_(FACET_INV_PI_)), X_EXP2_(y)), noh, alpha, gamma);
}

/* ---- Smith, exact ------------------------------------------------------ */

/* G1 = 2n / (n + sqrt(alpha^2 + (1 - alpha^2) n^2)) */
FACET_INLINE V_ FACET_K(smith_g1)(V_ nov, V_ alpha)
{
    V_ n = X_UNIT_(nov);
    V_ a = X_ALPHA_(alpha);
    V_ r = X_SQRT_(X_SMITH_W_(n, MUL_(a, a)));
    return NAN0_(MIN_(DIV_(ADD_(n, n), ADD_(n, r)), C_(1.0f)), nov, alpha);
}

/* nv sqrt(w(nl)) + nl sqrt(w(nv)): the height-correlated denominator,
 * G2 = 2 nl nv / den, Vis = G2 / (4 nl nv) = 0.5 / den. */
FACET_INLINE V_ X_G2_DEN_(V_ nl, V_ nv, V_ a)
{
    V_ a2 = MUL_(a, a);
    V_ rl = X_SQRT_(X_SMITH_W_(nl, a2));
    V_ rv = X_SQRT_(X_SMITH_W_(nv, a2));
    return ADD_(MUL_(nv, rl), MUL_(nl, rv)); /* not fused: symmetric in nl, nv to the bit */
}

FACET_INLINE V_ FACET_K(smith_g2)(V_ nol, V_ nov, V_ alpha)
{
    V_ nl = X_COS_(nol), nv = X_COS_(nov);
    V_ den = X_G2_DEN_(nl, nv, X_ALPHA_(alpha));
    V_ p = MUL_(nl, nv);
    return NAN0_(MIN_(DIV_(ADD_(p, p), den), C_(1.0f)), nol, nov, alpha);
}

FACET_INLINE V_ FACET_K(smith_vis)(V_ nol, V_ nov, V_ alpha)
{
    V_ nl = X_COS_(nol), nv = X_COS_(nov);
    V_ den = X_G2_DEN_(nl, nv, X_ALPHA_(alpha));
    return NAN0_(DIV_(C_(0.5f), den), nol, nov, alpha);
}

/* G1(L) G1(V) = 4 nl nv / ((nl + sqrt w(nl)) (nv + sqrt w(nv))): one reciprocal. */
FACET_INLINE V_ FACET_K(smith_g2_uncorrelated)(V_ nol, V_ nov, V_ alpha)
{
    V_ nl = X_COS_(nol), nv = X_COS_(nov);
    V_ a = X_ALPHA_(alpha);
    V_ a2 = MUL_(a, a);
    V_ dl = ADD_(nl, X_SQRT_(X_SMITH_W_(nl, a2)));
    V_ dv = ADD_(nv, X_SQRT_(X_SMITH_W_(nv, a2)));
    V_ p = MUL_(nl, nv);
    return NAN0_(MIN_(DIV_(MUL_(C_(4.0f), p), MUL_(dl, dv)), C_(1.0f)), nol, nov, alpha);
}

/* ---- Smith, Hammon's approximation ---------------------------------------- */

/* G1 ~ 2n / (n (2 - alpha) + alpha)  (= Schlick-GGX with k = alpha/2) */
FACET_INLINE V_ FACET_K(smith_g1_hammon)(V_ nov, V_ alpha)
{
    V_ n = X_UNIT_(nov);
    V_ a = X_ALPHA_(alpha);
    V_ den = FMA_(n, SUB_(C_(2.0f), a), a);
    return NAN0_(MIN_(DIV_(ADD_(n, n), den), C_(1.0f)), nov, alpha);
}

/* lerp(2 nl nv, nl + nv, alpha) written (1 - alpha) 2 nl nv + alpha (nl + nv):
 * both terms >= 0, so no cancellation; >= alpha_min * 2 FACET_COS_MIN. */
FACET_INLINE V_ X_HAMMON_DEN_(V_ nl, V_ nv, V_ a)
{
    V_ p = MUL_(nl, nv);
    return FMA_(a, ADD_(nl, nv), MUL_(SUB_(C_(1.0f), a), ADD_(p, p)));
}

FACET_INLINE V_ FACET_K(smith_g2_hammon)(V_ nol, V_ nov, V_ alpha)
{
    V_ nl = X_COS_(nol), nv = X_COS_(nov);
    V_ den = X_HAMMON_DEN_(nl, nv, X_ALPHA_(alpha));
    V_ p = MUL_(nl, nv);
    return NAN0_(MIN_(DIV_(ADD_(p, p), den), C_(1.0f)), nol, nov, alpha);
}

FACET_INLINE V_ FACET_K(smith_vis_hammon)(V_ nol, V_ nov, V_ alpha)
{
    V_ nl = X_COS_(nol), nv = X_COS_(nov);
    V_ den = X_HAMMON_DEN_(nl, nv, X_ALPHA_(alpha));
    return NAN0_(DIV_(C_(0.5f), den), nol, nov, alpha);
}

/* ---- Smith G1 for GTR (Dimov) ----------------------------------------------
 * The closed forms at gamma = 0 .. 4 in N.V (derivation: src/oracle/oracle.c and
 * facet.h), with s2 = 1 - n^2 = (1 - n)(1 + n) and W = sqrt(n^2 + alpha^2 s2)
 * (smith_g1's radicand), then the monotone cubic (Fritsch-Carlson) in gamma
 * through the five values.  The interpolation works on differences of the
 * five values (its slopes), which amplify their errors: every reciprocal
 * here is the precise one in both tiers (with the 14-bit estimates of
 * avx512 at their architectural bound the fast tier reached 2^-11.8). */

/* R(u) = ln(1 + u) / u / ln 2 for u >= 0 (1/ln 2 at 0): below u = 0.41 as
 * Q(s^2) / (2 + u) with s = u / (2 + u) (x_log2's polynomial: ln(1 + u) =
 * 2 atanh(s)), no cancellation at small u; above, log2(1 + u) / u. */
FACET_INLINE V_ X_LN1PR_(V_ u)
{
    V_ r2 = RCP_EXP_(ADD_(C_(2.0f), u));
    V_ sm = MUL_(u, r2), t = MUL_(sm, sm);
    V_ q = FMA_(t, C_(4.317176938e-01f), C_(5.767151713e-01f));
    V_ big;
    q = FMA_(q, t, C_(9.617988467e-01f));
    q = FMA_(q, t, C_(2.885390043e+00f));
    big = MUL_(X_LOG2_X_(ADD_(C_(1.0f), u)), RCP_EXP_(MAX_(u, C_(0.25f))));
    return FACET_OP(sel_lt)(u, C_(0.41f), MUL_(q, r2), big);
}

/* Fritsch-Carlson end slope: (3 d0 - d1) / 2, 0 against d0, at most 3 d0
 * where the data turn */
FACET_INLINE V_ X_PCHIP_END_(V_ d0, V_ d1)
{
    V_ m = MUL_(C_(0.5f), FNMA_(C_(1.0f), d1, MUL_(C_(3.0f), d0)));
    V_ lim = FACET_OP(sel_lt)(C_(0.0f), MUL_(d0, d1), m,
                              FACET_OP(sel_lt)(MUL_(C_(3.0f), MAX_(d0, SUB_(C_(0.0f), d0))),
                                               MAX_(m, SUB_(C_(0.0f), m)), MUL_(C_(3.0f), d0), m));
    return FACET_OP(sel_lt)(C_(0.0f), MUL_(m, d0), lim, C_(0.0f));
}

/* interior slope: the harmonic mean 2 a b / (a + b) of the secants, 0 at a turn */
FACET_INLINE V_ X_PCHIP_MID_(V_ a, V_ b)
{
    V_ p = MUL_(a, b);
    V_ h = MUL_(ADD_(p, p), RCP_EXP_(FACET_OP(sel_lt)(C_(0.0f), p, ADD_(a, b), C_(1.0f))));
    return FACET_OP(sel_lt)(C_(0.0f), p, h, C_(0.0f));
}

FACET_INLINE V_ FACET_K(smith_g1_gtr)(V_ nov, V_ alpha, V_ gamma)
{
    V_ n = X_UNIT_(nov);
    V_ a = X_ALPHA_(alpha);
    V_ g = CLAMP_(gamma, C_(0.0f), C_(4.0f));
    V_ a2 = MUL_(a, a);
    V_ s2 = MUL_(SUB_(C_(1.0f), n), ADD_(C_(1.0f), n));
    V_ w2 = X_SMITH_W_(n, a2);
    V_ W = SQRT_X5_(w2); /* cubed in G^4: the precise root in both tiers */
    V_ n2 = ADD_(n, n), nW = ADD_(n, W), b = ADD_(C_(1.0f), a2);
    V_ y0, y1, y2, y3, y4, la, e, den1, u, W3, num4, den4, k4;
    V_ d0, d1, d2, d3, m0, m1, m2, m3, m4, yj, yk, mj, mk, t, t1, j1, j2, j3, S, ex, sc;
    /* gamma = 0: 2n / (1 + n) */
    y0 = MUL_(n2, RCP_EXP_(ADD_(C_(1.0f), n)));
    /* gamma = 1: n / (n + e s2 (W + n (1 - R(u))) / ((W + 1)(n + W))),
     * e = (alpha^2 - 1) / ln alpha^2 = E(L) / ln 2, L = log2 alpha^2 */
    la = X_LOG2_X_(a);
    e = MUL_(X_EXP2M1R_(ADD_(la, la)), C_(1.44269504f));
    den1 = RCP_EXP_(MUL_(ADD_(W, C_(1.0f)), nW));
    /* (1 - alpha^2) s2 / ((W + 1)(n + W)) */
    u = MUL_(MUL_(SUB_(C_(1.0f), a), ADD_(C_(1.0f), a)), MUL_(s2, den1));
    y1 = FNMA_(MUL_(X_LN1PR_(u), C_(0.693147181f)), n, ADD_(W, n)); /* W + n (1 - R) */
    y1 = MUL_(MUL_(e, s2), MUL_(y1, den1));
    y1 = MUL_(n, RCP_EXP_(ADD_(n, y1)));
    /* gamma = 2: GGX, 2n / (n + W) */
    y2 = DIV_X5_(n2, nW); /* smith_g1's quotient, to the bit in the precise tier */
    /* gamma = 3: 4 (1 + alpha^2) n W / (alpha^2 (3 alpha^2 + 1) s2 + 2 (1 + alpha^2) n (n + W)) */
    /* n2 multiplies last in y3 and y4: n W or n W^3 underflows for a
     * denormal N.V where the quotient does not */
    y3 = MUL_(MUL_(C_(2.0f), b), W);
    y3 = MUL_(n2, MUL_(y3, RCP_EXP_(FMA_(MUL_(a2, FMA_(C_(3.0f), a2, C_(1.0f))), s2, MUL_(b, MUL_(n2, nW))))));
    /* gamma = 4: 2 n W^3 / (n (W^3 + n^3) + k4 (alpha^2 P5 s2^2 + 4 n^2 s2 P2)),
     * k4 = 3 alpha^2 / K, K = 8 (alpha^4 + alpha^2 + 1),
     * P5 = 5 alpha^4 + 2 alpha^2 + 1, P2 = 2 alpha^4 + alpha^2 + 1 */
    W3 = MUL_(MUL_(W, W), W);
    k4 = MUL_(MUL_(C_(0.375f), a2), RCP_EXP_(FMA_(a2, b, C_(1.0f))));
    num4 = FMA_(MUL_(a2, FMA_(a2, FMA_(C_(5.0f), a2, C_(2.0f)), C_(1.0f))), s2,
                MUL_(MUL_(C_(4.0f), MUL_(n, n)), FMA_(a2, FMA_(C_(2.0f), a2, C_(1.0f)), C_(1.0f))));
    den4 = FMA_(k4, MUL_(num4, s2), MUL_(n, FMA_(MUL_(n, n), n, W3)));
    y4 = MUL_(n2, MUL_(W3, RCP_EXP_(den4)));
    /* the monotone cubic in gamma.  Its slopes multiply differences of the
     * y (d0 d1 ...), which underflow for a tiny N.V (the y go as N.V):
     * they are formed on the differences scaled by sc = 2^-floor(log2 N.V)
     * (exact), and the slope term is scaled back by 1 / sc. */
    ex = FACET_OP(getexp)(MAX_(n, C_(1.17549435082228750796873653722e-38f)));
    sc = FACET_OP(exp2i)(SUB_(C_(0.0f), ex));
    d0 = MUL_(SUB_(y1, y0), sc);
    d1 = MUL_(SUB_(y2, y1), sc);
    d2 = MUL_(SUB_(y3, y2), sc);
    d3 = MUL_(SUB_(y4, y3), sc);
    m0 = X_PCHIP_END_(d0, d1);
    m1 = X_PCHIP_MID_(d0, d1);
    m2 = X_PCHIP_MID_(d1, d2);
    m3 = X_PCHIP_MID_(d2, d3);
    m4 = X_PCHIP_END_(d3, d2);
    j1 = C_(1.0f);
    j2 = C_(2.0f);
    j3 = C_(3.0f);
    yj = FACET_OP(sel_lt)(g, j1, y0, FACET_OP(sel_lt)(g, j2, y1, FACET_OP(sel_lt)(g, j3, y2, y3)));
    yk = FACET_OP(sel_lt)(g, j1, y1, FACET_OP(sel_lt)(g, j2, y2, FACET_OP(sel_lt)(g, j3, y3, y4)));
    mj = FACET_OP(sel_lt)(g, j1, m0, FACET_OP(sel_lt)(g, j2, m1, FACET_OP(sel_lt)(g, j3, m2, m3)));
    mk = FACET_OP(sel_lt)(g, j1, m1, FACET_OP(sel_lt)(g, j2, m2, FACET_OP(sel_lt)(g, j3, m3, m4)));
    t = SUB_(g, FACET_OP(sel_lt)(g, j1, C_(0.0f), FACET_OP(sel_lt)(g, j2, j1, FACET_OP(sel_lt)(g, j3, j2, j3))));
    t1 = SUB_(C_(1.0f), t);
    /* (1 + 2t)(1 - t)^2 yj + t^2 (3 - 2t) yk + t (1 - t) ((1 - t) mj - t mk) */
    S = MUL_(MUL_(FMA_(C_(2.0f), t, C_(1.0f)), MUL_(t1, t1)), yj);
    S = FMA_(MUL_(MUL_(t, t), FNMA_(C_(2.0f), t, C_(3.0f))), yk, S);
    S = FMA_(MUL_(t, t1), MUL_(FNMA_(t, mk, MUL_(t1, mj)), FACET_OP(exp2i)(ex)), S);
    return NAN0_(CLAMP_(S, C_(0.0f), C_(1.0f)), nov, alpha, gamma);
}

/* ---- shadowing and visibility: the rest of the menu ------------------------ */

/* Implicit G = N.L N.V: one rounding. */
FACET_INLINE V_ FACET_K(g_implicit)(V_ nol, V_ nov)
{
    return NAN0_(MUL_(X_UNIT_(nol), X_UNIT_(nov)), nol, nov);
}

/* Neumann G = N.L N.V / max(N.L, N.V), which is min(N.L, N.V) exactly
 * (and 0, not 0/0, at N.L = N.V = 0). */
FACET_INLINE V_ FACET_K(g_neumann)(V_ nol, V_ nov)
{
    return NAN0_(MIN_(X_UNIT_(nol), X_UNIT_(nov)), nol, nov);
}

/* Cook-Torrance G = min(1, 2 N.H N.V / V.H, 2 N.H N.L / V.H)
 *                 = min(1, g / V.H), g = 2 N.H min(N.L, N.V):
 * where g >= V.H (also V.H = 0) the result is 1 and no reciprocal is used;
 * below, V.H > g >= 0 and the quotient is < 1.  N.H and V.H enter only as
 * their ratio, so where either is below 2^-40 both are scaled by 2^60
 * (exactly; else 2 N.H min(N.L, N.V) would lose its bits as a denormal):
 * the reciprocal never sees a denormal (scaled, V.H >= 2^-89 or 0; the
 * floor 2^-100 only keeps 1/0 out of the unselected side), and g keeps its
 * precision. */
FACET_INLINE V_ FACET_K(g_cook_torrance)(V_ nol, V_ nov, V_ noh, V_ voh)
{
    V_ m = MIN_(X_COS_(nol), X_COS_(nov));
    V_ nh = X_UNIT_(noh), vh = X_UNIT_(voh);
    V_ sc = FACET_OP(sel_lt)(MIN_(nh, vh), C_(9.09494702e-13f), C_(1.15292150e18f), C_(1.0f));
    V_ g, v;
    nh = MUL_(nh, sc);
    v = MUL_(vh, sc);
    g = MUL_(ADD_(nh, nh), m);
    return NAN0_(FACET_OP(sel_lt)(g, v, DIV_(g, MAX_(v, C_(7.88860905e-31f))), C_(1.0f)),
                 nol, nov, noh, voh);
}

/* Kelemen G = N.L N.V / (V.H)^2, taken as min(1, ...): for real vectors
 * N.L N.V <= (V.H)^2 (= (1 + L.V)/2 >= (1 + cos(theta_l + theta_v))/2 >= N.L N.V),
 * so the cap only acts on triples no pair of vectors forms (e.g. V.H = 0).
 * The quotient is taken only where (V.H)^2 > N.L N.V >= 2^-40, so the
 * floor 2^-60 under the reciprocal's argument never changes a result. */
FACET_INLINE V_ FACET_K(g_kelemen)(V_ nol, V_ nov, V_ voh)
{
    V_ p = MUL_(X_COS_(nol), X_COS_(nov));
    V_ vh = X_UNIT_(voh);
    V_ q = MUL_(vh, vh);
    return NAN0_(FACET_OP(sel_lt)(p, q, DIV_(p, MAX_(q, C_(8.67361738e-19f))), C_(1.0f)), nol, nov, voh);
}

/* Walter's rational fit of Beckmann's Smith G1, c = N.V / (alpha sqrt(1 - N.V^2)):
 *   G1 = (3.535 c + 2.181 c^2) / (1 + 2.276 c + 2.577 c^2) for c < 1.6, else 1,
 * capped at 1 (the rational exceeds 1 by up to 6.1e-5 (at c = 1.589) for c in (1.548,
 * 1.631); with the cap the two pieces meet continuously).  Multiplied
 * through by (alpha s)^2, s = sqrt((1 - n)(1 + n)), p = alpha s, q = n:
 *   G1 = q (3.535 p + 2.181 q) / (p (p + 2.276 q) + 2.577 q^2),  q < 1.6 p,
 * no infinity at n = 1 (p = 0 selects 1) nor at n = 0 (q = 0 gives 0), and
 * every term >= 0.  The radicand is floored at 2^-30 (only n = 1 is below). */
FACET_INLINE V_ FACET_K(smith_g1_beckmann)(V_ nov, V_ alpha)
{
    V_ q = X_UNIT_(nov);
    V_ a = X_ALPHA_(alpha);
    V_ w = MAX_(MUL_(SUB_(C_(1.0f), q), ADD_(C_(1.0f), q)), C_(9.31322575e-10f));
    V_ p = MUL_(a, X_SQRT_(w));
    V_ num = MUL_(q, FMA_(C_(3.535f), p, MUL_(C_(2.181f), q)));
    V_ den = FMA_(p, FMA_(C_(2.276f), q, p), MUL_(C_(2.577f), MUL_(q, q)));
    V_ g = MIN_(DIV_(num, den), C_(1.0f));
    return NAN0_(FACET_OP(sel_lt)(q, MUL_(C_(1.6f), p), g, C_(1.0f)), nov, alpha);
}

/* Schlick's G1 for Beckmann: N.V / (N.V (1 - k) + k), k = alpha sqrt(2/pi)
 * (<= 0.798, so 1 - k > 0 and every term is >= 0). */
FACET_INLINE V_ FACET_K(smith_g1_schlick_beckmann)(V_ nov, V_ alpha)
{
    V_ n = X_UNIT_(nov);
    V_ k = MUL_(X_ALPHA_(alpha), C_(0.797884561f));
    V_ den = FMA_(n, SUB_(C_(1.0f), k), k);
    return NAN0_(MIN_(DIV_(n, den), C_(1.0f)), nov, alpha);
}

/* The joint approximation engines ship (Karis's UE4 form):
 *   0.5 / (N.L (N.V (1 - a) + a) + N.V (N.L (1 - a) + a))
 * = 0.5 / ((1 - a) 2 N.L N.V + a (N.L + N.V)), Hammon's visibility: the same
 * function, here in that form (terms >= 0; the two products are added, not
 * fused, so swapping N.L and N.V gives the same bits). */
FACET_INLINE V_ FACET_K(smith_vis_joint_approx)(V_ nol, V_ nov, V_ alpha)
{
    V_ nl = X_COS_(nol), nv = X_COS_(nov);
    V_ a = X_ALPHA_(alpha);
    V_ b = SUB_(C_(1.0f), a);
    V_ den = ADD_(MUL_(nl, FMA_(nv, b, a)), MUL_(nv, FMA_(nl, b, a)));
    return NAN0_(DIV_(C_(0.5f), den), nol, nov, alpha);
}

/* The fitted visibility (bench/fit/fit_vis.c): exact correlated Smith is
 * 0.5 / (N.V r(N.L) + N.L r(N.V)), r(x) = sqrt(a^2 + (1 - a^2) x^2) = |(a, s x)|,
 * s = sqrt(1 - a^2); r is replaced by the largest of three lines in a and
 * t = x sigma(a), sigma(a) = 1 + a (c1 + c2 a) standing in for s:
 *   R(x) = max(K1 a, K2 a + K3 t, K4 a + K5 t)  (= 2 r~: the 0.5 folded in)
 *   Vis ~ 1 / (N.V R(N.L) + N.L R(N.V)).
 * Every term >= 0; the products are added unfused (symmetric to the bit). */
#include "facet/detail/vis_fit.h"
FACET_INLINE V_ FACET_K(x_vis_fit_r)(V_ x, V_ ka1, V_ ka2, V_ ka4, V_ s3, V_ s5)
{
    return MAX_(ka1, MAX_(FMA_(s3, x, ka2), FMA_(s5, x, ka4)));
}

FACET_INLINE V_ FACET_K(smith_vis_fit)(V_ nol, V_ nov, V_ alpha)
{
    V_ nl = X_COS_(nol), nv = X_COS_(nov);
    V_ a = X_ALPHA_(alpha);
    V_ sg = FMA_(a, FMA_(C_(FACET_VIS_FIT_C2), a, C_(FACET_VIS_FIT_C1)), C_(1.0f));
    V_ ka1 = MUL_(C_(FACET_VIS_FIT_K1), a), ka2 = MUL_(C_(FACET_VIS_FIT_K2), a);
    V_ ka4 = MUL_(C_(FACET_VIS_FIT_K4), a);
    V_ s3 = MUL_(C_(FACET_VIS_FIT_K3), sg), s5 = MUL_(C_(FACET_VIS_FIT_K5), sg);
    V_ rl = FACET_K(x_vis_fit_r)(nl, ka1, ka2, ka4, s3, s5);
    V_ rv = FACET_K(x_vis_fit_r)(nv, ka1, ka2, ka4, s3, s5);
    return NAN0_(DIV_(C_(1.0f), ADD_(MUL_(nv, rl), MUL_(nl, rv))), nol, nov, alpha);
}

/* ---- Hammon's GGX diffuse --------------------------------------------------- */

/* Hammon's diffuse from the pieces the caller shares (h = 0.5 / N.H):
 *   facing = 0.5 + 0.5 L.V = t/2, so facing (0.9 - 0.4 facing) = t (0.45 - 0.1 t)
 *   rough  = t (0.45 - 0.1 t) (1 + h)
 *   smooth = 1.05 (1 - (1-nl)^5) (1 - (1-nv)^5) = 1.05 nl nv Q(nl) Q(nv)
 *   single = ((1 - alpha) smooth + alpha rough) / pi,  multi = 0.1159 alpha
 *   diffuse = albedo (single + albedo multi)
 * the 1/pi folded into the constants (the caller passes smooth / pi). */
#define FACET_DIF_K_ 0.334225380f /* 1.05 / pi */
FACET_INLINE V_ X_DIFFUSE_SINGLE_(V_ at, V_ tau, V_ h, V_ a, V_ smooth, V_ *multi)
{
    /* alpha rough = ar (1 + h), ar = (alpha t) (0.45 - 0.1 t) / pi
     * = (alpha tau) (0.9 - 0.4 tau) / pi with tau = t/2 (alpha tau the
     * caller's, brdf_hammon's D numerator too; the constants are the t form's
     * times 2 and 4, exact): h, the last quotient to arrive, enters by one
     * fma at the end of the chain */
    V_ ar = MUL_(at, FNMA_(C_(0.127323955f), tau, C_(0.286478907f)));
    /* 1 - alpha is exact for alpha >= 1/2 */
    *multi = MUL_(C_(0.1159f), a);
    return FMA_(ar, h, FMA_(SUB_(C_(1.0f), a), smooth, ar));
}

/* the diffuse, smooth from N.L and N.V: the product of the two Q is formed
 * first, so that swapping N.L and N.V gives the same bits */
FACET_INLINE V_ X_DIFFUSE_PI_(V_ nl, V_ nv, V_ tau, V_ h, V_ a, V_ alb)
{
    V_ smooth = MUL_(C_(FACET_DIF_K_), MUL_(MUL_(nl, nv), MUL_(X_POW5_Q_(nl, 1.0f), X_POW5_Q_(nv, 1.0f))));
    V_ multi, single = X_DIFFUSE_SINGLE_(MUL_(a, tau), tau, h, a, smooth, &multi);
    return MUL_(alb, FMA_(alb, multi, single));
}

/* h = 0.5 / N.H = L.H / s (N.H = s / (2 L.H)), from L.H = sqrt(tau),
 * tau = t/2 = (1 + L.V)/2: one quotient and the root, no reciprocal of
 * N.H.  tau >= s^2/4 caps N.H at 1, so h >= 1/2 but for roundings: the
 * precise tier floors it there, the fast tier takes the rounding's worth. */
FACET_INLINE V_ X_HALF_INV_NH_(V_ lh, V_ s)
{
    V_ h = DIV_(lh, s);
#if FAST_
    return h;
#else
    return MAX_(h, C_(0.5f));
#endif
}

FACET_INLINE V_ FACET_K(diffuse_hammon)(V_ nol, V_ nov, V_ lov, V_ alpha, V_ albedo)
{
    V_ nl = X_COS_(nol), nv = X_COS_(nov);
    V_ s = ADD_(nl, nv), hs = MUL_(C_(0.5f), s);
    /* tau = t/2 = max((1 + L.V)/2, s^2/4), exactly the halves of t's roundings */
    V_ tau = MAX_(FMA_(C_(0.5f), X_LOV_(lov), C_(0.5f)), MUL_(hs, hs));
    V_ d = X_DIFFUSE_PI_(nl, nv, tau, X_HALF_INV_NH_(SQRT_(tau), s), X_ALPHA_(alpha), X_UNIT_(albedo));
    return NAN0_(d, nol, nov, lov, alpha, albedo);
}

/* ---- more diffuse models: Burley (Disney), Oren-Nayar, Hammon's variants ---- */

/* Burley's diffuse ("Disney"), a BRDF value:
 *   f_d90 = 0.5 + 2 r L.H^2, r = sqrt(alpha) (Disney's roughness slider,
 *   whose square is the GGX alpha)
 *   result = albedo / pi (1 + (f_d90 - 1)(1 - N.L)^5) (1 + (f_d90 - 1)(1 - N.V)^5)
 * Each factor is >= 1/2 (f_d90 - 1 >= -1/2), so nothing cancels; the two
 * factors are multiplied last, so swapping N.L and N.V gives the same bits. */
FACET_INLINE V_ FACET_K(diffuse_burley)(V_ nol, V_ nov, V_ loh, V_ alpha, V_ albedo)
{
    V_ nl = X_COS_(nol), nv = X_COS_(nov), lh = X_UNIT_(loh), a = X_ALPHA_(alpha);
    V_ r = SQRT_(a);
    V_ k = FMA_(ADD_(r, r), MUL_(lh, lh), C_(-0.5f)); /* f_d90 - 1 */
    V_ fl = FMA_(k, X_POW5_Y_(nl), C_(1.0f));
    V_ fv = FMA_(k, X_POW5_Y_(nv), C_(1.0f));
    return NAN0_(MUL_(MUL_(X_UNIT_(albedo), MUL_(fl, fv)), C_(FACET_INV_PI_)), nol, nov, loh, alpha, albedo);
}

/* Oren-Nayar's qualitative model with sigma = alpha / 2 (radians), as in
 * Hammon's comparison:
 *   A = 1 - 0.5 sigma^2 / (sigma^2 + 0.33),  B = 0.45 sigma^2 / (sigma^2 + 0.09)
 *   result = albedo / pi (A + B max(0, cos(phi_l - phi_v)) sin(theta_max) tan(theta_min))
 * without angles: with L.V = N.L N.V + sin(theta_l) sin(theta_v) cos(phi_l - phi_v),
 *   cos(phi_l - phi_v) sin(theta_max) tan(theta_min)
 *     = cos(phi) sin(theta_l) sin(theta_v) / cos(theta_min)
 *     = (L.V - N.L N.V) / max(N.L, N.V),
 * since theta_min has the larger cosine.  So, with q = sigma^2 = alpha^2 / 4,
 *   pi result / albedo = A + B max(0, L.V - N.L N.V) / m,  m = max(N.L, N.V)
 *     = ((0.5 q + 0.33)(q + 0.09) m + 0.45 q (q + 0.33) x) / ((q + 0.33)(q + 0.09) m),
 * x = max(0, L.V - N.L N.V): positive terms, one reciprocal.  Inconsistent
 * triples take the identity as it stands (x grows with L.V).  Largest at
 * N.L = N.V = FACET_COS_MIN, L.V = 1: (A + B / FACET_COS_MIN) / pi. */
FACET_INLINE V_ FACET_K(diffuse_oren_nayar)(V_ nol, V_ nov, V_ lov, V_ alpha, V_ albedo)
{
    V_ nl = X_COS_(nol), nv = X_COS_(nov), a = X_ALPHA_(alpha);
    V_ q = MUL_(MUL_(C_(0.25f), a), a);
    V_ m = MAX_(nl, nv);
    V_ x = MAX_(FNMA_(nl, nv, X_LOV_(lov)), C_(0.0f));
    V_ d1 = ADD_(q, C_(0.33f)), d2 = ADD_(q, C_(0.09f));
    V_ na = MUL_(MUL_(FMA_(C_(0.5f), q, C_(0.33f)), d2), m);
    V_ num = FMA_(MUL_(MUL_(C_(0.45f), q), d1), x, na);
    V_ den = MUL_(MUL_(d1, d2), m);
    return NAN0_(MUL_(MUL_(X_UNIT_(albedo), DIV_(num, den)), C_(FACET_INV_PI_)), nol, nov, lov, alpha,
                 albedo);
}

#define X_DIFFUSE_VARIANT_ FACET_K(x_diffuse_variant)

/* Hammon's diffuse with another smooth term S (times 1 - alpha here):
 *   pi result = albedo ((1 - alpha) S + alpha rough + albedo 0.1159 pi alpha),
 * rough, tau = t/2 and 0.5 / N.H as diffuse_hammon (the raised t, 1 sqrt,
 * 1 quotient); t (0.45 - 0.1 t) = tau (0.9 - 0.4 tau). */
FACET_INLINE V_ X_DIFFUSE_VARIANT_(V_ nl, V_ nv, V_ lov, V_ a, V_ albedo, V_ smooth)
{
    V_ s = ADD_(nl, nv), hs = MUL_(C_(0.5f), s);
    V_ tau = MAX_(FMA_(C_(0.5f), X_LOV_(lov), C_(0.5f)), MUL_(hs, hs));
    V_ h = X_HALF_INV_NH_(SQRT_(tau), s);
    V_ rough = MUL_(MUL_(tau, FNMA_(C_(0.4f), tau, C_(0.9f))), ADD_(C_(1.0f), h));
    V_ single = FMA_(a, rough, MUL_(SUB_(C_(1.0f), a), smooth));
    V_ alb = X_UNIT_(albedo);
    V_ d = MUL_(alb, FMA_(alb, MUL_(C_(0.364110589f), a), single)); /* 0.1159 pi */
    return MUL_(d, C_(FACET_INV_PI_));
}

/* Hammon's hybrid: smooth = Disney's with f_d90 = 1/2,
 *   (1 - (1 - N.L)^5 / 2)(1 - (1 - N.V)^5 / 2)  (each factor >= 1/2),
 * so at alpha = 0 it is Burley's diffuse at roughness 0. */
FACET_INLINE V_ FACET_K(diffuse_hammon_hybrid)(V_ nol, V_ nov, V_ lov, V_ alpha, V_ albedo)
{
    V_ nl = X_COS_(nol), nv = X_COS_(nov);
    V_ fl = FNMA_(C_(0.5f), X_POW5_Y_(nl), C_(1.0f));
    V_ fv = FNMA_(C_(0.5f), X_POW5_Y_(nv), C_(1.0f));
    return NAN0_(X_DIFFUSE_VARIANT_(nl, nv, lov, X_ALPHA_(alpha), albedo, MUL_(fl, fv)), nol, nov, lov, alpha,
                 albedo);
}

/* Hammon's cheaper variant: smooth = 1 (Lambert). */
FACET_INLINE V_ FACET_K(diffuse_hammon_cheap)(V_ nol, V_ nov, V_ lov, V_ alpha, V_ albedo)
{
    return NAN0_(X_DIFFUSE_VARIANT_(X_COS_(nol), X_COS_(nov), lov, X_ALPHA_(alpha), albedo, C_(1.0f)), nol, nov,
                 lov, alpha, albedo);
}

#undef X_DIFFUSE_VARIANT_
#undef X_POW5_Y_

/* ---- the whole model ------------------------------------------------------ */

/* D(N.H) Vis_hammon F(f0, L.H) + diffuse_hammon, from the three dots.
 *
 * D is ill-conditioned in N.H at the peak for small alpha (d -> alpha^2), so
 * N.H is never formed for it.  With s = N.L + N.V and t = 1 + L.V:
 *   1 - N.H^2 = num / 2t,  num = 2t - s^2  (= |tangential part of L+V|^2)
 *   d = (1 - N.H^2) + alpha^2 N.H^2 = e / 2t,  e = num + alpha^2 s^2
 *   D = alpha^2 / (pi d^2) = (4/pi) (alpha t / e)^2.
 * num cancels at the peak, so it is formed exactly, in quarter units
 * (X_BRDF_PEAK_: s and tau = t/2 as unevaluated sums, Fast2Sum, and one
 * fnma exact before its rounding).  Likewise 1 - L.H, which F raises to
 * the fifth power, is formed without cancellation as
 * (1 - L.H^2) / (1 + L.H) = (1 - tau) / (1 + L.H), L.H = sqrt(tau).
 * With Vis = 0.5/m (m = Hammon's lerp), mh = m/2:
 *   pi D Vis = 2 (alpha t)^2 / (e^2 m) = (u mh) u / 4,
 *   u = alpha tau / (e/4 mh) = 2 alpha t / (e mh),
 * ordered so that no intermediate overflows at the grazing corner.
 * Quotients: alpha tau / (e/4 mh), (1 - tau) / (1 + L.H), L.H / s
 * (= 0.5 / N.H, for the diffuse), one square root: the port's div and sqrt
 * (a divide/sqrt unit where it runs beside the FMA pipes, else a
 * reciprocal estimate and steps).  The fast tier takes its cheaper quotient
 * for the first and the last (errors 2x and 1x its estimate's), the
 * precise one for 1 - L.H (times 5 in F), and drops the cap of 0.5 / N.H
 * at 0.5 (a rounding's worth). */
/* What brdf_hammon computes before f0 and albedo enter: F = f0 + (1 - f0) y^5
 * = y^5 + f0 (1 - y^5) (two non-negative terms), brdf = D Vis F + albedo
 * (single + albedo multi).  No intermediate is subnormal for an input in
 * the domain: y^5 reaches 2^-130 at L.V = 1 - 2^-24, so y is carried as
 * y5s = (2^16 y)^5 = 2^80 y^5 in [2^-50, 2^80] (or 0; the 2^-16 in the
 * quotient's divisor, exact) and D Vis as dv2 = 2^-80 D Vis (in the 1/pi,
 * exact; >= 2^-106, as u >= 2^-11): F D Vis = (y5s + f0 (2^80 - y5s)) dv2,
 * the same roundings as unscaled.  A subnormal result or operand costs
 * Intel cores a microcode assist per instruction: 1% of the benchmark's
 * samples at that L.V made the AVX-512 loop 1.45x slower on this tree's
 * Xeon.  The RGB form shares
 * it across channels; per channel the same operations run in the same order,
 * so each channel equals brdf_hammon to the bit. */
/* The parts are out-parameters, not a struct: RVV's vector types are
 * sizeless (no struct members, no arrays), and one body serves every port. */
/* The exact peak, in quarter units: e/4 = max(num/4, 0) + alpha^2 s^2/4 with
 * num/4 = tau - (s/2)^2 (tau = t/2) formed without cancellation, and what
 * it leaves the rest: the ordered pair big >= small, s rounded (sh) and
 * halved (hs, exact), tau (raised to (s/2)^2 where the triple is
 * inconsistent) and 1 - tau = min((1 - L.V)/2, 1 - (s/2)^2), each side
 * without cancellation.  With s = sh + sl and tau = th + tl (Fast2Sum, both
 * exact; th = (1 + L.V)/2 rounded, the half of 1 + L.V's rounding):
 *   num/4 = (th - hs^2) + (tl - hs sl) - sl^2/4,
 * the first exact before its one rounding and small near the peak (the
 * port's sqr_sub: one fnma, or without FMA the exact error of hs^2 and
 * Sterbenz), the second of the size of the roundings (sl^2/4 < 2^-50 s^2
 * dropped): a few 2^-24 of e, where the squared sum and its exact error
 * (sqr_err) in full units took five operations more.  Its own function so that tests/f32/test_op_counts.c
 * can count it apart (the "peak" of the budget, with X_ONE_MINUS_LH_
 * below). */
FACET_INLINE V_ X_BRDF_PEAK_(V_ nl, V_ nv, V_ lv, V_ a2, V_ *big_, V_ *small_, V_ *sh_, V_ *hs_, V_ *tau_,
                             V_ *w_)
{
    V_ big = MAX_(nl, nv), small = MIN_(nl, nv);
    V_ sh = ADD_(nl, nv); /* = big + small, without waiting for them */
    V_ sl = SUB_(small, SUB_(sh, big));
    V_ hs = MUL_(C_(0.5f), sh);
    V_ th = FMA_(C_(0.5f), lv, C_(0.5f));
    /* 0.5 - th is exact (Sterbenz for th >= 1/4, else th itself is exact) */
    V_ tl = FMA_(C_(0.5f), lv, SUB_(C_(0.5f), th));
    V_ q = MUL_(hs, hs);
    V_ numq = ADD_(FACET_OP(sqr_sub)(hs, th), FNMA_(hs, sl, tl));
    *big_ = big;
    *small_ = small;
    *sh_ = sh;
    *hs_ = hs;
    *tau_ = MAX_(th, q);
    *w_ = MIN_(FNMA_(C_(0.5f), lv, C_(0.5f)), FNMA_(hs, sl, FACET_OP(sqr_sub)(hs, C_(1.0f))));
    return FMA_(a2, q, MAX_(numq, C_(0.0f)));
}

/* 1 - L.H = (1 - tau) / (1 + L.H), from w = 1 - tau and L.H = sqrt(tau):
 * the precise quotient in both tiers (F takes its fifth power); 2^16 times
 * it, the divisor times 2^-16 (exact) */
FACET_INLINE V_ X_ONE_MINUS_LH_(V_ w, V_ lh)
{
    return DIV_X5_(w, FMA_(C_(1.52587891e-05f), lh, C_(1.52587891e-05f)));
}

FACET_INLINE void X_BRDF_GEOMETRY_(V_ nol, V_ nov, V_ lov, V_ alpha,
                                   V_ *y5_, V_ *dv2_, V_ *single_, V_ *multi_)
{
    V_ nl = X_COS_(nol), nv = X_COS_(nov);
    V_ a = X_ALPHA_(alpha);
    V_ big, small, sh, hs, tau, w;
    V_ eq = X_BRDF_PEAK_(nl, nv, X_LOV_(lov), MUL_(a, a), &big, &small, &sh, &hs, &tau, &w); /* e/4 */
    V_ p2 = MUL_(nl, nv);
    /* m/2 = (1 - alpha) nl nv + alpha s/2; s/2 - nl nv >= 0 */
    V_ mh = FMA_(a, SUB_(hs, p2), p2);
    V_ lh = SQRT_(tau); /* L.H */
    V_ y = X_ONE_MINUS_LH_(w, lh); /* 2^16 (1 - L.H) */
    V_ y2 = MUL_(y, y);
    /* u = alpha tau / (e/4 mh) = 2 alpha t / (e mh) <= 2^40; alpha tau
     * serves the diffuse too */
    V_ at = MUL_(a, tau);
    V_ u = DIV_(at, MUL_(eq, mh));
    V_ h = X_HALF_INV_NH_(lh, sh);
    *y5_ = MUL_(MUL_(y2, y2), y);
    /* 2^-80 D Vis = (u mh) (u 2^-82 / pi), u mh <= 1024 */
    *dv2_ = MUL_(MUL_(u, mh), MUL_(u, C_(6.5824939e-26f))); /* 2^-82 / pi, the float 1/pi times 2^-82 */
    /* smooth / pi = p2 Q(big) (1.05/pi) Q(small): symmetric in N.L, N.V */
    *single_ = X_DIFFUSE_SINGLE_(at, tau, h, a,
                                 MUL_(p2, MUL_(X_POW5_Q_(big, 1.0f), X_POW5_Q_(small, FACET_DIF_K_))), multi_);
}

FACET_INLINE V_ X_BRDF_CHANNEL_(V_ y5, V_ dv2, V_ single, V_ multi, V_ f0, V_ albedo)
{
    V_ f0c = X_UNIT_(f0), alb = X_UNIT_(albedo);
    V_ f = FMA_(f0c, SUB_(C_(1.20892582e+24f), y5), y5); /* 2^80 F (2^80 exactly) */
    V_ dif = MUL_(alb, FMA_(alb, multi, single));
    return FMA_(dv2, f, dif);
}

FACET_INLINE V_ FACET_K(brdf_hammon)(V_ nol, V_ nov, V_ lov, V_ alpha, V_ f0, V_ albedo)
{
    V_ y5, dv2, single, multi;
    X_BRDF_GEOMETRY_(nol, nov, lov, alpha, &y5, &dv2, &single, &multi);
    return NAN0_(X_BRDF_CHANNEL_(y5, dv2, single, multi, f0, albedo), nol, nov, lov, alpha, f0, albedo);
}

/* brdf_hammon for three channels of f0 and albedo at once, the geometry
 * computed once: *out_c equals brdf_hammon(..., f0_c, albedo_c) bit for bit
 * (NaN rule included: a NaN in the geometry zeroes every channel, one in
 * f0_c or albedo_c channel c).  Channels as separate arguments (sizeless
 * vector types have no arrays). */
#define X_BRDF_RGB_CH_(o, f0c, albc)                                                          \
    *(o) = NAN0_(X_BRDF_CHANNEL_(y5, dv2, single, multi, f0c, albc), nol, nov, lov, alpha, f0c, albc)
FACET_INLINE void FACET_K(brdf_hammon_rgb)(V_ *out_r, V_ *out_g, V_ *out_b, V_ nol, V_ nov, V_ lov,
                                           V_ alpha, V_ f0_r, V_ f0_g, V_ f0_b, V_ albedo_r,
                                           V_ albedo_g, V_ albedo_b)
{
    V_ y5, dv2, single, multi;
    X_BRDF_GEOMETRY_(nol, nov, lov, alpha, &y5, &dv2, &single, &multi);
    X_BRDF_RGB_CH_(out_r, f0_r, albedo_r);
    X_BRDF_RGB_CH_(out_g, f0_g, albedo_g);
    X_BRDF_RGB_CH_(out_b, f0_b, albedo_b);
}
#undef X_BRDF_RGB_CH_

/* Lambert: albedo / pi, the baseline diffuse. */
FACET_INLINE V_ FACET_K(lambert)(V_ albedo)
{
    return NAN0_(MUL_(X_UNIT_(albedo), C_(FACET_INV_PI_)), albedo);
}

#undef V_
#undef C_
#undef ADD_
#undef SUB_
#undef MUL_
#undef FMA_
#undef FNMA_
#undef MIN_
#undef MAX_
#undef CLAMP_
#undef KEEP_ORD_
#undef KEEP_ORD4_
#undef NAN0_
#undef NAN0_SEL_
#undef NAN0_1_
#undef NAN0_2_
#undef NAN0_3_
#undef NAN0_4_
#undef NAN0_5_
#undef NAN0_6_
#undef NAN0_7_
#undef NAN0_8_
#undef RCP_
#undef RSQRT_
#undef RCP_X5_
#undef RSQRT_X5_
#undef DIV_
#undef DIV_X5_
#undef SQRT_X5_
#undef SQRT_
#undef FAST_
#undef X_POW5_Q_
#undef RCP_EXP_
#undef FACET_INV_PI_
#undef FACET_DIF_K_
#undef X_UNIT_
#undef X_COS_
#undef X_ALPHA_
#undef X_LOV_
#undef X_ONE_MINUS_POW5_
#undef X_SMITH_W_
#undef X_SQRT_
#undef X_EXP2M1R_POLY_
#undef X_EXP2M1R_
#undef X_EXP2_
#undef X_LOG2_FOLD_
#undef X_LOG2_POLY_
#undef X_LOG2_
#undef X_LOG2_X_
#undef X_EXP2_SCALED_
#undef X_LN1PR_
#undef X_PCHIP_END_
#undef X_PCHIP_MID_
#undef X_FRESNEL_Y_
#undef X_FRESNEL_
#undef X_G2_DEN_
#undef X_HAMMON_DEN_
#undef X_DIFFUSE_SINGLE_
#undef X_DIFFUSE_PI_
#undef X_HALF_INV_NH_
#undef X_BRDF_GEOMETRY_
#undef X_BRDF_PEAK_
#undef X_ONE_MINUS_LH_
#undef X_BRDF_CHANNEL_
