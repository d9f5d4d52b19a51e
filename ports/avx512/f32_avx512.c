/* f32_avx512.c - the AVX-512F port's batch functions (16 lanes). */
#include "facet/avx512.h"
#include "../../src/core/port.h"

#define BATCH_PORT avx512
#define BATCH_W 16
#define BATCH_LOAD(p) _mm512_loadu_ps(p)
#define BATCH_STORE(p, v) _mm512_storeu_ps((p), (v))
#define BATCH_V __m512
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
