/* samplers.h - the importance-sampling section of the report (samplers.c). */
#ifndef FACET_BENCH_SAMPLERS_H
#define FACET_BENCH_SAMPLERS_H

#include <stdio.h>
#include "harness/bench.h"

/* the bench row of (kernel or sampler, format, port, path), or NULL */
typedef const bench_row *(*report_find_fn)(const char *kernel, const char *format, const char *port,
                                           const char *path);

/* Writes the section to md (Markdown) and html: the samplers' cost table
 * from the bench rows (tpc: ticks per core cycle), the picture
 * (OUTDIR/sampling.svg, 10^6 samples per panel, 10^5 when quick) and the
 * chi-square table read from OUTDIR/sample_chi2.txt. */
void report_samplers(FILE *md, FILE *html, const char *outdir, int quick, report_find_fn find, double tpc);

#endif
