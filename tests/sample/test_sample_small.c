/* test_sample_small.c - the pdfs where one argument is small: each pdf at
 * inputs where one direction component or cosine sweeps 2^-1 ... 2^-149
 * (the rest fixed, every alpha corner, anisotropic pairs stretched both
 * ways), on every port this CPU runs, both tiers, against the oracle at the
 * same float inputs (a flush-to-zero port at the flushed inputs, or at the
 * unflushed ones where its compares saw the denormal): relative
 * error within the pdf's bound wherever the oracle's value is at least the
 * absolute floor of facet.h (2^-100; 2^-60 on a flush-to-zero port),
 * within bound * floor below it.  So a positive
 * pdf above the floor never comes out 0, and an intermediate that
 * underflows long before the result does fails here. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "../lib/harness.h"
#include "facet.h"

#define ERR_FLOOR 0x1p-100
#define ERR_FLOOR_FTZ 0x1p-60

/* the active port flushes denormals (armv7 NEON, Helium): it is judged at
 * the flushed inputs, to the flush-to-zero floor (facet.h) */
static int port_flushes_denormals(void)
{
    float in = 1e-39f, out = 1.0f;
    facet_lambert_f32_batch(&out, &in, 1);
    return out == 0.0f;
}

#define T (-1.0f) /* in a template: the swept small value t */
#define MAXIN FACET_SAMPLER_MAX_INPUTS
#define NT 149 /* t = 2^-1 ... 2^-149 */

typedef struct { const char *pdf; float in[MAXIN]; int alphas; } tmpl;

/* alphas: the number of trailing alpha inputs the case sweeps over its
 * corners (1: alpha; 2: alpha_x, alpha_y) */
static const tmpl cases[] = {
    { "ggx_pdf_d", { T, 0 }, 1 },
    { "ggx_pdf_vndf", { T, 0.5f, 0.5f, 0 }, 1 },
    { "ggx_pdf_vndf", { 0.5f, T, 0.5f, 0 }, 1 },
    { "ggx_pdf_vndf", { 0.5f, 0.5f, T, 0 }, 1 },
    { "ggx_pdf_vndf", { T, 1.0f, T, 0 }, 1 },
    { "ggx_pdf_vndf_reflect", { T, 0.5f, 0.5f, 0 }, 1 },
    { "ggx_pdf_vndf_reflect", { 0.5f, 0.5f, T, 0 }, 1 },
    { "gtr_pdf_d", { T, 0, 1.0f }, 0 },
    { "gtr_pdf_d", { T, 0, 2.0f }, 0 },
    { "ggx_pdf_d_aniso", { 0, 1, T, 0, 0 }, 2 },
    { "ggx_pdf_d_aniso", { 1, 0, T, 0, 0 }, 2 },
    { "ggx_pdf_d_aniso", { T, 0, 1, 0, 0 }, 2 },
    { "ggx_pdf_d_aniso", { 0, T, 1, 0, 0 }, 2 },
    { "ggx_pdf_d_aniso", { 0.70710677f, 0.70710677f, T, 0, 0 }, 2 },
    { "ggx_pdf_vndf_aniso", { 0, 1, 0, 0, T, 1, 0, 0 }, 2 },
    { "ggx_pdf_vndf_aniso", { 1, 0, 0, T, 0, 1, 0, 0 }, 2 },
    { "ggx_pdf_vndf_aniso", { 0, 1, 0, 0, 1, T, 0, 0 }, 2 },
    { "ggx_pdf_vndf_aniso", { 0, 0, 1, 0, 1, T, 0, 0 }, 2 },
    { "ggx_pdf_vndf_aniso", { T, 0, 1, T, 0, 1, 0, 0 }, 2 },
    { "ggx_pdf_vndf_aniso", { 0.6f, 0.8f, T, 0.6f, 0.8f, T, 0, 0 }, 2 },
};
#define N_CASES (sizeof cases / sizeof cases[0])

static const float corners[] = { 0.0009765625f, 0.015625f, 0.25f, 1.0f };
#define N_CORNERS (sizeof corners / sizeof corners[0])

/* relative error of got against the oracle's w, absolute below the floor fl */
static double rel_err(double got, double w, double fl)
{
    return fabs(w) >= fl ? fabs(got - w) / fabs(w) : fabs(got - w) / fl;
}

int main(void)
{
    size_t c, pi;
    th_name = "sample_small";
    for (c = 0; c < N_CASES; c++) {
        const facet_sampler *k = facet_sampler_find(cases[c].pdf);
        int na = cases[c].alphas, nc = na == 2 ? 16 : na == 1 ? 4 : 4, tier;
        long n = (long)nc * NT, j;
        float *in[MAXIN], *out;
        double *want, *want_ftz;
        int i;
        if (!k) {
            CHECK(0, "no sampler %s", cases[c].pdf);
            continue;
        }
        for (i = 0; i < k->n_inputs; i++)
            in[i] = malloc(n * sizeof(float));
        out = malloc(n * sizeof(float));
        want = malloc(n * sizeof(double));
        want_ftz = malloc(n * sizeof(double));
        for (j = 0; j < n; j++) {
            int corner = (int)(j / NT), e = (int)(j % NT) + 1;
            float t = (float)ldexp(1.0, -e);
            double xd[MAXIN], o[1];
            for (i = 0; i < k->n_inputs; i++)
                in[i][j] = cases[c].in[i] == T ? t : cases[c].in[i];
            /* the alphas: the trailing inputs named alpha* (gtr_pdf_d: alpha
             * is the second input, its corners taken in turn) */
            if (na == 2) {
                in[k->n_inputs - 2][j] = corners[corner % 4];
                in[k->n_inputs - 1][j] = corners[corner / 4];
            } else if (na == 1) {
                in[k->n_inputs - 1][j] = corners[corner];
            } else {
                in[1][j] = corners[corner];
            }
            for (i = 0; i < k->n_inputs; i++)
                xd[i] = in[i][j];
            k->oracle(o, xd);
            want[j] = o[0];
            for (i = 0; i < k->n_inputs; i++)
                if (fabs(xd[i]) < 0x1p-126)
                    xd[i] = 0.0;
            k->oracle(o, xd);
            want_ftz[j] = o[0];
        }
        for (tier = 0; tier < 2; tier++) {
            double bound = tier ? k->err_f32_fast : k->err_f32;
            for (pi = 0; pi < facet_port_count(); pi++) {
                int sup, ftz;
                const char *pn = facet_port_at(pi, &sup, NULL);
                double worst = 0;
                long wj = -1, bad = 0;
                if (!sup)
                    continue;
                facet_set_port(pn);
                ftz = port_flushes_denormals();
                (tier ? k->f32_fast_batch : k->f32_batch)(&out, (const float *const *)in, (size_t)n);
                for (j = 0; j < n; j++) {
                    double fl = ftz ? ERR_FLOOR_FTZ : ERR_FLOOR, w = ftz ? want_ftz[j] : want[j];
                    double e = rel_err(out[j], w, fl);
                    /* a flush-to-zero port's compares may see the denormal
                     * as its value (qemu's armv7 NEON does): the oracle at
                     * the unflushed input is then the answer (V.H > 0 in
                     * ggx_pdf_vndf_reflect, whose pdf does not shrink with
                     * V.H) */
                    if (ftz && rel_err(out[j], want[j], fl) < e) {
                        w = want[j];
                        e = rel_err(out[j], w, fl);
                    }
                    if (!(e <= bound))
                        bad++;
                    if (!(e <= worst)) {
                        worst = e;
                        wj = j;
                    }
                }
                CHECK(bad == 0, "%s %s port %s case %lu: %ld of %ld beyond %.3g, worst %.3g at t = 2^-%ld "
                      "alpha corner %ld: got %.9g, oracle %.11g", k->name, tier ? "f32_fast" : "f32", pn, (unsigned long)c, bad,
                      n, bound, worst, wj % NT + 1, wj / NT, wj >= 0 ? out[wj] : 0.0, wj >= 0 ? (ftz ? want_ftz : want)[wj] : 0.0);
            }
        }
        facet_set_port("auto");
        for (i = 0; i < k->n_inputs; i++)
            free(in[i]);
        free(out);
        free(want);
        free(want_ftz);
    }
    return th_done();
}
