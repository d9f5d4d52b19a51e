/* geom.c - see geom.h. */
#include <math.h>
#include <string.h>
#include "geom.h"

int geom_input(const geom *g, const char *name, double *v)
{
    double t = 1.0 + g->lv, lh = sqrt(t > 0 ? t / 2 : 0);
    double nh = lh > 0 ? (g->nl + g->nv) / (2 * lh) : 1;
    if (nh > 1)
        nh = 1;
    if (!strcmp(name, "nol"))
        *v = g->nl;
    else if (!strcmp(name, "nov"))
        *v = g->nv;
    else if (!strcmp(name, "lov"))
        *v = g->lv;
    else if (!strcmp(name, "noh"))
        *v = nh;
    else if (!strcmp(name, "loh") || !strcmp(name, "voh") || !strcmp(name, "cos"))
        *v = lh;
    else if (!strcmp(name, "toh"))
        *v = sqrt(1 - nh * nh);
    else if (!strcmp(name, "boh"))
        *v = 0;
    else if (!strcmp(name, "alpha") || !strcmp(name, "alpha_x") || !strcmp(name, "alpha_y"))
        *v = g->alpha;
    else if (!strcmp(name, "f0"))
        *v = g->f0;
    else if (!strcmp(name, "f90"))
        *v = g->f90;
    else if (!strcmp(name, "albedo"))
        *v = g->albedo;
    else if (!strcmp(name, "gamma"))
        *v = g->gamma;
    else
        return 0;
    return 1;
}

int geom_inputs(const geom *g, const char *const *names, int n, double *in)
{
    int i;
    for (i = 0; i < n; i++)
        if (!geom_input(g, names[i], &in[i]))
            return 0;
    return 1;
}
