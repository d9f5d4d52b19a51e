/* samplers.h - the importance-sampling section of the report (samplers.c). */
#ifndef FACET_BENCH_SAMPLERS_H
#define FACET_BENCH_SAMPLERS_H

#include <stdio.h>
#include "data.h"

/* Writes the section to md (Markdown) and html: the samplers' cost table
 * from the bench rows (d: the measured set), the picture
 * (OUTDIR/sampling.svg, 10^6 samples per panel, 10^5 when quick) and the
 * chi-square table read from OUTDIR/sample_chi2.txt. */
void report_samplers(FILE *md, FILE *html, const report_data *d);

#endif
