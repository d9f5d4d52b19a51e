/* f32_avx2.c - the AVX2 + FMA port (8 lanes): its f32 kernel and sampler
 * batches of both tiers and their tables (src/f32/f32_port_body.h), over
 * facet/avx2.h. */
#include "facet/avx2.h"

#define BATCH_PORT avx2
#define BATCH_V __m256
#define BATCH_W 8
#define BATCH_LOAD(p) _mm256_loadu_ps(p)
#define BATCH_STORE(p, v) _mm256_storeu_ps((p), (v))
/* the tail by masked loads and stores (facet/avx2.h), no staged copy */
#define BATCH_LOAD_N(p, r) facet_avx2_load_n((p), (r))
#define BATCH_STORE_N(p, v, r) facet_avx2_store_n((p), (v), (r))
#include "../../src/f32/f32_port_body.h"
