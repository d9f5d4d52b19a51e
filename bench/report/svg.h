/* svg.h - the report's one SVG plotting module: every figure is drawn
 * with these axes, ticks, labels, legends and panels, so that all of them
 * read the same way (tick marks 4 px outside the plot area, tick labels in
 * the figure's font, a log axis labelled 10^k, axis labels in italics, a
 * plot's title in bold above it, grid lines light grey, a legend as
 * swatches with labels).
 *
 * An SVG is built in memory (svg_begin .. svg_end) and handed to the
 * document as a figure (doc.h).  A plot is a rectangle with two axes; its
 * data go through svg_plot_x / svg_plot_y.  A labelled picture (a PNG of
 * panels, pictures.h pic_axes) gets its titles, per-panel axes and colour
 * bar from svg_picture. */
#ifndef FACET_REPORT_SVG_H
#define FACET_REPORT_SVG_H

#include <stddef.h>
#include <stdio.h>
#include "pictures.h"

typedef struct svg {
    FILE *f;
    char *buf;
    size_t len;
    int w, h;
} svg;

/* an open <svg> of w x h px (font: sans-serif 11) */
void svg_begin(svg *s, int w, int h);
/* closes it; returns the text (malloc'd, the caller frees) */
char *svg_end(svg *s);
/* an element written as is */
void svg_raw(svg *s, const char *fmt, ...);
/* text at (x, y); anchor "start", "middle" or "end"; attrs extra
 * attributes (" font-weight=\"bold\"") or "" */
void svg_text(svg *s, double x, double y, const char *anchor, const char *attrs, const char *fmt, ...);
void svg_image(svg *s, double x, double y, double w, double h, const char *png_b64, int pixelated);

/* ---- axes -------------------------------------------------------------------- */

typedef struct svg_axis {
    const char *label; /* the axis label ("" or NULL: none) */
    double lo, hi;     /* the values at the axis' start (left, bottom) and end */
    int log;           /* 1: log10 scale, ticks at powers of ten */
    double step;       /* linear: the tick step (0: automatic) */
    const char *lo_text; /* the label of the tick at lo instead of its value, or NULL */
} svg_axis;

/* where value v falls, in px from the axis' start over len px */
double svg_along(const svg_axis *a, double v, double len);
/* the tick values within [lo, hi] (either order); returns the count */
int svg_ticks(const svg_axis *a, double *t, int max);
/* the automatic linear tick step over [lo, hi] */
double svg_step(double lo, double hi);

enum { SVG_BOTTOM, SVG_LEFT };
#define SVG_SKIP_END 1   /* no tick at the axis' far end (the next panel's first stands there) */
#define SVG_NO_LABEL 2   /* ticks only, no axis label */
/* An axis along a panel edge: SVG_BOTTOM from (x, y) to the right over
 * len px, ticks and labels below; SVG_LEFT from (x, y) (its bottom) up over
 * len px, ticks and labels to the left, the axis label rotated, label_gap
 * px left of the edge.  grid > 0: grid lines that long into the panel. */
void svg_axis_draw(svg *s, const svg_axis *a, int side, double x, double y, double len, double grid, int flags,
                   double label_gap);

/* ---- plots ------------------------------------------------------------------- */

typedef struct svg_plot {
    svg *s;
    double x, y, w, h; /* the plot area, (x, y) its top left corner */
    svg_axis ax, ay;
    double label_gap;  /* the y label's distance from the area (0: 44 px) */
    int clip;          /* set by svg_plot_frame: lines are clipped to the area */
} svg_plot;

/* the area (background, frame), grid lines, both axes, and the title
 * above the area (NULL: none) */
void svg_plot_frame(svg_plot *p, const char *title);
double svg_plot_x(const svg_plot *p, double v);
double svg_plot_y(const svg_plot *p, double v);
/* a line through n points, clipped to the area; dash 0 solid, 1 dashed, 2 dotted */
void svg_plot_line(const svg_plot *p, int n, const double *x, const double *y, const char *colour, int dash,
                   double width);
/* a dot at (x, y) with a short label beside it and hover text */
void svg_plot_dot(const svg_plot *p, double x, double y, const char *colour, const char *label, const char *hover);
/* a bar from the x axis' value x0 to x1, height y */
void svg_plot_bar(const svg_plot *p, double x0, double x1, double y, const char *colour);
/* a note in the middle of the area (grey) */
void svg_plot_note(const svg_plot *p, const char *text);

/* ---- legends ----------------------------------------------------------------- */

enum { SVG_KEY_LINE, SVG_KEY_BOX, SVG_KEY_DOT };
typedef struct svg_key {
    const char *label, *colour;
    int kind, dash;
} svg_key;
/* n entries from (x, y) down, 14 px apart (across: one line, each entry
 * after the last) */
void svg_legend(svg *s, double x, double y, int n, const svg_key *k, int across);

/* the dash pattern attribute of dash (0, 1, 2), "" for solid */
const char *svg_dash(int dash);

/* ---- labelled pictures -------------------------------------------------------- */

/* the picture (its PNG as base64) in an SVG with its column and row
 * titles, each panel's axes and the colour bar (pictures.h pic_axes);
 * returns the SVG text (malloc'd) */
char *svg_picture(const pic *p, const char *png_b64);

#endif
