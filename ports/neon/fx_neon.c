/* fx_neon.c - the fixed-point kernels on NEON (aarch64 and armv7): the op
 * layer of src/fx_vbody.h on uint64x2_t (vmull.u32 for the exact 32x32->64
 * products, vshl.u64 by a register for per-lane shifts).  armv7 has no
 * 64-bit lane compares: unsigned a > b is "the saturating a - b is not 0",
 * equality and non-zero tests combine the two 32-bit halves.  Integer
 * instructions only.  Bit-identical to src/fx_kernels.c
 * (tests/test_fx_ports.c, run under qemu-user by tests/suites/40-arm.sh). */
#if !defined(__ARM_NEON) && !defined(__ARM_NEON__)
#error "fx_neon.c needs NEON (aarch64, or armv7 with -mfpu=neon-vfpv4): built by ports/neon/port.mk"
#endif
#include <arm_neon.h>
#include <stdint.h>

typedef uint64x2_t fv;
#define FXV_W 2
#define FXV_PORT neon

static inline fv fv_set(uint64_t c) { return vdupq_n_u64(c); }
static inline fv fv_add(fv a, fv b) { return vaddq_u64(a, b); }
static inline fv fv_sub(fv a, fv b) { return vsubq_u64(a, b); }
static inline fv fv_and(fv a, fv b) { return vandq_u64(a, b); }
static inline fv fv_or(fv a, fv b) { return vorrq_u64(a, b); }
static inline fv fv_xor(fv a, fv b) { return veorq_u64(a, b); }
static inline fv fv_shl(fv a, int k) { return vshlq_u64(a, vdupq_n_s64(k)); }
static inline fv fv_shr(fv a, int k) { return vshlq_u64(a, vdupq_n_s64(-k)); }
static inline fv fv_shlv(fv a, fv k) { return vshlq_u64(a, vreinterpretq_s64_u64(k)); }
static inline fv fv_shrv(fv a, fv k)
{
    return vshlq_u64(a, vreinterpretq_s64_u64(vsubq_u64(vdupq_n_u64(0), k)));
}
static inline fv fv_mul32(fv a, fv b) { return vmull_u32(vmovn_u64(a), vmovn_u64(b)); }
#if defined(__aarch64__)
static inline fv fv_gt(fv a, fv b) { return vcgtq_u64(a, b); }
static inline fv fv_sgt(fv a, fv b) { return vcgtq_s64(vreinterpretq_s64_u64(a), vreinterpretq_s64_u64(b)); }
static inline fv fv_eq(fv a, fv b) { return vceqq_u64(a, b); }
static inline int fv_any(fv m) { return vmaxvq_u32(vreinterpretq_u32_u64(m)) != 0; }
#else
/* lanes that are not 0 -> all ones */
static inline fv fv_ne0_(fv x)
{
    uint32x4_t w = vreinterpretq_u32_u64(x), t = vtstq_u32(w, w);
    return vreinterpretq_u64_u32(vorrq_u32(t, vrev64q_u32(t)));
}
static inline fv fv_gt(fv a, fv b) { return fv_ne0_(vqsubq_u64(a, b)); }
static inline fv fv_sgt(fv a, fv b)
{
    const fv s = vdupq_n_u64((uint64_t)1 << 63);
    return fv_gt(veorq_u64(a, s), veorq_u64(b, s));
}
static inline fv fv_eq(fv a, fv b)
{
    uint32x4_t w = vceqq_u32(vreinterpretq_u32_u64(a), vreinterpretq_u32_u64(b));
    return vreinterpretq_u64_u32(vandq_u32(w, vrev64q_u32(w)));
}
static inline int fv_any(fv m) { return (vgetq_lane_u64(m, 0) | vgetq_lane_u64(m, 1)) != 0; }
#endif
static inline fv fv_sel(fv m, fv a, fv b) { return vbslq_u64(m, a, b); }
/* vclz.i32 on both halves: clz(hi), plus clz(lo) where hi is 0 */
static inline fv fv_clz64(fv x)
{
    fv c = vreinterpretq_u64_u32(vclzq_u32(vreinterpretq_u32_u64(x)));
    fv hi = vshrq_n_u64(c, 32), lo = vandq_u64(c, vdupq_n_u64(0xFFFFFFFFu));
    return vaddq_u64(hi, vandq_u64(lo, fv_eq(hi, vdupq_n_u64(32))));
}
static inline fv fv_lut(const uint32_t *t, fv i)
{
    return vcombine_u64(vcreate_u64(t[vgetq_lane_u64(i, 0)]), vcreate_u64(t[vgetq_lane_u64(i, 1)]));
}
static inline fv fv_load(const int32_t *p) { return vreinterpretq_u64_s64(vmovl_s32(vld1_s32(p))); }
static inline void fv_store32(void *p, fv v) { vst1_u32((uint32_t *)p, vmovn_u64(v)); }
static inline void fv_store64(void *p, fv v) { vst1q_u64((uint64_t *)p, v); }

#include "../../src/fx_vbody.h"
