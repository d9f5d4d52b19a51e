/* f32_neon.c - the NEON port (4 lanes; aarch64, armv7): its f32 kernel and sampler
 * batches of both tiers and their tables (src/f32/f32_port_body.h), over
 * facet/neon.h. */
#include "facet/neon.h"

#define BATCH_PORT neon
#define BATCH_V float32x4_t
#define BATCH_W 4
#define BATCH_LOAD(p) vld1q_f32(p)
#define BATCH_STORE(p, v) vst1q_f32((p), (v))
#include "../../src/f32/f32_port_body.h"
