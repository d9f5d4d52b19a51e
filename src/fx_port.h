/* fx_port.h - what a fixed-point port gives src/fx_dispatch.c: one batch
 * function per fx kernel.  Private to the library.  Every port's functions
 * are bit-identical to the scalar kernels of src/fx_kernels.c (the
 * specification), tested by tests/test_fx_ports.c. */
#ifndef FACET_FX_PORT_H
#define FACET_FX_PORT_H

#include <stddef.h>
#include <stdint.h>

/* kernel indices, in table order, for facet_fx_port.faster */
enum {
    FX_NOH_FROM_DOTS, FX_LOH_FROM_DOTS, FX_FRESNEL_SCHLICK, FX_GGX_D, FX_SMITH_G1, FX_SMITH_G2,
    FX_SMITH_G2_UNCORRELATED, FX_SMITH_VIS, FX_SMITH_G1_HAMMON, FX_SMITH_G2_HAMMON,
    FX_SMITH_VIS_HAMMON, FX_DIFFUSE_HAMMON, FX_BRDF_HAMMON
};
#define FX_BIT(k) (1u << (k))
#define FX_ALL 0x1fffu

typedef struct facet_fx_port {
    const char *name; /* the f32 port it goes with ("avx2", "neon", "scalar") */
    int lanes;        /* samples per vector step */
    /* FX_BIT(kernel) set: the dispatcher runs this port's code for that
     * kernel; clear: the scalar loop, measured faster on this port's CPUs
     * (the port file says where the measurement is).  Every function here is
     * bit-exact and tested, whether dispatched to or not. */
    unsigned faster;
    void (*noh_from_dots)(int32_t *, const int32_t *, const int32_t *, const int32_t *, size_t);
    void (*loh_from_dots)(int32_t *, const int32_t *, size_t);
    void (*fresnel_schlick)(int32_t *, const int32_t *, const int32_t *, size_t);
    void (*ggx_d)(uint32_t *, const int32_t *, const int32_t *, size_t);
    void (*smith_g1)(int32_t *, const int32_t *, const int32_t *, size_t);
    void (*smith_g2)(int32_t *, const int32_t *, const int32_t *, const int32_t *, size_t);
    void (*smith_g2_uncorrelated)(int32_t *, const int32_t *, const int32_t *, const int32_t *,
                                  size_t);
    void (*smith_vis)(uint32_t *, const int32_t *, const int32_t *, const int32_t *, size_t);
    void (*smith_g1_hammon)(int32_t *, const int32_t *, const int32_t *, size_t);
    void (*smith_g2_hammon)(int32_t *, const int32_t *, const int32_t *, const int32_t *, size_t);
    void (*smith_vis_hammon)(uint32_t *, const int32_t *, const int32_t *, const int32_t *,
                             size_t);
    void (*diffuse_hammon)(uint32_t *, const int32_t *, const int32_t *, const int32_t *,
                           const int32_t *, const int32_t *, size_t);
    void (*brdf_hammon)(uint64_t *, const int32_t *, const int32_t *, const int32_t *,
                        const int32_t *, const int32_t *, const int32_t *, size_t);
} facet_fx_port;

/* Tests and benchmarks only: nonzero makes the dispatcher run a port's own
 * code for every kernel, measured faster or not (fx_dispatch.c). */
void facet_fx_dispatch_all_vector(int on);

/* the portable scalar loops (src/fx_kernels.c): always present */
extern const facet_fx_port facet_fx_port_scalar;
#if defined(__x86_64__) || defined(__i386__)
extern const facet_fx_port facet_fx_port_avx2; /* ports/avx2/fx_avx2.c */
#endif
#if defined(__aarch64__) || (defined(__arm__) && defined(__linux__))
extern const facet_fx_port facet_fx_port_neon; /* ports/neon/fx_neon.c */
#endif

#endif
