/* f32_batch_body.h - one tier of a port's kernel batches and its table
 * facet_port_<port>_<tier> (src/core/port.h), from the inline kernels
 * facet_<kernel>_<tier>_<port>; included by src/f32/f32_port_body.h once
 * per tier (BATCH_TIER f32 or f32_fast) with the port's hooks (see there).
 * Names generated here from src/core/kernels.def: one batch function per
 * kernel, and the table. */
#define BATCH_FN(k) BATCH_CAT(batch_, k, BATCH_CAT(_, BATCH_TIER, _))
#define BATCH_KERNEL(k) BATCH_CAT(facet_, k, BATCH_CAT(_, BATCH_TIER, BATCH_CAT(_, BATCH_PORT, )))

#define BATCH_PARAM_(q) const float *x##q
#define BATCH_LOAD_AT_(q) BATCH_LOAD(x##q + i)
#define BATCH_LOAD_N_AT_(q) BATCH_LOAD_N(x##q + i, count - i)

/* the tail of kernel `name` (n inputs) at i < count: through the port's
 * partial loads and stores, or staged: every input copied with the pad in
 * one loop (one compare per lane for all inputs, not one per input) */
#ifdef BATCH_STAGED
#define BATCH_PAD_COPY_(q) pad_[q][j] = j < r ? x##q[i + j] : BATCH_PAD
#define BATCH_PAD_LOAD_(q) BATCH_LOAD(pad_[q])
#define BATCH_TAIL_(name, n)                                                       \
    {                                                                              \
        float pad_[n][BATCH_W];                                                    \
        size_t j, r = count - i;                                                   \
        for (j = 0; j < BATCH_W; j++) {                                            \
            FACET_EACH_INPUT(n, BATCH_PAD_COPY_);                                  \
        }                                                                          \
        BATCH_STORE_N(out + i, BATCH_KERNEL(name)(FACET_EACH_INPUT(n, BATCH_PAD_LOAD_)), r); \
    }
#else
#define BATCH_TAIL_(name, n) \
    BATCH_STORE_N(out + i, BATCH_KERNEL(name)(FACET_EACH_INPUT(n, BATCH_LOAD_N_AT_)), count - i);
#endif

/* whole vectors, then the tail */
#define FACET_KERNEL(name, NAME, n, ...)                                                    \
    static void BATCH_FN(name)(float *out, FACET_EACH_INPUT(n, BATCH_PARAM_), size_t count) \
    {                                                                                       \
        const size_t w_ = BATCH_STEP;                                                       \
        size_t i = 0;                                                                       \
        for (; i + w_ <= count; i += w_)                                                    \
            BATCH_STORE(out + i, BATCH_KERNEL(name)(FACET_EACH_INPUT(n, BATCH_LOAD_AT_)));  \
        if (i < count)                                                                      \
            BATCH_TAIL_(name, n)                                                            \
    }
#include "../core/kernels.def"
#undef FACET_KERNEL

/* the RGB batch */
#include "f32_rgb_batch_body.h"
/* the per-sample entries */
#include "f32_one_body.h"

const facet_f32_port BATCH_CAT(facet_port_, BATCH_PORT, BATCH_CAT(_, BATCH_TIER, )) = {
    BATCH_STR(BATCH_PORT), BATCH_W,
#define FACET_KERNEL(name, NAME, n, ...) BATCH_FN(name),
#include "../core/kernels.def"
#undef FACET_KERNEL
    BATCH_FN(brdf_hammon_rgb), BATCH_LANES_FN, &BATCH_ONE_TABLE,
};

#undef BATCH_FN
#undef BATCH_KERNEL
#undef BATCH_TAIL_
#undef BATCH_ONE_TABLE
#undef BATCH_ONE_TABLE_OF
