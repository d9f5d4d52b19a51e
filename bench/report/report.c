/* report.c - `facet-bench report OUTDIR [--quick] [--replay MEASURED.tsv]`:
 * the benchmark part of `make report`.  Measures (bench/harness/: every
 * kernel x format x port x path and the peers) or replays a recorded set
 * (data.h), writes the sections in the order listed below into one
 * document rendered as OUTDIR/bench.md and OUTDIR/bench.html (doc.h), and
 * composes OUTDIR/report.md and the self-contained OUTDIR/index.html
 * (inline SVG, PNGs as data URIs) from them and the accuracy part
 * (accuracy.md, tests/report/report.sh).  The roles, one unit each:
 *   data.c          the measured set and report.sh's tables (mca.tsv, ...)
 *   kernel_facts.c  what the report knows of each kernel (terms, references)
 *   doc*.c          the document and its Markdown and HTML writers
 *   svg.c           every figure's axes, ticks, legends and labels
 *   sec_*.c         the sections
 *   image_error.c, pictures.c, png.c, geom.c: what the sections compute */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "facet.h"
#include "facet_bench.h"
#include "harness/bench.h"
#include "harness/cycles.h"
#include "kernel_facts.h"
#include "png.h"
#include "report.h"
#include "svg.h"

/* the sections, in the report's order: the summary first, the figures
 * next, the long tables last (the targets need the rasterizer's figures,
 * so they follow it) */
static const struct {
    const char *name;
    void (*write)(report *r);
} sections[] = {
    { "chooser", section_choose },
    { "clock", section_clock },
    { "pareto", section_pareto },
    { "image-space error", section_image },
    { "white furnace", section_furnace },
    { "model error", section_model },
    { "pictures", section_pictures },
    { "importance sampling", section_samplers },
    { "Cortex-M", section_arm },
    { "execution time", section_wcet },
    { "hardware", section_rtl },
    { "rasterizer", section_raster },
    { "targets", section_targets },
    { "speed", section_speed },
    { "kernels", section_kernels },
};

/* ---- helpers for the sections (report.h) ---------------------------------- */

void report_say(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("report: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
}

char *report_fmt(char *b, size_t n, const char *f, ...)
{
    va_list ap;
    va_start(ap, f);
    vsnprintf(b, n, f, ap);
    va_end(ap);
    return b;
}

const char *report_g3(char *b, double x)
{
    if (x != x)
        return strcpy(b, "nan");
    if (isinf(x))
        return strcpy(b, "inf");
    snprintf(b, 32, "%.3g", x);
    return b;
}

void report_picture(const report *r, const pic *p, const char *name)
{
    unsigned char *buf;
    size_t n = png_encode(&buf, p->rgb, p->w, p->h);
    char path[1024], *b64, *markup = NULL;
    doc_fig f;
    FILE *out;
    if (!n)
        return;
    snprintf(path, sizeof path, "%s/%s", r->outdir, name);
    out = fopen(path, "wb");
    if (out) {
        if (fwrite(buf, 1, n, out) != n)
            report_say("short write: %s", path);
        fclose(out);
    }
    b64 = png_base64(buf, n);
    if (p->ax.cols > 0)
        markup = svg_picture(p, b64);
    memset(&f, 0, sizeof f);
    f.title = p->title;
    f.caption = p->caption;
    f.svg = markup;
    f.png_b64 = b64;
    f.file = name;
    doc_figure(r->doc, &f);
    free(markup);
    free(b64);
    free(buf);
}

void report_svg_figure(const report *r, char *markup, const char *title, const char *caption)
{
    doc_fig f;
    memset(&f, 0, sizeof f);
    f.title = title;
    f.caption = caption;
    f.svg = markup;
    doc_figure(r->doc, &f);
    free(markup);
}

/* ---- report.md and index.html ------------------------------------------------ */

/* the heading of the bench part, in bench.md and index.html: a quick run
 * says so, since its figures come from a few samples */
#define BENCH_TITLE "Benchmarks (bench/)"
#define BENCH_QUICK_TITLE "Benchmarks (bench/), QUICK RUN"
#define BENCH_QUICK_NOTE "Quick run (<code>facet-bench report --quick</code>): few samples, short passes, " \
    "small pictures; these figures test the machinery and are not for comparison. <code>make report</code> " \
    "measures in full."

static int copy_file(const char *path, FILE *out)
{
    FILE *in = fopen(path, "r");
    int c;
    if (!in)
        return 0;
    while ((c = fgetc(in)) != EOF)
        fputc(c, out);
    fclose(in);
    return 1;
}

/* report.md and index.html are composed here, from accuracy.md (the part
 * tests/report/report.sh writes; absent in a bench-only run) and this run's bench
 * part, so a quick run after a full one replaces the bench part of both
 * rather than adding a second one beside the stale first. */
/* accuracy.md split at its first section: the head (title, machine, date)
 * opens the report, the accuracy tables close it (the long tables last) */
static char *read_all(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    char *b = NULL;
    long len;
    *n = 0;
    if (!f)
        return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (len = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0) {
        b = malloc((size_t)len + 1);
        if (b) {
            *n = fread(b, 1, (size_t)len, f);
            b[*n] = 0;
        }
    }
    fclose(f);
    return b;
}

static size_t accuracy_split(const char *acc)
{
    const char *p = strstr(acc, "\n## ");
    return p ? (size_t)(p - acc) + 1 : strlen(acc);
}

static void write_index(const char *outdir, int quick)
{
    char path[1024];
    FILE *out;
    char *acc;
    size_t n, head;
    snprintf(path, sizeof path, "%s/index.html", outdir);
    out = fopen(path, "w");
    if (!out)
        return;
    doc_html_page_begin(out, quick ? "facet report (quick run)" : "facet report");
    snprintf(path, sizeof path, "%s/accuracy.md", outdir);
    acc = read_all(path, &n);
    head = acc ? accuracy_split(acc) : 0;
    if (acc)
        doc_html_from_markdown(out, acc, head);
    else
        fputs("<h1>facet report</h1>\n", out);
    snprintf(path, sizeof path, "%s/bench.html", outdir);
    copy_file(path, out);
    if (acc && head < n) {
        fputs("<h1>Accuracy (tests/report/report.sh)</h1>\n", out);
        doc_html_from_markdown(out, acc + head, n - head);
    }
    free(acc);
    doc_html_page_end(out);
    fclose(out);
}

static void write_report_md(const char *outdir)
{
    char path[1024];
    FILE *out;
    char *acc;
    size_t n, head;
    snprintf(path, sizeof path, "%s/report.md", outdir);
    out = fopen(path, "w");
    if (!out)
        return;
    snprintf(path, sizeof path, "%s/accuracy.md", outdir);
    acc = read_all(path, &n);
    head = acc ? accuracy_split(acc) : 0;
    if (acc)
        fwrite(acc, 1, head, out);
    else
        fputs("# facet report\n\n(bench part only: no accuracy.md from tests/report/report.sh here)\n", out);
    snprintf(path, sizeof path, "%s/bench.md", outdir);
    copy_file(path, out);
    if (acc && head < n) {
        fputs("\n# Accuracy (tests/report/report.sh)\n\n", out);
        fwrite(acc + head, 1, n - head, out);
    }
    free(acc);
    fclose(out);
}

/* ---- the verb ------------------------------------------------------------------- */

static int usage(void)
{
    fprintf(stderr, "usage: facet-bench report OUTDIR [--quick] [--replay MEASURED.tsv]\n"
                    "       facet-bench report --facts [KERNEL...]\n"
                    "  writes OUTDIR/bench.md, report.md, index.html, measured.tsv and the pictures;\n"
                    "  --replay renders from a recorded measured set instead of measuring;\n"
                    "  --facts prints what the report knows of each kernel (kernel_facts.c) and checks it\n"
                    "  against the kernel list (or the KERNELs given): exit 1 on a kernel without an entry\n");
    return 2;
}

/* --facts [KERNEL...]: the table, checked against the library's kernel
 * list or the names given */
static int facts(int argc, char **argv)
{
    int bad;
    kf_print(stdout);
    bad = kf_check(argc > 0 ? (const char *const *)argv : NULL, argc, stderr);
    if (fflush(stdout) != 0)
        return 1;
    return bad ? 1 : 0;
}

int facet_bench_report(int argc, char **argv)
{
    report_data data;
    report r;
    bench_opts o;
    char path[1024];
    const char *outdir = NULL, *replay = NULL;
    FILE *md, *html;
    size_t s;
    int i, quick = 0;
    time_t t0 = time(NULL);
    if (argc > 1 && !strcmp(argv[1], "--facts"))
        return facts(argc - 2, argv + 2);
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--quick"))
            quick = 1;
        else if (!strcmp(argv[i], "--replay") && i + 1 < argc)
            replay = argv[++i];
        else if (argv[i][0] != '-' && !outdir)
            outdir = argv[i];
        else
            return usage();
    }
    if (!outdir)
        return usage();
    if (kf_check(NULL, 0, stderr) != 0) {
        fprintf(stderr, "facet-bench report: bench/report/kernel_facts.c does not match the kernel list\n");
        return 1;
    }
    data.quick = quick;
    if (data_open(&data, outdir, replay) != 0)
        return 1;
    quick = data.quick; /* a replay renders as its recording ran */
    snprintf(path, sizeof path, "%s/bench.md", outdir);
    md = fopen(path, "w");
    snprintf(path, sizeof path, "%s/bench.html", outdir);
    html = fopen(path, "w");
    if (!md || !html) {
        fprintf(stderr, "facet-bench report: cannot write to %s\n", outdir);
        return 1;
    }
    memset(&r, 0, sizeof r);
    r.data = &data;
    r.outdir = outdir;
    r.quick = quick;
    r.raster_avx2_per_eval = r.raster_batch_per_eval = -1;
    r.doc = doc_new();
    doc_attach(r.doc, doc_md_writer(md));
    doc_attach(r.doc, doc_html_writer(html));
    if (data.replayed) {
        report_say("replaying the measured set %s (%d rows)", replay, data.n_rows);
    } else {
        bench_defaults(&o);
        if (quick) {
            o.n_time = 256;
            o.n_err = 4096;
            o.target = 5000;
        } else {
            o.n_err = 1 << 17;
        }
        o.progress = 1;
        o.sampler_batch_only = 1; /* the samplers' table shows the batch rows */
        cyc_init();
        data_set_clock(&data);
        report_say("benchmarks: every kernel x format x port x path, and the peers ...");
        if (bench_run(&o, data_add_row, &data) < 0)
            return 1;
        /* the speed table's run: both f32 tiers and the same-formula peers,
         * interleaved (harness/speed.h; sec_speed.c) */
        data.speed_rounds = quick ? 5 : 101;
        data.speed_n = quick ? 256 : 4096;
        report_say("speed: both f32 tiers against the same-formula peers, %d interleaved rounds ...",
                   data.speed_rounds);
        if (speed_run(NULL, data.speed_rounds, (size_t)data.speed_n, data_add_speed, &data) != 0)
            return 1;
    }
    report_say("model-error sweep of the approximations ...");
    kf_model_sweep(quick);
    if (kf_sim_load(KF_SIM_TABLE) <= 0)
        report_say("cannot read %s: the diffuse kernels' model errors are left out", KF_SIM_TABLE);

    doc_heading(r.doc, 1, "%s", quick ? BENCH_QUICK_TITLE : BENCH_TITLE);
    if (quick)
        doc_para(r.doc, BENCH_QUICK_NOTE);
    for (s = 0; s < sizeof sections / sizeof sections[0]; s++) {
        time_t ts = time(NULL);
        sections[s].write(&r);
        report_say("%s: done in %ld s", sections[s].name, (long)(time(NULL) - ts));
    }
    doc_free(r.doc);
    fclose(md);
    fclose(html);
    write_index(outdir, quick);
    write_report_md(outdir);
    snprintf(path, sizeof path, "%s/measured.tsv", outdir);
    if (!data.replayed && data_save(&data, path) != 0)
        report_say("cannot write %s", path);
    data_close(&data);
    report_say("bench part done in %ld s: %s/index.html, %s/bench.md", (long)(time(NULL) - t0), outdir, outdir);
    return 0;
}
