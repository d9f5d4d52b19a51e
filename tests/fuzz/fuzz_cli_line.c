/* fuzz_cli_line.c - libFuzzer target for the facet command's input rules
 * (src/cli/parse.c): the fuzz input is a whole stdin.
 *   - the reader returns only lines without NUL, at most
 *     FACET_CLI_LINE_MAX long, not blank or comment; it stops at the first
 *     malformed line;
 *   - on every line and every count 1..6 the f32, f64 and Q15 parsers
 *     agree on the syntax (Q15 refuses exactly the lines with NaN or an
 *     infinity among the numbers it reads);
 *   - each number's Q15 value equals floor(d 32768 + 1/2) computed in
 *     double from d = strtod(token) wherever that is unambiguous (d away
 *     from a rounding tie by far more than its rounding), saturated to
 *     int32; and the f32 value is strtof of the token. */
#define _GNU_SOURCE /* fmemopen */
#include <math.h>
#include "cli.h"
#include "fuzz_common.h"

static int is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

/* the tokens of a line (as the parser splits it), one per call */
static size_t next_token(const char *s, size_t *p, char *tok, size_t cap)
{
    size_t e, len;
    while (s[*p] && is_blank(s[*p]))
        (*p)++;
    for (e = *p; s[e] && !is_blank(s[e]); e++)
        ;
    len = e - *p;
    if (len >= cap)
        len = cap - 1;
    memcpy(tok, s + *p, len);
    tok[len] = '\0';
    *p = e;
    return len;
}

static void check_line(const char *line)
{
    int n;
    for (n = 1; n <= 6; n++) {
        float f[6];
        double d[6];
        int32_t q[6];
        const char *ef = facet_cli_parse_f32(line, n, f), *ed = facet_cli_parse_f64(line, n, d);
        const char *eq = facet_cli_parse_q15(line, n, q);
        int i, special = 0;
        size_t p = 0;
        if ((ef == NULL) != (ed == NULL) || (ef && strcmp(ef, ed)))
            FUZZ_FAIL("f32 and f64 disagree on \"%s\" (n %d): %s / %s", line, n, ef ? ef : "ok", ed ? ed : "ok");
        if (ed)
            continue;
        for (i = 0; i < n; i++) {
            char tok[FACET_CLI_LINE_MAX + 1];
            size_t len = next_token(line, &p, tok, sizeof tok);
            double dv = strtod(tok, NULL), y, fl;
            int is_word = strpbrk(tok, "nNiI") != NULL; /* nan, inf, infinity */
            special |= is_word;
            if (f[i] != strtof(tok, NULL) && !(f[i] != f[i]))
                FUZZ_FAIL("\"%s\": f32 of %s is %a, strtof %a", line, tok, f[i], strtof(tok, NULL));
            if (eq || is_word || len == 0)
                continue;
            /* the double reference, where it is unambiguous */
            if (fabs(dv) >= 65537.0) {
                if (q[i] != (dv > 0 ? INT32_MAX : INT32_MIN))
                    FUZZ_FAIL("\"%s\": %s gives %ld, not saturated", line, tok, (long)q[i]);
                continue;
            }
            y = dv * 32768.0;
            fl = floor(y);
            if (fabs((y - fl) - 0.5) > 1e-6 * (1.0 + fabs(y)) && fabs(y - fl) > 1e-6 * (1.0 + fabs(y)) &&
                fabs(y - fl - 1.0) > 1e-6 * (1.0 + fabs(y))) {
                int64_t want = (int64_t)fl + (y - fl >= 0.5);
                want = want > INT32_MAX ? INT32_MAX : want < INT32_MIN ? INT32_MIN : want;
                if (q[i] != want)
                    FUZZ_FAIL("\"%s\": Q15 of %s is %ld, via double %lld", line, tok, (long)q[i], (long long)want);
            }
        }
        if ((eq == NULL) == special)
            FUZZ_FAIL("\"%s\" (n %d): Q15 says %s, f64 ok, NaN/Inf among them: %d", line, n, eq ? eq : "ok", special);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    facet_cli_reader r;
    const char *err = NULL;
    int got;
    long last = 0;
    FILE *f;
    if (size == 0)
        return 0;
    f = fmemopen((void *)data, size, "r");
    if (!f)
        return 0;
    r.f = f;
    r.lineno = 0;
    while ((got = facet_cli_read_line(&r, &err)) == 1) {
        int skip;
        size_t k;
        if (r.len > FACET_CLI_LINE_MAX || strlen(r.buf) != r.len)
            FUZZ_FAIL("line %ld: length %zu, strlen %zu", r.lineno, r.len, strlen(r.buf));
        if (facet_cli_check_line(r.buf, r.len, &skip) || skip)
            FUZZ_FAIL("line %ld returned though blank, comment or NUL", r.lineno);
        for (k = 0; k < r.len; k++)
            if (r.buf[k] == '\n')
                FUZZ_FAIL("line %ld holds a newline", r.lineno);
        if (r.lineno <= last)
            FUZZ_FAIL("line numbers do not increase: %ld after %ld", r.lineno, last);
        last = r.lineno;
        check_line(r.buf);
    }
    if (got == -1) {
        /* a reported line must be bad: it holds a NUL or is too long */
        if (strcmp(err, "contains a NUL byte") && strncmp(err, "longer than", 11))
            FUZZ_FAIL("unexpected reader error '%s'", err);
        if (!strcmp(err, "contains a NUL byte") && !memchr(data, '\0', size))
            FUZZ_FAIL("NUL reported in an input without one");
    }
    fclose(f);
    /* the whole input as one token, too */
    {
        int32_t q;
        (void)facet_cli_decimal_to_q15((const char *)data, size, &q);
    }
    return 0;
}
