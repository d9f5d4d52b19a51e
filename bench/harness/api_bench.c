/* api_bench.c - `facet-bench api`: the entry points a renderer chooses
 * between, timed in one run on this machine (issue 15):
 *   - RGB: three brdf_hammon batches vs one RGB batch (planar, interleaved),
 *   - uniform material vs per-sample arrays (the same values),
 *   - per pixel: one sample per call through the library's scalar call,
 *     the vector entry, and the dispatched batch with n = 1,
 *   - fixed point: the RGB kernel vs three brdf_hammon_fx calls.
 * Per port this CPU runs (the batch forms follow facet_set_port), both f32
 * tiers where it matters.  Unit: the clock's (cyc_unit(): ticks on a VM
 * without a PMU), per RGB sample; min and median over >= 11 epochs. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "facet.h"
#include "facet/fx.h"
#include "tests/sample.h"
#include "cycles.h"
#include "facet_bench.h"
#include "raster/raster.h"

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

static void work_(void *ctx, long reps) { ((void (*)(long))ctx)(reps); }

/* the rasterizer's shading pass (bench/raster), one frame per rep */
static rs_gbuf *rg_;
static void r_scalar(long reps) { long r; for (r = 0; r < reps; r++) rs_shade_scalar(rg_); }
static void r_avx2(long reps) { long r; for (r = 0; r < reps; r++) rs_shade_avx2(rg_); }
static void r_batch(long reps) { long r; for (r = 0; r < reps; r++) rs_shade_batch(rg_); }
static void r_rgb(long reps) { long r; for (r = 0; r < reps; r++) rs_shade_rgb(rg_); }
static void r_material(long reps) { long r; for (r = 0; r < reps; r++) rs_shade_material(rg_); }
static void r_pixel(long reps) { long r; for (r = 0; r < reps; r++) rs_shade_pixel(rg_); }

static void measure_frame(const char *what, void (*fn)(long), int quick)
{
    cyc_stat s = cyc_measure(work_, (void *)fn, 1, 1, quick ? 11 : 11);
    printf("%-8s %-44s %9.3f %9.3f %6.1f%%%s  (%.1f / %.1f per shaded pixel)\n", facet_port_name(), what,
           s.min / 1e6, s.median / 1e6, 100 * s.spread, s.noisy ? "!" : "", s.min / rg_->n,
           s.median / rg_->n);
}

static void measure(const char *port, const char *what, void (*fn)(long), int quick)
{
    long reps = quick ? 1 : cyc_calibrate_reps(work_, (void *)fn, 2e6);
    cyc_stat s = cyc_measure(work_, (void *)fn, reps, N, quick ? 11 : 21);
    printf("%-8s %-44s %9.2f %9.2f %6.1f%%%s\n", port, what, s.min, s.median, 100 * s.spread,
           s.noisy ? "!" : "");
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
    printf("# facet-bench api: %s per RGB sample (clock %s; %s), N = %d, one run\n", cyc_unit(), cyc_source(),
           cyc_is_cycles() ? "core cycles" : "not core cycles", N);
    printf("%-8s %-44s %9s %9s %7s\n", "port", "entry point", "min", "median", "spread");
    for (pi = 0; pi < facet_port_count(); pi++) {
        int sup;
        const char *pn = facet_port_at(pi, &sup, NULL);
        if (!sup)
            continue;
        facet_set_port(pn);
        measure(pn, "brdf_hammon_f32_batch x 3 channels", mono3, quick);
        measure(pn, "brdf_hammon_rgb_f32_batch (planar arrays)", rgb_planar, quick);
        measure(pn, "brdf_hammon_rgb_f32_batch_interleaved", rgb_interleaved, quick);
        measure(pn, "brdf_hammon_rgb_f32_batch_material (uniform)", rgb_material, quick);
        measure(pn, "brdf_hammon_rgb_f32_batch_material_interleaved", rgb_material_interleaved, quick);
        measure(pn, "brdf_hammon_rgb_f32_fast_batch (planar arrays)", rgb_fast_planar, quick);
        measure(pn, "brdf_hammon_rgb_f32_fast_batch_material", rgb_fast_material, quick);
        measure(pn, "per pixel: ..._batch_material_interleaved n=1", pp_batch1, quick);
    }
    facet_set_port("auto");
    measure("scalar", "per pixel: brdf_hammon_rgb_f32 (call)", pp_scalar_call, quick);
    measure("scalar", "per pixel: shade_hammon_rgb_f32 (N, L, V)", pp_shade, quick);
    measure("scalar", "fx: brdf_hammon_fx x 3 channels", fx_mono3, quick);
    measure("scalar", "fx: brdf_hammon_rgb_fx_batch", fx_rgb, quick);
    measure("scalar", "fx_fast: brdf_hammon_fx_fast x 3 channels", fx_fast_mono3, quick);
    measure("scalar", "fx_fast: brdf_hammon_rgb_fx_fast_batch", fx_fast_rgb, quick);
    /* the rasterizer's frame (shading pass only), every path on the auto port */
    rg_ = rs_render(quick ? 96 : 480, quick ? 64 : 320);
    printf("# rasterizer %dx%d, %d shaded pixels, %d lights: M%s per frame (shading pass), min and median\n",
           rg_->w, rg_->h, rg_->n, rg_->n_lights, cyc_unit());
    measure_frame("raster: scalar inline (RGB kernel per pixel)", r_scalar, quick);
    if (rs_shade_avx2(rg_))
        measure_frame("raster: AVX2 inline (8 px, RGB kernel)", r_avx2, quick);
    measure_frame("raster: batch, 3 brdf_hammon calls per light", r_batch, quick);
    measure_frame("raster: RGB batch, 1 call per light", r_rgb, quick);
    measure_frame("raster: RGB batch, uniform material per run", r_material, quick);
    measure_frame("raster: per pixel, shade_hammon_rgb_f32", r_pixel, quick);
    rs_free(rg_);
    sink_ = oi[0] + op[0][0] + (float)qo[0][0];
    (void)smp_inputs;
    return 0;
}
