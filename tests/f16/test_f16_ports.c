/* test_f16_ports.c - the f16 list, bad input, tails, aliasing and the port
 * choice, on every f16 port this CPU runs and the per-sample entry:
 *   list     src/core/f16_kernels.def names every kernel of kernels.def, in
 *            its order; a kernel without an f16 form says why
 *   NaN      every NaN class (quiet, signalling, either sign, payloads) in
 *            every input position gives +0 (bits 0x0000)
 *   range    +-Inf, +-65504, beyond the domain, subnormals, -0: a finite
 *            result, bit-equal to the kernel at the clamped input
 *   tails    every count 0 .. 100 at offsets 0 .. 3: the same bits as the
 *            whole batch, nothing written past the count; out may be an input
 *   choice   the refusal of a port this CPU cannot run names what it needs,
 *            and the f16 batches then run the scalar port
 * FACET_TEST_F16_FORCE: a table the dispatcher refuses, run all the same
 * (f16_test.h); the choice checks still ask the dispatcher. */
#include <stdio.h>
#include <stdlib.h>
#include "../lib/harness.h"
#include "f16_test.h"

static const facet_f16 nans[] = { 0x7e00, 0xfe00, 0x7c01, 0xfc01, 0x7d55, 0x7fff, 0xffff, 0xfe01 };
static const facet_f16 odd[] = { 0x7c00, 0xfc00, 0x7bff, 0xfbff, 0x4000, 0xc000, 0x0001, 0x8001, 0x8000, 0x0000, 0x3c01 };

/* the clamped value of an input as binary16 bits */
static facet_f16 clamped(const char *name, facet_f16 x)
{
    double v = facet_f32_from_f16(x);
    return facet_f16_from_f32((float)f16t_clamp(name, v != v ? -2.0 : v));
}

/* one sample on port j (F16T_N_PORTS: the per-sample entry) */
static facet_f16 one(const facet_f16_kernel *h, size_t j, const facet_f16 *x)
{
    facet_f16 in[FACET_MAX_INPUTS][1], o = 0x1234;
    const facet_f16 *p[FACET_MAX_INPUTS];
    int i;
    if (j == F16T_N_PORTS)
        return h->f16(x);
    for (i = 0; i < h->n_inputs; i++) {
        in[i][0] = x[i];
        p[i] = in[i];
    }
    f16t_batch(h, j, &o, p, 1);
    return o;
}

static void list_checks(void)
{
    size_t i;
    CHECK(facet_f16_kernel_count() == facet_kernel_count(), "f16 list has %zu kernels, kernels.def %zu",
          facet_f16_kernel_count(), facet_kernel_count());
    for (i = 0; i < facet_f16_kernel_count() && i < facet_kernel_count(); i++) {
        const facet_f16_kernel *h = facet_f16_kernel_at(i);
        const facet_kernel *k = facet_kernel_at(i);
        CHECK(!strcmp(h->name, k->name) && h->n_inputs == k->n_inputs, "f16 list row %zu: %s, kernels.def: %s",
              i, h->name, k->name);
        if (h->f16)
            CHECK(h->f16_batch && h->err_f16 > 0 && h->err_f16 <= 0x1p-8, "%s: f16 bound %g not in (0, 2^-8]",
                  h->name, h->err_f16);
        else
            CHECK(h->why && strlen(h->why) > 10, "%s: no f16 form and no reason", h->name);
    }
}

static void bad_input(const facet_f16_kernel *h, const facet_kernel *k, size_t j, const char *pname)
{
    smp_rng r;
    int pos, t, c, bad_nan = 0, bad_range = 0;
    r.s = smp_name_seed(h->name);
    for (t = 0; t < 40; t++) {
        facet_f16 x[FACET_MAX_INPUTS], y[FACET_MAX_INPUTS];
        f16t_inputs(&r, k, x);
        for (pos = 0; pos < h->n_inputs; pos++) {
            memcpy(y, x, sizeof x);
            for (c = 0; c < (int)(sizeof nans / sizeof nans[0]); c++) {
                y[pos] = nans[c];
                if (one(h, j, y) != 0x0000)
                    bad_nan++;
            }
            for (c = 0; c < (int)(sizeof odd / sizeof odd[0]); c++) {
                facet_f16 o, o2;
                y[pos] = odd[c];
                o = one(h, j, y);
                y[pos] = clamped(k->inputs[pos], odd[c]);
                o2 = one(h, j, y);
                if ((o & 0x7c00u) == 0x7c00u || o != o2)
                    bad_range++;
            }
        }
    }
    CHECK(bad_nan == 0, "%s on %s: %d NaN inputs did not give +0", h->name, pname, bad_nan);
    CHECK(bad_range == 0, "%s on %s: %d out-of-range inputs not finite or not the clamped value", h->name,
          pname, bad_range);
}

#define N_ 104
static void tails(const facet_f16_kernel *h, const facet_kernel *k, size_t j, const char *pname)
{
    facet_f16 in[FACET_MAX_INPUTS][N_ + 8], ref[N_ + 8], out[N_ + 8], alias[N_ + 8];
    const facet_f16 *p[FACET_MAX_INPUTS];
    smp_rng r;
    size_t n, off, s;
    int i, bad = 0, bad_alias = 0;
    r.s = 7;
    for (s = 0; s < N_ + 8; s++) {
        facet_f16 x[FACET_MAX_INPUTS];
        f16t_inputs(&r, k, x);
        for (i = 0; i < h->n_inputs; i++)
            in[i][s] = x[i];
    }
    for (i = 0; i < h->n_inputs; i++)
        p[i] = in[i];
    f16t_batch(h, j, ref, p, N_ + 8);
    for (off = 0; off < 4; off++)
        for (n = 0; n <= 100; n++) {
            for (i = 0; i < h->n_inputs; i++)
                p[i] = in[i] + off;
            for (s = 0; s < N_ + 8; s++)
                out[s] = 0xabcd;
            f16t_batch(h, j, out + off, p, n);
            for (s = 0; s < N_ + 8; s++)
                if (out[s] != (s >= off && s < off + n ? ref[s] : 0xabcd))
                    bad++;
            /* out is the first input */
            memcpy(alias, in[0], sizeof alias);
            p[0] = alias + off;
            f16t_batch(h, j, alias + off, p, n);
            for (s = off; s < off + n; s++)
                if (alias[s] != ref[s])
                    bad_alias++;
        }
    CHECK(bad == 0, "%s on %s: %d wrong or stray lanes over counts 0..100, offsets 0..3", h->name, pname, bad);
    CHECK(bad_alias == 0, "%s on %s: %d wrong lanes with out == the first input", h->name, pname, bad_alias);
}

int main(void)
{
    size_t ki, j;
    th_name = "test_f16_ports";
    f16t_force_check();
    list_checks();
    for (j = 0; j <= F16T_N_PORTS; j++) {
        const char *pname = j < F16T_N_PORTS ? f16t_ports[j].f16 : "per-sample";
        if (j < F16T_N_PORTS && !f16t_use(j)) {
            const char *why = facet_f16_port_refusal(f16t_ports[j].f16);
            printf("port %s: not run here: %s\n", pname, why ? why : "not in this build");
            continue;
        }
        for (ki = 0; ki < facet_f16_kernel_count(); ki++) {
            const facet_f16_kernel *h = facet_f16_kernel_at(ki);
            const facet_kernel *k = facet_kernel_find(h->name);
            if (!h->f16 || !k)
                continue;
            bad_input(h, k, j, pname);
            if (j < F16T_N_PORTS)
                tails(h, k, j, pname);
        }
    }
    /* the choice */
    facet_set_port("auto");
    CHECK(!facet_f16_port_supported("bogus") && !facet_f16_port_refusal("bogus"), "an unknown f16 port name");
    CHECK(facet_f16_port_supported("scalar") && !facet_f16_port_refusal("scalar"), "scalar f16 refused");
    for (j = 1; j < F16T_N_PORTS; j++) {
        const char *n = f16t_ports[j].f16, *why = facet_f16_port_refusal(n);
        int sup = facet_f16_port_supported(n);
        CHECK(!(sup && why), "%s: supported, yet refused: %s", n, why ? why : "");
        if (!sup && !why)
            continue; /* not in this build (armv7 has no neonfp16, x86 none of Arm's) */
        if (!sup && facet_port_supported(f16t_ports[j].via)) {
            printf("port %s: refused: %s\n", n, why ? why : "?");
            CHECK(facet_set_port(f16t_ports[j].via) == 0 && !strcmp(facet_f16_port_name(), "scalar"),
                  "%s not supported, yet the f16 batches run %s", n, facet_f16_port_name());
        }
    }
    facet_set_port("auto");
    printf("f16 batches on %s (port %s)\n", facet_f16_port_name(), facet_port_name());
    return th_done();
}
