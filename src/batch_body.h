/* batch_body.h - instantiates a port's batch functions and its port table
 * from the inline kernels.  Include after the port header with
 *   BATCH_PORT   port name token (scalar, sse2, ...)
 *   BATCH_W      lanes
 *   BATCH_V      vector type
 *   BATCH_LOAD(p) / BATCH_STORE(p, v)   unaligned load / store
 * Whole vectors straight from the arrays; the tail (n % W) through a padded
 * stack copy, so every n and every alignment takes the same code.  All of a
 * block's inputs are loaded before its output is stored: out may alias any
 * input. */
#define BATCH_STR_(x) #x
#define BATCH_CAT_STR(x) BATCH_STR_(x)
#define BATCH_CAT_(a, b, c) a##b##c
#define BATCH_CAT(a, b, c) BATCH_CAT_(a, b, c)
#define BATCH_FN(k) BATCH_CAT(batch_, k, _)
#define BATCH_KERNEL(k) BATCH_CAT(facet_, k, BATCH_CAT(_f32_, BATCH_PORT, ))

/* pad value: any value works (kernels clamp), 0.5 is inside every domain */
#define BATCH_PAD 0.5f

#define BATCH_DEF(k, PARAMS, LOADS, TAILCOPY, TAILLOADS)                          \
    static void BATCH_FN(k) PARAMS                                                \
    {                                                                             \
        size_t i = 0;                                                             \
        for (; i + BATCH_W <= n_; i += BATCH_W)                                   \
            BATCH_STORE(out + i, BATCH_KERNEL(k) LOADS);                          \
        if (i < n_) {                                                             \
            float t_[6][BATCH_W], o_[BATCH_W];                                    \
            size_t j, r = n_ - i;                                                 \
            for (j = 0; j < BATCH_W; j++) {                                       \
                TAILCOPY                                                          \
            }                                                                     \
            BATCH_STORE(o_, BATCH_KERNEL(k) TAILLOADS);                           \
            for (j = 0; j < r; j++)                                               \
                out[i + j] = o_[j];                                               \
        }                                                                         \
    }

#define TC_(q, src) t_[q][j] = j < r ? src[i + j] : BATCH_PAD;
#define TL_(q) BATCH_LOAD(t_[q])

#define BATCH1(k) BATCH_DEF(k, (float *out, const float *a, size_t n_),                  \
    (BATCH_LOAD(a + i)), TC_(0, a), (TL_(0)))
#define BATCH2(k) BATCH_DEF(k, (float *out, const float *a, const float *b, size_t n_),  \
    (BATCH_LOAD(a + i), BATCH_LOAD(b + i)), TC_(0, a) TC_(1, b), (TL_(0), TL_(1)))
#define BATCH3(k) BATCH_DEF(k, (float *out, const float *a, const float *b, const float *c, size_t n_), \
    (BATCH_LOAD(a + i), BATCH_LOAD(b + i), BATCH_LOAD(c + i)), TC_(0, a) TC_(1, b) TC_(2, c),               \
    (TL_(0), TL_(1), TL_(2)))
#define BATCH5(k) BATCH_DEF(k, (float *out, const float *a, const float *b, const float *c,               \
    const float *d, const float *e, size_t n_),                                                             \
    (BATCH_LOAD(a + i), BATCH_LOAD(b + i), BATCH_LOAD(c + i), BATCH_LOAD(d + i), BATCH_LOAD(e + i)),        \
    TC_(0, a) TC_(1, b) TC_(2, c) TC_(3, d) TC_(4, e), (TL_(0), TL_(1), TL_(2), TL_(3), TL_(4)))
#define BATCH6(k) BATCH_DEF(k, (float *out, const float *a, const float *b, const float *c,               \
    const float *d, const float *e, const float *f, size_t n_),                                             \
    (BATCH_LOAD(a + i), BATCH_LOAD(b + i), BATCH_LOAD(c + i), BATCH_LOAD(d + i), BATCH_LOAD(e + i),         \
     BATCH_LOAD(f + i)),                                                                                    \
    TC_(0, a) TC_(1, b) TC_(2, c) TC_(3, d) TC_(4, e) TC_(5, f),                                            \
    (TL_(0), TL_(1), TL_(2), TL_(3), TL_(4), TL_(5)))

#define K(name, NAME, n, ...) BATCH##n(name)
#include "kernels.def"
#undef K

const facet_f32_port BATCH_CAT(facet_port_, BATCH_PORT, _f32) = {
    BATCH_CAT_STR(BATCH_PORT), BATCH_W,
#define K(name, NAME, n, ...) BATCH_FN(name),
#include "kernels.def"
#undef K
};
