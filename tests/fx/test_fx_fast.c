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

/* ---- monotonicity: every value of one input along lines of the others ----
 * Where the function is monotone in an input (the oracle: the survey in the
 * list's comment), the count of reversals (a step of the input by one raw
 * unit that moves the output against the direction) along lines through
 * every value of that input, the other inputs on a set of lines: for a
 * two-input kernel 128 values of the other (alpha: fx_alpha_set's ends and
 * log-spaced set; else every 256th raw value and 1 .. 89), for more inputs
 * 120 lines of fx_random_inputs (the first four at the ends of every other
 * input).  Held to exactly the figure the list states (0: monotone). */
static long mono_lines(const facet_fx_kernel *fk, int which, int dir, long *checks)
{
    fx_rng r = { 0x3070fa57u };
    int32_t in[FACET_FX_MAX_INPUTS], other[160];
    int i, j, lines;
    long bad = 0;
    if (fk->n_inputs == 2) {
        int o = 1 - which;
        static const int32_t small[] = { 1, 2, 3, 5, 8, 13, 21, 34, 55, 89 };
        if (!strcmp(fk->inputs[o], "alpha")) {
            lines = fx_alpha_set(other, 124);
        } else {
            for (lines = 0; lines <= 128; lines++)
                other[lines] = lines * 256;
            for (j = 0; j < (int)(sizeof small / sizeof small[0]); j++)
                other[lines++] = small[j];
        }
    } else {
        lines = 120;
    }
    if (quick)
        lines = lines < 8 ? lines : 8;
    for (i = 0; i < lines; i++) {
        uint64_t prev = 0;
        int32_t x;
        if (fk->n_inputs == 2) {
            in[1 - which] = other[i];
        } else {
            fx_random_inputs(&r, FX_GEOM_NEAR_NORMAL, fk, in);
            if (i < 4)
                for (j = 0; j < fk->n_inputs; j++)
                    in[j] = (i & 1) ? fk->hi[j] : fk->lo[j];
        }
        for (j = 0; j < fk->n_inputs; j++) /* the line's other inputs in the domain */
            in[j] = in[j] < fk->lo[j] ? fk->lo[j] : in[j] > fk->hi[j] ? fk->hi[j] : in[j];
        for (x = fk->lo[which]; x <= fk->hi[which]; x++) {
            uint64_t y;
            in[which] = x;
            y = cur(in);
            bad += x > fk->lo[which] && (dir > 0 ? y < prev : y > prev);
            prev = y;
            (*checks)++;
        }
    }
    return bad;
}

static void monotonicity(void)
{
    /* kernel, input, direction (+1 non-decreasing, -1 non-increasing), the
     * stated reversals on these lines (facet/fx.h); every pair where the
     * oracle is monotone over fx_random_inputs lines */
    static const struct { const char *k, *in; int dir; long stated; } mono[] = {
        { "noh_from_dots", "nol", 1, 0 }, { "noh_from_dots", "nov", 1, 0 }, { "noh_from_dots", "lov", -1, 0 },
        { "loh_from_dots", "lov", 1, 0 },
        { "fresnel_schlick", "f0", 1, 0 }, { "fresnel_schlick", "cos", -1, 0 },
        { "fresnel_schlick_f90", "f0", 1, 0 }, { "fresnel_schlick_f90", "f90", 1, 0 },
        { "fresnel_schlick_sg", "f0", 1, 0 }, { "fresnel_schlick_sg", "cos", -1, 0 },
        { "ggx_d", "noh", 1, 0 }, { "blinn_phong_d", "noh", 1, 0 }, { "gtr_d", "noh", 1, 0 },
        { "ggx_aniso_d", "noh", -1, 0 },
        { "smith_g1", "nov", 1, 0 }, { "smith_g1", "alpha", -1, 0 },
        { "smith_g2", "nol", 1, 0 }, { "smith_g2", "nov", 1, 0 }, { "smith_g2", "alpha", -1, 0 },
        { "smith_g2_uncorrelated", "nol", 1, 0 }, { "smith_g2_uncorrelated", "nov", 1, 0 },
        { "smith_g2_uncorrelated", "alpha", -1, 0 },
        { "smith_vis", "nol", -1, 0 }, { "smith_vis", "nov", -1, 0 }, { "smith_vis", "alpha", -1, 0 },
        { "smith_g1_hammon", "nov", 1, 0 }, { "smith_g1_hammon", "alpha", -1, 0 },
        { "smith_g1_gtr", "nov", 1, 1 }, { "smith_g1_gtr", "alpha", -1, 172 }, { "smith_g1_gtr", "gamma", 1, 0 },
        { "smith_g2_hammon", "nol", 1, 0 }, { "smith_g2_hammon", "nov", 1, 0 }, { "smith_g2_hammon", "alpha", -1, 0 },
        { "smith_vis_hammon", "nol", -1, 0 }, { "smith_vis_hammon", "nov", -1, 0 },
        { "smith_vis_hammon", "alpha", -1, 0 },
        { "g_implicit", "nol", 1, 0 }, { "g_implicit", "nov", 1, 0 }, { "g_neumann", "nol", 1, 0 },
        { "g_neumann", "nov", 1, 0 }, { "g_cook_torrance", "nol", 1, 0 }, { "g_cook_torrance", "nov", 1, 0 },
        { "g_cook_torrance", "noh", 1, 0 }, { "g_cook_torrance", "voh", -1, 0 },
        { "g_kelemen", "nol", 1, 0 }, { "g_kelemen", "nov", 1, 0 }, { "g_kelemen", "voh", -1, 0 },
        { "smith_g1_beckmann", "nov", 1, 0 }, { "smith_g1_beckmann", "alpha", -1, 0 },
        { "smith_g1_schlick_beckmann", "nov", 1, 0 }, { "smith_g1_schlick_beckmann", "alpha", -1, 0 },
        { "smith_vis_joint_approx", "nol", -1, 0 }, { "smith_vis_joint_approx", "nov", -1, 0 },
        { "smith_vis_joint_approx", "alpha", -1, 0 },
        { "smith_vis_fit", "nol", -1, 0 }, { "smith_vis_fit", "nov", -1, 0 },
        { "diffuse_hammon", "lov", 1, 0 }, { "diffuse_hammon", "albedo", 1, 0 },
        { "diffuse_burley", "loh", 1, 0 }, { "diffuse_burley", "alpha", 1, 0 }, { "diffuse_burley", "albedo", 1, 0 },
        { "diffuse_oren_nayar", "lov", 1, 0 }, { "diffuse_oren_nayar", "albedo", 1, 0 },
        { "diffuse_hammon_hybrid", "lov", 1, 0 }, { "diffuse_hammon_hybrid", "albedo", 1, 0 },
        { "diffuse_hammon_cheap", "lov", 1, 0 }, { "diffuse_hammon_cheap", "albedo", 1, 0 },
        { "brdf_hammon", "f0", 1, 0 }, { "brdf_hammon", "albedo", 1, 0 },
    };
    size_t i;
    long steps = 0;
    for (i = 0; i < sizeof mono / sizeof mono[0]; i++) {
        const facet_fx_kernel *fk = facet_fx_kernel_find(mono[i].k);
        int which = -1, j;
        long bad, checks = 0;
        for (j = 0; fk && j < fk->n_inputs; j++)
            if (!strcmp(fk->inputs[j], mono[i].in))
                which = j;
        CHECK(fk && fk->fx_fast && which >= 0, "monotonicity: %s has no fast tier or no input %s", mono[i].k,
              mono[i].in);
        if (!fk || !fk->fx_fast || which < 0)
            continue;
        cur = fk->fx_fast;
        bad = mono_lines(fk, which, mono[i].dir, &checks);
        if (bad || mono[i].stated)
            printf("monotonicity %-22s %-6s %+d: %ld reversals in %ld steps\n", mono[i].k, mono[i].in, mono[i].dir,
                   bad, checks);
        /* the quick sweep is a subset: at most the stated count */
        CHECK(quick ? bad <= mono[i].stated : bad == mono[i].stated,
              "%s: %ld reversals in %s (direction %+d) over %ld steps, stated %ld", mono[i].k, bad, mono[i].in,
              mono[i].dir, checks, mono[i].stated);
        steps += checks;
    }
    printf("monotonicity: %d kernel-input pairs, %ld steps\n", (int)(sizeof mono / sizeof mono[0]), steps);
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
    monotonicity();
    key_points();
    return th_done();
}
