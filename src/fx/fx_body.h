/* fx_body.h - the fixed-point kernels whose code is written once over an
 * integer lane op layer (kernels.def: fx_code = lanes), for the scalar
 * specification (src/fx/fx_kernels.c, over src/fx/fx_ops_scalar.h) and every
 * fixed-point SIMD port (ports/<isa>/fx_<isa>.c, over its own ops).  Private
 * to the library.  One body, so a port cannot drift from the specification:
 * the same operations on the same integers, bit for bit
 * (tests/fx/test_fx_ports.c).
 *
 * Which kernels are here is a measured decision (README, fixed point "SIMD
 * ports"): a kernel is written over lanes only where some port's lanes beat
 * the scalar loop.  The others need exact wide divisions and square roots
 * that the scalar code does with one hardware instruction (x86-64, aarch64,
 * Cortex-M3+) and 64-bit lanes only in software; they are scalar C.
 *
 * The op layer (a port defines these before including this file):
 *   fxv_i32       lanes of int32_t (raw Q15 inputs)
 *   fxv_u32       lanes of values below 2^32
 *   fxv_u64       lanes of uint64_t
 *   fxv_k32(c)                 a constant (fxv_u32)
 *   fxv_clamp(x, lo, hi)       min(max(x, lo), hi) as fxv_u32, lo >= 0
 *   fxv_add32 fxv_sub32        +, - of fxv_u32 whose result is in [0, 2^32)
 *   fxv_mul32(a, b)            a b of fxv_u32 whose product is below 2^32
 *   fxv_mulw(a, b)             a b as fxv_u64 (32 x 32 -> 64, exact)
 *   fxv_add64(a, b)            a + b mod 2^64
 *   fxv_shr64(a, k)            a >> k, 0 < k < 64 a constant
 *   fxv_and64(a, c)            a & c, c a constant
 *   fxv_lo(a) fxv_hi(a)        the low / high 32 bits of a fxv_u64
 *   fxv_narrow(a)              a fxv_u64 known to be below 2^32, as fxv_u32
 * and, for the fast tier (src/fx/fx_fast_body.h), on fxv_u32:
 *   fxv_shr(a, k) fxv_shl(a, k)    a >> k, a << k mod 2^32, 0 <= k < 32 a constant
 *   fxv_shrv(a, n) fxv_shlv(a, n)  the same by a per-lane count 0 <= n < 32
 *   fxv_clz(a)                 leading zeros of a 32-bit a, 32 for a = 0
 *   fxv_min(a, b) fxv_max(a, b)    unsigned minimum / maximum
 *   fxv_lt(a, b)               all ones where a < b (unsigned), else 0
 *   fxv_sel(m, a, b)           a where the mask m is all ones, else b
 *   fxv_and fxv_or fxv_not     bitwise and, or, complement
 *   fxv_clamp_off(x, lo, hi)   min(max(x, lo), hi) - lo as fxv_u32 (lo may be < 0)
 *   fxv_lut(t, i)              t[i], t a const uint32_t table, i in range
 * Every op is exact on the stated range; no op rounds, wraps or saturates
 * where the body uses it (the bounds in brackets say why). */
#ifndef FACET_FX_BODY_ONE
#define FACET_FX_BODY_ONE 32768u /* 1.0 in Q15 */
#endif

/* round(a / 2^k), ties up: the fixed-point rounding rule (facet/fx.h) */
static inline fxv_u64 fxb_rshr64(fxv_u64 a, int k)
{
    return fxv_add64(fxv_shr64(a, k), fxv_and64(fxv_shr64(a, k - 1), 1));
}

/* floor(p Y^4 / 2^32), Y^4 = (Y^2)^2 Q60 exact [Y <= 2^15, p <= 2^30]: the
 * 90-bit product kept as high and low words, so the caller's one rounding
 * is of the exact value.  Result < 2^58. */
static inline fxv_u64 fxb_p_y4_hi(fxv_u32 p, fxv_u32 y)
{
    fxv_u32 y2 = fxv_mul32(y, y);              /* <= 2^30 */
    fxv_u64 y4 = fxv_mulw(y2, y2);             /* Q60 */
    fxv_u64 lo = fxv_mulw(p, fxv_lo(y4));      /* < 2^62 */
    return fxv_add64(fxv_mulw(p, fxv_hi(y4)), fxv_shr64(lo, 32));
}

/* ---- Fresnel -----------------------------------------------------------------
 * F = f0 + (1 - f0) y^5, y = 1 - cos.  With Y = 2^15 - C exact:
 *   raw = F0 + round((2^15 - F0) Y^5 / 2^75),
 * Z = P Y^4 with P = Y (2^15 - F0) <= 2^30 (fxb_p_y4_hi), so the one
 * rounding is of the exact value.  F(f0, 1) = f0 and F(f0, 0) = 1 exactly.
 * Error: 0 LSB (correctly rounded).  Cost: 2 mul32, 3 mulw. */
static inline fxv_u32 fxb_fresnel_schlick(fxv_i32 f0_in, fxv_i32 cos_in)
{
    fxv_u32 f0 = fxv_clamp(f0_in, 0, FACET_FX_ONE);
    fxv_u32 y = fxv_sub32(fxv_k32(FACET_FX_BODY_ONE), fxv_clamp(cos_in, 0, FACET_FX_ONE));
    fxv_u32 p = fxv_mul32(y, fxv_sub32(fxv_k32(FACET_FX_BODY_ONE), f0));
    return fxv_add32(f0, fxv_narrow(fxb_rshr64(fxb_p_y4_hi(p, y), 43))); /* Z / 2^32 < 2^59 */
}
