/* report.h - what every section of `facet-bench report` shares: the run
 * (its measured set, its document, where it writes), a few formatting
 * helpers, and the sections themselves, one unit each (sec_*.c), called in
 * the order report.c lists them.  A section reads the data (data.h),
 * writes to the document (doc.h) and draws its figures with the SVG
 * module (svg.h); it knows nothing of Markdown or HTML. */
#ifndef FACET_REPORT_H
#define FACET_REPORT_H

#include <stddef.h>
#include "data.h"
#include "doc.h"
#include "pictures.h"

typedef struct report {
    report_data *data; /* the measured set and report.sh's tables */
    doc *doc;          /* bench.md and bench.html */
    const char *outdir;
    int quick;
    /* what one section leaves for a later one: the rasterizer's cost per
     * BRDF evaluation, est. cycles (-1: not measured), for the targets */
    double raster_avx2_per_eval, raster_batch_per_eval;
} report;

/* progress on stderr: "report: ..." */
void report_say(const char *fmt, ...);
/* printf into b; returns b */
char *report_fmt(char *b, size_t n, const char *fmt, ...);
/* %.3g, and "nan" / "inf" (b: at least 32 bytes) */
const char *report_g3(char *b, double x);
/* a picture: the PNG written to OUTDIR/file and shown as a figure (its
 * labels drawn around it where the picture describes its panels) */
void report_picture(const report *r, const pic *p, const char *file);
/* an SVG figure (markup: the svg_end text, freed here) with its title and
 * caption; Markdown shows none of it */
void report_svg_figure(const report *r, char *markup, const char *title, const char *caption);

/* ---- the sections (sec_*.c) ----------------------------------------------- */
void section_choose(report *r);     /* which one to use: the chooser */
void section_clock(report *r);      /* clock and method */
void section_pareto(report *r);     /* error vs cycles per term */
void section_image(report *r);      /* image-space error (image_error.c) */
void section_furnace(report *r);    /* white furnace of the diffuse models */
void section_model(report *r);      /* model error of every approximation */
void section_pictures(report *r);   /* BRDF slices, spheres, heat maps */
void section_samplers(report *r);   /* importance sampling */
void section_arm(report *r);        /* Cortex-M figures */
void section_wcet(report *r);       /* Cortex-M execution time per call (fx.h's table) */
void section_rtl(report *r);        /* the RTL port: cells, depth, iCE40 LUTs and clock */
void section_raster(report *r);     /* the software rasterizer */
void section_targets(report *r);    /* the targets, met or not */
void section_speed(report *r);      /* both f32 tiers vs the same-formula peers, interleaved; the vector ports' tiers */
void section_kernels(report *r);    /* every kernel x format x port: error and cost */

#endif
