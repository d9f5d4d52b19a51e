/* test_docs.c - the numbers the docs state are the numbers the code has.
 *   - include/README.md's kernel tables ("## The kernels"): one row per
 *     kernel of the table (facet_kernel_at), its f32 and f32_fast bounds
 *     equal to FACET_ERR_*_F32 / _F32_FAST, its ops equal to the "Cost:" of
 *     its contract in include/facet.h, its fixed-point tiers those the fx
 *     table has;
 *   - README.md's "which one" table: each bound is the header constant of
 *     its kernel and tier (f16: FACET_ERR_<NAME>_F16 of facet/f16.h), each
 *     model error, AVX2 cost, AVX-512 cost (f16: the avx512fp16 table's)
 *     and Cortex-M4F cost is the one bench/snapshot/report.md (a committed
 *     full report) has ("-" for f16 on AVX2 and Cortex-M4F, which compute
 *     no binary16: the snapshot must have no such row), and the README
 *     states the snapshot's date;
 *   - every "FACET_ERR_<NAME> (2^-k)" in include/facet.h's comments and
 *     every "#define FACET_ERR_<NAME> v /" "* 2^-k" agree with the value;
 *   - every diffuse kernel's model-error lines in include/facet.h are the
 *     contract lines bench/microsurface/model_error.md gives (which
 *     tests/suites/65-microsurface.sh regenerates byte for byte from the
 *     committed reference tables), inside that kernel's contract, and the
 *     README's model error of a diffuse row is that contract's maximum;
 *   - contracts stated in prose that the code relies on.
 * Run from the source tree's top.  Each failure names the file, the row
 * and both values. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <string.h>
#include "../lib/harness.h"
#include "facet.h"
#include "facet/fx.h"
#include "facet/f16.h"

/* ---- files ---------------------------------------------------------------- */
static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *s;
    long n;
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    rewind(f);
    s = malloc((size_t)n + 1);
    if (!s) {
        fclose(f);
        return NULL;
    }
    s[fread(s, 1, (size_t)n, f)] = '\0';
    fclose(f);
    return s;
}

/* copies live in one static arena: nothing to free, nothing leaks */
static char *dup(const char *s)
{
    static char arena[1 << 23];
    static size_t used;
    size_t n = strlen(s) + 1;
    char *d;
    if (used + n > sizeof arena)
        return NULL;
    d = memcpy(arena + used, s, n);
    used += n;
    return d;
}

/* ---- Markdown tables: every row of every table, cells trimmed ------------- */
#define MAX_CELLS 16
#define MAX_ROWS 8192
typedef struct {
    const char *const *head; /* the header's cells */
    int n_head;
    char *cell[MAX_CELLS];
    int n;
    const char *section;     /* the "## " heading above the table */
    int line;
} md_row;
typedef struct {
    md_row row[MAX_ROWS];
    int n;
    char *heads[MAX_ROWS][MAX_CELLS];
} md_doc;

static char *trim(char *s)
{
    char *e;
    while (*s == ' ')
        s++;
    e = s + strlen(s);
    while (e > s && e[-1] == ' ')
        *--e = '\0';
    return s;
}

/* splits "| a | b |" in place */
static int split_row(char *line, char **cell)
{
    int n = 0;
    char *p = strchr(line, '|'), *q;
    while (p && n < MAX_CELLS) {
        q = strchr(p + 1, '|');
        if (!q)
            break;
        *q = '\0';
        cell[n++] = trim(p + 1);
        p = q;
    }
    return n;
}

/* parses text (modified in place) */
static void md_parse(md_doc *d, char *text)
{
    char *line = text, *next, *prev = NULL;
    const char *section = "";
    int ln = 0, in_table = 0, n_heads = 0;
    const char *const *head = NULL;
    int n_head = 0;
    d->n = 0;
    for (; line; line = next) {
        next = strchr(line, '\n');
        if (next)
            *next++ = '\0';
        ln++;
        if (!strncmp(line, "## ", 3) && dup(line))
            section = dup(line);
        if (line[0] != '|') {
            in_table = 0;
            prev = line;
            continue;
        }
        if (!strncmp(line, "|---", 4)) { /* the line before was the header */
            char *h = prev && prev[0] == '|' && n_heads < MAX_ROWS ? dup(prev) : NULL;
            if (h) {
                n_head = split_row(h, d->heads[n_heads]);
                head = (const char *const *)d->heads[n_heads++];
                in_table = 1;
            }
            prev = line;
            continue;
        }
        if (in_table && d->n < MAX_ROWS && dup(line)) {
            md_row *r = &d->row[d->n++];
            char *copy = dup(line);
            r->n = split_row(copy, r->cell);
            r->head = head;
            r->n_head = n_head;
            r->section = section;
            r->line = ln;
        }
        prev = line;
    }
}

static int col_of(const md_row *r, const char *name)
{
    int i;
    for (i = 0; i < r->n_head; i++)
        if (!strcmp(r->head[i], name))
            return i;
    return -1;
}

/* the cell under column `want` of the first row whose columns k[i] hold
 * v[i] (n conditions), or NULL */
static const char *md_find(const md_doc *d, int n, const char *const *k, const char *const *v, const char *want)
{
    int i, j;
    for (i = 0; i < d->n; i++) {
        const md_row *r = &d->row[i];
        int w = col_of(r, want), ok = w >= 0 && w < r->n;
        for (j = 0; ok && j < n; j++) {
            int c = col_of(r, k[j]);
            ok = c >= 0 && c < r->n && !strcmp(r->cell[c], v[j]);
        }
        if (ok)
            return r->cell[w];
    }
    return NULL;
}

/* ---- the headers ---------------------------------------------------------- */
static char *facet_h;

/* facet.h's "Cost: N ops (a rsqrt, b rcp)" of a kernel: the last before
 * its prototype (as tests/f32/test_op_counts.c reads it) */
static int stated_cost(const char *kernel, long *ops, long *rs, long *rc)
{
    char proto[96];
    const char *p, *q, *cost = NULL;
    snprintf(proto, sizeof proto, " facet_%s_f32(", kernel);
    p = strstr(facet_h, proto);
    for (q = facet_h; p && (q = strstr(q, "Cost: ")) && q < p; q++)
        cost = q;
    return cost && sscanf(cost, "Cost: %ld ops (%ld rsqrt, %ld rcp)", ops, rs, rc) == 3;
}

/* "14 + 1 rcp", "17 + 1 rsqrt + 1 rcp", "5" */
static int parse_ops(const char *s, long *ops, long *rs, long *rc)
{
    char *e;
    *ops = strtol(s, &e, 10);
    *rs = *rc = 0;
    if (e == s)
        return 0;
    while (*e) {
        long k;
        char *f;
        while (*e == ' ' || *e == '+')
            e++;
        if (!*e)
            break;
        k = strtol(e, &f, 10);
        if (f == e)
            return 0;
        while (*f == ' ')
            f++;
        if (!strncmp(f, "rsqrt", 5))
            *rs = k, e = f + 5;
        else if (!strncmp(f, "rcp", 3))
            *rc = k, e = f + 3;
        else
            return 0;
    }
    return 1;
}

/* a bound cell "2^-21.5" against a relative bound */
static int bound_matches(const char *cell, double bound)
{
    return !strncmp(cell, "2^", 2) && fabs(atof(cell + 2) - log2(bound)) < 0.01;
}

/* ---- include/README.md: the kernel tables --------------------------------- */
static void kernel_tables(void)
{
    static md_doc d;
    char *text = slurp("include/README.md");
    int seen[64] = { 0 }, i;
    size_t k;
    CHECK(text != NULL, "include/README.md not found (run from the source tree's top)");
    if (!text)
        return;
    md_parse(&d, text);
    free(text);
    for (i = 0; i < d.n; i++) {
        const md_row *r = &d.row[i];
        int ck = col_of(r, "kernel"), cb = col_of(r, "f32 bound"), cf = col_of(r, "f32_fast bound"),
            co = col_of(r, "ops (+ rsqrt, rcp)"), cx = col_of(r, "fixed point");
        const facet_kernel *fk;
        const facet_fx_kernel *xk;
        char name[64];
        long o1, s1, r1, o2, s2, r2;
        const char *fx_want;
        if (strncmp(r->section, "## The kernels", 14) || ck < 0 || cb < 0 || cf < 0 || co < 0 || cx < 0 ||
            r->n != r->n_head)
            continue;
        if (sscanf(r->cell[ck], "`%63[a-z0-9_]`", name) != 1) {
            CHECK(0, "include/README.md:%d: kernel cell \"%s\" is not `name`", r->line, r->cell[ck]);
            continue;
        }
        fk = facet_kernel_find(name);
        CHECK(fk != NULL, "include/README.md:%d: %s is not a kernel", r->line, name);
        if (!fk)
            continue;
        seen[fk - facet_kernel_at(0)]++;
        CHECK(bound_matches(r->cell[cb], fk->err_f32), "include/README.md:%d: %s: f32 bound %s, facet.h has 2^%.2f",
              r->line, name, r->cell[cb], log2(fk->err_f32));
        CHECK(bound_matches(r->cell[cf], fk->err_f32_fast),
              "include/README.md:%d: %s: f32_fast bound %s, facet.h has 2^%.2f", r->line, name, r->cell[cf],
              log2(fk->err_f32_fast));
        if (!stated_cost(name, &o2, &s2, &r2))
            CHECK(0, "include/facet.h has no \"Cost: N ops (a rsqrt, b rcp)\" for %s", name);
        else if (!parse_ops(r->cell[co], &o1, &s1, &r1))
            CHECK(0, "include/README.md:%d: %s: ops cell \"%s\" unreadable", r->line, name, r->cell[co]);
        else
            CHECK(o1 == o2 && s1 == s2 && r1 == r2,
                  "include/README.md:%d: %s: ops %s, facet.h says %ld ops (%ld rsqrt, %ld rcp)", r->line, name,
                  r->cell[co], o2, s2, r2);
        xk = facet_fx_kernel_find(name);
        fx_want = !xk ? "-" : xk->fx ? "fx, fx_fast" : "fx_fast";
        CHECK(!strcmp(r->cell[cx], fx_want), "include/README.md:%d: %s: fixed point \"%s\", the fx table has \"%s\"",
              r->line, name, r->cell[cx], fx_want);
    }
    for (k = 0; k < facet_kernel_count(); k++)
        CHECK(seen[k] == 1, "%s has %d rows in include/README.md's kernel tables (want 1)", facet_kernel_at(k)->name,
              seen[k]);
}

/* ---- the diffuse kernels' model error: the microsurface simulation ------- */
/* the kernels measured against it (bench/microsurface/msim_analyse.c) */
static const char *const sim_kernels[] = { "diffuse_hammon", "diffuse_hammon_hybrid", "diffuse_hammon_cheap",
                                           "diffuse_burley", "diffuse_oren_nayar", "lambert" };
#define N_SIM ((int)(sizeof sim_kernels / sizeof sim_kernels[0]))
static const char *sim_lines[N_SIM];  /* each kernel's contract lines, from model_error.md */
static char sim_max[N_SIM][96];       /* "173.9% (+- 3.08%)": its whole-grid maximum */
static char sim_ref[N_SIM][32];       /* its material */

static int sim_index(const char *name)
{
    int i;
    for (i = 0; i < N_SIM; i++)
        if (!strcmp(sim_kernels[i], name))
            return i;
    return -1;
}

static void sim_contracts(void)
{
    char *md = slurp("bench/microsurface/model_error.md"), *p, *end;
    int i;
    CHECK(md != NULL, "bench/microsurface/model_error.md not found");
    if (!md)
        return;
    p = strstr(md, "## Contract lines");
    CHECK(p != NULL, "bench/microsurface/model_error.md has no \"## Contract lines\"");
    if (!p || !(p = strstr(p, "```\n")))
        return;
    p += 4;
    end = strstr(p, "```");
    if (end)
        *end = '\0';
    /* "name:\n * ...\n * ...\n" per kernel */
    while (*p) {
        char *colon = strchr(p, ':'), *nl = strchr(p, '\n'), *q, *next, *m, *at, *of;
        int k;
        if (!colon || !nl || colon > nl)
            break;
        *colon = '\0';
        k = sim_index(p);
        CHECK(k >= 0, "bench/microsurface/model_error.md: contract lines for \"%s\", not a diffuse kernel this test knows", p);
        q = nl + 1;
        for (next = q; !strncmp(next, " * ", 3);) {
            char *e = strchr(next, '\n');
            next = e ? e + 1 : next + strlen(next);
            if (!e)
                break;
        }
        if (k >= 0) {
            char save = *next;
            *next = '\0';
            sim_lines[k] = dup(q);
            *next = save;
            if ((m = strstr(sim_lines[k], ": max ")) && (at = strstr(m, " at alpha ")))
                snprintf(sim_max[k], sizeof sim_max[k], "%.*s", (int)(at - m - 6), m + 6);
            if ((of = strstr(sim_lines[k], "simulation of ")))
                sscanf(of + 14, "%31[a-z]", sim_ref[k]);
        }
        p = next;
    }
    free(md);
    for (i = 0; i < N_SIM; i++) {
        char decl[96];
        const char *d, *c;
        CHECK(sim_lines[i] && sim_max[i][0] && sim_ref[i][0],
              "bench/microsurface/model_error.md: no whole contract lines for %s", sim_kernels[i]);
        if (!sim_lines[i])
            continue;
        snprintf(decl, sizeof decl, "\nfloat facet_%s_f32(", sim_kernels[i]);
        d = strstr(facet_h, decl);
        CHECK(d != NULL, "include/facet.h: no declaration of facet_%s_f32", sim_kernels[i]);
        if (!d)
            continue;
        /* the kernel's contract: the comment that ends just above its declaration */
        for (c = d; c > facet_h && strncmp(c, "\n/*", 3); c--)
            ;
        {
            char *contract = dup(c);
            if (contract)
                contract[d - c] = '\0';
            CHECK(contract && strstr(contract, sim_lines[i]) != NULL,
                  "include/facet.h: the contract of %s does not have its model-error lines as "
                  "bench/microsurface/model_error.md gives them:\n%s", sim_kernels[i], sim_lines[i]);
        }
    }
}

/* ---- README.md: the "which one" table ------------------------------------- */
static void which_one(void)
{
    static md_doc readme, snap;
    char *rtext = slurp("README.md"), *stext = slurp("bench/snapshot/report.md"), *rcopy, date[32] = "";
    const char *p;
    int i, rows = 0, f16_rows = 0;
    CHECK(rtext && stext, "README.md or bench/snapshot/report.md not found (run from the source tree's top)");
    if (!rtext || !stext)
        return;
    /* the README says which run it quotes */
    if ((p = strstr(stext, "\nDate: ")))
        sscanf(p + 7, "%31s", date);
    CHECK(date[0] != '\0', "bench/snapshot/report.md has no \"Date: \" line");
    rcopy = dup(rtext);
    CHECK(date[0] && strstr(rcopy, date) != NULL, "README.md does not name the snapshot's date %s", date);
    md_parse(&readme, rtext);
    md_parse(&snap, stext);
    free(rtext);
    free(stext);
    for (i = 0; i < readme.n; i++) {
        const md_row *r = &readme.row[i];
        int ck = col_of(r, "kernel"), ct = col_of(r, "format, tier"), cm = col_of(r, "model error (max rel., vs)"),
            cb = col_of(r, "implementation bound"), ca = col_of(r, "AVX2 batch, est. cycles/sample"),
            c5 = col_of(r, "AVX-512 batch (f16: AVX-512 FP16), est. cycles/sample"),
            c4 = col_of(r, "Cortex-M4F, cycles/call");
        const facet_kernel *fk;
        const facet_fx_kernel *xk;
        const facet_f16_kernel *hk;
        char name[64], want[64];
        const char *tier, *got;
        if (ck < 0 || ct < 0 || cm < 0 || cb < 0 || ca < 0 || c5 < 0 || c4 < 0 || r->n != r->n_head)
            continue;
        rows++;
        f16_rows += !strcmp(r->cell[ct], "f16");
        if (sscanf(r->cell[ck], "`%63[a-z0-9_]`", name) != 1 || !(fk = facet_kernel_find(name))) {
            CHECK(0, "README.md:%d: \"%s\" is not a kernel", r->line, r->cell[ck]);
            continue;
        }
        tier = r->cell[ct];
        xk = facet_fx_kernel_find(name);
        /* the bound: the header constant of the tier */
        if (!strcmp(tier, "f32"))
            snprintf(want, sizeof want, "%.3g", fk->err_f32);
        else if (!strcmp(tier, "f32_fast"))
            snprintf(want, sizeof want, "%.3g", fk->err_f32_fast);
        else if (!strcmp(tier, "fx") && xk && xk->fx)
            snprintf(want, sizeof want, "%g LSB", xk->err_lsb);
        else if (!strcmp(tier, "fx_fast") && xk && xk->fx_fast)
            snprintf(want, sizeof want, "2^%g rel. or 1 LSB", log2(FACET_FX_FAST_TOL_REL));
        else if (!strcmp(tier, "f16") && (hk = facet_f16_kernel_find(name)) && hk->f16)
            snprintf(want, sizeof want, "%.3g", hk->err_f16);
        else {
            CHECK(0, "README.md:%d: %s has no tier \"%s\"", r->line, name, tier);
            continue;
        }
        CHECK(!strcmp(r->cell[cb], want), "README.md:%d: %s %s: bound \"%s\", the headers give \"%s\"", r->line, name,
              tier, r->cell[cb], want);
        /* the model error: a diffuse kernel's is its contract's maximum
         * against the microsurface simulation; the others' the snapshot's
         * tradeoff row of the kernel */
        if (sim_index(name) >= 0) {
            int k = sim_index(name);
            char wantm[192];
            snprintf(wantm, sizeof wantm, "%s vs the simulated microsurface (%s facets)", sim_max[k], sim_ref[k]);
            CHECK(!strcmp(r->cell[cm], wantm), "README.md:%d: %s: model error \"%s\", its contract: \"%s\"", r->line,
                  name, r->cell[cm], wantm);
        } else {
            const char *m = r->cell[cm];
            int j, found = 0;
            for (j = 0; j < snap.n; j++) {
                const md_row *s = &snap.row[j];
                int ca2 = col_of(s, "approximation"), ce = col_of(s, "exact"), cx = col_of(s, "max rel err");
                char first[64] = "", wantm[256], ref[192] = "";
                if (ca2 < 0 || ce < 0 || cx < 0 || s->n != s->n_head)
                    continue;
                sscanf(s->cell[ca2], "%63s", first);
                if (strcmp(first, name))
                    continue;
                found = 1;
                sscanf(s->cell[ce], "%191[^(]", ref);
                snprintf(wantm, sizeof wantm, "%s vs %s", s->cell[cx], trim(ref));
                if (strncmp(m, "- ", 2)) /* "- (a model of its own)" states none */
                    CHECK(!strcmp(m, wantm), "README.md:%d: %s: model error \"%s\", bench/snapshot/report.md: \"%s\"",
                          r->line, name, m, wantm);
            }
            if (!found)
                CHECK(!strcmp(m, "exact") || !strncmp(m, "- ", 2),
                      "README.md:%d: %s: model error \"%s\", but the snapshot's tradeoff table has no row for it",
                      r->line, name, m);
            else
                CHECK(strcmp(m, "exact"), "README.md:%d: %s is an approximation in the snapshot, not exact", r->line,
                      name);
        }
        /* AVX2: the snapshot's batch row of the kernel, tier and port; f16:
         * none (the avx2 line runs the scalar f16 table: no binary16
         * arithmetic), the cell "-" */
        {
            static const char *const k[] = { "kernel", "fmt", "port", "path" };
            const char *v[4];
            v[0] = name, v[1] = tier, v[2] = "avx2", v[3] = "batch";
            got = md_find(&snap, 4, k, v, "est. cyc/sample");
            if (!strcmp(tier, "f16"))
                CHECK(!got && !strcmp(r->cell[ca], "-"),
                      "README.md:%d: %s f16: AVX2 \"%s\" (want \"-\"), bench/snapshot/report.md: \"%s\"", r->line, name,
                      r->cell[ca], got ? got : "(no row)");
            else
                CHECK(got && !strcmp(r->cell[ca], got),
                      "README.md:%d: %s %s: AVX2 \"%s\", bench/snapshot/report.md: \"%s\"", r->line, name, tier,
                      r->cell[ca], got ? got : "(no row)");
            /* AVX-512: the avx512 port's row; f16 the avx512fp16 table's */
            v[2] = !strcmp(tier, "f16") ? "avx512fp16" : "avx512";
            got = md_find(&snap, 4, k, v, "est. cyc/sample");
            CHECK(got && !strcmp(r->cell[c5], got),
                  "README.md:%d: %s %s: AVX-512 \"%s\", bench/snapshot/report.md (%s): \"%s\"", r->line, name, tier,
                  r->cell[c5], v[2], got ? got : "(no row)");
        }
        /* Cortex-M4F: f32 on the FPU, fixed point on the integer unit */
        {
            static const char *const k[] = { "kernel" };
            const char *v[1], *colname = NULL;
            char first[32] = "-";
            v[0] = name;
            if (!strcmp(tier, "f32"))
                colname = "f32 FPU M4 / M7 mca";
            else if (!strcmp(tier, "fx"))
                colname = "fx M4 / M7 / M33 mca";
            else if (!strcmp(tier, "fx_fast"))
                colname = "fx_fast M4 / M7 / M33 mca";
            got = colname ? md_find(&snap, 1, k, v, colname) : "-";
            if (got)
                sscanf(got, "%31s", first);
            CHECK(got && !strcmp(r->cell[c4], first),
                  "README.md:%d: %s %s: Cortex-M4F \"%s\", bench/snapshot/report.md: \"%s\"", r->line, name, tier,
                  r->cell[c4], got ? first : "(no row)");
        }
    }
    CHECK(rows >= 8, "README.md: the \"which one\" table has %d rows (want at least 8)", rows);
    CHECK(f16_rows >= 1, "README.md: the \"which one\" table has no f16 row");
}

/* ---- facet.h: the 2^-k written beside a bound is its value ---------------- */
static double macro_value(const char *name)
{
    char key[128];
    const char *p;
    snprintf(key, sizeof key, "#define %s ", name);
    p = strstr(facet_h, key);
    return p ? atof(p + strlen(key) + strspn(p + strlen(key), " ")) : -1;
}

static void header_bounds(void)
{
    const char *p = facet_h;
    int n = 0;
    while ((p = strstr(p, "FACET_ERR_"))) {
        char name[96];
        double v, k;
        const char *after, *eol, *c;
        int len = 0, is_define = p - facet_h >= 8 && !strncmp(p - 8, "#define ", 8);
        while (p[len] == '_' || (p[len] >= 'A' && p[len] <= 'Z') || (p[len] >= '0' && p[len] <= '9'))
            len++;
        snprintf(name, sizeof name, "%.*s", len, p);
        after = p + len;
        p = after;
        if (!strncmp(after, " (2^", 4)) { /* a comment's "NAME (2^-k" */
            k = atof(after + 4);
        } else if (is_define) {           /* "#define NAME v /" "* 2^-k" */
            eol = strchr(after, '\n');
            c = strstr(after, "/* 2^");
            if (!c || (eol && c > eol))
                continue;
            k = atof(c + 5);
        } else {
            continue;
        }
        v = macro_value(name);
        n++;
        CHECK(v > 0 && fabs(log2(v) - k) < 0.01, "include/facet.h: %s is written 2^%g, its value %g is 2^%.3f", name, k,
              v, v > 0 ? log2(v) : 0.0);
    }
    CHECK(n > 100, "include/facet.h: only %d bound mentions found", n);
}

/* ---- prose -------------------------------------------------------------- */
/* 1 if the file has every one of the phrases (white space runs count as
 * one blank, so line breaks do not matter; in a .h, so does the " * " that
 * starts a comment line) */
static int has_phrases(const char *path, const char *const *phrases, int n, const char **missing)
{
    static char text[1 << 20];
    size_t len = 0;
    int c, blank = 0, i, bol = 0, is_c = strstr(path, ".h") != NULL;
    FILE *f = fopen(path, "r");
    *missing = path;
    if (!f)
        return 0;
    while ((c = getc(f)) != EOF && len + 1 < sizeof text) {
        if (c == '\n')
            bol = is_c; /* a C comment's " * " at the start of a line is blank */
        else if (!(bol && c == '*') && c != ' ' && c != '\t')
            bol = 0;
        if (c == ' ' || c == '\n' || c == '\t' || (bol && c == '*')) {
            blank = 1;
            continue;
        }
        if (blank && len)
            text[len++] = ' ';
        blank = 0;
        text[len++] = (char)c;
    }
    text[len] = '\0';
    fclose(f);
    for (i = 0; i < n; i++)
        if (!strstr(text, phrases[i])) {
            *missing = phrases[i];
            return 0;
        }
    return 1;
}

/* contracts stated in prose that the code relies on */
static void doc_contracts(void)
{
    static const char *const facet_h_says[] = {
        "out may be exactly the same array as any input", "no other overlap",
        "an unknown or unsupported name there is not an error for the library",
    };
    static const char *const cli[] = {
        "Exit status, the same for every verb: **0** success; **1** I/O error",
        "**2** usage error or malformed input",
        "lines whose first non-blank character is `#`, are skipped",
        "white space (space, tab, CR, VT, FF)",
        "a NUL byte anywhere in a line is an error",
        "`floor(x * 32768 + 1/2)` (nearest, ties up)",
        "Fixed point saturates any finite value",
        "A malformed line stops the run, the same way in every format",
    };
    const char *m = "";
    int ok = has_phrases("include/facet.h", facet_h_says, 3, &m);
    CHECK(ok, "include/facet.h does not say: %s", m);
    ok = has_phrases("src/cli/README.md", cli, 8, &m);
    CHECK(ok, "src/cli/README.md does not say: %s", m);
}


/* the parameter list after `open` in text (up to its ")"), comment
 * leaders ("\n *") and runs of blanks as one space, `from` words as `to`
 * ("V_" -> "V"); NULL if absent.  malloc'd */
static char *param_list(const char *text, const char *open, const char *from, const char *to)
{
    const char *p = text ? strstr(text, open) : NULL, *e;
    char *out, *o;
    if (!p)
        return NULL;
    p += strlen(open);
    e = strchr(p, ')');
    if (!e)
        return NULL;
    out = malloc((size_t)(e - p) * 2 + 1);
    if (!out)
        return NULL;
    for (o = out; p < e; p++) {
        if (*p == '\n') {
            while (p + 1 < e && (p[1] == ' ' || p[1] == '*'))
                p++;
            *o++ = ' ';
        } else if (!strncmp(p, from, strlen(from)) && (p == text || !(isalnum((unsigned char)p[-1]) || p[-1] == '_')) &&
                   !(isalnum((unsigned char)p[strlen(from)]) || p[strlen(from)] == '_')) {
            strcpy(o, to);
            o += strlen(to);
            p += strlen(from) - 1;
        } else {
            *o++ = *p == '\t' ? ' ' : *p;
        }
        if (o - out >= 2 && o[-1] == ' ' && o[-2] == ' ')
            o--;
    }
    *o = 0;
    return out;
}

/* include/facet.h states the RGB port-header signature
 * (facet_brdf_hammon_rgb_f32_<port>(V *out_r, ...)): it is the parameter
 * list of the one body, include/facet/detail/f32_body.h's
 * FACET_K(brdf_hammon_rgb), with its V_ written V (it once named arrays,
 * which no longer compiled) */
static void rgb_port_signature(void)
{
    char *body = slurp("include/facet/detail/f32_body.h");
    char *doc = param_list(facet_h, "facet_brdf_hammon_rgb_f32_<port>(", "V", "V");
    char *code = param_list(body, "FACET_K(brdf_hammon_rgb)(", "V_", "V");
    CHECK(doc != NULL, "include/facet.h does not state facet_brdf_hammon_rgb_f32_<port>(...)");
    CHECK(code != NULL, "include/facet/detail/f32_body.h has no FACET_K(brdf_hammon_rgb)(...)");
    if (doc && code)
        CHECK(!strcmp(doc, code), "include/facet.h states facet_brdf_hammon_rgb_f32_<port>(%s), the body has (%s)", doc,
              code);
    CHECK(strstr(facet_h, "facet_brdf_hammon_rgb_f32_fast_<port>(") != NULL,
          "include/facet.h does not name facet_brdf_hammon_rgb_f32_fast_<port>");
    free(doc);
    free(code);
    free(body);
}

int main(void)
{
    th_name = "docs";
    facet_h = slurp("include/facet.h");
    if (!facet_h) {
        CHECK(0, "include/facet.h not found (run from the source tree's top)");
        return th_done();
    }
    kernel_tables();
    sim_contracts();
    which_one();
    header_bounds();
    doc_contracts();
    rgb_port_signature();
    free(facet_h);
    return th_done();
}
