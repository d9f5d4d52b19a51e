/* fx_ops.h - the integer lane op layer the fixed-point bodies are written
 * over (src/fx/fx_body.h: the precise tier, src/fx/fx_fast_body.h: the fast
 * tier), and the ops derived from it once, here.  Private to the library.
 * A port defines the ops below, then includes the bodies (through
 * src/fx/fx_batch_body.h); src/fx/fx_ops_scalar.h defines them on one lane,
 * the fixed-point specification.  The same operations on the same
 * integers in every port, so no port can drift from the specification
 * (tests/fx/test_fx_ports.c, the pinned hashes).
 *
 * Types:
 *   fxv_i32       lanes of int32_t (raw Q15 inputs)
 *   fxv_u32       lanes of values below 2^32
 *   fxv_u64       lanes of values below 2^64
 * A mask is a fxv_u32 from fxv_lt / fxv_lt64 (all ones where true, else 0)
 * or a bitwise and / or / not of masks; only its low 32 bits count.
 * Ops a port defines (FXV_INLINE: their function attributes; FXV_BODY:
 * those of the precise body's functions, src/fx/fx_pfloat.h and
 * src/fx/fx_body.h):
 *   fxv_k32(c)                 a constant
 *   fxv_clamp(x, lo, hi)       min(max(x, lo), hi) as fxv_u32, lo >= 0
 *   fxv_clamp_off(x, lo, hi)   min(max(x, lo), hi) - lo (lo may be < 0)
 *   fxv_add32 fxv_sub32        +, - whose result is in [0, 2^32)
 *   fxv_mul32(a, b)            a b, the product below 2^32
 *   fxv_shr(a, k) fxv_shl(a, k)    a >> k, a << k mod 2^32, 0 <= k < 32 a constant
 *   fxv_shrv(a, n) fxv_shlv(a, n)  the same by a per-lane count 0 <= n < 32
 *   fxv_clz(a)                 leading zeros of a 32-bit a, 32 for a = 0
 *   fxv_min(a, b) fxv_max(a, b)    unsigned minimum / maximum
 *   fxv_lt(a, b)               the mask a < b (unsigned)
 *   fxv_sel(m, a, b)           a where the mask m is set, else b
 *   fxv_and fxv_or fxv_not     bitwise and, or, complement (32 bits)
 *   fxv_lut(t, i)              t[i], t a const uint32_t table, i in range
 *   fxv_mulw(a, b)             a b as fxv_u64 (32 x 32 -> 64, exact)
 *   fxv_wide(a)                a as fxv_u64
 *   fxv_lo(a) fxv_hi(a)        the low / high 32 bits of a fxv_u64
 *   fxv_narrow(a)              a fxv_u64 known to be below 2^32, as fxv_u32
 *   fxv_add64 fxv_sub64        +, - mod 2^64 (the bodies never wrap)
 *   fxv_shr64(a, k) fxv_shl64(a, k)    a >> k, a << k mod 2^64, 0 < k < 64 a constant
 *   fxv_shrv64(a, n) fxv_shlv64(a, n)  the same by a per-lane count 0 <= n < 64
 *   fxv_and64(a, c)            a & c, c a constant
 *   fxv_lt64(a, b)             the mask a < b (unsigned, 64 bits)
 *   fxv_sel64(m, a, b)         a where the mask m is set, else b (fxv_u64)
 *   fxv_div64(u1, u0, d, &r)   q = floor((u1 2^32 + u0) / d) and r the
 *                              remainder, for d in [2^31, 2^32) and u1 < d
 *                              (so q < 2^32), exact
 *   fxv_isqrt64(x, &rem)       g = floor(sqrt(x)) and rem = x - g^2 (< 2^33)
 *                              for any x, exact
 * Every op is exact on the stated range; no op rounds, wraps or saturates
 * where a body uses it (the bounds in brackets there say why).  The last
 * two are the precise tier's division and root: the scalar layer computes
 * them with the exact primitives of src/fx/fx_prims.h, a SIMD port the
 * fastest exact way it has (lane by lane through those primitives, or a
 * vector divide); an exact result has the same bits however it is found.
 * Every lane of a body is computed, also where a select then drops it, so
 * the bodies keep every op in its range on every lane: no sum or
 * difference wraps (a port with 32-bit values in 64-bit lanes would carry
 * the wrap into the high word), every shift count, table index, divisor
 * and dividend in range.  The one exception is a zero pseudo-float's
 * exponent (src/fx/fx_pfloat.h), which is never read. */
#ifndef FACET_FX_OPS_H
#define FACET_FX_OPS_H

#include "facet/fx.h"

/* ---- derived ops, written once over the port's ---------------------------- */

/* 0/1 from a mask */
FXV_INLINE fxv_u32 fxv_bit(fxv_u32 m) { return fxv_and(m, fxv_k32(1)); }
/* the mask a == 0 */
FXV_INLINE fxv_u32 fxv_is0(fxv_u32 a) { return fxv_lt(a, fxv_k32(1)); }
/* the mask a >= b */
FXV_INLINE fxv_u32 fxv_ge(fxv_u32 a, fxv_u32 b) { return fxv_not(fxv_lt(a, b)); }
/* hi 2^32 + lo */
FXV_INLINE fxv_u64 fxv_join(fxv_u32 hi, fxv_u32 lo) { return fxv_add64(fxv_shl64(fxv_wide(hi), 32), fxv_wide(lo)); }
/* a 64-bit constant */
FXV_INLINE fxv_u64 fxv_k64(uint64_t c) { return fxv_join(fxv_k32((uint32_t)(c >> 32)), fxv_k32((uint32_t)c)); }
/* x y for x y < 2^64 [so hi(x) y < 2^32] */
FXV_INLINE fxv_u64 fxv_mul64x32(fxv_u64 x, fxv_u32 y)
{
    return fxv_add64(fxv_mulw(fxv_lo(x), y), fxv_shl64(fxv_wide(fxv_mul32(fxv_hi(x), y)), 32));
}
/* max(a, b) of 64-bit lanes */
FXV_INLINE fxv_u64 fxv_max64(fxv_u64 a, fxv_u64 b) { return fxv_sel64(fxv_lt64(a, b), b, a); }
/* leading zeros of a 64-bit x, 64 for 0 */
FXV_INLINE fxv_u32 fxv_clz64(fxv_u64 x)
{
    fxv_u32 hi = fxv_hi(x);
    return fxv_sel(fxv_is0(hi), fxv_add32(fxv_k32(32), fxv_clz(fxv_lo(x))), fxv_clz(hi));
}
/* round(a / 2^k), ties up (the fixed-point rounding rule, facet/fx.h), 0 < k < 64 */
FXV_INLINE fxv_u64 fxv_rshr64(fxv_u64 a, int k)
{
    return fxv_add64(fxv_shr64(a, k), fxv_and64(fxv_shr64(a, k - 1), 1));
}

/* ---- the input domains (facet/fx.h), every int32 clamped ------------------ */
FXV_INLINE fxv_u32 fxv_unit(fxv_i32 x) { return fxv_clamp(x, 0, FACET_FX_ONE); }
FXV_INLINE fxv_u32 fxv_cosine(fxv_i32 x) { return fxv_clamp(x, FACET_FX_COS_MIN, FACET_FX_ONE); }
FXV_INLINE fxv_u32 fxv_alpha(fxv_i32 x) { return fxv_clamp(x, FACET_FX_ALPHA_MIN, FACET_FX_ONE); }
/* T = (1 + L.V) 2^15 in [0, 2^16] */
FXV_INLINE fxv_u32 fxv_lov_t(fxv_i32 lov) { return fxv_clamp_off(lov, -FACET_FX_ONE, FACET_FX_ONE); }

#endif
