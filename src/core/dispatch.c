/* dispatch.c - the one dispatcher: picks the port for the running CPU once,
 * for both formats, and routes every public facet_<kernel>_f32_batch and
 * facet_<kernel>_fx_batch to it.
 * Names generated here from src/core/kernels.def: the public f32 and f32_fast
 * batch entry points (the fx ones are in src/fx/fx_batch.c and ask facet_fx_active_port()).
 *
 * Ports compiled in follow the target, best first: x86-64 -> avx512, avx2,
 * sse2 (i386: avx2, sse2); aarch64 / armv7 Linux -> neon; Armv8.1-M with
 * MVE floating point (Cortex-M55 firmware) -> helium; riscv64 Linux -> rvv
 * (where ports/rvv/port.mk's compiler builds it); everywhere -> scalar.  A port is "supported" when src/core/cpu.c says this CPU and OS run it.
 * Each port brings its f32 batches and, where it has any, fixed-point code
 * (src/core/port.h): avx512 and avx2 run the AVX2 fx code, aarch64 neon the NEON
 * fx code, helium its own (ports/helium), rvv its fx_fast code (ports/rvv),
 * the others the scalar fx loops.
 *
 * The choice is one pointer.  The first batch call computes the automatic
 * choice (FACET_PORT, else the best supported port) and installs it with a
 * compare-and-swap from "not chosen", so it can never overwrite a choice
 * another thread made meanwhile with facet_set_port(); facet_set_port()
 * stores its port directly.  Every later call is one acquire load. */
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "facet/fx.h"
#include "cpu.h"
#include "port.h"

#if defined(__x86_64__) || defined(__i386__)
#define FACET_X86 1
#elif defined(__aarch64__) || (defined(__arm__) && defined(__linux__))
#define FACET_ARM 1
#elif defined(__ARM_FEATURE_MVE) && (__ARM_FEATURE_MVE & 2)
#define FACET_HELIUM 1 /* Armv8.1-M with MVE floating point (Cortex-M55, M85) */
#elif defined(__riscv) && __riscv_xlen == 64 && defined(__linux__) && defined(FACET_PORT_RVV)
#define FACET_RVV 1 /* ports/rvv, compiled in where RVV_CC builds it (ports/rvv/port.mk) */
#endif

typedef struct port_entry {
    const facet_f32_port *f32, *f32_fast;
    const facet_fx_port *fx, *fx_fast; /* NULL: the tier's scalar loops for every kernel */
    int (*supported)(void);
} port_entry;

static int always(void) { return 1; }
#if defined(__x86_64__)
/* the avx512 port also runs the AVX2 fx code: ask for both */
static int avx512_and_avx2(void) { return facet_cpu_avx512f() && facet_cpu_avx2_fma(); }
#endif

/* best first */
static const port_entry ports[] = {
#if FACET_X86
#if defined(__x86_64__)
    { &facet_port_avx512_f32, &facet_port_avx512_f32_fast, &facet_fx_port_avx2, &facet_fx_fast_port_avx2,
      avx512_and_avx2 },
#endif
    { &facet_port_avx2_f32, &facet_port_avx2_f32_fast, &facet_fx_port_avx2, &facet_fx_fast_port_avx2,
      facet_cpu_avx2_fma },
    { &facet_port_sse2_f32, &facet_port_sse2_f32_fast, NULL, NULL, facet_cpu_sse2 },
#endif
#if FACET_ARM
#if defined(__aarch64__)
    { &facet_port_neon_f32, &facet_port_neon_f32_fast, &facet_fx_port_neon, &facet_fx_fast_port_neon,
      facet_cpu_neon },
#else
    { &facet_port_neon_f32, &facet_port_neon_f32_fast, NULL, NULL, facet_cpu_neon }, /* armv7: see ports/neon/fx_neon.c */
#endif
#endif
#if FACET_HELIUM
    { &facet_port_helium_f32, &facet_port_helium_f32_fast, &facet_fx_port_helium, &facet_fx_fast_port_helium,
      facet_cpu_helium },
#endif
#if FACET_RVV
    /* lanes 0 (vector-length agnostic): facet_port_at asks facet_rvv_lanes() */
    { &facet_port_rvv_f32, &facet_port_rvv_f32_fast, NULL, &facet_fx_fast_port_rvv, facet_cpu_rvv },
#endif
    { &facet_port_scalar_f32, &facet_port_scalar_f32_fast, NULL, NULL, always },
};
#define N_PORTS (sizeof ports / sizeof ports[0])
#define SCALAR_PORT (&ports[N_PORTS - 1])

static const port_entry *find(const char *name)
{
    size_t i;
    for (i = 0; name && i < N_PORTS; i++)
        if (!strcmp(name, ports[i].f32->name))
            return &ports[i];
    return NULL;
}

/* FACET_PORT if it names a supported port, else the best supported one */
static const port_entry *automatic(void)
{
    const port_entry *p = find(getenv("FACET_PORT"));
    size_t i;
    if (p && p->supported())
        return p;
    for (i = 0; i < N_PORTS; i++)
        if (ports[i].supported())
            return &ports[i];
    return SCALAR_PORT;
}

static const port_entry *active; /* NULL: not chosen yet */

static const port_entry *port(void)
{
    const port_entry *p = __atomic_load_n(&active, __ATOMIC_ACQUIRE);
    if (!p) {
        const port_entry *mine = automatic();
        /* installs ours unless another thread chose first; p gets theirs */
        if (__atomic_compare_exchange_n(&active, &p, mine, 0, __ATOMIC_ACQ_REL, __ATOMIC_ACQUIRE))
            p = mine;
    }
    return p;
}

int facet_set_port(const char *name)
{
    const port_entry *p;
    if (!name || !strcmp(name, "auto")) {
        __atomic_store_n(&active, automatic(), __ATOMIC_RELEASE);
        return 0;
    }
    p = find(name);
    if (!p)
        return 1;
    if (!p->supported())
        return 2;
    __atomic_store_n(&active, p, __ATOMIC_RELEASE);
    return 0;
}

const char *facet_port_name(void) { return port()->f32->name; }

const char *facet_fx_port_name(void) { return facet_fx_active_port(0)->name; }

size_t facet_port_count(void) { return N_PORTS; }

const char *facet_port_at(size_t i, int *supported, int *lanes)
{
    if (i >= N_PORTS)
        return NULL;
    if (supported)
        *supported = ports[i].supported();
    if (lanes)
        *lanes = ports[i].f32->lanes;
#if FACET_RVV
    /* VLMAX, asked only where the CPU has V (vsetvli traps elsewhere) */
    if (lanes && !*lanes)
        *lanes = ports[i].supported() ? facet_rvv_lanes() : 0;
#endif
    return ports[i].f32->name;
}

int facet_port_supported(const char *name)
{
    const port_entry *p = find(name);
    return p && p->supported();
}

/* ---- the public batch entry points -------------------------------------- */
#define F32_PARAM_(q) const float *x##q
#define FX_PARAM_(q) const int32_t *x##q
#define ARG_(q) x##q

#define FACET_KERNEL(name, NAME, n, fx_type, ...)                                    \
    void facet_##name##_f32_batch(float *out, FACET_EACH_INPUT(n, F32_PARAM_), size_t count) \
    {                                                                                \
        port()->f32->name(out, FACET_EACH_INPUT(n, ARG_), count);                    \
    }                                                                                \
    void facet_##name##_f32_fast_batch(float *out, FACET_EACH_INPUT(n, F32_PARAM_), size_t count) \
    {                                                                                \
        port()->f32_fast->name(out, FACET_EACH_INPUT(n, ARG_), count);               \
    }
#include "kernels.def"
#undef FACET_KERNEL

/* the fx batch entry points (src/fx/fx_batch.c) ask here */
const facet_fx_port *facet_fx_active_port(int fast)
{
    const port_entry *p = port();
    if (fast)
        return p->fx_fast ? p->fx_fast : &facet_fx_fast_port_scalar;
    return p->fx ? p->fx : &facet_fx_port_scalar;
}

/* ---- the RGB batches (src/f32/f32_rgb_batch_body.h): one port function per tier,
 * every layout a set of strides ------------------------------------------- */
static void rgb_run_(int fast, float *const out[3], ptrdiff_t os, const float *nol, const float *nov,
                     const float *lov, const float *alpha, ptrdiff_t as, const float *const f0[3],
                     const float *const alb[3], ptrdiff_t ms, size_t n)
{
    facet_rgb_io io;
    int c;
    for (c = 0; c < 3; c++) {
        io.out[c] = out[c];
        io.f0[c] = f0[c];
        io.albedo[c] = alb[c];
    }
    io.out_stride = os;
    io.alpha = alpha;
    io.alpha_stride = as;
    io.material_stride = ms;
    (fast ? port()->f32_fast : port()->f32)->brdf_hammon_rgb(&io, nol, nov, lov, n);
}

#define RGB_ENTRIES_(tier, fast)                                                                    \
    void facet_brdf_hammon_rgb_##tier##_batch(float *const out[3], const float *nol,               \
                                              const float *nov, const float *lov,                  \
                                              const float *alpha, const float *const f0[3],        \
                                              const float *const albedo[3], size_t n)              \
    {                                                                                               \
        rgb_run_(fast, out, 1, nol, nov, lov, alpha, 1, f0, albedo, 1, n);                          \
    }                                                                                               \
    void facet_brdf_hammon_rgb_##tier##_batch_interleaved(float *out, const float *nol,            \
                                                          const float *nov, const float *lov,      \
                                                          const float *alpha, const float *f0,     \
                                                          const float *albedo, size_t n)           \
    {                                                                                               \
        float *const o[3] = { out, out + 1, out + 2 };                                              \
        const float *const f[3] = { f0, f0 + 1, f0 + 2 }, *const a[3] = { albedo, albedo + 1, albedo + 2 }; \
        rgb_run_(fast, o, 3, nol, nov, lov, alpha, 1, f, a, 3, n);                                  \
    }                                                                                               \
    void facet_brdf_hammon_rgb_##tier##_batch_material(float *const out[3], const float *nol,      \
                                                       const float *nov, const float *lov,         \
                                                       const facet_material_f32 *m, size_t n)      \
    {                                                                                               \
        const float *const f[3] = { &m->f0[0], &m->f0[1], &m->f0[2] };                              \
        const float *const a[3] = { &m->albedo[0], &m->albedo[1], &m->albedo[2] };                  \
        rgb_run_(fast, out, 1, nol, nov, lov, &m->alpha, 0, f, a, 0, n);                            \
    }                                                                                               \
    void facet_brdf_hammon_rgb_##tier##_batch_material_interleaved(float *out, const float *nol,   \
                                                                   const float *nov,               \
                                                                   const float *lov,               \
                                                                   const facet_material_f32 *m,    \
                                                                   size_t n)                       \
    {                                                                                               \
        float *const o[3] = { out, out + 1, out + 2 };                                              \
        const float *const f[3] = { &m->f0[0], &m->f0[1], &m->f0[2] };                              \
        const float *const a[3] = { &m->albedo[0], &m->albedo[1], &m->albedo[2] };                  \
        rgb_run_(fast, o, 3, nol, nov, lov, &m->alpha, 0, f, a, 0, n);                              \
    }
RGB_ENTRIES_(f32, 0)
RGB_ENTRIES_(f32_fast, 1)
