/* fx_helium.c - the lane op layer of src/fx/fx_body.h and src/fx/fx_fast_body.h
 * on Helium (Armv8.1-M MVE integer: Cortex-M55, M85): 4 lanes of 32 bits in
 * a uint32x4_t; a 64-bit lane value is a pair of them (low and high words),
 * the exact 32x32->64 product one VMUL and one VMULH (the high word alone
 * where the body takes only fxv_hi of it: the VMUL is dead code), the
 * 64-bit sum a carry by compare.  Table lookups are gathers (VLDRW with
 * shifted offsets), clz is VCLZ, shifts VSHL by a register or a per-lane
 * count.  Integer instructions only.  Bit-identical to the scalar
 * specification (tests/fx/test_fx_ports.c and the pinned hashes, run on the
 * Cortex-M55 model by tests/suites/52-helium.sh).
 * The batch functions' tails are predicated (VCTP): lanes past the end are
 * neither read nor written. */
#include <arm_mve.h>
#include <stdint.h>

typedef int32x4_t fxv_i32;
typedef uint32x4_t fxv_u32;
typedef struct { uint32x4_t lo, hi; } fxv_u64;

#define FXV_FAST_ static inline __attribute__((always_inline, unused))
FXV_FAST_ fxv_u32 fxv_k32(uint32_t c) { return vdupq_n_u32(c); }
FXV_FAST_ fxv_u32 fxv_clamp(fxv_i32 x, int32_t lo, int32_t hi)
{
    return vreinterpretq_u32_s32(vminq_s32(vmaxq_s32(x, vdupq_n_s32(lo)), vdupq_n_s32(hi)));
}
FXV_FAST_ fxv_u32 fxv_add32(fxv_u32 a, fxv_u32 b) { return vaddq_u32(a, b); }
FXV_FAST_ fxv_u32 fxv_sub32(fxv_u32 a, fxv_u32 b) { return vsubq_u32(a, b); }
FXV_FAST_ fxv_u32 fxv_mul32(fxv_u32 a, fxv_u32 b) { return vmulq_u32(a, b); }
FXV_FAST_ fxv_u64 fxv_mulw(fxv_u32 a, fxv_u32 b)
{
    fxv_u64 r;
    r.lo = vmulq_u32(a, b);
    r.hi = vmulhq_u32(a, b);
    return r;
}
/* the carry out of the low words: lo < a.lo */
FXV_FAST_ fxv_u64 fxv_add64(fxv_u64 a, fxv_u64 b)
{
    fxv_u64 r;
    r.lo = vaddq_u32(a.lo, b.lo);
    r.hi = vaddq_u32(a.hi, b.hi);
    r.hi = vaddq_m_n_u32(r.hi, r.hi, 1u, vcmphiq_u32(a.lo, r.lo));
    return r;
}
/* VSHL by a register: a negative count shifts right, |count| >= 32 gives 0 */
FXV_FAST_ fxv_u64 fxv_shr64(fxv_u64 a, int k)
{
    fxv_u64 r;
    r.lo = vorrq_u32(vshlq_r_u32(a.lo, -k), vshlq_r_u32(a.hi, 32 - k));
    r.hi = vshlq_r_u32(a.hi, -k);
    return r;
}
FXV_FAST_ fxv_u64 fxv_and64(fxv_u64 a, uint64_t c)
{
    fxv_u64 r;
    r.lo = vandq_u32(a.lo, vdupq_n_u32((uint32_t)c));
    r.hi = vandq_u32(a.hi, vdupq_n_u32((uint32_t)(c >> 32)));
    return r;
}
FXV_FAST_ fxv_u32 fxv_lo(fxv_u64 a) { return a.lo; }
FXV_FAST_ fxv_u32 fxv_hi(fxv_u64 a) { return a.hi; }
FXV_FAST_ fxv_u32 fxv_narrow(fxv_u64 a) { return a.lo; }

/* the fast tier's ops */
/* the body's constant shifts (1 to 31, src/fx/fx_fast_body.h) as immediates:
 * macros, so the count reaches the intrinsic as a constant expression */
#define fxv_shr(a, k) vshrq_n_u32((a), (k))
#define fxv_shl(a, k) vshlq_n_u32((a), (k))
FXV_FAST_ fxv_u32 fxv_shrv(fxv_u32 a, fxv_u32 n) { return vshlq_u32(a, vnegq_s32(vreinterpretq_s32_u32(n))); }
FXV_FAST_ fxv_u32 fxv_shlv(fxv_u32 a, fxv_u32 n) { return vshlq_u32(a, vreinterpretq_s32_u32(n)); }
/* a mask by a predicated move (VDUP into the lanes where a < b); the
 * select by a predicate from it (VPSEL; gcc 12 fails with an internal
 * error on that form, so under gcc it is and / bic / orr) */
FXV_FAST_ fxv_u32 fxv_lt(fxv_u32 a, fxv_u32 b) { return vdupq_m_n_u32(vdupq_n_u32(0), ~0u, vcmphiq_u32(b, a)); }
#if defined(__clang__)
FXV_FAST_ fxv_u32 fxv_sel(fxv_u32 m, fxv_u32 a, fxv_u32 b) { return vpselq_u32(a, b, vcmpneq_n_u32(m, 0)); }
#else
FXV_FAST_ fxv_u32 fxv_sel(fxv_u32 m, fxv_u32 a, fxv_u32 b) { return vorrq_u32(vandq_u32(a, m), vbicq_u32(b, m)); }
#endif
FXV_FAST_ fxv_u32 fxv_min(fxv_u32 a, fxv_u32 b) { return vminq_u32(a, b); }
FXV_FAST_ fxv_u32 fxv_max(fxv_u32 a, fxv_u32 b) { return vmaxq_u32(a, b); }
FXV_FAST_ fxv_u32 fxv_and(fxv_u32 a, fxv_u32 b) { return vandq_u32(a, b); }
FXV_FAST_ fxv_u32 fxv_or(fxv_u32 a, fxv_u32 b) { return vorrq_u32(a, b); }
FXV_FAST_ fxv_u32 fxv_not(fxv_u32 a) { return vmvnq_u32(a); }
FXV_FAST_ fxv_u32 fxv_clz(fxv_u32 a) { return vclzq_u32(a); }
FXV_FAST_ fxv_u32 fxv_clamp_off(fxv_i32 x, int32_t lo, int32_t hi)
{
    int32x4_t c = vminq_s32(vmaxq_s32(x, vdupq_n_s32(lo)), vdupq_n_s32(hi));
    return vreinterpretq_u32_s32(vsubq_s32(c, vdupq_n_s32(lo)));
}
FXV_FAST_ fxv_u32 fxv_lut(const uint32_t *t, fxv_u32 i) { return vldrwq_gather_shifted_offset_u32(t, i); }

#include "facet/fx.h"
#include "../../src/core/port.h"
#include "../../src/fx/fx_body.h"
#include "../../src/fx/fx_fast_body.h"

/* whole vectors by plain loads and stores, the tail (n % 4) by predicated
 * ones (0 in the lanes past the end, which are neither read nor written);
 * a uint64_t lane is stored as its two words: VST20/VST21 (interleaving),
 * in the tail two predicated scatters (word offsets 2j and 2j + 1) */
#define FXH_LOAD_(q) vldrwq_s32(x##q + i)
#define FXH_LOADP_(q) vldrwq_z_s32(x##q + i, p)
#define FXH_PARAM_(q) const int32_t *x##q
#define fxh_store_int32_t(o, v) vstrwq_s32((o), vreinterpretq_s32_u32(v))
#define fxh_store_uint32_t(o, v) vstrwq_u32((o), (v))
#define fxh_storep_int32_t(o, v, p) vstrwq_p_s32((o), vreinterpretq_s32_u32(v), (p))
#define fxh_storep_uint32_t(o, v, p) vstrwq_p_u32((o), (v), (p))
FXV_FAST_ void fxh_store_uint64_t(uint64_t *o, fxv_u64 v)
{
    uint32x4x2_t w;
    w.val[0] = v.lo;
    w.val[1] = v.hi;
    vst2q_u32((uint32_t *)o, w);
}
FXV_FAST_ void fxh_storep_uint64_t(uint64_t *o, fxv_u64 v, mve_pred16_t p)
{
    uint32x4_t even = vmulq_n_u32(vidupq_n_u32(0, 1), 2);
    vstrwq_scatter_shifted_offset_p_u32((uint32_t *)o, even, v.lo, p);
    vstrwq_scatter_shifted_offset_p_u32((uint32_t *)o, vaddq_n_u32(even, 1), v.hi, p);
}

#define FXH_DEF(fn, body, n, fx_type)                                                      \
    static void fn(fx_type *out, FACET_EACH_INPUT(n, FXH_PARAM_), size_t count)            \
    {                                                                                      \
        size_t i = 0;                                                                      \
        for (; i + 4 <= count; i += 4)                                                     \
            fxh_store_##fx_type(out + i, body(FACET_EACH_INPUT(n, FXH_LOAD_)));             \
        if (i < count) {                                                                   \
            mve_pred16_t p = vctp32q((uint32_t)(count - i));                               \
            fxh_storep_##fx_type(out + i, body(FACET_EACH_INPUT(n, FXH_LOADP_)), p);        \
        }                                                                                  \
    }
/* Names generated here from src/core/kernels.def: the precise tier on lanes
 * where fx_code is lanes, the fast tier on lanes for every fixed-point
 * kernel (fewer instructions than the scalar loop on the M55 model: README
 * "SIMD ports") */
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...)      \
    FACET_IF_LANES(fx_code, FXH_DEF(fxh_batch_##name, fxb_##name, n, fx_type))             \
    FACET_IF_FX(fx_type, FXH_DEF(fxh_fast_batch_##name, fxf_fast_##name, n, fx_type))
#include "../../src/core/kernels.def"
#undef FACET_KERNEL

const facet_fx_port facet_fx_port_helium = {
    "helium", 4,
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    FACET_IF_LANES(fx_code, .name = fxh_batch_##name,)
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
};
const facet_fx_port facet_fx_fast_port_helium = {
    "helium", 4,
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    FACET_IF_FX(fx_type, .name = fxh_fast_batch_##name,)
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
};
