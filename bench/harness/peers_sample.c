/* peers_sample.c - the textbook peers of the samplers (tests/lib/sample_peer.h:
 * the direct formulas with libm, as a renderer writes them from the
 * papers), as batch loops over SoA arrays for the bench.  Built like
 * peers_textbook.c (-O2, default floating point, bench/bench.mk).  Inputs
 * in the order of the facet sampler of the same name (facet.h); see peers.h. */
#include <string.h>
#include "facet.h"
#include "tests/lib/sample_peer.h"
#include "peers.h"

static void s_ggx_sample_d(float *const *out, const float *const *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        float h[3];
        peer_ggx_sample_d(h, in[0][i], in[1][i], in[2][i]);
        out[0][i] = h[0];
        out[1][i] = h[1];
        out[2][i] = h[2];
    }
}

static void s_ggx_pdf_d(float *const *out, const float *const *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        out[0][i] = peer_ggx_pdf_d(in[0][i], in[1][i]);
}

static void s_ggx_sample_vndf(float *const *out, const float *const *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        float h[3];
        peer_ggx_sample_vndf(h, in[0][i], in[1][i], in[2][i], in[3][i], in[4][i], in[5][i]);
        out[0][i] = h[0];
        out[1][i] = h[1];
        out[2][i] = h[2];
    }
}

static void s_ggx_pdf_vndf(float *const *out, const float *const *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        out[0][i] = peer_ggx_pdf_vndf(in[0][i], in[1][i], in[2][i], in[3][i]);
}

/* the GTR1 formula only: the facet rows of gtr_sample_d are timed with
 * gamma = 1 as well (bench.c) */
static void s_gtr_sample_d(float *const *out, const float *const *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        float h[3];
        peer_gtr1_sample_d(h, in[0][i], in[1][i], in[2][i]);
        out[0][i] = h[0];
        out[1][i] = h[1];
        out[2][i] = h[2];
    }
}

static void s_sincos_2pi(float *const *out, const float *const *in, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        float p = 2.0f * PEER_PI_ * in[0][i];
        out[0][i] = sinf(p);
        out[1][i] = cosf(p);
    }
}

static const struct {
    const char *name;
    peer_sample_fn fn;
    int same_map; /* 1: the same (u1, u2) -> h map as facet's oracle */
} table[] = {
    { "ggx_sample_d", s_ggx_sample_d, 1 },
    { "ggx_pdf_d", s_ggx_pdf_d, 1 },
    { "ggx_sample_vndf", s_ggx_sample_vndf, 0 }, /* Heitz's disk map, not the spherical cap's */
    { "ggx_pdf_vndf", s_ggx_pdf_vndf, 1 },
    { "gtr_sample_d", s_gtr_sample_d, 1 },
    { "sincos_2pi", s_sincos_2pi, 1 },
};

peer_sample_fn peer_sample_textbook(const char *name, int *same_map)
{
    size_t i;
    for (i = 0; i < sizeof table / sizeof table[0]; i++)
        if (!strcmp(table[i].name, name)) {
            if (same_map)
                *same_map = table[i].same_map;
            return table[i].fn;
        }
    return NULL;
}
