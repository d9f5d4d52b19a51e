/* f32_port_body.h - everything a port gives the dispatcher in f32, made from
 * its inline kernels: for each tier (f32, f32_fast) a batch function per
 * kernel and the RGB batch (src/f32/f32_batch_body.h, the table
 * facet_port_<port>_<tier>), and a batch function per sampler
 * (src/f32/f32_sample_batch_body.h, the table facet_sample_port_<port>_<tier>).
 * A port's f32 file (ports/<isa>/f32_<isa>.c) includes it once, after its
 * inline header, with its hooks:
 *   BATCH_PORT              the port's name token (src/core/ports.def)
 *   BATCH_V                 its vector type
 *   BATCH_W                 its lanes, for the tables (0: vector-length
 *                           agnostic, see BATCH_STEP and BATCH_LANES_FN)
 *   BATCH_LOAD(p), BATCH_STORE(p, v)   a whole vector (BATCH_STEP floats),
 *                           unaligned
 * and where the defaults do not fit:
 *   BATCH_STEP              lanes per vector at run time, an expression
 *                           (default BATCH_W)
 *   BATCH_LANES_FN          with BATCH_W 0: the function that returns them
 *                           (facet_port_at's lanes; default none, NULL)
 *   BATCH_LOAD_N(p, r), BATCH_STORE_N(p, v, r)   the tail: the first
 *                           r < BATCH_STEP floats, nothing read or written
 *                           past p + r; the other lanes may hold any value
 *                           (their results are dropped).  Default: a copy
 *                           staged through a BATCH_W-float buffer; a port
 *                           with masked or predicated loads names its own
 *                           (e.g. facet_<port>_load_n)
 *   BATCH_SET(x)            x in every lane (default facet_<port>_set)
 *   BATCH_LOAD_S(p, s, i, r), BATCH_STORE_S(p, s, i, r, v)   r <= BATCH_STEP
 *                           elements from element i of a stream of element
 *                           stride s (1 planar, 3 interleaved: the RGB
 *                           batch).  Default: whole unit-stride blocks
 *                           straight, the rest through a stack copy
 * Every batch is one loop: whole vectors straight from the arrays, then one
 * tail through the partial loads and stores, so every n and every
 * alignment takes the same code.  All of a block's inputs are loaded
 * before its outputs are stored: an output may be the very same array as
 * an input. */
#include "../core/platform.h"
#include "../core/port.h"
#include "../core/sample_port.h"

#define BATCH_STR_(x) #x
#define BATCH_STR(x) BATCH_STR_(x)
#define BATCH_CAT_(a, b, c) a##b##c
#define BATCH_CAT(a, b, c) BATCH_CAT_(a, b, c)
#define BATCH_OP(op) BATCH_CAT(facet_, BATCH_PORT, _##op)

/* the port is a line of src/core/ports.def whose guard holds on this
 * target (else the dispatcher would never run these tables): an undeclared
 * batch_listed_<port> below says it is not */
#define FACET_PORT(name, guard, ...) FACET_PORT_IF(guard, enum { batch_listed_##name = 1 };)
#include "../core/ports.def"
#undef FACET_PORT
typedef char BATCH_CAT(batch_listed_, BATCH_PORT, _check_)[BATCH_CAT(batch_listed_, BATCH_PORT, )];

#ifndef BATCH_STEP
#define BATCH_STEP BATCH_W
#endif
#ifndef BATCH_LANES_FN
#define BATCH_LANES_FN NULL
#endif
#ifndef BATCH_SET
#define BATCH_SET(x) BATCH_OP(set)(x)
#endif

/* pad value of the staged copies: any value works (kernels clamp), 0.5 is
 * inside every domain */
#define BATCH_PAD 0.5f

#ifndef BATCH_LOAD_N
/* the staged tail: the r floats and the pad through a BATCH_W-float buffer
 * (the kernels' batches stage all their inputs in one loop instead:
 * BATCH_STAGED, src/f32/f32_batch_body.h) */
#define BATCH_STAGED 1
FACET_INLINE BATCH_V batch_load_n_(const float *p, size_t r)
{
    float t[BATCH_W];
    size_t j;
    for (j = 0; j < BATCH_W; j++)
        t[j] = j < r ? p[j] : BATCH_PAD;
    return BATCH_LOAD(t);
}
FACET_INLINE void batch_store_n_(float *p, BATCH_V v, size_t r)
{
    float t[BATCH_W];
    size_t j;
    BATCH_STORE(t, v);
    for (j = 0; j < r; j++)
        p[j] = t[j];
}
#define BATCH_LOAD_N(p, r) batch_load_n_((p), (r))
#define BATCH_STORE_N(p, v, r) batch_store_n_((p), (v), (r))
#endif

#ifndef BATCH_LOAD_S
/* r elements of stream p (element stride s) from element i */
static BATCH_V batch_load_s_(const float *p, ptrdiff_t s, size_t i, size_t r)
{
    float t[BATCH_W];
    size_t j;
    if (s == 1 && r == BATCH_W)
        return BATCH_LOAD(p + i);
    for (j = 0; j < BATCH_W; j++)
        t[j] = j < r ? p[(ptrdiff_t)(i + j) * s] : BATCH_PAD;
    return BATCH_LOAD(t);
}

static void batch_store_s_(float *p, ptrdiff_t s, size_t i, size_t r, BATCH_V v)
{
    float t[BATCH_W];
    size_t j;
    if (s == 1 && r == BATCH_W) {
        BATCH_STORE(p + i, v);
        return;
    }
    BATCH_STORE(t, v);
    for (j = 0; j < r; j++)
        p[(ptrdiff_t)(i + j) * s] = t[j];
}
#define BATCH_LOAD_S(p, s, i, r) batch_load_s_((p), (s), (i), (r))
#define BATCH_STORE_S(p, s, i, r, v) batch_store_s_((p), (s), (i), (r), (v))
#endif

#define BATCH_TIER f32
#include "f32_batch_body.h"
#include "f32_sample_batch_body.h"
#undef BATCH_TIER
#define BATCH_TIER f32_fast
#include "f32_batch_body.h"
#include "f32_sample_batch_body.h"
#undef BATCH_TIER
