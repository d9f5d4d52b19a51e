/* loops_body.h - instantiates a port's loops tables, one per f32 tier (see
 * loops.h).  Define
 *   LP_V, LP_W, LP_LOAD(p), LP_STORE(p, v), LP_FEED(x, y) (x + y*0),
 *   LP_ZERO, LP_K(name, tier) (the kernel function of a tier: f32 or
 *   f32_fast), LP_NAME (table token: bench_loops_<LP_NAME>, and
 *   bench_loops_<LP_NAME>_fast for the fast tier), LP_PATH, LP_PORT
 *   (strings), LP_AVAIL (an int(void) function)
 * then include this file once. */
#define LP_TIER "f32"
#define LP_KT(name) LP_K(name, f32)
#define LP_TNAME LP_NAME
#include "loops_tier.h"
#undef LP_TIER
#undef LP_KT
#undef LP_TNAME
#define LP_TIER "f32_fast"
#define LP_KT(name) LP_K(name, f32_fast)
#define LP_TNAME LP_CAT(LP_NAME, _fast)
#include "loops_tier.h"
#undef LP_TIER
#undef LP_KT
#undef LP_TNAME
