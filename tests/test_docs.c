/* test_docs.c - the bounds the README states for each f32 kernel, both
 * tiers, are the bounds facet.h documents and the tests enforce
 * (FACET_ERR_*_F32, FACET_ERR_*_F32_FAST), and every kernel
 * of the table has a README row.  Run from the source tree's top. */
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <string.h>
#include "harness.h"
#include "facet.h"

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
    for (i = 0; i < facet_kernel_count(); i++)
        CHECK(seen[i] == 1, "%s has %d rows in the README kernel table (want 1)", facet_kernel_at(i)->name, seen[i]);
    return th_done();
}
