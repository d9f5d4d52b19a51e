/* doc_md.c - the Markdown writer of the report's document (doc.h). */
#include <stdlib.h>
#include "doc_writer.h"

static void md_heading(doc_writer *w, int level, const char *text)
{
    fprintf(w->f, "\n%.*s %s\n\n", level, "######", text);
}

static void md_para(doc_writer *w, const char *text) { fprintf(w->f, "%s\n\n", text); }

static void md_row(doc_writer *w, int n, const char *const *cells)
{
    int i;
    for (i = 0; i < n; i++)
        fprintf(w->f, "| %s ", cells[i]);
    fprintf(w->f, "|\n");
}

static void md_table_head(doc_writer *w, int n, const char *const *head)
{
    int i;
    md_row(w, n, head);
    for (i = 0; i < n; i++)
        fprintf(w->f, "|---");
    fprintf(w->f, "|\n");
}

static void md_table_end(doc_writer *w) { fprintf(w->f, "\n"); }

/* a figure with a file: the image and its caption; without: nothing (the
 * text says where the figure is) */
static void md_figure(doc_writer *w, const doc_fig *f)
{
    if (f->file && f->title)
        fprintf(w->f, "![%s](%s)\n\n*%s.* %s\n\n", f->title, f->file, f->title, f->caption ? f->caption : "");
}

static void md_markdown(doc_writer *w, const char *text, size_t n) { fwrite(text, 1, n, w->f); }

doc_writer *doc_md_writer(FILE *f)
{
    doc_writer *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    w->kind = DOC_MD;
    w->f = f;
    w->heading = md_heading;
    w->para = md_para;
    w->table_head = md_table_head;
    w->row = md_row;
    w->table_end = md_table_end;
    w->figure = md_figure;
    w->markdown = md_markdown;
    return w;
}
