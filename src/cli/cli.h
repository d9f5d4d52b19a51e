/* cli.h - what the facet command's verbs share: the input rules (one
 * sample per line, read by facet_cli_read_line; numbers parsed by
 * facet_cli_parse_*), the exit statuses, and the small helpers around them.
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

#endif
