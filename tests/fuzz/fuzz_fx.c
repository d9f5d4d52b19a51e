/* fuzz_fx.c - libFuzzer target for the fixed-point kernels.
 * Input: kernel (byte 0), n (byte 1), misalignment and aliasing (byte 2),
 * then raw int32 input patterns (every 32-bit pattern is a valid input).
 *   - the public batch facet_<kernel>_fx_batch under every port this CPU
 *     runs (facet_set_port) equals the scalar facet_<kernel>_fx bit for
 *     bit (a kernel with the fast tier only: its _fx_fast ones), for every n, misalignment and the permitted aliasing (out the
 *     very same array as an input, 32-bit outputs);
 *   - saturation: a Q15 result is in [0, 32768], none above the format's
 *     maximum;
 *   - clamping: a result equals the result at the clamped inputs;
 *   - monotonicity where the function is monotone (the list of
 *     tests/fx/test_fx_accuracy.c): consecutive samples that differ in one
 *     such input are ordered. */
#include "facet.h"
#include "facet/fx.h"
#include "fuzz_common.h"

#define MAX_N 80

/* The kernel and tier under test: the fx table's row (byte 0 picks it, in
 * kernels.def order), its precise kernel and batch, or for a kernel with
 * the fast tier only (fx NULL) its fx_fast ones. */
typedef struct {
    const char *name;
    void (*batch)(void *out, const int32_t *const *in, size_t n);
    uint64_t (*fx)(const int32_t *in);
    size_t out_size;
} fx_batch;

static uint64_t widen(const void *out, size_t size, size_t j)
{
    if (size == 8)
        return ((const uint64_t *)out)[j];
    return ((const uint32_t *)out)[j];
}

/* dir +1: non-decreasing in that input, -1: non-increasing */
static const struct { const char *k, *in; int dir; } mono[] = {
    { "noh_from_dots", "nol", 1 }, { "noh_from_dots", "nov", 1 }, { "noh_from_dots", "lov", -1 },
    { "loh_from_dots", "lov", 1 }, { "fresnel_schlick", "f0", 1 }, { "fresnel_schlick", "cos", -1 },
    { "ggx_d", "noh", 1 }, { "smith_g1", "nov", 1 }, { "smith_g1", "alpha", -1 },
    { "smith_g2", "nol", 1 }, { "smith_g2", "nov", 1 }, { "smith_g2", "alpha", -1 },
    { "smith_g2_uncorrelated", "nol", 1 }, { "smith_g2_uncorrelated", "nov", 1 },
    { "smith_g2_uncorrelated", "alpha", -1 }, { "smith_vis", "nol", -1 }, { "smith_vis", "nov", -1 },
    { "smith_vis", "alpha", -1 }, { "smith_g1_hammon", "nov", 1 }, { "smith_g1_hammon", "alpha", -1 },
    { "smith_g2_hammon", "nol", 1 }, { "smith_g2_hammon", "nov", 1 }, { "smith_g2_hammon", "alpha", -1 },
    { "smith_vis_hammon", "nol", -1 }, { "smith_vis_hammon", "nov", -1 }, { "smith_vis_hammon", "alpha", -1 },
    { "diffuse_hammon", "albedo", 1 }, { "brdf_hammon", "f0", 1 }, { "brdf_hammon", "albedo", 1 },
};

static void check_scalar(const facet_fx_kernel *k, const fx_batch *b, int32_t in[][MAX_N], size_t n)
{
    size_t j, m;
    int i;
    for (j = 0; j < n; j++) {
        int32_t x[FACET_FX_MAX_INPUTS], c[FACET_FX_MAX_INPUTS];
        uint64_t y;
        for (i = 0; i < k->n_inputs; i++) {
            x[i] = in[i][j];
            c[i] = x[i] < k->lo[i] ? k->lo[i] : x[i] > k->hi[i] ? k->hi[i] : x[i];
        }
        y = b->fx(x);
        if (k->out_frac == 15 && k->out_bits == 32 && y > FACET_FX_MAX_Q15)
            FUZZ_FAIL("%s: sample %zu: Q15 result %llu above 32768", k->name, j, (unsigned long long)y);
        if (y > k->out_max)
            FUZZ_FAIL("%s: sample %zu: result %llu above the format maximum", k->name, j, (unsigned long long)y);
        if (b->fx(c) != y)
            FUZZ_FAIL("%s: sample %zu: %llu, at the clamped inputs %llu", k->name, j, (unsigned long long)y,
                      (unsigned long long)b->fx(c));
        if (j == 0)
            continue;
        /* consecutive samples: monotone inputs move the result their way */
        for (m = 0; m < sizeof mono / sizeof mono[0]; m++) {
            int32_t p[FACET_FX_MAX_INPUTS];
            int w = -1;
            uint64_t yp;
            if (strcmp(mono[m].k, k->name))
                continue;
            for (i = 0; i < k->n_inputs; i++)
                if (!strcmp(k->inputs[i], mono[m].in))
                    w = i;
            if (w < 0)
                FUZZ_FAIL("%s: no input %s", k->name, mono[m].in);
            memcpy(p, x, sizeof p);
            p[w] = in[w][j - 1]; /* the previous sample's value of that input alone */
            yp = b->fx(p);
            if ((p[w] < x[w] && (mono[m].dir > 0 ? yp > y : yp < y)) ||
                (p[w] > x[w] && (mono[m].dir > 0 ? yp < y : yp > y)))
                FUZZ_FAIL("%s: not monotone in %s: %s = %ld gives %llu, %ld gives %llu", k->name, mono[m].in,
                          mono[m].in, (long)p[w], (unsigned long long)yp, (long)x[w], (unsigned long long)y);
        }
    }
}

static void check_port(const facet_fx_kernel *k, const fx_batch *b, const char *port, int32_t in[][MAX_N], size_t n,
                       size_t off, int alias)
{
    void *base[FACET_FX_MAX_INPUTS + 1], *out;
    int32_t *buf[FACET_FX_MAX_INPUTS];
    const int32_t *ptr[FACET_FX_MAX_INPUTS];
    size_t j;
    int i;
    for (i = 0; i < k->n_inputs; i++) {
        buf[i] = fuzz_buf(n, sizeof(int32_t), off, &base[i]);
        memcpy(buf[i], in[i], n * sizeof(int32_t));
        ptr[i] = buf[i];
    }
    out = fuzz_buf(n, b->out_size, (off + 5) % 8, &base[FACET_FX_MAX_INPUTS]);
    b->batch(out, ptr, n);
    for (j = 0; j < n; j++) {
        int32_t x[FACET_FX_MAX_INPUTS];
        uint64_t want;
        for (i = 0; i < k->n_inputs; i++)
            x[i] = in[i][j];
        want = b->fx(x);
        if (widen(out, b->out_size, j) != want)
            FUZZ_FAIL("%s/%s (fx %s): sample %zu of %zu: batch %llu, scalar %llu", port, k->name,
                      facet_fx_port_name(), j, n, (unsigned long long)widen(out, b->out_size, j),
                      (unsigned long long)want);
    }
    if (alias && n > 0 && b->out_size == 4) { /* out the very same array as input alias - 1 */
        int w = (alias - 1) % k->n_inputs;
        b->batch(buf[w], ptr, n);
        for (j = 0; j < n; j++)
            if (widen(buf[w], 4, j) != widen(out, 4, j))
                FUZZ_FAIL("%s/%s: out aliasing input %d: sample %zu %llu vs %llu", port, k->name, w, j,
                          (unsigned long long)widen(buf[w], 4, j), (unsigned long long)widen(out, 4, j));
    }
    for (i = 0; i < k->n_inputs; i++)
        free(base[i]);
    free(base[FACET_FX_MAX_INPUTS]);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static int32_t in[FACET_FX_MAX_INPUTS][MAX_N];
    fx_batch tier;
    const fx_batch *b;
    const facet_fx_kernel *k;
    size_t n, off, j, p;
    int i, alias;
    if (size < 3)
        return 0;
    k = facet_fx_kernel_at(data[0] % facet_fx_kernel_count());
    if (!k || !k->fx_fast || !k->fx_fast_batch || !k->fx != !k->fx_batch)
        FUZZ_FAIL("fx table row %u: incomplete", (unsigned)(data[0] % facet_fx_kernel_count()));
    tier.name = k->name;
    tier.fx = k->fx ? k->fx : k->fx_fast;
    tier.batch = k->fx ? k->fx_batch : k->fx_fast_batch;
    tier.out_size = (size_t)k->out_bits / 8;
    b = &tier;
    n = data[1] % (MAX_N + 1);
    off = data[2] & 7;
    alias = (data[2] >> 3) % (FACET_FX_MAX_INPUTS + 1);
    for (j = 0; j < n; j++)
        for (i = 0; i < k->n_inputs; i++)
            in[i][j] = (int32_t)fuzz_word(data + 3, size - 3, 4 * (j * (size_t)k->n_inputs + (size_t)i));
    check_scalar(k, b, in, n);
    for (p = 0; p < facet_port_count(); p++) {
        int sup;
        const char *port = facet_port_at(p, &sup, NULL);
        if (!sup)
            continue;
        if (facet_set_port(port) != 0)
            FUZZ_FAIL("%s: supported but not selectable", port);
        check_port(k, b, port, in, n, off, alias);
    }
    return 0;
}
