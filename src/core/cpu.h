/* cpu.h - what this CPU (and its OS) can run: the one place CPU features are
 * read (src/core/cpu.c).  Private to the library; everyone else asks through
 * facet_port_supported() (facet.h).  Each function exists only on its
 * architecture. */
#ifndef FACET_CPU_H
#define FACET_CPU_H

#if defined(__x86_64__) || defined(__i386__)
int facet_cpu_sse2(void);
int facet_cpu_avx2_fma(void); /* AVX2 + FMA, and the OS saves YMM state */
#if defined(__x86_64__)
int facet_cpu_avx512f(void);  /* AVX-512F, and the OS saves ZMM and opmask state */
#endif
#elif defined(__aarch64__) || (defined(__arm__) && defined(__linux__))
int facet_cpu_neon(void);     /* aarch64: always; armv7: NEON and VFPv4 in HWCAP */
#elif defined(__ARM_FEATURE_MVE) && (__ARM_FEATURE_MVE & 2)
int facet_cpu_helium(void);   /* MVE integer and floating point in MVFR1 */
#elif defined(__riscv) && __riscv_xlen == 64 && defined(__linux__)
int facet_cpu_rvv(void);      /* the V extension in AT_HWCAP */
#endif

#endif
