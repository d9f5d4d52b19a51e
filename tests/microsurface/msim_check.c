/* msim_check.c - the microsurface simulator's validation and the committed
 * tables' spot check (bench/microsurface/README.md, "Validation"); run by
 * tests/suites/65-microsurface.sh as
 *   build/tests/msim_check bench/microsurface
 * Every check is statistical with fixed seeds, so its outcome is fixed on a
 * machine: a figure passes when it is within k standard errors of what it
 * must equal (k = 5 where a check makes hundreds of comparisons, 4.5 else).
 * The analytic side comes from facet's oracle (include/facet/oracle.h). */
#include "tests/lib/harness.h"
#include "msim.h"
#include "msim_grid.h"
#include "msim_tables.h"
#include "facet/oracle.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

#define dir msim_dir

static void setup(msim_run *r, int facet, double alpha, double f0, double nl, uint64_t paths, uint64_t seed)
{
    memset(r, 0, sizeof *r);
    r->mat.facet = facet;
    r->mat.alpha = alpha;
    r->mat.f0 = f0;
    r->nl = nl;
    r->paths = paths;
    r->seed = seed;
    r->threads = 1;
    r->max_events = 1000;
}

static double lv_of(double nl, msim_v3 v)
{
    return sqrt(fmax(0.0, 1.0 - nl * nl)) * v.x + nl * v.z;
}

/* the height-correlated single-bounce specular BRDF, D G2 F / (4 N.L N.V) */
static double spec1_exact(double alpha, double f0, double nl, double nv, double lv, int uncorrelated)
{
    double noh = facet_oracle_noh_from_dots(nl, nv, lv), loh = facet_oracle_loh_from_dots(lv);
    double g2 = uncorrelated ? facet_oracle_smith_g2_uncorrelated(nl, nv, alpha) : facet_oracle_smith_g2(nl, nv, alpha);
    double f = f0 >= 1.0 ? 1.0 : facet_oracle_fresnel_schlick(f0, loh);
    return facet_oracle_ggx_d(noh, alpha) * g2 * f / (4.0 * nl * nv);
}

/* 1. the visible-normal sampler, both hemispheres: a histogram over
 * (cos theta_m, phi_m) against the quadrature of <w.m> D(m) / A(w), whose
 * total (1) checks the projected area A(w) on its own */
static void check_vndf(void)
{
    static const double alphas[2] = {0.35, 1.0}, wz[5] = {0.8, 0.1, 0.0, -0.3, -0.9};
    enum { NT = 10, NP = 8, SUB = 40, NS = 200000 };
    int ia, iw;
    for (ia = 0; ia < 2; ia++)
        for (iw = 0; iw < 5; iw++) {
            double a = alphas[ia], cnt[NT][NP] = {{0}}, ex[NT][NP] = {{0}}, tot = 0, area, worst = 0;
            msim_v3 w = dir(wz[iw], 20.0);
            msim_rng rng;
            int i, j, si, sj, bad = 0, outside = 0;
            area = msim_proj_area(w, a);
            for (i = 0; i < NT; i++)
                for (j = 0; j < NP; j++)
                    for (si = 0; si < SUB; si++)
                        for (sj = 0; sj < SUB; sj++) {
                            double mu = (i + (si + 0.5) / SUB) / NT, ph = 2.0 * PI * (j + (sj + 0.5) / SUB) / NP;
                            double s = sqrt(1.0 - mu * mu);
                            msim_v3 m = {s * cos(ph), s * sin(ph), mu};
                            double wm = m.x * w.x + m.y * w.y + m.z * w.z;
                            double d = a * a / (PI * pow(mu * mu * (a * a - 1.0) + 1.0, 2.0));
                            double cell = (1.0 / NT / SUB) * (2.0 * PI / NP / SUB);
                            if (wm > 0.0)
                                ex[i][j] += wm * d / area * cell;
                        }
            for (i = 0; i < NT; i++)
                for (j = 0; j < NP; j++)
                    tot += ex[i][j];
            CHECK(fabs(tot - 1.0) < 2e-3, "vndf alpha %g w_z %g: quadrature of <w.m> D / A(w) = %.6f, want 1", a,
                  wz[iw], tot);
            msim_rng_init(&rng, 77, (uint64_t)(ia * 5 + iw));
            for (i = 0; i < NS; i++) {
                double u1 = msim_uniform(&rng), u2 = msim_uniform(&rng);
                msim_v3 m = msim_sample_vndf(w, a, u1, u2);
                double ph = atan2(m.y, m.x), wm = m.x * w.x + m.y * w.y + m.z * w.z;
                int bt = (int)(m.z * NT), bp;
                if (ph < 0)
                    ph += 2.0 * PI;
                bp = (int)(ph / (2.0 * PI) * NP);
                if (bt >= NT) bt = NT - 1;
                if (bp >= NP) bp = NP - 1;
                if (!(m.z > 0.0) || wm < -1e-12)
                    outside++;
                else
                    cnt[bt][bp] += 1.0;
            }
            CHECK(outside == 0, "vndf alpha %g w_z %g: %d normals below the horizon or facing away", a, wz[iw],
                  outside);
            for (i = 0; i < NT; i++)
                for (j = 0; j < NP; j++) {
                    double p = ex[i][j], f = cnt[i][j] / NS, se = sqrt(fmax(p * (1.0 - p), 1e-12) / NS);
                    double z = fabs(f - p) / (se + 2e-4 * p);
                    if (z > worst)
                        worst = z;
                    if (z > 5.0)
                        bad++;
                }
            CHECK(bad == 0, "vndf alpha %g w_z %g: %d of %d bins beyond 5 sigma (worst %.1f)", a, wz[iw], bad,
                  NT * NP, worst);
        }
}

/* 2. the masking rate: a random surface point (C1 uniform) sees o with
 * probability Smith's G1(o) */
static void check_g1(void)
{
    static const double alphas[3] = {0.1, 0.5, 1.0}, cz[4] = {0.9, 0.5, 0.2, 0.05};
    int ia, ic;
    for (ia = 0; ia < 3; ia++)
        for (ic = 0; ic < 4; ic++) {
            msim_run r;
            msim_result res;
            double g, p, se;
            setup(&r, MSIM_LAMBERT, alphas[ia], 0.0, 1.0, 200000, 11);
            r.start_on_surface = 1;
            r.start_dir = dir(cz[ic], 0.0);
            r.max_events = 0; /* only the first flight matters */
            r.analog = 1;     /* the flight itself: hit or escape */
            msim_simulate(&r, &res);
            g = facet_oracle_smith_g1(cz[ic], alphas[ia]);
            p = (double)res.first_escape / res.paths;
            se = sqrt(fmax(g * (1.0 - g), 1e-12) / res.paths);
            CHECK(fabs(p - g) <= 4.5 * se, "G1 alpha %g N.V %g: escape rate %.6f, Smith G1 %.6f (%.1f sigma)",
                  alphas[ia], cz[ic], p, g, fabs(p - g) / se);
            msim_free(&res);
        }
}

/* 3. single-bounce specular: next-event estimates at points, and the walk's
 * own exits binned, against D G2 F / (4 N.L N.V) with height-correlated G2;
 * and the uncorrelated G2 is rejected (the check can tell them apart) */
static void check_spec1(void)
{
    static const struct {
        int facet;
        double alpha, f0, nl;
    } cfg[4] = {{MSIM_MIRROR, 0.2, 1.0, 0.7}, {MSIM_MIRROR, 0.8, 1.0, 0.25}, {MSIM_HAMMON, 0.5, 0.04, 0.5},
                {MSIM_HAMMON, 1.0, 0.04, 0.1}};
    static const double nvs[5] = {0.95, 0.7, 0.4, 0.15, 0.05}, phis[3] = {0.0, 100.0, 180.0};
    int ic, rejected = 0;
    for (ic = 0; ic < 4; ic++) {
        msim_v3 out[15];
        msim_run r;
        msim_result res;
        int i, j, n = 0;
        for (i = 0; i < 5; i++)
            for (j = 0; j < 3; j++)
                out[n++] = dir(nvs[i], phis[j]);
        setup(&r, cfg[ic].facet, cfg[ic].alpha, cfg[ic].f0, cfg[ic].nl, 100000, 21);
        r.n_out = n;
        r.out = out;
        msim_simulate(&r, &res);
        for (j = 0; j < n; j++) {
            double nv = out[j].z, lv = lv_of(cfg[ic].nl, out[j]);
            double want = spec1_exact(cfg[ic].alpha, cfg[ic].f0, cfg[ic].nl, nv, lv, 0);
            double unc = spec1_exact(cfg[ic].alpha, cfg[ic].f0, cfg[ic].nl, nv, lv, 1);
            double got = msim_mean(&res.nee[j], MSIM_SPEC1, res.paths) / nv;
            double se = msim_se(&res.nee[j], MSIM_SPEC1, res.paths) / nv;
            CHECK(fabs(got - want) <= 4.5 * se + 1e-12 * want,
                  "spec1 (next event) facet %d alpha %g N.L %g N.V %g L.V %.4f: %.7g +- %.2g, want %.7g (%.1f sigma)",
                  cfg[ic].facet, cfg[ic].alpha, cfg[ic].nl, nv, lv, got, se, want, fabs(got - want) / se);
            if (fabs(got - unc) > 10.0 * se)
                rejected++;
        }
        msim_free(&res);
    }
    CHECK(rejected >= 10, "spec1: the uncorrelated G2 is rejected at only %d points", rejected);
    /* the walk's exits, binned (16 x 12), single-bounce part */
    {
        enum { NM = 16, NPH = 12, SUB = 24 };
        msim_run r;
        msim_result res;
        double a = 0.6, nl = 0.5, worst = 0;
        int i, j, bad = 0;
        setup(&r, MSIM_MIRROR, a, 1.0, nl, 400000, 22);
        r.nb_mu = NM;
        r.nb_phi = NPH;
        msim_simulate(&r, &res);
        for (i = 0; i < NM; i++)
            for (j = 0; j < NPH; j++) {
                double ex = 0, got, se, z;
                int si, sj;
                for (si = 0; si < SUB; si++)
                    for (sj = 0; sj < SUB; sj++) {
                        double mu = (i + (si + 0.5) / SUB) / NM, ph = 180.0 * (j + (sj + 0.5) / SUB) / NPH;
                        msim_v3 v = dir(mu, ph);
                        /* exit density f mu over dmu dphi, both azimuth signs */
                        ex += spec1_exact(a, 1.0, nl, mu, lv_of(nl, v), 0) * mu * (1.0 / NM / SUB) *
                              (PI / NPH / SUB) * 2.0;
                    }
                got = msim_mean(&res.bins[i * NPH + j], MSIM_SPEC1, res.paths);
                se = msim_se(&res.bins[i * NPH + j], MSIM_SPEC1, res.paths);
                z = fabs(got - ex) / (se + 1e-3 * ex + 1e-9);
                if (z > worst)
                    worst = z;
                if (z > 5.0)
                    bad++;
            }
        CHECK(bad == 0, "spec1 (binned exits) alpha %g N.L %g: %d of %d bins beyond 5 sigma (worst %.1f)", a, nl,
              bad, NM * NPH, worst);
        msim_free(&res);
    }
}

/* 4. energy: a white microsurface (albedo 1, F = 1 or Hammon's facet, which
 * loses nothing at albedo 1) sends all of it back: the next-event estimate of
 * the albedo is 1; and it agrees part by part with the walk's own exits */
static void check_energy(void)
{
    static const struct {
        int facet;
        double alpha, f0, nl;
    } cfg[6] = {{MSIM_LAMBERT, 1.0, 0.0, 0.8}, {MSIM_LAMBERT, 0.3, 0.0, 0.15}, {MSIM_MIRROR, 1.0, 1.0, 0.2},
                {MSIM_MIRROR, 0.5, 1.0, 0.6}, {MSIM_HAMMON, 0.7, 0.04, 0.4}, {MSIM_HAMMON, 1.0, 0.04, 0.05}};
    static const int parts[8] = {MSIM_TOTAL, MSIM_SINGLE, MSIM_MULTI, MSIM_SPEC1, MSIM_SPECM, MSIM_D100, MSIM_D050, MSIM_K2};
    int ic, p;
    for (ic = 0; ic < 6; ic++) {
        msim_run r;
        msim_result res;
        double e, se;
        setup(&r, cfg[ic].facet, cfg[ic].alpha, cfg[ic].f0, cfg[ic].nl, 200000, 31);
        r.nee_albedo = 1;
        msim_simulate(&r, &res);
        e = msim_mean(&res.nee_albedo, MSIM_TOTAL, res.paths);
        se = msim_se(&res.nee_albedo, MSIM_TOTAL, res.paths);
        CHECK(fabs(e - 1.0) <= 4.5 * se && se < 5e-3,
              "energy facet %d alpha %g N.L %g: white albedo %.6f +- %.6f, want 1", cfg[ic].facet, cfg[ic].alpha,
              cfg[ic].nl, e, se);
        e = msim_mean(&res.albedo, MSIM_TOTAL, res.paths);
        se = msim_se(&res.albedo, MSIM_TOTAL, res.paths);
        CHECK(res.cut == 0 && fabs(e - 1.0) <= 4.5 * se + 1e-12,
              "energy facet %d alpha %g N.L %g: %llu paths cut, exits' albedo %.6f +- %.6f, want 1", cfg[ic].facet,
              cfg[ic].alpha, cfg[ic].nl, (unsigned long long)res.cut, e, se);
        for (p = 1; p < 8; p++) {
            double a = msim_mean(&res.albedo, parts[p], res.paths), sa = msim_se(&res.albedo, parts[p], res.paths);
            double b = msim_mean(&res.nee_albedo, parts[p], res.paths), sb = msim_se(&res.nee_albedo, parts[p], res.paths);
            double s = sqrt(sa * sa + sb * sb);
            CHECK(fabs(a - b) <= 4.5 * s + 1e-15, "albedo part %s facet %d alpha %g N.L %g: exits %.6f +- %.6f, "
                  "next event %.6f +- %.6f", msim_acc_name[parts[p]], cfg[ic].facet, cfg[ic].alpha, cfg[ic].nl, a, sa, b, sb);
        }
        msim_free(&res);
    }
}

/* 5. reciprocity: f(L, V) = f(V, L), the multiple-bounce part included */
static void check_reciprocity(void)
{
    static const struct {
        int facet;
        double alpha, f0;
    } cfg[3] = {{MSIM_HAMMON, 0.5, 0.04}, {MSIM_HAMMON, 1.0, 0.04}, {MSIM_LAMBERT, 0.75, 0.0}};
    static const double pairs[3][2] = {{0.9, 0.3}, {0.6, 0.1}, {0.2, 0.45}}, phis[3] = {0.0, 90.0, 180.0};
    static const int parts[4] = {MSIM_TOTAL, MSIM_MULTI, MSIM_D100, MSIM_D025};
    int ic, ip, p, j;
    for (ic = 0; ic < 3; ic++)
        for (ip = 0; ip < 3; ip++) {
            msim_run r1, r2;
            msim_result a, b;
            msim_v3 o1[3], o2[3];
            for (j = 0; j < 3; j++) {
                o1[j] = dir(pairs[ip][1], phis[j]);
                o2[j] = dir(pairs[ip][0], phis[j]);
            }
            setup(&r1, cfg[ic].facet, cfg[ic].alpha, cfg[ic].f0, pairs[ip][0], 150000, 41);
            setup(&r2, cfg[ic].facet, cfg[ic].alpha, cfg[ic].f0, pairs[ip][1], 150000, 41);
            r1.n_out = r2.n_out = 3;
            r1.out = o1;
            r2.out = o2;
            msim_simulate(&r1, &a);
            msim_simulate(&r2, &b);
            for (j = 0; j < 3; j++)
                for (p = 0; p < 4; p++) {
                    double fa = msim_mean(&a.nee[j], parts[p], a.paths) / pairs[ip][1];
                    double sa = msim_se(&a.nee[j], parts[p], a.paths) / pairs[ip][1];
                    double fb = msim_mean(&b.nee[j], parts[p], b.paths) / pairs[ip][0];
                    double sb = msim_se(&b.nee[j], parts[p], b.paths) / pairs[ip][0];
                    double s = sqrt(sa * sa + sb * sb);
                    CHECK(fabs(fa - fb) <= 4.5 * s && s < 0.02 * fabs(fa) + 1e-9,
                          "reciprocity facet %d alpha %g (%g, %g, phi %g) %s: %.6g +- %.2g vs %.6g +- %.2g",
                          cfg[ic].facet, cfg[ic].alpha, pairs[ip][0], pairs[ip][1], phis[j],
                          msim_acc_name[parts[p]], fa, sa, fb, sb);
                }
            msim_free(&a);
            msim_free(&b);
        }
}

/* 6. fixed seeds: the same run twice, and on 1 and 2 threads, bit for bit;
 * another seed differs */
static int same(const msim_result *a, const msim_result *b, int n_out, int nb)
{
    return a->paths == b->paths && a->events == b->events &&
           !memcmp(a->nee, b->nee, (size_t)n_out * sizeof *a->nee) &&
           !memcmp(a->bins, b->bins, (size_t)nb * sizeof *a->bins) &&
           !memcmp(&a->albedo, &b->albedo, sizeof a->albedo) &&
           !memcmp(&a->nee_albedo, &b->nee_albedo, sizeof a->nee_albedo);
}

static void check_determinism(void)
{
    msim_v3 out[4] = {dir(1.0, 0.0), dir(0.5, 30.0), dir(0.2, 180.0), dir(0.05, 90.0)};
    msim_run r;
    msim_result a, b, c, d;
    setup(&r, MSIM_HAMMON, 0.8, 0.04, 0.3, 30001, 51);
    r.n_out = 4;
    r.out = out;
    r.nb_mu = 8;
    r.nb_phi = 6;
    r.nee_albedo = 1;
    msim_simulate(&r, &a);
    msim_simulate(&r, &b);
    r.threads = 2;
    msim_simulate(&r, &c);
    r.threads = 1;
    r.seed = 52;
    msim_simulate(&r, &d);
    CHECK(same(&a, &b, 4, 48), "determinism: the same run twice differs");
    CHECK(same(&a, &c, 4, 48), "determinism: 1 and 2 threads differ");
    CHECK(!same(&a, &d, 4, 48), "determinism: seeds 51 and 52 give the same result");
    msim_free(&a);
    msim_free(&b);
    msim_free(&c);
    msim_free(&d);
}

/* 7. the committed tables: complete and finite, each row with V more
 * grazing than L equal to its reciprocal (the tables' rule: a run at the
 * more grazing incidence estimates both, README.md); a few runs
 * re-simulated with another seed and fewer paths agree with them, and so do
 * runs from the other side (steep incidence, grazing V: reciprocity checked
 * against the tables where that estimator's variance is moderate, alpha >=
 * 1/2), each value within 5 standard errors */
static int spot_compare(const msim_table *t, int im, double a, double nl, int from_steep, uint64_t paths,
                        int *cmp_out, double *worst_out)
{
    msim_v3 out[MSIM_NCOS * MSIM_NPHI];
    double onv[MSIM_NCOS * MSIM_NPHI], oph[MSIM_NCOS * MSIM_NPHI], w = 0;
    int n = 0, j, c, iv, ip, bad = 0, cmp = 0;
    msim_run r;
    msim_result res;
    for (iv = 0; iv < MSIM_NCOS; iv++) {
        double nv = msim_grid_cos[iv];
        if (from_steep ? !(nv < nl) : !(nv >= nl))
            continue;
        for (ip = 0; ip < (iv == 0 || nl >= 1.0 ? 1 : MSIM_NPHI); ip++) {
            onv[n] = nv;
            oph[n] = msim_grid_phi[ip];
            out[n] = dir(nv, oph[n]);
            n++;
        }
    }
    setup(&r, msim_grid_mat[im].facet, a, msim_grid_mat[im].f0, nl, paths, 424242);
    r.n_out = n;
    r.out = out;
    msim_simulate(&r, &res);
    for (j = 0; j < n; j++) {
        const msim_row *row = msim_table_find(t, a, nl, onv[j], oph[j]);
        if (!row)
            continue;
        for (c = 0; c < msim_table_ncols[im]; c++) {
            int pa = msim_table_cols[im][c];
            double v = msim_mean(&res.nee[j], pa, res.paths) / onv[j];
            double sv = msim_se(&res.nee[j], pa, res.paths) / onv[j];
            double sd = sqrt(sv * sv + row->se[pa] * row->se[pa]) + 1e-6 * fabs(v), z;
            if (v == 0.0 && row->val[pa] == 0.0)
                continue;
            z = fabs(v - row->val[pa]) / sd;
            cmp++;
            if (z > w)
                w = z;
            if (z > 5.0)
                bad++;
        }
    }
    msim_free(&res);
    *cmp_out = cmp;
    *worst_out = w;
    return bad;
}

static void check_tables(const char *dir_)
{
    /* the spot runs: {alpha index, N.L index} per material, then one from the steep side */
    static const int spot[MSIM_NMAT][3][2] = {{{7, 6}, {11, 8}, {9, 2}}, {{5, 5}, {10, 9}, {11, 3}},
                                              {{9, 7}, {11, 4}, {8, 2}}};
    int im;
    for (im = 0; im < MSIM_NMAT; im++) {
        char path[1024];
        msim_table t;
        int ia, il, iv, ip, missing = 0, badval = 0, asym = 0, c, s;
        snprintf(path, sizeof path, "%s/ref_%s.tsv", dir_, msim_grid_mat[im].name);
        if (msim_table_read(&t, path)) {
            CHECK(0, "tables: cannot read %s", path);
            continue;
        }
        for (ia = 0; ia < MSIM_NALPHA; ia++)
            for (il = 0; il < MSIM_NCOS; il++)
                for (iv = 0; iv < MSIM_NCOS; iv++)
                    for (ip = 0; ip < (iv == 0 || il == 0 ? 1 : MSIM_NPHI); ip++) {
                        double a = msim_grid_alpha[ia], nl = msim_grid_cos[il], nv = msim_grid_cos[iv];
                        double ph = msim_grid_phi[ip];
                        const msim_row *r = msim_table_find(&t, a, nl, nv, ph), *q = msim_table_find(&t, a, nv, nl, ph);
                        if (!r || !q) {
                            missing++;
                            continue;
                        }
                        for (c = 0; c < msim_table_ncols[im]; c++) {
                            int pa = msim_table_cols[im][c];
                            if (!isfinite(r->val[pa]) || !isfinite(r->se[pa]) || r->se[pa] < 0 || r->val[pa] < 0)
                                badval++;
                            if (r->val[pa] != q->val[pa] || r->se[pa] != q->se[pa])
                                asym++;
                        }
                        if (r->run_nl != fmin(nl, nv))
                            asym++;
                    }
        CHECK(missing == 0 && badval == 0 && asym == 0 && t.n == MSIM_NALPHA * (MSIM_NCOS + (MSIM_NCOS - 1) * (1 + (MSIM_NCOS - 1) * MSIM_NPHI)),
              "tables %s: %d rows, %d grid points missing, %d bad values, %d rows not reciprocal copies",
              msim_grid_mat[im].name, t.n, missing, badval, asym);
        for (s = 0; s < 3; s++) {
            int cmp, bad;
            double a = msim_grid_alpha[spot[im][s][0]], nl = msim_grid_cos[spot[im][s][1]], w;
            bad = spot_compare(&t, im, a, nl, s == 2, 100000, &cmp, &w);
            CHECK(bad == 0 && cmp > 20, "tables %s spot alpha %g N.L %g (%s): %d of %d values beyond 5 sigma (worst %.1f)",
                  msim_grid_mat[im].name, a, nl, s == 2 ? "steep side" : "the tables' side", bad, cmp, w);
        }
        msim_table_free(&t);
    }
}

int main(int argc, char **argv)
{
    th_name = "microsurface";
    check_vndf();
    check_g1();
    check_spec1();
    check_energy();
    check_reciprocity();
    check_determinism();
    if (argc > 1)
        check_tables(argv[1]);
    else
        SKIP("tables: no directory given");
    return th_done();
}
