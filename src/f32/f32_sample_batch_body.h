/* sample_batch_body.h - instantiates a port's sampler batch functions and
 * its sampler table (src/core/sample_port.h) from the inline samplers, like
 * src/f32/f32_batch_body.h for the kernels.  Include after the port header with
 * BATCH_PORT, BATCH_TIER, BATCH_W, BATCH_V, BATCH_LOAD, BATCH_STORE (see
 * batch_body.h).  Whole vectors straight from the arrays, the tail through
 * a padded stack copy; a block's inputs are all loaded before its outputs
 * are stored, so outputs may alias inputs. */
#include "../core/sample_port.h"

#define SBATCH_CAT_(a, b, c) a##b##c
#define SBATCH_CAT(a, b, c) SBATCH_CAT_(a, b, c)
#define SBATCH_STR_(x) #x
#define SBATCH_STR(x) SBATCH_STR_(x)
#define SBATCH_FN(k) SBATCH_CAT(sbatch_, k, SBATCH_CAT(_, BATCH_TIER, _))
#define SBATCH_KERNEL(k) SBATCH_CAT(facet_, k, SBATCH_CAT(_, BATCH_TIER, SBATCH_CAT(_, BATCH_PORT, )))

#define FACET_SAMPLER(name, NAME, kind, err, n_out, n_in, ...)                        \
    static void SBATCH_FN(name)(float *const *out, const float *const *in, size_t count) \
    {                                                                                \
        size_t i = 0, j;                                                             \
        int q;                                                                       \
        BATCH_V a_[n_in], o_[n_out];                                                 \
        for (; i + BATCH_W <= count; i += BATCH_W) {                                 \
            for (q = 0; q < n_in; q++)                                               \
                a_[q] = BATCH_LOAD(in[q] + i);                                       \
            FACET_SAMPLE_CALL(kind, SBATCH_KERNEL(name), o_, n_out, a_, n_in);              \
            for (q = 0; q < n_out; q++)                                              \
                BATCH_STORE(out[q] + i, o_[q]);                                      \
        }                                                                            \
        if (i < count) {                                                             \
            float pad_[BATCH_W], res_[BATCH_W];                                      \
            size_t r = count - i;                                                    \
            for (q = 0; q < n_in; q++) {                                             \
                for (j = 0; j < BATCH_W; j++)                                        \
                    pad_[j] = j < r ? in[q][i + j] : 0.5f;                           \
                a_[q] = BATCH_LOAD(pad_);                                            \
            }                                                                        \
            FACET_SAMPLE_CALL(kind, SBATCH_KERNEL(name), o_, n_out, a_, n_in);              \
            for (q = 0; q < n_out; q++) {                                            \
                BATCH_STORE(res_, o_[q]);                                            \
                for (j = 0; j < r; j++)                                              \
                    out[q][i + j] = res_[j];                                         \
            }                                                                        \
        }                                                                            \
    }
#include "../core/sample_kernels.def"
#undef FACET_SAMPLER

const facet_sample_port SBATCH_CAT(facet_sample_port_, BATCH_PORT, SBATCH_CAT(_, BATCH_TIER, )) = {
    SBATCH_STR(BATCH_PORT), BATCH_W,
#define FACET_SAMPLER(name, ...) SBATCH_FN(name),
#include "../core/sample_kernels.def"
#undef FACET_SAMPLER
};
