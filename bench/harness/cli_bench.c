/* cli_bench.c - `facet-bench bench`: cycles and error of every kernel x format x
 * port x path (and the peers), as a table or JSON.  See usage below. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet/f16.h"
#include "bench.h"
#include "peers.h"

#include "facet_bench.h"

static void usage(FILE *f)
{
    fprintf(f,
            "usage: facet-bench bench [KERNEL] [--port P] [--format f32|f32_fast|fx|fx_fast|f16] [--json]\n"
            "                         [--samples N] [--err-samples N] [--epochs E] [--quick] [--no-peers]\n"
            "Times every kernel (or KERNEL) on every port this CPU runs, through the batch\n"
            "API, the inline kernels and the library call, next to the peers (textbook;\n"
            "shader and shader_fm built for each port's vector width: shader_avx2,\n"
            "shader_avx512 on x86), and measures each one's error against the double oracle.\n"
            "Then the importance samplers and pdfs ('facet list' names them; KERNEL may be\n"
            "one): the batch API of both f32 tiers on every port, and the textbook peer\n"
            "(tests/lib/sample_peer.h); error in the samplers' measure (facet.h).\n"
            "Throughput: cycles per sample over an L1-resident SoA set (difference of R and\n"
            "2R passes); latency: cycles per call in a dependent chain.  >= 11 epochs after\n"
            "warm-up, pinned to one CPU; min, median, spread; '!' marks spread > 5%%.\n"
            "The clock is perf's core-cycle counter when the kernel allows it, otherwise\n"
            "the time-stamp counter in ticks (labelled so; est. cycles use a measured\n"
            "ticks-per-cycle ratio).\n"
            "  --port P         a facet port (scalar, sse2, avx2, avx512, neon) or a peer\n"
            "  --format F       f32, f32_fast, fx, fx_fast or f16 (binary16: port = the f16 table\n"
            "                   that ran, e.g. avx512fp16; --port takes that name too)\n"
            "  --json           one JSON document on stdout\n"
            "  --samples N      samples per timed pass (default 1024, multiple of 8,\n"
            "                   at most 65536)\n"
            "  --err-samples N  samples for the error (default 65536, at most 4194304)\n"
            "  --epochs E       timed epochs (default and minimum 11, at most 1001)\n"
            "  --quick          tiny run (for tests): few samples, short passes\n"
            "  --no-peers       facet only\n"
            "  --peer-check     only the peers' check (bench/harness/peers.h): each term's\n"
            "                   error against its kernel's oracle on the well-conditioned\n"
            "                   set, which must be arithmetic error; exit 1 if one is not\n"
            "Exit status: 0 success; 1 stdout could not be written; 2 usage error (an\n"
            "unknown kernel, port or format, a port this CPU cannot run, a value out of\n"
            "range).\n");
}

typedef struct sink_ctx {
    int json, first;
    double tpc;
} sink_ctx;

/* "KEY": NUMBER, printed at once (no shared buffer: a printf of several
 * formatted numbers cannot mix them up); JSON has no inf/nan: null */
static void jnum(const char *key, double x, const char *after)
{
    if (x != x || x - x != 0)
        printf("\"%s\": null%s", key, after);
    else
        printf("\"%s\": %.6g%s", key, x, after);
}

static void json_stat(const char *name, const cyc_stat *s, double tpc)
{
    printf("\"%s\": {", name);
    jnum("min", s->min, ", ");
    jnum("median", s->median, ", ");
    jnum("max", s->max, ", ");
    jnum("spread", s->spread, ", ");
    printf("\"noisy\": %s, \"epochs\": %d, ", s->noisy ? "true" : "false", s->epochs);
    jnum("est_cycles_median", s->median / tpc, "}");
}

static void sink(const bench_row *r, void *vctx)
{
    sink_ctx *c = vctx;
    int j;
    if (c->json) {
        printf("%s\n    {\"kernel\": \"%s\", \"format\": \"%s\", \"port\": \"%s\", \"path\": \"%s\", "
               "\"lanes\": %d,\n     ",
               c->first ? "" : ",", r->kernel, r->format, r->port, r->path, r->lanes);
        jnum("max_err", r->err.max_rel, ", ");
        jnum("mean_err", r->err.mean_rel, ", \"argmax\": [");
        for (j = 0; j < r->n_inputs; j++)
            printf("%s%.9g", j ? ", " : "", r->err.arg[j]);
        printf("], \"bound\": %.6g, \"within_bound\": %s,\n     ", r->bound,
               r->within ? "true" : "false");
        if (r->err.has_lsb) {
            jnum("max_err_lsb", r->err.max_lsb, ", ");
            jnum("mean_err_lsb", r->err.mean_lsb, ", \"bound_unit\": \"lsb\",\n     ");
        }
        json_stat("throughput", &r->thr, c->tpc);
        if (r->has_lat) {
            printf(",\n     ");
            json_stat("latency", &r->lat, c->tpc);
        }
        if (r->note[0])
            printf(",\n     \"note\": \"%s\"", r->note);
        printf("}");
    } else {
        char lat[48] = "-";
        if (r->has_lat)
            snprintf(lat, sizeof lat, "%8.2f%s", r->lat.median, r->lat.noisy ? "!" : " ");
        /* fx rows: the error columns are in LSB (marked 'L') */
        char e1[24], e2[24];
        if (r->err.has_lsb) {
            snprintf(e1, sizeof e1, "%7.3gL", r->err.max_lsb);
            snprintf(e2, sizeof e2, "%7.3gL", r->err.mean_lsb);
        } else {
            snprintf(e1, sizeof e1, "%9.3g", r->err.max_rel);
            snprintf(e2, sizeof e2, "%9.3g", r->err.mean_rel);
        }
        printf("%-22s %-8s %-16s %-12s %9s %9s %s %8.3f %8.3f %5.1f%%%s %8.3f %s\n", r->kernel,
               r->format, r->port, r->path, e1, e2,
               r->bound > 0 ? (r->within ? "ok " : "BAD") : "-  ", r->thr.min, r->thr.median,
               100 * r->thr.spread, r->thr.noisy ? "!" : " ", r->thr.median / c->tpc, lat);
    }
    c->first = 0;
    fflush(stdout);
}

int facet_cmd_bench(int argc, char **argv)
{
    bench_opts o;
    sink_ctx c;
    int i, n;
    bench_defaults(&o);
    memset(&c, 0, sizeof c);
    c.first = 1;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            return 0;
        } else if (!strcmp(a, "--json")) {
            c.json = 1;
        } else if (!strcmp(a, "--quick")) {
            o.n_time = 256;
            o.n_err = 2048;
            o.target = 5000;
        } else if (!strcmp(a, "--peer-check")) {
            size_t q;
            for (q = 0; peer_sets[q]; q++) {
                const peer_term_entry *t;
                if (!peer_available(peer_sets[q]))
                    continue;
                for (t = peer_sets[q]->terms; t && t->kernel; t++)
                    printf("%-18s %-26s %10.3g\n", peer_sets[q]->name, t->kernel, peer_arith_err(t->fn, t->kernel));
            }
            n = peer_check(stderr);
            printf("peer check: %s\n", n ? "FAILED" : "every term within 2^-10 (arithmetic error), the control fails");
            return fflush(stdout) != 0 || n != 0;
        } else if (!strcmp(a, "--no-peers")) {
            o.peers = 0;
        } else if (!strcmp(a, "--port") && i + 1 < argc) {
            o.port = argv[++i];
        } else if (!strcmp(a, "--format") && i + 1 < argc) {
            o.format = argv[++i];
        } else if ((!strcmp(a, "--samples") || !strcmp(a, "--err-samples") || !strcmp(a, "--epochs"))
                   && i + 1 < argc) {
            /* documented caps, so that a maximal run still ends in minutes */
            long cap = !strcmp(a, "--samples") ? 65536L : !strcmp(a, "--err-samples") ? 4194304L : 1001L;
            char *end;
            long v;
            if (argv[i + 1][0] < '0' || argv[i + 1][0] > '9') {
                fprintf(stderr, "facet-bench bench: bad value '%s' for %s (decimal digits)\n", argv[i + 1], a);
                return 2;
            }
            v = strtol(argv[++i], &end, 10);
            if (*end || v <= 0 || v > cap) {
                fprintf(stderr, "facet-bench bench: bad value '%s' for %s (1 to %ld)\n", argv[i], a, cap);
                return 2;
            }
            if (!strcmp(a, "--samples")) {
                if (v % 8) {
                    fprintf(stderr, "facet-bench bench: --samples must be a multiple of 8\n");
                    return 2;
                }
                o.n_time = (size_t)v;
            } else if (!strcmp(a, "--err-samples")) {
                o.n_err = (size_t)v;
            } else {
                o.epochs = (int)v;
            }
        } else if (a[0] == '-' && a[1]) {
            fprintf(stderr, "facet-bench bench: unknown or incomplete option '%s'\n", a);
            usage(stderr);
            return 2;
        } else if (!o.kernel) {
            if (!facet_kernel_find(a) && !facet_sampler_find(a)) {
                fprintf(stderr, "facet-bench bench: unknown kernel '%s' (see 'facet list')\n", a);
                return 2;
            }
            o.kernel = a;
        } else {
            fprintf(stderr, "facet-bench bench: unexpected argument '%s'\n", a);
            return 2;
        }
    }
    if (o.format && strcmp(o.format, "f32") && strcmp(o.format, "f32_fast") && strcmp(o.format, "fx") &&
        strcmp(o.format, "fx_fast") && strcmp(o.format, "f16")) {
        fprintf(stderr, "facet-bench bench: unknown format '%s' (known: f32, f32_fast, fx, fx_fast, f16)\n", o.format);
        return 2;
    }
    if (o.port) {
        int known = 0;
        size_t q;
        for (q = 0; peer_sets[q]; q++)
            if (!strcmp(o.port, peer_sets[q]->name))
                known = 1;
        size_t p;
        for (p = 0; p < facet_port_count(); p++)
            if (!strcmp(facet_port_at(p, NULL, NULL), o.port))
                known = 1;
        if (facet_f16_port_supported(o.port))
            known = 1;
        if (!known) {
            fprintf(stderr, "facet-bench bench: unknown port '%s'\n", o.port);
            return 2;
        }
        /* a facet port, or a peer built for one, that this CPU cannot run */
        for (q = 0; peer_sets[q]; q++)
            if (!strcmp(o.port, peer_sets[q]->name) && !peer_available(peer_sets[q])) {
                fprintf(stderr, "facet-bench bench: peer '%s' needs the %s port, which this CPU cannot run\n",
                        o.port, peer_sets[q]->width);
                return 2;
            }
        for (p = 0; p < facet_port_count(); p++) {
            int sup;
            if (!strcmp(facet_port_at(p, &sup, NULL), o.port) && !sup) {
                fprintf(stderr, "facet-bench bench: this CPU cannot run port '%s'\n", o.port);
                return 2;
            }
        }
    }
    if (o.n_err < o.n_time)
        o.n_err = o.n_time;
    cyc_init();
    c.tpc = cyc_ticks_per_cycle();
    if (c.json) {
        printf("{\"clock\": {\"source\": \"%s\", \"unit\": \"%s\", \"measured_core_cycles\": %s, "
               "\"ticks_per_cycle\": %.4f, \"cpu\": %d},\n \"samples\": %zu, \"err_samples\": %zu, "
               "\"epochs\": %d,\n \"results\": [",
               cyc_source(), cyc_unit(), cyc_is_cycles() ? "true" : "false", c.tpc, cyc_cpu(),
               o.n_time, o.n_err, o.epochs < 11 ? 11 : o.epochs);
    } else {
        printf("# clock: %s (%s%s), pinned to cpu %d; %zu samples/pass, %zu for the error\n",
               cyc_source(), cyc_unit(),
               cyc_is_cycles() ? ", measured core cycles" : ", NOT core cycles", cyc_cpu(),
               o.n_time, o.n_err);
        if (!cyc_is_cycles())
            printf("# est.cyc = ticks / %.3f (ticks per core cycle, from a chain of 1-cycle adds)\n",
                   c.tpc);
        if (!o.format || !strcmp(o.format, "fx") || !strcmp(o.format, "fx_fast"))
            printf("# fx rows: errors in LSB of the output format (L), vs round(oracle 2^frac) at the Q15 inputs;\n"
                   "# fx_fast rows: |raw - v 2^frac| / max(1, 2^-10 v 2^frac) (L), bound <= 1\n");
        printf("%-22s %-8s %-16s %-12s %9s %9s %s %8s %8s %6s %8s %s\n", "kernel", "fmt", "port",
               "path", "max_err", "mean_err", "bnd", "thr_min", "thr_med", "spread", "est.cyc",
               "latency/call");
    }
    n = bench_run(&o, sink, &c);
    if (n == -2)
        return 1;
    if (n < 0) {
        fprintf(stderr, "facet-bench bench: unknown port or format in the selection\n");
        return 2;
    }
    if (c.json)
        printf("\n ]}\n");
    if (n == 0 && !c.json)
        printf("# nothing to run for this selection on this machine\n");
    /* the facet command's rule: 1 when stdout could not be written */
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "facet-bench bench: cannot write the output\n");
        return 1;
    }
    return 0;
}
