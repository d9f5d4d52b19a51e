/* cli.h - what the facet command's verbs share. */
#ifndef FACET_CLI_H
#define FACET_CLI_H

/* Parses exactly n whitespace-separated decimal numbers from one input
 * line into out; returns NULL, or what is wrong with the line. */
const char *facet_cli_parse_numbers(const char *line, int n, double *out);

#endif
