/* loops_sse2.c - the bench's loops over the inline SSE2 kernels
 * (facet/sse2.h), 4 samples per call (loops_port.h). */
#include "facet/sse2.h"

#define LP_PORT_ID sse2
#define LP_V __m128
#define LP_W 4
#define LP_LOAD(p) _mm_loadu_ps(p)
#define LP_STORE(p, v) _mm_storeu_ps((p), (v))
#include "loops_port.h"
