/* fx_table.c - the fixed-point kernel table behind facet_fx_kernel_at/find:
 * the kernels of src/core/kernels.def that have a fixed-point version, in its
 * order, with each input's raw Q15 domain and the output format.
 * Names generated here from src/core/kernels.def: one table row and its four
 * array-argument wrappers (both tiers) per fixed-point kernel; a kernel
 * with the fast tier only (fx_code fast) has the two fx_fast wrappers, and
 * its row's fx and fx_batch are NULL (err_lsb 0). */
#include "facet/fx.h"
#include "../core/kernel_list.h"

#define SAMPLE_(q) in[q]
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...)     \
    FACET_IF_PRECISE(fx_code,                                                              \
    static uint64_t fx_##name(const int32_t *in)                                           \
    {                                                                                      \
        return (uint64_t)(fx_type)facet_##name##_fx(FACET_EACH_INPUT(n, SAMPLE_)) & FX_MASK_##fx_type; \
    }                                                                                      \
    static void batch_##name(void *out, const int32_t *const *in, size_t count)            \
    {                                                                                      \
        facet_##name##_fx_batch((fx_type *)out, FACET_EACH_INPUT(n, SAMPLE_), count);      \
    })                                                                                     \
    FACET_IF_FX(fx_type,                                                                   \
    static uint64_t fx_fast_##name(const int32_t *in)                                      \
    {                                                                                      \
        return (uint64_t)(fx_type)facet_##name##_fx_fast(FACET_EACH_INPUT(n, SAMPLE_)) & FX_MASK_##fx_type; \
    }                                                                                      \
    static void batch_fast_##name(void *out, const int32_t *const *in, size_t count)       \
    {                                                                                      \
        facet_##name##_fx_fast_batch((fx_type *)out, FACET_EACH_INPUT(n, SAMPLE_), count); \
    })
/* a raw output widened: the container's bits (Q15 outputs are >= 0) */
#define FX_MASK_int32_t 0xFFFFFFFFu
#define FX_MASK_uint32_t 0xFFFFFFFFu
#define FX_MASK_uint64_t 0xFFFFFFFFFFFFFFFFull
#include "../core/kernels.def"
#undef FACET_KERNEL

/* each input array filled to FACET_FX_MAX_INPUTS (6) entries: the unused
 * ones NULL / 0 written out (MISRA C:2012 9.3: no partly initialised array) */
#define PAD_1(z) , z, z, z, z, z
#define PAD_2(z) , z, z, z, z
#define PAD_3(z) , z, z, z
#define PAD_4(z) , z, z
#define PAD_5(z) , z
#define PAD_6(z)
static const facet_fx_kernel table[] = {
#define FACET_KERNEL(name, NAME, n, fx_type, fx_frac, fx_max, fx_format, fx_code, ...) FACET_IF_FX(fx_type, \
    { #name, n, { FACET_MAP_INPUTS(n, FACET_IN_NAME, __VA_ARGS__) PAD_##n(NULL) },                \
      { FACET_MAP_INPUTS(n, FACET_IN_LO, __VA_ARGS__) PAD_##n(0) },                               \
      { FACET_MAP_INPUTS(n, FACET_IN_HI, __VA_ARGS__) PAD_##n(0) }, fx_frac, (int)sizeof(fx_type) * 8, \
      fx_format, fx_max, FACET_PRECISE_OR(fx_code, fx_##name, NULL),                               \
      FACET_PRECISE_OR(fx_code, batch_##name, NULL), FACET_PRECISE_OR(fx_code, FACET_FX_ERR_##NAME, 0), \
      fx_fast_##name, batch_fast_##name, FACET_FX_FAST_ERR_##NAME },)
#include "../core/kernels.def"
#undef FACET_KERNEL
};

size_t facet_fx_kernel_count(void) { return sizeof table / sizeof table[0]; }

const facet_fx_kernel *facet_fx_kernel_at(size_t i)
{
    return i < facet_fx_kernel_count() ? &table[i] : NULL;
}

/* strcmp() == 0 without <string.h>: the firmware sources need no libc */
static int same_name(const char *a, const char *b)
{
    while (*a && *a == *b) {
        a++, b++;
    }
    return *a == *b;
}

const facet_fx_kernel *facet_fx_kernel_find(const char *name)
{
    size_t i;
    for (i = 0; name && i < facet_fx_kernel_count(); i++) {
        if (same_name(table[i].name, name) != 0) {
            return &table[i];
        }
    }
    return NULL;
}
