/* f16_entry.c - the library's per-sample f16 entry points (the scalar
 * port, out of line), the conversions, and the f16 kernel table.
 * Names generated here from src/core/f16_kernels.def: facet_<kernel>_f16
 * and the table's rows (the batches are src/core/dispatch.c's). */
#include <string.h>
#include "facet/f16.h"
#include "facet/f16_scalar.h"
#include "../core/f16_list.h"

#define PARAM_(q) facet_f16 x##q
#define ARG_(q) facet_f16_scalar_from_bits(x##q)
#define FACET_F16(name, NAME, n, form, why)                                                   \
    FACET_IF_F16(form, facet_f16 facet_##name##_f16(FACET_EACH_INPUT(n, PARAM_))             \
    {                                                                                         \
        return facet_f16_scalar_to_bits(facet_##name##_f16_scalar(FACET_EACH_INPUT(n, ARG_)));  \
    })
#include "../core/f16_kernels.def"
#undef FACET_F16

float facet_f32_from_f16(facet_f16 h) { return facet_f16_scalar_from_bits(h); }
facet_f16 facet_f16_from_f32(float x) { return facet_f16_scalar_to_bits(x); }
void facet_f16_from_f32_batch(facet_f16 *out, const float *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        out[i] = facet_f16_scalar_to_bits(in[i]);
}
void facet_f32_from_f16_batch(float *out, const facet_f16 *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        out[i] = facet_f16_scalar_from_bits(in[i]);
}

/* ---- the table ---- */
#define IN_(q) in[q]
#define FACET_F16(name, NAME, n, form, why)                                                   \
    FACET_IF_F16(form, static facet_f16 t_##name(const facet_f16 *in)                        \
    {                                                                                         \
        return facet_##name##_f16(FACET_EACH_INPUT(n, IN_));                                  \
    }                                                                                         \
    static void tb_##name(facet_f16 *out, const facet_f16 *const *in, size_t count)           \
    {                                                                                         \
        facet_##name##_f16_batch(out, FACET_EACH_INPUT(n, IN_), count);                       \
    })
#include "../core/f16_kernels.def"
#undef FACET_F16

#define ROW_f16(name, NAME, n, why) { #name, n, t_##name, tb_##name, FACET_ERR_##NAME##_F16, why },
#define ROW_none(name, NAME, n, why) { #name, n, NULL, NULL, 0.0, why },
static const facet_f16_kernel table[] = {
#define FACET_F16(name, NAME, n, form, why) ROW_##form(name, NAME, n, why)
#include "../core/f16_kernels.def"
#undef FACET_F16
};

size_t facet_f16_kernel_count(void) { return sizeof table / sizeof table[0]; }
const facet_f16_kernel *facet_f16_kernel_at(size_t i)
{
    return i < sizeof table / sizeof table[0] ? &table[i] : NULL;
}
const facet_f16_kernel *facet_f16_kernel_find(const char *name)
{
    size_t i;
    for (i = 0; name && i < sizeof table / sizeof table[0]; i++)
        if (!strcmp(name, table[i].name))
            return &table[i];
    return NULL;
}
