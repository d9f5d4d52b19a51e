/* test_cli_parse.c - the facet command's input rules (src/cli/parse.c):
 * decimal -> Q15 rounded exactly from the digits (ties, just below and just
 * above them, both signs, saturation of any finite value), decimal -> float
 * rounded once, the token syntax, and the line reader (NUL bytes, blank and
 * comment lines, long lines, a last line without a newline). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../lib/harness.h"
#include "cli.h"

static int q15(const char *s, int32_t *raw) { return facet_cli_decimal_to_q15(s, strlen(s), raw); }

/* the exact decimal of (2 r + half) / 65536, r >= 0, half in {0, 1} */
static void exact(char *buf, size_t size, const char *sign, uint32_t r, int half)
{
    uint64_t w = 2 * (uint64_t)r + (uint64_t)half; /* / 2^16 */
    snprintf(buf, size, "%s%llu.%016llu", sign, (unsigned long long)(w >> 16),
             (unsigned long long)((w & 65535u) * 152587890625ull)); /* 5^16 */
}

/* FACET_TEST_QUICK (sanitizers, qemu-user): a tenth of the random cases */
static long cases_(long n)
{
    const char *q = getenv("FACET_TEST_QUICK");
    return q && *q && strcmp(q, "0") ? n / 10 : n;
}

static int32_t sat(int64_t x) { return x > INT32_MAX ? INT32_MAX : x < INT32_MIN ? INT32_MIN : (int32_t)x; }

static void check_q15_ties(void)
{
    uint64_t s = 0x5eed;
    long bad = 0, n = 0, i;
    for (i = 0; i < cases_(300000); i++) {
        char t[96], u[160];
        uint32_t r;
        int32_t got;
        size_t len;
        if (i < 140000)
            r = (uint32_t)i; /* every raw value up to ~4.3 */
        else {
            s = s * 6364136223846793005ull + 1442695040888963407ull;
            r = (uint32_t)(s >> 33); /* up to 2^31 */
        }
        /* exactly r: r, and -r */
        exact(t, sizeof t, "", r, 0);
        bad += !q15(t, &got) || got != sat(r);
        exact(t, sizeof t, "-", r, 0);
        bad += !q15(t, &got) || got != sat(-(int64_t)r);
        /* the tie (r + 1/2): up to r + 1; -(r + 1/2) up to -r */
        exact(t, sizeof t, "", r, 1);
        bad += !q15(t, &got) || got != sat((int64_t)r + 1);
        exact(t, sizeof t, "-", r, 1);
        bad += !q15(t, &got) || got != sat(-(int64_t)r);
        /* 10^-40 below the tie (its last digit is 5: make it 4999...):
         * r for x > 0; 10^-40 beyond it for x < 0: -(r + 1) */
        exact(t, sizeof t, "", r, 1);
        len = strlen(t);
        t[len - 1] = '4';
        snprintf(u, sizeof u, "%s999999999999999999999999", t);
        bad += !q15(u, &got) || got != sat(r);
        exact(t, sizeof t, "-", r, 1);
        snprintf(u, sizeof u, "%s000000000000000000000001", t);
        bad += !q15(u, &got) || got != sat(-(int64_t)r - 1);
        /* and the same in exponent form: digits shifted by e-3 / e+3 */
        exact(t, sizeof t, "", r, 1);
        snprintf(u, sizeof u, "%s000001e0", t);
        bad += !q15(u, &got) || got != sat((int64_t)r + 1);
        n += 7;
    }
    CHECK(bad == 0, "decimal -> Q15 at exact values, ties and 10^-40 either side: %ld of %ld wrong", bad, n);
}

/* doubles printed exactly (%.100f is exact for |d| >= 2^-47 here) against
 * floor(d 32768 + 1/2) done exactly in double */
static void check_q15_doubles(void)
{
    uint64_t s = 0xd0b1e;
    long bad = 0, i;
    char buf[256], where[300] = "";
    for (i = 0; i < cases_(200000); i++) {
        double d, y, fl;
        int64_t want;
        int32_t got;
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        d = ldexp((double)(s >> 11), -53 - (int)((s >> 3) % 24) + 17); /* [0, 2^17), many scales */
        if (i % 3 == 0)
            d = (floor(d * 32768.0) + 0.5) / 32768.0; /* a tie */
        if (s & 4)
            d = -d;
        y = d * 32768.0;
        fl = floor(y);
        want = (int64_t)fl + (y - fl >= 0.5);
        snprintf(buf, sizeof buf, "%.100f", d);
        if (!q15(buf, &got) || got != sat(want)) {
            if (!bad)
                snprintf(where, sizeof where, "%s -> %ld, want %ld", buf, (long)got, (long)sat(want));
            bad++;
        }
    }
    CHECK(bad == 0, "decimal -> Q15 of exactly printed doubles: %ld wrong, first %s", bad, where);
}

static void check_q15_forms(void)
{
    static const struct { const char *s; int32_t want; } ok[] = {
        { "0.5", 16384 }, { ".5", 16384 }, { "5e-1", 16384 }, { "0.05E1", 16384 }, { "50000e-5", 16384 },
        { "000.500", 16384 }, { "+0.5", 16384 }, { "1", 32768 }, { "1.", 32768 }, { "-1", -32768 },
        { "0", 0 }, { "-0", 0 }, { "0e999999999999999999999", 0 }, { "0.0000000000e-3", 0 },
        { "1e-5", 0 }, { "1.6e-5", 1 }, { "-1.6e-5", -1 }, { "-1.5e-5", 0 },
        { "0.50001525878906249999999", 16384 }, { "0.500015258789062500", 16385 },
        { "65535.999969482421875", INT32_MAX }, { "65535.99993896484", INT32_MAX - 1 },
        { "65536", INT32_MAX }, { "-65536", INT32_MIN }, { "-65536.00001", INT32_MIN },
        { "-65535.999969482421875", -INT32_MAX }, { "1e301", INT32_MAX }, { "-1e301", INT32_MIN },
        { "1e999999999999999999999999", INT32_MAX }, { "1e-999999999999999999999", 0 },
        { "3.2768e4", 1073741824 }, { "0.000030517578125", 1 }, { "0.0000152587890625", 1 },
        { "-0.0000152587890625", 0 }, { "-0.00001525878906250001", -1 },
    };
    static const char *const bad[] = { "", ".", "e5", "1e", "1e+", "+", "-", "0x10", "1.2.3", "nan", "inf",
                                       "infinity", "1 2", "--1", "1e5.5", "1,5", "\xff" };
    size_t i;
    for (i = 0; i < sizeof ok / sizeof ok[0]; i++) {
        int32_t got = 12345;
        int r = q15(ok[i].s, &got);
        CHECK(r && got == ok[i].want, "q15(\"%s\") = %d, %ld; want %ld", ok[i].s, r, (long)got, (long)ok[i].want);
    }
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        int32_t got;
        CHECK(!q15(bad[i], &got), "q15(\"%s\") accepted", bad[i]);
    }
}

static void check_lines(void)
{
    static const struct { const char *line; int n; const char *err; } cases[] = {
        { "0.5 0.25", 2, NULL }, { " \t0.5\v0.25\f\r", 2, NULL }, { "0.5", 2, "too few inputs" },
        { "0.5 0.25 1", 2, "too many inputs" }, { "0.5 x", 2, "not a decimal number" },
        { "0.5 0.5x", 2, "not a decimal number" }, { "0x1p-1 0.5", 2, "not a decimal number" },
        { "nan 0.5", 2, NULL }, { "-inf INFINITY", 2, NULL },
    };
    size_t i;
    float f[2];
    int32_t q[2];
    double d[2];
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *e = facet_cli_parse_f32(cases[i].line, cases[i].n, f);
        CHECK(cases[i].err ? e && !strcmp(e, cases[i].err) : !e, "parse_f32(\"%s\"): %s, want %s", cases[i].line,
              e ? e : "ok", cases[i].err ? cases[i].err : "ok");
        e = facet_cli_parse_f64(cases[i].line, cases[i].n, d);
        CHECK(cases[i].err ? e && !strcmp(e, cases[i].err) : !e, "parse_f64(\"%s\"): %s", cases[i].line, e ? e : "ok");
    }
    CHECK(facet_cli_parse_q15("nan 0.5", 2, q) != NULL, "parse_q15 accepts nan");
    CHECK(facet_cli_parse_q15("0.5 -inf", 2, q) != NULL, "parse_q15 accepts -inf");
    CHECK(!facet_cli_parse_q15("1e301 -1e999", 2, q) && q[0] == INT32_MAX && q[1] == INT32_MIN,
          "parse_q15 saturates 1e301 and -1e999");
    /* one rounding to float: 0.5 + 2^-25 is a float tie (to even: 0.5); a
     * hair above it is 0.5 + 2^-24, though via double it would be the tie */
    CHECK(!facet_cli_parse_f32("0.5000000298023223876953125000001 0.5000000298023223876953125", 2, f) &&
              f[0] == 0.5f + 0x1p-24f && f[1] == 0.5f,
          "decimal -> float rounded twice: %.9g %.9g", f[0], f[1]);
    CHECK(!facet_cli_parse_f32("1e400 -1e400", 2, f) && isinf(f[0]) && f[0] > 0 && isinf(f[1]) && f[1] < 0,
          "1e400 is not +Inf for f32");
}

/* the reader over a byte string (may hold NULs) */
static int read_all(const char *bytes, size_t len, long *lines, char *errbuf, size_t errsize, long *errline)
{
    FILE *f = tmpfile();
    facet_cli_reader r;
    const char *err = NULL;
    int got;
    *lines = 0;
    *errline = 0;
    errbuf[0] = '\0';
    if (!f)
        return -3;
    fwrite(bytes, 1, len, f);
    rewind(f);
    r.f = f;
    r.lineno = 0;
    while ((got = facet_cli_read_line(&r, &err)) == 1)
        (*lines)++;
    if (got == -1) {
        snprintf(errbuf, errsize, "%s", err);
        *errline = r.lineno;
    }
    fclose(f);
    return got;
}

static void check_reader(void)
{
    static char longline[6000];
    struct { const char *bytes; size_t len; int got; long lines; const char *err; long errline; } c[] = {
        { "0.5 0.25\n", 9, 0, 1, "", 0 },
        { "0.5 0.25", 8, 0, 1, "", 0 }, /* last line without '\n' */
        { "# c\n\n \t\n0.5\n  # x\n\r\n", 20, 0, 1, "", 0 },
        { "0.5 0.25\0garbage", 16, -1, 0, "contains a NUL byte", 1 },
        { "1\n0.5 0.25\0x\n1\n", 15, -1, 1, "contains a NUL byte", 2 },
        { "# a\0comment\n", 12, -1, 0, "contains a NUL byte", 1 },
        { "\0", 1, -1, 0, "contains a NUL byte", 1 },
        { "", 0, 0, 0, "", 0 },
        { longline, 0, -1, 0, "longer than 4094 characters", 1 },
        { longline, 4094, 0, 1, "", 0 },
    };
    size_t i;
    memset(longline, '1', sizeof longline);
    c[8].len = sizeof longline;
    for (i = 0; i < sizeof c / sizeof c[0]; i++) {
        long lines, errline;
        char err[128];
        int got = read_all(c[i].bytes, c[i].len, &lines, err, sizeof err, &errline);
        CHECK(got == c[i].got && lines == c[i].lines && !strcmp(err, c[i].err) && errline == c[i].errline,
              "reader case %d: got %d, %ld lines, error '%s' at line %ld; want %d, %ld, '%s' at %ld", (int)i, got,
              lines, err, errline, c[i].got, c[i].lines, c[i].err, c[i].errline);
    }
}

static void check_suggest(void)
{
    static const char *const names[] = { "noh_from_dots", "ggx_d", "smith_g1", "smith_g2", "brdf_hammon",
                                         "diffuse_hammon" };
    const char *s;
    s = facet_cli_suggest("ggx_dd", names, 6);
    CHECK(s && !strcmp(s, "ggx_d"), "suggest(ggx_dd) = %s", s ? s : "NULL");
    s = facet_cli_suggest("smith_g3", names, 6);
    CHECK(s && (!strcmp(s, "smith_g1") || !strcmp(s, "smith_g2")), "suggest(smith_g3) = %s", s ? s : "NULL");
    s = facet_cli_suggest("brdf", names, 6);
    CHECK(s && !strcmp(s, "brdf_hammon"), "suggest(brdf) = %s", s ? s : "NULL");
    s = facet_cli_suggest("hammon", names, 6);
    CHECK(!s, "suggest(hammon) = %s (two names contain it)", s ? s : "NULL");
    s = facet_cli_suggest("completely_different", names, 6);
    CHECK(!s, "suggest(completely_different) = %s", s ? s : "NULL");
}

int main(void)
{
    th_name = "cli_parse";
    check_q15_forms();
    check_q15_ties();
    check_q15_doubles();
    check_lines();
    check_reader();
    check_suggest();
    return th_done();
}
