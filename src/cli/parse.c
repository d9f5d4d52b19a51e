/* parse.c - the facet command's input rules (cli.h): reading lines,
 * skipping blank and comment lines, and parsing the numbers on a line, one
 * implementation for every format; and the did-you-mean hint. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"

#define STR_(x) #x
#define STR(x) STR_(x)

static int is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

static int is_digit(char c) { return c >= '0' && c <= '9'; }

static char lower(char c) { return c >= 'A' && c <= 'Z' ? (char)(c - 'A' + 'a') : c; }

const char *facet_cli_check_line(const char *line, size_t len, int *skip)
{
    size_t i = 0;
    if (memchr(line, '\0', len))
        return "contains a NUL byte";
    while (i < len && is_blank(line[i]))
        i++;
    *skip = i == len || line[i] == '#';
    return NULL;
}

int facet_cli_read_line(facet_cli_reader *r, const char **err)
{
    for (;;) {
        int c = 0, skip;
        size_t len = 0;
        int nul = 0;
        while ((c = getc(r->f)) != EOF && c != '\n') {
            if (c == '\0')
                nul = 1;
            if (len == FACET_CLI_LINE_MAX) {
                r->lineno++;
                *err = nul ? "contains a NUL byte" : "longer than " STR(FACET_CLI_LINE_MAX) " characters";
                return -1;
            }
            r->buf[len++] = (char)c;
        }
        if (c == EOF && ferror(r->f))
            return -2;
        if (c == EOF && len == 0)
            return 0;
        r->lineno++;
        r->buf[len] = '\0';
        r->len = len;
        *err = facet_cli_check_line(r->buf, len, &skip);
        if (*err)
            return -1;
        if (!skip)
            return 1;
    }
}

/* ---- tokens ---------------------------------------------------------------
 * scan_number: the length of the decimal number at s (0 if there is none);
 * *special = 1 for nan/inf/infinity (then the length covers the word). */
static size_t scan_number(const char *s, size_t len, int *special)
{
    size_t i = 0, mant = 0;
    static const char *const words[] = { "infinity", "inf", "nan" };
    size_t w;
    *special = 0;
    if (i < len && (s[i] == '+' || s[i] == '-'))
        i++;
    for (w = 0; w < sizeof words / sizeof words[0]; w++) {
        size_t k = 0, wl = strlen(words[w]);
        while (k < wl && i + k < len && lower(s[i + k]) == words[w][k])
            k++;
        if (k == wl) {
            *special = 1;
            return i + k;
        }
    }
    while (i < len && is_digit(s[i]))
        i++, mant++;
    if (i < len && s[i] == '.') {
        i++;
        while (i < len && is_digit(s[i]))
            i++, mant++;
    }
    if (mant == 0)
        return 0;
    if (i < len && (s[i] == 'e' || s[i] == 'E')) {
        size_t j = i + 1;
        if (j < len && (s[j] == '+' || s[j] == '-'))
            j++;
        if (j < len && is_digit(s[j])) {
            while (j < len && is_digit(s[j]))
                j++;
            i = j;
        } else {
            return 0; /* "1e", "1e+": not a number */
        }
    }
    return i;
}

const char *facet_cli_parse(const char *line, int n, facet_cli_number to, void *out)
{
    size_t len = strlen(line), p = 0;
    int i;
    for (i = 0; i < n; i++) {
        size_t tl, e;
        int special;
        char tok[FACET_CLI_LINE_MAX + 1];
        while (p < len && is_blank(line[p]))
            p++;
        if (p == len)
            return "too few inputs";
        for (e = p; e < len && !is_blank(line[e]); e++)
            ;
        tl = scan_number(line + p, e - p, &special);
        if (tl == 0 || tl != e - p)
            return "not a decimal number";
        if (to == FACET_CLI_Q15) {
            if (special)
                return "not a finite number (fixed point has no NaN or infinity)";
            if (!facet_cli_decimal_to_q15(line + p, tl, (int32_t *)out + i))
                return "not a decimal number";
        } else {
            memcpy(tok, line + p, tl);
            tok[tl] = '\0';
            errno = 0; /* ERANGE is fine: overflow gives +-Inf, underflow 0 or a denormal */
            if (to == FACET_CLI_F32)
                ((float *)out)[i] = strtof(tok, NULL);
            else
                ((double *)out)[i] = strtod(tok, NULL);
        }
        p = e;
    }
    while (p < len && is_blank(line[p]))
        p++;
    return p < len ? "too many inputs" : NULL;
}

const char *facet_cli_parse_f32(const char *line, int n, float *out) { return facet_cli_parse(line, n, FACET_CLI_F32, out); }
const char *facet_cli_parse_f64(const char *line, int n, double *out) { return facet_cli_parse(line, n, FACET_CLI_F64, out); }
const char *facet_cli_parse_q15(const char *line, int n, int32_t *out) { return facet_cli_parse(line, n, FACET_CLI_Q15, out); }

/* ---- exact decimal -> Q15 -------------------------------------------------
 * x = +-0.D x 10^P (D the significant digits, no leading zero).  For
 * |x| >= 10^5 the result saturates; for |x| < 10^-5 (< 2^-16, so
 * |x| 32768 < 1/2) it is 0.  Otherwise |x| = I + F with I < 10^5 and F the
 * fraction digits; F 32768 = J + G is formed exactly by multiplying the
 * fraction's digit string by 32768 (the carry out is J, the digits left are
 * G), and the rounding needs only whether G >= 1/2 (first digit >= 5) and
 * whether G > 1/2.  floor(x 32768 + 1/2): +(A + [G >= 1/2]) for x >= 0,
 * -(A + [G > 1/2]) for x < 0, A = 32768 I + J. */
int facet_cli_decimal_to_q15(const char *s, size_t len, int32_t *raw)
{
    char frac[FACET_CLI_LINE_MAX + 8];
    size_t i = 0, nd = 0, nf = 0, k;
    int neg = 0, special;
    long p = 0, ex = 0, exsign = 1;
    int64_t a, ip = 0;
    unsigned carry;
    int ge_half, gt_half;
    const char *digits[2];
    size_t dlen[2];
    if (len == 0 || len > FACET_CLI_LINE_MAX || scan_number(s, len, &special) != len || special)
        return 0;
    if (s[i] == '+' || s[i] == '-')
        neg = s[i++] == '-';
    /* the digits before and after the point */
    digits[0] = s + i;
    while (i < len && is_digit(s[i]))
        i++;
    dlen[0] = (size_t)(s + i - digits[0]);
    digits[1] = s + i;
    dlen[1] = 0;
    if (i < len && s[i] == '.') {
        digits[1] = s + ++i;
        while (i < len && is_digit(s[i]))
            i++;
        dlen[1] = (size_t)(s + i - digits[1]);
    }
    if (i < len) { /* exponent, saturated: beyond +-10^6 the answer is 0 or saturation anyway */
        i++;
        if (s[i] == '+' || s[i] == '-')
            exsign = s[i++] == '-' ? -1 : 1;
        for (; i < len; i++)
            if (ex < 1000000)
                ex = ex * 10 + (s[i] - '0');
        ex *= exsign;
    }
    /* strip leading zeros: P = (digits before the point) - (leading zeros) + exponent */
    {
        size_t z = 0;
        const char *d = digits[0];
        while (z < dlen[0] && d[z] == '0')
            z++;
        if (z < dlen[0]) {
            p = (long)(dlen[0] - z);
            digits[0] += z;
            dlen[0] -= z;
        } else {
            size_t z1 = 0;
            dlen[0] = 0;
            while (z1 < dlen[1] && digits[1][z1] == '0')
                z1++;
            p = -(long)z1;
            digits[1] += z1;
            dlen[1] -= z1;
        }
    }
    nd = dlen[0] + dlen[1];
    {
        /* all-zero trailing digits do not matter; no significant digit: 0 */
        int any = 0;
        for (k = 0; k < nd && !any; k++)
            any = (k < dlen[0] ? digits[0][k] : digits[1][k - dlen[0]]) != '0';
        if (!any) {
            *raw = 0;
            return 1;
        }
    }
    p += ex;
    if (p > 5) {
        *raw = neg ? INT32_MIN : INT32_MAX;
        return 1;
    }
    if (p < -4) {
        *raw = 0;
        return 1;
    }
    /* integer part: the first p significant digits; fraction: -p zeros, then the rest */
    for (k = 0; k < nd; k++) {
        char c = k < dlen[0] ? digits[0][k] : digits[1][k - dlen[0]];
        if ((long)k < p)
            ip = ip * 10 + (c - '0');
        else
            frac[nf++] = c;
    }
    for (k = nd; (long)k < p; k++) /* p > nd: trailing zeros of I */
        ip *= 10;
    if (p < 0) {
        memmove(frac + (-p), frac, nf);
        memset(frac, '0', (size_t)(-p));
        nf += (size_t)(-p);
    }
    /* F 32768 = J + G */
    carry = 0;
    for (k = nf; k-- > 0;) {
        unsigned v = (unsigned)(frac[k] - '0') * 32768u + carry;
        frac[k] = (char)('0' + v % 10);
        carry = v / 10;
    }
    ge_half = nf > 0 && frac[0] >= '5';
    gt_half = 0;
    if (nf > 0 && frac[0] > '5')
        gt_half = 1;
    else if (nf > 0 && frac[0] == '5')
        for (k = 1; k < nf && !gt_half; k++)
            gt_half = frac[k] != '0';
    a = ip * 32768 + (int64_t)carry;
    a = neg ? -(a + gt_half) : a + ge_half;
    *raw = a > INT32_MAX ? INT32_MAX : a < INT32_MIN ? INT32_MIN : (int32_t)a;
    return 1;
}

/* ---- "did you mean" ------------------------------------------------------- */
static size_t edit_distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b), i, j, row[64];
    if (la >= 63 || lb >= 63)
        return (size_t)-1;
    for (j = 0; j <= lb; j++)
        row[j] = j;
    for (i = 1; i <= la; i++) {
        size_t diag = row[0], next;
        row[0] = i;
        for (j = 1; j <= lb; j++) {
            size_t best = diag + (a[i - 1] != b[j - 1]);
            if (row[j] + 1 < best)
                best = row[j] + 1;
            if (row[j - 1] + 1 < best)
                best = row[j - 1] + 1;
            next = row[j];
            row[j] = best;
            diag = next;
        }
    }
    return row[lb];
}

const char *facet_cli_suggest(const char *name, const char *const *names, size_t n)
{
    size_t i, best = (size_t)-1, limit = strlen(name) / 3 + 1;
    const char *pick = NULL;
    for (i = 0; i < n; i++) {
        size_t d = edit_distance(name, names[i]);
        if (d < best) {
            best = d;
            pick = names[i];
        }
    }
    if (limit > 4)
        limit = 4;
    if (best <= limit)
        return pick;
    /* else a part of exactly one name ("brdf" -> brdf_hammon) */
    pick = NULL;
    for (i = 0; i < n && *name; i++)
        if (strstr(names[i], name)) {
            if (pick)
                return NULL;
            pick = names[i];
        }
    return pick;
}
