/* raster_simd_body.h - the SIMD-inline shading path of the rasterizer,
 * W pixels per kernel call.  Included by raster_{avx2,sse2,neon}.c with
 * V, W, LD, ST, SET1, ADD, SUB, MUL, DIV, SQRT, MAX, BRDF_RGB, SHADE_FN defined.
 * Same lighting as rs_shade_scalar (raster.c), vectorised across pixels. */
SHADE_FN(rs_gbuf *g)
{
    int i, l, c;
    V one = SET1(1.0f), zero = SET1(0.0f);
    V cx = SET1(g->cam[0]), cy = SET1(g->cam[1]), cz = SET1(g->cam[2]);
    for (i = 0; i < g->cap; i += W) {
        V px = LD(g->px + i), py = LD(g->py + i), pz = LD(g->pz + i);
        V nx = LD(g->nx + i), ny = LD(g->ny + i), nz = LD(g->nz + i);
        V vx = SUB(cx, px), vy = SUB(cy, py), vz = SUB(cz, pz);
        V a = LD(g->alpha + i), inv;
        V acc[3];
        acc[0] = acc[1] = acc[2] = zero;
        inv = DIV(one, SQRT(ADD(ADD(MUL(nx, nx), MUL(ny, ny)), MUL(nz, nz))));
        nx = MUL(nx, inv); ny = MUL(ny, inv); nz = MUL(nz, inv);
        inv = DIV(one, SQRT(ADD(ADD(MUL(vx, vx), MUL(vy, vy)), MUL(vz, vz))));
        vx = MUL(vx, inv); vy = MUL(vy, inv); vz = MUL(vz, inv);
        for (l = 0; l < g->n_lights; l++) {
            const rs_light *L = &g->light[l];
            V dx, dy, dz, att = one, nol, nov, lov, sc;
            if (L->point) {
                V r2;
                dx = SUB(SET1(L->v[0]), px);
                dy = SUB(SET1(L->v[1]), py);
                dz = SUB(SET1(L->v[2]), pz);
                r2 = ADD(ADD(MUL(dx, dx), MUL(dy, dy)), MUL(dz, dz));
                inv = DIV(one, SQRT(r2));
                dx = MUL(dx, inv); dy = MUL(dy, inv); dz = MUL(dz, inv);
                att = DIV(one, r2);
            } else {
                dx = SET1(L->v[0]); dy = SET1(L->v[1]); dz = SET1(L->v[2]);
            }
            nol = ADD(ADD(MUL(nx, dx), MUL(ny, dy)), MUL(nz, dz));
            nov = ADD(ADD(MUL(nx, vx), MUL(ny, vy)), MUL(nz, vz));
            lov = ADD(ADD(MUL(dx, vx), MUL(dy, vy)), MUL(dz, vz));
            sc = MUL(MAX(nol, zero), att);
            {
                /* the RGB kernel: geometry once, three channels */
                V f0v[3], albv[3], b[3];
                for (c = 0; c < 3; c++) {
                    f0v[c] = LD(g->f0[c] + i);
                    albv[c] = LD(g->alb[c] + i);
                }
                BRDF_RGB(&b[0], &b[1], &b[2], nol, nov, lov, a, f0v[0], f0v[1], f0v[2], albv[0], albv[1],
                         albv[2]);
                for (c = 0; c < 3; c++)
                    acc[c] = ADD(acc[c], MUL(MUL(b[c], sc), SET1(L->e[c])));
            }
        }
        for (c = 0; c < 3; c++)
            ST(g->out[c] + i, acc[c]);
    }
    return 1;
}
