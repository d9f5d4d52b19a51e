/* fx_table.c - the fixed-point kernel table behind facet_fx_kernel_at/find:
 * the same kernels, order and input names as the f32 table (kernels.def),
 * with each input's raw Q15 domain and the output format. */
#include <string.h>
#include "facet/fx.h"

#define U_ 0, FACET_FX_ONE                 /* [0, 1] */
#define C_ FACET_FX_COS_MIN, FACET_FX_ONE  /* two-cosine kernels' N.L, N.V */
#define A_ FACET_FX_ALPHA_MIN, FACET_FX_ONE
#define L_ -FACET_FX_ONE, FACET_FX_ONE

static uint64_t w_noh_from_dots(const int32_t *in) { return (uint32_t)facet_noh_from_dots_fx(in[0], in[1], in[2]); }
static uint64_t w_loh_from_dots(const int32_t *in) { return (uint32_t)facet_loh_from_dots_fx(in[0]); }
static uint64_t w_fresnel_schlick(const int32_t *in) { return (uint32_t)facet_fresnel_schlick_fx(in[0], in[1]); }
static uint64_t w_ggx_d(const int32_t *in) { return facet_ggx_d_fx(in[0], in[1]); }
static uint64_t w_smith_g1(const int32_t *in) { return (uint32_t)facet_smith_g1_fx(in[0], in[1]); }
static uint64_t w_smith_g2(const int32_t *in) { return (uint32_t)facet_smith_g2_fx(in[0], in[1], in[2]); }
static uint64_t w_smith_g2_uncorrelated(const int32_t *in) { return (uint32_t)facet_smith_g2_uncorrelated_fx(in[0], in[1], in[2]); }
static uint64_t w_smith_vis(const int32_t *in) { return facet_smith_vis_fx(in[0], in[1], in[2]); }
static uint64_t w_smith_g1_hammon(const int32_t *in) { return (uint32_t)facet_smith_g1_hammon_fx(in[0], in[1]); }
static uint64_t w_smith_g2_hammon(const int32_t *in) { return (uint32_t)facet_smith_g2_hammon_fx(in[0], in[1], in[2]); }
static uint64_t w_smith_vis_hammon(const int32_t *in) { return facet_smith_vis_hammon_fx(in[0], in[1], in[2]); }
static uint64_t w_diffuse_hammon(const int32_t *in) { return facet_diffuse_hammon_fx(in[0], in[1], in[2], in[3], in[4]); }
static uint64_t w_brdf_hammon(const int32_t *in) { return facet_brdf_hammon_fx(in[0], in[1], in[2], in[3], in[4], in[5]); }

/* name, inputs, domains (lo/hi interleaved per input), frac, bits, format */
static const facet_fx_kernel table[] = {
    { "noh_from_dots", 3, { "nol", "nov", "lov" }, { FACET_FX_COS_MIN, FACET_FX_COS_MIN, -FACET_FX_ONE },
      { FACET_FX_ONE, FACET_FX_ONE, FACET_FX_ONE }, 15, 32, "Q15", w_noh_from_dots, FACET_FX_ERR_NOH_FROM_DOTS },
    { "loh_from_dots", 1, { "lov" }, { -FACET_FX_ONE }, { FACET_FX_ONE }, 15, 32, "Q15",
      w_loh_from_dots, FACET_FX_ERR_LOH_FROM_DOTS },
    { "fresnel_schlick", 2, { "f0", "cos" }, { 0, 0 }, { FACET_FX_ONE, FACET_FX_ONE }, 15, 32, "Q15",
      w_fresnel_schlick, FACET_FX_ERR_FRESNEL_SCHLICK },
    { "ggx_d", 2, { "noh", "alpha" }, { 0, FACET_FX_ALPHA_MIN }, { FACET_FX_ONE, FACET_FX_ONE }, 13, 32,
      "UQ19.13", w_ggx_d, FACET_FX_ERR_GGX_D },
    { "smith_g1", 2, { "nov", "alpha" }, { 0, FACET_FX_ALPHA_MIN }, { FACET_FX_ONE, FACET_FX_ONE }, 15, 32,
      "Q15", w_smith_g1, FACET_FX_ERR_SMITH_G1 },
    { "smith_g2", 3, { "nol", "nov", "alpha" }, { FACET_FX_COS_MIN, FACET_FX_COS_MIN, FACET_FX_ALPHA_MIN },
      { FACET_FX_ONE, FACET_FX_ONE, FACET_FX_ONE }, 15, 32, "Q15", w_smith_g2, FACET_FX_ERR_SMITH_G2 },
    { "smith_g2_uncorrelated", 3, { "nol", "nov", "alpha" },
      { FACET_FX_COS_MIN, FACET_FX_COS_MIN, FACET_FX_ALPHA_MIN }, { FACET_FX_ONE, FACET_FX_ONE, FACET_FX_ONE },
      15, 32, "Q15", w_smith_g2_uncorrelated, FACET_FX_ERR_SMITH_G2_UNCORRELATED },
    { "smith_vis", 3, { "nol", "nov", "alpha" }, { FACET_FX_COS_MIN, FACET_FX_COS_MIN, FACET_FX_ALPHA_MIN },
      { FACET_FX_ONE, FACET_FX_ONE, FACET_FX_ONE }, 16, 32, "UQ16.16", w_smith_vis, FACET_FX_ERR_SMITH_VIS },
    { "smith_g1_hammon", 2, { "nov", "alpha" }, { 0, FACET_FX_ALPHA_MIN }, { FACET_FX_ONE, FACET_FX_ONE },
      15, 32, "Q15", w_smith_g1_hammon, FACET_FX_ERR_SMITH_G1_HAMMON },
    { "smith_g2_hammon", 3, { "nol", "nov", "alpha" }, { FACET_FX_COS_MIN, FACET_FX_COS_MIN, FACET_FX_ALPHA_MIN },
      { FACET_FX_ONE, FACET_FX_ONE, FACET_FX_ONE }, 15, 32, "Q15", w_smith_g2_hammon, FACET_FX_ERR_SMITH_G2_HAMMON },
    { "smith_vis_hammon", 3, { "nol", "nov", "alpha" }, { FACET_FX_COS_MIN, FACET_FX_COS_MIN, FACET_FX_ALPHA_MIN },
      { FACET_FX_ONE, FACET_FX_ONE, FACET_FX_ONE }, 16, 32, "UQ16.16", w_smith_vis_hammon,
      FACET_FX_ERR_SMITH_VIS_HAMMON },
    { "diffuse_hammon", 5, { "nol", "nov", "lov", "alpha", "albedo" },
      { FACET_FX_COS_MIN, FACET_FX_COS_MIN, -FACET_FX_ONE, FACET_FX_ALPHA_MIN, 0 },
      { FACET_FX_ONE, FACET_FX_ONE, FACET_FX_ONE, FACET_FX_ONE, FACET_FX_ONE }, 24, 32, "UQ8.24",
      w_diffuse_hammon, FACET_FX_ERR_DIFFUSE_HAMMON },
    { "brdf_hammon", 6, { "nol", "nov", "lov", "alpha", "f0", "albedo" },
      { FACET_FX_COS_MIN, FACET_FX_COS_MIN, -FACET_FX_ONE, FACET_FX_ALPHA_MIN, 0, 0 },
      { FACET_FX_ONE, FACET_FX_ONE, FACET_FX_ONE, FACET_FX_ONE, FACET_FX_ONE, FACET_FX_ONE }, 24, 64, "UQ40.24",
      w_brdf_hammon, FACET_FX_ERR_BRDF_HAMMON },
};

size_t facet_fx_kernel_count(void) { return sizeof table / sizeof table[0]; }

const facet_fx_kernel *facet_fx_kernel_at(size_t i)
{
    return i < facet_fx_kernel_count() ? &table[i] : NULL;
}

const facet_fx_kernel *facet_fx_kernel_find(const char *name)
{
    size_t i;
    for (i = 0; name && i < facet_fx_kernel_count(); i++)
        if (strcmp(table[i].name, name) == 0)
            return &table[i];
    return NULL;
}
