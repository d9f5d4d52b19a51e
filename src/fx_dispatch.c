/* fx_dispatch.c - the public facet_<kernel>_fx_batch entry points: each call
 * goes to the fx implementation of the active f32 port (src/dispatch.c:
 * chosen once for the CPU, or forced by facet_set_port() / FACET_PORT),
 * matched by name (avx512 -> the AVX2 fx kernels); a port without an fx
 * implementation (sse2) runs the scalar fx loops.  Every fx port is bit-identical to the scalar kernels,
 * so the choice changes speed only, never a result.
 * No state of its own: the match is redone per call (a pointer load, a few
 * short strcmp), so it follows facet_set_port() at
 * once and is safe from any thread. */
#include <string.h>
#include "facet.h"
#include "facet/fx.h"
#include "port.h"
#include "fx_port.h"

static int always(void) { return 1; }

#if defined(__x86_64__) || defined(__i386__)
/* CPUID once (it traps in some VMs); racing threads store the same value */
static int avx2_ok(void)
{
    static int known = -1;
    int v = __atomic_load_n(&known, __ATOMIC_RELAXED);
    if (v < 0) {
        v = facet_cpu_avx2_fma();
        __atomic_store_n(&known, v, __ATOMIC_RELAXED);
    }
    return v;
}
#endif

/* f32 port name -> its fx implementation (and what the CPU must have for
 * it: the f32 port's own check was done by dispatch.c).  avx512 CPUs run
 * the AVX2 fx kernels (AVX-512F implies AVX2 on every shipped CPU; checked
 * anyway). */
static const struct {
    const char *f32;
    const facet_fx_port *fx;
    int (*supported)(void);
} fx_ports[] = {
#if defined(__x86_64__) || defined(__i386__)
    { "avx512", &facet_fx_port_avx2, avx2_ok },
    { "avx2", &facet_fx_port_avx2, always },
#endif
#if defined(__aarch64__) || (defined(__arm__) && defined(__linux__))
    { "neon", &facet_fx_port_neon, always },
#endif
    { "scalar", &facet_fx_port_scalar, always },
};

static const facet_fx_port *fx_port(void)
{
    const char *name = facet_port_name(); /* supported by the CPU: dispatch.c checked */
    size_t i;
    for (i = 0; i < sizeof fx_ports / sizeof fx_ports[0]; i++)
        if (!strcmp(name, fx_ports[i].f32))
            return fx_ports[i].supported() ? fx_ports[i].fx : &facet_fx_port_scalar;
    return &facet_fx_port_scalar;
}

const char *facet_fx_port_name(void) { return fx_port()->name; }

static int all_vector; /* facet_fx_dispatch_all_vector */

void facet_fx_dispatch_all_vector(int on) { __atomic_store_n(&all_vector, on, __ATOMIC_RELAXED); }

/* the port's code for kernel k where it was measured faster, else scalar */
#define PICK(k, K)                                                                  \
    ((fx_port()->faster & FX_BIT(K)) || __atomic_load_n(&all_vector, __ATOMIC_RELAXED) \
         ? fx_port()->k : facet_fx_port_scalar.k)

#define I const int32_t *
void facet_noh_from_dots_fx_batch(int32_t *out, I nol, I nov, I lov, size_t n)
{
    PICK(noh_from_dots, FX_NOH_FROM_DOTS)(out, nol, nov, lov, n);
}
void facet_loh_from_dots_fx_batch(int32_t *out, I lov, size_t n)
{
    PICK(loh_from_dots, FX_LOH_FROM_DOTS)(out, lov, n);
}
void facet_fresnel_schlick_fx_batch(int32_t *out, I f0, I cos_theta, size_t n)
{
    PICK(fresnel_schlick, FX_FRESNEL_SCHLICK)(out, f0, cos_theta, n);
}
void facet_ggx_d_fx_batch(uint32_t *out, I noh, I alpha, size_t n)
{
    PICK(ggx_d, FX_GGX_D)(out, noh, alpha, n);
}
void facet_smith_g1_fx_batch(int32_t *out, I nov, I alpha, size_t n)
{
    PICK(smith_g1, FX_SMITH_G1)(out, nov, alpha, n);
}
void facet_smith_g2_fx_batch(int32_t *out, I nol, I nov, I alpha, size_t n)
{
    PICK(smith_g2, FX_SMITH_G2)(out, nol, nov, alpha, n);
}
void facet_smith_g2_uncorrelated_fx_batch(int32_t *out, I nol, I nov, I alpha, size_t n)
{
    PICK(smith_g2_uncorrelated, FX_SMITH_G2_UNCORRELATED)(out, nol, nov, alpha, n);
}
void facet_smith_vis_fx_batch(uint32_t *out, I nol, I nov, I alpha, size_t n)
{
    PICK(smith_vis, FX_SMITH_VIS)(out, nol, nov, alpha, n);
}
void facet_smith_g1_hammon_fx_batch(int32_t *out, I nov, I alpha, size_t n)
{
    PICK(smith_g1_hammon, FX_SMITH_G1_HAMMON)(out, nov, alpha, n);
}
void facet_smith_g2_hammon_fx_batch(int32_t *out, I nol, I nov, I alpha, size_t n)
{
    PICK(smith_g2_hammon, FX_SMITH_G2_HAMMON)(out, nol, nov, alpha, n);
}
void facet_smith_vis_hammon_fx_batch(uint32_t *out, I nol, I nov, I alpha, size_t n)
{
    PICK(smith_vis_hammon, FX_SMITH_VIS_HAMMON)(out, nol, nov, alpha, n);
}
void facet_diffuse_hammon_fx_batch(uint32_t *out, I nol, I nov, I lov, I alpha, I albedo, size_t n)
{
    PICK(diffuse_hammon, FX_DIFFUSE_HAMMON)(out, nol, nov, lov, alpha, albedo, n);
}
void facet_brdf_hammon_fx_batch(uint64_t *out, I nol, I nov, I lov, I alpha, I f0, I albedo,
                                size_t n)
{
    PICK(brdf_hammon, FX_BRDF_HAMMON)(out, nol, nov, lov, alpha, f0, albedo, n);
}
