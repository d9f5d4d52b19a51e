/* f32_batch_scalar.c - the scalar port (the fallback): its f32 kernel and
 * sampler batches of both tiers and their tables (src/f32/f32_port_body.h),
 * over facet/scalar.h, one lane (so never a tail). */
#include "facet/scalar.h"

#define BATCH_PORT scalar
#define BATCH_V float
#define BATCH_W 1
#define BATCH_LOAD(p) (*(p))
#define BATCH_STORE(p, v) (*(p) = (v))
#define BATCH_LOAD_N(p, r) (*(p))
#define BATCH_STORE_N(p, v, r) (*(p) = (v))
#include "f32_port_body.h"
