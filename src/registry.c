/* registry.c - the kernel table behind facet_kernel_at/find. */
#include <string.h>
#include "facet.h"
#include "facet/oracle.h"

#define A1(f, T, in) f(in[0])
#define A2(f, T, in) f(in[0], in[1])
#define A3(f, T, in) f(in[0], in[1], in[2])
#define A5(f, T, in) f(in[0], in[1], in[2], in[3], in[4])
#define A6(f, T, in) f(in[0], in[1], in[2], in[3], in[4], in[5])

#define K(name, NAME, n, ...)                                                  \
    static float f32_##name(const float *in) { return A##n(facet_##name##_f32, float, in); } \
    static double oracle_##name(const double *in) { return A##n(facet_oracle_##name, double, in); }
#include "kernels.def"
#undef K

#define B1(f, in) f(out, in[0], n)
#define B2(f, in) f(out, in[0], in[1], n)
#define B3(f, in) f(out, in[0], in[1], in[2], n)
#define B5(f, in) f(out, in[0], in[1], in[2], in[3], in[4], n)
#define B6(f, in) f(out, in[0], in[1], in[2], in[3], in[4], in[5], n)
#define K(name, NAME, n_in, ...)                                                     \
    static void batch_##name(float *out, const float *const *in, size_t n)          \
    { B##n_in(facet_##name##_f32_batch, in); }
#include "kernels.def"
#undef K

static const facet_kernel table[] = {
#define K(name, NAME, n, ...) \
    { #name, n, { __VA_ARGS__ }, f32_##name, oracle_##name, batch_##name, FACET_ERR_##NAME##_F32 },
#include "kernels.def"
#undef K
};

size_t facet_kernel_count(void) { return sizeof table / sizeof table[0]; }

const facet_kernel *facet_kernel_at(size_t i)
{
    return i < facet_kernel_count() ? &table[i] : NULL;
}

const facet_kernel *facet_kernel_find(const char *name)
{
    size_t i;
    for (i = 0; name && i < facet_kernel_count(); i++)
        if (strcmp(table[i].name, name) == 0)
            return &table[i];
    return NULL;
}
