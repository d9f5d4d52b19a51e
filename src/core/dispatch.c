/* dispatch.c - the one dispatcher: picks the port for the running CPU once
 * and routes every public batch call to it: facet_<kernel>_f32_batch and
 * _f32_fast_batch, the RGB batches, the per-sample calls facet_<kernel>_f32
 * and _f32_fast and facet_brdf_hammon_rgb_f32 (_fast), facet_<sampler>_f32_batch and
 * _f32_fast_batch, and (through facet_fx_active_port) every
 * facet_<kernel>_fx_batch and _fx_fast_batch (src/fx/fx_batch.c).
 * Names generated here from src/core/ports.def (the table of ports),
 * src/core/kernels.def and src/core/sample_kernels.def (the entry points,
 * batch and per-sample).
 *
 * The ports compiled in are the lines of src/core/ports.def whose guard
 * holds (src/core/platform.h), best first, scalar last; a port is
 * "supported" when its CPU test (src/core/cpu.c) says this CPU and OS run
 * it.  Each line brings its f32 and sampler tables of both tiers and the
 * fixed-point tables it runs (src/core/port.h, src/core/sample_port.h).
 *
 * The choice is one pointer to a line of that table.  The first batch call
 * computes the automatic choice (FACET_PORT, else the best supported port)
 * and installs it with a compare-and-swap from "not chosen", so it can
 * never overwrite a choice another thread made meanwhile with
 * facet_set_port(); facet_set_port() stores its port directly.  Every later
 * call is one acquire load, then the table's function. */
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "facet/fx.h"
#include "platform.h"
#include "cpu.h"
#include "port.h"
#include "sample_port.h"
#include "f16_port.h"
#include "facet/f16.h"

typedef struct port_entry {
    const facet_f32_port *f32, *f32_fast;
    const facet_sample_port *sample, *sample_fast;
    const facet_fx_port *fx, *fx_fast;
    int (*supported)(void);
    const facet_f16_port *f16; /* run where f16_supported() says so, else the scalar one */
    int (*f16_supported)(void);
} port_entry;

/* best first, scalar last */
static const port_entry ports[] = {
#define FACET_PORT(name, guard, cpu, fx, fx_fast, f16, f16_cpu)                           \
    FACET_PORT_IF(guard, { &facet_port_##name##_f32, &facet_port_##name##_f32_fast,       \
                           &facet_sample_port_##name##_f32, &facet_sample_port_##name##_f32_fast, \
                           &facet_fx_port_##fx, &facet_fx_fast_port_##fx_fast, facet_cpu_##cpu, \
                           &facet_f16_port_##f16, facet_cpu_##f16_cpu },)
#include "ports.def"
#undef FACET_PORT
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
    /* lanes 0, vector-length agnostic: the port's run-time lanes, asked
     * only where the CPU runs it (rvv: vsetvli traps elsewhere) */
    if (lanes && !*lanes && ports[i].f32->lanes_fn)
        *lanes = ports[i].supported() ? ports[i].f32->lanes_fn() : 0;
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

/* ---- the per-sample entry points: the active port's per-sample entries of
 * the tier (src/f32/f32_one_body.h), one acquire load and an indirect call */
#define ONE_PARAM_(q) float x##q
#define FACET_KERNEL(name, NAME, n, fx_type, ...)                                    \
    float facet_##name##_f32(FACET_EACH_INPUT(n, ONE_PARAM_))                        \
    {                                                                                \
        return port()->f32->one->name(FACET_EACH_INPUT(n, ARG_));                    \
    }                                                                                \
    float facet_##name##_f32_fast(FACET_EACH_INPUT(n, ONE_PARAM_))                   \
    {                                                                                \
        return port()->f32_fast->one->name(FACET_EACH_INPUT(n, ARG_));               \
    }
#include "kernels.def"
#undef FACET_KERNEL

void facet_brdf_hammon_rgb_f32(float out[3], float nol, float nov, float lov, float alpha, const float f0[3],
                               const float albedo[3])
{
    port()->f32->one->brdf_hammon_rgb(out, nol, nov, lov, alpha, f0, albedo);
}

void facet_brdf_hammon_rgb_f32_fast(float out[3], float nol, float nov, float lov, float alpha,
                                    const float f0[3], const float albedo[3])
{
    port()->f32_fast->one->brdf_hammon_rgb(out, nol, nov, lov, alpha, f0, albedo);
}

/* the fx batch entry points (src/fx/fx_batch.c) ask here: the port's own
 * table of the tier, the scalar loops' where it has none (ports.def) */
const facet_fx_port *facet_fx_active_port(int fast)
{
    const port_entry *p = port();
    return fast ? p->fx_fast : p->fx;
}

/* ---- the RGB batches (src/f32/f32_rgb_batch_body.h): one port function per tier,
 * every layout a set of strides ------------------------------------------- */
static void rgb_run_(int fast, float *const out[3], ptrdiff_t os, const float *nol, const float *nov,
                     const float *lov, const float *alpha, ptrdiff_t as, const float *const f0[3],
                     const float *const alb[3], ptrdiff_t fs, ptrdiff_t abs_, size_t n)
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
    io.f0_stride = fs;
    io.albedo_stride = abs_;
    (fast ? port()->f32_fast : port()->f32)->brdf_hammon_rgb(&io, nol, nov, lov, n);
}

#define RGB_ENTRIES_(tier, fast)                                                                    \
    void facet_brdf_hammon_rgb_##tier##_batch(float *const out[3], const float *nol,               \
                                              const float *nov, const float *lov,                  \
                                              const float *alpha, const float *const f0[3],        \
                                              const float *const albedo[3], size_t n)              \
    {                                                                                               \
        rgb_run_(fast, out, 1, nol, nov, lov, alpha, 1, f0, albedo, 1, 1, n);                          \
    }                                                                                               \
    void facet_brdf_hammon_rgb_##tier##_batch_interleaved(float *out, const float *nol,            \
                                                          const float *nov, const float *lov,      \
                                                          const float *alpha, const float *f0,     \
                                                          const float *albedo, size_t n)           \
    {                                                                                               \
        float *const o[3] = { out, out + 1, out + 2 };                                              \
        const float *const f[3] = { f0, f0 + 1, f0 + 2 }, *const a[3] = { albedo, albedo + 1, albedo + 2 }; \
        rgb_run_(fast, o, 3, nol, nov, lov, alpha, 1, f, a, 3, 3, n);                                  \
    }                                                                                               \
    void facet_brdf_hammon_rgb_##tier##_batch_material(float *const out[3], const float *nol,      \
                                                       const float *nov, const float *lov,         \
                                                       const facet_material_f32 *m, size_t n)      \
    {                                                                                               \
        const float *const f[3] = { &m->f0[0], &m->f0[1], &m->f0[2] };                              \
        const float *const a[3] = { &m->albedo[0], &m->albedo[1], &m->albedo[2] };                  \
        rgb_run_(fast, out, 1, nol, nov, lov, &m->alpha, 0, f, a, 0, 0, n);                            \
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
        rgb_run_(fast, o, 3, nol, nov, lov, &m->alpha, 0, f, a, 0, 0, n);                           \
    }                                                                                               \
    void facet_brdf_hammon_rgb_##tier##_batch_textured(float *const out[3], const float *nol,      \
                                                       const float *nov, const float *lov,         \
                                                       const facet_material_f32 *m,                \
                                                       const float *const albedo[3], size_t n)     \
    {                                                                                               \
        const float *const f[3] = { &m->f0[0], &m->f0[1], &m->f0[2] };                              \
        rgb_run_(fast, out, 1, nol, nov, lov, &m->alpha, 0, f, albedo, 0, 1, n);                    \
    }                                                                                               \
    void facet_brdf_hammon_rgb_##tier##_batch_textured_rough(float *const out[3], const float *nol,\
                                                             const float *nov, const float *lov,   \
                                                             const float *alpha,                   \
                                                             const facet_material_f32 *m,          \
                                                             const float *const albedo[3], size_t n) \
    {                                                                                               \
        const float *const f[3] = { &m->f0[0], &m->f0[1], &m->f0[2] };                              \
        rgb_run_(fast, out, 1, nol, nov, lov, alpha, 1, f, albedo, 0, 1, n);                        \
    }
RGB_ENTRIES_(f32, 0)
RGB_ENTRIES_(f32_fast, 1)

/* ---- the samplers' batch entry points: the same port's sampler tables --- */
#define S_OUT_P_(q) float *o##q
#define S_IN_P_(q) const float *x##q
#define S_OUT_A_(q) o##q
#define FACET_SAMPLER(name, NAME, kind, err, n_out, n_in, ...)                                  \
    void facet_##name##_f32_batch(FACET_SAMPLE_EACH(n_out, S_OUT_P_), FACET_SAMPLE_EACH(n_in, S_IN_P_), \
                                  size_t n)                                                     \
    {                                                                                           \
        float *const o_[] = { FACET_SAMPLE_EACH(n_out, S_OUT_A_) };                             \
        const float *const i_[] = { FACET_SAMPLE_EACH(n_in, ARG_) };                            \
        port()->sample->name(o_, i_, n);                                                        \
    }                                                                                           \
    void facet_##name##_f32_fast_batch(FACET_SAMPLE_EACH(n_out, S_OUT_P_),                      \
                                       FACET_SAMPLE_EACH(n_in, S_IN_P_), size_t n)              \
    {                                                                                           \
        float *const o_[] = { FACET_SAMPLE_EACH(n_out, S_OUT_A_) };                             \
        const float *const i_[] = { FACET_SAMPLE_EACH(n_in, ARG_) };                            \
        port()->sample_fast->name(o_, i_, n);                                                   \
    }
#include "sample_kernels.def"
#undef FACET_SAMPLER

/* ---- the f16 batches (facet/f16.h): the active port's f16 table where its
 * own CPU test holds (AVX-512 FP16 is not implied by the avx512 port's
 * AVX-512F), else the scalar one ----------------------------------------- */
static const facet_f16_port *f16_port(void)
{
    const port_entry *p = port();
    return p->f16_supported() ? p->f16 : SCALAR_PORT->f16;
}

const char *facet_f16_port_name(void) { return f16_port()->name; }

/* the line of the f16 table called name, and whether this CPU runs it */
static const port_entry *f16_find(const char *name)
{
    size_t i;
    for (i = 0; name && i < N_PORTS; i++)
        if (!strcmp(name, ports[i].f16->name))
            return &ports[i];
    return NULL;
}

int facet_f16_port_supported(const char *name)
{
    const port_entry *p = f16_find(name);
    return p && p->f16_supported();
}

const char *facet_f16_port_refusal(const char *name)
{
    const port_entry *p = f16_find(name);
    const char *why;
    if (!p || p->f16_supported())
        return NULL;
    why = facet_cpu_why(p->f16_supported);
    return why ? why : p->f16->needs;
}

#define F16_PARAM_(q) const uint16_t *x##q
#define FACET_F16(name, NAME, n, form, why)                                                        \
    FACET_IF_F16(form, void facet_##name##_f16_batch(uint16_t *out, FACET_EACH_INPUT(n, F16_PARAM_), \
                                                     size_t count)                                 \
    {                                                                                              \
        f16_port()->name(out, FACET_EACH_INPUT(n, ARG_), count);                                   \
    })
#include "f16_kernels.def"
#undef FACET_F16
