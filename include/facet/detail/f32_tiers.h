/* facet/detail/f32_tiers.h - one body in both tiers for one port header
 * (included by the port headers, not by you; once per body, so no include
 * guard).  Define before including:
 *   FACET_V          the port's vector type
 *   FACET_PORT_NAME  the port's name: its op layer is facet_<port>_<op>, its
 *                    kernels facet_<k>_f32_<port> and facet_<k>_f32_fast_<port>
 *   FACET_BODY_SAMPLES  the body: 0 "facet/detail/f32_body.h" (the
 *                    kernels), 1 "facet/detail/f32_sample_body.h" (the
 *                    samplers); a flag, not a macro naming the file for a
 *                    computed include: pcc's preprocessor (1.2.0.DEVEL
 *                    20220331) aborts on a computed include (a double free)
 *                    and leaves its output cut short, so suite 25's pcc
 *                    probes of the port headers compiled nothing or a
 *                    fragment
 * and it defines FACET_OP and FACET_K for the body, the fast tier with
 * FACET_TIER_FAST 1; all of these are undefined again at the end. */
#ifndef FACET_XCAT3_
#define FACET_CAT3_(a, b, c) a##b##c
#define FACET_XCAT3_(a, b, c) FACET_CAT3_(a, b, c)
#endif

#define FACET_OP(op) FACET_XCAT3_(facet_, FACET_PORT_NAME, _##op)
#define FACET_K(k) FACET_XCAT3_(facet_##k, _f32_, FACET_PORT_NAME)
#if FACET_BODY_SAMPLES
#include "facet/detail/f32_sample_body.h"
#else
#include "facet/detail/f32_body.h"
#endif
#undef FACET_K
#define FACET_TIER_FAST 1
#define FACET_K(k) FACET_XCAT3_(facet_##k, _f32_fast_, FACET_PORT_NAME)
#if FACET_BODY_SAMPLES
#include "facet/detail/f32_sample_body.h"
#else
#include "facet/detail/f32_body.h"
#endif
#undef FACET_TIER_FAST
#undef FACET_K
#undef FACET_OP
#undef FACET_V
#undef FACET_PORT_NAME
#undef FACET_BODY_SAMPLES
