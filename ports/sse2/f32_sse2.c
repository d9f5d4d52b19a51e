/* f32_sse2.c - the SSE2 port (4 lanes): its f32 kernel and sampler
 * batches of both tiers and their tables (src/f32/f32_port_body.h), over
 * facet/sse2.h. */
#include "facet/sse2.h"

#define BATCH_PORT sse2
#define BATCH_V __m128
#define BATCH_W 4
#define BATCH_LOAD(p) _mm_loadu_ps(p)
#define BATCH_STORE(p, v) _mm_storeu_ps((p), (v))
#include "../../src/f32/f32_port_body.h"
