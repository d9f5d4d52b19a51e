/* msim_tables.c - the reference tables' reader (msim_tables.h). */
#include "msim_tables.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int part_index(const char *name)
{
    int a;
    for (a = 0; a < MSIM_NACC; a++)
        if (!strcmp(name, msim_acc_name[a]))
            return a;
    return -1;
}

int msim_table_read(msim_table *t, const char *path)
{
    FILE *f = fopen(path, "r");
    static char line[1 << 14];
    int colpart[64], colse[64], ncol = 0, cap = 0;
    t->n = 0;
    t->row = NULL;
    if (!f)
        return -1;
    while (fgets(line, sizeof line, f)) {
        char *tok, *save = NULL;
        int c = 0;
        if (line[0] == '#' || line[0] == '\n')
            continue;
        if (!strncmp(line, "alpha\t", 6)) { /* the header: which part each column is */
            for (tok = strtok_r(line, "\t\n", &save); tok; tok = strtok_r(NULL, "\t\n", &save), c++) {
                if (c >= 64)
                    break;
                colse[c] = !strncmp(tok, "se_", 3);
                colpart[c] = part_index(colse[c] ? tok + 3 : tok);
            }
            ncol = c;
            continue;
        }
        if (ncol < 7)
            break;
        if (t->n == cap) {
            cap = cap ? 2 * cap : 1024;
            t->row = realloc(t->row, (size_t)cap * sizeof *t->row);
        }
        {
            msim_row *r = &t->row[t->n];
            int a;
            for (a = 0; a < MSIM_NACC; a++)
                r->val[a] = r->se[a] = NAN;
            for (tok = strtok_r(line, "\t\n", &save); tok && c < ncol; tok = strtok_r(NULL, "\t\n", &save), c++) {
                double v = strtod(tok, NULL);
                switch (c) {
                case 0: r->alpha = v; break;
                case 1: r->nl = v; break;
                case 2: r->nv = v; break;
                case 3: r->phi = v; break;
                case 4: r->lv = v; break;
                case 5: r->run_nl = v; break;
                case 6: r->paths = v; break;
                default:
                    if (colpart[c] >= 0) {
                        if (colse[c])
                            r->se[colpart[c]] = v;
                        else
                            r->val[colpart[c]] = v;
                    }
                }
            }
            if (c == ncol)
                t->n++;
        }
    }
    fclose(f);
    return t->n > 0 ? 0 : -1;
}

void msim_table_free(msim_table *t)
{
    free(t->row);
    t->row = NULL;
    t->n = 0;
}

const msim_row *msim_table_find(const msim_table *t, double alpha, double nl, double nv, double phi)
{
    int i;
    for (i = 0; i < t->n; i++) {
        const msim_row *r = &t->row[i];
        if (r->alpha == alpha && r->nl == nl && r->nv == nv && (nl >= 1.0 || nv >= 1.0 || r->phi == phi))
            return r;
    }
    return NULL;
}
