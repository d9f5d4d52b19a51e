/* fx_vbatch.h - a fixed-point SIMD port's batch functions and port table,
 * instantiated from src/fx_body.h.  Include after the port's op layer with
 *   FXV_W                       lanes per vector
 *   FXV_PORT_NAME, FXV_PORT_VAR the port's name string and table variable
 *   fxv_load(p)                 FXV_W int32_t from p (unaligned) as fxv_i32
 *   fxv_store_<type>(p, v)      FXV_W outputs of the kernel's fx_type to p
 * Names generated here from src/kernels.def: one batch function per kernel
 * written over lanes; the port table leaves the others NULL (the scalar
 * loop).  Whole vectors straight from the arrays, the tail (n % FXV_W)
 * through a stack copy padded with 0 (every kernel clamps it; the pad
 * lanes' results are dropped).  A block's inputs are all loaded before its
 * output is stored, so out may be the same array as an input. */
#include "facet/fx.h"
#include "port.h"
#include "fx_body.h"

#define FXVB_PARAM_(q) const int32_t *x##q
#define FXVB_LOAD_(q) fxv_load(x##q + i)
#define FXVB_PAD_LOAD_(q) fxv_load(pad_[q])
#define FXVB_PAD_COPY_(q) pad_[q][j] = j < r ? x##q[i + j] : 0

#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...)      \
    FACET_IF_LANES(fx_code,                                                                \
    static void fxv_batch_##name(fx_type *out, FACET_EACH_INPUT(n, FXVB_PARAM_), size_t count) \
    {                                                                                      \
        size_t i = 0, j, r;                                                                \
        for (; i + FXV_W <= count; i += FXV_W)                                             \
            fxv_store_##fx_type(out + i, fxb_##name(FACET_EACH_INPUT(n, FXVB_LOAD_)));     \
        if (i < count) {                                                                   \
            int32_t pad_[n][FXV_W];                                                        \
            fx_type o_[FXV_W];                                                             \
            r = count - i;                                                                 \
            for (j = 0; j < FXV_W; j++) {                                                  \
                FACET_EACH_INPUT(n, FXVB_PAD_COPY_);                                       \
            }                                                                              \
            fxv_store_##fx_type(o_, fxb_##name(FACET_EACH_INPUT(n, FXVB_PAD_LOAD_)));      \
            for (j = 0; j < r; j++)                                                        \
                out[i + j] = o_[j];                                                        \
        }                                                                                  \
    })
#include "kernels.def"
#undef FACET_KERNEL

const facet_fx_port FXV_PORT_VAR = {
    FXV_PORT_NAME, FXV_W,
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    FACET_IF_LANES(fx_code, .name = fxv_batch_##name,)
#include "kernels.def"
#undef FACET_KERNEL
};
