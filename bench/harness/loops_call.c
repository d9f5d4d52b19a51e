/* loops_call.c - benchmark loops over the library's out-of-line scalar
 * functions facet_<k>_f32 (a call per sample). */
#include "facet.h"

static int always(void) { return 1; }

#define LP_V float
#define LP_W 1
#define LP_LOAD(p) (*(p))
#define LP_STORE(p, v) (*(p) = (v))
#define LP_FEED(x, y) ((x) + (y) * 0.0f)
#define LP_ZERO 0.0f
#define LP_K(name, tier) facet_##name##_##tier
#define LP_NAME scalar_call
#define LP_PATH "call"
#define LP_PORT "scalar"
#define LP_AVAIL always
/* facet_<sampler>_f32 takes its outputs as one array */
#define LP_SAMPLE_CALL(kind, k, o, n_out, a, n) FACET_SAMPLE_CALL_ARRAY(kind, k, o, a, n)
#include "loops_body.h"
