/* f32_neon.c - the NEON port's batch functions (4 lanes; aarch64, armv7). */
#include "facet/neon.h"
#include "../../src/core/port.h"

#define BATCH_PORT neon
#define BATCH_W 4
#define BATCH_LOAD(p) vld1q_f32(p)
#define BATCH_STORE(p, v) vst1q_f32((p), (v))
#define BATCH_V float32x4_t
#define BATCH_TIER f32
#include "../../src/f32/f32_batch_body.h"
#undef BATCH_TIER
#define BATCH_TIER f32_fast
#include "../../src/f32/f32_batch_body.h"
#undef BATCH_TIER

/* the samplers' batch functions and table (src/f32/f32_sample_batch_body.h) */
#define BATCH_TIER f32
#include "../../src/f32/f32_sample_batch_body.h"
#undef BATCH_TIER
#define BATCH_TIER f32_fast
#include "../../src/f32/f32_sample_batch_body.h"
#undef BATCH_TIER
