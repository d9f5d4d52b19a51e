/* svg.c - see svg.h. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "png.h"
#include "svg.h"

#define TICK_COLOUR "#333"
#define GRID_COLOUR "#ddd"

void svg_begin(svg *s, int w, int h)
{
    memset(s, 0, sizeof *s);
    s->w = w;
    s->h = h;
    s->f = open_memstream(&s->buf, &s->len);
    if (!s->f) {
        fprintf(stderr, "facet-bench report: out of memory\n");
        exit(1);
    }
    fprintf(s->f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" font-family=\"sans-serif\" "
                  "font-size=\"11\">\n", w, h);
}

char *svg_end(svg *s)
{
    char *b;
    fputs("</svg>", s->f);
    fclose(s->f);
    b = s->buf;
    s->f = NULL;
    s->buf = NULL;
    return b;
}

void svg_raw(svg *s, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfprintf(s->f, fmt, ap);
    va_end(ap);
}

void svg_text(svg *s, double x, double y, const char *anchor, const char *attrs, const char *fmt, ...)
{
    va_list ap;
    fprintf(s->f, "<text x=\"%.1f\" y=\"%.1f\"%s%s%s%s>", x, y, anchor ? " text-anchor=\"" : "", anchor ? anchor : "",
            anchor ? "\"" : "", attrs ? attrs : "");
    va_start(ap, fmt);
    vfprintf(s->f, fmt, ap);
    va_end(ap);
    fputs("</text>\n", s->f);
}

void svg_image(svg *s, double x, double y, double w, double h, const char *png_b64, int pixelated)
{
    fprintf(s->f, "<image x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\"%s href=\"data:image/png;base64,%s\"/>\n",
            x, y, w, h, pixelated ? " style=\"image-rendering:pixelated\"" : "", png_b64 ? png_b64 : "");
}

const char *svg_dash(int dash)
{
    return dash == 1 ? " stroke-dasharray=\"6 3\"" : dash == 2 ? " stroke-dasharray=\"2 2\"" : "";
}

/* ---- axes -------------------------------------------------------------------- */

double svg_along(const svg_axis *a, double v, double len)
{
    if (a->log)
        return (log10(v) - log10(a->lo)) / (log10(a->hi) - log10(a->lo)) * len;
    return (v - a->lo) / (a->hi - a->lo) * len;
}

/* "nice" steps (1, 2, 5 x 10^k) of about 3 to 7 per range; 30 for a
 * range of 90 (degrees) */
double svg_step(double lo, double hi)
{
    double r = fabs(hi - lo), step = pow(10, floor(log10(r / 3)));
    if (r / step > 7)
        step *= r / step > 15 ? 5 : 2;
    if (r == 90)
        step = 30;
    return step;
}

int svg_ticks(const svg_axis *a, double *t, int max)
{
    double lo = a->lo < a->hi ? a->lo : a->hi, hi = a->lo < a->hi ? a->hi : a->lo, step, v;
    int n = 0;
    if (a->log) {
        for (v = ceil(log10(lo) - 1e-9); v <= log10(hi) + 1e-9 && n < max; v++)
            t[n++] = pow(10, v);
        return n;
    }
    step = a->step > 0 ? a->step : svg_step(lo, hi);
    for (v = ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step && n < max; v += step)
        t[n++] = fabs(v) < 1e-12 * step ? 0 : v;
    return n;
}

static void tick_label(svg *s, const svg_axis *a, double x, double y, const char *anchor, double v)
{
    if (a->lo_text && fabs(v - a->lo) <= 1e-9 * fabs(a->lo))
        fprintf(s->f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"%s\">%s</text>", x, y, anchor, a->lo_text);
    else if (a->log)
        fprintf(s->f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"%s\">10<tspan dy=\"-5\" font-size=\"8\">%g</tspan></text>",
                x, y, anchor, log10(v));
    else
        fprintf(s->f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"%s\">%g</text>", x, y, anchor, v);
}

void svg_axis_draw(svg *s, const svg_axis *a, int side, double x, double y, double len, double grid, int flags,
                   double label_gap)
{
    double t[32];
    int n = svg_ticks(a, t, 32), i;
    for (i = 0; i < n; i++) {
        double u = svg_along(a, t[i], len);
        if ((flags & SVG_SKIP_END) && u > len - 0.5)
            continue;
        if (side == SVG_BOTTOM) {
            double px = x + u;
            if (grid > 0)
                fprintf(s->f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"" GRID_COLOUR "\"/>", px,
                        y - grid, px, y);
            fprintf(s->f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"" TICK_COLOUR "\"/>", px, y,
                    px, y + 4);
            tick_label(s, a, px, y + 15, "middle", t[i]);
        } else {
            double py = y - u;
            if (grid > 0)
                fprintf(s->f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"" GRID_COLOUR "\"/>", x,
                        py, x + grid, py);
            fprintf(s->f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"" TICK_COLOUR "\"/>", x - 4,
                    py, x, py);
            tick_label(s, a, x - 6, py + 4, "end", t[i]);
        }
    }
    fputc('\n', s->f);
    if ((flags & SVG_NO_LABEL) || !a->label || !a->label[0])
        return;
    if (side == SVG_BOTTOM)
        svg_text(s, x + len / 2, y + 30, "middle", " font-style=\"italic\"", "%s", a->label);
    else
        fprintf(s->f, "<text transform=\"translate(%.1f,%.1f) rotate(-90)\" text-anchor=\"middle\" "
                      "font-style=\"italic\">%s</text>\n", x - label_gap, y - len / 2, a->label);
}

/* ---- plots ------------------------------------------------------------------- */

double svg_plot_x(const svg_plot *p, double v) { return p->x + svg_along(&p->ax, v, p->w); }
double svg_plot_y(const svg_plot *p, double v) { return p->y + p->h - svg_along(&p->ay, v, p->h); }

/* clip-path ids, unique within the report's page (every figure is inline) */
static int clip_ids;

void svg_plot_frame(svg_plot *p, const char *title)
{
    p->clip = ++clip_ids;
    fprintf(p->s->f, "<clipPath id=\"plot%d\"><rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\"/></clipPath>\n",
            p->clip, p->x, p->y, p->w, p->h);
    fprintf(p->s->f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"#fafafa\" stroke=\"#888\"/>\n",
            p->x, p->y, p->w, p->h);
    svg_axis_draw(p->s, &p->ax, SVG_BOTTOM, p->x, p->y + p->h, p->w, p->h, 0, 0);
    svg_axis_draw(p->s, &p->ay, SVG_LEFT, p->x, p->y + p->h, p->h, p->w, 0, p->label_gap > 0 ? p->label_gap : 44);
    if (title)
        svg_text(p->s, p->x, p->y - 8, "start", " font-weight=\"bold\"", "%s", title);
}

void svg_plot_line(const svg_plot *p, int n, const double *x, const double *y, const char *colour, int dash,
                   double width)
{
    int i;
    fprintf(p->s->f, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"%g\"%s", colour, width, svg_dash(dash));
    if (p->clip)
        fprintf(p->s->f, " clip-path=\"url(#plot%d)\"", p->clip);
    fputs(" points=\"", p->s->f);
    for (i = 0; i < n; i++)
        fprintf(p->s->f, "%s%.1f,%.1f", i ? " " : "", svg_plot_x(p, x[i]), svg_plot_y(p, y[i]));
    fputs("\"/>\n", p->s->f);
}

void svg_plot_dot(const svg_plot *p, double x, double y, const char *colour, const char *label, const char *hover)
{
    double px = svg_plot_x(p, x), py = svg_plot_y(p, y);
    fprintf(p->s->f, "<g><circle cx=\"%.1f\" cy=\"%.1f\" r=\"3.5\" fill=\"%s\"/>", px, py, colour);
    if (label)
        fprintf(p->s->f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"9\" fill=\"%s\">%s</text>", px + 4, py - 3, colour,
                label);
    if (hover)
        fprintf(p->s->f, "<title>%s</title>", hover);
    fputs("</g>\n", p->s->f);
}

void svg_plot_bar(const svg_plot *p, double x0, double x1, double y, const char *colour)
{
    double a = svg_plot_x(p, x0), b = svg_plot_x(p, x1), top = svg_plot_y(p, y), base = svg_plot_y(p, p->ay.lo);
    fprintf(p->s->f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"%s\"/>\n", a, top,
            b - a - 0.3 > 0 ? b - a - 0.3 : 0, base - top, colour);
}

void svg_plot_note(const svg_plot *p, const char *text)
{
    svg_text(p->s, p->x + p->w / 2, p->y + p->h / 2, "middle", " fill=\"#666\"", "%s", text);
}

/* ---- legends ----------------------------------------------------------------- */

void svg_legend(svg *s, double x, double y, int n, const svg_key *k, int across)
{
    int i;
    double cx = x, cy = y;
    for (i = 0; i < n; i++) {
        if (k[i].kind == SVG_KEY_BOX)
            fprintf(s->f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"14\" height=\"10\" fill=\"%s\"/>", cx, cy - 5, k[i].colour);
        else if (k[i].kind == SVG_KEY_DOT)
            fprintf(s->f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3.5\" fill=\"%s\"/>", cx + 7, cy, k[i].colour);
        else
            fprintf(s->f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"2\"%s/>",
                    cx, cy, cx + 24, cy, k[i].colour, svg_dash(k[i].dash));
        svg_text(s, cx + (k[i].kind == SVG_KEY_LINE ? 28 : 18), cy + 4, "start", "", "%s", k[i].label);
        if (across)
            cx += (k[i].kind == SVG_KEY_LINE ? 36 : 26) + 6.2 * (double)strlen(k[i].label);
        else
            cy += 14;
    }
}

/* ---- labelled pictures -------------------------------------------------------- */

char *svg_picture(const pic *p, const char *b64)
{
    const pic_axes *a = &p->ax;
    int sc = p->w <= 460 ? 2 : 1, r, c;
    int rowt = 0, L, T = 22, B, W, H, bar = a->bar_label[0] != 0;
    int has_x = a->xlabel[0] != 0, has_y = a->ylabel[0] != 0;
    svg_axis ax = { a->xlabel, a->xmin, a->xmax, a->xlog, 0, NULL };
    svg_axis ay = { a->ylabel, a->ymin, a->ymax, a->ylog, 0, NULL };
    svg s;
    for (r = 0; r < a->rows; r++)
        if ((int)strlen(a->row_title[r]) > rowt)
            rowt = (int)strlen(a->row_title[r]);
    L = 8 + (rowt ? rowt * 7 + 8 : 0) + (has_y ? 52 : 0);
    B = (has_x ? 38 : 4) + (bar ? 48 : 0);
    W = L + p->w * sc + 12;
    H = T + p->h * sc + B;
    svg_begin(&s, W, H);
    svg_image(&s, L, T, p->w * sc, p->h * sc, b64, 1);
    for (c = 0; c < a->cols; c++) /* column titles */
        svg_text(&s, L + (a->x0 + c * (a->pw + a->gap) + a->pw / 2.0) * sc, T - 6, "middle", "", "%s", a->col_title[c]);
    for (r = 0; r < a->rows; r++) /* row titles */
        if (a->row_title[r][0])
            svg_text(&s, 6, T + (a->y0 + r * (a->ph + a->gap) + a->ph / 2.0) * sc + 4, NULL, "", "%s", a->row_title[r]);
    if (has_x) /* x axes under the bottom row of every column */
        for (c = 0; c < a->cols; c++)
            svg_axis_draw(&s, &ax, SVG_BOTTOM, L + (a->x0 + c * (a->pw + a->gap)) * sc,
                          T + (a->y0 + a->rows * (a->ph + a->gap) - a->gap) * sc, a->pw * sc, 0,
                          c + 1 < a->cols ? SVG_SKIP_END : 0, 0);
    if (has_y) /* y axes left of the first column, every row */
        for (r = 0; r < a->rows; r++)
            svg_axis_draw(&s, &ay, SVG_LEFT, L + a->x0 * sc, T + (a->y0 + r * (a->ph + a->gap) + a->ph) * sc,
                          a->ph * sc, 0, r > 0 ? SVG_SKIP_END : 0, 40);
    if (bar) { /* the colour bar with a labelled tick per power of ten */
        int bw = p->w * sc < 420 ? p->w * sc : 420, bh = 12;
        double by = T + p->h * sc + (has_x ? 38 : 4) + 4;
        svg_axis ab = { NULL, pow(10, a->bar_lo), pow(10, a->bar_hi), 1, 0, NULL };
        pic cb = pic_colorbar(bw, bh);
        unsigned char *buf;
        size_t nb = png_encode(&buf, cb.rgb, cb.w, cb.h);
        char *cb64 = nb ? png_base64(buf, nb) : NULL;
        svg_image(&s, L, by, bw, bh, cb64, 0);
        svg_axis_draw(&s, &ab, SVG_BOTTOM, L, by + bh, bw, 0, SVG_NO_LABEL, 0);
        svg_text(&s, L + bw + 8, by + 10, NULL, "", "%s", a->bar_label);
        free(cb64);
        if (nb)
            free(buf);
        pic_free(&cb);
    }
    return svg_end(&s);
}
