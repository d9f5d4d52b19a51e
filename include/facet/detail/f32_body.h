/* facet/detail/f32_body.h - the one body of every f32 kernel.
 *
 * Deliberately without an include guard: each port header includes it once
 * per tier,
 * after defining
 *   FACET_V        the vector (or scalar) type,
 *   FACET_OP(op)   the name of the port's op `op` (set add sub mul fma fnma
 *                  min max sel_lt clamp rcp rsqrt sqr_err, see facet/scalar.h),
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
/* the tier: the precise one, or with FACET_TIER_FAST 1 the fast one (the
 * same formulation, the port's cheaper rcp / rsqrt refinement) */
#if defined(FACET_TIER_FAST) && FACET_TIER_FAST
#define RCP_ FACET_OP(rcp_fast)
#define RSQRT_ FACET_OP(rsqrt_fast)
#else
#define RCP_ FACET_OP(rcp)
#define RSQRT_ FACET_OP(rsqrt)
#endif
/* where an error is raised to the fifth power (brdf_hammon's 1 - L.H), both
 * tiers refine fully: 5 times an unrefined estimate would exceed 2^-12 */
#define RCP_X5_ FACET_OP(rcp)
#define RSQRT_X5_ FACET_OP(rsqrt)

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
#define X_FRESNEL_Y_ FACET_K(x_fresnel_y)
#define X_FRESNEL_ FACET_K(x_fresnel)
#define X_G2_DEN_ FACET_K(x_g2_den)
#define X_HAMMON_DEN_ FACET_K(x_hammon_den)
#define X_DIFFUSE_SINGLE_ FACET_K(x_diffuse_single)
#define X_DIFFUSE_PI_ FACET_K(x_diffuse_pi)
#define X_BRDF_PARTS_ FACET_K(x_brdf_parts)
#define X_BRDF_GEOMETRY_ FACET_K(x_brdf_geometry)
#define X_BRDF_CHANNEL_ FACET_K(x_brdf_channel)

/* Domain handling, shared by all kernels: NaN and -Inf go to the low end. */
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

/* alpha^2 (1 - n^2) + n^2 = alpha^2 + (1 - alpha^2) n^2, the radicand of the
 * exact Smith terms, with 1 - n^2 formed as (1-n)(1+n): all terms >= 0. */
FACET_INLINE V_ X_SMITH_W_(V_ n, V_ a2)
{
    V_ q = MUL_(SUB_(C_(1.0f), n), ADD_(C_(1.0f), n));
    return FMA_(a2, q, MUL_(n, n));
}

FACET_INLINE V_ X_SQRT_(V_ w) { return MUL_(w, RSQRT_(w)); }

/* ---- identities ------------------------------------------------------ */

/* N.H = (N.L + N.V) / |L + V|, |L + V|^2 = 2 + 2 L.V.  t = 1 + L.V is raised
 * to (N.L + N.V)^2 / 2 where the triple is inconsistent, which caps N.H at 1
 * and keeps 2t > 0 (N.L, N.V >= FACET_COS_MIN). */
FACET_INLINE V_ FACET_K(noh_from_dots)(V_ nol, V_ nov, V_ lov)
{
    V_ s = ADD_(X_COS_(nol), X_COS_(nov));
    V_ t = ADD_(C_(1.0f), X_LOV_(lov));
    V_ t2 = MAX_(ADD_(t, t), MUL_(s, s));
    return MIN_(MUL_(s, RSQRT_(t2)), C_(1.0f));
}

/* L.H = |L + V| / 2 = sqrt((1 + L.V) / 2) = t * rsqrt(2t); 2t is floored at
 * 2^-100 only so that L.V = -1 gives 0 * finite = 0. */
FACET_INLINE V_ FACET_K(loh_from_dots)(V_ lov)
{
    V_ t = ADD_(C_(1.0f), X_LOV_(lov));
    V_ t2 = MAX_(ADD_(t, t), C_(7.88860905e-31f));
    return MIN_(MUL_(t, RSQRT_(t2)), C_(1.0f));
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
    return X_FRESNEL_(X_UNIT_(f0), X_UNIT_(c));
}

/* ---- GGX D ------------------------------------------------------------ */

/* D = alpha^2 / (pi d^2), d = (1 - n^2) + (n alpha)^2 with 1 - n^2 as
 * (1-n)(1+n), so d keeps full relative precision at the peak (d -> alpha^2).
 * Written D = (1/pi) (alpha/d)^2: alpha/d <= 1/alpha_min, no overflow. */
FACET_INLINE V_ FACET_K(ggx_d)(V_ noh, V_ alpha)
{
    V_ n = X_UNIT_(noh);
    V_ a = X_ALPHA_(alpha);
    V_ na = MUL_(n, a);
    V_ d = FMA_(SUB_(C_(1.0f), n), ADD_(C_(1.0f), n), MUL_(na, na));
    V_ k = MUL_(a, RCP_(d));
    return MUL_(MUL_(k, k), C_(FACET_INV_PI_));
}

/* ---- Smith, exact ------------------------------------------------------ */

/* G1 = 2n / (n + sqrt(alpha^2 + (1 - alpha^2) n^2)) */
FACET_INLINE V_ FACET_K(smith_g1)(V_ nov, V_ alpha)
{
    V_ n = X_UNIT_(nov);
    V_ a = X_ALPHA_(alpha);
    V_ r = X_SQRT_(X_SMITH_W_(n, MUL_(a, a)));
    return MIN_(MUL_(ADD_(n, n), RCP_(ADD_(n, r))), C_(1.0f));
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
    return MIN_(MUL_(ADD_(p, p), RCP_(den)), C_(1.0f));
}

FACET_INLINE V_ FACET_K(smith_vis)(V_ nol, V_ nov, V_ alpha)
{
    V_ nl = X_COS_(nol), nv = X_COS_(nov);
    V_ den = X_G2_DEN_(nl, nv, X_ALPHA_(alpha));
    return MUL_(C_(0.5f), RCP_(den));
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
    return MIN_(MUL_(MUL_(C_(4.0f), p), RCP_(MUL_(dl, dv))), C_(1.0f));
}

/* ---- Smith, Hammon's approximation ---------------------------------------- */

/* G1 ~ 2n / (n (2 - alpha) + alpha)  (= Schlick-GGX with k = alpha/2) */
FACET_INLINE V_ FACET_K(smith_g1_hammon)(V_ nov, V_ alpha)
{
    V_ n = X_UNIT_(nov);
    V_ a = X_ALPHA_(alpha);
    V_ den = FMA_(n, SUB_(C_(2.0f), a), a);
    return MIN_(MUL_(ADD_(n, n), RCP_(den)), C_(1.0f));
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
    return MIN_(MUL_(ADD_(p, p), RCP_(den)), C_(1.0f));
}

FACET_INLINE V_ FACET_K(smith_vis_hammon)(V_ nol, V_ nov, V_ alpha)
{
    V_ nl = X_COS_(nol), nv = X_COS_(nov);
    V_ den = X_HAMMON_DEN_(nl, nv, X_ALPHA_(alpha));
    return MUL_(C_(0.5f), RCP_(den));
}

/* ---- shadowing and visibility: the rest of the menu ------------------------ */

/* Implicit G = N.L N.V: one rounding. */
FACET_INLINE V_ FACET_K(g_implicit)(V_ nol, V_ nov)
{
    return MUL_(X_UNIT_(nol), X_UNIT_(nov));
}

/* Neumann G = N.L N.V / max(N.L, N.V), which is min(N.L, N.V) exactly
 * (and 0, not 0/0, at N.L = N.V = 0). */
FACET_INLINE V_ FACET_K(g_neumann)(V_ nol, V_ nov)
{
    return MIN_(X_UNIT_(nol), X_UNIT_(nov));
}

/* Cook-Torrance G = min(1, 2 N.H N.V / V.H, 2 N.H N.L / V.H)
 *                 = min(1, g / V.H), g = 2 N.H min(N.L, N.V):
 * where g >= V.H (also V.H = 0) the result is 1 and no reciprocal is used;
 * below, V.H > g >= 0 and the quotient is < 1.  N.H and V.H enter only as
 * their ratio, so below V.H = 2^-40 both are scaled by 2^60 (exactly):
 * the reciprocal never sees a denormal (scaled, V.H >= 2^-89 or 0; the
 * floor 2^-100 only keeps 1/0 out of the unselected side), and g keeps its
 * precision. */
FACET_INLINE V_ FACET_K(g_cook_torrance)(V_ nol, V_ nov, V_ noh, V_ voh)
{
    V_ m = MIN_(X_COS_(nol), X_COS_(nov));
    V_ nh = X_UNIT_(noh), vh = X_UNIT_(voh);
    V_ sc = FACET_OP(sel_lt)(vh, C_(9.09494702e-13f), C_(1.15292150e18f), C_(1.0f));
    V_ g, v;
    nh = MUL_(nh, sc);
    v = MUL_(vh, sc);
    g = MUL_(ADD_(nh, nh), m);
    return FACET_OP(sel_lt)(g, v, MUL_(g, RCP_(MAX_(v, C_(7.88860905e-31f)))), C_(1.0f));
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
    return FACET_OP(sel_lt)(p, q, MUL_(p, RCP_(MAX_(q, C_(8.67361738e-19f)))), C_(1.0f));
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
    V_ g = MIN_(MUL_(num, RCP_(den)), C_(1.0f));
    return FACET_OP(sel_lt)(q, MUL_(C_(1.6f), p), g, C_(1.0f));
}

/* Schlick's G1 for Beckmann: N.V / (N.V (1 - k) + k), k = alpha sqrt(2/pi)
 * (<= 0.798, so 1 - k > 0 and every term is >= 0). */
FACET_INLINE V_ FACET_K(smith_g1_schlick_beckmann)(V_ nov, V_ alpha)
{
    V_ n = X_UNIT_(nov);
    V_ k = MUL_(X_ALPHA_(alpha), C_(0.797884561f));
    V_ den = FMA_(n, SUB_(C_(1.0f), k), k);
    return MIN_(MUL_(n, RCP_(den)), C_(1.0f));
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
    return MUL_(C_(0.5f), RCP_(den));
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
    return RCP_(ADD_(MUL_(nv, rl), MUL_(nl, rv)));
}

/* ---- Hammon's GGX diffuse --------------------------------------------------- */

/* pi * diffuse, from the pieces the caller shares (h = 0.5 / N.H):
 *   facing = 0.5 + 0.5 L.V = t/2, so facing (0.9 - 0.4 facing) = t (0.45 - 0.1 t)
 *   rough  = t (0.45 - 0.1 t) (1 + h)
 *   smooth = 1.05 (1 - (1-nl)^5) (1 - (1-nv)^5)
 *   pi single = (1 - alpha) smooth + alpha rough,  pi multi = 0.1159 pi alpha
 *   pi diffuse = albedo (pi single + albedo pi multi)
 * The caller applies the 1/pi (brdf_hammon folds it with the specular). */
FACET_INLINE V_ X_DIFFUSE_SINGLE_(V_ nl, V_ nv, V_ t, V_ h, V_ a, V_ *multi)
{
    V_ rough = MUL_(MUL_(t, FNMA_(C_(0.1f), t, C_(0.45f))), ADD_(C_(1.0f), h));
    /* 1 - alpha is exact for alpha >= 1/2; the product of the two powers is
     * formed first so that swapping N.L and N.V gives the same bits */
    V_ c = MUL_(C_(1.05f), SUB_(C_(1.0f), a));
    V_ smooth = MUL_(c, MUL_(X_ONE_MINUS_POW5_(nl), X_ONE_MINUS_POW5_(nv)));
    *multi = MUL_(C_(0.364110589f), a); /* 0.1159 pi */
    return FMA_(a, rough, smooth);
}

FACET_INLINE V_ X_DIFFUSE_PI_(V_ nl, V_ nv, V_ t, V_ h, V_ a, V_ alb)
{
    V_ multi, single = X_DIFFUSE_SINGLE_(nl, nv, t, h, a, &multi);
    return MUL_(alb, FMA_(alb, multi, single));
}

FACET_INLINE V_ FACET_K(diffuse_hammon)(V_ nol, V_ nov, V_ lov, V_ alpha, V_ albedo)
{
    V_ nl = X_COS_(nol), nv = X_COS_(nov);
    V_ s = ADD_(nl, nv);
    V_ t = MAX_(ADD_(C_(1.0f), X_LOV_(lov)), MUL_(C_(0.5f), MUL_(s, s)));
    V_ nh = MIN_(MUL_(s, RSQRT_(ADD_(t, t))), C_(1.0f));
    V_ d = X_DIFFUSE_PI_(nl, nv, t, MUL_(C_(0.5f), RCP_(nh)), X_ALPHA_(alpha),
                                 X_UNIT_(albedo));
    return MUL_(d, C_(FACET_INV_PI_));
}

/* ---- the whole model ------------------------------------------------------ */

/* D(N.H) Vis_hammon F(f0, L.H) + diffuse_hammon, from the three dots.
 *
 * D is ill-conditioned in N.H at the peak for small alpha (d -> alpha^2), so
 * N.H is never formed for it.  With s = N.L + N.V and t = 1 + L.V:
 *   1 - N.H^2 = num / 2t,  num = 2t - s^2  (= |tangential part of L+V|^2)
 *   d = (1 - N.H^2) + alpha^2 N.H^2 = e / 2t,  e = num + alpha^2 s^2
 *   D = alpha^2 / (pi d^2) = (4/pi) (alpha t / e)^2.
 * num cancels at the peak, so it is formed exactly: s and t as unevaluated
 * sums (Fast2Sum), s^2 as p + pe with pe the exact rounding error.
 * Likewise 1 - L.H, which F raises to the fifth power, is formed without
 * cancellation as (1 - L.H^2) / (1 + L.H) = (2 - t) / (2 (1 + L.H)).
 * With Vis = 0.5/m (m = Hammon's lerp) and L.H = t rsqrt(2t):
 *   spec = (2/pi) (alpha t)^2 F / (e^2 m) = (2/pi) (u m) u F,  u = alpha t / (e m),
 * ordered so that no intermediate overflows at the grazing corner.
 * Three reciprocals (1/(e m), 1/(1 + L.H), 1/s) and one rsqrt in all. */
/* What brdf_hammon computes before f0 and albedo enter: F = f0 + (1 - f0) y5,
 * brdf = (dv2 F + albedo (single + albedo multi)) / pi.  The RGB form shares
 * it across channels; per channel the same operations run in the same order,
 * so each channel equals brdf_hammon to the bit. */
typedef struct X_BRDF_PARTS_ { V_ y5, dv2, single, multi; } X_BRDF_PARTS_;

FACET_INLINE X_BRDF_PARTS_ X_BRDF_GEOMETRY_(V_ nol, V_ nov, V_ lov, V_ alpha)
{
    X_BRDF_PARTS_ g;
    V_ nl = X_COS_(nol), nv = X_COS_(nov);
    V_ lv = X_LOV_(lov);
    V_ a = X_ALPHA_(alpha);
    V_ big = MAX_(nl, nv), small = MIN_(nl, nv);
    V_ sh = ADD_(big, small);
    V_ sl = SUB_(small, SUB_(sh, big));
    V_ th = ADD_(C_(1.0f), lv);
    V_ tl = SUB_(lv, SUB_(th, C_(1.0f)));
    V_ p = MUL_(sh, sh);
    V_ pe = FACET_OP(sqr_err)(sh, p);
    /* 2t - s^2 = (2th - p) + (2tl - (s^2 - p)); 2th - p is exact near the
     * peak (Sterbenz), the rest is tiny; s^2 - p = pe + sl (2sh + sl). */
    V_ s2lo = FMA_(sl, ADD_(ADD_(sh, sh), sl), pe); /* s^2 - p */
    V_ num = MAX_(ADD_(SUB_(ADD_(th, th), p), SUB_(ADD_(tl, tl), s2lo)), C_(0.0f));
    V_ t = MAX_(th, MUL_(C_(0.5f), p));
    V_ a2 = MUL_(a, a);
    V_ e = FMA_(a2, p, FMA_(a2, s2lo, num));
    V_ p2 = MUL_(nl, nv);
    V_ m = FMA_(a, sh, MUL_(SUB_(C_(1.0f), a), ADD_(p2, p2))); /* Hammon's lerp */
    V_ r = RSQRT_X5_(ADD_(t, t));
    V_ lh = MIN_(MUL_(t, r), C_(1.0f));
    /* w = 2 - t = min(1 - L.V, 2 - s^2/2), each side formed without
     * cancellation: 2 - s^2/2 = ((1 - nl) + (1 - nv)) (2 + s) / 2 */
    V_ w = MIN_(SUB_(C_(1.0f), lv),
                MUL_(MUL_(C_(0.5f), ADD_(SUB_(C_(1.0f), nl), SUB_(C_(1.0f), nv))),
                     ADD_(C_(2.0f), sh)));
    /* below L.H = 1/2, 1 - L.H itself is the better conditioned form */
    V_ y = FACET_OP(sel_lt)(lh, C_(0.5f), SUB_(C_(1.0f), lh),
                            MUL_(MUL_(C_(0.5f), w), RCP_X5_(ADD_(C_(1.0f), lh))));
    V_ y2 = MUL_(y, y);
    /* D Vis = (4/pi)(alpha t / e)^2 (0.5 / m) = (2/pi) (alpha t)^2 / (e^2 m),
     * and 1 / (e^2 m) = m R^2 with R = 1 / (e m): one reciprocal */
    V_ R = RCP_(MUL_(e, m));
    V_ u = MUL_(MUL_(a, t), R);                 /* alpha t / (e m) <= 2^38 */
    V_ dv_pi = MUL_(MUL_(u, m), u);             /* pi D Vis / 2; u m = alpha t / e <= 512 */
    /* 0.5 / N.H = L.H / s (N.H = s / (2 L.H)), at least 0.5 */
    V_ h = MAX_(MUL_(lh, RCP_(sh)), C_(0.5f));
    g.y5 = MUL_(MUL_(y2, y2), y);
    g.dv2 = ADD_(dv_pi, dv_pi);
    g.single = X_DIFFUSE_SINGLE_(nl, nv, t, h, a, &g.multi);
    return g;
}

FACET_INLINE V_ X_BRDF_CHANNEL_(const X_BRDF_PARTS_ *g, V_ f0, V_ albedo)
{
    V_ f0c = X_UNIT_(f0), alb = X_UNIT_(albedo);
    V_ f = FMA_(SUB_(C_(1.0f), f0c), g->y5, f0c);
    V_ dif = MUL_(alb, FMA_(alb, g->multi, g->single));
    return MUL_(FMA_(g->dv2, f, dif), C_(FACET_INV_PI_));
}

FACET_INLINE V_ FACET_K(brdf_hammon)(V_ nol, V_ nov, V_ lov, V_ alpha, V_ f0, V_ albedo)
{
    X_BRDF_PARTS_ g = X_BRDF_GEOMETRY_(nol, nov, lov, alpha);
    return X_BRDF_CHANNEL_(&g, f0, albedo);
}

/* brdf_hammon for three channels of f0 and albedo at once, the geometry
 * computed once: out[c] equals brdf_hammon(..., f0[c], albedo[c]) bit for bit. */
FACET_INLINE void FACET_K(brdf_hammon_rgb)(V_ out[3], V_ nol, V_ nov, V_ lov, V_ alpha,
                                           const V_ f0[3], const V_ albedo[3])
{
    X_BRDF_PARTS_ g = X_BRDF_GEOMETRY_(nol, nov, lov, alpha);
    out[0] = X_BRDF_CHANNEL_(&g, f0[0], albedo[0]);
    out[1] = X_BRDF_CHANNEL_(&g, f0[1], albedo[1]);
    out[2] = X_BRDF_CHANNEL_(&g, f0[2], albedo[2]);
}

/* Lambert: albedo / pi, the baseline diffuse. */
FACET_INLINE V_ FACET_K(lambert)(V_ albedo)
{
    return MUL_(X_UNIT_(albedo), C_(FACET_INV_PI_));
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
#undef RCP_
#undef RSQRT_
#undef RCP_X5_
#undef RSQRT_X5_
#undef FACET_INV_PI_
#undef X_UNIT_
#undef X_COS_
#undef X_ALPHA_
#undef X_LOV_
#undef X_ONE_MINUS_POW5_
#undef X_SMITH_W_
#undef X_SQRT_
#undef X_FRESNEL_Y_
#undef X_FRESNEL_
#undef X_G2_DEN_
#undef X_HAMMON_DEN_
#undef X_DIFFUSE_SINGLE_
#undef X_DIFFUSE_PI_
#undef X_BRDF_PARTS_
#undef X_BRDF_GEOMETRY_
#undef X_BRDF_CHANNEL_
