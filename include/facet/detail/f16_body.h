/* facet/detail/f16_body.h - the one body of every binary16 (f16) kernel.
 *
 * Deliberately without an include guard: each f16 port header includes it
 * once, after defining
 *   FACET_V        the binary16 vector (the scalar specification: a float
 *                  that always holds a binary16 value),
 *   FACET_W        the f32 vector of the same lanes (avx512fp16: a pair of
 *                  __m512), for the few operations binary16 cannot hold,
 *   FACET_OP(op)   the name of the port's op `op`: on V set add sub mul fma
 *                  fnma min max clamp keep_ord keep_ord4 rcp rsqrt div sqrt;
 *                  on W w_set w_add w_sub w_mul w_fma w_fnma w_min w_max
 *                  w_sqr_err (unused now) w_rcp w_rsqrt; widen (V to W,
 *                  exact) and
 *                  narrow (W to V for values >= 0, rounded to nearest
 *                  even; above 65504 the port may give 65504 or +Inf: the
 *                  body narrows only values below it or a term whose sum
 *                  it saturates),
 *   FACET_K(k)     the name to give kernel `k` (facet_<k>_f16_<port>).
 * There is one tier: binary16's rounding (2^-11) is already the cost the
 * format buys; the estimates are refined to it (see the port headers).
 * Contracts (formula, domain, measured error, cost): facet/f16.h; the
 * comments here explain the numerics.  u below is binary16's unit
 * roundoff 2^-11.
 */
#ifndef FACET_V
#error "include an f16 port header (facet/f16_scalar.h, facet/avx512fp16.h), not this file"
#endif

#define V_ FACET_V
#define W_ FACET_W
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
#define RCP_ FACET_OP(rcp)
#define RSQRT_ FACET_OP(rsqrt)
#define DIV_ FACET_OP(div)
#define SQRT_ FACET_OP(sqrt)
#define WC_(x) FACET_OP(w_set)(x)
#define WADD_ FACET_OP(w_add)
#define WSUB_ FACET_OP(w_sub)
#define WMUL_ FACET_OP(w_mul)
#define WFMA_ FACET_OP(w_fma)
#define WFNMA_ FACET_OP(w_fnma)
#define WMIN_ FACET_OP(w_min)
#define WMAX_ FACET_OP(w_max)
#define WRCP_ FACET_OP(w_rcp)
#define WRSQRT_ FACET_OP(w_rsqrt)
#define WIDEN_ FACET_OP(widen)
#define NARROW_ FACET_OP(narrow)

#define X16_UNIT_ FACET_K(x_unit)
#define X16_COS_ FACET_K(x_cos)
#define X16_ALPHA_ FACET_K(x_alpha)
#define X16_LOV_ FACET_K(x_lov)
#define X16_POW5_Q_ FACET_K(x_pow5_q)
#define X16_DIFFUSE_ FACET_K(x_diffuse)
#define X16_DIFFUSE_S_ FACET_K(x_diffuse_s)
#define X16_HALF_INV_NH_ FACET_K(x_half_inv_nh)
#define X16_POW5_Y_ FACET_K(x_pow5_y)
#define X16_SMITH_W_ FACET_K(x_smith_w)
#define X16_SQRT_N_ FACET_K(x_sqrt_n)

/* The NaN rule (as f32_body.h): a NaN in any input gives +0 for that
 * lane; the arithmetic runs on the clamped inputs (NaN clamps to the low
 * end), so no NaN or Inf arises, and the mask replaces the result. */
#define NAN0_(...) NAN0_SEL_(__VA_ARGS__, NAN0_6_, NAN0_5_, NAN0_4_, NAN0_3_, NAN0_2_, NAN0_1_, -)(__VA_ARGS__)
#define NAN0_SEL_(r, a, b, c, d, e, f, N, ...) N
#define NAN0_1_(r, a) KEEP_ORD_(r, a, a)
#define NAN0_2_(r, a, b) KEEP_ORD_(r, a, b)
#define NAN0_3_(r, a, b, c) KEEP_ORD4_(r, a, b, c, c)
#define NAN0_4_(r, a, b, c, d) KEEP_ORD4_(r, a, b, c, d)
#define NAN0_5_(r, a, b, c, d, e) KEEP_ORD_(NAN0_4_(r, a, b, c, d), e, e)
#define NAN0_6_(r, a, b, c, d, e, f) KEEP_ORD_(NAN0_4_(r, a, b, c, d), e, f)

/* Domain: N.L, N.V in [FACET_F16_COS_MIN, 1], alpha in [FACET_F16_ALPHA_MIN,
 * 1] (both 2^-7: alpha^2 and N.L N.V stay binary16 normals, >= 2^-14),
 * L.V in [-1, 1], the rest in [0, 1]; -Inf and NaN to the low end, +Inf to
 * the high end. */
FACET_INLINE V_ X16_UNIT_(V_ x) { return CLAMP_(x, C_(0.0f), C_(1.0f)); }
FACET_INLINE V_ X16_COS_(V_ x) { return CLAMP_(x, C_(FACET_F16_COS_MIN), C_(1.0f)); }
FACET_INLINE V_ X16_ALPHA_(V_ x) { return CLAMP_(x, C_(FACET_F16_ALPHA_MIN), C_(1.0f)); }
FACET_INLINE V_ X16_LOV_(V_ x) { return CLAMP_(x, C_(-1.0f), C_(1.0f)); }

/* ---- identities ---------------------------------------------------------
 * N.H = s rsqrt(max(2t, s^2)), s = N.L + N.V, t = 1 + L.V (t exact for
 * L.V <= -1/2, Sterbenz; else one rounding): about 4 u. */
FACET_INLINE V_ FACET_K(noh_from_dots)(V_ nol, V_ nov, V_ lov)
{
    V_ s = ADD_(X16_COS_(nol), X16_COS_(nov));
    V_ t = ADD_(C_(1.0f), X16_LOV_(lov));
    V_ t2 = MAX_(ADD_(t, t), MUL_(s, s));
    return NAN0_(MIN_(MUL_(s, RSQRT_(t2)), C_(1.0f)), nol, nov, lov);
}

/* L.H = t rsqrt(2t); 2t >= 2^-10 but at L.V = -1 (t = 0), floored at 2^-14
 * so that 0 * finite = 0. */
FACET_INLINE V_ FACET_K(loh_from_dots)(V_ lov)
{
    V_ t = ADD_(C_(1.0f), X16_LOV_(lov));
    V_ t2 = MAX_(ADD_(t, t), C_(6.103515625e-05f));
    return NAN0_(MIN_(MUL_(t, RSQRT_(t2)), C_(1.0f)), lov);
}

/* ---- Fresnel --------------------------------------------------------------
 * f0 + (1 - f0) y^5, y = 1 - c as yh + yl (Fast2Sum, exact in binary16 as
 * in f32), y^5 ~ yh^4 (yh + 5 yl): the rounding of 1 - c is not raised to
 * the fifth power; 4 roundings in y^5, one in 1 - f0, one in the fma. */
FACET_INLINE V_ FACET_K(fresnel_schlick)(V_ f0, V_ cos)
{
    V_ f = X16_UNIT_(f0), c = X16_UNIT_(cos);
    V_ yh = SUB_(C_(1.0f), c);
    V_ yl = SUB_(SUB_(C_(1.0f), yh), c);
    V_ y2 = MUL_(yh, yh);
    V_ y5 = MUL_(MUL_(y2, y2), FMA_(C_(5.0f), yl, yh));
    return NAN0_(FMA_(SUB_(C_(1.0f), f), y5, f), f0, cos);
}

/* k Q(x), Q(x) = (1 - (1 - x)^5) / x = 1 + y + y^2 + y^3 + y^4 (y = 1 - x)
 * by Horner (positive terms), k folded into the coefficients (one rounding
 * fewer than a product after it; k a constant or a vector) */
FACET_INLINE V_ X16_POW5_Q_(V_ x, V_ k)
{
    V_ y = SUB_(C_(1.0f), x);
    V_ p = FMA_(y, k, k);
    p = FMA_(p, y, k);
    p = FMA_(p, y, k);
    return FMA_(p, y, k);
}

/* (1 - c)^5 as fresnel_schlick forms it: 1 - c = yh + yl (Fast2Sum, exact),
 * y^5 ~ yh^4 (yh + 5 yl); 4 roundings */
FACET_INLINE V_ X16_POW5_Y_(V_ c)
{
    V_ yh = SUB_(C_(1.0f), c);
    V_ yl = SUB_(SUB_(C_(1.0f), yh), c);
    V_ y2 = MUL_(yh, yh);
    return MUL_(MUL_(y2, y2), FMA_(C_(5.0f), yl, yh));
}

/* Schlick with f90: the convex combination f0 (1 - y^5) + f90 y^5 (y = 1 - c,
 * as f32_body.h: f90 < f0 does not cancel), 1 - y^5 = c Q(c) (positive
 * terms, X16_POW5_Q_ above with f0 for its constant), f0 Q(c) formed
 * before the product with c (a subnormal c or f0 rounds once, last) */
FACET_INLINE V_ FACET_K(fresnel_schlick_f90)(V_ f0, V_ f90, V_ voh)
{
    V_ c = X16_UNIT_(voh);
    V_ q = MUL_(X16_POW5_Q_(c, X16_UNIT_(f0)), c);
    return NAN0_(FMA_(X16_UNIT_(f90), X16_POW5_Y_(c), q), f0, f90, voh);
}

/* ---- GGX D -----------------------------------------------------------------
 * D = (alpha / (sqrt(pi) d))^2, d = (1 - n^2) + (n alpha)^2.  D goes as
 * d^-2, and d's binary16 roundings (about 3 u) would double to 6 u, so d and
 * k = alpha / (sqrt(pi) d) (<= 73) are formed in f32 lanes, 1 - n^2 in one
 * fnma (exact for n >= 1/2), with the port's f32 reciprocal estimate (2^-14
 * on avx512fp16), and k is narrowed once: D = k^2 has 3 u (2 from k's
 * rounding, 1 from the square). */
FACET_INLINE V_ FACET_K(ggx_d)(V_ noh, V_ alpha)
{
    W_ n = WIDEN_(X16_UNIT_(noh)), a = WIDEN_(X16_ALPHA_(alpha));
    W_ na = WMUL_(n, a);
    W_ d = WFMA_(na, na, WFNMA_(n, n, WC_(1.0f)));
    V_ k = NARROW_(WMUL_(WMUL_(a, WC_(0.564189584f)), WRCP_(d)));
    return NAN0_(MUL_(k, k), noh, alpha);
}

/* Anisotropic GGX, f32_body.h's form D = ax^3 ay^3 / (pi K^2),
 * K = T.H^2 ay^2 + B.H^2 ax^2 + N.H^2 ax^2 ay^2 (terms >= 0, no 1 - N.H^2:
 * the peak does not cancel), floored at ax^2 ay^2 / 2: in f32 lanes, from
 * the exact binary16 inputs.  Range forces it: ax^2 ay^2 reaches 2^-28,
 * K with it (binary16's normals end at 2^-14).  The binary16 alternative,
 * k = K / (ax^2 ay^2) = (T.H / ax)^2 + (B.H / ay)^2 + N.H^2, takes two
 * quotients' errors (2 u each) into squares and D = 1 / (pi ax ay k^2)
 * doubles k's error again: about 10 u by this count (derived, not
 * measured), past 2^-8.  In f32 the squares are exact, K has 3 roundings
 * of 2^-24, D takes the f32 reciprocal estimate twice (2^-13 on
 * avx512fp16) and one narrowing: about 1.3 u.  D <= 4 / (pi ax ay) < 2^15. */
FACET_INLINE V_ FACET_K(ggx_aniso_d)(V_ noh, V_ toh, V_ boh, V_ alpha_x, V_ alpha_y)
{
    W_ n = WIDEN_(X16_UNIT_(noh)), t = WIDEN_(X16_LOV_(toh)), b = WIDEN_(X16_LOV_(boh));
    W_ ax = WIDEN_(X16_ALPHA_(alpha_x)), ay = WIDEN_(X16_ALPHA_(alpha_y));
    W_ ax2 = WMUL_(ax, ax), ay2 = WMUL_(ay, ay), a2 = WMUL_(ax2, ay2);
    W_ k = WFMA_(WMUL_(t, t), ay2, WFMA_(WMUL_(b, b), ax2, WMUL_(WMUL_(n, n), a2)));
    W_ r = WRCP_(WMAX_(k, WMUL_(WC_(0.5f), a2)));
    W_ d = WMUL_(WMUL_(WMUL_(a2, WMUL_(ax, ay)), WC_(0.318309886f)), WMUL_(r, r));
    return NAN0_(NARROW_(d), noh, toh, boh, alpha_x, alpha_y);
}

/* ---- Smith visibility -------------------------------------------------------
 * Hammon's: Vis = 0.5 / lerp(2 nl nv, nl + nv, alpha) = 0.25 / mh,
 * mh = nl nv + alpha (s/2 - nl nv) (both terms >= 0; nl nv >= 2^-14, a
 * normal, by the cosine floor): about 4 u, Vis <= 2^12. */
FACET_INLINE V_ FACET_K(smith_vis_hammon)(V_ nol, V_ nov, V_ alpha)
{
    V_ nl = X16_COS_(nol), nv = X16_COS_(nov), a = X16_ALPHA_(alpha);
    V_ p = MUL_(nl, nv);
    V_ mh = FMA_(a, SUB_(MUL_(C_(0.5f), ADD_(nl, nv)), p), p);
    return NAN0_(DIV_(C_(0.25f), mh), nol, nov, alpha);
}

/* Hammon's G2 = 2 nl nv / lerp(2 nl nv, nl + nv, alpha) = p / mh, p = nl nv,
 * mh as smith_vis_hammon's (p >= 2^-14 normal, mh >= p) */
FACET_INLINE V_ FACET_K(smith_g2_hammon)(V_ nol, V_ nov, V_ alpha)
{
    V_ nl = X16_COS_(nol), nv = X16_COS_(nov), a = X16_ALPHA_(alpha);
    V_ p = MUL_(nl, nv);
    V_ mh = FMA_(a, SUB_(MUL_(C_(0.5f), ADD_(nl, nv)), p), p);
    return NAN0_(MIN_(DIV_(p, mh), C_(1.0f)), nol, nov, alpha);
}

/* ---- the rest of the G menu ---------------------------------------------------
 * Implicit: nl nv, one rounding (nl, nv >= 2^-7: >= 2^-14, normal). */
FACET_INLINE V_ FACET_K(g_implicit)(V_ nol, V_ nov)
{
    return NAN0_(MUL_(X16_COS_(nol), X16_COS_(nov)), nol, nov);
}

/* Neumann: nl nv / max(nl, nv) = min(nl, nv), exactly. */
FACET_INLINE V_ FACET_K(g_neumann)(V_ nol, V_ nov)
{
    return NAN0_(MIN_(X16_COS_(nol), X16_COS_(nov)), nol, nov);
}

/* Cook-Torrance: min(1, m r), r = 2 N.H / V.H, m = min(N.L, N.V) >= 2^-7.
 * N.H and V.H span binary16's subnormals, so both are scaled first, exactly:
 * 2^15 N.H <= 32768 and 2^14 V.H, 0 or >= 2^-10 (a normal: the
 * reciprocal sees [2^-10, 2^14]); r = 2^15 N.H / (2^14 V.H) overflows to
 * +Inf only where the result is 1, and where the result is at least 2^-14
 * r >= 2^-14 is normal (m <= 1).  V.H = 0 gives 1 (the cap of an
 * infinite ratio, and 0/0 at N.H = 0 as f32_body.h): z = max(1 - 2^10
 * (2^14 V.H), 0) is 1 there and 0 for every other binary16 V.H, added
 * under the cap (no compare-and-select in the op layer).  3 roundings
 * (the estimate, r, the fma). */
FACET_INLINE V_ FACET_K(g_cook_torrance)(V_ nol, V_ nov, V_ noh, V_ voh)
{
    V_ m = MIN_(X16_COS_(nol), X16_COS_(nov));
    V_ h = MUL_(X16_UNIT_(noh), C_(32768.0f));
    V_ v = MUL_(X16_UNIT_(voh), C_(16384.0f));
    V_ r = MUL_(h, RCP_(MAX_(v, C_(9.765625e-04f))));
    V_ z = MAX_(FNMA_(v, C_(1024.0f), C_(1.0f)), C_(0.0f));
    return NAN0_(MIN_(FMA_(m, r, z), C_(1.0f)), nol, nov, noh, voh);
}

/* Kelemen: min(1, nl nv / V.H^2), p = nl nv >= 2^-14.  The result is below
 * 1 only where V.H^2 > p >= 2^-14, so V.H^2 is floored at 2^-14 (a normal,
 * for the reciprocal): below it p / 2^-14 >= 1 and the cap gives 1 (within
 * the estimate's error), V.H = 0 included.  3 roundings and the estimate. */
FACET_INLINE V_ FACET_K(g_kelemen)(V_ nol, V_ nov, V_ voh)
{
    V_ p = MUL_(X16_COS_(nol), X16_COS_(nov));
    V_ vh = X16_UNIT_(voh);
    V_ q = MAX_(MUL_(vh, vh), C_(6.103515625e-05f));
    return NAN0_(MIN_(DIV_(p, q), C_(1.0f)), nol, nov, voh);
}

/* Schlick's G1 for Beckmann: n / (n (1 - k) + k), k = alpha sqrt(2/pi)
 * (<= 0.798, >= 2^-7.3: terms >= 0, the divisor normal; sqrt(2/pi) rounds
 * to binary16 within 2^-14.5 of itself) */
FACET_INLINE V_ FACET_K(smith_g1_schlick_beckmann)(V_ nov, V_ alpha)
{
    V_ n = X16_COS_(nov);
    V_ k = MUL_(X16_ALPHA_(alpha), C_(0.797884561f));
    V_ den = FMA_(n, SUB_(C_(1.0f), k), k);
    return NAN0_(MIN_(DIV_(n, den), C_(1.0f)), nov, alpha);
}

/* The engines' joint form 0.5 / (nl (nv (1 - a) + a) + nv (nl (1 - a) + a))
 * (Hammon's visibility written as Karis writes it): terms >= 0, the two
 * products added unfused as in f32_body.h; divisor >= 2^-12 */
FACET_INLINE V_ FACET_K(smith_vis_joint_approx)(V_ nol, V_ nov, V_ alpha)
{
    V_ nl = X16_COS_(nol), nv = X16_COS_(nov), a = X16_ALPHA_(alpha);
    V_ b = SUB_(C_(1.0f), a);
    V_ den = ADD_(MUL_(nl, FMA_(nv, b, a)), MUL_(nv, FMA_(nl, b, a)));
    return NAN0_(DIV_(C_(0.5f), den), nol, nov, alpha);
}

/* The exact height-correlated one: 0.5 / (nv sqrt(w(nl)) + nl sqrt(w(nv))),
 * w(n) = alpha^2 (1 - n)(1 + n) + n^2 (all terms >= 0; alpha^2 >= 2^-14 and
 * n^2 >= 2^-14 normal): sums of positive terms throughout. */
FACET_INLINE V_ FACET_K(smith_vis)(V_ nol, V_ nov, V_ alpha)
{
    V_ nl = X16_COS_(nol), nv = X16_COS_(nov), a = X16_ALPHA_(alpha);
    V_ a2 = MUL_(a, a);
    V_ wl = FMA_(a2, MUL_(SUB_(C_(1.0f), nl), ADD_(C_(1.0f), nl)), MUL_(nl, nl));
    V_ wv = FMA_(a2, MUL_(SUB_(C_(1.0f), nv), ADD_(C_(1.0f), nv)), MUL_(nv, nv));
    V_ den = ADD_(MUL_(nv, SQRT_(wl)), MUL_(nl, SQRT_(wv)));
    return NAN0_(DIV_(C_(0.5f), den), nol, nov, alpha);
}

/* sqrt(x) for a positive normal x, within about u: s = x rsqrt(x) carries
 * the estimate's error (up to 2^-11 + 2^-14 on avx512fp16, more on
 * neonfp16's one step) and one rounding; one Newton correction
 * s + (x - s^2) rsqrt(x) / 2 (x - s^2 exact in the fnma before its rounding,
 * small against s) leaves the correction's own rounding.  Three operations
 * more than SQRT_, where a kernel would otherwise take a root's error twice. */
FACET_INLINE V_ X16_SQRT_N_(V_ x)
{
    V_ r = RSQRT_(x);
    V_ s = MUL_(x, r);
    return FMA_(FNMA_(s, s, x), MUL_(C_(0.5f), r), s);
}

/* The radicand of the exact Smith terms below, alpha^2 (1 - n^2) + n^2 with
 * 1 - n^2 in one fnma (exact before its rounding: every binary16 port
 * fuses): both terms >= 0, n^2 >= 2^-14 normal; 3 roundings at most in
 * either term.  (smith_vis above keeps its (1 - n)(1 + n), measured.) */
FACET_INLINE V_ X16_SMITH_W_(V_ n, V_ a2)
{
    return FMA_(a2, FNMA_(n, n, C_(1.0f)), MUL_(n, n));
}

/* G1 = 2n / (n + sqrt(w(n))): a sum of positive terms and a quotient
 * (the root x rsqrt(x) of a normal, the divisor >= 2^-6) */
FACET_INLINE V_ FACET_K(smith_g1)(V_ nov, V_ alpha)
{
    V_ n = X16_COS_(nov), a = X16_ALPHA_(alpha);
    V_ r = SQRT_(X16_SMITH_W_(n, MUL_(a, a)));
    return NAN0_(MIN_(DIV_(ADD_(n, n), ADD_(n, r)), C_(1.0f)), nov, alpha);
}

/* G2 = 2 nl nv / (nv sqrt(w(nl)) + nl sqrt(w(nv))) (= 4 nl nv Vis), the
 * denominator >= 2 nl nv >= 2^-13 */
FACET_INLINE V_ FACET_K(smith_g2)(V_ nol, V_ nov, V_ alpha)
{
    V_ nl = X16_COS_(nol), nv = X16_COS_(nov), a = X16_ALPHA_(alpha);
    V_ a2 = MUL_(a, a);
    V_ den = ADD_(MUL_(nv, SQRT_(X16_SMITH_W_(nl, a2))), MUL_(nl, SQRT_(X16_SMITH_W_(nv, a2))));
    V_ p = MUL_(nl, nv);
    return NAN0_(MIN_(DIV_(ADD_(p, p), den), C_(1.0f)), nol, nov, alpha);
}

/* G1(L) G1(V) = 4 nl nv / ((nl + sqrt(w(nl))) (nv + sqrt(w(nv)))): one
 * quotient, its divisor >= 4 nl nv >= 2^-12 */
FACET_INLINE V_ FACET_K(smith_g2_uncorrelated)(V_ nol, V_ nov, V_ alpha)
{
    V_ nl = X16_COS_(nol), nv = X16_COS_(nov), a = X16_ALPHA_(alpha);
    V_ a2 = MUL_(a, a);
    V_ dl = ADD_(nl, X16_SQRT_N_(X16_SMITH_W_(nl, a2)));
    V_ dv = ADD_(nv, X16_SQRT_N_(X16_SMITH_W_(nv, a2)));
    V_ p = MUL_(nl, nv);
    return NAN0_(MIN_(DIV_(MUL_(C_(4.0f), p), MUL_(dl, dv)), C_(1.0f)), nol, nov, alpha);
}

/* Hammon's G1 ~ 2n / (n (2 - alpha) + alpha): positive terms, divisor >= 2^-7 */
FACET_INLINE V_ FACET_K(smith_g1_hammon)(V_ nov, V_ alpha)
{
    V_ n = X16_COS_(nov), a = X16_ALPHA_(alpha);
    V_ den = FMA_(n, SUB_(C_(2.0f), a), a);
    return NAN0_(MIN_(DIV_(ADD_(n, n), den), C_(1.0f)), nov, alpha);
}

/* ---- Hammon's diffuse --------------------------------------------------------
 * As f32_body.h: Q(x) (X16_POW5_Q_ above), smooth / pi = (1.05 / pi) nl nv Q(nl) Q(nv), rough from
 * t = max(1 + L.V, s^2 / 2) and h = 0.5 / N.H = 1 / (s rsqrt(t / 2)) >= 1/2
 * (three roundings: the rsqrt, the product, the reciprocal),
 * single = ((1 - alpha) smooth + alpha rough) / pi, multi = 0.1159 alpha,
 * diffuse = albedo (single + albedo multi): every sum of positive terms. */
/* h = 0.5 / N.H from t and s */
FACET_INLINE V_ X16_HALF_INV_NH_(V_ t, V_ s)
{
    return MAX_(RCP_(MUL_(s, RSQRT_(MUL_(C_(0.5f), t)))), C_(0.5f));
}

/* the diffuse from h, t and smooth / pi (Hammon's and his variants') */
FACET_INLINE V_ X16_DIFFUSE_S_(V_ h, V_ t, V_ a, V_ alb, V_ smooth)
{
    V_ ar = MUL_(MUL_(a, t), FNMA_(C_(0.0318309886f), t, C_(0.143239449f)));
    V_ single = FMA_(ar, h, FMA_(SUB_(C_(1.0f), a), smooth, ar));
    return MUL_(alb, FMA_(alb, MUL_(C_(0.1159f), a), single));
}

/* (h first, then smooth: the order the Helium table's counts were taken in) */
FACET_INLINE V_ X16_DIFFUSE_(V_ nl, V_ nv, V_ t, V_ s, V_ a, V_ alb)
{
    V_ h = X16_HALF_INV_NH_(t, s);
    V_ smooth = MUL_(MUL_(nl, nv), MUL_(X16_POW5_Q_(nl, C_(1.0f)), X16_POW5_Q_(nv, C_(0.334225380f))));
    return X16_DIFFUSE_S_(h, t, a, alb, smooth);
}

FACET_INLINE V_ FACET_K(diffuse_hammon)(V_ nol, V_ nov, V_ lov, V_ alpha, V_ albedo)
{
    V_ nl = X16_COS_(nol), nv = X16_COS_(nov);
    V_ s = ADD_(nl, nv);
    V_ t = MAX_(ADD_(C_(1.0f), X16_LOV_(lov)), MUL_(C_(0.5f), MUL_(s, s)));
    V_ d = X16_DIFFUSE_(nl, nv, t, s, X16_ALPHA_(alpha), X16_UNIT_(albedo));
    return NAN0_(d, nol, nov, lov, alpha, albedo);
}

/* Hammon's variants (f32_body.h's X_DIFFUSE_VARIANT_: diffuse_hammon's
 * rough, single and multi with another smooth term), on diffuse_hammon's
 * binary16 body.  The hybrid's smooth (1 - y_l^5 / 2)(1 - y_v^5 / 2) takes
 * each factor as 1/2 + (n / 2) Q(n) (1 - y^5 = n Q(n)): two positive terms,
 * where 1 - y^5 / 2 from a rounded y^5 would carry y^5's four roundings at
 * full weight next to N.L = 0; 1/pi folded into the second's constants. */
FACET_INLINE V_ FACET_K(diffuse_hammon_hybrid)(V_ nol, V_ nov, V_ lov, V_ alpha, V_ albedo)
{
    V_ nl = X16_COS_(nol), nv = X16_COS_(nov);
    V_ s = ADD_(nl, nv);
    V_ t = MAX_(ADD_(C_(1.0f), X16_LOV_(lov)), MUL_(C_(0.5f), MUL_(s, s)));
    V_ fl = FMA_(nl, X16_POW5_Q_(nl, C_(0.5f)), C_(0.5f));
    V_ fv = FMA_(nv, X16_POW5_Q_(nv, C_(0.159154943f)), C_(0.159154943f)); /* 0.5 / pi */
    V_ d = X16_DIFFUSE_S_(X16_HALF_INV_NH_(t, s), t, X16_ALPHA_(alpha), X16_UNIT_(albedo), MUL_(fl, fv));
    return NAN0_(d, nol, nov, lov, alpha, albedo);
}

/* Hammon's cheaper variant: smooth = 1 (Lambert), 1/pi as a constant */
FACET_INLINE V_ FACET_K(diffuse_hammon_cheap)(V_ nol, V_ nov, V_ lov, V_ alpha, V_ albedo)
{
    V_ nl = X16_COS_(nol), nv = X16_COS_(nov);
    V_ s = ADD_(nl, nv);
    V_ t = MAX_(ADD_(C_(1.0f), X16_LOV_(lov)), MUL_(C_(0.5f), MUL_(s, s)));
    V_ d = X16_DIFFUSE_S_(X16_HALF_INV_NH_(t, s), t, X16_ALPHA_(alpha), X16_UNIT_(albedo),
                            C_(0.318309886f));
    return NAN0_(d, nol, nov, lov, alpha, albedo);
}

/* Burley's diffuse: albedo / pi fl fv, each factor
 * 1 + (f_d90 - 1) y^5 = (1 - y^5 / 2) + g y^5,  g = 2 sqrt(alpha) L.H^2 >= 0
 * (f_d90 - 1 = g - 1/2 would cancel): two positive terms, the first as the
 * hybrid's, y^5 as fresnel_schlick's. */
FACET_INLINE V_ FACET_K(diffuse_burley)(V_ nol, V_ nov, V_ loh, V_ alpha, V_ albedo)
{
    V_ nl = X16_COS_(nol), nv = X16_COS_(nov), lh = X16_UNIT_(loh);
    V_ g = MUL_(MUL_(lh, lh), MUL_(C_(2.0f), X16_SQRT_N_(X16_ALPHA_(alpha))));
    V_ fl = FMA_(g, X16_POW5_Y_(nl), FMA_(nl, X16_POW5_Q_(nl, C_(0.5f)), C_(0.5f)));
    V_ fv = FMA_(MUL_(g, C_(0.318309886f)), X16_POW5_Y_(nv),
                 FMA_(nv, X16_POW5_Q_(nv, C_(0.159154943f)), C_(0.159154943f))); /* / pi */
    V_ d = MUL_(X16_UNIT_(albedo), MUL_(fl, fv));
    return NAN0_(d, nol, nov, loh, alpha, albedo);
}

/* Oren-Nayar (f32_body.h: A + B max(0, L.V - N.L N.V) / max(N.L, N.V), with
 * sigma^2 = alpha^2 / 4), its constants rescaled for binary16 (0.33, 0.09 and
 * 0.45 round there by up to 0.9 u): with Q = alpha^2 (>= 2^-14, normal),
 *   A = h1 / u1,  u1 = 1 + Q / 1.32,  h1 = 1 + Q / 2.64,
 *   B = 1.25 Q / u2,  u2 = 1 + Q / 0.36,
 *   pi f / albedo = (h1 w + 1.25 Q u1 x) / (u1 w),  w = u2 m,
 * x = max(L.V - N.L N.V, 0) (one fnma), m = max(N.L, N.V) >= 2^-7:
 * positive terms, one quotient, 1/pi folded into the numerator's constants.
 * 1/1.32 and 1/0.36 round within 0.7 u of themselves, which moves A and B
 * by 0.1 u and 0.3 u; 1/pi's binary16 is 0.32 u high (as lambert's). */
FACET_INLINE V_ FACET_K(diffuse_oren_nayar)(V_ nol, V_ nov, V_ lov, V_ alpha, V_ albedo)
{
    V_ nl = X16_COS_(nol), nv = X16_COS_(nov), a = X16_ALPHA_(alpha);
    V_ q = MUL_(a, a);
    V_ x = MAX_(FNMA_(nl, nv, X16_LOV_(lov)), C_(0.0f));
    V_ u1 = FMA_(C_(0.757575758f), q, C_(1.0f));
    V_ h1 = FMA_(C_(0.120571927f), q, C_(0.318309886f)); /* h1 / pi */
    V_ w = MUL_(FMA_(C_(2.77777778f), q, C_(1.0f)), MAX_(nl, nv));
    V_ num = FMA_(MUL_(MUL_(C_(0.397887358f), q), u1), x, MUL_(h1, w)); /* / pi */
    V_ d = MUL_(X16_UNIT_(albedo), DIV_(num, MUL_(u1, w)));
    return NAN0_(d, nol, nov, lov, alpha, albedo);
}

/* ---- the whole model ----------------------------------------------------------
 * D(N.H) Vis_hammon F(f0, L.H) + diffuse_hammon, from the three dots (the
 * algebra of f32_body.h's brdf_hammon).  The specular factor is where
 * binary16 cannot hold the bound: the peak e = (2t - s^2) + alpha^2 s^2
 * cancels (2t - s^2 needs s^2 exactly: 36 bits for binary16 inputs), F's
 * (1 - L.H)^5 raises one rounding of 1 - L.H five times, and D Vis F spans
 * 2^-18 .. 2^24 (F takes D Vis above 65504 back below it, and binary16's
 * subnormals would keep too few bits of a small F that D Vis raises).  So
 * the specular term runs in f32 lanes, from the exact binary16 inputs, with
 * as few operations as its bound needs:
 *   s = N.L + N.V        exact in f32 (at most 18 significant bits above the
 *                        cosine floor 2^-7)
 *   2t = 2 + 2 L.V       rounded, and its rounding error t2l exactly (it is
 *                        non-zero only for 0 < L.V < 2^-13)
 *   num = 2t - s^2       fnma(s, s, 2t) + t2l: one rounding of the exact
 *                        2t - s^2 and one of the sum, each relative to num
 *                        itself; negative (no unit vectors have these dots)
 *                        to 0, and 2t then raised to s^2 (the contract's
 *                        extension), as f32_body.h
 *   e = num + alpha^2 s^2 (alpha^2 exact in f32)
 *   D Vis = (u mh) (u / (4 pi)),  u = alpha 2t / (e mh),
 *                        mh = nl nv + alpha (s/2 - nl nv) (positive terms)
 *   y = 1 - L.H = w / (2 + sqrt(2t)),  w = 2 - t = min(1 - L.V, 2 - s^2/2)
 *                        (each side without cancellation)
 *   spec = D Vis (f0 + (1 - f0) y^5)
 * with the port's f32 estimates (2^-14 on avx512fp16: 5 (1.5 2^-14) in y^5,
 * 2^-14 in u^2), narrowed once (above 65504 it may give +Inf, which the
 * final min turns into 65504).  The rest is binary16 and is diffuse_hammon's
 * body itself (so brdf_hammon - spec is diffuse_hammon to the bit): the
 * diffuse and the sum, saturated at 65504 (never Inf). */
FACET_INLINE V_ FACET_K(brdf_hammon)(V_ nol, V_ nov, V_ lov, V_ alpha, V_ f0, V_ albedo)
{
    V_ nl = X16_COS_(nol), nv = X16_COS_(nov), lv = X16_LOV_(lov), a = X16_ALPHA_(alpha);
    V_ f = X16_UNIT_(f0);
    W_ nlw = WIDEN_(nl), nvw = WIDEN_(nv), lvw = WIDEN_(lv), aw = WIDEN_(a), fw = WIDEN_(f);
    W_ sw = WADD_(nlw, nvw);                                             /* exact */
    W_ t2 = WFMA_(lvw, WC_(2.0f), WC_(2.0f));                            /* 2t, rounded */
    W_ t2l = WFMA_(lvw, WC_(2.0f), WSUB_(WC_(2.0f), t2));                /* 2t = t2 + t2l */
    W_ p = WMUL_(sw, sw);
    W_ num = WMAX_(WADD_(WFNMA_(sw, sw, t2), t2l), WC_(0.0f));
    W_ e = WFMA_(WMUL_(aw, aw), p, num);
    W_ tt = WMAX_(t2, p);                                                /* 2t, raised */
    W_ p2 = WMUL_(nlw, nvw);
    W_ mh = WFMA_(aw, WFNMA_(nlw, nvw, WMUL_(WC_(0.5f), sw)), p2);
    W_ u = WMUL_(WMUL_(aw, tt), WRCP_(WMUL_(e, mh)));
    W_ dv = WMUL_(WMUL_(u, mh), WMUL_(u, WC_(0.0795774715f)));          /* 1 / (4 pi) */
    W_ w = WMIN_(WSUB_(WC_(1.0f), lvw), WFNMA_(WC_(0.5f), p, WC_(2.0f)));
    W_ y = WMUL_(w, WRCP_(WADD_(WMUL_(tt, WRSQRT_(tt)), WC_(2.0f))));
    W_ y2 = WMUL_(y, y);
    W_ spec = WMUL_(dv, WFMA_(WSUB_(WC_(1.0f), fw), WMUL_(WMUL_(y2, y2), y), fw));
    V_ s = ADD_(nl, nv);
    V_ t = MAX_(ADD_(C_(1.0f), lv), MUL_(C_(0.5f), MUL_(s, s)));
    V_ dif = X16_DIFFUSE_(nl, nv, t, s, a, X16_UNIT_(albedo));
    V_ r = MIN_(ADD_(NARROW_(spec), dif), C_(65504.0f));
    return NAN0_(r, nol, nov, lov, alpha, f0, albedo);
}

/* Lambert: albedo / pi (one rounding and 1/pi's). */
FACET_INLINE V_ FACET_K(lambert)(V_ albedo)
{
    return NAN0_(MUL_(X16_UNIT_(albedo), C_(0.318309886f)), albedo);
}

#undef V_
#undef W_
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
#undef RCP_
#undef RSQRT_
#undef DIV_
#undef SQRT_
#undef WC_
#undef WADD_
#undef WSUB_
#undef WMUL_
#undef WFMA_
#undef WFNMA_
#undef WMIN_
#undef WMAX_
#undef WRCP_
#undef WRSQRT_
#undef WIDEN_
#undef NARROW_
#undef X16_UNIT_
#undef X16_COS_
#undef X16_ALPHA_
#undef X16_LOV_
#undef X16_POW5_Q_
#undef X16_DIFFUSE_
#undef X16_DIFFUSE_S_
#undef X16_HALF_INV_NH_
#undef X16_POW5_Y_
#undef X16_SMITH_W_
#undef X16_SQRT_N_
#undef NAN0_
#undef NAN0_SEL_
#undef NAN0_1_
#undef NAN0_2_
#undef NAN0_3_
#undef NAN0_4_
#undef NAN0_5_
#undef NAN0_6_
