/* api_bench.c - `facet-bench api`: the entry points a renderer chooses
 * between, timed in one run on this machine (issue 15):
 *   - RGB: three brdf_hammon batches vs one RGB batch (planar, interleaved),
 *   - uniform material vs per-sample arrays (the same values),
 *   - per pixel: one sample per call through the library's scalar call,
 *     the vector entry, and the dispatched batch with n = 1,
 *   - fixed point: the RGB kernel vs three brdf_hammon_fx calls,
 *   - per call (issue 26): facet_brdf_hammon_f32 and _f32_fast one sample
 *     per call (dispatched to the port's per-sample entries), facet/scalar.h
 *     inline and the engine-style formula (-ffast-math), each in a loop of
 *     independent calls that is not vectorized (percall.h), in ticks per
 *     call and as a ratio to the engine-style code.
 * Per port this CPU runs (the batch forms follow facet_set_port), both f32
 * tiers where it matters.  Unit: the clock's (cyc_unit(): ticks on a VM
 * without a PMU), per RGB sample; min and median over >= 11 epochs. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "facet.h"
#include "facet/fx.h"
#include "tests/lib/sample.h"
#include "cycles.h"
#include "facet_bench.h"
#include "raster/raster.h"
#include "percall.h"

#define N 1024

static float nl[N], nv[N], lv[N], al[N], f0p[3][N], abp[3][N], f0i[3 * N], abi[3 * N];
static float op[3][N], oi[3 * N];
static int32_t qnl[N], qnv[N], qlv[N], qal[N], qf0[3][N], qab[3][N];
static uint64_t qo[3][N];
static facet_material_f32 mat;
static volatile float sink_;

static void mono3(long reps)
{
    long r;
    for (r = 0; r < reps; r++) {
        int c;
        for (c = 0; c < 3; c++)
            facet_brdf_hammon_f32_batch(op[c], nl, nv, lv, al, f0p[c], abp[c], N);
    }
}
static void rgb_planar(long reps)
{
    long r;
    float *o[3] = { op[0], op[1], op[2] };
    const float *f[3] = { f0p[0], f0p[1], f0p[2] }, *a[3] = { abp[0], abp[1], abp[2] };
    for (r = 0; r < reps; r++)
        facet_brdf_hammon_rgb_f32_batch(o, nl, nv, lv, al, f, a, N);
}
static void rgb_interleaved(long reps)
{
    long r;
    for (r = 0; r < reps; r++)
        facet_brdf_hammon_rgb_f32_batch_interleaved(oi, nl, nv, lv, al, f0i, abi, N);
}
static void rgb_material(long reps)
{
    long r;
    float *o[3] = { op[0], op[1], op[2] };
    for (r = 0; r < reps; r++)
        facet_brdf_hammon_rgb_f32_batch_material(o, nl, nv, lv, &mat, N);
}
static void rgb_textured(long reps)
{
    long r;
    float *o[3] = { op[0], op[1], op[2] };
    const float *a[3] = { abp[0], abp[1], abp[2] };
    for (r = 0; r < reps; r++)
        facet_brdf_hammon_rgb_f32_batch_textured(o, nl, nv, lv, &mat, a, N);
}
static void rgb_textured_rough(long reps)
{
    long r;
    float *o[3] = { op[0], op[1], op[2] };
    const float *a[3] = { abp[0], abp[1], abp[2] };
    for (r = 0; r < reps; r++)
        facet_brdf_hammon_rgb_f32_batch_textured_rough(o, nl, nv, lv, al, &mat, a, N);
}
static void rgb_material_interleaved(long reps)
{
    long r;
    for (r = 0; r < reps; r++)
        facet_brdf_hammon_rgb_f32_batch_material_interleaved(oi, nl, nv, lv, &mat, N);
}
static void rgb_fast_planar(long reps)
{
    long r;
    float *o[3] = { op[0], op[1], op[2] };
    const float *f[3] = { f0p[0], f0p[1], f0p[2] }, *a[3] = { abp[0], abp[1], abp[2] };
    for (r = 0; r < reps; r++)
        facet_brdf_hammon_rgb_f32_fast_batch(o, nl, nv, lv, al, f, a, N);
}
static void rgb_fast_material(long reps)
{
    long r;
    float *o[3] = { op[0], op[1], op[2] };
    for (r = 0; r < reps; r++)
        facet_brdf_hammon_rgb_f32_fast_batch_material(o, nl, nv, lv, &mat, N);
}
/* per pixel: one call per sample */
static void pp_scalar_call(long reps)
{
    long r;
    int i;
    for (r = 0; r < reps; r++)
        for (i = 0; i < N; i++)
            facet_brdf_hammon_rgb_f32(&oi[3 * i], nl[i], nv[i], lv[i], mat.alpha, mat.f0, mat.albedo);
}
static void pp_batch1(long reps)
{
    long r;
    int i;
    for (r = 0; r < reps; r++)
        for (i = 0; i < N; i++)
            facet_brdf_hammon_rgb_f32_batch_material_interleaved(&oi[3 * i], &nl[i], &nv[i], &lv[i], &mat, 1);
}
static facet_dirs_f32 dirs[N];
static void pp_shade(long reps)
{
    long r;
    int i;
    for (r = 0; r < reps; r++)
        for (i = 0; i < N; i++)
            facet_shade_hammon_rgb_f32(&oi[3 * i], &dirs[i], &mat);
}
static void fx_mono3(long reps)
{
    long r;
    int i, c;
    for (r = 0; r < reps; r++)
        for (i = 0; i < N; i++)
            for (c = 0; c < 3; c++)
                qo[c][i] = facet_brdf_hammon_fx(qnl[i], qnv[i], qlv[i], qal[i], qf0[c][i], qab[c][i]);
}
static void fx_rgb(long reps)
{
    long r;
    uint64_t *o[3] = { qo[0], qo[1], qo[2] };
    const int32_t *f[3] = { qf0[0], qf0[1], qf0[2] }, *a[3] = { qab[0], qab[1], qab[2] };
    for (r = 0; r < reps; r++)
        facet_brdf_hammon_rgb_fx_batch(o, qnl, qnv, qlv, qal, f, a, N);
}
static void fx_fast_mono3(long reps)
{
    long r;
    int i, c;
    for (r = 0; r < reps; r++)
        for (i = 0; i < N; i++)
            for (c = 0; c < 3; c++)
                qo[c][i] = facet_brdf_hammon_fx_fast(qnl[i], qnv[i], qlv[i], qal[i], qf0[c][i], qab[c][i]);
}
static void fx_fast_rgb(long reps)
{
    long r;
    uint64_t *o[3] = { qo[0], qo[1], qo[2] };
    const int32_t *f[3] = { qf0[0], qf0[1], qf0[2] }, *a[3] = { qab[0], qab[1], qab[2] };
    for (r = 0; r < reps; r++)
        facet_brdf_hammon_rgb_fx_fast_batch(o, qnl, qnv, qlv, qal, f, a, N);
}


/* per call: brdf_hammon, one sample per call, a loop of independent calls */
static const float *pc_in_[6] = { nl, nv, lv, al, f0p[0], abp[0] };
static void pc_lib(long reps)
{
    long r;
    int i;
    for (r = 0; r < reps; r++)
        for (i = 0; i < N; i++)
            op[1][i] = facet_brdf_hammon_f32(nl[i], nv[i], lv[i], al[i], f0p[0][i], abp[0][i]);
}
static void pc_lib_fast(long reps)
{
    long r;
    int i;
    for (r = 0; r < reps; r++)
        for (i = 0; i < N; i++)
            op[1][i] = facet_brdf_hammon_f32_fast(nl[i], nv[i], lv[i], al[i], f0p[0][i], abp[0][i]);
}
static void pc_inline(long reps) { long r; for (r = 0; r < reps; r++) percall_scalar_h(op[1], pc_in_, N); }
static void pc_inline_fast(long reps) { long r; for (r = 0; r < reps; r++) percall_scalar_h_fast(op[1], pc_in_, N); }
static void pc_peer(long reps) { long r; for (r = 0; r < reps; r++) percall_peer(op[1], pc_in_, N); }

/* the rasterizer's shading pass (bench/raster), one frame per rep */
static rs_gbuf *rg_;
static void r_scalar(long reps) { long r; for (r = 0; r < reps; r++) rs_shade_scalar(rg_); }
static void r_avx2(long reps) { long r; for (r = 0; r < reps; r++) rs_shade_avx2(rg_); }
static void r_batch(long reps) { long r; for (r = 0; r < reps; r++) rs_shade_batch(rg_); }
static void r_rgb(long reps) { long r; for (r = 0; r < reps; r++) rs_shade_rgb(rg_); }
static void r_material(long reps) { long r; for (r = 0; r < reps; r++) rs_shade_material(rg_); }
static void r_pixel(long reps) { long r; for (r = 0; r < reps; r++) rs_shade_pixel(rg_); }


/* Interleaved rounds: each round times one pass of every entry (rdtsc
 * around the call); per entry the minimum over the rounds (and the median)
 * per unit.  Interruptions by the other load on a shared VM only add time,
 * so the minimum of direct timings is the robust figure, and entries
 * compared with each other were measured in the same rounds. */
typedef struct entry { const char *port, *what; void (*fn)(long); double units; } entry;

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double last_min_[16]; /* run_entries: each entry's minimum */
static void run_entries(const entry *e, int n, int rounds, const char *suffix)
{
    static double t[16][401];
    int r, i;
    for (i = 0; i < n; i++)
        e[i].fn(1); /* warm-up */
    for (r = 0; r < rounds; r++)
        for (i = 0; i < n; i++) {
            uint64_t t0 = cyc_now();
            e[i].fn(1);
            t[i][r] = (double)(cyc_now() - t0) / e[i].units;
        }
    for (i = 0; i < n; i++) {
        qsort(t[i], (size_t)rounds, sizeof(double), cmp_d);
        last_min_[i] = t[i][0];
        printf("%-8s %-48s %10.2f %10.2f%s\n", e[i].port, e[i].what, t[i][0], t[i][rounds / 2], suffix);
    }
}

int facet_bench_api(int argc, char **argv)
{
    smp_rng rng = { 2026 };
    int i, c, quick = argc > 1 && !strcmp(argv[1], "--quick");
    size_t pi;
    if (argc > 1 && !quick) {
        printf("usage: facet-bench api [--quick]\n"
               "Times the RGB, uniform-material, per-pixel and fixed-point RGB entry points\n"
               "in one run, per port this CPU runs (README \"Per-pixel use\").\n");
        return !strcmp(argv[1], "--help") ? 0 : 2;
    }
    cyc_init();
    for (i = 0; i < N; i++) {
        float lx, ly, lz, len;
        smp_geometry(&rng, &nl[i], &nv[i], &lv[i]);
        al[i] = 0.0625f;
        for (c = 0; c < 3; c++) {
            f0p[c][i] = f0i[3 * i + c] = 0.04f + 0.01f * c;
            abp[c][i] = abi[3 * i + c] = 0.8f - 0.3f * c;
        }
        qnl[i] = (int32_t)(nl[i] * 32768);
        qnv[i] = (int32_t)(nv[i] * 32768);
        qlv[i] = (int32_t)(lv[i] * 32768);
        qal[i] = 2048;
        for (c = 0; c < 3; c++) {
            qf0[c][i] = (int32_t)(f0p[c][i] * 32768);
            qab[c][i] = (int32_t)(abp[c][i] * 32768);
        }
        /* unit vectors for the vector entry: N = z, V in the xz plane */
        dirs[i].n.x = 0; dirs[i].n.y = 0; dirs[i].n.z = 1;
        dirs[i].v.x = 0.6f; dirs[i].v.y = 0; dirs[i].v.z = 0.8f;
        lx = (float)(smp_u01(&rng) - 0.5); ly = (float)(smp_u01(&rng) - 0.5); lz = (float)smp_u01(&rng);
        len = (float)sqrt(lx * lx + ly * ly + lz * lz) + 1e-6f;
        dirs[i].l.x = lx / len; dirs[i].l.y = ly / len; dirs[i].l.z = lz / len;
    }
    mat.alpha = 0.0625f;
    for (c = 0; c < 3; c++) {
        mat.f0[c] = 0.04f + 0.01f * c;
        mat.albedo[c] = 0.8f - 0.3f * c;
    }
    printf("# facet-bench api: %s per RGB sample (clock %s; %s), N = %d, interleaved rounds, one run\n", cyc_unit(), cyc_source(),
           cyc_is_cycles() ? "core cycles" : "not core cycles", N);
    printf("%-8s %-48s %10s %10s\n", "port", "entry point (per RGB sample)", "min", "median");
    for (pi = 0; pi < facet_port_count(); pi++) {
        int sup;
        const char *pn = facet_port_at(pi, &sup, NULL);
        if (!sup)
            continue;
        facet_set_port(pn);
        {
            entry e[] = {
                { pn, "brdf_hammon_f32_batch x 3 channels", mono3, N },
                { pn, "brdf_hammon_rgb_f32_batch (planar arrays)", rgb_planar, N },
                { pn, "brdf_hammon_rgb_f32_batch_interleaved", rgb_interleaved, N },
                { pn, "brdf_hammon_rgb_f32_batch_material (uniform)", rgb_material, N },
                { pn, "brdf_hammon_rgb_f32_batch_material_interleaved", rgb_material_interleaved, N },
                { pn, "brdf_hammon_rgb_f32_batch_textured", rgb_textured, N },
                { pn, "brdf_hammon_rgb_f32_batch_textured_rough", rgb_textured_rough, N },
                { pn, "brdf_hammon_rgb_f32_fast_batch (planar arrays)", rgb_fast_planar, N },
                { pn, "brdf_hammon_rgb_f32_fast_batch_material", rgb_fast_material, N },
                { pn, "per pixel: _batch_material_interleaved, n = 1", pp_batch1, N },
                { pn, "per pixel: brdf_hammon_rgb_f32 (scalar call)", pp_scalar_call, N },
                { pn, "per pixel: shade_hammon_rgb_f32 (N, L, V)", pp_shade, N },
                { pn, "per call: brdf_hammon_f32 (mono)", pc_lib, N },
                { pn, "per call: brdf_hammon_f32_fast (mono)", pc_lib_fast, N },
            };
            run_entries(e, (int)(sizeof e / sizeof e[0]), quick ? 5 : 200, "");
        }
    }
    facet_set_port("auto");
    {
        entry e[] = {
            { "scalar", "fx: brdf_hammon_fx x 3 channels", fx_mono3, N },
            { "scalar", "fx: brdf_hammon_rgb_fx_batch", fx_rgb, N },
            { "scalar", "fx_fast: brdf_hammon_fx_fast x 3 channels", fx_fast_mono3, N },
            { "scalar", "fx_fast: brdf_hammon_rgb_fx_fast_batch", fx_fast_rgb, N },
        };
        run_entries(e, 4, quick ? 5 : 60, "");
    }
    /* per call, interleaved: the library's dispatched per-sample calls, scalar.h
     * inline and the engine-style formula, built for percall_march */
#if defined(__x86_64__) || defined(__i386__)
    if (facet_port_supported("avx2")) /* the objects are built for x86-64-v3 */
#endif
    {
        const char *pn = facet_port_name();
        entry e[] = {
            { pn, "per call: facet_brdf_hammon_f32 (dispatched)", pc_lib, N },
            { pn, "per call: facet_brdf_hammon_f32_fast (dispatched)", pc_lib_fast, N },
            { "inline", "per call: facet/scalar.h f32, -O2", pc_inline, N },
            { "inline", "per call: facet/scalar.h f32_fast, -O2", pc_inline_fast, N },
            { "peer", "per call: engine-style, -O2 -ffast-math", pc_peer, N },
        };
        int k;
        printf("# per call: brdf_hammon one sample per call, a loop of %d independent calls, not vectorized;\n"
               "# inline and peer built with %s -fno-tree-vectorize; %s per call, min and median, ratio to the peer's min\n",
               N, percall_march, cyc_unit());
        run_entries(e, 5, quick ? 11 : 301, "");
        for (k = 0; k < 4; k++)
            printf("%-8s %-48s %10.2fx\n", e[k].port, e[k].what, last_min_[k] / last_min_[4]);
    }
    /* the rasterizer's frame (shading pass only), every path on the auto port */
    rg_ = rs_render(quick ? 96 : 480, quick ? 64 : 320);
    printf("# rasterizer %dx%d, %d shaded pixels, %d lights: M%s per frame (shading pass only), min and median\n",
           rg_->w, rg_->h, rg_->n, rg_->n_lights, cyc_unit());
    {
        const char *pn = facet_port_name();
        entry e[] = {
            { pn, "raster: scalar inline (RGB kernel per pixel)", r_scalar, 1e6 },
            { pn, "raster: batch, 3 brdf_hammon calls per light", r_batch, 1e6 },
            { pn, "raster: RGB batch, 1 call per light", r_rgb, 1e6 },
            { pn, "raster: RGB batch, uniform material per run", r_material, 1e6 },
            { pn, "raster: per pixel, shade_hammon_rgb_f32", r_pixel, 1e6 },
            { pn, "raster: AVX2 inline (8 px, RGB kernel)", r_avx2, 1e6 },
        };
        int ne = rs_shade_avx2(rg_) ? 6 : 5;
        run_entries(e, ne, quick ? 3 : 41, "  M per frame");
    }
    rs_free(rg_);
    sink_ = oi[0] + op[0][0] + (float)qo[0][0];
    (void)smp_inputs;
    return 0;
}
