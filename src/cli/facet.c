/* facet - the command-line face of the library.
 *   facet list
 *   facet eval KERNEL [--format f32] [--port auto|scalar|sse2|avx2|neon]
 * Exit status: 0 success, 2 usage error or malformed input, 1 I/O error. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "cli.h"

#define LINE_MAX_ 4096
#define CHUNK 1024 /* samples per batch call */

static const char *prog = "facet";

int facet_cli_fx_eval(int argc, char **argv); /* src/cli/fx.c: eval --format fx */
int facet_cli_vectors(int argc, char **argv);  /* src/cli/fx.c: vectors */

static void usage_main(FILE *f)
{
    fprintf(f,
            "usage: %s <verb> [options]\n"
            "verbs:\n"
            "  list                 one line per kernel: name, then its inputs in order\n"
            "  eval KERNEL          evaluate KERNEL on samples read from stdin\n"
            "                       (--format f32|fx, --port P)\n"
            "  vectors KERNEL       golden input/output vectors of a fixed-point kernel\n"
            "Run '%s <verb> --help' for a verb's options.\n",
            prog, prog);
}

static void usage_list(FILE *f)
{
    fprintf(f, "usage: %s list\n"
               "Prints one line per kernel: its name, then the names of its inputs in the\n"
               "order 'eval' reads them.\n", prog);
}

static void usage_eval(FILE *f)
{
    fprintf(f,
            "usage: %s eval KERNEL [--format f32] [--port P]\n"
            "Reads samples from stdin, one per line: the kernel's inputs as decimal\n"
            "numbers separated by white space, in 'facet list' order.  Writes one line\n"
            "per sample: the output, printed with %%.9g (round-trips the float).\n"
            "A malformed line is an error naming its line number (exit status 2).\n"
            "  --format f32     the float kernels (default)\n"
            "  --port P         port to run the batch kernels on: auto (default: the\n"
            "                   best this CPU runs, or $FACET_PORT), or one of the\n"
            "                   ports compiled in (listed below)\n",
            prog);
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

static int cmd_list(int argc, char **argv)
{
    size_t i;
    int j;
    if (argc > 1) {
        if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
            usage_list(stdout);
            return 0;
        }
        fprintf(stderr, "%s list: unexpected argument '%s'\n", prog, argv[1]);
        usage_list(stderr);
        return 2;
    }
    for (i = 0; i < facet_kernel_count(); i++) {
        const facet_kernel *k = facet_kernel_at(i);
        printf("%s", k->name);
        for (j = 0; j < k->n_inputs; j++)
            printf(" %s", k->inputs[j]);
        printf("\n");
    }
    return 0;
}

/* Parses exactly n numbers from line into floats; NULL or the error. */
static const char *parse_line(const char *line, int n, float *in)
{
    double v[FACET_MAX_INPUTS];
    const char *err = facet_cli_parse_numbers(line, n, v);
    int i;
    for (i = 0; !err && i < n; i++)
        in[i] = (float)v[i];
    return err;
}

static int cmd_eval(int argc, char **argv)
{
    const facet_kernel *k = NULL;
    const char *format = "f32", *port = "auto";
    char line[LINE_MAX_];
    static float cols[FACET_MAX_INPUTS][CHUNK], out[CHUNK];
    long lineno = 0;
    int i;

    for (i = 1; i + 1 < argc; i++) /* fx has its own options: src/cli/fx.c */
        if (!strcmp(argv[i], "--format") && !strcmp(argv[i + 1], "fx"))
            return facet_cli_fx_eval(argc, argv);
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            usage_eval(stdout);
            return 0;
        } else if (!strcmp(argv[i], "--format") && i + 1 < argc) {
            format = argv[++i];
        } else if (!strcmp(argv[i], "--port") && i + 1 < argc) {
            port = argv[++i];
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            fprintf(stderr, "%s eval: unknown or incomplete option '%s'\n", prog, argv[i]);
            usage_eval(stderr);
            return 2;
        } else if (!k) {
            k = facet_kernel_find(argv[i]);
            if (!k) {
                fprintf(stderr, "%s eval: unknown kernel '%s' (see '%s list')\n", prog, argv[i], prog);
                return 2;
            }
        } else {
            fprintf(stderr, "%s eval: unexpected argument '%s'\n", prog, argv[i]);
            return 2;
        }
    }
    if (!k) {
        fprintf(stderr, "%s eval: missing KERNEL\n", prog);
        usage_eval(stderr);
        return 2;
    }
    if (strcmp(format, "f32")) {
        fprintf(stderr, "%s eval: unknown format '%s' (known: f32, fx)\n", prog, format);
        return 2;
    }
    if (!strcmp(port, "auto") && getenv("FACET_PORT") && *getenv("FACET_PORT"))
        port = getenv("FACET_PORT");
    switch (facet_set_port(port)) {
    case 0:
        break;
    case 2:
        fprintf(stderr, "%s eval: port '%s' is compiled in but this CPU cannot run it\n", prog, port);
        return 2;
    default:
        fprintf(stderr, "%s eval: unknown port '%s' (see '%s eval --help')\n", prog, port, prog);
        return 2;
    }
    for (;;) {
        int n = 0;
        while (n < CHUNK && fgets(line, sizeof line, stdin)) {
            float in[FACET_MAX_INPUTS];
            const char *err;
            lineno++;
            if (!strchr(line, '\n') && !feof(stdin)) {
                fprintf(stderr, "%s eval: line %ld: longer than %d characters\n", prog, lineno, LINE_MAX_ - 2);
                return 2;
            }
            err = parse_line(line, k->n_inputs, in);
            if (err) {
                fprintf(stderr, "%s eval: line %ld: %s (expected %d numbers:", prog, lineno, err, k->n_inputs);
                for (i = 0; i < k->n_inputs; i++)
                    fprintf(stderr, " %s", k->inputs[i]);
                fprintf(stderr, ")\n");
                return 2;
            }
            for (i = 0; i < k->n_inputs; i++)
                cols[i][n] = in[i];
            n++;
        }
        if (n == 0)
            break;
        {
            const float *ptr[FACET_MAX_INPUTS];
            for (i = 0; i < FACET_MAX_INPUTS; i++)
                ptr[i] = cols[i];
            k->f32_batch(out, ptr, (size_t)n);
        }
        for (i = 0; i < n; i++)
            printf("%.9g\n", out[i]);
    }
    if (ferror(stdin) || fflush(stdout) != 0) {
        fprintf(stderr, "%s eval: I/O error\n", prog);
        return 1;
    }
    return 0;
}

/* Verbs.  Parts of the library that bring a verb add a line here and
 * implement it in their own file under src/cli/. */
typedef struct {
    const char *name;
    int (*run)(int argc, char **argv); /* argv[0] is the verb */
} verb;

static const verb verbs[] = {
    { "list", cmd_list },
    { "eval", cmd_eval },
    { "vectors", facet_cli_vectors }, /* src/cli/fx.c */
};

int main(int argc, char **argv)
{
    size_t i;
    if (argc < 2) {
        usage_main(stderr);
        return 2;
    }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
        usage_main(stdout);
        return 0;
    }
    if (!strcmp(argv[1], "--version")) {
        printf("facet %s\n", FACET_VERSION);
        return 0;
    }
    for (i = 0; i < sizeof verbs / sizeof verbs[0]; i++)
        if (!strcmp(argv[1], verbs[i].name))
            return verbs[i].run(argc - 1, argv + 1);
    fprintf(stderr, "%s: unknown verb '%s'\n", prog, argv[1]);
    usage_main(stderr);
    return 2;
}
