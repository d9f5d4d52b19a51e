/* harness.h - the tiny test harness every test binary uses.
 * A test binary prints one line per failed check, and ends with
 *   <name>: N passed, N failed, N skipped
 * which tests/check.sh sums into the closing line of make check. */
#ifndef FACET_TEST_HARNESS_H
#define FACET_TEST_HARNESS_H

#include <stdio.h>
#include <stdarg.h>

static int th_pass, th_fail, th_skip;
static const char *th_name = "test";

static inline void th_check(int ok, const char *fmt, ...)
{
    if (ok) {
        th_pass++;
        return;
    }
    th_fail++;
    {
        va_list ap;
        va_start(ap, fmt);
        fprintf(stdout, "FAIL %s: ", th_name);
        vfprintf(stdout, fmt, ap);
        fputc('\n', stdout);
        va_end(ap);
    }
}

static inline void th_skip_(const char *fmt, ...)
{
    va_list ap;
    th_skip++;
    va_start(ap, fmt);
    fprintf(stdout, "SKIP %s: ", th_name);
    vfprintf(stdout, fmt, ap);
    fputc('\n', stdout);
    va_end(ap);
}

#define CHECK(cond, ...) th_check(!!(cond), __VA_ARGS__)
#define SKIP(...) th_skip_(__VA_ARGS__)

static inline int th_done(void)
{
    printf("%s: %d passed, %d failed, %d skipped\n", th_name, th_pass, th_fail, th_skip);
    return th_fail ? 1 : 0;
}

#endif
