/* port.h - what a port gives the dispatcher: a batch function per kernel.
 * Private to the library. */
#ifndef FACET_PORT_H
#define FACET_PORT_H

#include <stddef.h>

typedef void (*facet_batch1)(float *, const float *, size_t);
typedef void (*facet_batch2)(float *, const float *, const float *, size_t);
typedef void (*facet_batch3)(float *, const float *, const float *, const float *, size_t);
typedef void (*facet_batch5)(float *, const float *, const float *, const float *, const float *,
                             const float *, size_t);
typedef void (*facet_batch6)(float *, const float *, const float *, const float *, const float *,
                             const float *, const float *, size_t);

typedef struct facet_f32_port {
    const char *name;
    int lanes;
#define K(name, NAME, n, ...) facet_batch##n name;
#include "kernels.def"
#undef K
} facet_f32_port;

/* CPU features (dispatch.c); each exists only on its architecture. */
#if defined(__x86_64__) || defined(__i386__)
int facet_cpu_avx2_fma(void); /* AVX2 + FMA, and the OS saves YMM state */
#if defined(__x86_64__)
int facet_cpu_avx512f(void);  /* AVX-512F, and the OS saves ZMM and opmask state */
#endif
int facet_cpu_sse41(void);
int facet_cpu_sse2(void);
#elif defined(__aarch64__) || (defined(__arm__) && defined(__linux__))
int facet_cpu_neon(void); /* armv7: NEON and VFPv4 in HWCAP */
#endif

extern const facet_f32_port facet_port_scalar_f32;
extern const facet_f32_port facet_port_sse2_f32;
extern const facet_f32_port facet_port_avx2_f32;
extern const facet_f32_port facet_port_avx512_f32;
extern const facet_f32_port facet_port_neon_f32;

#endif
