/* data.c - see data.h.
 *
 * measured.tsv, one record a line, fields separated by tabs (doubles as
 * %.17g and floats as %.9g, so that a replay reads back the same bits):
 *   quick   Q
 *   clock   source unit is_cycles cpu ticks_per_cycle
 *   row     kernel format port path note n_inputs lanes  err: max_rel
 *           mean_rel max_rel_vis arg[0..5] got want n has_lsb max_lsb
 *           mean_lsb big_rel n_lsb  bound within  thr: min median max
 *           spread epochs noisy  has_lat  lat: (the same six)
 *   timing  key  min median max spread epochs noisy
 *   speedrun  rounds samples_per_pass
 *   speed   kernel port tier width min median err err_peak */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "data.h"
#include "src/core/platform.h"

#define MAX_FIELDS 64

static void *grow(void *p, int *cap, int n, size_t size)
{
    if (n < *cap)
        return p;
    *cap = *cap ? 2 * *cap : 64;
    p = realloc(p, (size_t)*cap * size);
    if (!p) {
        fprintf(stderr, "facet-bench report: out of memory\n");
        exit(1);
    }
    return p;
}

/* ---- report.sh's tables ------------------------------------------------------ */

static data_tsv *read_tsv(const char *outdir, const char *name, int *n, int with_format)
{
    char path[1024], line[512];
    FILE *f;
    data_tsv *t = NULL;
    int cap = 0;
    *n = 0;
    snprintf(path, sizeof path, "%s/%s", outdir, name);
    f = fopen(path, "r");
    if (!f)
        return NULL;
    while (fgets(line, sizeof line, f)) {
        data_tsv x;
        memset(&x, 0, sizeof x);
        if (line[0] == '#')
            continue;
        if (with_format ? sscanf(line, "%31s %31s %31s %31s %lf", x.f, x.a, x.b, x.c, &x.v) < 5
                        : sscanf(line, "%31s %31s %31s %lf %63s", x.a, x.b, x.c, &x.v, x.src) < 4)
            continue;
        t = grow(t, &cap, *n, sizeof *t);
        t[(*n)++] = x;
    }
    fclose(f);
    return t;
}

double data_mca(const report_data *d, const char *format, const char *port, const char *kernel, const char *cpu)
{
    int i;
    for (i = 0; i < d->n_mca; i++)
        if (!strcmp(d->mca[i].f, format) && !strcmp(d->mca[i].a, port) && !strcmp(d->mca[i].b, kernel) &&
            !strcmp(d->mca[i].c, cpu))
            return d->mca[i].v;
    return -1;
}

double data_size(const report_data *d, const char *format, const char *port, const char *kernel)
{
    int i;
    for (i = 0; i < d->n_sizes; i++)
        if (!strcmp(d->sizes[i].a, format) && !strcmp(d->sizes[i].b, port) && !strcmp(d->sizes[i].c, kernel))
            return d->sizes[i].v;
    return -1;
}

double data_arm(const report_data *d, const char *what, const char *kernel, const char *cpu)
{
    int i;
    for (i = 0; i < d->n_arm; i++)
        if (!strcmp(d->arm[i].a, what) && !strcmp(d->arm[i].b, kernel) && !strcmp(d->arm[i].c, cpu))
            return d->arm[i].v;
    return -1;
}

double data_armvec(const report_data *d, const char *format, const char *port, const char *kernel,
                   const char *measure)
{
    int i;
    for (i = 0; i < d->n_armvec; i++)
        if (!strcmp(d->armvec[i].f, format) && !strcmp(d->armvec[i].a, port) && !strcmp(d->armvec[i].b, kernel) &&
            !strcmp(d->armvec[i].c, measure))
            return d->armvec[i].v;
    return -1;
}

int data_armvec_status(const report_data *d, const char *port, char *b, size_t n)
{
    char path[1024], line[512];
    size_t k = strlen(port);
    FILE *f;
    snprintf(path, sizeof path, "%s/arm_vec.status", d->outdir);
    f = fopen(path, "r");
    snprintf(b, n, "skipped: no arm_vec.status (a facet-bench report run without bench/report/report.sh, "
                   "which runs bench/report/arm_targets.sh)");
    if (!f)
        return 0;
    while (fgets(line, sizeof line, f))
        if (!strncmp(line, port, k) && line[k] == ' ') {
            line[strcspn(line, "\n")] = 0;
            snprintf(b, n, "%s", line + k + 1);
            fclose(f);
            return !strncmp(line + k + 1, "ok", 2);
        }
    fclose(f);
    return 0;
}

/* ---- the measured set -------------------------------------------------------- */

/* the rows' string pointers, to their own copies (the array moves as it grows) */
static void fix_rows(report_data *d)
{
    int i;
    for (i = 0; i < d->n_rows; i++) {
        data_row *x = &d->rows[i];
        x->r.kernel = x->kernel;
        x->r.format = x->format;
        x->r.port = x->port;
        x->r.path = x->path;
        x->r.note = x->note;
    }
}

void data_add_row(const bench_row *r, void *ctx)
{
    report_data *d = ctx;
    data_row *x;
    d->rows = grow(d->rows, &d->cap_rows, d->n_rows, sizeof *d->rows);
    x = &d->rows[d->n_rows++];
    x->r = *r;
    snprintf(x->kernel, sizeof x->kernel, "%s", r->kernel);
    snprintf(x->format, sizeof x->format, "%s", r->format);
    snprintf(x->port, sizeof x->port, "%s", r->port);
    snprintf(x->path, sizeof x->path, "%s", r->path);
    snprintf(x->note, sizeof x->note, "%s", r->note ? r->note : "");
    fix_rows(d);
}

void data_add_speed(const speed_row *r, void *ctx)
{
    report_data *d = ctx;
    data_speed *x;
    d->speed = grow(d->speed, &d->cap_speed, d->n_speed, sizeof *d->speed);
    x = &d->speed[d->n_speed++];
    snprintf(x->kernel, sizeof x->kernel, "%s", r->kernel);
    snprintf(x->port, sizeof x->port, "%s", r->port);
    snprintf(x->tier, sizeof x->tier, "%s", r->tier);
    snprintf(x->width, sizeof x->width, "%s", r->width);
    x->min = r->min, x->median = r->median, x->err = r->err, x->err_peak = r->err_peak;
}

const data_speed *data_speed_of(const report_data *d, const char *kernel, const char *port, const char *tier)
{
    int i;
    for (i = 0; i < d->n_speed; i++)
        if (!strcmp(d->speed[i].kernel, kernel) && !strcmp(d->speed[i].port, port) && !strcmp(d->speed[i].tier, tier))
            return &d->speed[i];
    return NULL;
}

void data_set_clock(report_data *d)
{
    snprintf(d->clock.source, sizeof d->clock.source, "%s", cyc_source());
    snprintf(d->clock.unit, sizeof d->clock.unit, "%s", cyc_unit());
    d->clock.is_cycles = cyc_is_cycles();
    d->clock.cpu = cyc_cpu();
    d->clock.tpc = cyc_ticks_per_cycle();
}

cyc_stat data_timing_of(report_data *d, const char *key, cyc_work fn, void *ctx, long reps, double units_per_rep,
                        int epochs)
{
    cyc_stat s;
    int i;
    if (d->replayed) {
        for (i = 0; i < d->n_timings; i++)
            if (!strcmp(d->timings[i].key, key))
                return d->timings[i].s;
        memset(&s, 0, sizeof s);
        return s;
    }
    s = cyc_measure(fn, ctx, reps, units_per_rep, epochs);
    d->timings = grow(d->timings, &d->cap_timings, d->n_timings, sizeof *d->timings);
    snprintf(d->timings[d->n_timings].key, sizeof d->timings[0].key, "%s", key);
    d->timings[d->n_timings++].s = s;
    return s;
}

static void put_stat(FILE *f, const cyc_stat *s)
{
    fprintf(f, "\t%.17g\t%.17g\t%.17g\t%.17g\t%d\t%d", s->min, s->median, s->max, s->spread, s->epochs, s->noisy);
}

int data_save(const report_data *d, const char *path)
{
    FILE *f = fopen(path, "w");
    int i, j;
    if (!f)
        return -1;
    fprintf(f, "# facet-bench report: the measured set (bench/report/data.c; replay: facet-bench report OUTDIR "
               "--replay FILE)\n");
    fprintf(f, "quick\t%d\n", d->quick);
    fprintf(f, "clock\t%s\t%s\t%d\t%d\t%.17g\n", d->clock.source, d->clock.unit, d->clock.is_cycles, d->clock.cpu,
            d->clock.tpc);
    for (i = 0; i < d->n_rows; i++) {
        const bench_row *r = &d->rows[i].r;
        const bench_err *e = &r->err;
        fprintf(f, "row\t%s\t%s\t%s\t%s\t%s\t%d\t%d", r->kernel, r->format, r->port, r->path, r->note ? r->note : "",
                r->n_inputs, r->lanes);
        fprintf(f, "\t%.17g\t%.17g\t%.17g", e->max_rel, e->mean_rel, e->max_rel_vis);
        for (j = 0; j < FACET_MAX_INPUTS; j++)
            fprintf(f, "\t%.9g", (double)e->arg[j]);
        fprintf(f, "\t%.17g\t%.17g\t%ld\t%d\t%.17g\t%.17g\t%.17g\t%ld", e->got, e->want, e->n, e->has_lsb, e->max_lsb,
                e->mean_lsb, e->big_rel, e->n_lsb);
        fprintf(f, "\t%.17g\t%d", r->bound, r->within);
        put_stat(f, &r->thr);
        fprintf(f, "\t%d", r->has_lat);
        put_stat(f, &r->lat);
        fputc('\n', f);
    }
    for (i = 0; i < d->n_timings; i++) {
        fprintf(f, "timing\t%s", d->timings[i].key);
        put_stat(f, &d->timings[i].s);
        fputc('\n', f);
    }
    if (d->n_speed)
        fprintf(f, "speedrun\t%d\t%ld\n", d->speed_rounds, d->speed_n);
    for (i = 0; i < d->n_speed; i++) {
        const data_speed *x = &d->speed[i];
        fprintf(f, "speed\t%s\t%s\t%s\t%s\t%.17g\t%.17g\t%.17g\t%.17g\n", x->kernel, x->port, x->tier, x->width,
                x->min, x->median, x->err, x->err_peak);
    }
    return fclose(f) ? -1 : 0;
}

/* splits line at tabs (in place); returns the field count */
static int split_tabs(char *line, char **fld, int max)
{
    int n = 0;
    line[strcspn(line, "\r\n")] = 0;
    while (n < max) {
        char *t = strchr(line, '\t');
        fld[n++] = line;
        if (!t)
            break;
        *t = 0;
        line = t + 1;
    }
    return n;
}

static void get_stat(char **f, cyc_stat *s)
{
    s->min = strtod(f[0], NULL);
    s->median = strtod(f[1], NULL);
    s->max = strtod(f[2], NULL);
    s->spread = strtod(f[3], NULL);
    s->epochs = atoi(f[4]);
    s->noisy = atoi(f[5]);
}

static int read_measured(report_data *d, const char *path)
{
    FILE *f = fopen(path, "r");
    char line[4096], *fld[MAX_FIELDS];
    int n, j, lineno = 0;
    if (!f) {
        fprintf(stderr, "facet-bench report: cannot read %s\n", path);
        return -1;
    }
    while (fgets(line, sizeof line, f)) {
        lineno++;
        if (line[0] == '#' || line[0] == '\n')
            continue;
        n = split_tabs(line, fld, MAX_FIELDS);
        if (!strcmp(fld[0], "quick") && n == 2) {
            d->quick = atoi(fld[1]);
        } else if (!strcmp(fld[0], "clock") && n == 6) {
            snprintf(d->clock.source, sizeof d->clock.source, "%s", fld[1]);
            snprintf(d->clock.unit, sizeof d->clock.unit, "%s", fld[2]);
            d->clock.is_cycles = atoi(fld[3]);
            d->clock.cpu = atoi(fld[4]);
            d->clock.tpc = strtod(fld[5], NULL);
        } else if (!strcmp(fld[0], "row") && n == 8 + 3 + FACET_MAX_INPUTS + 8 + 2 + 6 + 1 + 6) {
            bench_row r;
            char **p = fld + 8;
            memset(&r, 0, sizeof r);
            r.kernel = fld[1], r.format = fld[2], r.port = fld[3], r.path = fld[4], r.note = fld[5];
            r.n_inputs = atoi(fld[6]);
            r.lanes = atoi(fld[7]);
            r.err.max_rel = strtod(*p++, NULL);
            r.err.mean_rel = strtod(*p++, NULL);
            r.err.max_rel_vis = strtod(*p++, NULL);
            for (j = 0; j < FACET_MAX_INPUTS; j++)
                r.err.arg[j] = strtof(*p++, NULL);
            r.err.got = strtod(*p++, NULL);
            r.err.want = strtod(*p++, NULL);
            r.err.n = strtol(*p++, NULL, 10);
            r.err.has_lsb = atoi(*p++);
            r.err.max_lsb = strtod(*p++, NULL);
            r.err.mean_lsb = strtod(*p++, NULL);
            r.err.big_rel = strtod(*p++, NULL);
            r.err.n_lsb = strtol(*p++, NULL, 10);
            r.bound = strtod(*p++, NULL);
            r.within = atoi(*p++);
            get_stat(p, &r.thr);
            p += 6;
            r.has_lat = atoi(*p++);
            get_stat(p, &r.lat);
            data_add_row(&r, d);
        } else if (!strcmp(fld[0], "speedrun") && n == 3) {
            d->speed_rounds = atoi(fld[1]);
            d->speed_n = strtol(fld[2], NULL, 10);
        } else if (!strcmp(fld[0], "speed") && n == 9) {
            speed_row r;
            r.kernel = fld[1], r.port = fld[2], r.tier = fld[3], r.width = fld[4];
            r.min = strtod(fld[5], NULL);
            r.median = strtod(fld[6], NULL);
            r.err = strtod(fld[7], NULL);
            r.err_peak = strtod(fld[8], NULL);
            data_add_speed(&r, d);
        } else if (!strcmp(fld[0], "timing") && n == 8) {
            d->timings = grow(d->timings, &d->cap_timings, d->n_timings, sizeof *d->timings);
            snprintf(d->timings[d->n_timings].key, sizeof d->timings[0].key, "%s", fld[1]);
            get_stat(fld + 2, &d->timings[d->n_timings++].s);
        } else {
            fprintf(stderr, "facet-bench report: %s:%d: not a measured-set record\n", path, lineno);
            fclose(f);
            return -1;
        }
    }
    fclose(f);
    d->replayed = 1;
    return 0;
}

/* "-" (a figure the row lacks) reads as -1 */
static double rtl_num(const char *s) { return strcmp(s, "-") ? atof(s) : -1; }

/* ports/rtl/cost.tsv: a header line, then tab-separated module, latency,
 * cells, gate_equivalents, depth, luts, dsps, fmax_mhz, device, lcs, ebr,
 * ffs, luts_no_dsp */
static void read_rtl(report_data *d)
{
    char line[512];
    FILE *f;
    int cap = 0, lineno = 0;
    char path[1024];
    snprintf(path, sizeof path, "%s/rtl_cost.tsv", d->outdir);
    /* named without OUTDIR, so a replay elsewhere renders the same text */
    snprintf(d->rtl_path, sizeof d->rtl_path, "rtl_cost.tsv of the report's directory");
    f = fopen(path, "r");
    if (!f) {
        snprintf(d->rtl_path, sizeof d->rtl_path, "ports/rtl/cost.tsv");
        f = fopen(d->rtl_path, "r");
    }
    if (!f)
        return;
    while (fgets(line, sizeof line, f)) {
        char fld[13][32];
        data_rtl x;
        if (lineno++ == 0)
            continue; /* the header */
        if (sscanf(line, "%31s %31s %31s %31s %31s %31s %31s %31s %31s %31s %31s %31s %31s", fld[0], fld[1], fld[2],
                   fld[3], fld[4], fld[5], fld[6], fld[7], fld[8], fld[9], fld[10], fld[11], fld[12]) != 13) {
            fprintf(stderr, "facet-bench report: %s:%d: not a cost row (13 fields)\n", d->rtl_path, lineno);
            continue;
        }
        memset(&x, 0, sizeof x);
        snprintf(x.module, sizeof x.module, "%s", fld[0]);
        snprintf(x.device, sizeof x.device, "%s", fld[8]);
        x.latency = rtl_num(fld[1]), x.cells = rtl_num(fld[2]), x.gate_eq = rtl_num(fld[3]);
        x.depth = rtl_num(fld[4]), x.luts = rtl_num(fld[5]), x.dsps = rtl_num(fld[6]);
        x.fmax_mhz = rtl_num(fld[7]), x.lcs = rtl_num(fld[9]), x.ebr = rtl_num(fld[10]);
        x.ffs = rtl_num(fld[11]), x.luts_no_dsp = rtl_num(fld[12]);
        d->rtl = grow(d->rtl, &cap, d->n_rtl, sizeof *d->rtl);
        d->rtl[d->n_rtl++] = x;
    }
    fclose(f);
}

const data_rtl *data_rtl_of(const report_data *d, const char *kernel)
{
    int i;
    for (i = 0; i < d->n_rtl; i++)
        if (!strcmp(d->rtl[i].module, kernel))
            return &d->rtl[i];
    return NULL;
}

int data_open(report_data *d, const char *outdir, const char *replay)
{
    int quick = d->quick;
    memset(d, 0, sizeof *d);
    d->outdir = outdir;
    d->quick = quick;
    d->clock.tpc = 1.0;
    d->mca = read_tsv(outdir, "mca.tsv", &d->n_mca, 1);
    d->sizes = read_tsv(outdir, "size.tsv", &d->n_sizes, 0);
    d->arm = read_tsv(outdir, "arm.tsv", &d->n_arm, 0);
    d->armvec = read_tsv(outdir, "arm_vec.tsv", &d->n_armvec, 1);
    read_rtl(d);
    return replay ? read_measured(d, replay) : 0;
}

void data_close(report_data *d)
{
    free(d->speed), d->speed = NULL;
    free(d->rows), free(d->timings), free(d->mca), free(d->sizes), free(d->arm), free(d->armvec), free(d->rtl);
    d->rows = NULL, d->timings = NULL, d->mca = d->sizes = d->arm = d->armvec = NULL, d->rtl = NULL;
}

/* ---- lookups ------------------------------------------------------------------ */

const bench_row *data_row_of(const report_data *d, const char *kernel, const char *format, const char *port,
                             const char *path)
{
    int i;
    for (i = 0; i < d->n_rows; i++)
        if (!strcmp(d->rows[i].kernel, kernel) && !strcmp(d->rows[i].format, format) &&
            !strcmp(d->rows[i].port, port) && !strcmp(d->rows[i].path, path))
            return &d->rows[i].r;
    return NULL;
}

const bench_row *data_best_batch(const report_data *d, const char *kernel)
{
    const bench_row *b = NULL;
    int i;
    for (i = 0; i < d->n_rows; i++)
        if (!strcmp(d->rows[i].kernel, kernel) && !strcmp(d->rows[i].format, "f32") &&
            !strcmp(d->rows[i].path, "batch") && (!b || d->rows[i].r.thr.median < b->thr.median))
            b = &d->rows[i].r;
    return b;
}

const bench_row *data_best_peer(const report_data *d, const char *kernel, const char *path)
{
    const bench_row *b = NULL;
    int i;
    for (i = 0; i < d->n_rows; i++)
        if (!strcmp(d->rows[i].path, path) && !strcmp(d->rows[i].kernel, kernel) &&
            (!b || d->rows[i].r.thr.median < b->thr.median))
            b = &d->rows[i].r;
    return b;
}

double data_est(const report_data *d, double ticks) { return ticks / d->clock.tpc; }

/* ---- the port list's f16 column ------------------------------------------------ */

const char *data_f16_table(const char *port)
{
    static const char *const lines[][2] = {
#define FACET_PORT(name, guard, cpu, fx, fx_fast, f16, f16_cpu) FACET_PORT_IF(guard, { #name, #f16 },)
#include "src/core/ports.def"
#undef FACET_PORT
    };
    size_t i;
    for (i = 0; i < sizeof lines / sizeof lines[0]; i++)
        if (!strcmp(lines[i][0], port))
            return lines[i][1];
    return NULL;
}

int data_f16_lines(const char **ports, const char **tables, int max)
{
    static const char *const lines[][2] = {
#define FACET_PORT(name, guard, cpu, fx, fx_fast, f16, f16_cpu) { #name, #f16 },
#include "src/core/ports.def"
#undef FACET_PORT
    };
    int i, n = 0;
    for (i = 0; i < (int)(sizeof lines / sizeof lines[0]) && n < max; i++, n++) {
        ports[n] = lines[i][0];
        tables[n] = lines[i][1];
    }
    return n;
}
