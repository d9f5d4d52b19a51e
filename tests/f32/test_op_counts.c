/* test_op_counts.c - the "Cost:" of every contract in facet.h is the
 * operation count of the kernel body, counted by instantiating the body on
 * a counting op layer (one evaluation, every op tallied).  Counting rules,
 * as a port with FMA executes them: add, sub, mul, fma, fnma, min, max,
 * sqr_err = 1; clamp = 2 (max, min); sel_lt = 2 (compare, blend);
 * keep_ord = 2 (ordered compare, mask: the NaN rule);
 * the exponent-bit ops exp2i, getexp, getmant = 1;
 * rcp and rsqrt = 1 each, reported separately (their refinement steps are
 * the port's: see each port header). */
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <string.h>
#include "../lib/harness.h"
#include "facet.h"
#include "../../src/core/kernel_list.h"

static long n_ops, n_rcp, n_rsqrt;

static float cnt_set(float x) { return x; }
static float cnt_add(float a, float b) { n_ops++; return a + b; }
static float cnt_sub(float a, float b) { n_ops++; return a - b; }
static float cnt_mul(float a, float b) { n_ops++; return a * b; }
static float cnt_fma(float a, float b, float c) { n_ops++; return a * b + c; }
static float cnt_fnma(float a, float b, float c) { n_ops++; return c - a * b; }
static float cnt_min(float a, float b) { n_ops++; return a < b ? a : b; }
static float cnt_max(float a, float b) { n_ops++; return a > b ? a : b; }
static float cnt_sel_lt(float a, float b, float x, float y) { n_ops += 2; return a < b ? x : y; }
static float cnt_clamp(float x, float lo, float hi) { n_ops += 2; x = x > lo ? x : lo; return x < hi ? x : hi; }
static float cnt_keep_ord(float r, float a, float b) { n_ops += 2; return a == a && b == b ? r : 0.0f; }
static float cnt_rcp(float x) { n_rcp++; return 1.0f / x; }
static float cnt_rsqrt(float x) { n_rsqrt++; return 1.0f / (float)sqrt(x); }
static float cnt_sqr_err(float a, float p) { n_ops++; return (float)((double)a * a - p); }
/* the exponent-bit ops count 1 each, as in tests/sample/test_sample_prims.c */
static float cnt_exp2i(float k) { n_ops++; return (float)ldexp(1.0, (int)k); }
static float cnt_getexp(float x) { int e; n_ops++; frexp(x, &e); return (float)(e - 1); }
static float cnt_getmant(float x) { int e; n_ops++; return 2.0f * (float)frexp(x, &e); }

#define FACET_V float
#define FACET_OP(op) cnt_##op
#define FACET_K(k) count_##k
#include "facet/detail/f32_body.h"
#undef FACET_V
#undef FACET_OP
#undef FACET_K

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
    n_ops = n_rcp = n_rsqrt = 0;                                       \
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
