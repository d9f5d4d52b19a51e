/* f16_port_body.h - an f16 port's batches and its table facet_f16_port_<port>
 * (src/core/f16_port.h), from its inline kernels facet_<kernel>_f16_<port>.
 * A port's f16 file includes it once, after its inline header, with:
 *   F16_PORT             the port's name token (ports.def's f16 column)
 *   F16_W                its lanes (0: vector-length agnostic, see F16_STEP)
 *   F16_STEP             lanes per vector at run time, an expression (default
 *                        F16_W; rvvfp16: VLMAX)
 *   F16_NEEDS            what the CPU needs for it (a string, "" for none)
 *   F16_LOAD(p), F16_STORE(p, v)          a whole vector of binary16 bits
 *   F16_LOAD_N(p, r), F16_STORE_N(p, v, r) the tail: r < F16_STEP values,
 *                        nothing read or written past p + r
 * Names generated here from src/core/f16_kernels.def.  Every batch is one
 * loop: whole vectors, then one tail; all of a block's inputs are loaded
 * before its output is stored, so out may be an input. */
#include "../core/f16_port.h"

#ifndef F16_STEP
#define F16_STEP F16_W
#endif

#define F16_CAT_(a, b, c) a##b##c
#define F16_CAT(a, b, c) F16_CAT_(a, b, c)
#define F16_STR_(x) #x
#define F16_STR(x) F16_STR_(x)
#define F16_FN(k) F16_CAT(f16_batch_, k, _)
#define F16_KERNEL(k) F16_CAT(facet_, k, F16_CAT(_f16_, F16_PORT, ))

#define F16_PARAM_(q) const uint16_t *x##q
#define F16_LOAD_AT_(q) F16_LOAD(x##q + i)
#define F16_LOAD_N_AT_(q) F16_LOAD_N(x##q + i, count - i)

#define FACET_F16(name, NAME, n, form, why)                                                     \
    FACET_IF_F16(form,                                                                          \
    static void F16_FN(name)(uint16_t *out, FACET_EACH_INPUT(n, F16_PARAM_), size_t count)      \
    {                                                                                           \
        size_t i = 0, w_ = F16_STEP;                                                            \
        for (; i + w_ <= count; i += w_)                                                        \
            F16_STORE(out + i, F16_KERNEL(name)(FACET_EACH_INPUT(n, F16_LOAD_AT_)));            \
        if (i < count)                                                                          \
            F16_STORE_N(out + i, F16_KERNEL(name)(FACET_EACH_INPUT(n, F16_LOAD_N_AT_)), count - i); \
    })
#include "../core/f16_kernels.def"
#undef FACET_F16

const facet_f16_port F16_CAT(facet_f16_port_, F16_PORT, ) = {
    F16_STR(F16_PORT), F16_W,
#define FACET_F16(name, NAME, n, form, why) FACET_IF_F16(form, F16_FN(name),)
#include "../core/f16_kernels.def"
#undef FACET_F16
    F16_NEEDS,
};
