/* fx_helium.c - the fixed-point lane op layer (src/fx/fx_ops.h) on Helium
 * (Armv8.1-M MVE integer: Cortex-M55, M85): 4 lanes of 32 bits in a
 * uint32x4_t; a 64-bit lane value is a pair of them (low and high words),
 * the exact 32x32->64 product one VMUL and one VMULH (the high word alone
 * where the body takes only fxv_hi of it: the VMUL is dead code), the
 * 64-bit sum a carry by compare.  Table lookups are gathers (VLDRW with
 * shifted offsets), clz is VCLZ, shifts VSHL by a register or a per-lane
 * count; the 64/32 division and the integer root lane by lane (the scalar
 * primitives: two UDIV digits).  Integer instructions only.  Bit-identical
 * to the scalar specification (tests/fx/test_fx_ports.c and the pinned
 * hashes, run on the Cortex-M55 model by tests/suites/52-helium.sh).
 * The batch tails are predicated (VCTP): lanes past the end are neither
 * read nor written. */
#include <arm_mve.h>
#include <stddef.h>
#include <stdint.h>
#include "../../src/fx/fx_prims.h"

typedef int32x4_t fxv_i32;
typedef uint32x4_t fxv_u32;
typedef struct { uint32x4_t lo, hi; } fxv_u64;
#define FXV_W 4
#define FXV_STEP 4
#define FXV_PORT_NAME "helium"
#define FXV_PORT_VAR facet_fx_port_helium
#define FXV_FAST_PORT_VAR facet_fx_fast_port_helium
/* Which kernels of each tier run on these lanes; the others run the tier's
 * scalar loop.  Measured: executed instructions per sample on qemu's
 * Cortex-M55 model (64-sample batches of in-domain inputs, a
 * -DFACET_FX_ALL_LANES build, the port objects by arm-none-eabi-gcc 12 -O2,
 * the default; clang's in brackets after), on lanes where the scalar loop
 * executed >= 1.15x as many and the code stays small (flash: this port is
 * for microcontrollers).  Fast: every kernel (1.61 to 4.78; clang 2.9 to
 * 5.0).  Precise: fresnel_schlick 1.80 (2.08), g_implicit 4.07 (3.98),
 * g_neumann 4.78 (4.26), ggx_d 1.33 (1.63), ggx_aniso_d 1.55 (2.20),
 * g_cook_torrance 1.18 (1.38), smith_g2_hammon 1.19 (1.46),
 * smith_vis_hammon 1.15 (1.38), smith_vis_joint_approx 1.15 (1.39): 18 KB
 * of code (gcc -O2); not: brdf_hammon 1.28 (1.75) and diffuse_hammon 1.36
 * (1.93), 29 and 14 KB of code on lanes (the tests' Cortex-M55 images
 * then overflow their 512 KB), the others 0.94 to 1.10 under gcc (1.02 to
 * 1.94 under clang: gcc spills Q registers around the lane-by-lane
 * divisions and roots).  (Before: the precise tier's Fresnel alone.) */
#define FXV_LANES_FX(X) X(fresnel_schlick) X(g_implicit) X(g_neumann) X(ggx_d) X(ggx_aniso_d) X(g_cook_torrance) \
    X(smith_g2_hammon) X(smith_vis_hammon) X(smith_vis_joint_approx)
#define FXV_LANES_FX_FAST_ALL 1

/* FXV_INLINE the ops, FXV_BODY the precise body's functions (src/fx/fx_ops.h):
 * inlined, so a kernel is one sequence of vector instructions; a body need
 * not use every op */
#define FXV_INLINE static inline __attribute__((always_inline, unused))
#define FXV_BODY FXV_INLINE
FXV_INLINE fxv_u32 fxv_k32(uint32_t c) { return vdupq_n_u32(c); }
FXV_INLINE fxv_u32 fxv_clamp(fxv_i32 x, int32_t lo, int32_t hi)
{
    return vreinterpretq_u32_s32(vminq_s32(vmaxq_s32(x, vdupq_n_s32(lo)), vdupq_n_s32(hi)));
}
FXV_INLINE fxv_u32 fxv_clamp_off(fxv_i32 x, int32_t lo, int32_t hi)
{
    int32x4_t c = vminq_s32(vmaxq_s32(x, vdupq_n_s32(lo)), vdupq_n_s32(hi));
    return vreinterpretq_u32_s32(vsubq_s32(c, vdupq_n_s32(lo)));
}
FXV_INLINE fxv_u32 fxv_add32(fxv_u32 a, fxv_u32 b) { return vaddq_u32(a, b); }
FXV_INLINE fxv_u32 fxv_sub32(fxv_u32 a, fxv_u32 b) { return vsubq_u32(a, b); }
FXV_INLINE fxv_u32 fxv_mul32(fxv_u32 a, fxv_u32 b) { return vmulq_u32(a, b); }
/* the bodies' constant shifts (1 to 31) as immediates: macros, so the
 * count reaches the intrinsic as a constant expression */
#define fxv_shr(a, k) vshrq_n_u32((a), (k))
#define fxv_shl(a, k) vshlq_n_u32((a), (k))
FXV_INLINE fxv_u32 fxv_shrv(fxv_u32 a, fxv_u32 n) { return vshlq_u32(a, vnegq_s32(vreinterpretq_s32_u32(n))); }
FXV_INLINE fxv_u32 fxv_shlv(fxv_u32 a, fxv_u32 n) { return vshlq_u32(a, vreinterpretq_s32_u32(n)); }
/* a mask by a predicated move (VDUP into the lanes where a < b); the
 * select by a predicate from it (VPSEL; gcc 12 fails with an internal
 * error on that form, so under gcc it is and / bic / orr) */
FXV_INLINE fxv_u32 fxv_mask_(mve_pred16_t p) { return vdupq_m_n_u32(vdupq_n_u32(0), ~0u, p); }
FXV_INLINE fxv_u32 fxv_lt(fxv_u32 a, fxv_u32 b) { return fxv_mask_(vcmphiq_u32(b, a)); }
#if defined(__clang__)
FXV_INLINE fxv_u32 fxv_sel(fxv_u32 m, fxv_u32 a, fxv_u32 b) { return vpselq_u32(a, b, vcmpneq_n_u32(m, 0)); }
#else
FXV_INLINE fxv_u32 fxv_sel(fxv_u32 m, fxv_u32 a, fxv_u32 b) { return vorrq_u32(vandq_u32(a, m), vbicq_u32(b, m)); }
#endif
FXV_INLINE fxv_u32 fxv_min(fxv_u32 a, fxv_u32 b) { return vminq_u32(a, b); }
FXV_INLINE fxv_u32 fxv_max(fxv_u32 a, fxv_u32 b) { return vmaxq_u32(a, b); }
FXV_INLINE fxv_u32 fxv_and(fxv_u32 a, fxv_u32 b) { return vandq_u32(a, b); }
FXV_INLINE fxv_u32 fxv_or(fxv_u32 a, fxv_u32 b) { return vorrq_u32(a, b); }
FXV_INLINE fxv_u32 fxv_not(fxv_u32 a) { return vmvnq_u32(a); }
FXV_INLINE fxv_u32 fxv_clz(fxv_u32 a) { return vclzq_u32(a); }
FXV_INLINE fxv_u32 fxv_lut(const uint32_t *t, fxv_u32 i) { return vldrwq_gather_shifted_offset_u32(t, i); }

FXV_INLINE fxv_u64 fxv_mulw(fxv_u32 a, fxv_u32 b)
{
    fxv_u64 r;
    r.lo = vmulq_u32(a, b);
    r.hi = vmulhq_u32(a, b);
    return r;
}
FXV_INLINE fxv_u64 fxv_wide(fxv_u32 a)
{
    fxv_u64 r;
    r.lo = a;
    r.hi = vdupq_n_u32(0);
    return r;
}
FXV_INLINE fxv_u32 fxv_lo(fxv_u64 a) { return a.lo; }
FXV_INLINE fxv_u32 fxv_hi(fxv_u64 a) { return a.hi; }
FXV_INLINE fxv_u32 fxv_narrow(fxv_u64 a) { return a.lo; }
/* the carry out of the low words: lo < a.lo */
FXV_INLINE fxv_u64 fxv_add64(fxv_u64 a, fxv_u64 b)
{
    fxv_u64 r;
    r.lo = vaddq_u32(a.lo, b.lo);
    r.hi = vaddq_u32(a.hi, b.hi);
    r.hi = vaddq_m_n_u32(r.hi, r.hi, 1u, vcmphiq_u32(a.lo, r.lo));
    return r;
}
/* the borrow out of the low words: a.lo < b.lo */
FXV_INLINE fxv_u64 fxv_sub64(fxv_u64 a, fxv_u64 b)
{
    fxv_u64 r;
    r.lo = vsubq_u32(a.lo, b.lo);
    r.hi = vsubq_u32(a.hi, b.hi);
    r.hi = vsubq_m_n_u32(r.hi, r.hi, 1u, vcmphiq_u32(b.lo, a.lo));
    return r;
}
/* VSHL by a register or a per-lane count: a negative count shifts right,
 * |count| >= 32 gives 0 */
FXV_INLINE fxv_u64 fxv_shr64(fxv_u64 a, int k)
{
    fxv_u64 r;
    r.lo = vorrq_u32(vshlq_r_u32(a.lo, -k), vshlq_r_u32(a.hi, 32 - k));
    r.hi = vshlq_r_u32(a.hi, -k);
    return r;
}
FXV_INLINE fxv_u64 fxv_shl64(fxv_u64 a, int k)
{
    fxv_u64 r;
    r.hi = vorrq_u32(vshlq_r_u32(a.hi, k), vshlq_r_u32(a.lo, k - 32));
    r.lo = vshlq_r_u32(a.lo, k);
    return r;
}
FXV_INLINE fxv_u64 fxv_shrv64(fxv_u64 a, fxv_u32 n)
{
    int32x4_t s = vreinterpretq_s32_u32(n);
    fxv_u64 r;
    r.lo = vorrq_u32(vshlq_u32(a.lo, vnegq_s32(s)), vshlq_u32(a.hi, vsubq_s32(vdupq_n_s32(32), s)));
    r.hi = vshlq_u32(a.hi, vnegq_s32(s));
    return r;
}
FXV_INLINE fxv_u64 fxv_shlv64(fxv_u64 a, fxv_u32 n)
{
    int32x4_t s = vreinterpretq_s32_u32(n);
    fxv_u64 r;
    r.hi = vorrq_u32(vshlq_u32(a.hi, s), vshlq_u32(a.lo, vsubq_s32(s, vdupq_n_s32(32))));
    r.lo = vshlq_u32(a.lo, s);
    return r;
}
FXV_INLINE fxv_u64 fxv_and64(fxv_u64 a, uint64_t c)
{
    fxv_u64 r;
    r.lo = vandq_u32(a.lo, vdupq_n_u32((uint32_t)c));
    r.hi = vandq_u32(a.hi, vdupq_n_u32((uint32_t)(c >> 32)));
    return r;
}
/* high words below, or equal and low words below */
FXV_INLINE fxv_u32 fxv_lt64(fxv_u64 a, fxv_u64 b)
{
    return fxv_mask_((mve_pred16_t)(vcmphiq_u32(b.hi, a.hi) | (vcmpeqq_u32(a.hi, b.hi) & vcmphiq_u32(b.lo, a.lo))));
}
FXV_INLINE fxv_u64 fxv_sel64(fxv_u32 m, fxv_u64 a, fxv_u64 b)
{
    fxv_u64 r;
    r.lo = fxv_sel(m, a.lo, b.lo);
    r.hi = fxv_sel(m, a.hi, b.hi);
    return r;
}
/* lane by lane: the scalar primitives */
FXV_INLINE fxv_u32 fxv_div64(fxv_u32 u1, fxv_u32 u0, fxv_u32 d, fxv_u32 *r)
{
    uint32_t a[4], b[4], c[4], q[4], s[4];
    int j;
    vst1q_u32(a, u1);
    vst1q_u32(b, u0);
    vst1q_u32(c, d);
    for (j = 0; j < 4; j++)
        q[j] = fxp_div64(a[j], b[j], c[j], &s[j]);
    *r = vld1q_u32(s);
    return vld1q_u32(q);
}
FXV_INLINE fxv_u32 fxv_isqrt64(fxv_u64 x, fxv_u64 *rem)
{
    uint32_t lo[4], hi[4], g[4], sl[4], sh[4];
    int j;
    vst1q_u32(lo, x.lo);
    vst1q_u32(hi, x.hi);
    for (j = 0; j < 4; j++) {
        uint64_t s;
        g[j] = facet_fx_isqrt64_rem(((uint64_t)hi[j] << 32) | lo[j], &s);
        sl[j] = (uint32_t)s;
        sh[j] = (uint32_t)(s >> 32);
    }
    rem->lo = vld1q_u32(sl);
    rem->hi = vld1q_u32(sh);
    return vld1q_u32(g);
}

/* loads and stores: whole vectors by plain ones, the tail (n % 4) by
 * predicated ones (0 in the lanes past the end, which are neither read nor
 * written); a uint64_t lane is stored as its two words: VST20/VST21
 * (interleaving), in the tail two predicated scatters (word offsets 2j and
 * 2j + 1) */
FXV_INLINE fxv_i32 fxv_load(const int32_t *p) { return vldrwq_s32(p); }
FXV_INLINE fxv_i32 fxv_load_n(const int32_t *p, size_t r) { return vldrwq_z_s32(p, vctp32q((uint32_t)r)); }
FXV_INLINE void fxv_store_int32_t(int32_t *p, fxv_u32 v) { vstrwq_s32(p, vreinterpretq_s32_u32(v)); }
FXV_INLINE void fxv_store_uint32_t(uint32_t *p, fxv_u32 v) { vstrwq_u32(p, v); }
FXV_INLINE void fxv_store_n_int32_t(int32_t *p, fxv_u32 v, size_t r)
{
    vstrwq_p_s32(p, vreinterpretq_s32_u32(v), vctp32q((uint32_t)r));
}
FXV_INLINE void fxv_store_n_uint32_t(uint32_t *p, fxv_u32 v, size_t r) { vstrwq_p_u32(p, v, vctp32q((uint32_t)r)); }
FXV_INLINE void fxv_store_uint64_t(uint64_t *p, fxv_u64 v)
{
    uint32x4x2_t w;
    w.val[0] = v.lo;
    w.val[1] = v.hi;
    vst2q_u32((uint32_t *)p, w);
}
FXV_INLINE void fxv_store_n_uint64_t(uint64_t *p, fxv_u64 v, size_t r)
{
    mve_pred16_t m = vctp32q((uint32_t)r);
    uint32x4_t even = vmulq_n_u32(vidupq_n_u32(0, 1), 2);
    vstrwq_scatter_shifted_offset_p_u32((uint32_t *)p, even, v.lo, m);
    vstrwq_scatter_shifted_offset_p_u32((uint32_t *)p, vaddq_n_u32(even, 1), v.hi, m);
}

#include "../../src/fx/fx_batch_body.h"
