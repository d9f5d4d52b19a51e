/* test_docs.c - the bounds the README states for each f32 kernel, both
 * tiers, are the bounds facet.h documents and the tests enforce
 * (FACET_ERR_*_F32, FACET_ERR_*_F32_FAST), and every kernel
 * of the table has a README row.  Run from the source tree's top. */
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <string.h>
#include "../lib/harness.h"
#include "facet.h"

/* 1 if the file has every one of the phrases (white space runs count as
 * one blank, so line breaks do not matter; in a .h, so does the " * " that
 * starts a comment line) */
static int has_phrases(const char *path, const char *const *phrases, int n, const char **missing)
{
    static char text[1 << 20];
    size_t len = 0;
    int c, blank = 0, i, bol = 0, is_c = strstr(path, ".h") != NULL;
    FILE *f = fopen(path, "r");
    *missing = path;
    if (!f)
        return 0;
    while ((c = getc(f)) != EOF && len + 1 < sizeof text) {
        if (c == '\n')
            bol = is_c; /* a C comment's " * " at the start of a line is blank */
        else if (!(bol && c == '*') && c != ' ' && c != '\t')
            bol = 0;
        if (c == ' ' || c == '\n' || c == '\t' || (bol && c == '*')) {
            blank = 1;
            continue;
        }
        if (blank && len)
            text[len++] = ' ';
        blank = 0;
        text[len++] = (char)c;
    }
    text[len] = '\0';
    fclose(f);
    for (i = 0; i < n; i++)
        if (!strstr(text, phrases[i])) {
            *missing = phrases[i];
            return 0;
        }
    return 1;
}

/* contracts stated in prose that the code relies on */
static void doc_contracts(void)
{
    static const char *const facet_h[] = {
        "out may be exactly the same array as any input", "no other overlap",
        "an unknown or unsupported name there is not an error for the library",
    };
    static const char *const readme[] = {
        "Exit status, the same for every verb: **0** success; **1** I/O error",
        "**2** usage error or malformed input",
        "lines whose first non-blank character is `#`, are skipped",
        "white space (space, tab, CR, VT, FF)",
        "a NUL byte anywhere in a line is an error",
        "`floor(x * 32768 + 1/2)` (nearest, ties up)",
        "Fixed point saturates any finite value",
        "A malformed line stops the run, the same way in every format",
    };
    const char *m = "";
    int ok = has_phrases("include/facet.h", facet_h, 3, &m);
    CHECK(ok, "include/facet.h does not say: %s", m);
    ok = has_phrases("README.md", readme, 8, &m);
    CHECK(ok, "README.md does not say: %s", m);
}

int main(void)
{
    FILE *f = fopen("README.md", "r");
    char line[1024];
    size_t i;
    int seen[64] = {0};
    th_name = "docs";
    if (!f) {
        CHECK(0, "README.md not found (run from the source tree's top)");
        return th_done();
    }
    int in_table = 0; /* only the "## Kernels (f32)" section */
    while (fgets(line, sizeof line, f)) {
        if (!strncmp(line, "## ", 3))
            in_table = !strncmp(line, "## Kernels (f32)", 16);
        if (!in_table)
            continue;
        for (i = 0; i < facet_kernel_count(); i++) {
            const facet_kernel *k = facet_kernel_at(i);
            char key[64], *p;
            double e;
            snprintf(key, sizeof key, "| `%s` |", k->name);
            if (strncmp(line, key, strlen(key)))
                continue;
            /* the first "2^-" cell after the formula is the bound */
            p = strstr(line + strlen(key), "| 2^-");
            CHECK(p != NULL, "README row of %s has no 2^-k bound cell", k->name);
            if (!p)
                continue;
            e = -atof(p + 5);
            seen[i]++;
            CHECK(fabs(log2(k->err_f32) - e) < 0.01, "%s: README says 2^%g, facet.h enforces 2^%.2f",
                  k->name, e, log2(k->err_f32));
            /* the next one is the f32_fast bound */
            p = strstr(p + 1, "| 2^-");
            CHECK(p != NULL, "README row of %s has no f32_fast bound cell", k->name);
            if (p)
                CHECK(fabs(log2(k->err_f32_fast) + atof(p + 5)) < 0.01,
                      "%s: README says f32_fast 2^-%g, facet.h enforces 2^%.2f", k->name, atof(p + 5),
                      log2(k->err_f32_fast));
        }
    }
    fclose(f);
    doc_contracts();
    for (i = 0; i < facet_kernel_count(); i++)
        CHECK(seen[i] == 1, "%s has %d rows in the README kernel table (want 1)", facet_kernel_at(i)->name, seen[i]);
    return th_done();
}
