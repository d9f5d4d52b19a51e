/* fx_neon.c - the lane op layer of src/fx/fx_body.h on aarch64 NEON: 2 lanes,
 * each a uint64_t in a uint64x2_t (vmull.u32 for the exact 32x32->64
 * products), int32 inputs clamped as 2 words (smax / smin) before they are
 * widened.  Integer instructions only.  Bit-identical to the scalar
 * specification (tests/fx/test_fx_ports.c, run under qemu-user by
 * tests/suites/40-arm.sh).
 * aarch64 only: on armv7 the scalar loop executed fewer instructions for
 * every fixed-point kernel (qemu counts, README fixed point "SIMD ports"),
 * so armv7 has no fixed-point SIMD code and its neon port runs the scalar
 * loops (src/core/dispatch.c). */
#if defined(__aarch64__)
#include <arm_neon.h>
#include <stdint.h>

typedef int32x2_t fxv_i32;
typedef uint64x2_t fxv_u32; /* values below 2^32 in 64-bit lanes */
typedef uint64x2_t fxv_u64;
#define FXV_W 2
#define FXV_PORT_NAME "neon"
#define FXV_PORT_VAR facet_fx_port_neon
#define FXV_FAST_PORT_VAR facet_fx_fast_port_neon
/* the fast tier's lanes executed 1.2x to 1.7x fewer instructions than its
 * scalar loop for every kernel (qemu-aarch64, 64-sample batches; README
 * fixed point "SIMD ports"), the precise tier's only for Fresnel */
#define FXV_FAST_EVERY_KERNEL 1

static inline fxv_u32 fxv_k32(uint32_t c) { return vdupq_n_u64(c); }
static inline fxv_u32 fxv_clamp(fxv_i32 x, int32_t lo, int32_t hi)
{
    return vmovl_u32(vreinterpret_u32_s32(vmin_s32(vmax_s32(x, vdup_n_s32(lo)), vdup_n_s32(hi))));
}
static inline fxv_u32 fxv_add32(fxv_u32 a, fxv_u32 b) { return vaddq_u64(a, b); }
static inline fxv_u32 fxv_sub32(fxv_u32 a, fxv_u32 b) { return vsubq_u64(a, b); }
static inline fxv_u32 fxv_mul32(fxv_u32 a, fxv_u32 b) { return vmull_u32(vmovn_u64(a), vmovn_u64(b)); }
static inline fxv_u64 fxv_mulw(fxv_u32 a, fxv_u32 b) { return vmull_u32(vmovn_u64(a), vmovn_u64(b)); }
static inline fxv_u64 fxv_add64(fxv_u64 a, fxv_u64 b) { return vaddq_u64(a, b); }
static inline fxv_u64 fxv_shr64(fxv_u64 a, int k) { return vshlq_u64(a, vdupq_n_s64(-k)); }
static inline fxv_u64 fxv_and64(fxv_u64 a, uint64_t c) { return vandq_u64(a, vdupq_n_u64(c)); }
static inline fxv_u32 fxv_lo(fxv_u64 a) { return vandq_u64(a, vdupq_n_u64(0xFFFFFFFFu)); }
static inline fxv_u32 fxv_hi(fxv_u64 a) { return vshrq_n_u64(a, 32); }
static inline fxv_u32 fxv_narrow(fxv_u64 a) { return a; }

/* the fast tier's ops (src/fx/fx_body.h's list; src/fx/fx_fast_body.h): values
 * below 2^32 in 64-bit lanes; a left shift is masked back to 32 bits (mod
 * 2^32, as the scalar ops); clz is the 32-bit clz of each lane's low word */
#define FXV_M32_ vdupq_n_u64(0xFFFFFFFFu)
/* the fast tier's ops: a kernel body need not use all of them */
#define FXV_FAST_ static inline __attribute__((unused))
FXV_FAST_ fxv_u32 fxv_shr(fxv_u32 a, int k) { return vshlq_u64(a, vdupq_n_s64(-k)); }
FXV_FAST_ fxv_u32 fxv_shl(fxv_u32 a, int k) { return vandq_u64(vshlq_u64(a, vdupq_n_s64(k)), FXV_M32_); }
FXV_FAST_ fxv_u32 fxv_shrv(fxv_u32 a, fxv_u32 n) { return vshlq_u64(a, vnegq_s64(vreinterpretq_s64_u64(n))); }
FXV_FAST_ fxv_u32 fxv_shlv(fxv_u32 a, fxv_u32 n) { return vandq_u64(vshlq_u64(a, vreinterpretq_s64_u64(n)), FXV_M32_); }
FXV_FAST_ fxv_u32 fxv_lt(fxv_u32 a, fxv_u32 b) { return vcltq_u64(a, b); }
FXV_FAST_ fxv_u32 fxv_sel(fxv_u32 m, fxv_u32 a, fxv_u32 b) { return vbslq_u64(m, a, b); }
FXV_FAST_ fxv_u32 fxv_min(fxv_u32 a, fxv_u32 b) { return vbslq_u64(vcltq_u64(a, b), a, b); }
FXV_FAST_ fxv_u32 fxv_max(fxv_u32 a, fxv_u32 b) { return vbslq_u64(vcltq_u64(a, b), b, a); }
FXV_FAST_ fxv_u32 fxv_and(fxv_u32 a, fxv_u32 b) { return vandq_u64(a, b); }
FXV_FAST_ fxv_u32 fxv_or(fxv_u32 a, fxv_u32 b) { return vorrq_u64(a, b); }
FXV_FAST_ fxv_u32 fxv_not(fxv_u32 a) { return veorq_u64(a, FXV_M32_); }
FXV_FAST_ fxv_u32 fxv_clz(fxv_u32 a) { return vmovl_u32(vclz_u32(vmovn_u64(a))); }
FXV_FAST_ fxv_u32 fxv_clamp_off(fxv_i32 x, int32_t lo, int32_t hi)
{
    int32x2_t c = vmin_s32(vmax_s32(x, vdup_n_s32(lo)), vdup_n_s32(hi));
    return vmovl_u32(vreinterpret_u32_s32(vsub_s32(c, vdup_n_s32(lo))));
}
FXV_FAST_ fxv_u32 fxv_lut(const uint32_t *t, fxv_u32 i)
{
    uint64x2_t r = vdupq_n_u64(t[vgetq_lane_u64(i, 0)]);
    return vsetq_lane_u64(t[vgetq_lane_u64(i, 1)], r, 1);
}

static inline fxv_i32 fxv_load(const int32_t *p) { return vld1_s32(p); }
/* macros, not functions: a port need not use every output type (clang
 * warns about an unused static function) */
#define fxv_store_int32_t(p, v) vst1_s32((p), vreinterpret_s32_u32(vmovn_u64(v)))
#define fxv_store_uint32_t(p, v) vst1_u32((p), vmovn_u64(v))
#define fxv_store_uint64_t(p, v) vst1q_u64((p), (v))

#include "../../src/fx/fx_batch_body.h"
#else
typedef int facet_fx_neon_aarch64_only_; /* ISO C wants a declaration */
#endif
