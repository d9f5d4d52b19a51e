/* data.h - what the report reads, in one place.
 *
 * The measured set: this run's bench rows (harness/bench.c), the clock it
 * measured with, and every timing a section takes itself (the
 * rasterizer's frames).  A measuring run records it to OUTDIR/measured.tsv;
 * `facet-bench report OUTDIR --replay FILE` renders the report from a
 * recorded set instead of measuring, so two renderings of one set can be
 * compared byte for byte (everything else the report shows is computed
 * from the library and the oracles, deterministically on one machine).
 *
 * The tables bench/report/report.sh leaves in OUTDIR: mca.tsv (llvm-mca
 * cycles per sample of each port's batch loop), size.tsv (bytes of each
 * batch function), arm.tsv (Cortex-M figures, bench/cortexm/cortexm.sh),
 * arm_vec.tsv and arm_vec.status (the NEON and Helium ports' costs,
 * arm_targets.sh).  And the RTL port's committed cost (ports/rtl/cost.tsv).
 * A missing table reads as empty. */
#ifndef FACET_REPORT_DATA_H
#define FACET_REPORT_DATA_H

#include <stddef.h>
#include "harness/bench.h"
#include "harness/cycles.h"
#include "harness/speed.h"

/* a bench row that owns its strings */
typedef struct data_row {
    bench_row r;
    char kernel[32], format[16], port[32], path[16], note[160];
} data_row;

/* the clock of the measuring run (cycles.h) */
typedef struct data_clock {
    char source[16], unit[16];
    int is_cycles, cpu;
    double tpc; /* ticks per core cycle */
} data_clock;

/* a row of a .tsv: three names and a value (and a source), or with a
 * leading format column (mca.tsv, arm_vec.tsv) four names */
typedef struct data_tsv {
    char f[32], a[32], b[32], c[32];
    double v;
    char src[64];
} data_tsv;

typedef struct data_timing {
    char key[48];
    cyc_stat s;
} data_timing;

/* a row of the RTL port's cost (ports/rtl/cost.tsv, the format in
 * ports/rtl/README.md; made by `make rtl`, committed, so the report needs
 * no synthesis run); -1 for a figure the row does not have ("-") */
typedef struct data_rtl {
    char module[32], device[32];
    double latency, cells, gate_eq, depth, luts, dsps, fmax_mhz, lcs, ebr, ffs, luts_no_dsp;
} data_rtl;

/* a row of the interleaved speed run (harness/speed.h) that owns its strings */
typedef struct data_speed {
    char kernel[32], port[32], tier[16], width[16];
    double min, median, err, err_peak;
} data_speed;

typedef struct report_data {
    const char *outdir;
    int quick, replayed;
    data_clock clock;
    data_row *rows;
    int n_rows, cap_rows;
    data_timing *timings;
    int n_timings, cap_timings;
    /* the interleaved speed run (speed_run): its rows, rounds and samples
     * per pass (0: none in this set) */
    data_speed *speed;
    int n_speed, cap_speed, speed_rounds;
    long speed_n;
    data_tsv *mca, *sizes, *arm, *armvec;
    int n_mca, n_sizes, n_arm, n_armvec;
    data_rtl *rtl;
    int n_rtl;
    char rtl_path[1024]; /* the cost file read (or looked for), as the report names it (no OUTDIR) */
} report_data;

/* Reads OUTDIR's tables; with replay (a measured.tsv path) also the
 * measured set and its quick flag.  Returns 0, or -1 if replay cannot be
 * read. */
int data_open(report_data *d, const char *outdir, const char *replay);
/* this run's clock (after cyc_init), when measuring */
void data_set_clock(report_data *d);
/* a bench_run sink: keeps a copy of the row */
void data_add_row(const bench_row *r, void *report_data_ptr);
/* a speed_run sink: keeps a copy of the row (set speed_rounds and speed_n
 * beside it) */
void data_add_speed(const speed_row *r, void *report_data_ptr);
/* the speed row of (kernel, port or peer, tier), or NULL */
const data_speed *data_speed_of(const report_data *d, const char *kernel, const char *port, const char *tier);
/* Writes the measured set to path; 0 on success. */
int data_save(const report_data *d, const char *path);
void data_close(report_data *d);

/* A timing by key: measured now (cyc_measure) and kept for the record,
 * or, when replaying, the recorded one (a key the set lacks: all zero). */
cyc_stat data_timing_of(report_data *d, const char *key, cyc_work fn, void *ctx, long reps, double units_per_rep,
                        int epochs);

/* ---- lookups ---------------------------------------------------------------- */

/* the row of (kernel or sampler, format, port, path), or NULL */
const bench_row *data_row_of(const report_data *d, const char *kernel, const char *format, const char *port,
                             const char *path);
/* the lowest-median f32 batch row of a kernel, any port, or NULL */
const bench_row *data_best_batch(const report_data *d, const char *kernel);
/* the lowest-median row of a kernel on a peer path ("peer": the kernel's own
 * formula; "peer-vectors": the exact-Vis BRDF), any peer, or NULL */
const bench_row *data_best_peer(const report_data *d, const char *kernel, const char *path);
/* clock units to est. core cycles */
double data_est(const report_data *d, double ticks);

/* mca.tsv: format port kernel cpu cycles_per_sample; -1 if absent (only
 * the f32 tiers' batch loops are modelled) */
double data_mca(const report_data *d, const char *format, const char *port, const char *kernel, const char *cpu);
/* size.tsv: format port kernel bytes; -1 if absent */
double data_size(const report_data *d, const char *format, const char *port, const char *kernel);
/* arm.tsv: what (fx-mca, f32soft-insns, ...) kernel cpu value; -1 if absent */
double data_arm(const report_data *d, const char *what, const char *kernel, const char *cpu);
/* arm_vec.tsv: format port kernel measure value; -1 if absent */
double data_armvec(const report_data *d, const char *format, const char *port, const char *kernel,
                   const char *measure);
/* the RTL cost: OUTDIR/rtl_cost.tsv if there is one (a fixture), else the
 * committed ports/rtl/cost.tsv (the report runs from the tree's root); the
 * row of kernel, or NULL */
const data_rtl *data_rtl_of(const report_data *d, const char *kernel);
/* arm_vec.status: "PORT ok HOW" or "PORT skipped WHY": the line for port
 * (without the port's name) into b, or why there is none; 1 if ok.  A
 * port's binary16 table has its own line, port "PORT-f16" ("ok the TABLE
 * table, HOW"). */
int data_armvec_status(const report_data *d, const char *port, char *b, size_t n);

/* src/core/ports.def's f16 column: the binary16 table that port's line
 * runs in this build (the line whose guard holds here), "scalar" where the
 * line has no f16 code of its own, NULL for a port not compiled in */
const char *data_f16_table(const char *port);
/* every line of ports.def, guards ignored: its port and its f16 table,
 * at most max; returns the count */
int data_f16_lines(const char **ports, const char **tables, int max);

#endif
