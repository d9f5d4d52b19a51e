/* test_sample_furnace.c - Monte Carlo white furnace: the directional albedo
 * of the GGX specular term with F = 1,
 *   A(v) = integral over L of D(H) Vis(N.L, N.V) N.L dL
 * (facet's ggx_d and smith_vis, the height-correlated Smith term), estimated
 * with visible-normal samples h, l = reflect(v, h), weight
 * f N.L / ggx_pdf_vndf_reflect (= G2 / G1(v), 0 where l is below the
 * horizon), against a quadrature of the same f32 kernels over h
 * (dL = 4 V.H dH), composite Gauss-Legendre in the q / phi coordinates of
 * tests/sample/test_sample_chi2.c.  Pass: |MC - quadrature| < 3 standard errors.
 * 10^6 samples (2 10^5 under FACET_TEST_QUICK), fixed seeds. */
#include <stdio.h>
#include <stdlib.h>
#include "../lib/harness.h"
#include "../lib/sample_common.h"
#include "../lib/quad.h"

static const double PI_ = 3.14159265358979323846;
static gl_rule GL8;

/* the integrand over h: f(l, v) N.L 4 V.H with f = D Vis from the f32 kernels */
static double integrand(const double v[3], const double h[3], float a)
{
    double vh = v[0] * h[0] + v[1] * h[1] + v[2] * h[2], lz;
    if (vh <= 0)
        return 0;
    lz = 2 * vh * h[2] - v[2];
    if (lz <= 0)
        return 0;
    return (double)facet_ggx_d_f32((float)h[2], a) * facet_smith_vis_f32((float)lz, (float)v[2], a) * lz * 4 * vh;
}

typedef struct {
    const double *v;
    float a;
    double sum;
} quad_ctx;

static void quad_node(const double h[3], double weight, void *ctx)
{
    quad_ctx *c = ctx;
    c->sum += weight * integrand(c->v, h, c->a);
}

static double quadrature(const double v[3], float a)
{
    const int NW = 96, NF = 96;
    quad_ctx c;
    int iw, ip;
    c.v = v;
    c.a = a;
    c.sum = 0;
    for (iw = 0; iw < NW; iw++)
        for (ip = 0; ip < NF; ip++)
            gl_q_cell(&GL8, a, (double)iw / NW, (double)(iw + 1) / NW, 2 * PI_ * ip / NF, 2 * PI_ * (ip + 1) / NF,
                      quad_node, &c);
    return c.sum;
}

int main(void)
{
    static const double alphas[] = { 0.1, 0.3, 0.6, 1.0 };
    static const double views[] = { 0, 45, 75, 88 };
    long n = getenv("FACET_TEST_QUICK") ? 200000 : 1000000, j;
    float *u1 = malloc(n * sizeof(float)), *u2 = malloc(n * sizeof(float));
    float *vx = malloc(n * sizeof(float)), *vy = malloc(n * sizeof(float)), *vz = malloc(n * sizeof(float));
    float *al = malloc(n * sizeof(float)), *hx = malloc(n * sizeof(float)), *hy = malloc(n * sizeof(float));
    float *hz = malloc(n * sizeof(float)), *lx = malloc(n * sizeof(float)), *ly = malloc(n * sizeof(float));
    float *lz = malloc(n * sizeof(float)), *nov = malloc(n * sizeof(float)), *voh = malloc(n * sizeof(float));
    float *pdf = malloc(n * sizeof(float)), *d = malloc(n * sizeof(float)), *vis = malloc(n * sizeof(float));
    size_t ia, iv;
    th_name = "sample_furnace";
    gl_make(&GL8, 8);
    printf("port %s, %ld samples each\n| alpha | view (deg) | MC | std err | quadrature | (MC - Q) / SE |\n|---|---|---|---|---|---|\n",
           facet_port_name(), n);
    for (ia = 0; ia < sizeof alphas / sizeof alphas[0]; ia++)
        for (iv = 0; iv < sizeof views / sizeof views[0]; iv++) {
            double t = views[iv] * PI_ / 180, v[3] = { sin(t) * cos(0.3), sin(t) * sin(0.3), cos(t) };
            float a = (float)alphas[ia];
            double s1 = 0, s2 = 0, mc, se, q;
            smp_rng rng;
            rng.s = 0xf00d0000u + ia * 16 + iv;
            for (j = 0; j < n; j++) {
                u1[j] = ss_u24(&rng);
                u2[j] = ss_u24(&rng);
                vx[j] = (float)v[0];
                vy[j] = (float)v[1];
                vz[j] = (float)v[2];
                al[j] = a;
            }
            /* the renderer's loop: sample h, reflect, the pdf of l, the BRDF */
            facet_ggx_sample_vndf_f32_batch(hx, hy, hz, vx, vy, vz, u1, u2, al, n);
            facet_reflect_f32_batch(lx, ly, lz, vx, vy, vz, hx, hy, hz, n);
            for (j = 0; j < n; j++) {
                nov[j] = vz[j];
                voh[j] = vx[j] * hx[j] + vy[j] * hy[j] + vz[j] * hz[j];
            }
            facet_ggx_pdf_vndf_reflect_f32_batch(pdf, nov, hz, voh, al, n);
            facet_ggx_d_f32_batch(d, hz, al, n);
            facet_smith_vis_f32_batch(vis, lz, nov, al, n);
            for (j = 0; j < n; j++) {
                double w = lz[j] > 0 && pdf[j] > 0 ? (double)d[j] * vis[j] * lz[j] / pdf[j] : 0;
                s1 += w;
                s2 += w * w;
            }
            mc = s1 / n;
            se = sqrt((s2 / n - mc * mc) / (n - 1));
            q = quadrature(v, a);
            printf("| %.2f | %4.1f | %.6f | %.1e | %.6f | %+.2f |\n", alphas[ia], views[iv], mc, se, q, (mc - q) / se);
            CHECK(fabs(mc - q) < 3 * se, "alpha %g view %g: MC %.6f +- %.2g vs quadrature %.6f", alphas[ia],
                  views[iv], mc, se, q);
        }
    free(u1); free(u2); free(vx); free(vy); free(vz); free(al); free(hx); free(hy); free(hz);
    free(lx); free(ly); free(lz); free(nov); free(voh); free(pdf); free(d); free(vis);
    (void)smp_inputs;
    (void)ss_inputs;
    return th_done();
}
