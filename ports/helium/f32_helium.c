/* f32_helium.c - the Helium port's batch functions (4 lanes, Cortex-M55 /
 * M85 with MVE floating point).  Whole vectors by plain loads and stores;
 * the tail (n % 4) predicated, its lanes enabled by VCTP (lanes past the
 * end are neither read nor written; their inputs are 0 and their results
 * dropped, so no stack copy); all of a block's inputs are loaded before its output is stored,
 * so out may alias any input.  The samplers take src/f32/f32_sample_batch_body.h's
 * padded tail. */
#include "facet/helium.h"
#include "../../src/core/port.h"

#define HB_PARAM_(q) const float *x##q
#define HB_LOAD_(q) vldrwq_f32(x##q + i)
#define HB_LOADP_(q) vldrwq_z_f32(x##q + i, p)

/* Names generated here from src/core/kernels.def: one batch function per kernel
 * and tier, and the two port tables. */
#define HB_DEF_(name, n, tier)                                                              \
    static void hb_##name##_##tier(float *out, FACET_EACH_INPUT(n, HB_PARAM_), size_t count) \
    {                                                                                      \
        size_t i = 0;                                                                      \
        for (; i + 4 <= count; i += 4)                                                     \
            vstrwq_f32(out + i, facet_##name##_##tier##_helium(FACET_EACH_INPUT(n, HB_LOAD_))); \
        if (i < count) {                                                                   \
            mve_pred16_t p = vctp32q((uint32_t)(count - i));                               \
            vstrwq_p_f32(out + i, facet_##name##_##tier##_helium(FACET_EACH_INPUT(n, HB_LOADP_)), p); \
        }                                                                                  \
    }
#define FACET_KERNEL(name, NAME, n, ...) HB_DEF_(name, n, f32) HB_DEF_(name, n, f32_fast)
#include "../../src/core/kernels.def"
#undef FACET_KERNEL

/* the RGB batch of each tier, from the shared body (src/f32/f32_rgb_batch_body.h:
 * stride-aware loads through a stack copy for the tail, like every port) */
#define BATCH_CAT_(a, b, c) a##b##c
#define BATCH_CAT(a, b, c) BATCH_CAT_(a, b, c)
#define BATCH_FN(k) BATCH_CAT(batch_, k, BATCH_CAT(_, BATCH_TIER, _))
#define BATCH_KERNEL(k) BATCH_CAT(facet_, k, BATCH_CAT(_, BATCH_TIER, BATCH_CAT(_, BATCH_PORT, )))
#define BATCH_PAD 0.5f
#define BATCH_PORT helium
#define BATCH_W 4
#define BATCH_V float32x4_t
#define BATCH_LOAD(p) vld1q_f32(p)
#define BATCH_STORE(p, v) vst1q_f32((p), (v))
#define BATCH_TIER f32
#include "../../src/f32/f32_rgb_batch_body.h"
#undef BATCH_TIER
#define BATCH_TIER f32_fast
#include "../../src/f32/f32_rgb_batch_body.h"
#undef BATCH_TIER

const facet_f32_port facet_port_helium_f32 = {
    "helium", 4,
#define FACET_KERNEL(name, NAME, n, ...) hb_##name##_f32,
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
    batch_brdf_hammon_rgb_f32_,
};
const facet_f32_port facet_port_helium_f32_fast = {
    "helium", 4,
#define FACET_KERNEL(name, NAME, n, ...) hb_##name##_f32_fast,
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
    batch_brdf_hammon_rgb_f32_fast_,
};

/* the samplers' batch functions and table (src/f32/f32_sample_batch_body.h) */
#define BATCH_PORT helium
#define BATCH_W 4
#define BATCH_LOAD(p) vld1q_f32(p)
#define BATCH_STORE(p, v) vst1q_f32((p), (v))
#define BATCH_V float32x4_t
#define BATCH_TIER f32
#include "../../src/f32/f32_sample_batch_body.h"
#undef BATCH_TIER
#define BATCH_TIER f32_fast
#include "../../src/f32/f32_sample_batch_body.h"
#undef BATCH_TIER
