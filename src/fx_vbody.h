/* fx_vbody.h - the fixed-point kernels on vectors, written once over a small
 * op layer and instantiated by each SIMD port (ports/<isa>/fx_<isa>.c).
 * Private to the library; the scalar code (src/fx_core.[ch],
 * src/fx_kernels.c) is the specification and this is a lane-wise
 * transcription of it, bit for bit (tests/test_fx_ports.c).
 *
 * Lanes.  One lane = one uint64_t, the widest type the scalar code uses, so
 * every scalar expression maps to the same expression on lanes:
 *   uint64 arithmetic      -> the lane op (wraps mod 2^64 as in C)
 *   uint32 arithmetic      -> the lane op, then v_lo() where C would wrap
 *   fx_mul64(a, b)         -> fv_mul32 (32x32->64 of the low words: vpmuludq,
 *                             vmull.u32), exact as in C
 *   int32 exponents (fxf.e) -> two's complement in the lane; signed
 *                             compares with fv_sgt, /2 of an even value by v_sra1
 *   if/else                -> both sides computed, fv_sel by the condition
 * Lanes the scalar code would not reach in a branch (a divisor that is 0
 * because the result is the early-return value, say) are computed on and
 * discarded; the two primitives with loops or tables sanitise their operand
 * (v_rcp32 sets bit 31, v_isqrt64 replaces 0 by 1, table indexes are masked)
 * so such lanes cannot read out of bounds or spin.
 *
 * Data-dependent loops (rcp32's and isqrt64's fix-ups, noh_from_dots' +-1
 * steps) run "while any lane still steps", each lane stepping under its own
 * mask exactly when the scalar loop would, so every lane does the scalar
 * arithmetic step for step and the result is exact whatever the count.  The
 * counts are small (each lane stops where the scalar one does; measured with
 * counters in the scalar code): rcp32 at most 4 down / 2 up over all 2^31
 * divisors (exhaustive), isqrt64 at most 4 / 4 (2e7 random radicands and
 * the kernels' own: the rsqrt estimate is within 2^-29 relative), the noh
 * steps at most 1 / 1 (its estimate is within 1, fx_kernels.c).
 *
 * The port defines, before including this file:
 *   fv, FXV_W                  vector of FXV_W uint64_t lanes
 *   fv_set(c)  fv_add fv_sub fv_and fv_or fv_xor
 *   fv_shl(a, k) fv_shr(a, k)  uniform shift, 0 <= k <= 63
 *   fv_shlv(a, k) fv_shrv(a, k) per-lane shift, 0 <= k <= 63 (other counts:
 *                              any value, no trap)
 *   fv_mul32(a, b)             (a mod 2^32) (b mod 2^32)
 *   fv_gt(a, b) fv_sgt(a, b) fv_eq(a, b)   unsigned >, signed >, == (masks)
 *   fv_sel(m, a, b)            m ? a : b per lane
 *   fv_any(m)                  some lane of mask m set
 *   fv_clz64(x)                leading zeros of each nonzero lane
 *   fv_lut(t, i)               t[i] of a uint32_t table, 0 <= i < 32
 *   fv_load(p)                 FXV_W int32_t sign-extended
 *   fv_store32(p, v) fv_store64(p, v)   low words / whole lanes, unaligned
 *   FXV_PORT                   the port's name token (avx2, neon)
 *   FXV_FASTER                 (optional) FX_BIT mask of the kernels to dispatch
 *                              here; the others run the scalar loop (fx_port.h)
 */
#include "facet/fx.h"
#include "fx_port.h"
#include "fx_core.h" /* the seed table values */

#define FXV_ONE 32768u
#define FXV_STR_(x) #x
#define FXV_STR(x) FXV_STR_(x)
#define FXV_CAT_(a, b) a##b
#define FXV_CAT(a, b) FXV_CAT_(a, b)

typedef struct { fv m, e; } vf; /* fxf per lane */

static inline fv v_k(uint64_t c) { return fv_set(c); }
static inline fv v_ks(int64_t c) { return fv_set((uint64_t)c); }
static inline fv v_zero(void) { return fv_set(0); }
static inline fv v_one(void) { return fv_set(1); }
static inline fv v_m32(void) { return fv_set(0xFFFFFFFFu); }
static inline fv v_lo(fv a) { return fv_and(a, v_m32()); }
static inline fv v_not(fv m) { return fv_xor(m, fv_set(~(uint64_t)0)); }
static inline fv v_ge(fv a, fv b) { return v_not(fv_gt(b, a)); }
static inline fv v_b01(fv m) { return fv_and(m, v_one()); }
static inline fv v_min(fv a, fv b) { return fv_sel(fv_gt(a, b), b, a); }
static inline fv v_max(fv a, fv b) { return fv_sel(fv_gt(a, b), a, b); }
static inline fv v_inc(fv a) { return fv_add(a, v_one()); }
static inline fv v_dec(fv a) { return fv_sub(a, v_one()); }
/* round(x / 2^k), ties up, 1 <= k <= 63 (fx_rshr64) */
static inline fv v_rshr(fv x, fv k) { return fv_add(fv_shrv(x, k), v_b01(fv_shrv(x, v_dec(k)))); }
/* arithmetic >> 1 of a two's complement lane (exact /2 of an even value) */
static inline fv v_sra1(fv a) { return fv_or(fv_shr(a, 1), fv_and(a, fv_set((uint64_t)1 << 63))); }
/* fx_kernels.c's mul64x32 */
static inline fv v_mul64x32(fv x, fv y) { return fv_add(fv_mul32(x, y), fv_shl(fv_mul32(fv_shr(x, 32), y), 32)); }
static inline vf vf_sel(fv m, vf a, vf b)
{
    vf r;
    r.m = fv_sel(m, a.m, b.m);
    r.e = fv_sel(m, a.e, b.e);
    return r;
}
static inline vf vf_k(uint32_t m, int32_t e)
{
    vf r;
    r.m = v_k(m);
    r.e = v_ks(e);
    return r;
}

/* the seed tables of src/fx_core.c (the same values, widened to 32 bits for
 * the gathers; the rsqrt table padded to 32 so a masked index stays inside) */
static const uint32_t V_RCP_SEED[32] = { FX_RCP_SEED_VALUES };
static const uint32_t V_RSQRT_SEED[32] = { FX_RSQRT_SEED_VALUES }; /* rest 0 */

/* ---- facet_fx_rcp32 ------------------------------------------------------ */
static inline fv v_rcp32(fv d)
{
    const fv c = v_k(0x80000000u), m32 = v_m32();
    fv r, v, n, p, m;
    int i;
    d = fv_or(v_lo(d), c); /* identity on the scalar domain [2^31, 2^32) */
    r = fv_shl(fv_lut(V_RCP_SEED, fv_and(fv_sub(fv_shr(d, 26), v_k(32)), v_k(31))), 16);
    for (i = 0; i < 3; i++) {
        fv h = fv_shr(fv_mul32(d, r), 32);
        fv up = fv_gt(h, c);
        fv q = fv_shr(fv_mul32(r, fv_sel(up, fv_sub(h, c), fv_sub(c, h))), 31);
        r = fv_sel(up, fv_sub(r, q), fv_add(r, q));
        r = fv_sel(fv_gt(r, m32), m32, r);
    }
    v = v_lo(fv_shl(r, 1));
    n = fv_or(fv_shl(v_lo(fv_xor(d, m32)), 32), m32);
    p = fv_mul32(v, d);
    m = fv_gt(p, n);
    while (fv_any(m)) {
        v = fv_sel(m, v_lo(v_dec(v)), v);
        p = fv_sel(m, fv_sub(p, d), p);
        m = fv_and(m, fv_gt(p, n));
    }
    m = fv_and(v_ge(fv_sub(n, p), d), v_not(fv_eq(v, m32)));
    while (fv_any(m)) {
        v = fv_sel(m, v_inc(v), v);
        p = fv_sel(m, fv_add(p, d), p);
        m = fv_and(m, fv_and(v_ge(fv_sub(n, p), d), v_not(fv_eq(v, m32))));
    }
    return v;
}

/* ---- facet_fx_div2by1 ---------------------------------------------------- */
static inline fv v_div2by1(fv u1, fv u0, fv d, fv v, fv *r)
{
    fv q = fv_add(fv_mul32(v, u1), fv_or(fv_shl(v_lo(v_inc(u1)), 32), u0));
    fv q1 = fv_shr(q, 32), q0 = v_lo(q);
    fv rem = v_lo(fv_sub(u0, fv_mul32(q1, d)));
    fv m = fv_gt(rem, q0);
    q1 = fv_sel(m, v_lo(v_dec(q1)), q1);
    rem = fv_sel(m, v_lo(fv_add(rem, d)), rem);
    m = v_ge(rem, d);
    q1 = fv_sel(m, v_lo(v_inc(q1)), q1);
    rem = fv_sel(m, fv_sub(rem, d), rem);
    *r = rem;
    return q1;
}

/* ---- facet_fx_rsqrt32 ---------------------------------------------------- */
static inline fv v_rsqrt32(fv x)
{
    fv y = fv_shl(fv_lut(V_RSQRT_SEED, fv_and(fv_sub(fv_shr(x, 27), v_k(8)), v_k(31))), 16);
    int i;
    for (i = 0; i < 3; i++) {
        fv y2 = fv_shr(fv_mul32(y, y), 32);
        fv xy2 = fv_shr(fv_mul32(x, y2), 32);
        fv h = v_lo(fv_sub(v_k(0xC0000000u), xy2));
        fv m = fv_shr(fv_mul32(y, h), 32);
        y = fv_sel(fv_gt(m, v_k(0x7FFFFFFFu)), v_m32(), v_lo(fv_shl(m, 1)));
    }
    return y;
}

/* ---- facet_fx_isqrt64, fx_isqrt64_rnd ------------------------------------ */
static inline fv v_isqrt64(fv x)
{
    const fv m32 = v_m32();
    fv z = fv_eq(x, v_zero()), xs, s, t, gg, g, g1, m;
    xs = fv_sel(z, v_one(), x);
    s = fv_and(fv_clz64(xs), v_k(~(uint64_t)1));
    t = fv_shr(fv_shlv(xs, s), 32);
    gg = fv_shr(fv_mul32(t, v_rsqrt32(t)), 31);
    gg = fv_shrv(gg, fv_shr(s, 1));
    g = v_min(gg, m32);
    m = fv_gt(fv_mul32(g, g), xs);
    while (fv_any(m)) {
        g = fv_sel(m, v_dec(g), g);
        m = fv_and(m, fv_gt(fv_mul32(g, g), xs));
    }
    g1 = v_lo(v_inc(g));
    m = fv_and(v_not(fv_eq(g, m32)), v_not(fv_gt(fv_mul32(g1, g1), xs)));
    while (fv_any(m)) {
        g = fv_sel(m, v_inc(g), g);
        g1 = v_lo(v_inc(g));
        m = fv_and(m, fv_and(v_not(fv_eq(g, m32)), v_not(fv_gt(fv_mul32(g1, g1), xs))));
    }
    return fv_sel(z, v_zero(), g);
}

static inline fv v_isqrt64_rnd(fv x)
{
    fv g = v_isqrt64(x);
    return fv_add(g, v_b01(fv_gt(fv_sub(x, fv_mul32(g, g)), g)));
}

/* ---- fxf ------------------------------------------------------------------ */
static inline vf vf_u64(fv x, fv e)
{
    const fv k32 = v_k(32);
    fv z = fv_eq(x, v_zero()), xs, lz, small, k, mb, eb, ov;
    vf r;
    xs = fv_sel(z, v_one(), x);
    lz = fv_clz64(xs);
    small = v_ge(lz, k32);
    k = fv_sub(k32, lz); /* 1..32 where !small */
    mb = v_rshr(xs, k);
    eb = fv_add(e, k);
    ov = fv_gt(mb, v_m32());
    mb = fv_sel(ov, fv_shr(mb, 1), mb);
    eb = fv_sel(ov, v_inc(eb), eb);
    r.m = fv_sel(small, v_lo(fv_shlv(xs, fv_sub(lz, k32))), mb);
    r.e = fv_sel(small, fv_sub(e, fv_sub(lz, k32)), eb);
    r.m = fv_sel(z, v_zero(), r.m);
    r.e = fv_sel(z, v_zero(), r.e);
    return r;
}

static inline vf vf_from_prod(fv p, fv e)
{
    fv top = fv_gt(p, v_k(0x7FFFFFFFFFFFFFFFull)), ov;
    vf r;
    r.m = fv_sel(top, fv_add(fv_shr(p, 32), v_b01(fv_shr(p, 31))),
                 fv_add(fv_shr(p, 31), v_b01(fv_shr(p, 30))));
    r.e = fv_add(e, fv_sel(top, v_k(32), v_k(31)));
    ov = fv_gt(r.m, v_m32());
    r.m = fv_sel(ov, fv_shr(r.m, 1), r.m);
    r.e = fv_sel(ov, v_inc(r.e), r.e);
    return r;
}

static inline vf vf_mul(vf a, vf b)
{
    fv z = fv_or(fv_eq(a.m, v_zero()), fv_eq(b.m, v_zero()));
    vf r = vf_from_prod(fv_mul32(a.m, b.m), fv_add(a.e, b.e));
    r.m = fv_sel(z, v_zero(), r.m);
    r.e = fv_sel(z, v_zero(), r.e);
    return r;
}

static inline vf vf_add(vf a, vf b)
{
    fv az = fv_eq(a.m, v_zero()), bz = fv_eq(b.m, v_zero());
    fv sw = fv_sgt(b.e, a.e), d, bs;
    vf x = vf_sel(sw, b, a), y = vf_sel(sw, a, b), r;
    d = fv_sub(x.e, y.e); /* >= 0 */
    bs = fv_sel(fv_eq(d, v_k(32)), fv_shr(y.m, 1), fv_shlv(y.m, fv_sub(v_k(31), d)));
    r = vf_u64(fv_add(fv_shl(x.m, 31), bs), fv_sub(x.e, v_k(31)));
    r = vf_sel(fv_gt(d, v_k(32)), x, r);
    r = vf_sel(az, b, r);
    return vf_sel(bz, a, r);
}

static inline vf vf_div(vf a, vf b)
{
    fv az = fv_eq(a.m, v_zero()), rem, q, hi, bit, rem2, mh, ml, e, ov;
    vf r;
    q = v_div2by1(fv_shr(a.m, 1), v_lo(fv_shl(a.m, 31)), b.m, v_rcp32(b.m), &rem);
    e = fv_sub(fv_sub(a.e, b.e), v_k(31));
    hi = fv_gt(q, v_k(0x7FFFFFFFu));
    bit = v_ge(rem, fv_sub(b.m, rem));
    mh = fv_add(q, v_b01(bit));
    rem2 = v_lo(fv_sel(bit, fv_sub(rem, fv_sub(b.m, rem)), fv_shl(rem, 1)));
    ml = fv_add(fv_or(fv_shl(q, 1), v_b01(bit)), v_b01(v_ge(rem2, fv_sub(b.m, rem2))));
    r.m = fv_sel(hi, mh, ml);
    e = fv_sel(hi, e, v_dec(e));
    ov = fv_gt(r.m, v_m32());
    r.m = fv_sel(ov, fv_shr(r.m, 1), r.m);
    r.e = fv_sel(ov, v_inc(e), e);
    return vf_sel(az, a, r);
}

static inline vf vf_sqrt(vf a)
{
    fv az = fv_eq(a.m, v_zero());
    fv odd = fv_eq(fv_and(a.e, v_one()), v_one()), x, e2, g, ov;
    vf r;
    x = fv_sel(odd, fv_shl(a.m, 31), fv_shl(a.m, 32));
    e2 = fv_sub(a.e, fv_sel(odd, v_k(31), v_k(32)));
    g = v_isqrt64_rnd(x);
    r.e = v_sra1(e2);
    ov = fv_gt(g, v_m32());
    r.m = fv_sel(ov, fv_shr(g, 1), g);
    r.e = fv_sel(ov, v_inc(r.e), r.e);
    return vf_sel(az, a, r);
}

static inline vf vf_sqrt64(fv x, int32_t e0)
{
    fv e = v_ks(e0), z = fv_eq(x, v_zero()), xs, s, neg, xn, g, ov;
    vf r;
    xs = fv_sel(z, v_one(), x);
    s = fv_clz64(xs);
    s = fv_sel(fv_eq(fv_and(fv_sub(e, s), v_one()), v_one()), v_dec(s), s);
    neg = fv_sgt(v_zero(), s);
    xn = fv_sel(neg, fv_add(fv_shr(xs, 1), fv_and(xs, v_one())), fv_shlv(xs, s));
    g = v_isqrt64_rnd(xn);
    r.e = v_sra1(fv_sub(e, s));
    ov = fv_gt(g, v_m32());
    r.m = fv_sel(ov, fv_shr(g, 1), g);
    r.e = fv_sel(ov, v_inc(r.e), r.e);
    r.m = fv_sel(z, v_zero(), r.m);
    r.e = fv_sel(z, v_zero(), r.e);
    return r;
}

static inline fv vf_fixed(vf a, int32_t f, uint64_t max)
{
    fv nk = fv_add(a.e, v_ks(f)), k = fv_sub(v_zero(), nk), vmax = v_k(max), sat, r1, r2, r;
    sat = fv_or(fv_sgt(nk, v_k(31)), fv_gt(a.m, fv_shrv(vmax, nk)));
    r1 = fv_sel(sat, vmax, fv_shlv(a.m, nk));
    r2 = fv_sel(fv_sgt(k, v_k(32)), v_zero(), v_rshr(a.m, k));
    r = fv_sel(fv_sgt(k, v_zero()), r2, r1);
    r = v_min(r, vmax);
    return fv_sel(fv_eq(a.m, v_zero()), v_zero(), r);
}

static inline fv vf_div_fixed(vf a, vf b, int32_t f, uint32_t max)
{
    fv vmax = v_k(max), k, q, rem, r0, raw;
    k = fv_sub(v_k(31), fv_add(fv_sub(a.e, b.e), v_ks(f)));
    q = v_div2by1(fv_shr(a.m, 1), v_lo(fv_shl(a.m, 31)), b.m, v_rcp32(b.m), &rem);
    r0 = fv_sel(fv_eq(q, v_m32()), vmax, fv_add(q, v_b01(v_ge(rem, fv_sub(b.m, rem)))));
    raw = fv_sel(fv_eq(k, v_zero()), r0, v_rshr(q, k));
    raw = v_min(raw, vmax);
    raw = fv_sel(fv_sgt(v_zero(), k), vmax, raw);
    raw = fv_sel(fv_sgt(k, v_k(32)), v_zero(), raw);
    return fv_sel(fv_eq(a.m, v_zero()), v_zero(), raw);
}

/* ---- input clamping (fx_kernels.c) --------------------------------------- */
static inline fv v_clamp(fv x, int32_t lo, int32_t hi)
{
    fv l = v_ks(lo), h = v_ks(hi);
    x = fv_sel(fv_sgt(l, x), l, x);
    return fv_sel(fv_sgt(x, h), h, x);
}
static inline fv v_unit(fv x) { return v_clamp(x, 0, FACET_FX_ONE); }
static inline fv v_cos(fv x) { return v_clamp(x, FACET_FX_COS_MIN, FACET_FX_ONE); }
static inline fv v_alpha(fv x) { return v_clamp(x, FACET_FX_ALPHA_MIN, FACET_FX_ONE); }
static inline fv v_t(fv lov) { return fv_add(v_clamp(lov, -FACET_FX_ONE, FACET_FX_ONE), v_k(FXV_ONE)); }
static inline fv v_t31(fv t, fv s) { return v_max(fv_shl(t, 16), fv_mul32(s, s)); }
static inline fv v_omc(fv x) { return fv_sub(v_k(FXV_ONE), x); } /* 1 - x */
static inline fv v_opc(fv x) { return fv_add(v_k(FXV_ONE), x); } /* 1 + x */

/* ---- kernels ---------------------------------------------------------------- */
static inline fv vk_noh_from_dots(const fv *x)
{
    fv s = fv_add(v_cos(x[0]), v_cos(x[1])), t = v_t(x[2]), s2, top, act, k, m, k2;
    s2 = fv_shl(fv_mul32(s, s), 16);
    top = v_ge(s2, fv_shl(t, 32));
    act = v_not(top);
    k = vf_div_fixed(vf_u64(s, v_k(7)), vf_sqrt(vf_u64(t, v_zero())), 0, FXV_ONE);
    k2 = v_dec(fv_shl(k, 1));
    m = fv_and(act, fv_and(fv_gt(k, v_zero()), fv_gt(v_mul64x32(fv_mul32(k2, k2), t), s2)));
    while (fv_any(m)) {
        k = fv_sel(m, v_dec(k), k);
        k2 = v_dec(fv_shl(k, 1));
        m = fv_and(m, fv_and(fv_gt(k, v_zero()), fv_gt(v_mul64x32(fv_mul32(k2, k2), t), s2)));
    }
    k2 = v_inc(fv_shl(k, 1));
    m = fv_and(act, fv_and(fv_gt(v_k(FXV_ONE), k), v_not(fv_gt(v_mul64x32(fv_mul32(k2, k2), t), s2))));
    while (fv_any(m)) {
        k = fv_sel(m, v_inc(k), k);
        k2 = v_inc(fv_shl(k, 1));
        m = fv_and(m, fv_and(fv_gt(v_k(FXV_ONE), k),
                             v_not(fv_gt(v_mul64x32(fv_mul32(k2, k2), t), s2))));
    }
    return fv_sel(top, v_k(FXV_ONE), k);
}

static inline fv vk_loh_from_dots(const fv *x) { return v_isqrt64_rnd(fv_shl(v_t(x[0]), 14)); }

static inline fv vk_fresnel_schlick(const fv *x)
{
    fv f0 = v_unit(x[0]), y = v_omc(v_unit(x[1]));
    fv p = fv_mul32(y, v_omc(f0)), yy = fv_mul32(y, y), y4 = fv_mul32(yy, yy);
    fv lo = fv_mul32(p, y4), zhi = fv_add(fv_mul32(p, fv_shr(y4, 32)), fv_shr(lo, 32));
    return fv_add(f0, fv_add(fv_shr(zhi, 43), v_b01(fv_shr(zhi, 42))));
}

#define FXV_INV_PI_2_64 0x517CC1B727220A94ull /* floor(2^64 / pi) */
#define FXV_PI_M 0xC90FDAA2u                  /* round(pi 2^30) */

static inline fv vk_ggx_d(const fv *x)
{
    fv n = v_unit(x[0]), a = v_alpha(x[1]), a2 = fv_mul32(a, a), s, u, dd, q, rem, rp, na, d60;
    vf d, den;
    /* N.H = 1 */
    s = fv_sub(fv_clz64(a2), v_k(32));
    u = fv_shrv(v_k(FXV_INV_PI_2_64), fv_sub(v_k(21), s));
    dd = v_lo(fv_shlv(a2, s));
    q = v_div2by1(fv_shr(u, 32), v_lo(u), dd, v_rcp32(dd), &rem);
    rp = v_lo(fv_add(q, v_b01(v_ge(rem, fv_sub(dd, rem)))));
    /* below the peak */
    na = fv_mul32(n, a);
    d60 = fv_add(fv_shl(fv_mul32(v_omc(n), v_opc(n)), 30), fv_mul32(na, na));
    d = vf_u64(d60, v_ks(-60));
    den = vf_mul(vf_k(FXV_PI_M, -30), vf_mul(d, d));
    return fv_sel(fv_eq(n, v_k(FXV_ONE)), rp,
                  vf_div_fixed(vf_u64(a2, v_ks(-30)), den, FACET_FX_D_FRAC, FACET_FX_MAX_D));
}

static inline vf v_smith_r(fv n, fv a2)
{
    fv w60 = fv_add(fv_mul32(a2, fv_mul32(v_omc(n), v_opc(n))), fv_shl(fv_mul32(n, n), 30));
    return vf_sqrt64(w60, -60);
}

static inline fv vk_smith_g1(const fv *x)
{
    fv n = v_unit(x[0]), a = v_alpha(x[1]);
    vf den = vf_add(vf_u64(n, v_ks(-15)), v_smith_r(n, fv_mul32(a, a)));
    return vf_div_fixed(vf_u64(fv_shl(n, 1), v_ks(-15)), den, 15, FXV_ONE);
}

static inline vf v_g2_den(fv nl, fv nv, fv a2)
{
    return vf_add(vf_mul(vf_u64(nv, v_ks(-15)), v_smith_r(nl, a2)),
                  vf_mul(vf_u64(nl, v_ks(-15)), v_smith_r(nv, a2)));
}

static inline fv vk_smith_g2(const fv *x)
{
    fv nl = v_cos(x[0]), nv = v_cos(x[1]), a = v_alpha(x[2]);
    return vf_div_fixed(vf_u64(fv_shl(fv_mul32(nl, nv), 1), v_ks(-30)), v_g2_den(nl, nv, fv_mul32(a, a)),
                        15, FXV_ONE);
}

static inline fv vk_smith_vis(const fv *x)
{
    fv nl = v_cos(x[0]), nv = v_cos(x[1]), a = v_alpha(x[2]);
    return vf_div_fixed(vf_k(0x80000000u, -32), v_g2_den(nl, nv, fv_mul32(a, a)), FACET_FX_VIS_FRAC,
                        FACET_FX_MAX_VIS);
}

static inline fv vk_smith_g2_uncorrelated(const fv *x)
{
    fv nl = v_cos(x[0]), nv = v_cos(x[1]), a = v_alpha(x[2]), a2 = fv_mul32(a, a);
    vf dl = vf_add(vf_u64(nl, v_ks(-15)), v_smith_r(nl, a2));
    vf dv = vf_add(vf_u64(nv, v_ks(-15)), v_smith_r(nv, a2));
    return vf_div_fixed(vf_u64(fv_shl(fv_mul32(nl, nv), 2), v_ks(-30)), vf_mul(dl, dv), 15, FXV_ONE);
}

static inline fv vk_smith_g1_hammon(const fv *x)
{
    fv n = v_unit(x[0]), a = v_alpha(x[1]);
    fv den30 = fv_add(fv_mul32(n, fv_sub(v_k(2 * FXV_ONE), a)), fv_shl(a, 15));
    return vf_div_fixed(vf_u64(fv_shl(n, 1), v_ks(-15)), vf_u64(den30, v_ks(-30)), 15, FXV_ONE);
}

static inline fv v_hammon_m45(fv nl, fv nv, fv a)
{
    return fv_add(v_mul64x32(fv_shl(fv_mul32(nl, nv), 1), v_omc(a)),
                  fv_shl(fv_mul32(a, fv_add(nl, nv)), 15));
}

static inline fv vk_smith_g2_hammon(const fv *x)
{
    fv nl = v_cos(x[0]), nv = v_cos(x[1]), a = v_alpha(x[2]);
    return vf_div_fixed(vf_u64(fv_shl(fv_mul32(nl, nv), 1), v_ks(-30)),
                        vf_u64(v_hammon_m45(nl, nv, a), v_ks(-45)), 15, FXV_ONE);
}

static inline fv vk_smith_vis_hammon(const fv *x)
{
    fv nl = v_cos(x[0]), nv = v_cos(x[1]), a = v_alpha(x[2]);
    return vf_div_fixed(vf_k(0x80000000u, -32), vf_u64(v_hammon_m45(nl, nv, a), v_ks(-45)),
                        FACET_FX_VIS_FRAC, FACET_FX_MAX_VIS);
}

#define FXV_C105_M 0x86666666u
#define FXV_MULTI_M 0xBA6CB3FCu
#define FXV_INV_PI_M 0xA2F9836Eu
#define FXV_TWO_PI_M 0xC90FDAA2u

static inline fv v_one_minus_pow5_q30(fv x)
{
    fv y = v_omc(x), yy = fv_mul32(y, y), y4 = fv_mul32(yy, yy);
    fv lo = fv_mul32(y, y4), zhi = fv_add(fv_mul32(y, fv_shr(y4, 32)), fv_shr(lo, 32));
    return fv_sub(v_k(1u << 30), fv_add(fv_shr(zhi, 13), v_b01(fv_shr(zhi, 12))));
}

static inline vf v_diffuse(fv nl, fv nv, fv t31, fv a, fv alb)
{
    fv s = fv_add(nl, nv);
    vf t = vf_u64(t31, v_ks(-31));
    vf tt = vf_mul(t, vf_u64(fv_sub(v_k(9ull << 30), t31), v_ks(-31)));
    vf sum = vf_add(vf_u64(s, v_ks(-14)), vf_sqrt(vf_u64(t31, v_ks(-30))));
    vf rough = vf_div(vf_mul(tt, sum), vf_u64(fv_mul32(v_k(20), s), v_ks(-15)));
    vf smooth = vf_mul(vf_mul(vf_u64(v_one_minus_pow5_q30(nl), v_ks(-30)),
                              vf_u64(v_one_minus_pow5_q30(nv), v_ks(-30))), vf_k(FXV_C105_M, -31));
    vf single = vf_add(vf_mul(vf_u64(v_omc(a), v_ks(-15)), smooth), vf_mul(vf_u64(a, v_ks(-15)), rough));
    vf multi = vf_mul(vf_mul(vf_u64(alb, v_ks(-15)), vf_u64(a, v_ks(-15))), vf_k(FXV_MULTI_M, -33));
    return vf_mul(vf_mul(vf_u64(alb, v_ks(-15)), vf_k(FXV_INV_PI_M, -33)), vf_add(single, multi));
}

static inline fv vk_diffuse_hammon(const fv *x)
{
    fv nl = v_cos(x[0]), nv = v_cos(x[1]);
    vf r = v_diffuse(nl, nv, v_t31(v_t(x[2]), fv_add(nl, nv)), v_alpha(x[3]), v_unit(x[4]));
    return vf_fixed(r, FACET_FX_BRDF_FRAC, FACET_FX_MAX_DIFF);
}

static inline fv vk_brdf_hammon(const fv *x)
{
    fv nl = v_cos(x[0]), nv = v_cos(x[1]), a = v_alpha(x[3]), s = fv_add(nl, nv), f0r = v_unit(x[4]);
    fv s2 = fv_mul32(s, s), t31 = v_t31(v_t(x[2]), s);
    fv e60 = fv_add(fv_shl(fv_sub(t31, s2), 30), v_mul64x32(s2, fv_mul32(a, a)));
    vf e = vf_u64(e60, v_ks(-60));
    vf a2t = vf_mul(vf_u64(a, v_ks(-15)), vf_u64(t31, v_ks(-30)));
    vf lh = vf_sqrt(vf_u64(t31, v_ks(-32)));
    vf y = vf_div(vf_u64(fv_sub(v_k(1ull << 32), t31), v_ks(-32)), vf_add(vf_k(0x80000000u, -31), lh));
    vf y2 = vf_mul(y, y);
    vf f = vf_add(vf_u64(f0r, v_ks(-15)), vf_mul(vf_u64(v_omc(f0r), v_ks(-15)), vf_mul(vf_mul(y2, y2), y)));
    vf den = vf_mul(vf_mul(vf_mul(e, e), vf_u64(v_hammon_m45(nl, nv, a), v_ks(-45))),
                    vf_k(FXV_TWO_PI_M, -29));
    vf spec = vf_div(vf_mul(vf_mul(a2t, a2t), f), den);
    vf r = vf_add(spec, v_diffuse(nl, nv, t31, a, v_unit(x[5])));
    return vf_fixed(r, FACET_FX_BRDF_FRAC, FACET_FX_MAX_BRDF);
}

/* ---- batches ------------------------------------------------------------------
 * Whole vectors straight from the arrays, the tail (n % FXV_W) through a
 * stack copy padded with 0 (every kernel clamps it; the pad lanes' results
 * are dropped).  A block's inputs are all loaded before its output is
 * stored, so out may be the same array as an input. */
#define FXV_DRIVE(K, NIN, T, STORE)                                                    \
    {                                                                                  \
        size_t i_ = 0, j_, r_;                                                         \
        fv x_[6];                                                                      \
        int q_;                                                                        \
        for (; i_ + FXV_W <= n; i_ += FXV_W) {                                         \
            for (q_ = 0; q_ < NIN; q_++)                                               \
                x_[q_] = fv_load(in_[q_] + i_);                                        \
            STORE(out + i_, K(x_));                                                    \
        }                                                                              \
        if (i_ < n) {                                                                  \
            int32_t t_[6][FXV_W];                                                      \
            uint64_t o_[FXV_W];                                                        \
            r_ = n - i_;                                                               \
            for (q_ = 0; q_ < NIN; q_++) {                                             \
                for (j_ = 0; j_ < FXV_W; j_++)                                         \
                    t_[q_][j_] = j_ < r_ ? in_[q_][i_ + j_] : 0;                       \
                x_[q_] = fv_load(t_[q_]);                                              \
            }                                                                          \
            fv_store64(o_, K(x_));                                                     \
            for (j_ = 0; j_ < r_; j_++)                                                \
                out[i_ + j_] = (T)o_[j_];                                              \
        }                                                                              \
    }

#define FXV_S32(p, v) fv_store32((p), (v))
#define FXV_S64(p, v) fv_store64((p), (v))
#define FXV_FN(k) FXV_CAT(fxv_batch_, k)
#define I const int32_t *

/* int32 outputs hold 0..32768, so (int32_t)(uint32_t) is exact */
#define FXV_B1(k, T, S)                                                                \
    static void FXV_FN(k)(T *out, I a, size_t n)                                       \
    {                                                                                  \
        I in_[1];                                                                      \
        in_[0] = a;                                                                    \
        FXV_DRIVE(vk_##k, 1, T, S)                                                     \
    }
#define FXV_B2(k, T, S)                                                                \
    static void FXV_FN(k)(T *out, I a, I b, size_t n)                                  \
    {                                                                                  \
        I in_[2];                                                                      \
        in_[0] = a;                                                                    \
        in_[1] = b;                                                                    \
        FXV_DRIVE(vk_##k, 2, T, S)                                                     \
    }
#define FXV_B3(k, T, S)                                                                \
    static void FXV_FN(k)(T *out, I a, I b, I c, size_t n)                             \
    {                                                                                  \
        I in_[3];                                                                      \
        in_[0] = a;                                                                    \
        in_[1] = b;                                                                    \
        in_[2] = c;                                                                    \
        FXV_DRIVE(vk_##k, 3, T, S)                                                     \
    }

FXV_B3(noh_from_dots, int32_t, FXV_S32)
FXV_B1(loh_from_dots, int32_t, FXV_S32)
FXV_B2(fresnel_schlick, int32_t, FXV_S32)
FXV_B2(ggx_d, uint32_t, FXV_S32)
FXV_B2(smith_g1, int32_t, FXV_S32)
FXV_B3(smith_g2, int32_t, FXV_S32)
FXV_B3(smith_g2_uncorrelated, int32_t, FXV_S32)
FXV_B3(smith_vis, uint32_t, FXV_S32)
FXV_B2(smith_g1_hammon, int32_t, FXV_S32)
FXV_B3(smith_g2_hammon, int32_t, FXV_S32)
FXV_B3(smith_vis_hammon, uint32_t, FXV_S32)

static void FXV_FN(diffuse_hammon)(uint32_t *out, I a, I b, I c, I d, I e, size_t n)
{
    I in_[5];
    in_[0] = a;
    in_[1] = b;
    in_[2] = c;
    in_[3] = d;
    in_[4] = e;
    FXV_DRIVE(vk_diffuse_hammon, 5, uint32_t, FXV_S32)
}

static void FXV_FN(brdf_hammon)(uint64_t *out, I a, I b, I c, I d, I e, I f, size_t n)
{
    I in_[6];
    in_[0] = a;
    in_[1] = b;
    in_[2] = c;
    in_[3] = d;
    in_[4] = e;
    in_[5] = f;
    FXV_DRIVE(vk_brdf_hammon, 6, uint64_t, FXV_S64)
}
#undef I

#ifndef FXV_FASTER
#define FXV_FASTER FX_ALL
#endif
const facet_fx_port FXV_CAT(facet_fx_port_, FXV_PORT) = {
    FXV_STR(FXV_PORT), FXV_W, FXV_FASTER,
    FXV_FN(noh_from_dots), FXV_FN(loh_from_dots), FXV_FN(fresnel_schlick), FXV_FN(ggx_d),
    FXV_FN(smith_g1), FXV_FN(smith_g2), FXV_FN(smith_g2_uncorrelated), FXV_FN(smith_vis),
    FXV_FN(smith_g1_hammon), FXV_FN(smith_g2_hammon), FXV_FN(smith_vis_hammon),
    FXV_FN(diffuse_hammon), FXV_FN(brdf_hammon),
};
