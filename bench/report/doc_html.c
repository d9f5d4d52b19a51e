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

/* A table of more than LONG_TABLE rows is collapsed into a <details>
 * whose summary says how many rows it has and what its columns are, so
 * that the page reads as headings, text and figures; a short one is
 * shown as is. */
#define LONG_TABLE 12

/* the table's text (tab_buf, tab_len), written to out: collapsed if long;
 * head: the column names, for the summary */
static void table_put(FILE *out, const char *buf, size_t len, int rows, const char *head)
{
    if (rows > LONG_TABLE)
        fprintf(out, "<details><summary>table of %d rows: %s (click to show)</summary>\n", rows, head);
    fwrite(buf, 1, len, out);
    if (rows > LONG_TABLE)
        fputs("</details>\n", out);
}

/* the column names as one line of text ("a, b, c"), tags dropped */
static void head_text(char *b, size_t cap, int n, const char *const *head)
{
    size_t len = 0;
    int i, in_tag = 0;
    const char *p;
    b[0] = 0;
    for (i = 0; i < n && len + 3 < cap; i++) {
        if (i) {
            b[len++] = ',';
            b[len++] = ' ';
        }
        for (p = head[i]; *p && len + 1 < cap; p++) {
            if (*p == '<')
                in_tag = 1;
            else if (*p == '>')
                in_tag = 0;
            else if (!in_tag)
                b[len++] = *p;
        }
    }
    b[len] = 0;
}

static char table_head_text[512];

static void html_table_head(doc_writer *w, int n, const char *const *head)
{
    w->tab_buf = NULL;
    w->tab_len = 0;
    w->tab_rows = 0;
    w->tab = open_memstream(&w->tab_buf, &w->tab_len);
    head_text(table_head_text, sizeof table_head_text, n, head);
    fprintf(w->tab ? w->tab : w->f, "<table>");
    html_cells(w->tab ? w->tab : w->f, n, head, "th");
}

static void html_row(doc_writer *w, int n, const char *const *cells)
{
    w->tab_rows++;
    html_cells(w->tab ? w->tab : w->f, n, cells, "td");
}

static void html_table_end(doc_writer *w)
{
    if (!w->tab) {
        fprintf(w->f, "</table>\n");
        return;
    }
    fprintf(w->tab, "</table>\n");
    fclose(w->tab);
    w->tab = NULL;
    table_put(w->f, w->tab_buf, w->tab_len, w->tab_rows, table_head_text);
    free(w->tab_buf);
    w->tab_buf = NULL;
}

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

void doc_html_from_markdown(FILE *page, const char *text, size_t n)
{
    const char *p = text, *end = text + n;
    int in_table = 0, header = 0, rows = 0;
    char *line = malloc(n + 1), *tbuf = NULL, head[512];
    size_t tlen = 0;
    FILE *out = page; /* a table goes to tbuf until it ends (table_put) */
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
                FILE *t = open_memstream(&tbuf, &tlen);
                out = t ? t : page;
                fputs("<table>", out);
                in_table = 1;
                header = 1;
                rows = 0;
                head[0] = 0;
            }
            fputs("<tr>", out);
            rows += !header;
            while ((q = strchr(c, '|'))) {
                *q = 0;
                fprintf(out, header ? "<th>%s</th>" : "<td>%s</td>", c);
                if (header) { /* the column name, trimmed, for the summary */
                    size_t cl;
                    while (*c == ' ')
                        c++;
                    cl = strlen(c);
                    while (cl && c[cl - 1] == ' ')
                        c[--cl] = 0;
                    if (strlen(head) + cl + 3 < sizeof head)
                        strcat(strcat(head, head[0] ? ", " : ""), c);
                }
                c = q + 1;
            }
            fputs("</tr>\n", out);
            continue;
        }
        if (in_table) {
            fputs("</table>\n", out);
            in_table = 0;
            if (out != page) {
                fclose(out);
                out = page;
                table_put(page, tbuf, tlen, rows, head);
                free(tbuf);
                tbuf = NULL;
            }
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
    if (in_table) {
        fputs("</table>\n", out);
        if (out != page) {
            fclose(out);
            table_put(page, tbuf, tlen, rows, head);
            free(tbuf);
        }
    }
    free(line);
}

static void html_markdown(doc_writer *w, const char *text, size_t n) { doc_html_from_markdown(w->f, text, n); }

void doc_html_page_begin(FILE *f, const char *title)
{
    fprintf(f, "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>%s</title>\n", title);
    fputs("<style>body{font-family:sans-serif;max-width:1200px;margin:2em auto;padding:0 1em;color:#222}"
          "table{border-collapse:collapse;font-size:12px;margin:1em 0}td,th{border:1px solid #ccc;padding:2px 6px;"
          "text-align:left}th{background:#f0f0f0}figure{margin:1em 0}figcaption{font-size:12px;color:#444;"
          "max-width:900px}img{image-rendering:pixelated}summary{cursor:pointer;color:#0550ae;font-size:13px;margin:.5em 0}</style></head><body>\n", f);
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
