/* fx_batch_body.h - the one batch loop of every fixed-point SIMD port and
 * its port tables, one per tier, instantiated from src/fx/fx_body.h
 * (fxb_<kernel>, the precise tier) and src/fx/fx_fast_body.h (fxq_<kernel>,
 * the fast tier).  A port (ports/<isa>/fx_<isa>.c) includes it after its op
 * layer (src/fx/fx_ops.h lists the ops) with:
 *   FXV_PORT_NAME               the port's name string
 *   FXV_PORT_VAR                the precise tier's table variable
 *   FXV_FAST_PORT_VAR           the fast tier's table variable
 *   FXV_W                       lanes per vector for the table (0: run time)
 *   FXV_STEP                    lanes per vector at run time (an expression)
 *   fxv_load(p)                 FXV_STEP int32_t from p (unaligned) as fxv_i32
 *   fxv_load_n(p, r)            the first r < FXV_STEP of them, nothing read
 *                               past p + r (the other lanes any value: every
 *                               body clamps its inputs, and their results
 *                               are dropped)
 *   fxv_store_<type>(p, v)      FXV_STEP outputs of the kernel's fx_type
 *   fxv_store_n_<type>(p, v, r) the first r < FXV_STEP of them, nothing
 *                               written past p + r
 *   which kernels of each tier run on these lanes, the port's measured
 *   choice (the others: the tier's scalar loop, a NULL table member):
 *   FXV_LANES_FX(X)             X(name) for each precise kernel on lanes, or
 *                               FXV_LANES_FX_ALL 1 for every one
 *   FXV_LANES_FX_FAST(X)        the same for the fast tier, or
 *                               FXV_LANES_FX_FAST_ALL 1
 * A build with -DFACET_FX_ALL_LANES runs every kernel of both tiers on
 * lanes, whatever the port chose (for measuring the choice; bit-identical
 * like any other).
 * Names generated here from src/core/kernels.def: a batch function per
 * kernel and tier (static inline: only the ones a table names are
 * compiled).  Whole vectors straight from the arrays, then the tail (n %
 * FXV_STEP) through the port's partial loads and stores (a stack copy, a
 * predicate, a vector length).  A block's inputs are all loaded before its
 * output is stored, so out may be the same array as an input. */
#include "facet/fx.h"
#include "../core/port.h"
#include "fx_body.h"
#include "fx_fast_body.h"

#define FXVB_PARAM_(q) const int32_t *x##q
#define FXVB_LOAD_(q) fxv_load(x##q + i)
#define FXVB_LOAD_N_(q) fxv_load_n(x##q + i, count - i)

/* batch `fn` of body function `body` */
#define FXVB_DEF(fn, body, n, fx_type)                                                            \
    static inline __attribute__((unused)) void fn(fx_type *out, FACET_EACH_INPUT(n, FXVB_PARAM_), \
                                                  size_t count)                                   \
    {                                                                                            \
        size_t i = 0, w = FXV_STEP;                                                              \
        for (; i + w <= count; i += w)                                                           \
            fxv_store_##fx_type(out + i, body(FACET_EACH_INPUT(n, FXVB_LOAD_)));                 \
        if (i < count)                                                                           \
            fxv_store_n_##fx_type(out + i, body(FACET_EACH_INPUT(n, FXVB_LOAD_N_)), count - i);  \
    }
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    FACET_IF_PRECISE(fx_code, FXVB_DEF(fxvb_fx_##name, fxb_##name, n, fx_type))       \
    FACET_IF_FX(fx_type, FXVB_DEF(fxvb_fx_fast_##name, fxq_##name, n, fx_type))
#include "../core/kernels.def"
#undef FACET_KERNEL

#ifdef FACET_FX_ALL_LANES
#undef FXV_LANES_FX_ALL
#undef FXV_LANES_FX_FAST_ALL
#define FXV_LANES_FX_ALL 1
#define FXV_LANES_FX_FAST_ALL 1
#endif

#define FXVB_FX_(name) .name = fxvb_fx_##name,
#define FXVB_FX_FAST_(name) .name = fxvb_fx_fast_##name,

const facet_fx_port FXV_PORT_VAR = {
    FXV_PORT_NAME, FXV_W,
#if defined(FXV_LANES_FX_ALL) && FXV_LANES_FX_ALL
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) \
    FACET_IF_PRECISE(fx_code, FXVB_FX_(name))
#include "../core/kernels.def"
#undef FACET_KERNEL
#else
    FXV_LANES_FX(FXVB_FX_)
#endif
};

const facet_fx_port FXV_FAST_PORT_VAR = {
    FXV_PORT_NAME, FXV_W,
#if defined(FXV_LANES_FX_FAST_ALL) && FXV_LANES_FX_FAST_ALL
#define FACET_KERNEL(name, NAME, n, fx_type, ...) FACET_IF_FX(fx_type, FXVB_FX_FAST_(name))
#include "../core/kernels.def"
#undef FACET_KERNEL
#else
    FXV_LANES_FX_FAST(FXVB_FX_FAST_)
#endif
};
