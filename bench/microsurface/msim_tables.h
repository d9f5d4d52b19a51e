/* msim_tables.h - the reference tables' columns and their reader
 * (bench/microsurface/README.md, "Tables"). */
#ifndef MSIM_TABLES_H
#define MSIM_TABLES_H

#include "msim.h"
#include "msim_grid.h"

/* the parts each material's table keeps, in column order */
static const int msim_table_cols[MSIM_NMAT][12] = {
    {MSIM_TOTAL, MSIM_SINGLE, MSIM_MULTI, MSIM_SPEC1, MSIM_SPECM, MSIM_D100, MSIM_D075, MSIM_D050,
     MSIM_D025, MSIM_DIFF1, MSIM_DIFF1M, MSIM_K2},
    {MSIM_TOTAL, MSIM_SINGLE, MSIM_MULTI, MSIM_D075, MSIM_D050, MSIM_D025},
    {MSIM_TOTAL, MSIM_SINGLE, MSIM_MULTI},
};
static const int msim_table_ncols[MSIM_NMAT] = {12, 6, 3};

typedef struct {
    double alpha, nl, nv, phi, lv;
    double run_nl; /* the incidence of the run that estimated it (min(nl, nv)) */
    double paths;
    double val[MSIM_NACC], se[MSIM_NACC]; /* NAN where the table has no column */
} msim_row;

typedef struct {
    int n;
    msim_row *row;
} msim_table;

/* reads DIR/ref_NAME.tsv (or any file of that format); 0 on success */
int msim_table_read(msim_table *t, const char *path);
void msim_table_free(msim_table *t);
/* the row at a grid point (exact match on alpha, nl, nv, phi), or NULL */
const msim_row *msim_table_find(const msim_table *t, double alpha, double nl, double nv, double phi);

#endif
