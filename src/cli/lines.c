/* lines.c - the one line-evaluation loop of `facet eval` (cli.h): read a
 * line, parse it, evaluate a chunk of rows, print, and the reports that end
 * a run; what a line is parsed as and how rows are evaluated and printed
 * is the caller's (facet_cli_evaluator). */
#include <stdio.h>
#include "facet.h"
#include "facet/fx.h"
#include "cli.h"

/* a row holds the inputs of any table's kernel */
typedef char max_inputs_covers_kernels[FACET_CLI_MAX_INPUTS >= FACET_MAX_INPUTS ? 1 : -1];
typedef char max_inputs_covers_samplers[FACET_CLI_MAX_INPUTS >= FACET_SAMPLER_MAX_INPUTS ? 1 : -1];
typedef char max_inputs_covers_fx[FACET_CLI_MAX_INPUTS >= FACET_FX_MAX_INPUTS ? 1 : -1];

static facet_cli_rows rows;

static void *row(facet_cli_number number, size_t s)
{
    return number == FACET_CLI_F32 ? (void *)rows.f32[s] : number == FACET_CLI_F64 ? (void *)rows.f64[s]
                                                                                    : (void *)rows.q15[s];
}

int facet_cli_eval_lines(const facet_cli_evaluator *e)
{
    facet_cli_reader r;
    const char *err = NULL;
    int got = 1;
    r.f = stdin;
    r.lineno = 0;
    while (got == 1) {
        size_t n = 0;
        /* a chunk of lines; a malformed one ends the chunk, and the run
         * after the lines before it are printed */
        while (n < e->chunk && (got = facet_cli_read_line(&r, &err)) == 1) {
            err = facet_cli_parse(r.buf, e->n_inputs, e->number, row(e->number, n));
            if (err) {
                got = -1;
                break;
            }
            n++;
        }
        if (n > 0) {
            e->flush(e, &rows, n);
            if (ferror(stdout))
                return facet_cli_finish("eval");
        }
    }
    if (got == -2) {
        fprintf(stderr, "facet eval: error reading the input\n");
        return FACET_EXIT_IO;
    }
    if (got == -1) {
        int rc = facet_cli_finish("eval");
        facet_cli_line_error(r.lineno, err, e->n_inputs, e->inputs);
        return rc ? rc : FACET_EXIT_USAGE;
    }
    return facet_cli_finish("eval");
}

void facet_cli_f32_columns(const facet_cli_rows *in_rows, size_t n, const float **in)
{
    static float cols[FACET_CLI_MAX_INPUTS][FACET_CLI_CHUNK];
    size_t s;
    int i;
    for (i = 0; i < FACET_CLI_MAX_INPUTS; i++) {
        for (s = 0; s < n; s++)
            cols[i][s] = in_rows->f32[s][i];
        in[i] = cols[i];
    }
}

int facet_cli_finish(const char *verb)
{
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "facet %s: I/O error writing the output\n", verb);
        return FACET_EXIT_IO;
    }
    return FACET_EXIT_OK;
}

void facet_cli_line_error(long lineno, const char *err, int n, const char *const *names)
{
    int i;
    fprintf(stderr, "facet eval: line %ld: %s (expected %d numbers:", lineno, err, n);
    for (i = 0; i < n; i++)
        fprintf(stderr, " %s", names[i]);
    fprintf(stderr, ")\n");
}
