/* loops_tables.c - the list of loop tables (inline and call paths). */
#include "loops.h"

const bench_loops *const bench_loop_tables[] = {
    &bench_loops_scalar_inline, &bench_loops_scalar_call, &bench_loops_sse2_inline,
    &bench_loops_avx2_inline, &bench_loops_neon_inline,
    &bench_loops_scalar_inline_fast, &bench_loops_scalar_call_fast, &bench_loops_sse2_inline_fast,
    &bench_loops_avx2_inline_fast, &bench_loops_neon_inline_fast, 0,
};
