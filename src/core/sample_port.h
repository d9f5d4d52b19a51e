/* sample_port.h - what a port gives the dispatcher for the samplers
 * (src/core/dispatch.c): one batch function per sampler and tier, in
 * src/core/sample_kernels.def order.  Private to the library. */
#ifndef FACET_SAMPLE_PORT_H
#define FACET_SAMPLE_PORT_H

#include <stddef.h>

/* out[o][i] = output o of sampler(in[0][i], ...), i < count; any count, out
 * may alias any input */
typedef void (*facet_sample_batch_fn)(float *const *out, const float *const *in, size_t count);

typedef struct facet_sample_port {
    const char *name;
    int lanes;
#define FACET_SAMPLER(name, ...) facet_sample_batch_fn name;
#include "sample_kernels.def"
#undef FACET_SAMPLER
} facet_sample_port;

/* Names generated here from src/core/ports.def: every port's two sampler
 * tables (ports/<isa>/f32_<isa>.c and src/f32/f32_batch_scalar.c, made by
 * src/f32/f32_port_body.h), declared for every line */
#define FACET_PORT(name, ...) \
    extern const facet_sample_port facet_sample_port_##name##_f32, facet_sample_port_##name##_f32_fast;
#include "ports.def"
#undef FACET_PORT

/* F(0), F(1), ..., F(n - 1): one item per input or output (n <= 8) */
#define FACET_SAMPLE_EACH(n, F) FACET_SAMPLE_EACH_##n(F)
#define FACET_SAMPLE_EACH_1(F) F(0)
#define FACET_SAMPLE_EACH_2(F) FACET_SAMPLE_EACH_1(F), F(1)
#define FACET_SAMPLE_EACH_3(F) FACET_SAMPLE_EACH_2(F), F(2)
#define FACET_SAMPLE_EACH_4(F) FACET_SAMPLE_EACH_3(F), F(3)
#define FACET_SAMPLE_EACH_5(F) FACET_SAMPLE_EACH_4(F), F(4)
#define FACET_SAMPLE_EACH_6(F) FACET_SAMPLE_EACH_5(F), F(5)
#define FACET_SAMPLE_EACH_7(F) FACET_SAMPLE_EACH_6(F), F(6)
#define FACET_SAMPLE_EACH_8(F) FACET_SAMPLE_EACH_7(F), F(7)

/* argument lists a[0], ..., a[n - 1] */
#define FACET_SAMPLE_ARGS(n, a) FACET_SAMPLE_ARGS_##n(a)
#define FACET_SAMPLE_ARGS_1(a) a[0]
#define FACET_SAMPLE_ARGS_2(a) FACET_SAMPLE_ARGS_1(a), a[1]
#define FACET_SAMPLE_ARGS_3(a) FACET_SAMPLE_ARGS_2(a), a[2]
#define FACET_SAMPLE_ARGS_4(a) FACET_SAMPLE_ARGS_3(a), a[3]
#define FACET_SAMPLE_ARGS_5(a) FACET_SAMPLE_ARGS_4(a), a[4]
#define FACET_SAMPLE_ARGS_6(a) FACET_SAMPLE_ARGS_5(a), a[5]
#define FACET_SAMPLE_ARGS_7(a) FACET_SAMPLE_ARGS_6(a), a[6]
#define FACET_SAMPLE_ARGS_8(a) FACET_SAMPLE_ARGS_7(a), a[7]

/* output pointers &o[0], ..., &o[n - 1] (the inline samplers take each
 * output by its own pointer: RVV's sizeless vectors have no arrays) */
#define FACET_SAMPLE_OUTS(n, o) FACET_SAMPLE_OUTS_##n(o)
#define FACET_SAMPLE_OUTS_1(o) &(o)[0]
#define FACET_SAMPLE_OUTS_2(o) FACET_SAMPLE_OUTS_1(o), &(o)[1]
#define FACET_SAMPLE_OUTS_3(o) FACET_SAMPLE_OUTS_2(o), &(o)[2]

/* the call of an inline sampler of either kind: o[] = k(a[0], ...), n_out
 * outputs, n inputs */
#define FACET_SAMPLE_CALL(kind, k, o, n_out, a, n) FACET_SAMPLE_CALL_##kind(k, o, n_out, a, n)
#define FACET_SAMPLE_CALL_vec(k, o, n_out, a, n) k(FACET_SAMPLE_OUTS(n_out, o), FACET_SAMPLE_ARGS(n, a))
#define FACET_SAMPLE_CALL_ret(k, o, n_out, a, n) (o)[0] = k(FACET_SAMPLE_ARGS(n, a))
/* the same for the functions that take the outputs as one array (the
 * oracle, facet/oracle.h, and the out-of-line facet_<sampler>_f32) */
#define FACET_SAMPLE_CALL_ARRAY(kind, k, o, a, n) FACET_SAMPLE_CALL_ARRAY_##kind(k, o, a, n)
#define FACET_SAMPLE_CALL_ARRAY_vec(k, o, a, n) k(o, FACET_SAMPLE_ARGS(n, a))
#define FACET_SAMPLE_CALL_ARRAY_ret(k, o, a, n) (o)[0] = k(FACET_SAMPLE_ARGS(n, a))

#endif
