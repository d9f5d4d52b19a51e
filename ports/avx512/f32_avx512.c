/* f32_avx512.c - the AVX-512F port (16 lanes): its f32 kernel and sampler
 * batches of both tiers and their tables (src/f32/f32_port_body.h), over
 * facet/avx512.h. */
#include "facet/avx512.h"

#define BATCH_PORT avx512
#define BATCH_V __m512
#define BATCH_W 16
#define BATCH_LOAD(p) _mm512_loadu_ps(p)
#define BATCH_STORE(p, v) _mm512_storeu_ps((p), (v))
/* the tail by masked loads and stores (facet/avx512.h), no staged copy */
#define BATCH_LOAD_N(p, r) facet_avx512_load_n((p), (r))
#define BATCH_STORE_N(p, v, r) facet_avx512_store_n((p), (v), (r))
/* the per-sample entries: the AVX2 port's (src/f32/f32_one_body.h; the
 * AVX-512 CPU test implies AVX2 and FMA).  Scalar code built with
 * -mavx512f alone moves xmm16-31 through zmm registers (no AVX512VL) and
 * leaves their upper halves dirty: measured (facet-bench api), 390 TSC
 * ticks per brdf_hammon call from this object against 30 from avx2's. */
#define BATCH_ONE_FROM avx2
#include "../../src/f32/f32_port_body.h"
