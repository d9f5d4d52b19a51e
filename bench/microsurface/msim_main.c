/* msim_main.c - build/microsurface, the microsurface reference tool
 * (bench/microsurface/README.md):
 *   microsurface point  ...   the BRDF at one (N.L, N.V, phi), every part
 *   microsurface brdf   ...   the binned BRDF over outgoing directions and
 *                             the directional albedo for one incident direction
 *   microsurface table  ...   the reference tables (make microsurface)
 *   microsurface error | refit | energy   the analyses (msim_analyse.c)
 * Every figure is printed with its Monte Carlo standard error. */
#include "facet.h"
#include "msim.h"
#include "msim_grid.h"
#include "msim_tables.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>


static void usage(void)
{
    fprintf(stderr,
            "usage: microsurface point --facet F --alpha A --nl X --nv Y --phi DEG [options]\n"
            "       microsurface brdf  --facet F --alpha A --nl X [--bins MU PHI] [options]\n"
            "       microsurface table --out DIR [--paths N] [--only MATERIAL] [options]\n"
            "       microsurface error  --dir DIR   (model error of the diffuse kernels)\n"
            "       microsurface refit  --dir DIR   (Hammon's constants refitted)\n"
            "       microsurface energy --dir DIR   (single-scattering GGX's energy loss)\n"
            "options: --f0 F0 (hammon 0.04, mirror 1), --paths N (point/brdf 1000000),\n"
            "         --seed S (1), --threads T (1), --max-events N (1000)\n"
            "facets: hammon (Schlick-F mirror + Hammon's symmetric diffuse), lambert, mirror\n");
}

static int parse_facet(const char *s)
{
    if (!strcmp(s, "hammon"))
        return MSIM_HAMMON;
    if (!strcmp(s, "lambert"))
        return MSIM_LAMBERT;
    if (!strcmp(s, "mirror"))
        return MSIM_MIRROR;
    return -1;
}

typedef struct {
    int facet;
    double alpha, f0, nl, nv, phi;
    int have_f0;
    uint64_t paths, seed;
    int threads, max_events, nb_mu, nb_phi;
    const char *out, *only, *dir;
} opts;

static int parse(int argc, char **argv, opts *o)
{
    int i;
    memset(o, 0, sizeof *o);
    o->facet = MSIM_HAMMON;
    o->alpha = 0.5;
    o->nl = o->nv = 1.0;
    o->paths = 1000000;
    o->seed = 1;
    o->threads = 1;
    o->max_events = 1000;
    o->nb_mu = 16;
    o->nb_phi = 12;
    for (i = 2; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--bins") && i + 2 < argc) {
            o->nb_mu = atoi(argv[i + 1]);
            o->nb_phi = atoi(argv[i + 2]);
            i += 2;
            continue;
        }
        if (!v)
            return -1;
        if (!strcmp(a, "--facet")) {
            if ((o->facet = parse_facet(v)) < 0)
                return -1;
        } else if (!strcmp(a, "--alpha"))
            o->alpha = atof(v);
        else if (!strcmp(a, "--f0")) {
            o->f0 = atof(v);
            o->have_f0 = 1;
        } else if (!strcmp(a, "--nl"))
            o->nl = atof(v);
        else if (!strcmp(a, "--nv"))
            o->nv = atof(v);
        else if (!strcmp(a, "--phi"))
            o->phi = atof(v);
        else if (!strcmp(a, "--paths"))
            o->paths = strtoull(v, NULL, 10);
        else if (!strcmp(a, "--seed"))
            o->seed = strtoull(v, NULL, 10);
        else if (!strcmp(a, "--threads"))
            o->threads = atoi(v);
        else if (!strcmp(a, "--max-events"))
            o->max_events = atoi(v);
        else if (!strcmp(a, "--out"))
            o->out = v;
        else if (!strcmp(a, "--only"))
            o->only = v;
        else if (!strcmp(a, "--dir"))
            o->dir = v;
        else
            return -1;
        i++;
    }
    if (!o->have_f0)
        o->f0 = o->facet == MSIM_MIRROR ? 1.0 : o->facet == MSIM_HAMMON ? 0.04 : 0.0;
    if (o->paths < 2 || o->threads < 1 || o->threads > 64 || o->nb_mu < 1 || o->nb_phi < 1 ||
        !(o->alpha > 0.0 && o->alpha <= 1.0) || !(o->nl > 0.0 && o->nl <= 1.0) ||
        !(o->nv > 0.0 && o->nv <= 1.0))
        return -1;
    return 0;
}

static void base_run(msim_run *r, const opts *o)
{
    memset(r, 0, sizeof *r);
    r->mat.facet = o->facet;
    r->mat.alpha = o->alpha;
    r->mat.f0 = o->f0;
    r->nl = o->nl;
    r->seed = o->seed;
    r->paths = o->paths;
    r->threads = o->threads;
    r->max_events = o->max_events;
}

static int cmd_point(const opts *o)
{
    msim_run r;
    msim_result res;
    msim_v3 v = msim_dir(o->nv, o->phi);
    int a;
    base_run(&r, o);
    r.n_out = 1;
    r.out = &v;
    if (msim_simulate(&r, &res))
        return 2;
    printf("# point: facet %d alpha %.17g f0 %g nl %.17g nv %.17g phi %g, %llu paths, seed %llu\n",
           o->facet, o->alpha, o->f0, o->nl, o->nv, o->phi, (unsigned long long)res.paths,
           (unsigned long long)o->seed);
    printf("# part\tbrdf\tse\n");
    for (a = 0; a < MSIM_NACC; a++)
        printf("%s\t%.9e\t%.3e\n", msim_acc_name[a], msim_mean(&res.nee[0], a, res.paths) / o->nv,
               msim_se(&res.nee[0], a, res.paths) / o->nv);
    printf("# events/path %.4f, cut %llu\n", (double)res.events / res.paths, (unsigned long long)res.cut);
    msim_free(&res);
    return 0;
}

static int cmd_brdf(const opts *o)
{
    msim_run r;
    msim_result res;
    int a, i, j;
    base_run(&r, o);
    r.nb_mu = o->nb_mu;
    r.nb_phi = o->nb_phi;
    if (msim_simulate(&r, &res))
        return 2;
    printf("# brdf: facet %d alpha %.17g f0 %g nl %.17g, %llu paths, seed %llu; bins: cos theta_o "
           "uniform x %d, |phi| uniform in [0, 180] x %d (phi 0: L's side)\n",
           o->facet, o->alpha, o->f0, o->nl, (unsigned long long)res.paths, (unsigned long long)o->seed,
           o->nb_mu, o->nb_phi);
    printf("# directional albedo (analog):");
    for (a = 0; a < MSIM_NACC; a++)
        printf(" %s %.6f +- %.6f", msim_acc_name[a], msim_mean(&res.albedo, a, res.paths),
               msim_se(&res.albedo, a, res.paths));
    printf("\n# events/path %.4f, cut %llu\n", (double)res.events / res.paths, (unsigned long long)res.cut);
    printf("# mu_lo\tmu_hi\tphi_lo\tphi_hi\ttotal\tse\tsingle\tse\tmulti\tse\n");
    for (i = 0; i < o->nb_mu; i++)
        for (j = 0; j < o->nb_phi; j++) {
            const msim_acc *b = &res.bins[i * o->nb_phi + j];
            double m = msim_bin_measure(i, o->nb_mu, o->nb_phi);
            printf("%.4f\t%.4f\t%.2f\t%.2f", (double)i / o->nb_mu, (double)(i + 1) / o->nb_mu,
                   180.0 * j / o->nb_phi, 180.0 * (j + 1) / o->nb_phi);
            for (a = MSIM_TOTAL; a <= MSIM_MULTI; a++)
                printf("\t%.6e\t%.2e", msim_mean(b, a, res.paths) / m, msim_se(b, a, res.paths) / m);
            printf("\n");
        }
    msim_free(&res);
    return 0;
}

/* the table columns each material keeps (msim_tables.h names them) */
static int cmd_table(const opts *o)
{
    int im, ia, il;
    double t_all = 0;
    if (!o->out)
        return -1;
    for (im = 0; im < MSIM_NMAT; im++) {
        char path[1024];
        FILE *f, *fa;
        const int *cols = msim_table_cols[im];
        int ncols = msim_table_ncols[im], c;
        clock_t t0 = clock();
        time_t w0 = time(NULL);
        if (o->only && strcmp(o->only, msim_grid_mat[im].name))
            continue;
        snprintf(path, sizeof path, "%s/ref_%s.tsv", o->out, msim_grid_mat[im].name);
        f = fopen(path, "w");
        snprintf(path, sizeof path, "%s/albedo_%s.tsv", o->out, msim_grid_mat[im].name);
        fa = fopen(path, "w");
        if (!f || !fa) {
            fprintf(stderr, "microsurface: cannot write %s\n", path);
            return 2;
        }
        fprintf(f, "# microsurface reference, material %s (bench/microsurface/README.md): BRDF values "
                   "f(L, V) (not times N.V) by next-event estimation\n",
                msim_grid_mat[im].name);
        fprintf(f, "# made by: build/microsurface table --out DIR --paths %llu --seed %llu "
                   "(make microsurface); f0 %g; paths per (alpha, nl) run\n",
                (unsigned long long)o->paths, (unsigned long long)o->seed, msim_grid_mat[im].f0);
        fprintf(f, "# columns: alpha nl nv phi_deg lv, run_nl (the incidence of the run that estimated the row: the "
                   "more grazing of L and V; rows with run_nl = nv are f(V, L) by reciprocity), paths, then per part "
                   "its mean and standard error\n");
        fprintf(f, "alpha\tnl\tnv\tphi\tlv\trun_nl\tpaths");
        for (c = 0; c < ncols; c++)
            fprintf(f, "\t%s\tse_%s", msim_acc_name[cols[c]], msim_acc_name[cols[c]]);
        fprintf(f, "\n");
        fprintf(fa, "# microsurface directional albedo, material %s, analog estimator (escaped "
                    "energy per path), same runs as ref_%s.tsv\n",
                msim_grid_mat[im].name, msim_grid_mat[im].name);
        fprintf(fa, "alpha\tnl\tpaths\tevents_per_path\tcut");
        for (c = 0; c < MSIM_NACC; c++)
            fprintf(fa, "\t%s\tse_%s", msim_acc_name[c], msim_acc_name[c]);
        fprintf(fa, "\n");
        for (ia = 0; ia < MSIM_NALPHA; ia++) {
            /* rows[il][iv][ip]: the values at (cos[il], cos[iv], phi[ip]); the run at
             * incidence cos[il] estimates every V at least as steep (iv <= il), and
             * the rows with V more grazing than L are those values by reciprocity */
            static double val[MSIM_NCOS][MSIM_NCOS][MSIM_NPHI][MSIM_NACC], se[MSIM_NCOS][MSIM_NCOS][MSIM_NPHI][MSIM_NACC];
            static double npaths[MSIM_NCOS];
            int iv, ip;
            for (il = 0; il < MSIM_NCOS; il++) {
                msim_v3 out[MSIM_NCOS * MSIM_NPHI];
                int oiv[MSIM_NCOS * MSIM_NPHI], oip[MSIM_NCOS * MSIM_NPHI];
                int n = 0, j, a;
                msim_run r;
                msim_result res;
                double nl = msim_grid_cos[il];
                for (iv = 0; iv <= il; iv++)
                    for (ip = 0; ip < (iv == 0 ? 1 : MSIM_NPHI); ip++) {
                        oiv[n] = iv;
                        oip[n] = ip;
                        out[n] = msim_dir(msim_grid_cos[iv], msim_grid_phi[ip]);
                        n++;
                    }
                memset(&r, 0, sizeof r);
                r.mat.facet = msim_grid_mat[im].facet;
                r.mat.alpha = msim_grid_alpha[ia];
                r.mat.f0 = msim_grid_mat[im].f0;
                r.nl = nl;
                r.n_out = n;
                r.out = out;
                r.seed = o->seed;
                r.paths = o->paths;
                r.threads = o->threads;
                r.max_events = o->max_events;
                if (msim_simulate(&r, &res))
                    return 2;
                npaths[il] = (double)res.paths;
                for (j = 0; j < n; j++) {
                    double nv = msim_grid_cos[oiv[j]];
                    for (a = 0; a < MSIM_NACC; a++) {
                        val[il][oiv[j]][oip[j]][a] = msim_mean(&res.nee[j], a, res.paths) / nv;
                        se[il][oiv[j]][oip[j]][a] = msim_se(&res.nee[j], a, res.paths) / nv;
                    }
                }
                fprintf(fa, "%.17g\t%.17g\t%llu\t%.5f\t%llu", r.mat.alpha, nl, (unsigned long long)res.paths,
                        (double)res.events / res.paths, (unsigned long long)res.cut);
                for (c = 0; c < MSIM_NACC; c++)
                    fprintf(fa, "\t%.7e\t%.2e", msim_mean(&res.albedo, c, res.paths),
                            msim_se(&res.albedo, c, res.paths));
                fprintf(fa, "\n");
                fflush(fa);
                msim_free(&res);
            }
            for (il = 0; il < MSIM_NCOS; il++)
                for (iv = 0; iv < MSIM_NCOS; iv++)
                    for (ip = 0; ip < (iv == 0 || il == 0 ? 1 : MSIM_NPHI); ip++) {
                        double nl = msim_grid_cos[il], nv = msim_grid_cos[iv];
                        int rl = iv <= il ? il : iv, rv = iv <= il ? iv : il; /* the run and its V */
                        int rp = rv == 0 ? 0 : ip;
                        msim_v3 v = msim_dir(nv, msim_grid_phi[ip]);
                        double lv = sqrt(fmax(0.0, 1.0 - nl * nl)) * v.x + nl * v.z;
                        fprintf(f, "%.17g\t%.17g\t%.17g\t%g\t%.17g\t%.17g\t%.0f", msim_grid_alpha[ia], nl, nv,
                                msim_grid_phi[ip], lv, msim_grid_cos[rl], npaths[rl]);
                        for (c = 0; c < ncols; c++)
                            fprintf(f, "\t%.6e\t%.2e", val[rl][rv][rp][cols[c]], se[rl][rv][rp][cols[c]]);
                        fprintf(f, "\n");
                    }
            fflush(f);
        }
        fclose(f);
        fclose(fa);
        t_all += (double)(clock() - t0) / CLOCKS_PER_SEC;
        fprintf(stderr, "microsurface table: %s done, %.0f s CPU (process), %.0f s wall\n",
                msim_grid_mat[im].name, (double)(clock() - t0) / CLOCKS_PER_SEC, difftime(time(NULL), w0));
    }
    fprintf(stderr, "microsurface table: %.0f s CPU in all\n", t_all);
    return 0;
}

int msim_cmd_error(const char *dir);
int msim_cmd_refit(const char *dir);
int msim_cmd_energy(const char *dir);

int main(int argc, char **argv)
{
    opts o;
    int rc;
    if (argc < 2 || parse(argc, argv, &o)) {
        usage();
        return 2;
    }
    /* the model-error tables quote the f32 kernels' values: the portable
     * scalar port (IEEE operations only) gives the same digits on every
     * CPU, where a dispatched per-sample call would carry this CPU's
     * rcp/rsqrt estimates (they differ between vendors) into the
     * committed, byte-compared files */
    if (facet_set_port("scalar") != 0) {
        fprintf(stderr, "microsurface: cannot select the scalar port\n");
        return 1;
    }
    if (!strcmp(argv[1], "point"))
        rc = cmd_point(&o);
    else if (!strcmp(argv[1], "brdf"))
        rc = cmd_brdf(&o);
    else if (!strcmp(argv[1], "table"))
        rc = cmd_table(&o);
    else if (!strcmp(argv[1], "error") && o.dir)
        rc = msim_cmd_error(o.dir);
    else if (!strcmp(argv[1], "refit") && o.dir)
        rc = msim_cmd_refit(o.dir);
    else if (!strcmp(argv[1], "energy") && o.dir)
        rc = msim_cmd_energy(o.dir);
    else
        rc = -1;
    if (rc < 0)
        usage();
    return rc < 0 ? 2 : rc;
}
