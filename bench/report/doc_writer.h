/* doc_writer.h - what a writer of the report's document implements (doc.h;
 * doc_md.c, doc_html.c).  Private to the report. */
#ifndef FACET_REPORT_DOC_WRITER_H
#define FACET_REPORT_DOC_WRITER_H

#include "doc.h"

struct doc_writer {
    int kind; /* DOC_MD or DOC_HTML */
    FILE *f;
    void (*heading)(doc_writer *w, int level, const char *text);
    void (*para)(doc_writer *w, const char *text);
    void (*table_head)(doc_writer *w, int n, const char *const *head);
    void (*row)(doc_writer *w, int n, const char *const *cells);
    void (*table_end)(doc_writer *w);
    void (*figure)(doc_writer *w, const doc_fig *f);
    void (*markdown)(doc_writer *w, const char *text, size_t n);
};

#endif
