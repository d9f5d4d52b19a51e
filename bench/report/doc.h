/* doc.h - the report as a document: a section writes its headings,
 * paragraphs, tables and figures once, and every writer attached to the
 * document renders them (doc_md.c: Markdown, bench.md and report.md;
 * doc_html.c: HTML, index.html).  Text may carry inline HTML (<b>, <code>),
 * which Markdown passes through. */
#ifndef FACET_REPORT_DOC_H
#define FACET_REPORT_DOC_H

#include <stddef.h>
#include <stdio.h>

enum { DOC_MD = 1, DOC_HTML = 2 };

/* a figure: an inline SVG (or, without one, a PNG as a data URI), its
 * title and caption ("<b>title.</b> caption"; no title: no caption) and
 * the file beside the report that Markdown links to (none: Markdown shows
 * nothing of the figure) */
typedef struct doc_fig {
    const char *title, *caption;
    const char *svg;     /* the SVG element, or NULL */
    const char *png_b64; /* without svg: the picture, base64 */
    const char *file;    /* "slices.png", or NULL */
} doc_fig;

typedef struct doc_writer doc_writer;
typedef struct doc doc;

/* writers on an open file (the caller closes it after doc_free) */
doc_writer *doc_md_writer(FILE *f);
doc_writer *doc_html_writer(FILE *f);

doc *doc_new(void);
void doc_attach(doc *d, doc_writer *w); /* the document owns w */
void doc_free(doc *d);

void doc_heading(doc *d, int level, const char *fmt, ...);
void doc_para(doc *d, const char *fmt, ...);
/* a table: its n header cells, then rows of n cells, then the end */
void doc_table(doc *d, int n, ...);
void doc_table_head(doc *d, int n, const char *const *head);
void doc_row(doc *d, const char *const *cells);
void doc_table_end(doc *d);
void doc_figure(doc *d, const doc_fig *f);
/* a Markdown block written by another tool (the accuracy sweep, a test's
 * table): Markdown copies it, HTML converts its headings, tables and
 * paragraphs */
void doc_markdown(doc *d, const char *text, size_t n);
/* a block for one format only (kind DOC_MD or DOC_HTML), written as is */
void doc_only(doc *d, int kind, const char *fmt, ...);

/* ---- the HTML page around the parts (doc_html.c) ------------------------ */
void doc_html_page_begin(FILE *f, const char *title);
void doc_html_page_end(FILE *f);
/* Markdown text -> HTML (headings, tables, paragraphs: what the accuracy
 * sweep and the tests write) */
void doc_html_from_markdown(FILE *f, const char *text, size_t n);

#endif
