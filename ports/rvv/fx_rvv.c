/* fx_rvv.c - the lane op layer of src/fx/fx_fast_body.h (and the 64-bit ops
 * of src/fx/fx_body.h it uses) on RVV 1.0, vector-length agnostic: VLMAX
 * lanes of 32 bits in a vuint32m1_t, a 64-bit lane value one element of a
 * vuint64m2_t (the same lane count at twice the LMUL): the exact 32x32->64
 * product is one widening vwmulu, its high word a narrowing shift.  Every
 * op runs on all VLMAX lanes; the batch functions load and store with the
 * strip's vl (nothing past n is read or written).  Integer instructions
 * only, bit-identical to the scalar specification (tests/fx/test_fx_ports.c
 * and the pinned hashes, run at VLEN 128, 256 and 512 by
 * tests/suites/54-rvv.sh).  The fast tier only: the precise tier runs the
 * scalar loops (NULL members).
 *
 * RVV 1.0 has no clz (that is Zvbb): clz(a) = 1054 - the biased exponent
 * of a widened exactly to double (vfwcvt, exact for every u32), and 0 gives
 * 1054, held at 32 by a min.  Shift counts by register use the low 5 bits
 * (SEW 32); the body's counts are all in [0, 31] (src/fx/fx_fast_body.h). */
#include <riscv_vector.h>
#include <stdint.h>
#include <stddef.h>

typedef vint32m1_t fxv_i32;
typedef vuint32m1_t fxv_u32;
typedef vuint64m2_t fxv_u64;

#define FXV_FAST_ static inline __attribute__((always_inline, unused))
#define FXV_VL_ ((size_t)-1) /* VLMAX: see FACET_RVV_VL_ in facet/rvv.h */
FXV_FAST_ fxv_u32 fxv_k32(uint32_t c) { return vmv_v_x_u32m1(c, FXV_VL_); }
FXV_FAST_ fxv_u32 fxv_clamp(fxv_i32 x, int32_t lo, int32_t hi)
{
    size_t vl = FXV_VL_;
    return vreinterpret_v_i32m1_u32m1(vmin_vx_i32m1(vmax_vx_i32m1(x, lo, vl), hi, vl));
}
FXV_FAST_ fxv_u32 fxv_add32(fxv_u32 a, fxv_u32 b) { return vadd_vv_u32m1(a, b, FXV_VL_); }
FXV_FAST_ fxv_u32 fxv_sub32(fxv_u32 a, fxv_u32 b) { return vsub_vv_u32m1(a, b, FXV_VL_); }
FXV_FAST_ fxv_u32 fxv_mul32(fxv_u32 a, fxv_u32 b) { return vmul_vv_u32m1(a, b, FXV_VL_); }
FXV_FAST_ fxv_u64 fxv_mulw(fxv_u32 a, fxv_u32 b) { return vwmulu_vv_u64m2(a, b, FXV_VL_); }
FXV_FAST_ fxv_u64 fxv_add64(fxv_u64 a, fxv_u64 b) { return vadd_vv_u64m2(a, b, FXV_VL_); }
FXV_FAST_ fxv_u64 fxv_shr64(fxv_u64 a, int k) { return vsrl_vx_u64m2(a, (size_t)k, FXV_VL_); }
FXV_FAST_ fxv_u64 fxv_and64(fxv_u64 a, uint64_t c) { return vand_vx_u64m2(a, c, FXV_VL_); }
FXV_FAST_ fxv_u32 fxv_lo(fxv_u64 a) { return vnsrl_wx_u32m1(a, 0, FXV_VL_); }
FXV_FAST_ fxv_u32 fxv_hi(fxv_u64 a) { return vnsrl_wx_u32m1(a, 32, FXV_VL_); }
FXV_FAST_ fxv_u32 fxv_narrow(fxv_u64 a) { return vnsrl_wx_u32m1(a, 0, FXV_VL_); }

FXV_FAST_ fxv_u32 fxv_shr(fxv_u32 a, int k) { return vsrl_vx_u32m1(a, (size_t)k, FXV_VL_); }
FXV_FAST_ fxv_u32 fxv_shl(fxv_u32 a, int k) { return vsll_vx_u32m1(a, (size_t)k, FXV_VL_); }
FXV_FAST_ fxv_u32 fxv_shrv(fxv_u32 a, fxv_u32 n) { return vsrl_vv_u32m1(a, n, FXV_VL_); }
FXV_FAST_ fxv_u32 fxv_shlv(fxv_u32 a, fxv_u32 n) { return vsll_vv_u32m1(a, n, FXV_VL_); }
/* all-ones where a < b (unsigned), else 0 */
FXV_FAST_ fxv_u32 fxv_lt(fxv_u32 a, fxv_u32 b)
{
    size_t vl = FXV_VL_;
    return vmerge_vxm_u32m1(vmsltu_vv_u32m1_b32(a, b, vl), vmv_v_x_u32m1(0, vl), ~0u, vl);
}
/* m is a mask from fxv_lt (all-ones or 0): a where it is set */
FXV_FAST_ fxv_u32 fxv_sel(fxv_u32 m, fxv_u32 a, fxv_u32 b)
{
    size_t vl = FXV_VL_;
    return vmerge_vvm_u32m1(vmsne_vx_u32m1_b32(m, 0, vl), b, a, vl);
}
FXV_FAST_ fxv_u32 fxv_min(fxv_u32 a, fxv_u32 b) { return vminu_vv_u32m1(a, b, FXV_VL_); }
FXV_FAST_ fxv_u32 fxv_max(fxv_u32 a, fxv_u32 b) { return vmaxu_vv_u32m1(a, b, FXV_VL_); }
FXV_FAST_ fxv_u32 fxv_and(fxv_u32 a, fxv_u32 b) { return vand_vv_u32m1(a, b, FXV_VL_); }
FXV_FAST_ fxv_u32 fxv_or(fxv_u32 a, fxv_u32 b) { return vor_vv_u32m1(a, b, FXV_VL_); }
FXV_FAST_ fxv_u32 fxv_not(fxv_u32 a) { return vnot_v_u32m1(a, FXV_VL_); }
FXV_FAST_ fxv_u32 fxv_clz(fxv_u32 a)
{
    size_t vl = FXV_VL_;
    vuint64m2_t d = vreinterpret_v_f64m2_u64m2(vfwcvt_f_xu_v_f64m2(a, vl)); /* exact */
    fxv_u32 e = vnsrl_wx_u32m1(d, 52, vl);                                 /* 1023 + floor(log2 a) */
    return vminu_vx_u32m1(vrsub_vx_u32m1(e, 1054u, vl), 32u, vl);
}
FXV_FAST_ fxv_u32 fxv_clamp_off(fxv_i32 x, int32_t lo, int32_t hi)
{
    size_t vl = FXV_VL_;
    fxv_i32 c = vmin_vx_i32m1(vmax_vx_i32m1(x, lo, vl), hi, vl);
    return vreinterpret_v_i32m1_u32m1(vsub_vx_i32m1(c, lo, vl));
}
/* a gather: an indexed load with byte offsets 4 i */
FXV_FAST_ fxv_u32 fxv_lut(const uint32_t *t, fxv_u32 i)
{
    size_t vl = FXV_VL_;
    return vluxei32_v_u32m1(t, vsll_vx_u32m1(i, 2, vl), vl);
}

#include "facet/fx.h"
#include "../../src/core/port.h"
#include "../../src/fx/fx_body.h"
#include "../../src/fx/fx_fast_body.h"

/* strips of vl = vsetvl(n - i) lanes, loaded and stored with that vl; a
 * uint64_t output lane is one element of the u64m2 result */
#define FXR_LOAD_(q) vreinterpret_v_u32m1_i32m1(vle32_v_u32m1((const uint32_t *)(x##q + i), vl))
#define FXR_PARAM_(q) const int32_t *x##q
#define fxr_store_int32_t(o, v, vl) vse32_v_i32m1((o), vreinterpret_v_u32m1_i32m1(v), (vl))
#define fxr_store_uint32_t(o, v, vl) vse32_v_u32m1((o), (v), (vl))
#define fxr_store_uint64_t(o, v, vl) vse64_v_u64m2((o), (v), (vl))

#define FXR_DEF(fn, body, n, fx_type)                                                      \
    static void fn(fx_type *out, FACET_EACH_INPUT(n, FXR_PARAM_), size_t count)            \
    {                                                                                      \
        size_t i, vl;                                                                      \
        for (i = 0; i < count; i += vl) {                                                  \
            vl = vsetvl_e32m1(count - i);                                                  \
            fxr_store_##fx_type(out + i, body(FACET_EACH_INPUT(n, FXR_LOAD_)), vl);        \
        }                                                                                  \
    }
/* Names generated here from src/core/kernels.def: the fast tier on lanes for
 * every fixed-point kernel */
#define FACET_KERNEL(name, NAME, n, fx_type, ...) \
    FACET_IF_FX(fx_type, FXR_DEF(fxr_fast_batch_##name, fxf_fast_##name, n, fx_type))
#include "../../src/core/kernels.def"
#undef FACET_KERNEL

const facet_fx_port facet_fx_fast_port_rvv = {
    "rvv", 0,
#define FACET_KERNEL(name, NAME, n, fx_type, ...) FACET_IF_FX(fx_type, .name = fxr_fast_batch_##name,)
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
};
