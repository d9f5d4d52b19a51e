/* f32_avx2.c - the AVX2 + FMA port's batch functions (8 lanes). */
#include "facet/avx2.h"
#include "../../src/core/port.h"

#define BATCH_PORT avx2
#define BATCH_W 8
#define BATCH_LOAD(p) _mm256_loadu_ps(p)
#define BATCH_STORE(p, v) _mm256_storeu_ps((p), (v))
#define BATCH_V __m256
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
