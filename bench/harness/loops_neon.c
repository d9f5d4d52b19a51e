/* loops_neon.c - the bench's loops over the inline NEON kernels
 * (facet/neon.h), 4 samples per call (loops_port.h; aarch64, and armv7
 * with the port's -mfpu=neon-vfpv4). */
#include "facet/neon.h"

#define LP_PORT_ID neon
#define LP_V float32x4_t
#define LP_W 4
#define LP_LOAD(p) vld1q_f32(p)
#define LP_STORE(p, v) vst1q_f32((p), (v))
#include "loops_port.h"
