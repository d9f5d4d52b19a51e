/* f32_helium.c - the Helium port (4 lanes, Cortex-M55 / M85 with MVE
 * floating point): its f32 kernel and sampler batches of both tiers and
 * their tables (src/f32/f32_port_body.h), over facet/helium.h.  The tail
 * (n % 4) is predicated, its lanes enabled by VCTP: lanes past the end are
 * neither read nor written (their inputs 0, their results dropped), no
 * stack copy. */
#include "facet/helium.h"

#define BATCH_PORT helium
#define BATCH_V float32x4_t
#define BATCH_W 4
#define BATCH_LOAD(p) vldrwq_f32(p)
#define BATCH_STORE(p, v) vstrwq_f32((p), (v))
#define BATCH_LOAD_N(p, r) vldrwq_z_f32((p), vctp32q((uint32_t)(r)))
#define BATCH_STORE_N(p, v, r) vstrwq_p_f32((p), (v), vctp32q((uint32_t)(r)))
/* the per-sample entries: the scalar port's (src/f32/f32_one_body.h), the
 * same scalar code, since an Armv8.1-M build compiles every object with the
 * one -mcpu (its FPU's FMA): a second copy overflowed the M55 test image's
 * code region (tests/ports/helium.mk, test_f32_bad_input) */
#define BATCH_ONE_FROM scalar
#include "../../src/f32/f32_port_body.h"
