/* loops_tables.c - the list of loop tables (inline and call paths): the
 * scalar port's, then each port's inline loops that this build has
 * (bench/harness/loops_<port>.c for the ports compiled in: bench/bench.mk
 * passes them as BENCH_INLINE_PORTS(X), X(port) for each). */
#include "loops.h"

#ifndef BENCH_INLINE_PORTS
#define BENCH_INLINE_PORTS(X)
#endif
#define DECL_(p) extern const bench_loops bench_loops_##p##_inline, bench_loops_##p##_inline_fast;
BENCH_INLINE_PORTS(DECL_)
#define F32_(p) &bench_loops_##p##_inline,
#define F32_FAST_(p) &bench_loops_##p##_inline_fast,

const bench_loops *const bench_loop_tables[] = {
    &bench_loops_scalar_inline, &bench_loops_scalar_call, BENCH_INLINE_PORTS(F32_)
    &bench_loops_scalar_inline_fast, &bench_loops_scalar_call_fast, BENCH_INLINE_PORTS(F32_FAST_) 0,
};
