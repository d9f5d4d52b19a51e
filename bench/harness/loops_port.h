/* loops_port.h - a port's inline loops (its kernels of both tiers as
 * throughput and latency loops, loops_body.h), the tables
 * bench_loops_<port>_inline and _inline_fast.  A file
 * bench/harness/loops_<port>.c includes it once after the port's header
 * with the port's hooks (the same as its ports/<isa>/f32_<isa>.c):
 *   LP_PORT_ID   the port's name token (src/core/ports.def)
 *   LP_V, LP_W   its vector type and lanes
 *   LP_LOAD(p), LP_STORE(p, v)   a whole vector, unaligned
 * The rest comes from the port's op layer (facet_<port>_add, _mul, _set)
 * and its name.  bench/bench.mk builds the file only where the port is
 * compiled in, with the port's ISA flags (PORT_FLAGS_<port>, its port.mk),
 * and lists it in bench_loop_tables (loops_tables.c); each table runs only
 * where facet_port_supported(<port>) says this CPU runs it. */
#include "facet.h"
#include "loops.h"

#define LP_STR_(x) #x
#define LP_STR(x) LP_STR_(x)
#define LP_CAT3_(a, b, c) a##b##c
#define LP_CAT3(a, b, c) LP_CAT3_(a, b, c)
#define LP_OP(op) LP_CAT3(facet_, LP_PORT_ID, _##op)

static int lp_avail_(void) { return facet_port_supported(LP_STR(LP_PORT_ID)); }

#define LP_FEED(x, y) LP_OP(add)((x), LP_OP(mul)((y), LP_OP(set)(0.0f)))
#define LP_ZERO LP_OP(set)(0.0f)
#define LP_K(name, tier) LP_CAT3(facet_##name##_##tier, _, LP_PORT_ID)
#define LP_NAME LP_CAT3(LP_PORT_ID, _inline, )
#define LP_PATH "inline"
#define LP_PORT LP_STR(LP_PORT_ID)
#define LP_AVAIL lp_avail_
#include "loops_body.h"
