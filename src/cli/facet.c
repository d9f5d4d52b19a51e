/* facet - the command-line face of the library.
 *   facet list | ports
 *   facet eval KERNEL [--format f32|f32_fast|fx|fx_fast] [--oracle] [--port P]
 *   facet vectors KERNEL [--format fx|fx_fast] [--count N] [--seed S] [--hex]
 * Input rules and exit statuses: src/cli/cli.h (0 success, 1 I/O error,
 * 2 usage error or malformed input), the same for every verb. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "facet/fx.h"
#include "cli.h"

#define CHUNK 1024 /* samples per batch call */

static const char *prog = "facet";

int facet_cli_fx_eval(int argc, char **argv); /* src/cli/fx.c: eval --format fx */
int facet_cli_vectors(int argc, char **argv);  /* src/cli/fx.c: vectors */
int facet_cli_sample_eval(const facet_sampler *s, int fast, int oracle); /* src/cli/sample.c */

/* the rules every verb shares, for the --help texts */
const char facet_cli_input_help[] =
    "Input: one sample per line, the kernel's inputs in 'facet list' order as\n"
    "decimal numbers ([+-]digits[.digits][e[+-]digits]) separated by white space\n"
    "(space, tab, CR, VT, FF).  Blank lines and lines whose first non-blank\n"
    "character is '#' are skipped.  A line may have at most 4094 characters; a\n"
    "NUL byte anywhere is an error.  A malformed line stops the run: every line\n"
    "before it has been evaluated and printed, the error (with its line number)\n"
    "goes to stderr, and the exit status is 2.\n";
const char facet_cli_exit_help[] =
    "Exit status (every verb): 0 success; 1 I/O error (reading stdin or writing\n"
    "stdout failed, e.g. stdout is /dev/full); 2 usage error or malformed input.\n";

static void usage_main(FILE *f)
{
    fprintf(f,
            "usage: %s <verb> [options]\n"
            "verbs:\n"
            "  list                 one line per kernel: name, then its inputs in order\n"
            "  ports                the ports compiled in, which this CPU runs, and\n"
            "                       which one 'auto' picks\n"
            "  eval KERNEL          evaluate KERNEL on samples read from stdin\n"
            "                       (--format f32|f32_fast|fx|fx_fast, --oracle, --port P)\n"
            "  vectors KERNEL       golden input/output vectors of a fixed-point kernel\n"
            "  --version            the library version\n"
            "Run '%s <verb> --help' for a verb's options.\n%s",
            prog, prog, facet_cli_exit_help);
}

static void usage_list(FILE *f)
{
    fprintf(f, "usage: %s list [--formats]\n"
               "Prints one line per kernel: its name, then the names of its inputs in the\n"
               "order 'eval' reads them.  With --formats: its name, then the formats it\n"
               "comes in (f32 f32_fast, and fx fx_fast where it has a fixed-point form;\n"
               "fx_fast alone where it has only the fast fixed-point tier).\n%s",
            prog, facet_cli_exit_help);
}

static void usage_ports(FILE *f)
{
    fprintf(f, "usage: %s ports\n"
               "Prints one line per port compiled in, best first: its name, its lanes,\n"
               "whether this CPU runs it, and 'auto' on the port the automatic choice\n"
               "picks here.  With FACET_PORT set, a last line says what the library does\n"
               "with it: a port this CPU runs is the library's initial port; any other\n"
               "value is ignored by the library (it starts on auto; facet_port_name()\n"
               "tells), whereas 'facet eval' (f32) refuses it (exit status 2).\n%s",
            prog, facet_cli_exit_help);
}

static void usage_eval(FILE *f)
{
    fprintf(f,
            "usage: %s eval KERNEL [--format f32|f32_fast|fx|fx_fast] [--oracle] [--port P]\n"
            "Evaluates KERNEL on the samples read from stdin, one output line per sample.\n"
            "  --format f32     the float kernels (default): each input rounded once to\n"
            "                   the nearest float; output printed with %%.9g (round-trips)\n"
            "  --format f32_fast  the fast f32 tier (facet_<kernel>_f32_fast_batch)\n"
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

/* a verb given only --help / -h; 1 if it was (and the help is printed) */
static int wants_help(int argc, char **argv)
{
    return argc == 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"));
}

static int cmd_list(int argc, char **argv)
{
    size_t i;
    int j;
    if (wants_help(argc, argv)) {
        usage_list(stdout);
        return facet_cli_finish("list");
    }
    if (argc > 2 || (argc == 2 && strcmp(argv[1], "--formats"))) {
        fprintf(stderr, "%s list: unexpected argument '%s'\n", prog, argv[1]);
        usage_list(stderr);
        return FACET_EXIT_USAGE;
    }
    for (i = 0; i < facet_kernel_count(); i++) {
        const facet_kernel *k = facet_kernel_at(i);
        printf("%s", k->name);
        if (argc == 2) {
            const facet_fx_kernel *fk = facet_fx_kernel_find(k->name);
            printf(" f32 f32_fast%s%s", fk && fk->fx ? " fx" : "", fk ? " fx_fast" : "");
        }
        else
            for (j = 0; j < k->n_inputs; j++)
                printf(" %s", k->inputs[j]);
        printf("\n");
    }
    /* the importance samplers: inputs, then '->' and their outputs */
    for (i = 0; i < facet_sampler_count(); i++) {
        const facet_sampler *smp = facet_sampler_at(i);
        printf("%s", smp->name);
        if (argc == 2)
            printf(" f32 f32_fast\n");
        else {
            for (j = 0; j < smp->n_inputs; j++)
                printf(" %s", smp->inputs[j]);
            printf(" ->");
            for (j = 0; j < smp->n_outputs; j++)
                printf(" %s", smp->outputs[j]);
            printf("\n");
        }
    }
    return facet_cli_finish("list");
}

static int cmd_ports(int argc, char **argv)
{
    size_t i;
    int picked = 0;
    const char *env = getenv("FACET_PORT");
    if (wants_help(argc, argv)) {
        usage_ports(stdout);
        return facet_cli_finish("ports");
    }
    if (argc > 1) {
        fprintf(stderr, "%s ports: unexpected argument '%s'\n", prog, argv[1]);
        usage_ports(stderr);
        return FACET_EXIT_USAGE;
    }
    for (i = 0; i < facet_port_count(); i++) {
        int sup, lanes;
        const char *n = facet_port_at(i, &sup, &lanes);
        printf("%-8s %2d lane%s  %s%s\n", n, lanes, lanes == 1 ? " " : "s",
               sup ? "runs on this CPU" : "not on this CPU", sup && !picked ? "  auto" : "");
        picked |= sup; /* best first: auto is the first one this CPU runs */
    }
    if (env && *env && strcmp(env, "auto")) {
        int sup = 0, known = 0;
        for (i = 0; i < facet_port_count(); i++)
            if (!strcmp(env, facet_port_at(i, &sup, NULL))) {
                known = 1;
                break;
            }
        if (known && sup)
            printf("FACET_PORT=%s: the library starts on %s\n", env, env);
        else
            printf("FACET_PORT=%s: %s; the library ignores it (starts on auto), "
                   "'%s eval' (f32) refuses it\n", env, known ? "this CPU cannot run it" : "not a port compiled in",
                   prog);
    }
    return facet_cli_finish("ports");
}

static void kernel_names(const char **names, size_t cap, size_t *n)
{
    size_t i;
    *n = facet_kernel_count() < cap ? facet_kernel_count() : cap;
    for (i = 0; i < *n; i++)
        names[i] = facet_kernel_at(i)->name;
}

/* "unknown kernel" with a did-you-mean hint; shared with src/cli/fx.c */
void facet_cli_unknown_kernel(const char *verb, const char *what, const char *name)
{
    const char *names[64];
    size_t n;
    const char *hint;
    kernel_names(names, sizeof names / sizeof names[0], &n);
    hint = facet_cli_suggest(name, names, n);
    fprintf(stderr, "%s %s: unknown %s '%s'", prog, verb, what, name);
    if (hint)
        fprintf(stderr, "; did you mean '%s'?", hint);
    fprintf(stderr, " (see '%s list')\n", prog);
}

static void report_line_error(const facet_kernel *k, const facet_cli_reader *r, const char *err)
{
    facet_cli_line_error(r->lineno, err, k->n_inputs, k->inputs);
}

/* the oracle, one line at a time */
static int eval_oracle(const facet_kernel *k)
{
    facet_cli_reader r;
    const char *err = NULL;
    int got;
    r.f = stdin;
    r.lineno = 0;
    while ((got = facet_cli_read_line(&r, &err)) == 1) {
        double in[FACET_MAX_INPUTS];
        err = facet_cli_parse_f64(r.buf, k->n_inputs, in);
        if (err)
            break;
        printf("%.17g\n", k->oracle(in));
        if (ferror(stdout))
            return facet_cli_finish("eval");
    }
    if (got == -2) {
        fprintf(stderr, "%s eval: error reading the input\n", prog);
        return FACET_EXIT_IO;
    }
    if (got == -1 || err) {
        int rc = facet_cli_finish("eval");
        report_line_error(k, &r, err);
        return rc ? rc : FACET_EXIT_USAGE;
    }
    return facet_cli_finish("eval");
}

static int cmd_eval(int argc, char **argv)
{
    const facet_kernel *k = NULL;
    const facet_sampler *smp = NULL;
    const char *format = "f32", *port = "auto";
    static float cols[FACET_MAX_INPUTS][CHUNK], out[CHUNK];
    facet_cli_reader r;
    const char *err = NULL;
    int i, oracle = 0, got = 1;

    for (i = 1; i + 1 < argc; i++) /* fx has its own options: src/cli/fx.c */
        if (!strcmp(argv[i], "--format") && (!strcmp(argv[i + 1], "fx") || !strcmp(argv[i + 1], "fx_fast")))
            return facet_cli_fx_eval(argc, argv);
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            usage_eval(stdout);
            return facet_cli_finish("eval");
        } else if (!strcmp(argv[i], "--format") && i + 1 < argc) {
            format = argv[++i];
        } else if (!strcmp(argv[i], "--port") && i + 1 < argc) {
            port = argv[++i];
        } else if (!strcmp(argv[i], "--oracle")) {
            oracle = 1;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            fprintf(stderr, "%s eval: unknown or incomplete option '%s'\n", prog, argv[i]);
            usage_eval(stderr);
            return FACET_EXIT_USAGE;
        } else if (!k && !smp) {
            k = facet_kernel_find(argv[i]);
            smp = k ? NULL : facet_sampler_find(argv[i]);
            if (!k && !smp) {
                facet_cli_unknown_kernel("eval", "kernel", argv[i]);
                return FACET_EXIT_USAGE;
            }
        } else {
            fprintf(stderr, "%s eval: unexpected argument '%s'\n", prog, argv[i]);
            return FACET_EXIT_USAGE;
        }
    }
    if (!k && !smp) {
        fprintf(stderr, "%s eval: missing KERNEL\n", prog);
        usage_eval(stderr);
        return FACET_EXIT_USAGE;
    }
    if (strcmp(format, "f32") && strcmp(format, "f32_fast")) {
        fprintf(stderr, "%s eval: unknown format '%s' (known: f32, f32_fast, fx, fx_fast)\n", prog, format);
        return FACET_EXIT_USAGE;
    }
    if (oracle && k)
        return eval_oracle(k);
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
    if (smp)
        return facet_cli_sample_eval(smp, strcmp(format, "f32") != 0, oracle);
    r.f = stdin;
    r.lineno = 0;
    while (got == 1) {
        int n = 0;
        /* a chunk of lines; a malformed one ends the chunk, and the run
         * after the lines before it are printed */
        while (n < CHUNK && (got = facet_cli_read_line(&r, &err)) == 1) {
            float in[FACET_MAX_INPUTS];
            err = facet_cli_parse_f32(r.buf, k->n_inputs, in);
            if (err) {
                got = -1;
                break;
            }
            for (i = 0; i < k->n_inputs; i++)
                cols[i][n] = in[i];
            n++;
        }
        if (n > 0) {
            const float *ptr[FACET_MAX_INPUTS];
            for (i = 0; i < FACET_MAX_INPUTS; i++)
                ptr[i] = cols[i];
            (strcmp(format, "f32") ? k->f32_fast_batch : k->f32_batch)(out, ptr, (size_t)n);
            for (i = 0; i < n; i++)
                printf("%.9g\n", out[i]);
            if (ferror(stdout))
                return facet_cli_finish("eval");
        }
    }
    if (got == -2) {
        fprintf(stderr, "%s eval: error reading the input\n", prog);
        return FACET_EXIT_IO;
    }
    if (got == -1) {
        int rc = facet_cli_finish("eval");
        report_line_error(k, &r, err);
        return rc ? rc : FACET_EXIT_USAGE;
    }
    return facet_cli_finish("eval");
}

/* Verbs.  Parts of the library that bring a verb add a line here and
 * implement it in their own file under src/cli/. */
typedef struct {
    const char *name;
    int (*run)(int argc, char **argv); /* argv[0] is the verb */
} verb;

static const verb verbs[] = {
    { "list", cmd_list },
    { "ports", cmd_ports },
    { "eval", cmd_eval },
    { "vectors", facet_cli_vectors }, /* src/cli/fx.c */
};

int main(int argc, char **argv)
{
    size_t i;
    if (argc < 2) {
        usage_main(stderr);
        return FACET_EXIT_USAGE;
    }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
        usage_main(stdout);
        return facet_cli_finish("--help");
    }
    if (!strcmp(argv[1], "--version")) {
        printf("facet %s\n", FACET_VERSION);
        return facet_cli_finish("--version");
    }
    for (i = 0; i < sizeof verbs / sizeof verbs[0]; i++)
        if (!strcmp(argv[1], verbs[i].name))
            return verbs[i].run(argc - 1, argv + 1);
    fprintf(stderr, "%s: unknown verb '%s'\n", prog, argv[1]);
    usage_main(stderr);
    return FACET_EXIT_USAGE;
}
