/* bench.c - the benchmark engine (see bench.h). */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet/oracle.h"
#include "facet/f16.h"
#include "tests/lib/sample_common.h" /* the samplers the tests judge error on (and sample.h) */
#include "bench.h"
#include "loops.h"
#include "peers.h"
#include "fxhook.h"
#include "tests/f16/f16_test.h" /* the f16 tests' inputs, domain clamp and error measure */

#define ERR_FLOOR 0x1p-100

void bench_defaults(bench_opts *o)
{
    memset(o, 0, sizeof *o);
    o->n_time = 1024;
    o->n_err = 1 << 16;
    o->epochs = 11;
    o->target = 1e5;
    o->seed = 0x5eed0005ull;
    o->peers = 1;
}

double bench_rel_err(double got, double want)
{
    if (got != got)
        return INFINITY;
    return fabs(got - want) / fmax(fabs(want), ERR_FLOOR);
}

double bench_oracle_brdf_exact(double nol, double nov, double lov, double alpha,
                               double f0, double albedo)
{
    facet_oracle_geom g = facet_oracle_geometry(nol, nov, lov);
    double a = fmin(fmax(alpha, FACET_ALPHA_MIN), 1.0);
    double d = facet_oracle_ggx_d_tan2(g.tan2_h, g.n_h, a);
    double vis = facet_oracle_smith_vis(g.n_l, g.n_v, a);
    double f = facet_oracle_fresnel_schlick(f0, g.l_h);
    return d * vis * f + facet_oracle_diffuse_hammon(nol, nov, lov, a, albedo);
}

void bench_vectors(double nl, double nv, double lv, double psi, double L[3], double V[3])
{
    double sl = sqrt(fmax(0.0, 1 - nl * nl)), sv = sqrt(fmax(0.0, 1 - nv * nv));
    double c = (sl * sv > 0) ? (lv - nl * nv) / (sl * sv) : 1.0;
    double s;
    c = fmin(fmax(c, -1.0), 1.0);
    s = sqrt(fmax(0.0, 1 - c * c));
    V[0] = sv * cos(psi);
    V[1] = sv * sin(psi);
    V[2] = nv;
    /* L at azimuth psi + phi, cos phi = c */
    L[0] = sl * (c * cos(psi) - s * sin(psi));
    L[1] = sl * (c * sin(psi) + s * cos(psi));
    L[2] = nl;
}

/* ---- timing -------------------------------------------------------------- */

typedef struct work {
    bench_fn fn;
    float *out;
    const float *const *in;
    size_t n;
    peer_brdf_fn pb;
    const peer_brdf_in *pin;
    bench_fx_fn fx;           /* fixed point: raw Q15 inputs, raw outputs */
    void *fxout;
    const int32_t *const *fxin;
    peer_sample_fn sfn;       /* a sampler's batch (facet's or a peer's): SoA outputs */
    float *const *sout;
    void (*hfn)(facet_f16 *, const facet_f16 *const *, size_t); /* an f16 batch: binary16 bits */
    facet_f16 *hout;
    const facet_f16 *const *hin;
} work;

static void run_work(void *ctx, long reps)
{
    work *w = ctx;
    long r;
    if (w->pb) {
        for (r = 0; r < reps; r++)
            w->pb(w->out, w->pin, w->n);
    } else if (w->fx) {
        for (r = 0; r < reps; r++)
            w->fx(w->fxout, w->fxin, w->n);
    } else if (w->sfn) {
        for (r = 0; r < reps; r++)
            w->sfn(w->sout, w->in, w->n);
    } else if (w->hfn) {
        for (r = 0; r < reps; r++)
            w->hfn(w->hout, w->hin, w->n);
    } else {
        for (r = 0; r < reps; r++)
            w->fn(w->out, w->in, w->n);
    }
}

static cyc_stat time_work(work *w, double units, const bench_opts *o)
{
    long reps = cyc_calibrate_reps(run_work, w, o->target);
    return cyc_measure(run_work, w, reps, units, o->epochs);
}

static cyc_stat stat_minus(cyc_stat s, double d)
{
    s.min -= d;
    s.median -= d;
    s.max -= d;
    if (s.min < 0) s.min = 0;
    if (s.median < 0) s.median = 0;
    if (s.max < 0) s.max = 0;
    s.spread = s.median > 0 ? (s.max - s.min) / s.median : 0;
    s.noisy = s.spread > 0.05;
    return s;
}

/* ---- data ------------------------------------------------------------------ */

typedef struct kdata {
    const facet_kernel *k;
    size_t n;                 /* n_err, multiple of 8 */
    float *in[FACET_MAX_INPUTS];
    double *want;
    float *out;
} kdata;

static void kdata_make(kdata *d, const facet_kernel *k, size_t n, unsigned long long seed)
{
    smp_rng r;
    size_t i;
    int j;
    memset(d, 0, sizeof *d);
    d->k = k;
    d->n = n;
    r.s = seed ^ (uint64_t)(uintptr_t)k->name[0] * 0x9e3779b97f4a7c15ull;
    for (j = 0; j < k->n_inputs; j++)
        d->in[j] = malloc(n * sizeof(float));
    d->want = malloc(n * sizeof(double));
    d->out = malloc((n + 8) * sizeof(float));
    for (i = 0; i < n; i++) {
        float v[FACET_MAX_INPUTS];
        double dv[FACET_MAX_INPUTS];
        smp_inputs(&r, k, v);
        for (j = 0; j < k->n_inputs; j++) {
            d->in[j][i] = v[j];
            dv[j] = v[j];
        }
        d->want[i] = k->oracle(dv);
    }
}

static void kdata_free(kdata *d)
{
    int j;
    for (j = 0; j < FACET_MAX_INPUTS; j++)
        free(d->in[j]);
    free(d->want);
    free(d->out);
}

static void err_of(bench_err *e, const kdata *d, const float *got, const double *want)
{
    size_t i;
    double sum = 0;
    int j;
    memset(e, 0, sizeof *e);
    e->max_rel = -1;
    for (i = 0; i < d->n; i++) {
        double rel = bench_rel_err(got[i], want[i]);
        sum += rel;
        if (fabs(want[i]) >= 0x1p-8 && rel > e->max_rel_vis)
            e->max_rel_vis = rel;
        if (rel > e->max_rel) {
            e->max_rel = rel;
            e->got = got[i];
            e->want = want[i];
            for (j = 0; j < d->k->n_inputs; j++)
                e->arg[j] = d->in[j][i];
        }
    }
    e->n = (long)d->n;
    e->mean_rel = sum / (double)d->n;
}

/* runs fn over the whole error set in passes of `chunk` */
static void eval_all(bench_fn fn, const kdata *d, float *out, size_t chunk)
{
    size_t i;
    int j;
    for (i = 0; i < d->n; i += chunk) {
        const float *in[FACET_MAX_INPUTS];
        size_t m = d->n - i < chunk ? d->n - i : chunk;
        for (j = 0; j < d->k->n_inputs; j++)
            in[j] = d->in[j] + i;
        fn(out + i, in, m);
    }
}

/* ---- one row -------------------------------------------------------------- */

static int want_port(const bench_opts *o, const char *port)
{
    return !o->port || !strcmp(o->port, port);
}

static void progress(const bench_opts *o, const bench_row *r)
{
    if (o->progress)
        fprintf(stderr, "bench: %-22s %-8s %-16s %-6s %10.3g %s/sample\n", r->kernel, r->format,
                r->port, r->path, r->thr.median, cyc_unit());
}

static void row_init(bench_row *r, const kdata *d, const char *format, const char *port,
                     const char *path, int lanes)
{
    memset(r, 0, sizeof *r);
    r->kernel = d->k->name;
    r->format = format;
    r->port = port;
    r->path = path;
    r->note = "";
    r->n_inputs = d->k->n_inputs;
    r->lanes = lanes;
    r->bound = d->k->err_f32;
}

static void row_time(bench_row *r, bench_fn thr, const kdata *d, const bench_opts *o)
{
    work w;
    int j;
    const float *in[FACET_MAX_INPUTS];
    for (j = 0; j < d->k->n_inputs; j++)
        in[j] = d->in[j];
    memset(&w, 0, sizeof w);
    w.fn = thr;
    w.out = d->out;
    w.in = in;
    w.n = o->n_time < d->n ? o->n_time : d->n;
    r->thr = time_work(&w, (double)w.n, o);
}

static void row_latency(bench_row *r, bench_fn chain, bench_fn ident, int lanes, const kdata *d,
                        const bench_opts *o)
{
    work w;
    int j;
    const float *in[FACET_MAX_INPUTS];
    cyc_stat base;
    if (!chain)
        return;
    for (j = 0; j < d->k->n_inputs; j++)
        in[j] = d->in[j];
    memset(&w, 0, sizeof w);
    w.out = d->out;
    w.in = in;
    w.n = o->n_time < d->n ? o->n_time : d->n;
    w.fn = ident;
    base = time_work(&w, (double)(w.n / (size_t)lanes), o);
    w.fn = chain;
    r->lat = stat_minus(time_work(&w, (double)(w.n / (size_t)lanes), o), base.median);
    r->has_lat = 1;
}

static void finish(bench_row *r, const bench_opts *o, bench_sink sink, void *ctx, int *count)
{
    if (r->err.has_lsb)
        r->within = r->err.max_lsb <= r->bound && r->err.big_rel <= 0x1p-26;
    else
        r->within = r->bound <= 0 || r->err.max_rel <= r->bound;
    progress(o, r);
    sink(r, ctx);
    (*count)++;
}

/* ---- the exact-Vis BRDF peers, from vectors (path "peer-vectors": another
 * model than brdf_hammon's, judged against its own oracle; brdf_hammon's
 * same-formula peers are term peers, path "peer", peers.h) ---------------- */

static void run_brdf_peers(const kdata *d, const bench_opts *o, bench_sink sink, void *ctx,
                           int *count)
{
    size_t n = d->n, i;
    float *v[9];
    double *want = malloc(n * sizeof(double));
    peer_brdf_in pin;
    smp_rng r;
    unsigned s;
    r.s = o->seed ^ 0xb4dfull;
    for (s = 0; s < 9; s++)
        v[s] = malloc(n * sizeof(float));
    for (i = 0; i < n; i++) {
        double L[3], V[3], fl[3], fv[3], ll, lvn;
        int c;
        bench_vectors(d->in[0][i], d->in[1][i], d->in[2][i], 2 * M_PI * smp_u01(&r), L, V);
        for (c = 0; c < 3; c++) {
            v[c][i] = (float)L[c];
            v[3 + c][i] = (float)V[c];
            fl[c] = v[c][i];
            fv[c] = v[3 + c][i];
        }
        v[6][i] = d->in[3][i];
        v[7][i] = d->in[4][i];
        v[8][i] = d->in[5][i];
        /* the oracle at the dots of the float vectors, normalised in double */
        ll = sqrt(fl[0] * fl[0] + fl[1] * fl[1] + fl[2] * fl[2]);
        lvn = sqrt(fv[0] * fv[0] + fv[1] * fv[1] + fv[2] * fv[2]);
        want[i] = bench_oracle_brdf_exact(fl[2] / ll, fv[2] / lvn,
                                          (fl[0] * fv[0] + fl[1] * fv[1] + fl[2] * fv[2]) / (ll * lvn),
                                          v[6][i], v[7][i], v[8][i]);
    }
    pin.lx = v[0]; pin.ly = v[1]; pin.lz = v[2];
    pin.vx = v[3]; pin.vy = v[4]; pin.vz = v[5];
    pin.alpha = v[6]; pin.f0 = v[7]; pin.albedo = v[8];
    for (i = 0; peer_sets[i]; i++) {
        const peer_set *ps = peer_sets[i];
        bench_row row;
        work w;
        if (!peer_available(ps) || !want_port(o, ps->name))
            continue;
        row_init(&row, d, "f32", ps->name, "peer-vectors", 1);
        row.note = "another model: D * exact correlated Vis * F + Hammon diffuse, from vectors L, V";
        row.bound = 0;
        ps->brdf(d->out, &pin, n);
        err_of(&row.err, d, d->out, want);
        memset(&w, 0, sizeof w);
        w.pb = ps->brdf;
        w.pin = &pin;
        w.out = d->out;
        w.n = o->n_time < n ? o->n_time : n;
        row.thr = time_work(&w, (double)w.n, o);
        finish(&row, o, sink, ctx, count);
    }
    for (s = 0; s < 9; s++)
        free(v[s]);
    free(want);
}


/* ---- fixed point (facet/fx.h) ------------------------------------------------ */

typedef struct fxdata {
    int32_t *q[FACET_MAX_INPUTS];   /* the float inputs in Q15, clamped to the fx domain */
    double *want;                   /* oracle at the Q15 inputs */
    void *out;                      /* n raw outputs (64-bit slots: fits every container) */
} fxdata;

/* fx: LSB against round(oracle 2^frac) (brdf_hammon >= 16: relative);
 * fx_fast: the tier's measure |raw - v 2^frac| / max(1, 2^-10 v 2^frac),
 * bounded by FACET_FX_FAST_ERR_* (<= 1) */
static void fx_err(bench_err *e, const bench_fx *fx, const kdata *d, const fxdata *x, int fast)
{
    size_t i;
    double sum = 0, suml = 0, lsb_v = ldexp(1.0, -fx->fk->out_frac);
    int j;
    memset(e, 0, sizeof *e);
    e->has_lsb = 1;
    e->max_rel = -1;
    e->max_lsb = -1;
    e->big_rel = -1;
    for (i = 0; i < d->n; i++) {
        uint64_t raw = bench_fx_raw(fx, x->out, i);
        double got = bench_fx_value(fx, raw);
        double scaled = floor(ldexp(x->want[i], fx->fk->out_frac) + 0.5);
        double lsb = fabs(ldexp(got, fx->fk->out_frac) - scaled);
        double rel = fabs(got - x->want[i]) / fmax(fabs(x->want[i]), lsb_v);
        if (fast) {
            double v = ldexp(x->want[i], fx->fk->out_frac);
            lsb = fabs(ldexp(got, fx->fk->out_frac) - v) / fmax(1.0, ldexp(v, -10));
        }
        sum += rel;
        if (rel > e->max_rel)
            e->max_rel = rel;
        if (fabs(x->want[i]) >= 0x1p-8 && rel > e->max_rel_vis)
            e->max_rel_vis = rel;
        if (!fast && fx->fk->out_bits == 64 && x->want[i] >= 16.0) {
            if (rel > e->big_rel)
                e->big_rel = rel;
            continue;
        }
        suml += lsb;
        e->n_lsb++;
        if (lsb > e->max_lsb) {
            e->max_lsb = lsb;
            e->got = got;
            e->want = x->want[i];
            for (j = 0; j < d->k->n_inputs; j++)
                e->arg[j] = (float)(x->q[j][i] / 32768.0);
        }
    }
    e->n = (long)d->n;
    e->mean_rel = sum / (double)d->n;
    e->mean_lsb = e->n_lsb ? suml / (double)e->n_lsb : 0;
}

/* the whole error set in one call (outputs contiguous in the kernel's container) */
static void fx_run_all(bench_fx_fn fn, const kdata *d, const fxdata *x)
{
    fn(x->out, (const int32_t *const *)x->q, d->n);
}

static cyc_stat fx_time(bench_fx_fn fn, const fxdata *x, const kdata *d, const bench_opts *o)
{
    work w;
    memset(&w, 0, sizeof w);
    w.fx = fn;
    w.fxout = x->out;
    w.fxin = (const int32_t *const *)x->q;
    w.n = o->n_time < d->n ? o->n_time : d->n;
    return time_work(&w, (double)w.n, o);
}

static void fx_row(bench_row *r, const bench_fx *fx, const kdata *d, const char *port, const char *path,
                   int fast)
{
    row_init(r, d, fast ? "fx_fast" : "fx", port, path, 1);
    r->bound = fast ? fx->fk->err_fast : fx->fk->err_lsb;
}

static void run_fx(const bench_fx *fx, const kdata *d, const bench_opts *o, bench_sink sink,
                   void *ctx, int *count, int fast)
{
    bench_fx_fn fbatch = fast ? fx->fast_batch : fx->batch, fcall = fast ? fx->fast_call : fx->call;
    bench_fx_fn fchain = fast ? fx->fast_chain : fx->chain;
    fxdata x;
    size_t i, p;
    int j;
    const char *saved_port = facet_port_name();
    bench_row row;
    memset(&x, 0, sizeof x);
    for (j = 0; j < d->k->n_inputs; j++)
        x.q[j] = malloc(d->n * sizeof(int32_t));
    x.want = malloc(d->n * sizeof(double));
    x.out = calloc(d->n + 8, sizeof(uint64_t));
    for (i = 0; i < d->n; i++) {
        double dv[FACET_MAX_INPUTS];
        for (j = 0; j < d->k->n_inputs; j++) {
            int32_t q = bench_fx_q15(d->in[j][i]);
            q = q < fx->fk->lo[j] ? fx->fk->lo[j] : q > fx->fk->hi[j] ? fx->fk->hi[j] : q;
            x.q[j][i] = q;
            dv[j] = q / 32768.0;
        }
        x.want[i] = d->k->oracle(dv);
    }
    /* the batch API on every port facet_set_port() accepts on this CPU */
    for (p = 0; p < facet_port_count(); p++) {
        int sup = 0;
        const char *pn = facet_port_at(p, &sup, NULL);
        if (!sup || !want_port(o, pn) || facet_set_port(pn) != 0)
            continue;
        fx_row(&row, fx, d, pn, "batch", fast);
        row.note = fast ? "facet_<kernel>_fx_fast_batch with facet_set_port(port) active"
                        : "facet_<kernel>_fx_batch with facet_set_port(port) active";
        fx_run_all(fbatch, d, &x);
        fx_err(&row.err, fx, d, &x, fast);
        row.thr = fx_time(fbatch, &x, d, o);
        finish(&row, o, sink, ctx, count);
    }
    facet_set_port(saved_port ? saved_port : "auto");
    /* one library call per sample, and its latency */
    if (want_port(o, "scalar")) {
        work w;
        cyc_stat base;
        fx_row(&row, fx, d, "scalar", "call", fast);
        row.note = fast ? "facet_<kernel>_fx_fast per sample" : "facet_<kernel>_fx per sample";
        fx_run_all(fcall, d, &x);
        fx_err(&row.err, fx, d, &x, fast);
        row.thr = fx_time(fcall, &x, d, o);
        memset(&w, 0, sizeof w);
        w.fxout = x.out;
        w.fxin = (const int32_t *const *)x.q;
        w.n = o->n_time < d->n ? o->n_time : d->n;
        w.fx = bench_fx_identity_chain;
        base = time_work(&w, (double)w.n, o);
        w.fx = fchain;
        row.lat = stat_minus(time_work(&w, (double)w.n, o), base.median);
        row.has_lat = 1;
        finish(&row, o, sink, ctx, count);
    }
    for (j = 0; j < d->k->n_inputs; j++)
        free(x.q[j]);
    free(x.want);
    free(x.out);
}

/* ---- binary16 (facet/f16.h) ---------------------------------------------------
 * Format "f16", path "batch", port the f16 table that ran
 * (facet_f16_port_name(): the f16 column of the active port's line of
 * src/core/ports.def where this CPU runs it, else "scalar"): every f16
 * table this CPU runs, each once, reached through the first f32 port that
 * selects it.  Inputs: the f16 tests' generator (tests/f16/f16_test.h: the
 * f32 samplers rounded to binary16, 1 in 4 cosines and alpha aimed at the
 * 2^-7 floors); error: facet/f16.h's measure against the double oracle at
 * the same binary16 inputs after the domain clamp (max_rel, bound
 * FACET_ERR_<NAME>_F16); max_rel_vis: plain relative error where the
 * oracle is >= 2^-8, as for the other formats (want above 65504: against
 * 65504, the saturation the contract states).  Timed like the f32 batch
 * rows (n_time samples per call, the same calibration and epochs), right
 * after the kernel's fixed-point rows in the same run. */
static void run_f16(const facet_f16_kernel *h, const kdata *d, const bench_opts *o, bench_sink sink, void *ctx,
                    int *count)
{
    size_t n = d->n, i, p;
    facet_f16 *hin[FACET_MAX_INPUTS], *hout = malloc((n + 32) * sizeof(facet_f16));
    double *want = malloc(n * sizeof(double));
    const char *done[16], *saved_port = facet_port_name();
    int nd = 0, j;
    smp_rng r;
    r.s = o->seed ^ 0xf16f16ull ^ (uint64_t)(strlen(h->name) * 977u);
    for (j = 0; j < d->k->n_inputs; j++)
        hin[j] = malloc(n * sizeof(facet_f16));
    for (i = 0; i < n; i++) {
        facet_f16 x[FACET_MAX_INPUTS];
        double dv[FACET_MAX_INPUTS];
        f16t_inputs(&r, d->k, x);
        for (j = 0; j < d->k->n_inputs; j++) {
            hin[j][i] = x[j];
            dv[j] = f16t_clamp(d->k->inputs[j], facet_f32_from_f16(x[j]));
        }
        want[i] = d->k->oracle(dv);
    }
    for (p = 0; p < facet_port_count(); p++) {
        int sup = 0, k, seen = 0;
        const char *pn = facet_port_at(p, &sup, NULL), *hn;
        bench_row row;
        bench_err *e = &row.err;
        double sum = 0;
        work w;
        if (!sup || facet_set_port(pn) != 0)
            continue;
        hn = facet_f16_port_name();
        for (k = 0; k < nd; k++)
            seen |= !strcmp(done[k], hn);
        if (seen || nd == 16 || !want_port(o, hn))
            continue;
        done[nd++] = hn;
        row_init(&row, d, "f16", hn, "batch", 1);
        row.bound = h->err_f16;
        row.note = "facet_<kernel>_f16_batch (binary16 bits in and out) with facet_set_port(port) active";
        h->f16_batch(hout, (const facet_f16 *const *)hin, n);
        e->max_rel = -1;
        for (i = 0; i < n; i++) {
            double got = facet_f32_from_f16(hout[i]), rel = f16t_err(got, want[i]);
            if (got != got)
                rel = INFINITY;
            sum += rel;
            if (want[i] >= 0x1p-8 && rel > e->max_rel_vis)
                e->max_rel_vis = rel;
            if (rel > e->max_rel) {
                e->max_rel = rel;
                e->got = got;
                e->want = want[i];
                for (j = 0; j < d->k->n_inputs; j++)
                    e->arg[j] = facet_f32_from_f16(hin[j][i]);
            }
        }
        e->n = (long)n;
        e->mean_rel = sum / (double)n;
        memset(&w, 0, sizeof w);
        w.hfn = h->f16_batch;
        w.hout = hout;
        w.hin = (const facet_f16 *const *)hin;
        w.n = o->n_time < n ? o->n_time : n;
        row.thr = time_work(&w, (double)w.n, o);
        finish(&row, o, sink, ctx, count);
    }
    facet_set_port(saved_port ? saved_port : "auto");
    for (j = 0; j < d->k->n_inputs; j++)
        free(hin[j]);
    free(hout);
    free(want);
}

/* ---- the importance samplers (facet.h, src/core/sample_kernels.def) ----------------- */

typedef struct sdata {
    const facet_sampler *k;
    size_t n;
    float *in[FACET_SAMPLER_MAX_INPUTS], *out[FACET_SAMPLER_MAX_OUTPUTS];
    double *want[FACET_SAMPLER_MAX_OUTPUTS], *cond;
} sdata;

/* in-domain inputs from tests/lib/sample_common.h (the accuracy test's), with
 * gamma = 1 (GTR1, the closed form the peer computes too), the oracle's
 * outputs and the conditioning of the contracts' error measure */
static void sdata_make(sdata *d, const facet_sampler *k, size_t n, unsigned long long seed)
{
    smp_rng r;
    size_t i;
    int j;
    memset(d, 0, sizeof *d);
    d->k = k;
    d->n = n;
    r.s = seed ^ 0x5a3b1e00ull ^ (uint64_t)(strlen(k->name) * 131u + (unsigned char)k->name[4]) * 0x9e3779b97f4a7c15ull;
    for (j = 0; j < k->n_inputs; j++)
        d->in[j] = malloc(n * sizeof(float));
    for (j = 0; j < k->n_outputs; j++) {
        d->out[j] = malloc(n * sizeof(float));
        d->want[j] = malloc(n * sizeof(double));
    }
    d->cond = malloc(n * sizeof(double));
    for (i = 0; i < n; i++) {
        float x[FACET_SAMPLER_MAX_INPUTS];
        double xd[FACET_SAMPLER_MAX_INPUTS] = { 0 }, o[FACET_SAMPLER_MAX_OUTPUTS];
        ss_inputs(&r, k, x);
        for (j = 0; j < k->n_inputs; j++) {
            if (!strcmp(k->inputs[j], "gamma"))
                x[j] = 1.0f;
            d->in[j][i] = x[j];
            xd[j] = x[j];
        }
        k->oracle(o, xd);
        for (j = 0; j < k->n_outputs; j++)
            d->want[j][i] = o[j];
        d->cond[i] = k->err_abs ? fmax(1.0, ss_sampler_cond(k, xd, o) / 16) : 1.0;
    }
    if (!k->err_abs)
        for (i = 0; i < n; i++)
            d->cond[i] = ss_dot_cond(k, (const float *const *)d->in, (long)i);
}

static void sdata_free(sdata *d)
{
    int j;
    for (j = 0; j < FACET_SAMPLER_MAX_INPUTS; j++)
        free(d->in[j]);
    for (j = 0; j < FACET_SAMPLER_MAX_OUTPUTS; j++) {
        free(d->out[j]);
        free(d->want[j]);
    }
    free(d->cond);
}

/* the contracts' measure (facet.h, tests/sample/test_sample_accuracy.c): vectors
 * by Euclidean distance / max(1, K / 16), pdfs by relative error / the
 * conditioning of v.h; max_rel and mean_rel hold it */
static void serr_of(bench_err *e, const sdata *d)
{
    size_t i;
    double sum = 0;
    int j, na = d->k->n_inputs < FACET_MAX_INPUTS ? d->k->n_inputs : FACET_MAX_INPUTS;
    memset(e, 0, sizeof *e);
    e->max_rel = -1;
    for (i = 0; i < d->n; i++) {
        double x = 0;
        if (d->k->err_abs) {
            for (j = 0; j < d->k->n_outputs; j++) {
                double t = d->out[j][i] - d->want[j][i];
                x += t * t;
            }
            x = sqrt(x) / d->cond[i];
            if (x != x)
                x = INFINITY;
        } else {
            x = bench_rel_err(d->out[0][i], d->want[0][i]) / d->cond[i];
        }
        sum += x;
        if (x > e->max_rel) {
            e->max_rel = x;
            e->got = d->out[0][i];
            e->want = d->want[0][i];
            for (j = 0; j < na; j++)
                e->arg[j] = d->in[j][i];
        }
    }
    e->n = (long)d->n;
    e->mean_rel = sum / (double)d->n;
}

static void srow(bench_row *r, const sdata *d, const char *format, const char *port, const char *path,
                 int lanes)
{
    memset(r, 0, sizeof *r);
    r->kernel = d->k->name;
    r->format = format;
    r->port = port;
    r->path = path;
    r->note = "";
    r->n_inputs = d->k->n_inputs < FACET_MAX_INPUTS ? d->k->n_inputs : FACET_MAX_INPUTS;
    r->lanes = lanes;
}

static void stime(bench_row *r, bench_sfn fn, sdata *d, const bench_opts *o)
{
    work w;
    memset(&w, 0, sizeof w);
    w.sfn = fn;
    w.sout = d->out;
    w.in = (const float *const *)d->in;
    w.n = o->n_time < d->n ? o->n_time : d->n;
    r->thr = time_work(&w, (double)w.n, o);
}

/* Every sampler and pdf: the batch API (facet_sampler.f32_batch and
 * f32_fast_batch) on every port this CPU runs, as the kernels' batch rows,
 * the inline and call loops (loops_tier.h), then the textbook peer
 * (peers_sample.c) where there is one.  Error: the contracts' measure on
 * min(n_err, 16384) samples, against the facet.h bound.  No latency rows. */
static void run_samplers(const bench_opts *o, bench_sink sink, void *ctx, int *count)
{
    size_t si, p;
    int tier;
    const char *saved_port = facet_port_name();
    size_t n = o->n_err < 16384 ? o->n_err : 16384;
    if (n < o->n_time)
        n = o->n_time;
    n = (n + 7) / 8 * 8;
    for (si = 0; si < facet_sampler_count(); si++) {
        const facet_sampler *k = facet_sampler_at(si);
        sdata d;
        bench_row row;
        if (o->kernel && strcmp(o->kernel, k->name))
            continue;
        sdata_make(&d, k, n, o->seed);
        for (tier = 0; tier < 2; tier++) {
            const char *tn = tier ? "f32_fast" : "f32";
            peer_sample_fn fn = tier ? k->f32_fast_batch : k->f32_batch;
            if (o->format && strcmp(o->format, tn))
                continue;
            for (p = 0; p < facet_port_count(); p++) {
                int sup = 0, lanes = 1;
                const char *pn = facet_port_at(p, &sup, &lanes);
                if (!sup || !want_port(o, pn) || facet_set_port(pn) != 0)
                    continue;
                srow(&row, &d, tn, pn, "batch", lanes);
                row.bound = tier ? k->err_f32_fast : k->err_f32;
                row.note = "facet_<sampler>_batch with facet_set_port(port) active";
                fn(d.out, (const float *const *)d.in, d.n);
                serr_of(&row.err, &d);
                stime(&row, fn, &d, o);
                finish(&row, o, sink, ctx, count);
            }
            facet_set_port(saved_port ? saved_port : "auto");
            /* the inline port kernels and the library call, as the kernels' */
            for (p = 0; bench_loop_tables[p]; p++) {
                const bench_loops *t = bench_loop_tables[p];
                if (o->sampler_batch_only || strcmp(t->tier, tn) || !t->s || !t->available() ||
                    !want_port(o, t->port))
                    continue;
                srow(&row, &d, tn, t->port, t->path, t->lanes);
                row.bound = tier ? k->err_f32_fast : k->err_f32;
                t->s[si](d.out, (const float *const *)d.in, d.n);
                serr_of(&row.err, &d);
                stime(&row, t->s[si], &d, o);
                finish(&row, o, sink, ctx, count);
            }
        }
        if (o->peers && (!o->format || !strcmp(o->format, "f32")) && want_port(o, "textbook")) {
            int same = 0;
            peer_sample_fn fn = peer_sample_textbook(k->name, &same);
            if (fn) {
                srow(&row, &d, "f32", "textbook", "peer", 1);
                row.note = same ? "tests/lib/sample_peer.h: the direct formulas with libm, -O2"
                                : "tests/lib/sample_peer.h: Heitz 2018 as transcribed, libm, -O2 (another map of "
                                  "(u1, u2) to h with the same law: error not comparable)";
                fn(d.out, (const float *const *)d.in, d.n);
                serr_of(&row.err, &d);
                if (!same)
                    row.err.max_rel = row.err.mean_rel = NAN;
                stime(&row, fn, &d, o);
                finish(&row, o, sink, ctx, count);
            }
        }
        sdata_free(&d);
    }
}

/* ---- everything ------------------------------------------------------------- */

int bench_run(const bench_opts *o, bench_sink sink, void *ctx)
{
    size_t ki, nk = facet_kernel_count();
    int count = 0;
    size_t ti;
    int tier;
    const char *saved_port;

    if (o->kernel && !facet_kernel_find(o->kernel) && !facet_sampler_find(o->kernel))
        return -1;
    if (o->peers && peer_check(stderr) != 0)
        return -2;
    if (o->format && strcmp(o->format, "f32") && strcmp(o->format, "f32_fast") && strcmp(o->format, "fx") &&
        strcmp(o->format, "fx_fast") && strcmp(o->format, "f16"))
        return -1;
    if (o->port) {
        int known = 0;
        for (ti = 0; peer_sets[ti]; ti++)
            if (!strcmp(o->port, peer_sets[ti]->name))
                known = 1;
        size_t p;
        for (p = 0; p < facet_port_count(); p++)
            if (!strcmp(facet_port_at(p, NULL, NULL), o->port))
                known = 1;
        if (facet_f16_port_supported(o->port))
            known = 1;
        if (!known)
            return -1;
    }
    cyc_init();
    saved_port = facet_port_name();

    for (ki = 0; ki < nk; ki++) {
        const facet_kernel *k = facet_kernel_at(ki);
        kdata d;
        size_t p;
        if (o->kernel && strcmp(o->kernel, k->name))
            continue;
        kdata_make(&d, k, (o->n_err + 7) / 8 * 8, o->seed);

        for (tier = 0; tier < 2; tier++) {
            /* both f32 tiers: the batch on every port this CPU runs, then the
             * inline and call loops */
            const char *tn = tier ? "f32_fast" : "f32";
            const bench_loops *batch = tier ? &bench_loops_batch_fast : &bench_loops_batch;
            if (o->format && strcmp(o->format, tn))
                continue;
            for (p = 0; p < facet_port_count(); p++) {
                int sup = 0, lanes = 1;
                const char *pn = facet_port_at(p, &sup, &lanes);
                bench_row row;
                const bench_loops *il = NULL;
                if (!sup || !want_port(o, pn) || facet_set_port(pn) != 0)
                    continue;
                row_init(&row, &d, tn, pn, "batch", lanes);
                if (tier)
                    row.bound = k->err_f32_fast;
                eval_all(batch->k[ki].thr, &d, d.out, d.n);
                err_of(&row.err, &d, d.out, d.want);
                row_time(&row, batch->k[ki].thr, &d, o);
                /* latency: the port's inline kernel in a dependent chain */
                for (ti = 0; bench_loop_tables[ti]; ti++)
                    if (!strcmp(bench_loop_tables[ti]->path, "inline") &&
                        !strcmp(bench_loop_tables[ti]->port, pn) && !strcmp(bench_loop_tables[ti]->tier, tn) &&
                        bench_loop_tables[ti]->available())
                        il = bench_loop_tables[ti];
                if (il)
                    row_latency(&row, il->k[ki].chain, il->k[nk].chain, il->lanes, &d, o);
                finish(&row, o, sink, ctx, &count);
            }
            facet_set_port(saved_port ? saved_port : "auto");
            for (ti = 0; bench_loop_tables[ti]; ti++) {
                const bench_loops *t = bench_loop_tables[ti];
                bench_row row;
                if (strcmp(t->tier, tn) || !t->available() || !want_port(o, t->port) || !t->k[ki].thr)
                    continue;
                row_init(&row, &d, tn, t->port, t->path, t->lanes);
                if (tier)
                    row.bound = k->err_f32_fast;
                eval_all(t->k[ki].thr, &d, d.out, o->n_time);
                err_of(&row.err, &d, d.out, d.want);
                row_time(&row, t->k[ki].thr, &d, o);
                row_latency(&row, t->k[ki].chain, t->k[nk].chain, t->lanes, &d, o);
                finish(&row, o, sink, ctx, &count);
            }
        }
        if (!o->format || !strcmp(o->format, "f32")) {
            /* peers */
            if (o->peers) {
                const peer_set *const *sets = peer_sets;
                size_t s;
                for (s = 0; sets[s]; s++) {
                    peer_term_fn fn = peer_term(sets[s], k->name);
                    bench_row row;
                    if (!fn || !peer_available(sets[s]) || !want_port(o, sets[s]->name))
                        continue;
                    row_init(&row, &d, "f32", sets[s]->name, "peer", 1);
                    row.bound = 0;
                    row.note = sets[s]->build;
                    eval_all(fn, &d, d.out, d.n);
                    err_of(&row.err, &d, d.out, d.want);
                    row_time(&row, fn, &d, o);
                    finish(&row, o, sink, ctx, &count);
                }
                if (!strcmp(k->name, "brdf_hammon"))
                    run_brdf_peers(&d, o, sink, ctx, &count);
            }
        }
        for (tier = 0; tier < 2; tier++) {
            const bench_fx *fx = bench_fx_find(k->name);
            if (fx && (tier || fx->batch) && (!o->format || !strcmp(o->format, tier ? "fx_fast" : "fx")))
                run_fx(fx, &d, o, sink, ctx, &count, tier);
        }
        {
            const facet_f16_kernel *h = facet_f16_kernel_find(k->name);
            if (h && h->f16 && h->f16_batch && (!o->format || !strcmp(o->format, "f16")))
                run_f16(h, &d, o, sink, ctx, &count);
        }
        kdata_free(&d);
    }
    if (!o->format || !strcmp(o->format, "f32") || !strcmp(o->format, "f32_fast"))
        run_samplers(o, sink, ctx, &count);
    return count;
}
