/* f32_one_body.h - one tier of a port's per-sample entries and their table
 * (facet_f32_one, src/core/port.h): the scalar port's inline kernels
 * (facet/scalar.h) compiled in the port's own object, i.e. with its flags,
 * so that scalar.h's ops follow them (on x86 with FMA the hardware's
 * estimates and square root, one lane of the AVX2 / AVX-512 arithmetic;
 * FMA on NEON, Helium and RVV targets; the portable ops elsewhere).
 * Included by src/f32/f32_batch_body.h once per tier, which puts the table
 * (facet_one_<port>_<tier>) in the port's facet_f32_port (member one).
 * A port whose own flags do not make good scalar code names the port whose
 * table it takes instead, BATCH_ONE_FROM (a port its CPU test implies):
 * ports/avx512/f32_avx512.c takes avx2's, ports/helium/f32_helium.c the
 * scalar port's (the same code there).
 * Names generated here from src/core/kernels.def: one function per kernel. */
#include "facet/scalar.h"

#define BATCH_ONE_FN(k) BATCH_CAT(one_, k, BATCH_CAT(_, BATCH_TIER, _))
#define BATCH_ONE_KERNEL(k) BATCH_CAT(facet_, k, BATCH_CAT(_, BATCH_TIER, _scalar))
#define BATCH_ONE_TABLE_OF(p) BATCH_CAT(facet_one_, p, BATCH_CAT(_, BATCH_TIER, ))
#ifdef BATCH_ONE_FROM
#define BATCH_ONE_TABLE BATCH_ONE_TABLE_OF(BATCH_ONE_FROM)
extern const facet_f32_one BATCH_ONE_TABLE;
#else
#define BATCH_ONE_TABLE BATCH_ONE_TABLE_OF(BATCH_PORT)
#define BATCH_ONE_PARAM_(q) float x##q
#define BATCH_ONE_ARG_(q) x##q

#define FACET_KERNEL(name, NAME, n, ...)                                    \
    static float BATCH_ONE_FN(name)(FACET_EACH_INPUT(n, BATCH_ONE_PARAM_))  \
    {                                                                       \
        return BATCH_ONE_KERNEL(name)(FACET_EACH_INPUT(n, BATCH_ONE_ARG_)); \
    }
#include "../core/kernels.def"
#undef FACET_KERNEL

static void BATCH_ONE_FN(brdf_hammon_rgb)(float out[3], float nol, float nov, float lov, float alpha,
                                          const float f0[3], const float albedo[3])
{
    BATCH_CAT(facet_brdf_hammon_rgb_, BATCH_TIER, _scalar)(&out[0], &out[1], &out[2], nol, nov, lov, alpha,
                                                           f0[0], f0[1], f0[2], albedo[0], albedo[1],
                                                           albedo[2]);
}

extern const facet_f32_one BATCH_ONE_TABLE;
const facet_f32_one BATCH_ONE_TABLE = {
#define FACET_KERNEL(name, NAME, n, ...) BATCH_ONE_FN(name),
#include "../core/kernels.def"
#undef FACET_KERNEL
    BATCH_ONE_FN(brdf_hammon_rgb),
};

#endif /* !BATCH_ONE_FROM */

#undef BATCH_ONE_FN
#undef BATCH_ONE_KERNEL
