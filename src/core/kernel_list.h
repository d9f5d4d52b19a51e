/* kernel_list.h - helpers for expanding src/core/kernels.def.  Private to the
 * library, the tests and the bench (never installed).
 *
 *   FACET_EACH_INPUT(n, F)   F(0), F(1), ..., F(n - 1): one item per input,
 *                            for parameter lists, argument lists and rows
 *                            (n is a kernel's arity: 1 to 6)
 *   FACET_IF_FX(fx_type, ...)  the rest of the arguments where the kernel
 *                            has a fixed-point version, nothing where its
 *                            fx_type is `none`
 *   FACET_IF_PRECISE(fx_code, ...)  the rest where the kernel has a precise
 *                            fixed-point kernel (facet_<name>_fx: fx_code
 *                            both), nothing where it has none (fast: the
 *                            fx_fast tier only; none)
 *   FACET_PRECISE_OR(fx_code, yes, no)  yes where the kernel has a precise
 *                            fixed-point kernel, no otherwise (one token
 *                            each: a table's function pointer or NULL)
 *   FACET_MAP_INPUTS(n, F, inputs...)  F applied to each of a kernel's n
 *                            FACET_IN() entries, comma-separated; F is one of
 *   FACET_IN_NAME / FACET_IN_LO / FACET_IN_HI (input, domain)
 *                            the input's name as a string, the low and the
 *                            high end of its raw Q15 domain (the last two
 *                            need include/facet/fx.h)
 * A user defines FACET_KERNEL before including kernels.def and undefines it
 * after; FACET_IN is defined here once (an entry is the pair itself). */
#ifndef FACET_KERNEL_LIST_H
#define FACET_KERNEL_LIST_H

#define FACET_EACH_INPUT(n, F) FACET_EACH_INPUT_##n(F)
#define FACET_EACH_INPUT_1(F) F(0)
#define FACET_EACH_INPUT_2(F) F(0), F(1)
#define FACET_EACH_INPUT_3(F) F(0), F(1), F(2)
#define FACET_EACH_INPUT_4(F) F(0), F(1), F(2), F(3)
#define FACET_EACH_INPUT_5(F) F(0), F(1), F(2), F(3), F(4)
#define FACET_EACH_INPUT_6(F) F(0), F(1), F(2), F(3), F(4), F(5)

#define FACET_IF_FX(fx_type, ...) FACET_IF_FX_##fx_type(__VA_ARGS__)
#define FACET_IF_FX_int32_t(...) __VA_ARGS__
#define FACET_IF_FX_uint32_t(...) __VA_ARGS__
#define FACET_IF_FX_uint64_t(...) __VA_ARGS__
#define FACET_IF_FX_none(...)

#define FACET_IF_PRECISE(fx_code, ...) FACET_IF_PRECISE_##fx_code(__VA_ARGS__)
#define FACET_IF_PRECISE_both(...) __VA_ARGS__
#define FACET_IF_PRECISE_fast(...)
#define FACET_IF_PRECISE_none(...)

#define FACET_PRECISE_OR(fx_code, yes, no) FACET_PRECISE_OR_##fx_code(yes, no)
#define FACET_PRECISE_OR_both(yes, no) yes
#define FACET_PRECISE_OR_fast(yes, no) no
#define FACET_PRECISE_OR_none(yes, no) no

#define FACET_IN(input, domain) (input, domain)
#define FACET_MAP_INPUTS(n, F, ...) FACET_MAP_INPUTS_##n(F, __VA_ARGS__)
#define FACET_MAP_INPUTS_1(F, a) F a
#define FACET_MAP_INPUTS_2(F, a, b) F a, F b
#define FACET_MAP_INPUTS_3(F, a, b, c) F a, F b, F c
#define FACET_MAP_INPUTS_4(F, a, b, c, d) F a, F b, F c, F d
#define FACET_MAP_INPUTS_5(F, a, b, c, d, e) F a, F b, F c, F d, F e
#define FACET_MAP_INPUTS_6(F, a, b, c, d, e, f) F a, F b, F c, F d, F e, F f

#define FACET_IN_NAME(input, domain) #input
#define FACET_IN_LO(input, domain) FACET_DOMAIN_LO_##domain
#define FACET_IN_HI(input, domain) FACET_DOMAIN_HI_##domain
#define FACET_DOMAIN_LO_UNIT 0
#define FACET_DOMAIN_HI_UNIT FACET_FX_ONE
#define FACET_DOMAIN_LO_COS FACET_FX_COS_MIN
#define FACET_DOMAIN_HI_COS FACET_FX_ONE
#define FACET_DOMAIN_LO_ALPHA FACET_FX_ALPHA_MIN
#define FACET_DOMAIN_HI_ALPHA FACET_FX_ONE
#define FACET_DOMAIN_LO_LOV (-FACET_FX_ONE)
#define FACET_DOMAIN_HI_LOV FACET_FX_ONE
#define FACET_DOMAIN_LO_GAMMA 0
#define FACET_DOMAIN_HI_GAMMA (4 * FACET_FX_ONE)

#endif
