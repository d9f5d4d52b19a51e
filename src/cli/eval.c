/* eval.c - `facet eval NAME` in the float formats: a kernel or an
 * importance sampler (facet.h), evaluated by its f32 or f32_fast batch on
 * the chosen port, or by the double oracle; one output line per sample
 * (a sampler's: the sampled vector's components, or the pdf).  The fixed
 * point formats are fx.c's.  Input rules and exit statuses: src/cli/cli.h. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "facet/f16.h"
#include "cli.h"

static const char *prog = "facet";

static void usage_eval(FILE *f)
{
    fprintf(f,
            "usage: %s eval KERNEL [--format f32|f32_fast|f16|fx|fx_fast] [--oracle] [--port P]\n"
            "Evaluates KERNEL on the samples read from stdin, one output line per sample.\n"
            "  --format f32     the float kernels (default): each input rounded once to\n"
            "                   the nearest float; output printed with %%.9g (round-trips)\n"
            "  --format f32_fast  the fast f32 tier (facet_<kernel>_f32_fast_batch)\n"
            "  --format f16     binary16 (facet/f16.h): each input rounded once to the\n"
            "                   nearest binary16, the f16 batch on the port's f16 table\n"
            "                   (avx512fp16 where the CPU has it, else scalar); output\n"
            "                   the binary16 result printed with %%.9g (exact)\n"
            "  --format fx      the fixed-point kernels ('%s eval --format fx --help');\n"
            "                   fx_fast their fast tier\n"
            "  --oracle         the double-precision oracle instead (facet/oracle.h):\n"
            "                   each input rounded once to the nearest double (give\n"
            "                   float values to judge --format f32); output with %%.17g\n"
            "  --port P         port to run the batch kernels on: auto (default: the\n"
            "                   best this CPU runs, or $FACET_PORT), or one of the\n"
            "                   ports compiled in (listed below; see '%s ports').  An\n"
            "                   unknown port, or one this CPU cannot run, is an error\n"
            "                   (exit status 2), from --port and from $FACET_PORT alike.\n"
            "NaN and infinities are accepted by f32 and --oracle: a NaN input gives 0\n"
            "(samplers: their documented substitute); -Inf clamps to the low end of the\n"
            "domain, +Inf to the high end; a finite value beyond float range becomes\n"
            "+-Inf, so it clamps too.\n%s%s",
            prog, prog, prog, facet_cli_input_help, facet_cli_exit_help);
    {
        size_t i;
        fprintf(f, "ports compiled in:");
        for (i = 0; i < facet_port_count(); i++) {
            int sup;
            const char *n = facet_port_at(i, &sup, NULL);
            fprintf(f, " %s%s", n, sup ? "" : " (not on this CPU)");
        }
        fprintf(f, "\n");
    }
}

/* ---- how a row is evaluated and printed (facet_cli_evaluator flushes) ---- */
static void kernel_f32(const facet_cli_evaluator *e, const facet_cli_rows *rows, size_t n)
{
    static float out[FACET_CLI_CHUNK];
    const facet_kernel *k = e->what;
    const float *in[FACET_CLI_MAX_INPUTS];
    size_t s;
    facet_cli_f32_columns(rows, n, in);
    (e->fast ? k->f32_fast_batch : k->f32_batch)(out, in, n);
    for (s = 0; s < n; s++)
        printf("%.9g\n", out[s]);
}

static void kernel_f16(const facet_cli_evaluator *e, const facet_cli_rows *rows, size_t n)
{
    static facet_f16 out[FACET_CLI_CHUNK], ins[FACET_CLI_MAX_INPUTS][FACET_CLI_CHUNK];
    const facet_f16_kernel *h = e->what;
    const float *in[FACET_CLI_MAX_INPUTS];
    const facet_f16 *hin[FACET_CLI_MAX_INPUTS];
    size_t s;
    int i;
    facet_cli_f32_columns(rows, n, in);
    for (i = 0; i < h->n_inputs; i++) {
        facet_f16_from_f32_batch(ins[i], in[i], n);
        hin[i] = ins[i];
    }
    h->f16_batch(out, hin, n);
    for (s = 0; s < n; s++)
        printf("%.9g\n", facet_f32_from_f16(out[s]));
}

static void kernel_oracle(const facet_cli_evaluator *e, const facet_cli_rows *rows, size_t n)
{
    const facet_kernel *k = e->what;
    size_t s;
    for (s = 0; s < n; s++)
        printf("%.17g\n", k->oracle(rows->f64[s]));
}

static void sampler_f32(const facet_cli_evaluator *e, const facet_cli_rows *rows, size_t n)
{
    static float outs[FACET_SAMPLER_MAX_OUTPUTS][FACET_CLI_CHUNK];
    const facet_sampler *smp = e->what;
    const float *in[FACET_CLI_MAX_INPUTS];
    float *out[FACET_SAMPLER_MAX_OUTPUTS];
    size_t s;
    int o;
    facet_cli_f32_columns(rows, n, in);
    for (o = 0; o < FACET_SAMPLER_MAX_OUTPUTS; o++)
        out[o] = outs[o];
    (e->fast ? smp->f32_fast_batch : smp->f32_batch)(out, in, n);
    for (s = 0; s < n; s++) {
        for (o = 0; o < smp->n_outputs; o++)
            printf("%s%.9g", o ? " " : "", outs[o][s]);
        printf("\n");
    }
}

static void sampler_oracle(const facet_cli_evaluator *e, const facet_cli_rows *rows, size_t n)
{
    const facet_sampler *smp = e->what;
    double out[FACET_SAMPLER_MAX_OUTPUTS];
    size_t s;
    int o;
    for (s = 0; s < n; s++) {
        smp->oracle(out, rows->f64[s]);
        for (o = 0; o < smp->n_outputs; o++)
            printf("%s%.17g", o ? " " : "", out[o]);
        printf("\n");
    }
}

int facet_cli_eval(int argc, char **argv)
{
    static const facet_cli_option opts[] = { { "--format", 1 }, { "--port", 1 }, { "--oracle", 0 }, { NULL, 0 } };
    enum { OPT_FORMAT, OPT_PORT, OPT_ORACLE };
    facet_cli_args a = facet_cli_args_of(argc, argv, "eval", opts, usage_eval);
    facet_cli_evaluator e = { 0 };
    const facet_kernel *k = NULL;
    const facet_sampler *smp = NULL;
    const char *format = "f32", *port = "auto", *v;
    int i, oracle = 0, arg;

    for (i = 1; i + 1 < argc; i++) /* fx has its own options: src/cli/fx.c */
        if (!strcmp(argv[i], "--format") && (!strcmp(argv[i + 1], "fx") || !strcmp(argv[i + 1], "fx_fast")))
            return facet_cli_fx_eval(argc, argv);
    while ((arg = facet_cli_next_arg(&a, &v)) != FACET_CLI_ARG_END) {
        switch (arg) {
        case FACET_CLI_ARG_DONE:
            return a.status;
        case FACET_CLI_ARG_NAME:
            k = facet_kernel_find(v);
            smp = k ? NULL : facet_sampler_find(v);
            if (!k && !smp) {
                facet_cli_unknown_kernel("eval", "kernel", v);
                return FACET_EXIT_USAGE;
            }
            break;
        case OPT_FORMAT:
            format = v;
            break;
        case OPT_PORT:
            port = v;
            break;
        case OPT_ORACLE:
            oracle = 1;
            break;
        }
    }
    if (!k && !smp) {
        fprintf(stderr, "%s eval: missing KERNEL\n", prog);
        usage_eval(stderr);
        return FACET_EXIT_USAGE;
    }
    if (strcmp(format, "f32") && strcmp(format, "f32_fast") && strcmp(format, "f16")) {
        fprintf(stderr, "%s eval: unknown format '%s' (known: f32, f32_fast, f16, fx, fx_fast)\n", prog, format);
        return FACET_EXIT_USAGE;
    }
    if (!strcmp(format, "f16") && !oracle) {
        const facet_f16_kernel *h = k ? facet_f16_kernel_find(k->name) : NULL;
        if (!h || !h->f16) {
            fprintf(stderr, "%s eval: '%s' has no f16 form: %s\n", prog, k ? k->name : smp->name,
                    h ? h->why : "the samplers are f32 only");
            return FACET_EXIT_USAGE;
        }
    }
    e.fast = strcmp(format, "f32") != 0;
    e.number = oracle ? FACET_CLI_F64 : FACET_CLI_F32;
    e.chunk = oracle ? 1 : FACET_CLI_CHUNK; /* the oracle line by line */
    if (k) {
        e.what = k;
        e.n_inputs = k->n_inputs;
        e.inputs = k->inputs;
        e.flush = oracle ? kernel_oracle : kernel_f32;
        if (!oracle && !strcmp(format, "f16")) {
            e.what = facet_f16_kernel_find(k->name);
            e.flush = kernel_f16;
        }
    } else {
        e.what = smp;
        e.n_inputs = smp->n_inputs;
        e.inputs = smp->inputs;
        e.flush = oracle ? sampler_oracle : sampler_f32;
    }
    if (oracle && k) /* a kernel's oracle runs on no port */
        return facet_cli_eval_lines(&e);
    if (!strcmp(port, "auto") && getenv("FACET_PORT") && *getenv("FACET_PORT"))
        port = getenv("FACET_PORT");
    switch (facet_set_port(port)) {
    case 0:
        break;
    case 2:
        fprintf(stderr, "%s eval: port '%s' is compiled in but this CPU cannot run it\n", prog, port);
        return FACET_EXIT_USAGE;
    default:
        fprintf(stderr, "%s eval: unknown port '%s' (see '%s ports')\n", prog, port, prog);
        return FACET_EXIT_USAGE;
    }
    return facet_cli_eval_lines(&e);
}
