/* f32_scalar.c - the library's f32 entry points: the scalar port, out of line. */
#include "facet.h"
#include "facet/scalar.h"

float facet_noh_from_dots_f32(float nol, float nov, float lov)
{ return facet_noh_from_dots_f32_scalar(nol, nov, lov); }
float facet_loh_from_dots_f32(float lov)
{ return facet_loh_from_dots_f32_scalar(lov); }
float facet_fresnel_schlick_f32(float f0, float cos_theta)
{ return facet_fresnel_schlick_f32_scalar(f0, cos_theta); }
float facet_ggx_d_f32(float noh, float alpha)
{ return facet_ggx_d_f32_scalar(noh, alpha); }
float facet_smith_g1_f32(float nov, float alpha)
{ return facet_smith_g1_f32_scalar(nov, alpha); }
float facet_smith_g2_f32(float nol, float nov, float alpha)
{ return facet_smith_g2_f32_scalar(nol, nov, alpha); }
float facet_smith_g2_uncorrelated_f32(float nol, float nov, float alpha)
{ return facet_smith_g2_uncorrelated_f32_scalar(nol, nov, alpha); }
float facet_smith_vis_f32(float nol, float nov, float alpha)
{ return facet_smith_vis_f32_scalar(nol, nov, alpha); }
float facet_smith_g1_hammon_f32(float nov, float alpha)
{ return facet_smith_g1_hammon_f32_scalar(nov, alpha); }
float facet_smith_g2_hammon_f32(float nol, float nov, float alpha)
{ return facet_smith_g2_hammon_f32_scalar(nol, nov, alpha); }
float facet_smith_vis_hammon_f32(float nol, float nov, float alpha)
{ return facet_smith_vis_hammon_f32_scalar(nol, nov, alpha); }
float facet_diffuse_hammon_f32(float nol, float nov, float lov, float alpha, float albedo)
{ return facet_diffuse_hammon_f32_scalar(nol, nov, lov, alpha, albedo); }
float facet_brdf_hammon_f32(float nol, float nov, float lov, float alpha, float f0,
                            float albedo)
{ return facet_brdf_hammon_f32_scalar(nol, nov, lov, alpha, f0, albedo); }
float facet_lambert_f32(float albedo)
{ return facet_lambert_f32_scalar(albedo); }

void facet_brdf_hammon_rgb_f32(float out[3], float nol, float nov, float lov,
                               float alpha, const float f0[3], const float albedo[3])
{
    facet_brdf_hammon_rgb_f32_scalar(out, nol, nov, lov, alpha, f0, albedo);
}
