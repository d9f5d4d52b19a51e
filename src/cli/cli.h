/* cli.h - what the facet command's files share: the input rules (one
 * sample per line, read by facet_cli_read_line; numbers parsed by
 * facet_cli_parse_*), the exit statuses, the one line-evaluation loop every
 * form of `facet eval` runs (facet_cli_eval_lines), the argument reader of
 * the verbs that take a NAME and options, and the verbs themselves.
 *
 * The files, by role:
 *   facet.c  main, the verb table, the help texts and reports every verb
 *            shares, the argument reader;
 *   info.c   list, ports (what is compiled in);
 *   eval.c   eval in the float formats: kernels and samplers, f32 and
 *            f32_fast batches, the double oracle;
 *   fx.c     eval --format fx|fx_fast, and vectors;
 *   lines.c  the line-evaluation loop and the reports that end a run;
 *   parse.c  the input rules (reading lines, parsing numbers), the
 *            did-you-mean hint.
 *
 * Input rules (the same for every format):
 *   - a line ends at '\n' (the last line may lack it); at most
 *     FACET_CLI_LINE_MAX characters, not counting the '\n';
 *   - a NUL byte anywhere in a line is an error ("contains a NUL byte");
 *   - white space is ' ', '\t', '\r', '\v' and '\f';
 *   - a blank line, or one whose first non-blank character is '#', is
 *     skipped (it still counts for the line numbers of error messages);
 *   - a number is a decimal: [+-] digits [. digits] [e|E [+-] digits]
 *     (digits on at least one side of the point), or, for the float
 *     formats only, nan, inf or infinity (any case, optional sign); no hex.
 * Exit statuses: FACET_EXIT_OK, FACET_EXIT_IO (reading stdin or writing
 * stdout failed), FACET_EXIT_USAGE (bad arguments or malformed input). */
#ifndef FACET_CLI_H
#define FACET_CLI_H

#include <stdint.h>
#include <stdio.h>

#define FACET_EXIT_OK 0
#define FACET_EXIT_IO 1
#define FACET_EXIT_USAGE 2

#define FACET_CLI_LINE_MAX 4094

typedef struct {
    FILE *f;
    long lineno;                        /* of the line last returned */
    char buf[FACET_CLI_LINE_MAX + 1];   /* the line, NUL-terminated, no '\n' */
    size_t len;
} facet_cli_reader;

/* The next line that is not blank or a comment into r->buf.  Returns 1 for
 * a line, 0 at the end of the input, -1 for a malformed line (*err says
 * why; r->lineno is its number), -2 for a read error. */
int facet_cli_read_line(facet_cli_reader *r, const char **err);

/* Classifies a line of len bytes (no '\n'): NULL if it is fine, else what
 * is wrong with it (a NUL byte); *skip = 1 for a blank or comment line. */
const char *facet_cli_check_line(const char *line, size_t len, int *skip);

/* Exactly n numbers from a NUL-terminated line; NULL or what is wrong.
 *   f32: rounded once, to nearest float (strtof);
 *   f64: rounded once, to nearest double (strtod);
 *   q15: rounded once, exactly from the decimal digits, to
 *        floor(x 32768 + 1/2) (nearest, ties up), saturated to int32;
 *        NaN and infinity are refused. */
const char *facet_cli_parse_f32(const char *line, int n, float *out);
const char *facet_cli_parse_f64(const char *line, int n, double *out);
const char *facet_cli_parse_q15(const char *line, int n, int32_t *out);

/* The same, the number format as a value (out: n of its type) */
typedef enum { FACET_CLI_F32, FACET_CLI_F64, FACET_CLI_Q15 } facet_cli_number;
const char *facet_cli_parse(const char *line, int n, facet_cli_number to, void *out);

/* One decimal token (len bytes, syntax as above, no NaN/Inf) to Q15 as
 * facet_cli_parse_q15 does; 0 if it is not a decimal number (or longer
 * than FACET_CLI_LINE_MAX). */
int facet_cli_decimal_to_q15(const char *s, size_t len, int32_t *raw);

/* The closest of names[0..n-1] to name by edit distance, if close enough
 * to be a likely typo; NULL otherwise. */
const char *facet_cli_suggest(const char *name, const char *const *names, size_t n);

/* Flushes stdout; on failure reports "facet VERB: I/O error writing
 * output" and returns FACET_EXIT_IO, else FACET_EXIT_OK. */
int facet_cli_finish(const char *verb);

/* "facet eval: line N: ERR (expected n numbers: NAME ...)" on stderr: the
 * report of a malformed line, the same for every kind of kernel */
void facet_cli_line_error(long lineno, const char *err, int n, const char *const *names);

/* ---- the line-evaluation loop ---------------------------------------------
 * Every form of `facet eval` reads stdin by the input rules, parses each
 * line into a row of numbers (e->number), and after e->chunk rows, at the
 * end of the input, or before a malformed line is reported, hands the rows
 * read to e->flush, which evaluates them and prints one output line each.
 * A batch kernel takes a chunk of lines per call; a form evaluated line by
 * line (the oracle, fixed point) has chunk 1, so each output line follows
 * its input line.  Ends at the end of the input (FACET_EXIT_OK), at the
 * first malformed line (the lines before it are printed, the error goes to
 * stderr: FACET_EXIT_USAGE), or at a read or write error (FACET_EXIT_IO). */
#define FACET_CLI_CHUNK 1024     /* rows per flush at most */
#define FACET_CLI_MAX_INPUTS 8   /* numbers per line at most (every table's max) */

typedef union { /* the rows read, in the type of e->number */
    float f32[FACET_CLI_CHUNK][FACET_CLI_MAX_INPUTS];
    double f64[FACET_CLI_CHUNK][FACET_CLI_MAX_INPUTS];
    int32_t q15[FACET_CLI_CHUNK][FACET_CLI_MAX_INPUTS];
} facet_cli_rows;

typedef struct facet_cli_evaluator facet_cli_evaluator;
struct facet_cli_evaluator {
    facet_cli_number number;        /* how a line is parsed */
    size_t chunk;                   /* 1 .. FACET_CLI_CHUNK */
    int n_inputs;                   /* numbers per line, and their names */
    const char *const *inputs;      /* (for the report of a malformed line) */
    /* evaluates rows 0 .. n-1 and prints one line each */
    void (*flush)(const facet_cli_evaluator *e, const facet_cli_rows *rows, size_t n);
    const void *what;               /* the kernel or sampler flush evaluates */
    int fast;                       /* the fast tier */
    int raw;                        /* fixed point: raw integers out */
};

int facet_cli_eval_lines(const facet_cli_evaluator *e);

/* Rows 0 .. n-1 of f32 numbers as columns, for a batch call:
 * in[i][s] = rows->f32[s][i] for every i < FACET_CLI_MAX_INPUTS */
void facet_cli_f32_columns(const facet_cli_rows *rows, size_t n, const float **in);

/* ---- the verbs and what they share (facet.c) --------------------------- */
extern const char facet_cli_input_help[], facet_cli_exit_help[]; /* for --help texts */

/* "facet VERB: unknown WHAT 'NAME'" with a did-you-mean hint among the kernels */
void facet_cli_unknown_kernel(const char *verb, const char *what, const char *name);

/* The arguments of `facet VERB [NAME] [options]` (argv[0] is VERB), read one
 * at a time by facet_cli_next_arg: --help or -h prints the usage on stdout;
 * an option of opts (a flag, or one with a value: the next argument);
 * the first argument that is not an option is NAME ("-" alone is one); an
 * unknown option, or one lacking its value, is reported with the usage on
 * stderr; a second NAME is reported as an unexpected argument. */
typedef struct {
    const char *name;  /* "--format" */
    int has_value;
} facet_cli_option;

typedef struct {
    int argc;
    char **argv;
    const char *verb;                /* "eval" */
    const facet_cli_option *opts;    /* ends with a NULL name */
    void (*usage)(FILE *f);
    int i;                           /* the argument last read */
    int named;                       /* NAME has been read */
    int status;                      /* the exit status, after FACET_CLI_ARG_DONE */
} facet_cli_args;

#define FACET_CLI_ARG_END (-1)   /* no argument left */
#define FACET_CLI_ARG_DONE (-2)  /* help printed, or an error reported: exit with a->status */
#define FACET_CLI_ARG_NAME (-3)  /* NAME, in *value */

/* the reader of argv (argv[0] is VERB), before its first argument */
facet_cli_args facet_cli_args_of(int argc, char **argv, const char *verb, const facet_cli_option *opts,
                                 void (*usage)(FILE *f));

/* The next argument: the index in a->opts of an option (*value: its value,
 * NULL for a flag), or one of FACET_CLI_ARG_* */
int facet_cli_next_arg(facet_cli_args *a, const char **value);

/* the verbs: argv[0] is the verb; each returns the exit status */
int facet_cli_list(int argc, char **argv);    /* info.c */
int facet_cli_ports(int argc, char **argv);   /* info.c */
int facet_cli_eval(int argc, char **argv);    /* eval.c: hands --format fx|fx_fast to fx.c */
int facet_cli_fx_eval(int argc, char **argv); /* fx.c */
int facet_cli_vectors(int argc, char **argv); /* fx.c */

#endif
