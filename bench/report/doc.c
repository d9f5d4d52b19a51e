/* doc.c - see doc.h: the document hands every element to each writer. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "doc_writer.h"

#define DOC_MAX_WRITERS 4
#define DOC_MAX_COLS 64

struct doc {
    doc_writer *w[DOC_MAX_WRITERS];
    int n, cols;
};

doc *doc_new(void)
{
    doc *d = calloc(1, sizeof *d);
    if (!d) {
        fprintf(stderr, "facet-bench report: out of memory\n");
        exit(1);
    }
    return d;
}

void doc_attach(doc *d, doc_writer *w)
{
    if (w && d->n < DOC_MAX_WRITERS)
        d->w[d->n++] = w;
}

void doc_free(doc *d)
{
    int i;
    if (!d)
        return;
    for (i = 0; i < d->n; i++)
        free(d->w[i]);
    free(d);
}

/* the formatted text, malloc'd */
static char *vformat(const char *fmt, va_list ap)
{
    va_list aq;
    int n;
    char *b;
    va_copy(aq, ap);
    n = vsnprintf(NULL, 0, fmt, aq);
    va_end(aq);
    b = malloc((size_t)(n < 0 ? 0 : n) + 1);
    if (!b) {
        fprintf(stderr, "facet-bench report: out of memory\n");
        exit(1);
    }
    vsnprintf(b, (size_t)(n < 0 ? 0 : n) + 1, fmt, ap);
    return b;
}

/* t = the caller's format and arguments, formatted */
#define FORMAT_ARGS(t, fmt)                                                                            \
    do {                                                                                               \
        va_list ap_;                                                                                   \
        va_start(ap_, fmt);                                                                            \
        t = vformat(fmt, ap_);                                                                         \
        va_end(ap_);                                                                                   \
    } while (0)

void doc_heading(doc *d, int level, const char *fmt, ...)
{
    char *t;
    int i;
    FORMAT_ARGS(t, fmt);
    for (i = 0; i < d->n; i++)
        d->w[i]->heading(d->w[i], level, t);
    free(t);
}

void doc_para(doc *d, const char *fmt, ...)
{
    char *t;
    int i;
    FORMAT_ARGS(t, fmt);
    for (i = 0; i < d->n; i++)
        d->w[i]->para(d->w[i], t);
    free(t);
}

void doc_table_head(doc *d, int n, const char *const *head)
{
    int i;
    d->cols = n;
    for (i = 0; i < d->n; i++)
        d->w[i]->table_head(d->w[i], n, head);
}

void doc_table(doc *d, int n, ...)
{
    const char *head[DOC_MAX_COLS];
    va_list ap;
    int i;
    va_start(ap, n);
    for (i = 0; i < n && i < DOC_MAX_COLS; i++)
        head[i] = va_arg(ap, const char *);
    va_end(ap);
    doc_table_head(d, i, head);
}

void doc_row(doc *d, const char *const *cells)
{
    int i;
    for (i = 0; i < d->n; i++)
        d->w[i]->row(d->w[i], d->cols, cells);
}

void doc_table_end(doc *d)
{
    int i;
    for (i = 0; i < d->n; i++)
        d->w[i]->table_end(d->w[i]);
}

void doc_figure(doc *d, const doc_fig *f)
{
    int i;
    for (i = 0; i < d->n; i++)
        d->w[i]->figure(d->w[i], f);
}

void doc_markdown(doc *d, const char *text, size_t n)
{
    int i;
    for (i = 0; i < d->n; i++)
        d->w[i]->markdown(d->w[i], text, n);
}

void doc_only(doc *d, int kind, const char *fmt, ...)
{
    char *t;
    int i;
    FORMAT_ARGS(t, fmt);
    for (i = 0; i < d->n; i++)
        if (d->w[i]->kind == kind)
            fputs(t, d->w[i]->f);
    free(t);
}
