/* fxhook.h - the fixed-point kernels (facet/fx.h) as benchmark loops on
 * float SoA data: inputs converted to the fx format outside... see fxhook.c.
 * bench_fx_find() returns NULL for a kernel without an fx version (or when
 * this build has no facet/fx.h). */
#ifndef FACET_BENCH_FXHOOK_H
#define FACET_BENCH_FXHOOK_H

#include "loops.h"

typedef struct bench_fx {
    const char *kernel;
    bench_fn thr;      /* float in, float out, through the fx kernel */
    bench_fn chain;    /* dependent chain, or NULL */
    double bound;      /* the fx bound from facet/fx.h (0: none stated) */
} bench_fx;

const bench_fx *bench_fx_find(const char *kernel);
int bench_fx_available(void);

#endif
