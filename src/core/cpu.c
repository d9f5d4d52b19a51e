/* cpu.c - the one place CPU features are read: CPUID and XCR0 on x86 (the
 * CPU has the instructions and the OS saves their registers), HWCAP on
 * armv7; aarch64 always has NEON; MVFR1 on Armv8.1-M (Helium); HWCAP on
 * riscv64 Linux (RVV).  src/core/dispatch.c asks it which ports this
 * CPU runs; the bench and the rasterizer ask through facet_port_supported(). */
#if defined(__linux__) && !defined(_GNU_SOURCE)
#define _GNU_SOURCE /* getauxval */
#endif
#include "cpu.h"

#if defined(__x86_64__) || defined(__i386__)
#define FACET_X86 1
#include <cpuid.h>
#elif defined(__aarch64__) || (defined(__arm__) && defined(__linux__))
#define FACET_ARM 1
#if !defined(__aarch64__)
#include <sys/auxv.h>
#endif
#elif defined(__ARM_FEATURE_MVE) && (__ARM_FEATURE_MVE & 2)
#define FACET_HELIUM 1
#elif defined(__riscv) && __riscv_xlen == 64 && defined(__linux__)
#define FACET_RISCV 1
#include <sys/auxv.h>
#endif

#if FACET_X86
int facet_cpu_avx2_fma(void)
{
    unsigned a, b, c, d, xlo, xhi;
    if (!__get_cpuid(1, &a, &b, &c, &d))
        return 0;
    if (!(c & (1u << 12)) || !(c & (1u << 27)) || !(c & (1u << 28))) /* FMA, OSXSAVE, AVX */
        return 0;
    __asm__ volatile("xgetbv" : "=a"(xlo), "=d"(xhi) : "c"(0));
    if ((xlo & 6u) != 6u) /* XMM and YMM state enabled by the OS */
        return 0;
    if (!__get_cpuid_count(7, 0, &a, &b, &c, &d))
        return 0;
    return (b >> 5) & 1u; /* AVX2 */
}
#if defined(__x86_64__)
int facet_cpu_avx512f(void)
{
    unsigned a, b, c, d, xlo, xhi;
    if (!__get_cpuid(1, &a, &b, &c, &d) || !(c & (1u << 27))) /* OSXSAVE */
        return 0;
    __asm__ volatile("xgetbv" : "=a"(xlo), "=d"(xhi) : "c"(0));
    if ((xlo & 0xe6u) != 0xe6u) /* XMM, YMM, opmask, ZMM0-15 upper, ZMM16-31 */
        return 0;
    if (!__get_cpuid_count(7, 0, &a, &b, &c, &d))
        return 0;
    return (b >> 16) & 1u; /* AVX512F */
}
#endif
int facet_cpu_sse2(void)
{
#if defined(__x86_64__)
    return 1;
#else
    unsigned a, b, c, d;
    return __get_cpuid(1, &a, &b, &c, &d) && ((d >> 26) & 1u);
#endif
}
#endif

#if FACET_ARM
int facet_cpu_neon(void)
{
#if defined(__aarch64__)
    return 1;
#else
    unsigned long hw = getauxval(AT_HWCAP);
    return (hw & (1ul << 12)) && (hw & (1ul << 16)); /* HWCAP_NEON, HWCAP_VFPv4 */
#endif
}
#endif

#if FACET_HELIUM
/* M-profile firmware runs privileged with no OS in between: MVFR1
 * (0xE000EF44, the System Control Space) field MVE, bits 11:8, is 2 where
 * the core has MVE integer and floating point (1: integer only, 0: none) */
int facet_cpu_helium(void)
{
    unsigned long mvfr1 = *(volatile const unsigned long *)0xE000EF44ul;
    return ((mvfr1 >> 8) & 0xFu) == 2u;
}
#endif

#if FACET_RISCV
/* Linux sets AT_HWCAP bit ('V' - 'A') where the harts have the V extension
 * and the kernel saves its state (qemu-user 7.2 sets it for -cpu
 * rv64,v=true and clears it without); the port is RVV 1.0, the only
 * version Linux enables */
int facet_cpu_rvv(void)
{
    return (getauxval(AT_HWCAP) >> ('V' - 'A')) & 1ul;
}
#endif

typedef int facet_cpu_iso_c_needs_a_declaration_;
