/* loops_scalar.c - benchmark loops over the scalar port: the inline kernels
 * of facet/scalar.h, and the library's out-of-line facet_<k>_f32. */
#include "facet/scalar.h"
#include "facet.h"

static int always(void) { return 1; }

#define LP_V float
#define LP_W 1
#define LP_LOAD(p) (*(p))
#define LP_STORE(p, v) (*(p) = (v))
#define LP_FEED(x, y) ((x) + (y) * 0.0f)
#define LP_ZERO 0.0f
#define LP_K(name, tier) facet_##name##_##tier##_scalar
#define LP_NAME scalar_inline
#define LP_PATH "inline"
#define LP_PORT "scalar"
#define LP_AVAIL always
#include "loops_body.h"
