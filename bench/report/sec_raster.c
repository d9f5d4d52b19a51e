/* sec_raster.c - the software rasterizer (bench/raster/): the cost and the error of every
 * shading path. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "png.h"
#include "image_error.h"
#include "raster/raster.h"
#include "report.h"

typedef struct shade_ctx { rs_gbuf *g; int path; } shade_ctx;

static int shade(rs_gbuf *g, int path)
{
    switch (path) {
    case 0: rs_shade_scalar(g); return 1;
    case 1: return rs_shade_avx2(g);
    case 2: return rs_shade_sse2(g);
    case 3: rs_shade_batch(g); return 1;
    case 4: return rs_shade_neon(g);
    case 5: return rs_shade_fx(g);
    case 6: rs_shade_rgb(g); return 1;
    case 7: rs_shade_material(g); return 1;
    default: rs_shade_pixel(g); return 1;
    }
}

static void shade_work(void *ctx, long reps)
{
    shade_ctx *c = ctx;
    long r;
    for (r = 0; r < reps; r++)
        shade(c->g, c->path);
}

void section_raster(report *r)
{
    report_data *D = r->data;
    static const char *names[9] = { "scalar inline", "AVX2 inline (8 px)", "SSE2 inline (4 px)",
                                    "batch (deferred, 3 calls per light)", "NEON inline (4 px)", "fixed point",
                                    "RGB batch (deferred, 1 call per light)",
                                    "RGB batch, uniform material per run", "per pixel: shade_hammon_rgb_f32 (N, L, V)" };
    static const char *files[9] = { "raster_scalar.png", "raster_avx2.png", "raster_sse2.png",
                                    "raster_batch.png", "raster_neon.png", "raster_fx.png",
                                    "raster_rgb.png", "raster_material.png", "raster_pixel.png" };
    int W = r->quick ? 96 : 480, H = r->quick ? 64 : 320, p;
    rs_gbuf *g;
    unsigned char *ref, *img;
    size_t np;
    char b[10][64];
    pic pp = { 0 };
    report_say("rasterizer: %dx%d ...", W, H);
    g = rs_render(W, H);
    np = (size_t)W * (size_t)H * 3;
    ref = malloc(np);
    img = malloc(np);
    rs_shade_oracle(g);
    rs_to_srgb(g, ref);
    doc_heading(r->doc, 2, "%s", "Software rasterizer");
    doc_para(r->doc, "%dx%d, %ld front-facing triangles rasterized (perspective, z-buffer, perspective-correct "
         "normals and positions), %d shaded pixels, %d lights (directional + point), RGB: %d BRDF "
         "evaluations per pixel. Cost of the shading pass only (dots from the interpolated normal, view "
         "and light vectors, BRDF, accumulation), measured like the kernels (R vs 2R frames, >= 11 epochs). "
         "Difference: 8-bit sRGB against the same frame shaded by the double oracle, over shaded pixels "
         "(max and mean per channel; p99 of each pixel's largest channel difference; CIE76 delta E).",
         W, H, g->triangles, g->n, g->n_lights, 3 * g->n_lights);
    doc_table(r->doc, 10, "path", "ticks/pixel", "est. cyc/pixel", "est. cyc/BRDF eval", "spread", "max diff", "mean diff",
          "p99 diff", "mean dE76", "max dE76");
    for (p = 0; p < 9; p++) {
        shade_ctx c;
        cyc_stat s;
        long reps;
        int maxd;
        double meand, per_eval;
        const char *cells[10];
        img_err ie;
        c.g = g;
        c.path = p;
        if (!shade(g, p)) {
            cells[0] = names[p];
            cells[1] = cells[2] = cells[3] = cells[4] = cells[5] = cells[6] = cells[7] = cells[8] = cells[9] = "n/a";
            doc_row(r->doc, cells);
            continue;
        }
        rs_to_srgb(g, img);
        rs_diff(g, ref, img, &maxd, &meand);
        img_compare_rgb8(&ie, img, ref, g->idx, g->n);
        reps = 1;
        s = data_timing_of(D, files[p], shade_work, &c, reps, (double)g->n, 11);
        per_eval = data_est(D, s.median) / (3.0 * g->n_lights);
        if (p == 1)
            r->raster_avx2_per_eval = per_eval;
        if (p == 3)
            r->raster_batch_per_eval = per_eval;
        cells[0] = names[p];
        cells[1] = report_fmt(b[0], sizeof b[0], "%.1f", s.median);
        cells[2] = report_fmt(b[1], sizeof b[1], "%.1f", data_est(D, s.median));
        cells[3] = report_fmt(b[2], sizeof b[2], "%.2f", per_eval);
        cells[4] = report_fmt(b[3], sizeof b[3], "%.1f%%%s", 100 * s.spread, s.noisy ? " !" : "");
        cells[5] = report_fmt(b[4], sizeof b[4], "%d", maxd);
        cells[6] = report_fmt(b[5], sizeof b[5], "%.4f", meand);
        cells[7] = report_fmt(b[6], sizeof b[6], "%.0f", ie.p99_code);
        cells[8] = report_fmt(b[7], sizeof b[7], "%.4f", ie.mean_de);
        cells[9] = report_fmt(b[8], sizeof b[8], "%.2f", ie.max_de);
        doc_row(r->doc, cells);
        {
            char path[1024];
            snprintf(path, sizeof path, "%s/%s", r->outdir, files[p]);
            png_write(path, img, W, H);
        }
    }
    doc_table_end(r->doc);
    pp.w = W;
    pp.h = H;
    pp.rgb = ref;
    snprintf(pp.title, sizeof pp.title, "Rasterizer, oracle-shaded reference");
    snprintf(pp.caption, sizeof pp.caption, "Spheres across alpha (0.02 copper, 0.08 red plastic, 0.2 gold, 0.45 blue plastic, 0.9 clay) on a rippled floor mesh (alpha 0.3); directional light from the upper left and a bluish point light on the right. The facet-shaded frames (raster_*.png) differ from it by at most the 'max diff' above.");
    report_picture(r, &pp, "raster_oracle.png");
    if (!shade(g, 1))
        shade(g, 0);
    rs_to_srgb(g, img);
    pp.rgb = img;
    snprintf(pp.title, sizeof pp.title, "Rasterizer, shaded with facet (AVX2 inline where available)");
    snprintf(pp.caption, sizeof pp.caption, "The same frame shaded with facet_brdf_hammon_f32_avx2, 8 pixels per call.");
    report_picture(r, &pp, "raster_facet.png");
    free(ref);
    free(img);
    rs_free(g);
}

