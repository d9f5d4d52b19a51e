/* loops_avx2.c - the bench's loops over the inline AVX2 kernels
 * (facet/avx2.h), 8 samples per call (loops_port.h). */
#include "facet/avx2.h"

#define LP_PORT_ID avx2
#define LP_V __m256
#define LP_W 8
#define LP_LOAD(p) _mm256_loadu_ps(p)
#define LP_STORE(p, v) _mm256_storeu_ps((p), (v))
#include "loops_port.h"
