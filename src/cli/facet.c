/* facet - the command-line face of the library.
 *   facet list | ports
 *   facet eval KERNEL [--format f32|f32_fast|fx|fx_fast] [--oracle] [--port P]
 *   facet vectors KERNEL [--format fx|fx_fast] [--count N] [--seed S] [--hex]
 * This file: main, the verb table, and what the verbs share (the help
 * texts, the unknown-kernel report, the argument reader); the verbs live in
 * the files cli.h names.  Input rules and exit statuses: src/cli/cli.h (0
 * success, 1 I/O error, 2 usage error or malformed input), the same for
 * every verb. */
#include <stdio.h>
#include <string.h>
#include "facet.h"
#include "cli.h"

static const char *prog = "facet";

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

static void kernel_names(const char **names, size_t cap, size_t *n)
{
    size_t i;
    *n = facet_kernel_count() < cap ? facet_kernel_count() : cap;
    for (i = 0; i < *n; i++)
        names[i] = facet_kernel_at(i)->name;
}

/* "unknown kernel" with a did-you-mean hint */
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

facet_cli_args facet_cli_args_of(int argc, char **argv, const char *verb, const facet_cli_option *opts,
                                 void (*usage)(FILE *f))
{
    facet_cli_args a;
    a.argc = argc;
    a.argv = argv;
    a.verb = verb;
    a.opts = opts;
    a.usage = usage;
    a.i = 0;
    a.named = 0;
    a.status = FACET_EXIT_OK;
    return a;
}

int facet_cli_next_arg(facet_cli_args *a, const char **value)
{
    const char *arg;
    const facet_cli_option *o;
    if (++a->i >= a->argc)
        return FACET_CLI_ARG_END;
    arg = a->argv[a->i];
    *value = NULL;
    if (!strcmp(arg, "--help") || !strcmp(arg, "-h")) {
        a->usage(stdout);
        a->status = facet_cli_finish(a->verb);
        return FACET_CLI_ARG_DONE;
    }
    for (o = a->opts; o->name; o++)
        if (!strcmp(arg, o->name) && (!o->has_value || a->i + 1 < a->argc)) {
            if (o->has_value)
                *value = a->argv[++a->i];
            return (int)(o - a->opts);
        }
    a->status = FACET_EXIT_USAGE;
    if (arg[0] == '-' && arg[1] != '\0') {
        fprintf(stderr, "%s %s: unknown or incomplete option '%s'\n", prog, a->verb, arg);
        a->usage(stderr);
        return FACET_CLI_ARG_DONE;
    }
    if (a->named) {
        fprintf(stderr, "%s %s: unexpected argument '%s'\n", prog, a->verb, arg);
        return FACET_CLI_ARG_DONE;
    }
    a->named = 1;
    *value = arg;
    return FACET_CLI_ARG_NAME;
}

/* Verbs.  Parts of the library that bring a verb add a line here, declare
 * it in cli.h and implement it in their own file under src/cli/. */
typedef struct {
    const char *name;
    int (*run)(int argc, char **argv); /* argv[0] is the verb */
} verb;

static const verb verbs[] = {
    { "list", facet_cli_list },       /* info.c */
    { "ports", facet_cli_ports },     /* info.c */
    { "eval", facet_cli_eval },       /* eval.c */
    { "vectors", facet_cli_vectors }, /* fx.c */
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
