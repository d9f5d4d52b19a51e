/* f32_sample_batch_body.h - one tier of a port's sampler batches and its
 * sampler table facet_sample_port_<port>_<tier> (src/core/sample_port.h),
 * from the inline samplers facet_<sampler>_<tier>_<port>; included by
 * src/f32/f32_port_body.h once per tier with the port's hooks (see there).
 * The same loop as the kernels' (src/f32/f32_batch_body.h): whole vectors,
 * then the tail through the partial loads and stores; a block's inputs are
 * all loaded before its outputs are stored, so outputs may alias inputs.
 * Outputs in locals o0, o1, o2, no arrays of vectors (RVV's are sizeless).
 * Names generated here from src/core/sample_kernels.def: one batch function
 * per sampler, and the table. */
#define SBATCH_FN(k) BATCH_CAT(sbatch_, k, BATCH_CAT(_, BATCH_TIER, _))
#define SBATCH_KERNEL(k) BATCH_CAT(facet_, k, BATCH_CAT(_, BATCH_TIER, BATCH_CAT(_, BATCH_PORT, )))

#ifndef SBATCH_HELPERS_
#define SBATCH_HELPERS_
#define SBATCH_LOAD_AT_(q) BATCH_LOAD(in[q] + i)
#define SBATCH_LOAD_N_AT_(q) BATCH_LOAD_N(in[q] + i, count - i)
#define SBATCH_DECL_1 BATCH_V o0
#define SBATCH_DECL_2 BATCH_V o0, o1
#define SBATCH_DECL_3 BATCH_V o0, o1, o2
/* o0.. = sampler(inputs...): vec takes a pointer per output, ret returns one */
#define SBATCH_CALL_vec_2(k, ...) k(&o0, &o1, __VA_ARGS__)
#define SBATCH_CALL_vec_3(k, ...) k(&o0, &o1, &o2, __VA_ARGS__)
#define SBATCH_CALL_ret_1(k, ...) o0 = k(__VA_ARGS__)
#define SBATCH_STORE_(q, v) BATCH_STORE(out[q] + i, v)
#define SBATCH_STORE_N_(q, v) BATCH_STORE_N(out[q] + i, v, count - i)
#define SBATCH_STORES_1(S) S(0, o0)
#define SBATCH_STORES_2(S) S(0, o0); S(1, o1)
#define SBATCH_STORES_3(S) S(0, o0); S(1, o1); S(2, o2)
#endif

#define FACET_SAMPLER(name, NAME, kind, err, n_out, n_in, ...)                                   \
    static void SBATCH_FN(name)(float *const *out, const float *const *in, size_t count)        \
    {                                                                                           \
        const size_t w_ = BATCH_STEP;                                                           \
        size_t i = 0;                                                                           \
        SBATCH_DECL_##n_out;                                                                    \
        for (; i + w_ <= count; i += w_) {                                                      \
            SBATCH_CALL_##kind##_##n_out(SBATCH_KERNEL(name), FACET_SAMPLE_EACH(n_in, SBATCH_LOAD_AT_)); \
            SBATCH_STORES_##n_out(SBATCH_STORE_);                                               \
        }                                                                                       \
        if (i < count) {                                                                        \
            SBATCH_CALL_##kind##_##n_out(SBATCH_KERNEL(name), FACET_SAMPLE_EACH(n_in, SBATCH_LOAD_N_AT_)); \
            SBATCH_STORES_##n_out(SBATCH_STORE_N_);                                             \
        }                                                                                       \
    }
#include "../core/sample_kernels.def"
#undef FACET_SAMPLER

const facet_sample_port BATCH_CAT(facet_sample_port_, BATCH_PORT, BATCH_CAT(_, BATCH_TIER, )) = {
    BATCH_STR(BATCH_PORT), BATCH_W,
#define FACET_SAMPLER(name, ...) SBATCH_FN(name),
#include "../core/sample_kernels.def"
#undef FACET_SAMPLER
};

#undef SBATCH_FN
#undef SBATCH_KERNEL
