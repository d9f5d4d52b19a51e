/* raster.c - see raster.h. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "facet/scalar.h"
#include "facet/oracle.h"
#include "facet/fx.h"
#include "raster.h"

/* ---- scene ----------------------------------------------------------------- */

typedef struct vtx { float p[3], n[3]; } vtx;

typedef struct material { float alpha, f0[3], alb[3]; } material;

#define N_SPHERES 5
static const material mats[N_SPHERES + 1] = {
    { 0.02f, { 0.95f, 0.64f, 0.54f }, { 0.0f, 0.0f, 0.0f } },    /* polished copper */
    { 0.08f, { 0.04f, 0.04f, 0.04f }, { 0.80f, 0.10f, 0.10f } }, /* glossy red plastic */
    { 0.20f, { 1.00f, 0.78f, 0.34f }, { 0.0f, 0.0f, 0.0f } },    /* gold */
    { 0.45f, { 0.04f, 0.04f, 0.04f }, { 0.10f, 0.50f, 0.80f } }, /* blue plastic */
    { 0.90f, { 0.04f, 0.04f, 0.04f }, { 0.75f, 0.75f, 0.70f } }, /* rough clay */
    { 0.30f, { 0.04f, 0.04f, 0.04f }, { 0.35f, 0.45f, 0.30f } }, /* floor */
};

typedef struct mat4 { float m[16]; } mat4; /* row-major, column vectors */

static void xform(const mat4 *M, const float p[3], float out[4])
{
    int r;
    for (r = 0; r < 4; r++)
        out[r] = M->m[r * 4] * p[0] + M->m[r * 4 + 1] * p[1] + M->m[r * 4 + 2] * p[2] + M->m[r * 4 + 3];
}

static void normalize3(float v[3])
{
    float l = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l > 0) {
        v[0] /= l;
        v[1] /= l;
        v[2] /= l;
    }
}

static void cross3(const float a[3], const float b[3], float c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* perspective projection * look-at */
static mat4 camera(const float eye[3], const float at[3], float fovy, float aspect)
{
    float f[3], s[3], u[3], up[3] = { 0, 1, 0 }, t = 1.0f / tanf(fovy / 2);
    float zn = 0.1f, zf = 100.0f;
    mat4 V, P, M;
    int r, c, k;
    f[0] = at[0] - eye[0];
    f[1] = at[1] - eye[1];
    f[2] = at[2] - eye[2];
    normalize3(f);
    cross3(f, up, s);
    normalize3(s);
    cross3(s, f, u);
    memset(&V, 0, sizeof V);
    memset(&P, 0, sizeof P);
    for (k = 0; k < 3; k++) {
        V.m[k] = s[k];
        V.m[4 + k] = u[k];
        V.m[8 + k] = -f[k];
    }
    V.m[3] = -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]);
    V.m[7] = -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
    V.m[11] = f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2];
    V.m[15] = 1;
    P.m[0] = t / aspect;
    P.m[5] = t;
    P.m[10] = (zf + zn) / (zn - zf);
    P.m[11] = 2 * zf * zn / (zn - zf);
    P.m[14] = -1;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) {
            float acc = 0;
            for (k = 0; k < 4; k++)
                acc += P.m[r * 4 + k] * V.m[k * 4 + c];
            M.m[r * 4 + c] = acc;
        }
    return M;
}

typedef struct raster {
    int w, h;
    float *z;
    float *px, *py, *pz, *nx, *ny, *nz;
    unsigned char *mat;
    mat4 M;
    long tris;
} raster;

/* one triangle: clip-space setup, edge functions, z test, perspective-correct
 * interpolation (attributes / w and 1 / w are affine in screen space) */
static void tri(raster *R, const vtx *a, const vtx *b, const vtx *c, unsigned char mat)
{
    const vtx *v[3] = { a, b, c };
    float clip[3][4], sx[3], sy[3], sz[3], iw[3], area;
    int i, x0, x1, y0, y1, x, y;
    for (i = 0; i < 3; i++) {
        xform(&R->M, v[i]->p, clip[i]);
        if (clip[i][3] < 0.1f)
            return; /* behind the near plane: the scene never needs clipping */
        iw[i] = 1.0f / clip[i][3];
        sx[i] = (clip[i][0] * iw[i] * 0.5f + 0.5f) * (float)R->w;
        sy[i] = (0.5f - clip[i][1] * iw[i] * 0.5f) * (float)R->h;
        sz[i] = clip[i][2] * iw[i];
    }
    area = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sx[2] - sx[0]) * (sy[1] - sy[0]);
    if (area >= 0)
        return; /* back-facing (screen y points down) or degenerate */
    R->tris++;
    x0 = (int)floorf(fminf(sx[0], fminf(sx[1], sx[2])));
    x1 = (int)ceilf(fmaxf(sx[0], fmaxf(sx[1], sx[2])));
    y0 = (int)floorf(fminf(sy[0], fminf(sy[1], sy[2])));
    y1 = (int)ceilf(fmaxf(sy[0], fmaxf(sy[1], sy[2])));
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > R->w - 1) x1 = R->w - 1;
    if (y1 > R->h - 1) y1 = R->h - 1;
    for (y = y0; y <= y1; y++)
        for (x = x0; x <= x1; x++) {
            float qx = (float)x + 0.5f, qy = (float)y + 0.5f;
            float w0 = (sx[2] - sx[1]) * (qy - sy[1]) - (sy[2] - sy[1]) * (qx - sx[1]);
            float w1 = (sx[0] - sx[2]) * (qy - sy[2]) - (sy[0] - sy[2]) * (qx - sx[2]);
            float w2 = (sx[1] - sx[0]) * (qy - sy[0]) - (sy[1] - sy[0]) * (qx - sx[0]);
            float b0, b1, b2, z, pw;
            int k = y * R->w + x;
            if (w0 > 0 || w1 > 0 || w2 > 0)
                continue;
            b0 = w0 / area;
            b1 = w1 / area;
            b2 = w2 / area;
            z = b0 * sz[0] + b1 * sz[1] + b2 * sz[2];
            if (z >= R->z[k])
                continue;
            R->z[k] = z;
            /* perspective-correct weights */
            b0 *= iw[0];
            b1 *= iw[1];
            b2 *= iw[2];
            pw = 1.0f / (b0 + b1 + b2);
            b0 *= pw;
            b1 *= pw;
            b2 *= pw;
            R->px[k] = b0 * a->p[0] + b1 * b->p[0] + b2 * c->p[0];
            R->py[k] = b0 * a->p[1] + b1 * b->p[1] + b2 * c->p[1];
            R->pz[k] = b0 * a->p[2] + b1 * b->p[2] + b2 * c->p[2];
            R->nx[k] = b0 * a->n[0] + b1 * b->n[0] + b2 * c->n[0];
            R->ny[k] = b0 * a->n[1] + b1 * b->n[1] + b2 * c->n[1];
            R->nz[k] = b0 * a->n[2] + b1 * b->n[2] + b2 * c->n[2];
            R->mat[k] = mat;
        }
}

/* a tessellated grid of vertices, f(u, v) -> position and normal */
typedef void (*surf_fn)(float u, float v, const float *prm, vtx *out);

static void grid(raster *R, surf_fn f, const float *prm, int nu, int nv, unsigned char mat, int flip)
{
    vtx *g = malloc(sizeof(vtx) * (size_t)(nu + 1) * (size_t)(nv + 1));
    int i, j;
    for (j = 0; j <= nv; j++)
        for (i = 0; i <= nu; i++)
            f((float)i / (float)nu, (float)j / (float)nv, prm, &g[j * (nu + 1) + i]);
    for (j = 0; j < nv; j++)
        for (i = 0; i < nu; i++) {
            const vtx *a = &g[j * (nu + 1) + i], *b = &g[j * (nu + 1) + i + 1];
            const vtx *c = &g[(j + 1) * (nu + 1) + i], *d = &g[(j + 1) * (nu + 1) + i + 1];
            if (flip) {
                tri(R, a, b, c, mat);
                tri(R, b, d, c, mat);
            } else {
                tri(R, a, c, b, mat);
                tri(R, b, c, d, mat);
            }
        }
    free(g);
}

static void sphere_fn(float u, float v, const float *c, vtx *o)
{
    float th = v * 3.14159265f, ph = u * 6.28318531f;
    o->n[0] = sinf(th) * cosf(ph);
    o->n[1] = cosf(th);
    o->n[2] = -sinf(th) * sinf(ph);
    o->p[0] = c[0] + c[3] * o->n[0];
    o->p[1] = c[1] + c[3] * o->n[1];
    o->p[2] = c[2] + c[3] * o->n[2];
}

/* the floor: a rippled sheet y = -1 + 0.12 sin(2.2 x) cos(1.7 z) */
static void floor_fn(float u, float v, const float *prm, vtx *o)
{
    float x = -6.0f + 12.0f * u, z = 2.5f - 9.0f * v;
    float k1 = 2.2f, k2 = 1.7f, A = 0.12f;
    float dydx = A * k1 * cosf(k1 * x) * cosf(k2 * z), dydz = -A * k2 * sinf(k1 * x) * sinf(k2 * z);
    (void)prm;
    o->p[0] = x;
    o->p[1] = -1.0f + A * sinf(k1 * x) * cosf(k2 * z);
    o->p[2] = z;
    o->n[0] = -dydx;
    o->n[1] = 1.0f;
    o->n[2] = -dydz;
    normalize3(o->n);
}

static float *fa(size_t n) { return calloc(n, sizeof(float)); }

rs_gbuf *rs_render(int w, int h)
{
    raster R;
    rs_gbuf *g = calloc(1, sizeof *g);
    float eye[3] = { 0.0f, 1.3f, 6.2f }, at[3] = { 0.0f, -0.2f, 0.0f };
    size_t np = (size_t)w * (size_t)h, k;
    int i, c, s, mi;
    memset(&R, 0, sizeof R);
    R.w = w;
    R.h = h;
    R.z = malloc(np * sizeof(float));
    for (k = 0; k < np; k++)
        R.z[k] = INFINITY;
    R.px = fa(np); R.py = fa(np); R.pz = fa(np);
    R.nx = fa(np); R.ny = fa(np); R.nz = fa(np);
    R.mat = calloc(np, 1);
    R.M = camera(eye, at, 0.75f, (float)w / (float)h);
    for (i = 0; i < N_SPHERES; i++) {
        float prm[4];
        prm[0] = -2.6f + 1.3f * (float)i;
        prm[1] = -0.35f;
        prm[2] = 0.0f;
        prm[3] = 0.6f;
        grid(&R, sphere_fn, prm, 48, 24, (unsigned char)(i + 1), 0);
    }
    grid(&R, floor_fn, NULL, 96, 64, N_SPHERES + 1, 1);

    g->w = w;
    g->h = h;
    g->triangles = R.tris;
    for (k = 0; k < np; k++)
        g->n += R.mat[k] != 0;
    g->cap = (g->n + 7) / 8 * 8;
    if (g->cap == 0)
        g->cap = 8;
    g->idx = calloc((size_t)g->cap, sizeof(int));
    g->px = fa((size_t)g->cap); g->py = fa((size_t)g->cap); g->pz = fa((size_t)g->cap);
    g->nx = fa((size_t)g->cap); g->ny = fa((size_t)g->cap); g->nz = fa((size_t)g->cap);
    g->alpha = fa((size_t)g->cap);
    for (c = 0; c < 3; c++) {
        g->f0[c] = fa((size_t)g->cap);
        g->alb[c] = fa((size_t)g->cap);
        g->out[c] = fa((size_t)g->cap);
    }
    for (s = 0; s < 8; s++)
        g->s[s] = fa((size_t)g->cap);
    /* pixels grouped by material (runs, for the uniform-material path),
     * in scan order within a material */
    for (mi = 0, i = 0; mi < N_SPHERES + 1; mi++) {
        g->run_start[mi] = i;
        g->mat[mi].alpha = mats[mi].alpha;
        for (c = 0; c < 3; c++) {
            g->mat[mi].f0[c] = mats[mi].f0[c];
            g->mat[mi].albedo[c] = mats[mi].alb[c];
        }
    for (k = 0; k < np; k++) {
        const material *m;
        if (R.mat[k] != mi + 1)
            continue;
        m = &mats[R.mat[k] - 1];
        g->idx[i] = (int)k;
        g->px[i] = R.px[k]; g->py[i] = R.py[k]; g->pz[i] = R.pz[k];
        g->nx[i] = R.nx[k]; g->ny[i] = R.ny[k]; g->nz[i] = R.nz[k];
        g->alpha[i] = m->alpha;
        for (c = 0; c < 3; c++) {
            g->f0[c][i] = m->f0[c];
            g->alb[c][i] = m->alb[c];
        }
        i++;
    }
        g->run_len[mi] = i - g->run_start[mi];
    }
    g->n_runs = N_SPHERES + 1;
    /* padding: a valid pixel facing the camera, never written back */
    for (i = g->n; i < g->cap; i++) {
        g->pz[i] = 0; g->nz[i] = 1; g->alpha[i] = 0.5f;
    }
    memcpy(g->cam, eye, sizeof eye);
    g->n_lights = 2;
    g->light[0].point = 0;
    g->light[0].v[0] = -0.5f; g->light[0].v[1] = 0.8f; g->light[0].v[2] = 0.6f;
    normalize3(g->light[0].v);
    g->light[0].e[0] = 2.6f; g->light[0].e[1] = 2.5f; g->light[0].e[2] = 2.3f;
    g->light[1].point = 1;
    g->light[1].v[0] = 2.5f; g->light[1].v[1] = 1.5f; g->light[1].v[2] = 2.0f;
    g->light[1].e[0] = 6.0f; g->light[1].e[1] = 7.0f; g->light[1].e[2] = 9.0f;
    free(R.z); free(R.px); free(R.py); free(R.pz); free(R.nx); free(R.ny); free(R.nz); free(R.mat);
    return g;
}

void rs_free(rs_gbuf *g)
{
    int c;
    if (!g)
        return;
    free(g->idx);
    free(g->px); free(g->py); free(g->pz); free(g->nx); free(g->ny); free(g->nz);
    free(g->alpha);
    for (c = 0; c < 3; c++) {
        free(g->f0[c]);
        free(g->alb[c]);
        free(g->out[c]);
    }
    for (c = 0; c < 8; c++)
        free(g->s[c]);
    free(g);
}

/* ---- per-pixel geometry, shared by the scalar, batch and oracle paths ---- */

/* the dots for pixel i and light l, the light's irradiance scale and the
 * clamped N.L the result is multiplied by */
static void geom(const rs_gbuf *g, int i, int l, float *nol, float *nov, float *lov, float *scale)
{
    const rs_light *L = &g->light[l];
    float n[3] = { g->nx[i], g->ny[i], g->nz[i] };
    float v[3] = { g->cam[0] - g->px[i], g->cam[1] - g->py[i], g->cam[2] - g->pz[i] };
    float d[3], inv, att = 1.0f;
    inv = 1.0f / sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    n[0] *= inv; n[1] *= inv; n[2] *= inv;
    inv = 1.0f / sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    v[0] *= inv; v[1] *= inv; v[2] *= inv;
    if (L->point) {
        float r2;
        d[0] = L->v[0] - g->px[i];
        d[1] = L->v[1] - g->py[i];
        d[2] = L->v[2] - g->pz[i];
        r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        inv = 1.0f / sqrtf(r2);
        d[0] *= inv; d[1] *= inv; d[2] *= inv;
        att = 1.0f / r2;
    } else {
        d[0] = L->v[0]; d[1] = L->v[1]; d[2] = L->v[2];
    }
    *nol = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
    *nov = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
    *lov = d[0] * v[0] + d[1] * v[1] + d[2] * v[2];
    *scale = (*nol > 0 ? *nol : 0.0f) * att;
}

void rs_shade_scalar(rs_gbuf *g)
{
    int i, l, c;
    for (i = 0; i < g->n; i++) {
        float acc[3] = { 0, 0, 0 };
        for (l = 0; l < g->n_lights; l++) {
            float nol, nov, lov, sc;
            float f0[3], alb[3], b[3];
            geom(g, i, l, &nol, &nov, &lov, &sc);
            for (c = 0; c < 3; c++) {
                f0[c] = g->f0[c][i];
                alb[c] = g->alb[c][i];
            }
            facet_brdf_hammon_rgb_f32_scalar(&b[0], &b[1], &b[2], nol, nov, lov, g->alpha[i], f0[0],
                                             f0[1], f0[2], alb[0], alb[1], alb[2]);
            for (c = 0; c < 3; c++)
                acc[c] += b[c] * sc * g->light[l].e[c];
        }
        for (c = 0; c < 3; c++)
            g->out[c][i] = acc[c];
    }
}

void rs_shade_batch(rs_gbuf *g)
{
    float *nol = g->s[0], *nov = g->s[1], *lov = g->s[2], *sc = g->s[3], *b = g->s[4];
    int i, l, c, n = g->n;
    for (c = 0; c < 3; c++)
        memset(g->out[c], 0, (size_t)n * sizeof(float));
    for (l = 0; l < g->n_lights; l++) {
        for (i = 0; i < n; i++)
            geom(g, i, l, &nol[i], &nov[i], &lov[i], &sc[i]);
        for (c = 0; c < 3; c++) {
            float e = g->light[l].e[c];
            float *o = g->out[c];
            facet_brdf_hammon_f32_batch(b, nol, nov, lov, g->alpha, g->f0[c], g->alb[c], (size_t)n);
            for (i = 0; i < n; i++)
                o[i] += b[i] * sc[i] * e;
        }
    }
}

/* the dots of every pixel for light l into nol, nov, lov, sc (scratch) */
static void dots_all(rs_gbuf *g, int l)
{
    int i;
    for (i = 0; i < g->n; i++)
        geom(g, i, l, &g->s[0][i], &g->s[1][i], &g->s[2][i], &g->s[3][i]);
}

void rs_shade_rgb(rs_gbuf *g)
{
    float *b[3] = { g->s[4], g->s[5], g->s[6] }, *sc = g->s[3];
    const float *f0[3] = { g->f0[0], g->f0[1], g->f0[2] }, *alb[3] = { g->alb[0], g->alb[1], g->alb[2] };
    int i, l, c, n = g->n;
    for (c = 0; c < 3; c++)
        memset(g->out[c], 0, (size_t)n * sizeof(float));
    for (l = 0; l < g->n_lights; l++) {
        dots_all(g, l);
        facet_brdf_hammon_rgb_f32_batch(b, g->s[0], g->s[1], g->s[2], g->alpha, f0, alb, (size_t)n);
        for (c = 0; c < 3; c++) {
            float e = g->light[l].e[c], *o = g->out[c];
            for (i = 0; i < n; i++)
                o[i] += b[c][i] * sc[i] * e;
        }
    }
}

void rs_shade_material(rs_gbuf *g)
{
    float *sc = g->s[3];
    int i, l, c, r, n = g->n;
    for (c = 0; c < 3; c++)
        memset(g->out[c], 0, (size_t)n * sizeof(float));
    for (l = 0; l < g->n_lights; l++) {
        dots_all(g, l);
        for (r = 0; r < g->n_runs; r++) {
            int s0 = g->run_start[r];
            float *b[3] = { g->s[4] + s0, g->s[5] + s0, g->s[6] + s0 };
            facet_brdf_hammon_rgb_f32_batch_material(b, g->s[0] + s0, g->s[1] + s0, g->s[2] + s0, &g->mat[r],
                                                     (size_t)g->run_len[r]);
        }
        for (c = 0; c < 3; c++) {
            float e = g->light[l].e[c], *o = g->out[c], *bc = g->s[4 + c];
            for (i = 0; i < n; i++)
                o[i] += bc[i] * sc[i] * e;
        }
    }
}

/* per pixel through the vector entry: unit N, V and L per light */
void rs_shade_pixel(rs_gbuf *g)
{
    int r, i, l, c;
    for (r = 0; r < g->n_runs; r++)
        for (i = g->run_start[r]; i < g->run_start[r] + g->run_len[r]; i++) {
            float acc[3] = { 0, 0, 0 }, inv, att, k[3];
            facet_dirs_f32 d;
            d.n.x = g->nx[i]; d.n.y = g->ny[i]; d.n.z = g->nz[i];
            inv = 1.0f / sqrtf(d.n.x * d.n.x + d.n.y * d.n.y + d.n.z * d.n.z);
            d.n.x *= inv; d.n.y *= inv; d.n.z *= inv;
            d.v.x = g->cam[0] - g->px[i]; d.v.y = g->cam[1] - g->py[i]; d.v.z = g->cam[2] - g->pz[i];
            inv = 1.0f / sqrtf(d.v.x * d.v.x + d.v.y * d.v.y + d.v.z * d.v.z);
            d.v.x *= inv; d.v.y *= inv; d.v.z *= inv;
            for (l = 0; l < g->n_lights; l++) {
                const rs_light *L = &g->light[l];
                att = 1.0f;
                if (L->point) {
                    float r2;
                    d.l.x = L->v[0] - g->px[i]; d.l.y = L->v[1] - g->py[i]; d.l.z = L->v[2] - g->pz[i];
                    r2 = d.l.x * d.l.x + d.l.y * d.l.y + d.l.z * d.l.z;
                    inv = 1.0f / sqrtf(r2);
                    d.l.x *= inv; d.l.y *= inv; d.l.z *= inv;
                    att = 1.0f / r2;
                } else {
                    d.l.x = L->v[0]; d.l.y = L->v[1]; d.l.z = L->v[2];
                }
                facet_shade_hammon_rgb_f32(k, &d, &g->mat[r]);
                for (c = 0; c < 3; c++)
                    acc[c] += k[c] * att * L->e[c];
            }
            for (c = 0; c < 3; c++)
                g->out[c][i] = acc[c];
        }
}

void rs_shade_oracle(rs_gbuf *g)
{
    int i, l, c;
    for (i = 0; i < g->n; i++) {
        double acc[3] = { 0, 0, 0 };
        for (l = 0; l < g->n_lights; l++) {
            float nol, nov, lov, sc;
            geom(g, i, l, &nol, &nov, &lov, &sc);
            for (c = 0; c < 3; c++)
                acc[c] += facet_oracle_brdf_hammon(nol, nov, lov, g->alpha[i], g->f0[c][i],
                                                   g->alb[c][i]) * sc * g->light[l].e[c];
        }
        for (c = 0; c < 3; c++)
            g->out[c][i] = (float)acc[c];
    }
}

/* x in Q15, round to nearest, ties up (the facet/fx.h rule); the inputs
 * here are finite dots and material values in [-1, 1] */
static int32_t q15(float x)
{
    return (int32_t)floorf(x * 32768.0f + 0.5f);
}

/* fixed point: the float dots (and the material) rounded to Q15, N.L and
 * N.V raised to the fx cos floor (FACET_FX_COS_MIN = 2^-8, where the f32
 * kernels go down to 2^-20), one facet_brdf_hammon_fx call per light and
 * channel, its UQ40.24 result back to float for the accumulation */
int rs_shade_fx(rs_gbuf *g)
{
    int i, l, c;
    for (i = 0; i < g->n; i++) {
        float acc[3] = { 0, 0, 0 };
        int32_t qa = q15(g->alpha[i]), qf[3], qb[3];
        for (c = 0; c < 3; c++) {
            qf[c] = q15(g->f0[c][i]);
            qb[c] = q15(g->alb[c][i]);
        }
        for (l = 0; l < g->n_lights; l++) {
            float nol, nov, lov, sc;
            int32_t ql, qv, qlv;
            geom(g, i, l, &nol, &nov, &lov, &sc);
            ql = q15(nol);
            qv = q15(nov);
            qlv = q15(lov);
            if (ql < FACET_FX_COS_MIN)
                ql = FACET_FX_COS_MIN;
            if (qv < FACET_FX_COS_MIN)
                qv = FACET_FX_COS_MIN;
            for (c = 0; c < 3; c++)
                acc[c] += (float)((double)facet_brdf_hammon_fx(ql, qv, qlv, qa, qf[c], qb[c]) * 0x1p-24)
                          * sc * g->light[l].e[c];
        }
        for (c = 0; c < 3; c++)
            g->out[c][i] = acc[c];
    }
    return 1;
}

static unsigned char srgb8(float x)
{
    double y;
    x *= 0.6f; /* exposure */
    if (!(x > 0))
        return 0;
    if (x >= 1)
        return 255;
    y = x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1 / 2.4) - 0.055;
    return (unsigned char)(y * 255.0 + 0.5);
}

void rs_to_srgb(const rs_gbuf *g, unsigned char *rgb)
{
    int i, c, x, y;
    for (y = 0; y < g->h; y++)
        for (x = 0; x < g->w; x++) {
            /* background: a dark vertical gradient */
            unsigned char v = (unsigned char)(18 + 22 * y / g->h);
            unsigned char *p = rgb + ((size_t)y * (size_t)g->w + (size_t)x) * 3;
            p[0] = v;
            p[1] = v;
            p[2] = (unsigned char)(v + 8);
        }
    for (i = 0; i < g->n; i++)
        for (c = 0; c < 3; c++)
            rgb[(size_t)g->idx[i] * 3 + (size_t)c] = srgb8(g->out[c][i]);
}

void rs_diff(const rs_gbuf *g, const unsigned char *a, const unsigned char *b, int *maxd,
             double *meand)
{
    int i, c, m = 0;
    double sum = 0;
    for (i = 0; i < g->n; i++)
        for (c = 0; c < 3; c++) {
            size_t k = (size_t)g->idx[i] * 3 + (size_t)c;
            int d = abs((int)a[k] - (int)b[k]);
            if (d > m)
                m = d;
            sum += d;
        }
    *maxd = m;
    *meand = g->n ? sum / (3.0 * g->n) : 0;
}
