/* loops_tier.h - one tier's loops table, included by loops_body.h once per
 * tier with LP_KT(name) (the kernel of that tier), LP_TNAME (the table
 * token) and LP_TIER (its name string). */
#include "facet.h"
#include "loops.h"
#include "src/core/kernel_list.h"
#include "src/core/sample_port.h" /* FACET_SAMPLE_CALL: a sampler's call by its kind */

#define LP_CAT_(a, b) a##b
#define LP_CAT(a, b) LP_CAT_(a, b)

/* input q at sample i, plain, or (the chain) the first one fed by y */
#define LP_PLAIN_(q) LP_LOAD(in[q] + i)
#define LP_FED_(q) LP_CAT(LP_FED_AT_, q)
#define LP_FED_AT_0 LP_FEED(LP_LOAD(in[0] + i), y)
#define LP_FED_AT_1 LP_PLAIN_(1)
#define LP_FED_AT_2 LP_PLAIN_(2)
#define LP_FED_AT_3 LP_PLAIN_(3)
#define LP_FED_AT_4 LP_PLAIN_(4)
#define LP_FED_AT_5 LP_PLAIN_(5)

/* Names generated here from src/core/kernels.def: two loops per kernel. */
#define FACET_KERNEL(name, NAME, n, ...)                                        \
    static void LP_CAT(LP_TNAME, LP_CAT(_thr_, name))(float *out, const float *const *in, size_t n_) \
    {                                                                           \
        size_t i;                                                               \
        for (i = 0; i < n_; i += LP_W)                                          \
            LP_STORE(out + i, LP_KT(name)(FACET_EACH_INPUT(n, LP_PLAIN_)));      \
    }                                                                           \
    static void LP_CAT(LP_TNAME, LP_CAT(_chain_, name))(float *out, const float *const *in, size_t n_) \
    {                                                                           \
        size_t i;                                                               \
        LP_V y = LP_ZERO;                                                       \
        for (i = 0; i < n_; i += LP_W)                                          \
            y = LP_KT(name)(FACET_EACH_INPUT(n, LP_FED_));                       \
        LP_STORE(out, y);                                                       \
    }
#include "src/core/kernels.def"
#undef FACET_KERNEL

static void LP_CAT(LP_TNAME, _thr_identity)(float *out, const float *const *in, size_t n_)
{
    size_t i;
    for (i = 0; i < n_; i += LP_W)
        LP_STORE(out + i, LP_LOAD(in[0] + i));
}

static void LP_CAT(LP_TNAME, _chain_identity)(float *out, const float *const *in, size_t n_)
{
    size_t i;
    LP_V y = LP_ZERO;
    for (i = 0; i < n_; i += LP_W)
        y = LP_FEED(LP_LOAD(in[0] + i), y);
    LP_STORE(out, y);
}

static const bench_loop LP_CAT(lp_k_, LP_TNAME)[] = {
#define FACET_KERNEL(name, NAME, n, ...) { LP_CAT(LP_TNAME, LP_CAT(_thr_, name)), LP_CAT(LP_TNAME, LP_CAT(_chain_, name)) },
#include "src/core/kernels.def"
#undef FACET_KERNEL
    { LP_CAT(LP_TNAME, _thr_identity), LP_CAT(LP_TNAME, _chain_identity) },
};

/* the sampler's call: inline port samplers take a pointer per output; a
 * file over functions taking one output array (loops_call.c) defines it */
#ifndef LP_SAMPLE_CALL
#define LP_SAMPLE_CALL(kind, k, o, n_out, a, n) FACET_SAMPLE_CALL(kind, k, o, n_out, a, n)
#endif

/* Names generated here from src/core/sample_kernels.def: one throughput loop
 * per sampler (inputs loaded, the sampler called, its outputs stored). */
#define FACET_SAMPLER(name, NAME, kind, err, n_out, n_in, outs, ins)           \
    static void LP_CAT(LP_TNAME, LP_CAT(_s_, name))(float *const *out, const float *const *in, size_t n_) \
    {                                                                           \
        size_t i;                                                               \
        int j;                                                                  \
        for (i = 0; i < n_; i += LP_W) {                                        \
            LP_V a_[n_in], o_[n_out];                                           \
            for (j = 0; j < n_in; j++)                                          \
                a_[j] = LP_LOAD(in[j] + i);                                     \
            LP_SAMPLE_CALL(kind, LP_KT(name), o_, n_out, a_, n_in);             \
            for (j = 0; j < n_out; j++)                                         \
                LP_STORE(out[j] + i, o_[j]);                                    \
        }                                                                       \
    }
#include "src/core/sample_kernels.def"
#undef FACET_SAMPLER

static const bench_sfn LP_CAT(lp_s_, LP_TNAME)[] = {
#define FACET_SAMPLER(name, ...) LP_CAT(LP_TNAME, LP_CAT(_s_, name)),
#include "src/core/sample_kernels.def"
#undef FACET_SAMPLER
};

const bench_loops LP_CAT(bench_loops_, LP_TNAME) = {
    LP_PATH, LP_PORT, LP_W, LP_AVAIL, LP_CAT(lp_k_, LP_TNAME), LP_TIER, LP_CAT(lp_s_, LP_TNAME),
};
