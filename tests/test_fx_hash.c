/* test_fx_hash.c - pinned output hashes of every fixed-point kernel over
 * fixed input grids.  Integer only and libc-light (printf), so the same
 * file runs on the host (make check), under qemu-user (aarch64, armv7) and
 * bare-metal on Cortex-M0/M4 (tests/fx.mk): every target must print the
 * same hashes, the ones pinned here.
 * Inputs: for one-input kernels every raw value in [-40000, 40000]; for
 * two-input kernels a 129 x 129 grid over the domain plus the clamping
 * edges; for all, 3000 pseudo-random raw tuples (an LCG, 1 in 8 inputs out
 * of domain).  Hash: FNV-1a 64 over the outputs as little-endian bytes. */
#include <stdio.h>
#include <string.h>
#include "harness.h"
#include "facet/fx.h"

static uint64_t h_;
static void feed(uint64_t v, int bytes)
{
    int i;
    for (i = 0; i < bytes; i++) {
        h_ ^= (v >> (8 * i)) & 0xFFu;
        h_ *= 0x100000001B3ull;
    }
}

static uint32_t lcg_; /* Numerical Recipes LCG, top bits used */
static uint32_t lcg(void) { lcg_ = lcg_ * 1664525u + 1013904223u; return lcg_; }

static int32_t rand_in(const facet_fx_kernel *k, int i)
{
    uint32_t r = lcg();
    uint32_t span = (uint32_t)(k->hi[i] - k->lo[i]) + 1u;
    if ((r & 7u) == 0) /* out of domain, clamped by the kernel */
        return (r & 8u) ? k->hi[i] + (int32_t)(lcg() >> 8) : k->lo[i] - (int32_t)(lcg() >> 8);
    return k->lo[i] + (int32_t)((lcg() >> 8) % span);
}

static uint64_t kernel_hash(const facet_fx_kernel *k)
{
    int32_t in[FACET_FX_MAX_INPUTS];
    int i, j, t, bytes = k->out_bits / 8;
    h_ = 0xCBF29CE484222325ull;
    lcg_ = 12345u;
    if (k->n_inputs == 1) {
        for (j = -40000; j <= 40000; j++) {
            in[0] = j;
            feed(k->fx(in), bytes);
        }
    } else if (k->n_inputs == 2) {
        for (i = -1; i <= 129; i++)
            for (j = -1; j <= 129; j++) {
                in[0] = k->lo[0] + (int32_t)(((int64_t)(k->hi[0] - k->lo[0]) * i) / 128);
                in[1] = k->lo[1] + (int32_t)(((int64_t)(k->hi[1] - k->lo[1]) * j) / 128);
                feed(k->fx(in), bytes);
            }
    }
    for (t = 0; t < 3000; t++) {
        for (i = 0; i < k->n_inputs; i++)
            in[i] = rand_in(k, i);
        feed(k->fx(in), bytes);
    }
    return h_;
}

static const struct { const char *name; uint64_t hash; } pinned[] = {
    { "noh_from_dots", 0xa146c73a868ee5adull },
    { "loh_from_dots", 0xd5ab15bf73c12591ull },
    { "fresnel_schlick", 0x8d3297d639d8cc3eull },
    { "ggx_d", 0x795c9e15a3e89032ull },
    { "smith_g1", 0xf569b41f61b818aeull },
    { "smith_g2", 0x17ee3f96fa07a290ull },
    { "smith_g2_uncorrelated", 0x426e611473d534a8ull },
    { "smith_vis", 0xb30498f39c6c0132ull },
    { "smith_g1_hammon", 0xdd33c33dac5fc05cull },
    { "smith_g2_hammon", 0x43d3163a9e875ecfull },
    { "smith_vis_hammon", 0x0fb5ec8fe077f4c9ull },
    { "diffuse_hammon", 0xf6c3466f7a26795cull },
    { "brdf_hammon", 0x92c13617ba9ce468ull },
};

int main(void)
{
    size_t i;
    th_name = "fx_hash";
    CHECK(facet_fx_kernel_count() == sizeof pinned / sizeof pinned[0], "kernel count %u",
          (unsigned)facet_fx_kernel_count());
    for (i = 0; i < sizeof pinned / sizeof pinned[0]; i++) {
        const facet_fx_kernel *k = facet_fx_kernel_find(pinned[i].name);
        uint64_t h;
        if (!k) {
            CHECK(0, "%s: not in the fx table", pinned[i].name);
            continue;
        }
        h = kernel_hash(k);
        printf("    { \"%s\", 0x%08lx%08lxull },\n", k->name, (unsigned long)(h >> 32),
               (unsigned long)(h & 0xFFFFFFFFu));
        CHECK(h == pinned[i].hash, "%s: hash %08lx%08lx, pinned %08lx%08lx", k->name,
              (unsigned long)(h >> 32), (unsigned long)(h & 0xFFFFFFFFu),
              (unsigned long)(pinned[i].hash >> 32), (unsigned long)(pinned[i].hash & 0xFFFFFFFFu));
    }
    return th_done();
}
