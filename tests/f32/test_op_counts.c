/* test_op_counts.c - the "Cost:" and "Budget:" of every contract in facet.h
 * are the operation counts of the kernel body in each tier, counted by
 * instantiating the body on the counting op layer (tests/lib/op_count.h:
 * its rules there; one evaluation, every op tallied), once per tier.
 *   Cost:    N ops (r rsqrt, c rcp), the precise tier (estimates apart);
 *   Budget:  the same ops by what they are for, in both tiers:
 *            clamps (the domain rule), NaN (the NaN rule), peak (brdf_hammon's
 *            exact 2 + 2 L.V - (N.L + N.V)^2 and 1 - L.H, the functions
 *            x_brdf_peak and x_one_minus_lh of f32_body.h), term (the rest:
 *            the formula itself); the estimates' refinement steps are each
 *            port's, tabled below from the port headers.
 * `test_op_counts --tsv FILE` also writes the budget of every kernel and
 * tier, with the refinement ops per port, for the report (and the same
 * count for brdf_hammon's fast-math shader peer, peers_shader.c's loop
 * transcribed on the counting layer). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../lib/harness.h"
#include "../lib/op_count.h"
#include "../../src/core/kernel_list.h"

#define HALF_(q) 0.5f

typedef struct {
    long ops, rcp, rsqrt, div, sqrt, clamp, nan, peak;
} budget;

typedef struct {
    const char *name;
    budget t[2]; /* precise, fast */
} counted;

/* one entry per kernel of the list */
enum {
    N_KERNELS_ = 0
#define FACET_KERNEL(...) + 1
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
};

static budget take(void)
{
    budget b;
    b.ops = n_ops;
    b.rcp = n_rcp;
    b.rsqrt = n_rsqrt;
    b.div = n_div;
    b.sqrt = n_sqrt;
    b.clamp = n_clamp_ops;
    b.nan = n_nan_ops;
    b.peak = 0;
    return b;
}

/* Ops an estimate takes on each port beyond what the counting layer counts
 * (a rcp or rsqrt itself counts 0, a div or sqrt 1: its multiply), from the
 * port headers: the estimate and its refinement steps.  {rcp, rsqrt, div,
 * sqrt} per tier.  A port with a divide/sqrt unit (sse2, avx2, avx512 and
 * the scalar division) does a div in the 1 op counted. */
static const struct {
    const char *port;
    int cost[2][4];
} refine[] = {
    { "scalar", { { 1, 14, 0, 14 }, { 1, 10, 0, 10 } } },  /* divss; seed (2) + 3 or 2 steps of 4 */
    { "sse2", { { 1, 2, 0, 0 }, { 4, 6, 0, 0 } } },        /* divps, sqrtps + divps; rcpps / rsqrtps + a step */
    { "avx2", { { 4, 6, 0, 0 }, { 3, 5, 0, 0 } } },        /* estimate + third- / first-order step; vdivps, vsqrtps */
    { "avx512", { { 3, 5, 0, 0 }, { 1, 1, 0, 1 } } },      /* 14-bit estimate + a step / raw; sqrt_fast = rsqrt14 * x */
    { "neon", { { 7, 11, 7, 11 }, { 5, 8, 5, 8 } } },      /* vrecpe/vrsqrte + 3 or 2 steps */
    { "helium", { { 7, 14, 7, 14 }, { 5, 10, 5, 10 } } },  /* bit seed + 3 or 2 steps */
    { "rvv", { { 5, 9, 5, 9 }, { 3, 5, 3, 5 } } },         /* vfrec7/vfrsqrt7 + 2 or 1 steps */
};
#define N_REFINE ((int)(sizeof refine / sizeof refine[0]))

static long refine_ops(const budget *b, int port, int tier)
{
    const int *c = refine[port].cost[tier];
    return (b->rcp - b->div) * c[0] + (b->rsqrt - b->sqrt) * c[1] + b->div * c[2] + b->sqrt * c[3];
}

/* brdf_hammon's fast-math shader peer (bench/harness/peers_shader.c,
 * sh_brdf_hammon_b), its loop body on the counting layer: clamps of N.L,
 * N.V, alpha, L.V and the two saturates; one rsqrt; three quotients (D,
 * Vis, the diffuse's (0.5 + N.H) / N.H); no NaN rule, no exact peak. */
static float peer_pow5(float x) { float x2 = cnt_mul(x, x); return cnt_mul(cnt_mul(x2, x2), x); }
static float peer_brdf(float nol, float nov, float lov, float alpha, float f0, float albedo)
{
    float nl = cnt_clamp(nol, FACET_COS_MIN, 1.0f), nv = cnt_clamp(nov, FACET_COS_MIN, 1.0f);
    float a = cnt_clamp(alpha, FACET_ALPHA_MIN, 1.0f), lv = cnt_clamp(lov, -1.0f, 1.0f);
    float inv = cnt_rsqrt(cnt_max(cnt_fma(2.0f, lv, 2.0f), 1e-12f));
    float noh = cnt_clamp(cnt_mul(cnt_add(nl, nv), inv), 0.0f, 1.0f);
    float loh = cnt_clamp(cnt_fma(inv, lv, inv), 0.0f, 1.0f);
    float a2 = cnt_mul(a, a);
    float d = cnt_fma(cnt_fnma(noh, 1.0f, cnt_mul(noh, a2)), noh, 1.0f);
    float p = cnt_mul(cnt_add(nl, nl), nv);
    float vis = cnt_div(0.5f, cnt_fma(cnt_sub(cnt_add(nl, nv), p), a, p));
    float f = cnt_fma(cnt_sub(1.0f, f0), peer_pow5(cnt_sub(1.0f, loh)), f0);
    float spec = cnt_mul(cnt_mul(cnt_mul(cnt_div(a2, cnt_mul(d, d)), 0.318309886f), vis), f);
    float facing = cnt_fma(0.5f, lv, 0.5f);
    float rough = cnt_mul(cnt_mul(facing, cnt_fnma(0.4f, facing, 0.9f)), cnt_div(cnt_add(0.5f, noh), noh));
    float smooth = cnt_mul(cnt_mul(1.05f, cnt_sub(1.0f, peer_pow5(cnt_sub(1.0f, nl)))),
                           cnt_sub(1.0f, peer_pow5(cnt_sub(1.0f, nv))));
    float single = cnt_mul(cnt_fma(a, cnt_sub(rough, smooth), smooth), 0.318309886f);
    return cnt_fma(albedo, cnt_fma(albedo, cnt_mul(0.1159f, a), single), spec);
}

/* the numbers a contract states: the last "Cost:" and "Budget:" before its
 * prototype */
static const char *last_before(const char *hdr, const char *key, const char *p)
{
    const char *q, *found = NULL;
    for (q = hdr; p && (q = strstr(q, key)) && q < p; q++)
        found = q;
    return found;
}

int main(int argc, char **argv)
{
    static counted c[N_KERNELS_];
    int n = 0, i, tier, pt;
    char *hdr;
    long len;
    FILE *f, *tsv = NULL;
    budget peer;
    th_name = "op_counts";
    if (argc > 2 && !strcmp(argv[1], "--tsv") && !(tsv = fopen(argv[2], "w"))) {
        CHECK(0, "cannot write %s", argv[2]);
        return th_done();
    }
#define FACET_KERNEL(kn, NAME, ar, ...)                                              \
    c[n].name = #kn;                                                                 \
    opc_reset();                                                                     \
    (void)count_##kn(FACET_EACH_INPUT(ar, HALF_));                                   \
    c[n].t[0] = take();                                                              \
    opc_reset();                                                                     \
    (void)countf_##kn(FACET_EACH_INPUT(ar, HALF_));                                  \
    c[n].t[1] = take();                                                              \
    n++;
#include "../../src/core/kernels.def"
#undef FACET_KERNEL
    /* the exact peak, counted apart (only brdf_hammon has it) */
    for (i = 0; i < n; i++)
        if (!strcmp(c[i].name, "brdf_hammon")) {
            float big, small, sh, hs, tau, w;
            opc_reset();
            (void)count_x_one_minus_lh(count_x_brdf_peak(0.5f, 0.5f, 0.5f, 0.25f, &big, &small, &sh, &hs, &tau, &w),
                                       0.5f);
            c[i].t[0].peak = n_ops;
            opc_reset();
            (void)countf_x_one_minus_lh(countf_x_brdf_peak(0.5f, 0.5f, 0.5f, 0.25f, &big, &small, &sh, &hs, &tau, &w),
                                        0.5f);
            c[i].t[1].peak = n_ops;
        }
    opc_reset();
    (void)peer_brdf(0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f);
    peer = take();

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
    if (tsv) {
        fprintf(tsv, "# kernel\ttier\tops\tclamps\tnan\tpeak\tterm\trsqrt\trcp\tdiv\tsqrt");
        for (pt = 0; pt < N_REFINE; pt++)
            fprintf(tsv, "\trefine_%s", refine[pt].port);
        fprintf(tsv, "\t(ops: tests/lib/op_count.h rules; refine_<port>: the estimates and their steps there)\n");
    }
    printf("%-22s %-8s %4s = %6s + %4s + %4s + %4s  (rsqrt rcp; div sqrt)  facet.h\n", "kernel", "tier", "ops",
           "clamps", "NaN", "peak", "term");
    for (i = 0; i < n; i++) {
        char proto[96];
        const char *p, *cost, *bud, *start;
        long ops = -1, rs = -1, rc = -1, bd[2][4];
        memset(bd, -1, sizeof bd);
        snprintf(proto, sizeof proto, " facet_%s_f32(", c[i].name);
        p = strstr(hdr, proto);
        cost = last_before(hdr, "Cost: ", p);
        bud = last_before(hdr, "Budget: ", p);
        start = last_before(hdr, "/*", p); /* the contract: the comment before the prototype */
        if (cost)
            sscanf(cost, "Cost: %ld ops (%ld rsqrt, %ld rcp)", &ops, &rs, &rc);
        if (bud && bud > start)
            sscanf(bud, "Budget: clamps %ld, NaN %ld, peak %ld, term %ld; fast: clamps %ld, NaN %ld, peak %ld, term %ld",
                   &bd[0][0], &bd[0][1], &bd[0][2], &bd[0][3], &bd[1][0], &bd[1][1], &bd[1][2], &bd[1][3]);
        for (tier = 0; tier < 2; tier++) {
            const budget *b = &c[i].t[tier];
            long term = b->ops - b->clamp - b->nan - b->peak;
            printf("%-22s %-8s %4ld = %6ld + %4ld + %4ld + %4ld  (%ld %ld; %ld %ld)  %ld, %ld, %ld, %ld\n", c[i].name,
                   tier ? "f32_fast" : "f32", b->ops, b->clamp, b->nan, b->peak, term, b->rsqrt, b->rcp, b->div,
                   b->sqrt, bd[tier][0], bd[tier][1], bd[tier][2], bd[tier][3]);
            CHECK(bd[tier][0] == b->clamp && bd[tier][1] == b->nan && bd[tier][2] == b->peak && bd[tier][3] == term,
                  "%s %s: facet.h says Budget: clamps %ld, NaN %ld, peak %ld, term %ld; the body has clamps %ld, "
                  "NaN %ld, peak %ld, term %ld",
                  c[i].name, tier ? "f32_fast" : "f32", bd[tier][0], bd[tier][1], bd[tier][2], bd[tier][3], b->clamp,
                  b->nan, b->peak, term);
            if (tsv) {
                fprintf(tsv, "%s\t%s\t%ld\t%ld\t%ld\t%ld\t%ld\t%ld\t%ld\t%ld\t%ld", c[i].name, tier ? "f32_fast" : "f32",
                        b->ops, b->clamp, b->nan, b->peak, term, b->rsqrt, b->rcp, b->div, b->sqrt);
                for (pt = 0; pt < N_REFINE; pt++)
                    fprintf(tsv, "\t%ld", refine_ops(b, pt, tier));
                fprintf(tsv, "\n");
            }
        }
        /* the estimates are the same in both tiers (which kind differs) */
        CHECK(c[i].t[0].rcp == c[i].t[1].rcp && c[i].t[0].rsqrt == c[i].t[1].rsqrt, "%s: the tiers' estimates differ",
              c[i].name);
        CHECK(ops == c[i].t[0].ops && rs == c[i].t[0].rsqrt && rc == c[i].t[0].rcp,
              "%s: facet.h says Cost: %ld ops (%ld rsqrt, %ld rcp); the body has %ld ops (%ld rsqrt, %ld rcp)",
              c[i].name, ops, rs, rc, c[i].t[0].ops, c[i].t[0].rsqrt, c[i].t[0].rcp);
    }
    printf("%-22s %-8s %4ld = %6ld + %4ld + %4ld + %4ld  (%ld %ld; %ld %ld)  (bench/harness/peers_shader.c)\n",
           "brdf_hammon", "peer_fm", peer.ops, peer.clamp, peer.nan, 0L, peer.ops - peer.clamp - peer.nan, peer.rsqrt,
           peer.rcp, peer.div, peer.sqrt);
    if (tsv) {
        fprintf(tsv, "brdf_hammon\tpeer\t%ld\t%ld\t%ld\t0\t%ld\t%ld\t%ld\t%ld\t%ld", peer.ops, peer.clamp, peer.nan,
                peer.ops - peer.clamp - peer.nan, peer.rsqrt, peer.rcp, peer.div, peer.sqrt);
        for (pt = 0; pt < N_REFINE; pt++)
            fprintf(tsv, "\t-");
        fprintf(tsv, "\n");
        CHECK(fclose(tsv) == 0, "writing %s", argv[2]);
    }
    free(hdr);
    return th_done();
}
