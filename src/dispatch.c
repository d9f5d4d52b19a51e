/* dispatch.c - picks the f32 port for the running CPU, once, and routes the
 * public facet_<kernel>_f32_batch functions to it.
 *
 * Ports compiled in follow the target: x86-64 -> avx512, avx2, sse2
 * (i386: avx2, sse2); aarch64/armv7 ->
 * neon; everywhere -> scalar.  "Supported" means the CPU and OS can run the
 * port: x86 checks CPUID (AVX-512F / AVX2, FMA, OSXSAVE) and XCR0 (the OS
 * saves the YMM / ZMM and opmask state);
 * armv7 checks HWCAP (NEON and VFPv4); aarch64 always has NEON.
 * The choice is a pointer published with an atomic store: threads racing on
 * the first call compute the same choice, so no lock is needed. */
#if defined(__linux__) && !defined(_GNU_SOURCE)
#define _GNU_SOURCE /* getauxval */
#endif
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "port.h"

#if defined(__x86_64__) || defined(__i386__)
#define FACET_X86 1
#include <cpuid.h>
#elif defined(__aarch64__) || (defined(__arm__) && defined(__linux__))
#define FACET_ARM 1
#if !defined(__aarch64__)
#include <sys/auxv.h>
#endif
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
int facet_cpu_sse41(void)
{
    unsigned a, b, c, d;
    return __get_cpuid(1, &a, &b, &c, &d) && ((c >> 19) & 1u);
}
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

static int always(void) { return 1; }

typedef struct {
    const facet_f32_port *port;
    int (*supported)(void);
} port_entry;

/* best first */
static const port_entry ports[] = {
#if FACET_X86
#if defined(__x86_64__)
    { &facet_port_avx512_f32, facet_cpu_avx512f },
#endif
    { &facet_port_avx2_f32, facet_cpu_avx2_fma },
    { &facet_port_sse2_f32, facet_cpu_sse2 },
#endif
#if FACET_ARM
    { &facet_port_neon_f32, facet_cpu_neon },
#endif
    { &facet_port_scalar_f32, always },
};
#define N_PORTS (sizeof ports / sizeof ports[0])

static const facet_f32_port *active;

static const facet_f32_port *best_port(void)
{
    size_t i;
    const char *env = getenv("FACET_PORT");
    if (env && *env && strcmp(env, "auto"))
        for (i = 0; i < N_PORTS; i++)
            if (!strcmp(env, ports[i].port->name) && ports[i].supported())
                return ports[i].port;
    for (i = 0; i < N_PORTS; i++)
        if (ports[i].supported())
            return ports[i].port;
    return &facet_port_scalar_f32;
}

static const facet_f32_port *port(void)
{
    const facet_f32_port *p = __atomic_load_n(&active, __ATOMIC_ACQUIRE);
    if (!p) {
        p = best_port();
        __atomic_store_n(&active, p, __ATOMIC_RELEASE);
    }
    return p;
}

int facet_set_port(const char *name)
{
    size_t i;
    if (!name || !strcmp(name, "auto")) {
        __atomic_store_n(&active, (const facet_f32_port *)NULL, __ATOMIC_RELEASE);
        (void)port();
        return 0;
    }
    for (i = 0; i < N_PORTS; i++)
        if (!strcmp(name, ports[i].port->name)) {
            if (!ports[i].supported())
                return 2;
            __atomic_store_n(&active, ports[i].port, __ATOMIC_RELEASE);
            return 0;
        }
    return 1;
}

const char *facet_port_name(void) { return port()->name; }

size_t facet_port_count(void) { return N_PORTS; }

const char *facet_port_at(size_t i, int *supported, int *lanes)
{
    if (i >= N_PORTS)
        return NULL;
    if (supported)
        *supported = ports[i].supported();
    if (lanes)
        *lanes = ports[i].port->lanes;
    return ports[i].port->name;
}

/* the public batch entry points */
#define P1 const float *a
#define P2 P1, const float *b
#define P3 P2, const float *c
#define P5 P3, const float *d, const float *e
#define P6 P5, const float *f
#define A1 a
#define A2 A1, b
#define A3 A2, c
#define A5 A3, d, e
#define A6 A5, f
#define K(name, NAME, n, ...)                                      \
    void facet_##name##_f32_batch(float *out, P##n, size_t count)  \
    {                                                              \
        port()->name(out, A##n, count);                            \
    }
#include "kernels.def"
#undef K
