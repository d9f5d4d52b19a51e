/* sec_image.c - image-space error: what a pixel shows (image_error.c renders). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "facet.h"
#include "facet/f16.h"
#include "image_error.h"
#include "data.h"
#include "report.h"

static const char *img_cell(char *b, size_t n, const img_err *e)
{
    return report_fmt(b, n, "%.0f / %.0f / %.3f (%.2f)", e->max_code, e->p99_code, e->mean_code, e->max_de);
}

/* every variant of the menu in image space: implementation and model error */
static void section_image_variants(report *r)
{
    int nmax = img_variant_count(), n, i, j;
    img_variant *v = calloc((size_t)nmax, sizeof *v);
    pic diff;
    char port[32];
    clock_t ts = clock();
    report_say("image-space error: the menu's variants ...");
    n = img_variants_run(v, nmax, &diff, port, sizeof port);
    report_say("image-space error: %d variants in %.1f s CPU", n, (double)(clock() - ts) / CLOCKS_PER_SEC);
    doc_heading(r->doc, 3, "The menu's variants in image space");
    doc_para(r->doc, "The same spheres with a BRDF assembled as D * Vis * F + diffuse from double oracles (GGX D, exact "
         "height-correlated Smith Vis, Schlick F with V.H, Hammon's diffuse), except the part the variant "
         "computes (a G1 gives Vis = G1(N.L) G1(N.V) / (4 N.L N.V), with Beckmann's D for the Beckmann G1s "
         "and GTR's at the same gamma for smith_g1_gtr; a G2 gives Vis = G2 / (4 N.L N.V)). Implementation "
         "error: the kernel's render against the render from its own double oracle at the same float inputs "
         "(f32 and f32_fast: batch on %s, the best port of this CPU; fx and fx_fast where the kernel has them: "
         "the inputs rounded to Q15, so input rounding is included). Model error: the variant's oracle render "
         "against the reference's (G and Vis: the exact height-correlated Smith Vis; Beckmann G1: the exact "
         "Beckmann G1; smith_g1_gtr: the exact GTR G1 by quadrature; Fresnel: the exact dielectric Fresnel from "
         "f0; gtr_d at gamma 2: GGX); '-': no reference (a model of its own) or no such format. Each cell: max "
         "/ p99 / mean code difference (8-bit sRGB, largest channel per pixel, lit pixels) and, in brackets, "
         "the max CIE76 delta E.", port);
    doc_table(r->doc, 8, "variant", "term", "f32", "f32_fast", "fx (Q15 dots)", "fx_fast (Q15 dots)", "model: against",
          "model error");
    for (i = 0; i < n; i++) {
        char b[6][64];
        const char *cells[8];
        cells[0] = v[i].name;
        cells[1] = v[i].term;
        for (j = 0; j < 4; j++)
            cells[2 + j] = v[i].have[j] ? img_cell(b[j], sizeof b[j], &v[i].impl[j]) : "-";
        cells[6] = v[i].reference[0] ? v[i].reference : "-";
        cells[7] = !v[i].has_model ? "-" : v[i].is_reference ? "0 (the reference)" : img_cell(b[4], sizeof b[4], &v[i].model);
        doc_row(r->doc, cells);
    }
    doc_table_end(r->doc);
    if (diff.ax.rows)
        report_picture(r, &diff, "image_variants_model.png");
    pic_free(&diff);
    free(v);
}

/* what a viewer sees: brdf_hammon's formats, tiers and ports in 8-bit sRGB */
/* the binary16 tables of the port list (src/core/ports.def's f16 column)
 * that this run has no row for, and why; and the ports without an f16
 * table of their own */
static void f16_not_run(char *b, size_t cap, const img_err *e, int n)
{
    const char *ports[32], *tabs[32];
    int nl = data_f16_lines(ports, tabs, 32), i, j, k;
    size_t len = 0;
    b[0] = 0;
    for (i = 0; i < nl; i++) {
        char name[64];
        int ran = 0, dup = 0;
        if (!strcmp(tabs[i], "scalar"))
            continue;
        for (j = 0; j < i; j++)
            dup |= !strcmp(tabs[j], tabs[i]);
        snprintf(name, sizeof name, "f16 %s ", tabs[i]);
        for (k = 0; k < n; k++)
            ran |= !strncmp(e[k].name, name, strlen(name));
        if (dup || ran)
            continue;
        len += (size_t)snprintf(b + len, len < cap ? cap - len : 0, "%s%s (the %s line) not run here: %s", len ? "; " : "",
                                tabs[i], ports[i],
                                facet_f16_port_refusal(tabs[i]) ? facet_f16_port_refusal(tabs[i])
                                : facet_f16_port_supported(tabs[i]) ? "this CPU runs it, but no port line selected it"
                                : "not in this build (another architecture's port: its suite runs it under qemu, tests/README.md)");
    }
    {
        int first = 1;
        for (i = 0; i < nl; i++) {
            int own = 0, dup = 0;
            if (strcmp(tabs[i], "scalar") || !strcmp(ports[i], "scalar"))
                continue;
            for (j = 0; j < nl; j++)
                own |= !strcmp(ports[j], ports[i]) && strcmp(tabs[j], "scalar");
            for (j = 0; j < i; j++)
                dup |= !strcmp(ports[j], ports[i]);
            if (own || dup)
                continue;
            len += (size_t)snprintf(b + len, len < cap ? cap - len : 0, "%s%s", first ? (len ? "; no f16 table of their own (their f16 batches run the scalar one): " : "no f16 table of their own (their f16 batches run the scalar one): ") : ", ", ports[i]);
            first = 0;
        }
    }
}

void section_image(report *r)
{
    img_err e[IMG_ERR_MAX];
    pic ref, diff;
    int n, i;
    char notrun[1024];
    report_say("image-space error: spheres in every format, tier and port ...");
    n = img_error_run(e, IMG_ERR_MAX, &ref, &diff);
    f16_not_run(notrun, sizeof notrun, e, n);
    doc_heading(r->doc, 2, "%s", "Image-space error: what a pixel shows");
    doc_para(r->doc, "Lit spheres (two materials x six alpha) rendered with each format, tier and port of brdf_hammon and "
         "compared with the same render from the double oracle, as 8-bit sRGB codes (radiance = BRDF N.L E, so "
         "the error is weighted by N.L as a pixel weights it; tone c / (1 + c) per channel so that highlights "
         "are not clipped) and as CIE76 colour differences (D65; delta E of 1 is about the smallest visible). "
         "f32 rows: the kernel's arithmetic only (reference at the same float dots). Fixed-point rows: the dots "
         "rounded to Q15 as a caller must, against the float reference, so input rounding is included. The "
         "model row: the exact-Vis BRDF against brdf_hammon, both as oracles (Hammon's Vis approximation in "
         "codes). Code differences: per pixel the largest of the three channels; p99 over the lit pixels. "
         "Binary16 rows (f16, facet_brdf_hammon_f16_batch on each f16 table this CPU runs): the dots, alpha, f0 "
         "and albedo rounded to binary16 (facet_f16_from_f32_batch) as a caller must, against the same float "
         "reference, so input rounding is included as for fixed point, over the spheres with alpha at or above "
         "the f16 floor 2^-7 = %g (the pixel counts say how many); for the best f16 table also its arithmetic "
         "alone (against the oracle at the same binary16 inputs, clamped to the f16 domain, as the f32 rows); "
         "beside them the f32 rows of the best port and both "
         "fixed-point tiers over the same spheres, and in the difference image the spheres below the floor are "
         "left blank. %s.", (double)FACET_F16_ALPHA_MIN, notrun[0] ? notrun : "Every f16 table of the port list ran");
    doc_table(r->doc, 9, "candidate", "against", "max code diff", "p99 code diff", "mean code diff", "pixels off",
          "mean dE76", "p99 dE76", "max dE76");
    for (i = 0; i < n; i++) {
        char b[8][32];
        const char *cells[9];
        cells[0] = e[i].name;
        cells[1] = e[i].against;
        cells[2] = report_fmt(b[0], sizeof b[0], "%.0f", e[i].max_code);
        cells[3] = report_fmt(b[1], sizeof b[1], "%.0f", e[i].p99_code);
        cells[4] = report_fmt(b[2], sizeof b[2], "%.3f", e[i].mean_code);
        cells[5] = report_fmt(b[3], sizeof b[3], "%.2f%% of %ld", 100 * e[i].frac_diff, e[i].pixels);
        cells[6] = report_fmt(b[4], sizeof b[4], "%.3f", e[i].mean_de);
        cells[7] = report_fmt(b[5], sizeof b[5], "%.2f", e[i].p99_de);
        cells[8] = report_fmt(b[6], sizeof b[6], "%.2f", e[i].max_de);
        doc_row(r->doc, cells);
    }
    doc_table_end(r->doc);
    report_picture(r, &ref, "image_reference.png");
    report_picture(r, &diff, "image_difference.png");
    pic_free(&ref);
    pic_free(&diff);
    section_image_variants(r);
}

