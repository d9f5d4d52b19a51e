/* fx_fast.c - the fx_fast tier's scalar kernels (facet/fx.h "fast tier"):
 * the bodies of src/fx_fast_body.h on one lane (src/fx_ops_scalar.h), the
 * specification every port of the tier reproduces bit for bit. */
#include "facet/fx.h"
#include "fx_ops_scalar.h"
#include "fx_body.h" /* fxb_rshr64 */
#include "fx_fast_body.h"

int32_t facet_noh_from_dots_fx_fast(int32_t nol, int32_t nov, int32_t lov)
{
    return (int32_t)fxf_fast_noh_from_dots(nol, nov, lov);
}
int32_t facet_loh_from_dots_fx_fast(int32_t lov) { return (int32_t)fxf_fast_loh_from_dots(lov); }
int32_t facet_fresnel_schlick_fx_fast(int32_t f0, int32_t cos_theta)
{
    return (int32_t)fxf_fast_fresnel_schlick(f0, cos_theta);
}
uint32_t facet_ggx_d_fx_fast(int32_t noh, int32_t alpha) { return fxf_fast_ggx_d(noh, alpha); }
int32_t facet_smith_g1_fx_fast(int32_t nov, int32_t alpha) { return (int32_t)fxf_fast_smith_g1(nov, alpha); }
int32_t facet_smith_g2_fx_fast(int32_t nol, int32_t nov, int32_t alpha)
{
    return (int32_t)fxf_fast_smith_g2(nol, nov, alpha);
}
int32_t facet_smith_g2_uncorrelated_fx_fast(int32_t nol, int32_t nov, int32_t alpha)
{
    return (int32_t)fxf_fast_smith_g2_uncorrelated(nol, nov, alpha);
}
uint32_t facet_smith_vis_fx_fast(int32_t nol, int32_t nov, int32_t alpha)
{
    return fxf_fast_smith_vis(nol, nov, alpha);
}
int32_t facet_smith_g1_hammon_fx_fast(int32_t nov, int32_t alpha)
{
    return (int32_t)fxf_fast_smith_g1_hammon(nov, alpha);
}
int32_t facet_smith_g2_hammon_fx_fast(int32_t nol, int32_t nov, int32_t alpha)
{
    return (int32_t)fxf_fast_smith_g2_hammon(nol, nov, alpha);
}
uint32_t facet_smith_vis_hammon_fx_fast(int32_t nol, int32_t nov, int32_t alpha)
{
    return fxf_fast_smith_vis_hammon(nol, nov, alpha);
}
uint32_t facet_diffuse_hammon_fx_fast(int32_t nol, int32_t nov, int32_t lov, int32_t alpha,
                                      int32_t albedo)
{
    return fxf_fast_diffuse_hammon(nol, nov, lov, alpha, albedo);
}
uint64_t facet_brdf_hammon_fx_fast(int32_t nol, int32_t nov, int32_t lov, int32_t alpha,
                                   int32_t f0, int32_t albedo)
{
    return fxf_fast_brdf_hammon(nol, nov, lov, alpha, f0, albedo);
}
