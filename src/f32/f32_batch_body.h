/* batch_body.h - instantiates a port's batch functions and its port table
 * from the inline kernels.  Include after the port header with
 *   BATCH_PORT   port name token (scalar, sse2, ...)
 *   BATCH_TIER   f32 or f32_fast (included once per tier)
 *   BATCH_W      lanes
 *   BATCH_V      vector type (also for src/f32/f32_rgb_batch_body.h)
 *   BATCH_LOAD(p) / BATCH_STORE(p, v)   unaligned load / store
 * Whole vectors straight from the arrays; the tail (n % W) through a padded
 * stack copy, so every n and every alignment takes the same code.  All of a
 * block's inputs are loaded before its output is stored: out may alias any
 * input. */
#define BATCH_STR_(x) #x
#define BATCH_CAT_STR(x) BATCH_STR_(x)
#define BATCH_CAT_(a, b, c) a##b##c
#define BATCH_CAT(a, b, c) BATCH_CAT_(a, b, c)
#define BATCH_FN(k) BATCH_CAT(batch_, k, BATCH_CAT(_, BATCH_TIER, _))
#define BATCH_KERNEL(k) BATCH_CAT(facet_, k, BATCH_CAT(_, BATCH_TIER, BATCH_CAT(_, BATCH_PORT, )))

/* pad value: any value works (kernels clamp), 0.5 is inside every domain */
#define BATCH_PAD 0.5f

#define BATCH_PARAM_(q) const float *x##q
#define BATCH_LOAD_AT_(q) BATCH_LOAD(x##q + i)
#define BATCH_PAD_COPY_(q) pad_[q][j] = j < r ? x##q[i + j] : BATCH_PAD
#define BATCH_PAD_LOAD_(q) BATCH_LOAD(pad_[q])

/* Names generated here from src/core/kernels.def: one batch function per kernel
 * and the port's table. */
#define FACET_KERNEL(name, NAME, n, ...)                                           \
    static void BATCH_FN(name)(float *out, FACET_EACH_INPUT(n, BATCH_PARAM_), size_t count) \
    {                                                                              \
        size_t i = 0;                                                              \
        for (; i + BATCH_W <= count; i += BATCH_W)                                 \
            BATCH_STORE(out + i, BATCH_KERNEL(name)(FACET_EACH_INPUT(n, BATCH_LOAD_AT_))); \
        if (i < count) {                                                           \
            float pad_[n][BATCH_W], o_[BATCH_W];                                   \
            size_t j, r = count - i;                                               \
            for (j = 0; j < BATCH_W; j++) {                                        \
                FACET_EACH_INPUT(n, BATCH_PAD_COPY_);                              \
            }                                                                      \
            BATCH_STORE(o_, BATCH_KERNEL(name)(FACET_EACH_INPUT(n, BATCH_PAD_LOAD_))); \
            for (j = 0; j < r; j++)                                                \
                out[i + j] = o_[j];                                                \
        }                                                                          \
    }
#include "../core/kernels.def"
#undef FACET_KERNEL

/* the RGB batch (needs BATCH_V, the port's vector type) */
#include "f32_rgb_batch_body.h"

const facet_f32_port BATCH_CAT(facet_port_, BATCH_PORT, BATCH_CAT(_, BATCH_TIER, )) = {
    BATCH_CAT_STR(BATCH_PORT), BATCH_W,
#define FACET_KERNEL(name, NAME, n, ...) BATCH_FN(name),
#include "../core/kernels.def"
#undef FACET_KERNEL
    BATCH_FN(brdf_hammon_rgb),
};
