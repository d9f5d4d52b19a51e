/* fx_neon.c - the fixed-point lane op layer (src/fx/fx_ops.h) on aarch64
 * NEON: 2 lanes, each a uint64_t in a uint64x2_t (vmull.u32 for the exact
 * 32x32->64 products), int32 inputs clamped as 2 words (smax / smin) before
 * they are widened; the 64/32 division and the integer root lane by lane
 * (the scalar primitives: aarch64's udiv).  Integer instructions only.
 * Bit-identical to the scalar specification (tests/fx/test_fx_ports.c, run
 * under qemu-user by tests/suites/40-arm.sh).
 * aarch64 only: on armv7 the scalar loop executed fewer instructions for
 * every fixed-point kernel (qemu counts, README fixed point "SIMD ports"),
 * so armv7 has no fixed-point SIMD code and its neon port runs the scalar
 * loops (src/core/dispatch.c). */
#if defined(__aarch64__)
#include <arm_neon.h>
#include <stddef.h>
#include <stdint.h>
#include "../../src/fx/fx_prims.h"

typedef int32x2_t fxv_i32;
typedef uint64x2_t fxv_u32; /* values below 2^32 in 64-bit lanes */
typedef uint64x2_t fxv_u64;
#define FXV_W 2
#define FXV_STEP 2
#define FXV_PORT_NAME "neon"
#define FXV_PORT_VAR facet_fx_port_neon
#define FXV_FAST_PORT_VAR facet_fx_fast_port_neon
/* Which kernels of each tier run on these lanes; the others run the tier's
 * scalar loop.  Measured: executed instructions per sample under
 * qemu-aarch64 (64-sample batches of in-domain inputs, a -DFACET_FX_ALL_LANES
 * build, gcc 12 -O2), on lanes where the scalar loop executed >= 1.15x as
 * many (the ratio in brackets).  Fast: every kernel (1.04 smith_g1_gtr, the
 * others 1.23 to 2.98).  Precise: fresnel_schlick (1.91), g_implicit (2.98),
 * g_neumann (2.48), ggx_d (1.62), ggx_aniso_d (1.87), g_cook_torrance
 * (1.29), smith_g1_beckmann (1.32), smith_g1_schlick_beckmann (1.18),
 * smith_g2_hammon (1.52), smith_vis_hammon (1.57), smith_vis_joint_approx
 * (1.59), smith_vis_fit (1.41), diffuse_hammon (1.47), brdf_hammon (1.46);
 * not: noh_from_dots 1.01, smith_g2_uncorrelated 1.04, smith_g2 1.08,
 * loh_from_dots, smith_vis, smith_g1_hammon 1.09, smith_g1 1.12, g_kelemen
 * 1.14 (the division and root lane by lane).  (Before: the precise tier's
 * Fresnel alone.) */
#define FXV_LANES_FX(X) X(fresnel_schlick) X(g_implicit) X(g_neumann) X(ggx_d) X(ggx_aniso_d) X(g_cook_torrance) \
    X(smith_g1_beckmann) X(smith_g1_schlick_beckmann) X(smith_g2_hammon) X(smith_vis_hammon)                       \
    X(smith_vis_joint_approx) X(smith_vis_fit) X(diffuse_hammon) X(brdf_hammon)
#define FXV_LANES_FX_FAST_ALL 1

/* FXV_INLINE the ops, FXV_BODY the precise body's functions (src/fx/fx_ops.h):
 * inlined, so a kernel is one sequence of vector instructions; a body need
 * not use every op */
#define FXV_INLINE static inline __attribute__((always_inline, unused))
#define FXV_BODY FXV_INLINE
#define FXV_M32_ vdupq_n_u64(0xFFFFFFFFu)

FXV_INLINE fxv_u32 fxv_k32(uint32_t c) { return vdupq_n_u64(c); }
FXV_INLINE fxv_u32 fxv_clamp(fxv_i32 x, int32_t lo, int32_t hi)
{
    return vmovl_u32(vreinterpret_u32_s32(vmin_s32(vmax_s32(x, vdup_n_s32(lo)), vdup_n_s32(hi))));
}
FXV_INLINE fxv_u32 fxv_clamp_off(fxv_i32 x, int32_t lo, int32_t hi)
{
    int32x2_t c = vmin_s32(vmax_s32(x, vdup_n_s32(lo)), vdup_n_s32(hi));
    return vmovl_u32(vreinterpret_u32_s32(vsub_s32(c, vdup_n_s32(lo))));
}
FXV_INLINE fxv_u32 fxv_add32(fxv_u32 a, fxv_u32 b) { return vaddq_u64(a, b); }
FXV_INLINE fxv_u32 fxv_sub32(fxv_u32 a, fxv_u32 b) { return vsubq_u64(a, b); }
FXV_INLINE fxv_u32 fxv_mul32(fxv_u32 a, fxv_u32 b) { return vmull_u32(vmovn_u64(a), vmovn_u64(b)); }
/* a left shift is masked back to 32 bits (mod 2^32, as the scalar ops) */
FXV_INLINE fxv_u32 fxv_shr(fxv_u32 a, int k) { return vshlq_u64(a, vdupq_n_s64(-k)); }
FXV_INLINE fxv_u32 fxv_shl(fxv_u32 a, int k) { return vandq_u64(vshlq_u64(a, vdupq_n_s64(k)), FXV_M32_); }
FXV_INLINE fxv_u32 fxv_shrv(fxv_u32 a, fxv_u32 n) { return vshlq_u64(a, vnegq_s64(vreinterpretq_s64_u64(n))); }
FXV_INLINE fxv_u32 fxv_shlv(fxv_u32 a, fxv_u32 n) { return vandq_u64(vshlq_u64(a, vreinterpretq_s64_u64(n)), FXV_M32_); }
FXV_INLINE fxv_u32 fxv_lt(fxv_u32 a, fxv_u32 b) { return vcltq_u64(a, b); }
FXV_INLINE fxv_u32 fxv_sel(fxv_u32 m, fxv_u32 a, fxv_u32 b) { return vbslq_u64(m, a, b); }
FXV_INLINE fxv_u32 fxv_min(fxv_u32 a, fxv_u32 b) { return vbslq_u64(vcltq_u64(a, b), a, b); }
FXV_INLINE fxv_u32 fxv_max(fxv_u32 a, fxv_u32 b) { return vbslq_u64(vcltq_u64(a, b), b, a); }
FXV_INLINE fxv_u32 fxv_and(fxv_u32 a, fxv_u32 b) { return vandq_u64(a, b); }
FXV_INLINE fxv_u32 fxv_or(fxv_u32 a, fxv_u32 b) { return vorrq_u64(a, b); }
FXV_INLINE fxv_u32 fxv_not(fxv_u32 a) { return veorq_u64(a, FXV_M32_); }
/* the 32-bit clz of each lane's low word */
FXV_INLINE fxv_u32 fxv_clz(fxv_u32 a) { return vmovl_u32(vclz_u32(vmovn_u64(a))); }
FXV_INLINE fxv_u32 fxv_lut(const uint32_t *t, fxv_u32 i)
{
    uint64x2_t r = vdupq_n_u64(t[vgetq_lane_u64(i, 0)]);
    return vsetq_lane_u64(t[vgetq_lane_u64(i, 1)], r, 1);
}

FXV_INLINE fxv_u64 fxv_mulw(fxv_u32 a, fxv_u32 b) { return vmull_u32(vmovn_u64(a), vmovn_u64(b)); }
FXV_INLINE fxv_u64 fxv_wide(fxv_u32 a) { return a; }
FXV_INLINE fxv_u32 fxv_lo(fxv_u64 a) { return vandq_u64(a, FXV_M32_); }
FXV_INLINE fxv_u32 fxv_hi(fxv_u64 a) { return vshrq_n_u64(a, 32); }
FXV_INLINE fxv_u32 fxv_narrow(fxv_u64 a) { return a; }
FXV_INLINE fxv_u64 fxv_add64(fxv_u64 a, fxv_u64 b) { return vaddq_u64(a, b); }
FXV_INLINE fxv_u64 fxv_sub64(fxv_u64 a, fxv_u64 b) { return vsubq_u64(a, b); }
FXV_INLINE fxv_u64 fxv_shr64(fxv_u64 a, int k) { return vshlq_u64(a, vdupq_n_s64(-k)); }
FXV_INLINE fxv_u64 fxv_shl64(fxv_u64 a, int k) { return vshlq_u64(a, vdupq_n_s64(k)); }
FXV_INLINE fxv_u64 fxv_shrv64(fxv_u64 a, fxv_u32 n) { return vshlq_u64(a, vnegq_s64(vreinterpretq_s64_u64(n))); }
FXV_INLINE fxv_u64 fxv_shlv64(fxv_u64 a, fxv_u32 n) { return vshlq_u64(a, vreinterpretq_s64_u64(n)); }
FXV_INLINE fxv_u64 fxv_and64(fxv_u64 a, uint64_t c) { return vandq_u64(a, vdupq_n_u64(c)); }
FXV_INLINE fxv_u32 fxv_lt64(fxv_u64 a, fxv_u64 b) { return vcltq_u64(a, b); }
/* a mask's low word sign-extended over the lane (fxv_not leaves the high one) */
FXV_INLINE fxv_u64 fxv_sel64(fxv_u32 m, fxv_u64 a, fxv_u64 b)
{
    return vbslq_u64(vreinterpretq_u64_s64(vshrq_n_s64(vshlq_n_s64(vreinterpretq_s64_u64(m), 32), 32)), a, b);
}
/* lane by lane: the scalar primitives */
FXV_INLINE fxv_u32 fxv_div64(fxv_u32 u1, fxv_u32 u0, fxv_u32 d, fxv_u32 *r)
{
    uint32_t r0, r1;
    uint32_t q0 = fxp_div64((uint32_t)vgetq_lane_u64(u1, 0), (uint32_t)vgetq_lane_u64(u0, 0),
                            (uint32_t)vgetq_lane_u64(d, 0), &r0);
    uint32_t q1 = fxp_div64((uint32_t)vgetq_lane_u64(u1, 1), (uint32_t)vgetq_lane_u64(u0, 1),
                            (uint32_t)vgetq_lane_u64(d, 1), &r1);
    *r = vsetq_lane_u64(r1, vdupq_n_u64(r0), 1);
    return vsetq_lane_u64(q1, vdupq_n_u64(q0), 1);
}
FXV_INLINE fxv_u32 fxv_isqrt64(fxv_u64 x, fxv_u64 *rem)
{
    uint64_t s0, s1;
    uint32_t g0 = facet_fx_isqrt64_rem(vgetq_lane_u64(x, 0), &s0), g1 = facet_fx_isqrt64_rem(vgetq_lane_u64(x, 1), &s1);
    *rem = vsetq_lane_u64(s1, vdupq_n_u64(s0), 1);
    return vsetq_lane_u64(g1, vdupq_n_u64(g0), 1);
}

/* loads and stores: whole vectors, the tail (one lane) through a copy */
FXV_INLINE fxv_i32 fxv_load(const int32_t *p) { return vld1_s32(p); }
FXV_INLINE fxv_i32 fxv_load_n(const int32_t *p, size_t r)
{
    (void)r; /* r = 1 */
    return vset_lane_s32(p[0], vdup_n_s32(0), 0);
}
FXV_INLINE void fxv_store_int32_t(int32_t *p, fxv_u32 v) { vst1_s32(p, vreinterpret_s32_u32(vmovn_u64(v))); }
FXV_INLINE void fxv_store_uint32_t(uint32_t *p, fxv_u32 v) { vst1_u32(p, vmovn_u64(v)); }
FXV_INLINE void fxv_store_uint64_t(uint64_t *p, fxv_u64 v) { vst1q_u64(p, v); }
FXV_INLINE void fxv_store_n_int32_t(int32_t *p, fxv_u32 v, size_t r)
{
    (void)r;
    p[0] = (int32_t)vgetq_lane_u64(v, 0);
}
FXV_INLINE void fxv_store_n_uint32_t(uint32_t *p, fxv_u32 v, size_t r)
{
    (void)r;
    p[0] = (uint32_t)vgetq_lane_u64(v, 0);
}
FXV_INLINE void fxv_store_n_uint64_t(uint64_t *p, fxv_u64 v, size_t r)
{
    (void)r;
    p[0] = vgetq_lane_u64(v, 0);
}

#include "../../src/fx/fx_batch_body.h"
#else
typedef int facet_fx_neon_aarch64_only_; /* ISO C wants a declaration */
#endif
