/* doc_html.c - the HTML writer of the report's document (doc.h), the page
 * around it, and the Markdown the other tools write, converted. */
#include <stdlib.h>
#include <string.h>
#include "doc_writer.h"

static void html_heading(doc_writer *w, int level, const char *text)
{
    fprintf(w->f, "<h%d>%s</h%d>\n", level, text, level);
}

static void html_para(doc_writer *w, const char *text) { fprintf(w->f, "<p>%s</p>\n", text); }

static void html_cells(FILE *f, int n, const char *const *cells, const char *tag)
{
    int i;
    fprintf(f, "<tr>");
    for (i = 0; i < n; i++)
        fprintf(f, "<%s>%s</%s>", tag, cells[i], tag);
    fprintf(f, "</tr>\n");
}

static void html_table_head(doc_writer *w, int n, const char *const *head)
{
    fprintf(w->f, "<table>");
    html_cells(w->f, n, head, "th");
}

static void html_row(doc_writer *w, int n, const char *const *cells) { html_cells(w->f, n, cells, "td"); }

static void html_table_end(doc_writer *w) { fprintf(w->f, "</table>\n"); }

static void html_figure(doc_writer *w, const doc_fig *f)
{
    fprintf(w->f, "<figure>");
    if (f->svg)
        fputs(f->svg, w->f);
    else
        fprintf(w->f, "<img alt=\"%s\" src=\"data:image/png;base64,%s\">", f->title ? f->title : "",
                f->png_b64 ? f->png_b64 : "");
    if (f->title)
        fprintf(w->f, "<figcaption><b>%s.</b> %s</figcaption>", f->title, f->caption ? f->caption : "");
    fprintf(w->f, "</figure>\n");
}

void doc_html_from_markdown(FILE *out, const char *text, size_t n)
{
    const char *p = text, *end = text + n;
    int in_table = 0, header = 0;
    char *line = malloc(n + 1);
    if (!line)
        return;
    while (p < end) {
        const char *e = memchr(p, '\n', (size_t)(end - p));
        size_t len = e ? (size_t)(e - p) : (size_t)(end - p);
        memcpy(line, p, len);
        line[len] = 0;
        p = e ? e + 1 : end;
        while (len && (line[len - 1] == '\r'))
            line[--len] = 0;
        if (line[0] == '|') {
            char *c = line + 1, *q;
            if (strstr(line, "---")) {
                header = 0;
                continue;
            }
            if (!in_table) {
                fputs("<table>", out);
                in_table = 1;
                header = 1;
            }
            fputs("<tr>", out);
            while ((q = strchr(c, '|'))) {
                *q = 0;
                fprintf(out, header ? "<th>%s</th>" : "<td>%s</td>", c);
                c = q + 1;
            }
            fputs("</tr>\n", out);
            continue;
        }
        if (in_table) {
            fputs("</table>\n", out);
            in_table = 0;
        }
        if (!line[0])
            continue;
        if (line[0] == '#') {
            int lv = 0;
            while (line[lv] == '#')
                lv++;
            fprintf(out, "<h%d>%s</h%d>\n", lv, line + lv + (line[lv] ? 1 : 0), lv);
        } else {
            fprintf(out, "<p>%s</p>\n", line);
        }
    }
    if (in_table)
        fputs("</table>\n", out);
    free(line);
}

static void html_markdown(doc_writer *w, const char *text, size_t n) { doc_html_from_markdown(w->f, text, n); }

void doc_html_page_begin(FILE *f, const char *title)
{
    fprintf(f, "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>%s</title>\n", title);
    fputs("<style>body{font-family:sans-serif;max-width:1200px;margin:2em auto;padding:0 1em;color:#222}"
          "table{border-collapse:collapse;font-size:12px;margin:1em 0}td,th{border:1px solid #ccc;padding:2px 6px;"
          "text-align:left}th{background:#f0f0f0}figure{margin:1em 0}figcaption{font-size:12px;color:#444;"
          "max-width:900px}img{image-rendering:pixelated}</style></head><body>\n", f);
}

void doc_html_page_end(FILE *f) { fputs("</body></html>\n", f); }

doc_writer *doc_html_writer(FILE *f)
{
    doc_writer *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    w->kind = DOC_HTML;
    w->f = f;
    w->heading = html_heading;
    w->para = html_para;
    w->table_head = html_table_head;
    w->row = html_row;
    w->table_end = html_table_end;
    w->figure = html_figure;
    w->markdown = html_markdown;
    return w;
}
