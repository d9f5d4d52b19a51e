/* f32_batch_scalar.c - the scalar port's batch functions (the fallback). */
#include "facet/scalar.h"
#include "../core/port.h"

#define BATCH_PORT scalar
#define BATCH_W 1
#define BATCH_LOAD(p) (*(p))
#define BATCH_STORE(p, v) (*(p) = (v))
#define BATCH_V float
#define BATCH_TIER f32
#include "f32_batch_body.h"
#undef BATCH_TIER
#define BATCH_TIER f32_fast
#include "f32_batch_body.h"
#undef BATCH_TIER

/* the samplers' batch functions and table (src/f32/f32_sample_batch_body.h) */
#define BATCH_TIER f32
#include "f32_sample_batch_body.h"
#undef BATCH_TIER
#define BATCH_TIER f32_fast
#include "f32_sample_batch_body.h"
#undef BATCH_TIER
