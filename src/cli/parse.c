/* parse.c - the one sample-line parser of the facet command. */
#include <stdlib.h>
#include <string.h>
#include "cli.h"

const char *facet_cli_parse_numbers(const char *line, int n, double *out)
{
    const char *p = line;
    char *end;
    int i;
    for (i = 0; i < n; i++) {
        while (*p == ' ' || *p == '\t' || *p == '\r')
            p++;
        if (*p == '\0' || *p == '\n')
            return "too few inputs";
        out[i] = strtod(p, &end);
        if (end == p || (*end && !strchr(" \t\r\n", *end)))
            return "not a decimal number";
        p = end;
    }
    while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n')
        p++;
    return *p ? "too many inputs" : NULL;
}
