/* test_fx_fast.c - the fx_fast tier (facet/fx.h "fast tier") against the
 * double oracle at the same raw Q15 inputs:
 *   - loh_from_dots on every input; the two-input kernels on every value of
 *     their first input times a set of second inputs (Fresnel: both ways);
 *   - every kernel on random geometry (consistent dot triples aimed at the
 *     peak, grazing angles, L near V and the near-normal peak), on raw
 *     tuples uniform over the domain (ends and the peak's L.V weighted),
 *     and on an edge grid;
 * error = |raw - v 2^frac| / max(1, 2^-10 v 2^frac) (the tier's bound: 1
 * LSB or 2^-10 relative, whichever is larger), held to exactly
 * FACET_FX_FAST_ERR_<NAME>; prints per kernel the samples, the max error,
 * the max LSB error where v 2^frac < 2^10, the max relative error above and
 * above 2^15 LSB (where the final rounding no longer shows), and the
 * argmax of the error.  Also: every out-of-domain int32 class (INT32_MIN/MAX
 * included) gives the kernel at the clamped input, no output exceeds the
 * format maximum, and the exact key points the body promises. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../lib/harness.h"
#include "../lib/fx_test.h"
#include "facet.h"
#include "facet/fx.h"
#include "facet/oracle.h"

typedef uint64_t (*fast_fn)(const int32_t *in);

static int quick;
static fast_fn cur;

typedef struct {
    long n;
    double max_err, max_lsb, max_rel, max_rel_big;
    int32_t arg[FACET_FX_MAX_INPUTS];
    uint64_t got;
    double want;
} stat;

static void one(const facet_fx_kernel *fk, const facet_kernel *k, const int32_t *in, stat *st)
{
    double din[FACET_FX_MAX_INPUTS], scaled, diff, err;
    uint64_t got;
    int i;
    for (i = 0; i < fk->n_inputs; i++)
        din[i] = in[i] / 32768.0;
    /* results saturate at the format's maximum (facet/fx.h): the reference too */
    scaled = fmin(ldexp(k->oracle(din), fk->out_frac), (double)fk->out_max);
    got = cur(in);
    diff = fabs((double)got - scaled);
    err = diff / fmax(1.0, scaled * FACET_FX_FAST_TOL_REL);
    st->n++;
    if (scaled < 1024.0) {
        if (diff > st->max_lsb)
            st->max_lsb = diff;
    } else if (diff / scaled > st->max_rel) {
        st->max_rel = diff / scaled;
    }
    if (scaled >= 32768.0 && diff / scaled > st->max_rel_big)
        st->max_rel_big = diff / scaled;
    if (err > st->max_err || st->n == 1) {
        st->max_err = err;
        st->got = got;
        st->want = scaled;
        memcpy(st->arg, in, sizeof st->arg);
    }
}

/* raw tuples uniform over the domain, 1 in 4 inputs pinned near an end of
 * its range, alpha log-uniform 1 in 8, L.V half the time near the peak's
 * 2 nl nv - 1 or L = V's value (then maybe inconsistent by up to 2^-10) */
static void uniform_inputs(fx_rng *r, const facet_fx_kernel *fk, int32_t *in)
{
    int i;
    for (i = 0; i < fk->n_inputs; i++) {
        uint64_t x = fx_next(r);
        int32_t lo = fk->lo[i], hi = fk->hi[i];
        unsigned mode = (unsigned)(x & 7);
        x >>= 3;
        if (mode == 0) in[i] = lo + (int32_t)(x % 64);
        else if (mode == 1) in[i] = hi - (int32_t)(x % 64);
        else if (mode == 2 && !strcmp(fk->inputs[i], "alpha")) in[i] = (int32_t)floor(32.0 * pow(1024.0, (x >> 11) * 0x1p-53));
        else in[i] = lo + (int32_t)(x % (uint64_t)(hi - lo + 1));
        if (!strcmp(fk->inputs[i], "lov") && i >= 2 && (x & 1)) {
            double nl = in[0] / 32768.0, nv = in[1] / 32768.0;
            double v = (x & 2) ? 2 * nl * nv - 1 : nl * nv + sqrt(1 - nl * nl) * sqrt(1 - nv * nv);
            v += ((double)(fx_next(r) % 2001) - 1000) * 0x1p-20;
            in[i] = (int32_t)fx_round_hu(fmin(fmax(v, -1.0), 1.0) * 32768);
        }
    }
}

/* one() as an fx_edge_grid visitor */
struct one_ctx { const facet_fx_kernel *fk; const facet_kernel *k; stat *st; };
static void one_visit(const int32_t *in, void *ctx)
{
    struct one_ctx *c = (struct one_ctx *)ctx;
    one(c->fk, c->k, in, c->st);
}

static void accuracy(const facet_fx_kernel *fk, const facet_kernel *k, double bound)
{
    stat st;
    fx_rng r;
    int32_t in[FACET_FX_MAX_INPUTS], al[200];
    long j, nr;
    int i, na;
    memset(&st, 0, sizeof st);
    r.s = 0xfa570000u + (uint64_t)strlen(fk->name);
    if (fk->n_inputs == 1) {
        for (j = fk->lo[0]; j <= fk->hi[0]; j++) {
            in[0] = (int32_t)j;
            one(fk, k, in, &st);
        }
    } else if (fk->n_inputs == 2) {
        int step = quick ? 61 : 1;
        na = fx_alpha_set(al, quick ? 12 : 28);
        for (i = 0; i < na; i++)
            for (j = 0; j <= 32768; j += step) {
                int cosk = !strcmp(fk->inputs[1], "cos");
                in[0] = (int32_t)j;
                in[1] = cosk && al[i] == 32 ? 0 : al[i];
                one(fk, k, in, &st);
                if (cosk) {
                    in[1] = (int32_t)j;
                    in[0] = al[i] == 32 ? 0 : al[i];
                    one(fk, k, in, &st);
                }
            }
    }
    nr = fk->n_inputs <= 2 ? 100000 : fk->n_inputs == 3 ? 400000 : 1000000;
    if (quick)
        nr /= 20;
    for (j = 0; j < nr; j++) {
        fx_random_inputs(&r, FX_GEOM_NEAR_NORMAL | FX_GEOM_TINY, fk, in);
        one(fk, k, in, &st);
    }
    for (j = 0; j < nr; j++) {
        uniform_inputs(&r, fk, in);
        one(fk, k, in, &st);
    }
    {
        struct one_ctx c;
        c.fk = fk;
        c.k = k;
        c.st = &st;
        fx_edge_grid(fk, LONG_MAX, one_visit, &c);
    }
    printf(getenv("FACET_FX_FAST_DIGITS") ? "%-22s %-8s %9ld %.6f %6.3f 2^%6.2f " : "%-22s %-8s %9ld %7.4f %6.3f 2^%6.2f ", fk->name, fk->out_format, st.n, st.max_err, st.max_lsb,
           st.max_rel > 0 ? log2(st.max_rel) : -99.0);
    if (st.max_rel_big > 0)
        printf("2^%6.2f  (", log2(st.max_rel_big));
    else
        printf("%9s  (", "-");
    for (i = 0; i < fk->n_inputs; i++)
        printf("%s%d", i ? " " : "", (int)st.arg[i]);
    printf(") -> %llu / %.3f\n", (unsigned long long)st.got, st.want);
    CHECK(st.max_err <= bound, "%s: max error %.4f exceeds FACET_FX_FAST_ERR %.4f", fk->name, st.max_err, bound);
    CHECK(bound <= 1.0, "%s: FACET_FX_FAST_ERR %.4f above the tier's bound 1", fk->name, bound);
}

/* out-of-domain raw values give the kernel at the clamped value; no output
 * above the format maximum */
static void clamping(const facet_fx_kernel *fk)
{
    static const int32_t bad_vals[] = { INT32_MIN, -2147483647, -65536, -32769, -32768, -32767, -1, 0, 1, 31,
                                        32, 127, 128, 32767, 32768, 32769, 65535, 65536, 1 << 30, INT32_MAX };
    fx_rng r = { 0xc1a5 };
    long bad = 0, over = 0;
    int i, j, t;
    for (t = 0; t < (quick ? 20 : 300); t++) {
        int32_t in[FACET_FX_MAX_INPUTS], cl[FACET_FX_MAX_INPUTS];
        fx_random_inputs(&r, FX_GEOM_NEAR_NORMAL | FX_GEOM_TINY, fk, in);
        for (i = 0; i < fk->n_inputs; i++)
            for (j = 0; j < (int)(sizeof bad_vals / sizeof bad_vals[0]); j++) {
                uint64_t y;
                memcpy(cl, in, sizeof cl);
                cl[i] = bad_vals[j] < fk->lo[i] ? fk->lo[i] : bad_vals[j] > fk->hi[i] ? fk->hi[i] : bad_vals[j];
                in[i] = bad_vals[j];
                y = cur(in);
                bad += y != cur(cl);
                over += y > fk->out_max;
                in[i] = cl[i];
            }
    }
    /* every input at every bad value at once */
    for (j = 0; j < (int)(sizeof bad_vals / sizeof bad_vals[0]); j++) {
        int32_t in[FACET_FX_MAX_INPUTS];
        for (i = 0; i < fk->n_inputs; i++)
            in[i] = bad_vals[(j + 3 * i) % (int)(sizeof bad_vals / sizeof bad_vals[0])];
        over += cur(in) > fk->out_max;
    }
    CHECK(bad == 0, "%s: %ld out-of-domain inputs differ from their clamped value", fk->name, bad);
    CHECK(over == 0, "%s: %ld outputs above the format maximum", fk->name, over);
}

static void key_points(void)
{
    long bad = 0;
    int32_t x;
    for (x = 0; x <= 32768; x++) {
        bad += facet_fresnel_schlick_fx_fast(x, 32768) != x;
        bad += facet_fresnel_schlick_fx_fast(x, 0) != 32768;
    }
    CHECK(bad == 0, "fast F(f0, cos = 1) = f0 / F(f0, 0) = 1 fails for %ld f0", bad);
    for (bad = 0, x = 0; x <= 32768; x++) {
        bad += facet_fresnel_schlick_f90_fx_fast(x, 12345, 32768) != x;
        bad += facet_fresnel_schlick_f90_fx_fast(12345, x, 0) != x;
        bad += facet_fresnel_schlick_sg_fx_fast(x, 0) != 32768;
        bad += x > 0 && facet_fresnel_cook_torrance_fx_fast(x, 0) != 32768;
        bad += facet_fresnel_cook_torrance_fx_fast(0, x) != 0 || facet_fresnel_cook_torrance_fx_fast(32768, x) != 32768;
    }
    CHECK(bad == 0, "fast F90(f0, f90, 1) = f0, F90(f0, f90, 0) = f90, F_sg(f0, 0) = 1, F_ct(f0 > 0, 0) = 1, "
          "F_ct(0, c) = 0, F_ct(1, c) = 1: %ld fail", bad);
    CHECK(facet_noh_from_dots_fx_fast(32768, 32768, 32768) == 32768 && facet_loh_from_dots_fx_fast(32768) == 32768 &&
          facet_loh_from_dots_fx_fast(-32768) == 0 && facet_smith_g1_fx_fast(0, 1000) == 0 &&
          facet_smith_g1_hammon_fx_fast(0, 1000) == 0, "fast N.H, L.H, G1 key points");
}

int main(void)
{
    size_t i;
    quick = getenv("FACET_TEST_QUICK") != NULL;
    th_name = "fx_fast";
    printf("%-22s %-8s %9s %7s %6s %9s %9s  argmax of err\n", "kernel", "format", "samples", "err", "LSB<1K",
           "rel>=1K", "rel>=32K");
    /* every kernel of the fx table (src/core/kernels.def), its fast tier
     * and its FACET_FX_FAST_ERR_<NAME> bound from the table */
    for (i = 0; i < facet_fx_kernel_count(); i++) {
        const facet_fx_kernel *fk = facet_fx_kernel_at(i);
        const facet_kernel *k = facet_kernel_find(fk->name);
        CHECK(k && fk->fx_fast, "%s: no oracle kernel of that name, or no fast tier", fk->name);
        if (!k || !fk->fx_fast)
            continue;
        cur = fk->fx_fast;
        accuracy(fk, k, fk->err_fast);
        clamping(fk);
    }
    key_points();
    return th_done();
}
