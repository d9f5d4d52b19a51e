/* fx_hash.h - the pinned-hash input grids and hash values, shared by
 * tests/fx/test_fx_hash.c (scalar kernels, every target) and
 * tests/fx/test_fx_ports.c (the batch API on every port).
 * Inputs: for one-input kernels every raw value in [-40000, 40000]; for
 * two-input kernels a 129 x 129 grid over the domain plus the clamping
 * edges; for all, 3000 pseudo-random raw tuples (an LCG, 1 in 8 inputs out
 * of domain).  Hash: FNV-1a 64 over the outputs as little-endian bytes. */
#ifndef FACET_TEST_FX_HASH_H
#define FACET_TEST_FX_HASH_H

#include <stdint.h>
#include "facet/fx.h"

static void fxh_feed(uint64_t *h, uint64_t v, int bytes)
{
    int i;
    for (i = 0; i < bytes; i++) {
        *h ^= (v >> (8 * i)) & 0xFFu;
        *h *= 0x100000001B3ull;
    }
}
#define FXH_INIT 0xCBF29CE484222325ull

static uint32_t fxh_lcg_; /* Numerical Recipes LCG, top bits used */
static uint32_t fxh_lcg(void) { fxh_lcg_ = fxh_lcg_ * 1664525u + 1013904223u; return fxh_lcg_; }

static int32_t fxh_rand_in(const facet_fx_kernel *k, int i)
{
    uint32_t r = fxh_lcg();
    uint32_t span = (uint32_t)(k->hi[i] - k->lo[i]) + 1u;
    if ((r & 7u) == 0) /* out of domain, clamped by the kernel */
        return (r & 8u) ? k->hi[i] + (int32_t)(fxh_lcg() >> 8) : k->lo[i] - (int32_t)(fxh_lcg() >> 8);
    return k->lo[i] + (int32_t)((fxh_lcg() >> 8) % span);
}

/* calls visit(in, ctx) for every input tuple of k's hash, in hash order */
static void fxh_walk(const facet_fx_kernel *k, void (*visit)(const int32_t *, void *), void *ctx)
{
    int32_t in[FACET_FX_MAX_INPUTS];
    int i, j, t;
    fxh_lcg_ = 12345u;
    if (k->n_inputs == 1) {
        for (j = -40000; j <= 40000; j++) {
            in[0] = j;
            visit(in, ctx);
        }
    } else if (k->n_inputs == 2) {
        for (i = -1; i <= 129; i++)
            for (j = -1; j <= 129; j++) {
                in[0] = k->lo[0] + (int32_t)(((int64_t)(k->hi[0] - k->lo[0]) * i) / 128);
                in[1] = k->lo[1] + (int32_t)(((int64_t)(k->hi[1] - k->lo[1]) * j) / 128);
                visit(in, ctx);
            }
    }
    for (t = 0; t < 3000; t++) {
        for (i = 0; i < k->n_inputs; i++)
            in[i] = fxh_rand_in(k, i);
        visit(in, ctx);
    }
}

static const struct { const char *name; uint64_t hash; } fxh_pinned[] = {
    { "noh_from_dots", 0xa146c73a868ee5adull },
    { "loh_from_dots", 0xd5ab15bf73c12591ull },
    { "fresnel_schlick", 0x8d3297d639d8cc3eull },
    { "ggx_d", 0x795c9e15a3e89032ull },
    { "ggx_aniso_d", 0x4175a245efae94f6ull },
    { "smith_g1", 0xf569b41f61b818aeull },
    { "smith_g2", 0x17ee3f96fa07a290ull },
    { "smith_g2_uncorrelated", 0x426e611473d534a8ull },
    { "smith_vis", 0xb30498f39c6c0132ull },
    { "smith_g1_hammon", 0xdd33c33dac5fc05cull },
    { "smith_g2_hammon", 0x43d3163a9e875ecfull },
    { "smith_vis_hammon", 0x0fb5ec8fe077f4c9ull },
    { "g_implicit", 0xc49c6a1111731783ull },
    { "g_neumann", 0x41092bc865b19c64ull },
    { "g_cook_torrance", 0x1cf032c9e23bb6f6ull },
    { "g_kelemen", 0x5ccbeaa3d713d8a6ull },
    { "smith_g1_beckmann", 0x75a457326d8825e8ull },
    { "smith_g1_schlick_beckmann", 0x05d6ed8234d9e264ull },
    { "smith_vis_joint_approx", 0x0fb5ec8fe077f4c9ull },
    { "smith_vis_fit", 0x2a5c324c3d352a99ull },
    { "diffuse_hammon", 0xf6c3466f7a26795cull },
    { "brdf_hammon", 0x92c13617ba9ce468ull },
};
#define FXH_N_PINNED (sizeof fxh_pinned / sizeof fxh_pinned[0])

#ifdef FXH_FAST
/* the fx_fast tier (facet_<kernel>_fx_fast), same grids */
static const struct { const char *name; uint64_t hash; } fxh_pinned_fast[] = {
    { "noh_from_dots", 0xc1d1d71ca71a5fe3ull },
    { "loh_from_dots", 0x5af0098ffbb4d64aull },
    { "fresnel_schlick", 0x8d3297d639d8cc3eull },
    { "ggx_d", 0x20b277145c20eb43ull },
    { "blinn_phong_d", 0xb29166f1c3ccac85ull },
    { "beckmann_d", 0xa202c036d64a4faaull },
    { "ggx_aniso_d", 0x2f1382a7d7a98b0cull },
    { "gtr_d", 0x188655fdf2466217ull },
    { "smith_g1", 0x508b5cc464984afbull },
    { "smith_g2", 0x94a7352fe846b3feull },
    { "smith_g2_uncorrelated", 0x62a4efad6be3bb4eull },
    { "smith_vis", 0x92aac1660a9557b6ull },
    { "smith_g1_hammon", 0xdd33c33dac5fc05cull },
    { "smith_g1_gtr", 0x93f77130947a1adeull },
    { "smith_g2_hammon", 0x43d3163a9e875ecfull },
    { "smith_vis_hammon", 0xe94f2258d41b5949ull },
    { "g_implicit", 0xc49c6a1111731783ull },
    { "g_neumann", 0x41092bc865b19c64ull },
    { "g_cook_torrance", 0xf4c37468c207243cull },
    { "g_kelemen", 0xef2f4ff7e2cb0eedull },
    { "smith_g1_beckmann", 0x67a529b3066449ffull },
    { "smith_g1_schlick_beckmann", 0x05d6ed8234d9e264ull },
    { "smith_vis_joint_approx", 0xe94f2258d41b5949ull },
    { "smith_vis_fit", 0xa736c6b884a9d72cull },
    { "diffuse_hammon", 0x08cbfb8476579d9cull },
    { "brdf_hammon", 0xb03e03d0f7286755ull },
    /* the fast tier only (no precise kernel, so not in fxh_pinned) */
    { "fresnel_cook_torrance", 0xfab7c63e85bcc30dull },
    { "fresnel_schlick_f90", 0x0dae320f77d0d831ull },
    { "fresnel_schlick_sg", 0xd1f161746c0c0a69ull },
    { "diffuse_burley", 0xe8019d74b0a0a641ull },
    { "diffuse_oren_nayar", 0x5dcb551eac3871f8ull },
    { "diffuse_hammon_hybrid", 0x145fb7dbfd878ab7ull },
    { "diffuse_hammon_cheap", 0xcc3967ded50b38a2ull },
};
#define FXH_N_PINNED_FAST (sizeof fxh_pinned_fast / sizeof fxh_pinned_fast[0])
#endif

#endif
