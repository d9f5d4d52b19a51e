/* platform.h - the one platform ladder: what this build targets, each
 * FACET_ON_<platform> 1 or 0 (never undefined, so that src/core/ports.def
 * can name one as a port's guard and FACET_PORT_IF below can test it in a
 * macro).  Private to the library.  The port list (src/core/ports.def) and
 * the CPU module (src/core/cpu.c) use it; nothing else asks the compiler
 * which machine it is.  A rung here follows what ports/<isa>/port.mk
 * builds for the same target (its TARGET filter, its compiler test). */
#ifndef FACET_PLATFORM_H
#define FACET_PLATFORM_H

#if defined(__x86_64__) || defined(__i386__)
#define FACET_ON_X86 1
#if defined(__x86_64__)
#define FACET_ON_X86_64 1
#endif
#elif defined(__aarch64__) || (defined(__arm__) && defined(__linux__))
#define FACET_ON_ARM_LINUX 1 /* aarch64 (any OS) or armv7 Linux */
#if defined(__aarch64__)
#define FACET_ON_AARCH64 1
#else
#define FACET_ON_ARMV7_LINUX 1
#endif
#elif defined(__ARM_FEATURE_MVE) && (__ARM_FEATURE_MVE & 2)
#define FACET_ON_MVE_FP 1 /* Armv8.1-M with MVE floating point (Cortex-M55, M85) */
#elif defined(__riscv) && __riscv_xlen == 64 && defined(__linux__)
#define FACET_ON_RISCV64_LINUX 1
#if defined(FACET_PORT_RVV)
#define FACET_ON_RVV 1 /* and ports/rvv/port.mk's RVV_CC built the port */
#if defined(FACET_PORT_RVVFP16)
#define FACET_ON_RVVFP16 1 /* and ports/rvvfp16/port.mk its binary16 table */
#else
#define FACET_ON_RVV_NO_F16 1
#endif
#endif
#endif

#ifndef FACET_ON_X86
#define FACET_ON_X86 0
#endif
#ifndef FACET_ON_X86_64
#define FACET_ON_X86_64 0
#endif
#ifndef FACET_ON_ARM_LINUX
#define FACET_ON_ARM_LINUX 0
#endif
#ifndef FACET_ON_AARCH64
#define FACET_ON_AARCH64 0
#endif
#ifndef FACET_ON_ARMV7_LINUX
#define FACET_ON_ARMV7_LINUX 0
#endif
#ifndef FACET_ON_MVE_FP
#define FACET_ON_MVE_FP 0
#endif
#ifndef FACET_ON_RISCV64_LINUX
#define FACET_ON_RISCV64_LINUX 0
#endif
#ifndef FACET_ON_RVV
#define FACET_ON_RVV 0
#endif
#ifndef FACET_ON_RVVFP16
#define FACET_ON_RVVFP16 0
#endif
#ifndef FACET_ON_RVV_NO_F16
#define FACET_ON_RVV_NO_F16 0
#endif
/* every build */
#define FACET_ON_ANY 1

/* FACET_PORT_IF(guard, ...): the rest where guard (a FACET_ON_* above)
 * is 1, nothing where it is 0: a port list line's guard inside a macro */
#define FACET_PORT_IF(guard, ...) FACET_PORT_IF_(guard, __VA_ARGS__)
#define FACET_PORT_IF_(guard, ...) FACET_PORT_IF_##guard(__VA_ARGS__)
#define FACET_PORT_IF_1(...) __VA_ARGS__
#define FACET_PORT_IF_0(...)

#endif
