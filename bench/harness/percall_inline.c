/* percall_inline.c - facet/scalar.h inline, one sample per call of a loop
 * that is not vectorized, under the user's -march (bench/harness/percall.h). */
#include "facet/scalar.h"
#include "percall.h"

#define PERCALL_STR_(x) #x
#define PERCALL_STR(x) PERCALL_STR_(x)
const char percall_march[] = PERCALL_STR(PERCALL_MARCH);

void percall_scalar_h(float *out, const float *const *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        out[i] = facet_brdf_hammon_f32_scalar(in[0][i], in[1][i], in[2][i], in[3][i], in[4][i], in[5][i]);
}

void percall_scalar_h_fast(float *out, const float *const *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        out[i] = facet_brdf_hammon_f32_fast_scalar(in[0][i], in[1][i], in[2][i], in[3][i], in[4][i], in[5][i]);
}
