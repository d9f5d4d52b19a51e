/* test_op_counts.c - the "Cost:" of every contract in facet.h is the
 * operation count of the kernel body, counted by instantiating the body on
 * the counting op layer (tests/lib/op_count.h: its counting rules) at one
 * evaluation, for every kernel of the list. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../lib/harness.h"
#include "../lib/op_count.h"
#include "../../src/core/kernel_list.h"

#define HALF_(q) 0.5f

typedef struct { const char *name; long ops, rcp, rsqrt; } counted;

/* one entry per kernel of the list */
enum {
    N_KERNELS_ = 0
#define FACET_KERNEL(...) + 1
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
};

int main(void)
{
    static counted c[N_KERNELS_];
    int n = 0, i;
    char *hdr;
    long len;
    FILE *f;
    th_name = "op_counts";
#define FACET_KERNEL(kn, NAME, ar, ...)                                \
    opc_reset();                                                       \
    (void)count_##kn(FACET_EACH_INPUT(ar, HALF_));                     \
    c[n].name = #kn; c[n].ops = n_ops; c[n].rcp = n_rcp; c[n].rsqrt = n_rsqrt; n++;
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
    f = fopen("include/facet.h", "rb");
    if (!f) {
        CHECK(0, "include/facet.h not found (run from the source tree's top)");
        return th_done();
    }
    fseek(f, 0, SEEK_END);
    len = ftell(f);
    rewind(f);
    hdr = malloc(len + 1);
    hdr[fread(hdr, 1, len, f)] = '\0';
    fclose(f);
    for (i = 0; i < n; i++) {
        char proto[96], *p, *cost = NULL, *q;
        long ops = -1, rs = -1, rc = -1;
        snprintf(proto, sizeof proto, " facet_%s_f32(", c[i].name);
        p = strstr(hdr, proto);
        /* the last "Cost:" before the prototype is its contract's */
        for (q = hdr; p && (q = strstr(q, "Cost: ")) && q < p; q++)
            cost = q;
        if (cost)
            sscanf(cost, "Cost: %ld ops (%ld rsqrt, %ld rcp)", &ops, &rs, &rc);
        printf("%-22s %3ld ops, %ld rsqrt, %ld rcp   (facet.h: %ld, %ld, %ld)\n", c[i].name, c[i].ops,
               c[i].rsqrt, c[i].rcp, ops, rs, rc);
        CHECK(ops == c[i].ops && rs == c[i].rsqrt && rc == c[i].rcp,
              "%s: facet.h says Cost: %ld ops (%ld rsqrt, %ld rcp); the body has %ld ops (%ld rsqrt, %ld rcp)",
              c[i].name, ops, rs, rc, c[i].ops, c[i].rsqrt, c[i].rcp);
    }
    free(hdr);
    return th_done();
}
