/* fx_vbatch.h - a fixed-point SIMD port's batch functions and port tables,
 * one per tier, instantiated from src/fx/fx_body.h (fx) and src/fx/fx_fast_body.h
 * (fx_fast).  Include after the port's op layer with
 *   FXV_W                       lanes per vector
 *   FXV_PORT_NAME, FXV_PORT_VAR the port's name string and table variable
 *   FXV_FAST_PORT_VAR           the fast tier's table variable
 *   FXV_FAST_EVERY_KERNEL       (optional) 1: the fast tier of every
 *                               fixed-point kernel on lanes, where the port
 *                               measured its lanes faster for all of them
 *   fxv_load(p)                 FXV_W int32_t from p (unaligned) as fxv_i32
 *   fxv_store_<type>(p, v)      FXV_W outputs of the kernel's fx_type to p
 * Names generated here from src/core/kernels.def: for each kernel whose fx_code
 * is lanes, one batch function per tier (and with FXV_FAST_EVERY_KERNEL a
 * fast-tier batch for every fixed-point kernel); the tables leave the others
 * NULL (the tier's scalar loop: measured faster there, README "SIMD ports").  Whole vectors straight from the arrays, the tail (n % FXV_W)
 * through a stack copy padded with 0 (every kernel clamps it; the pad
 * lanes' results are dropped).  A block's inputs are all loaded before its
 * output is stored, so out may be the same array as an input. */
#include "facet/fx.h"
#include "../core/port.h"
#include "fx_body.h"
#include "fx_fast_body.h"

#define FXVB_PARAM_(q) const int32_t *x##q
#define FXVB_LOAD_(q) fxv_load(x##q + i)
#define FXVB_PAD_LOAD_(q) fxv_load(pad_[q])
#define FXVB_PAD_COPY_(q) pad_[q][j] = j < r ? x##q[i + j] : 0

/* batch `fn` of body function `body` */
#define FXVB_DEF(fn, body, n, fx_type)                                                      \
    static void fn(fx_type *out, FACET_EACH_INPUT(n, FXVB_PARAM_), size_t count)            \
    {                                                                                      \
        size_t i = 0, j, r;                                                                \
        for (; i + FXV_W <= count; i += FXV_W)                                             \
            fxv_store_##fx_type(out + i, body(FACET_EACH_INPUT(n, FXVB_LOAD_)));           \
        if (i < count) {                                                                   \
            int32_t pad_[n][FXV_W];                                                        \
            fx_type o_[FXV_W];                                                             \
            r = count - i;                                                                 \
            for (j = 0; j < FXV_W; j++) {                                                  \
                FACET_EACH_INPUT(n, FXVB_PAD_COPY_);                                       \
            }                                                                              \
            fxv_store_##fx_type(o_, body(FACET_EACH_INPUT(n, FXVB_PAD_LOAD_)));            \
            for (j = 0; j < r; j++)                                                        \
                out[i + j] = o_[j];                                                        \
        }                                                                                  \
    }
/* which kernels' fast tier runs on this port's lanes: those whose fx_code
 * is lanes, or every fixed-point kernel where the port says so (those
 * with the fast tier only included) */
#if defined(FXV_FAST_EVERY_KERNEL) && FXV_FAST_EVERY_KERNEL
#define FXVB_IF_FAST(fx_type, fx_code, ...) FACET_IF_FX(fx_type, __VA_ARGS__)
#else
#define FXVB_IF_FAST(fx_type, fx_code, ...) FACET_IF_LANES(fx_code, __VA_ARGS__)
#endif
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...)      \
    FACET_IF_LANES(fx_code, FXVB_DEF(fxv_batch_##name, fxb_##name, n, fx_type))            \
    FXVB_IF_FAST(fx_type, fx_code, FXVB_DEF(fxv_fast_batch_##name, fxf_fast_##name, n, fx_type))
#include "../core/kernels.def"
#undef FACET_KERNEL

const facet_fx_port FXV_PORT_VAR = {
    FXV_PORT_NAME, FXV_W,
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    FACET_IF_LANES(fx_code, .name = fxv_batch_##name,)
#include "../core/kernels.def"
#undef FACET_KERNEL
};

const facet_fx_port FXV_FAST_PORT_VAR = {
    FXV_PORT_NAME, FXV_W,
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    FXVB_IF_FAST(fx_type, fx_code, .name = fxv_fast_batch_##name,)
#include "../core/kernels.def"
#undef FACET_KERNEL
};
