/* loops_body.h - instantiates a loops table (see loops.h).  Define
 *   LP_V, LP_W, LP_LOAD(p), LP_STORE(p, v), LP_FEED(x, y) (x + y*0),
 *   LP_ZERO, LP_K(name) (the kernel function), LP_NAME (table token),
 *   LP_PATH, LP_PORT (strings), LP_AVAIL (an int(void) function)
 * then include this file once. */
#include "facet.h"
#include "loops.h"

#define LP_CAT_(a, b) a##b
#define LP_CAT(a, b) LP_CAT_(a, b)

#define LP_A1(i, f0) f0(0, i)
#define LP_A2(i, f0) f0(0, i), LP_LOAD(in[1] + i)
#define LP_A3(i, f0) LP_A2(i, f0), LP_LOAD(in[2] + i)
#define LP_A5(i, f0) LP_A3(i, f0), LP_LOAD(in[3] + i), LP_LOAD(in[4] + i)
#define LP_A6(i, f0) LP_A5(i, f0), LP_LOAD(in[5] + i)
#define LP_PLAIN(q, i) LP_LOAD(in[q] + i)
#define LP_FED(q, i) LP_FEED(LP_LOAD(in[q] + i), y)

#define K(name, NAME, n, ...)                                                   \
    static void LP_CAT(thr_, name)(float *out, const float *const *in, size_t n_) \
    {                                                                           \
        size_t i;                                                               \
        for (i = 0; i < n_; i += LP_W)                                          \
            LP_STORE(out + i, LP_K(name)(LP_A##n(i, LP_PLAIN)));                \
    }                                                                           \
    static void LP_CAT(chain_, name)(float *out, const float *const *in, size_t n_) \
    {                                                                           \
        size_t i;                                                               \
        LP_V y = LP_ZERO;                                                       \
        for (i = 0; i < n_; i += LP_W)                                          \
            y = LP_K(name)(LP_A##n(i, LP_FED));                                 \
        LP_STORE(out, y);                                                       \
    }
#include "../src/kernels.def"
#undef K

static void lp_thr_identity(float *out, const float *const *in, size_t n_)
{
    size_t i;
    for (i = 0; i < n_; i += LP_W)
        LP_STORE(out + i, LP_LOAD(in[0] + i));
}

static void lp_chain_identity(float *out, const float *const *in, size_t n_)
{
    size_t i;
    LP_V y = LP_ZERO;
    for (i = 0; i < n_; i += LP_W)
        y = LP_FEED(LP_LOAD(in[0] + i), y);
    LP_STORE(out, y);
}

static const bench_loop LP_CAT(lp_k_, LP_NAME)[] = {
#define K(name, NAME, n, ...) { LP_CAT(thr_, name), LP_CAT(chain_, name) },
#include "../src/kernels.def"
#undef K
    { lp_thr_identity, lp_chain_identity },
};

const bench_loops LP_CAT(bench_loops_, LP_NAME) = {
    LP_PATH, LP_PORT, LP_W, LP_AVAIL, LP_CAT(lp_k_, LP_NAME),
};
