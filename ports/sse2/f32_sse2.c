/* f32_sse2.c - the SSE2 port's batch functions (4 lanes). */
#include "facet/sse2.h"
#include "../../src/core/port.h"

#define BATCH_PORT sse2
#define BATCH_W 4
#define BATCH_LOAD(p) _mm_loadu_ps(p)
#define BATCH_STORE(p, v) _mm_storeu_ps((p), (v))
#define BATCH_V __m128
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
