/* cpu.c - the one place CPU features are read: CPUID and XCR0 on x86 (the
 * CPU has the instructions and the OS saves their registers), HWCAP on
 * armv7; aarch64 always has NEON; MVFR1 on Armv8.1-M (Helium); HWCAP on
 * riscv64 Linux (RVV) and the riscv_hwprobe system call (Zvfh).  One test per port of src/core/ports.def (its cpu
 * column), defined under that line's guard (src/core/platform.h); the
 * dispatcher (src/core/dispatch.c) asks them, the bench and the
 * rasterizer ask through facet_port_supported().  Built without any ISA
 * flags: the tests themselves run on every CPU of the target. */
#if defined(__linux__) && !defined(_GNU_SOURCE)
#define _GNU_SOURCE /* getauxval */
#endif
#include "platform.h"
#include "cpu.h"

#if FACET_ON_X86
#include <cpuid.h>
#endif
#if FACET_ON_ARMV7_LINUX || FACET_ON_RISCV64_LINUX || (FACET_ON_AARCH64 && defined(__linux__))
#include <sys/auxv.h>
#endif
#if FACET_ON_RVVFP16
#include <errno.h>
#include <stdint.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

int facet_cpu_always(void) { return 1; }

#if FACET_ON_X86
/* Each x86 test reads CPUID once and keeps the answer (0: not yet read, 1:
 * no, 2: yes; a relaxed load of an int, racing first calls compute the
 * same value): CPUID traps to the hypervisor in a VM, and after that exit
 * the next AVX-512 batch was measured up to 2.6x slower on a Xeon VM, so
 * facet_set_port() and the f16 batches, which ask on every call, must not
 * execute it again. */
#define FACET_CPU_ONCE_(name, test)                                \
    int name(void)                                                 \
    {                                                              \
        static int known;                                          \
        int k = __atomic_load_n(&known, __ATOMIC_RELAXED);         \
        if (!k) {                                                  \
            k = test() ? 2 : 1;                                    \
            __atomic_store_n(&known, k, __ATOMIC_RELAXED);         \
        }                                                          \
        return k == 2;                                             \
    }
static int avx2_fma_(void) /* AVX2 + FMA, and the OS saves YMM state */
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
FACET_CPU_ONCE_(facet_cpu_avx2_fma, avx2_fma_)
#if FACET_ON_X86_64
/* AVX-512F, and the OS saves ZMM and opmask state */
static int avx512f(void)
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
/* the avx512 port also runs the AVX2 fx code (src/core/ports.def): both */
static int avx512_(void) { return avx512f() && avx2_fma_(); }
FACET_CPU_ONCE_(facet_cpu_avx512, avx512_)
/* the f16 table of the avx512 line (src/core/ports.def): AVX-512 FP16
 * (CPUID.(EAX=7,ECX=0):EDX[23]) with AVX-512 BW and VL (EBX[30], EBX[31]),
 * on top of AVX-512F and the OS's ZMM state */
static int avx512fp16_(void)
{
    unsigned a, b, c, d;
#ifdef FACET_TEST_CPU_WITHOUT_AVX512FP16
    /* test builds only (tests/suites/45-x86-old-cpu.sh): this CPU as an
     * AVX-512 CPU without FP16 (Zen 4 and 5), which no emulator here offers */
    return 0;
#endif
    if (!avx512f() || !__get_cpuid_count(7, 0, &a, &b, &c, &d))
        return 0;
    return ((d >> 23) & 1u) && ((b >> 30) & 1u) && ((b >> 31) & 1u);
}
FACET_CPU_ONCE_(facet_cpu_avx512fp16, avx512fp16_)
#endif
int facet_cpu_sse2(void)
{
#if FACET_ON_X86_64
    return 1;
#else
    unsigned a, b, c, d;
    return __get_cpuid(1, &a, &b, &c, &d) && ((d >> 26) & 1u);
#endif
}
#endif

#if FACET_ON_ARM_LINUX
/* aarch64: always; armv7: NEON and VFPv4 in HWCAP */
int facet_cpu_neon(void)
{
#if FACET_ON_AARCH64
    return 1;
#else
    unsigned long hw = getauxval(AT_HWCAP);
    return (hw & (1ul << 12)) && (hw & (1ul << 16)); /* HWCAP_NEON, HWCAP_VFPv4 */
#endif
}
#endif

#if FACET_ON_AARCH64
/* the f16 table of the aarch64 neon line (src/core/ports.def): FP16
 * scalar and vector arithmetic, HWCAP_FPHP (bit 9) and HWCAP_ASIMDHP
 * (bit 10) on Linux; elsewhere not asked (the scalar f16 table runs) */
int facet_cpu_neonfp16(void)
{
#if defined(__linux__)
    unsigned long hw = getauxval(AT_HWCAP);
    return (hw >> 9 & 1ul) && (hw >> 10 & 1ul);
#else
    return 0;
#endif
}
#endif

#if FACET_ON_MVE_FP
/* M-profile firmware runs privileged with no OS in between: MVFR1
 * (0xE000EF44, the System Control Space) field MVE, bits 11:8, is 2 where
 * the core has MVE integer and floating point (1: integer only, 0: none) */
int facet_cpu_helium(void)
{
    unsigned long mvfr1 = *(volatile const unsigned long *)0xE000EF44ul;
    return ((mvfr1 >> 8) & 0xFu) == 2u;
}
#endif

#if FACET_ON_RISCV64_LINUX
/* Linux sets AT_HWCAP bit ('V' - 'A') where the harts have the V extension
 * and the kernel saves its state (qemu-user 7.2 sets it for -cpu
 * rv64,v=true and clears it without); the port is RVV 1.0, the only
 * version Linux enables */
int facet_cpu_rvv(void)
{
    return (getauxval(AT_HWCAP) >> ('V' - 'A')) & 1ul;
}
#endif

#if FACET_ON_RVVFP16
/* The f16 table of the rvv line (src/core/ports.def): V (AT_HWCAP, above)
 * and Zvfh, which AT_HWCAP cannot say (it has the single-letter extensions
 * only) and V does not imply: a core may have V without Zvfh, and the
 * table would raise SIGILL there.  Linux reports Zvfh only through the
 * riscv_hwprobe system call (Documentation/arch/riscv/hwprobe.rst; the
 * call came with Linux 6.4, the Zvfh bit with a later release): one
 * key-value pair, RISCV_HWPROBE_KEY_IMA_EXT_0 = 4, whose value has
 * RISCV_HWPROBE_EXT_ZVFH = 1 << 30 set where every online hart has Zvfh
 * (cpus NULL, cpusetsize 0: all online CPUs; a key the kernel does not
 * know comes back as -1).  The numbers are the Linux UAPI's
 * (arch/riscv/include/uapi/asm/hwprobe.h; __NR_riscv_hwprobe = 258,
 * include/uapi/asm-generic/unistd.h), written out here because the
 * toolchain's kernel headers (Debian 12: Linux 6.1) predate the call.
 * Where the call is absent (ENOSYS: a kernel before 6.4, qemu-user 7.2)
 * Zvfh cannot be detected and the table is refused, with that reason
 * (facet_cpu_why).  Read once, as avx512fp16's test: the f16 batches ask
 * on every call. */
#define FACET_NR_RISCV_HWPROBE 258
#define FACET_HWPROBE_KEY_IMA_EXT_0 4
#define FACET_HWPROBE_EXT_ZVFH (1ull << 30)

enum { RVVFP16_UNREAD, RVVFP16_YES, RVVFP16_NO_V, RVVFP16_ENOSYS, RVVFP16_FAILED, RVVFP16_NO_KEY, RVVFP16_NO_ZVFH };
static int rvvfp16_read_(void)
{
    struct { int64_t key; uint64_t value; } pair = { FACET_HWPROBE_KEY_IMA_EXT_0, 0 };
    if (!facet_cpu_rvv())
        return RVVFP16_NO_V;
    if (syscall(FACET_NR_RISCV_HWPROBE, &pair, (size_t)1, (size_t)0, (void *)0, 0u) != 0)
        return errno == ENOSYS ? RVVFP16_ENOSYS : RVVFP16_FAILED;
    if (pair.key != FACET_HWPROBE_KEY_IMA_EXT_0)
        return RVVFP16_NO_KEY;
    return pair.value & FACET_HWPROBE_EXT_ZVFH ? RVVFP16_YES : RVVFP16_NO_ZVFH;
}
static int rvvfp16_state_(void)
{
    static int known; /* RVVFP16_UNREAD until read */
    int k = __atomic_load_n(&known, __ATOMIC_RELAXED);
    if (k == RVVFP16_UNREAD) {
        k = rvvfp16_read_();
        __atomic_store_n(&known, k, __ATOMIC_RELAXED);
    }
    return k;
}
int facet_cpu_rvvfp16(void) { return rvvfp16_state_() == RVVFP16_YES; }
#endif

/* what a failed CPU test saw, where it can say more than the table's
 * `needs` (src/core/f16_port.h): facet_f16_port_refusal's text; NULL
 * elsewhere */
const char *facet_cpu_why(int (*test)(void))
{
#if FACET_ON_RVVFP16
    if (test == facet_cpu_rvvfp16)
        switch (rvvfp16_state_()) {
        case RVVFP16_NO_V: return "RISC-V V with Zvfh: AT_HWCAP has no V here";
        case RVVFP16_ENOSYS:
            return "RISC-V V with Zvfh, which only the riscv_hwprobe system call reports: riscv_hwprobe answers "
                   "ENOSYS here (a kernel before 6.4, or qemu-user 7.2), so Zvfh cannot be detected";
        case RVVFP16_FAILED: return "RISC-V V with Zvfh: the riscv_hwprobe system call failed here";
        case RVVFP16_NO_KEY:
            return "RISC-V V with Zvfh: this kernel's riscv_hwprobe does not know RISCV_HWPROBE_KEY_IMA_EXT_0";
        case RVVFP16_NO_ZVFH:
            return "RISC-V V with Zvfh: riscv_hwprobe does not report Zvfh here (the CPU lacks it, or the kernel "
                   "predates its bit)";
        default: return (const char *)0;
        }
#endif
    (void)test;
    return (const char *)0;
}
