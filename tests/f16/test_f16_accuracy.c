/* test_f16_accuracy.c - every f16 kernel (src/core/f16_kernels.def) against
 * the double oracle at the same binary16 inputs (after facet/f16.h's domain
 * clamp), on every f16 port this CPU runs and the per-sample entry:
 * enforces FACET_ERR_<NAME>_F16 (the error measure of facet/f16.h), that no
 * result is Inf or NaN, and that values above 65504 give 65504; prints the
 * measured table (max error, log2, argmax inputs).
 * FACET_TEST_QUICK: fewer samples (emulators); FACET_TEST_F16_FORCE: a
 * table the dispatcher refuses, run all the same (f16_test.h). */
#include <stdio.h>
#include <stdlib.h>
#include "../lib/harness.h"
#include "f16_test.h"

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : getenv("FACET_TEST_QUICK") ? 30000 : 400000;
    size_t ki, j;
    th_name = "test_f16_accuracy";
    f16t_force_check();
    printf("%-18s %-11s %10s %7s  %s\n", "kernel", "port", "max err", "log2", "at (inputs; got, want)");
    for (ki = 0; ki < facet_f16_kernel_count(); ki++) {
        const facet_f16_kernel *h = facet_f16_kernel_at(ki);
        const facet_kernel *k = facet_kernel_find(h->name);
        facet_f16 *in[FACET_MAX_INPUTS], *out;
        double *want;
        smp_rng r;
        long s;
        int i;
        if (!h->f16)
            continue;
        CHECK(k && k->n_inputs == h->n_inputs, "%s: f16 table and kernel table disagree", h->name);
        if (!k)
            continue;
        r.s = smp_name_seed(h->name) ^ 0xf16;
        for (i = 0; i < k->n_inputs; i++)
            in[i] = malloc(n * sizeof(facet_f16));
        out = malloc(n * sizeof(facet_f16));
        want = malloc(n * sizeof(double));
        for (s = 0; s < n; s++) {
            facet_f16 x[FACET_MAX_INPUTS];
            double d[FACET_MAX_INPUTS];
            f16t_inputs(&r, k, x);
            for (i = 0; i < k->n_inputs; i++) {
                in[i][s] = x[i];
                d[i] = f16t_clamp(k->inputs[i], facet_f32_from_f16(x[i]));
            }
            want[s] = k->oracle(d);
        }
        /* port index F16T_N_PORTS: the per-sample entry (the scalar spec) */
        for (j = 0; j <= F16T_N_PORTS; j++) {
            const char *pname = j < F16T_N_PORTS ? f16t_ports[j].f16 : "per-sample";
            double max = 0.0;
            long arg = 0, bad_inf = 0, bad_sat = 0;
            if (j < F16T_N_PORTS) {
                if (!f16t_use(j)) {
                    const char *why = facet_f16_port_refusal(f16t_ports[j].f16);
                    printf("%-18s %-11s not run: %s\n", h->name, pname, why ? why : "not in this build");
                    continue;
                }
                f16t_batch(h, j, out, (const facet_f16 *const *)in, (size_t)n);
            } else {
                for (s = 0; s < n; s++) {
                    facet_f16 x[FACET_MAX_INPUTS];
                    for (i = 0; i < k->n_inputs; i++)
                        x[i] = in[i][s];
                    out[s] = h->f16(x);
                }
            }
            for (s = 0; s < n; s++) {
                double got = facet_f32_from_f16(out[s]), e;
                if ((out[s] & 0x7c00u) == 0x7c00u) {
                    bad_inf++;
                    continue;
                }
                if (want[s] > FACET_F16_MAX * (1.0 + h->err_f16) && out[s] != 0x7bffu)
                    bad_sat++;
                e = f16t_err(got, want[s]);
                if (e > max) {
                    max = e;
                    arg = s;
                }
            }
            printf("%-18s %-11s %10.3e %7.2f  (", h->name, pname, max, max > 0 ? log2(max) : -99.0);
            for (i = 0; i < k->n_inputs; i++)
                printf("%s%.9g", i ? " " : "", facet_f32_from_f16(in[i][arg]));
            printf("; %.9g, %.9g)\n", facet_f32_from_f16(out[arg]), want[arg]);
            CHECK(max <= h->err_f16, "%s on %s: error %.3e above the bound %.3e", h->name, pname, max,
                  h->err_f16);
            CHECK(bad_inf == 0, "%s on %s: %ld results Inf or NaN", h->name, pname, bad_inf);
            CHECK(bad_sat == 0, "%s on %s: %ld results above 65504 not saturated to 65504", h->name, pname,
                  bad_sat);
        }
        facet_set_port("auto");
        for (i = 0; i < k->n_inputs; i++)
            free(in[i]);
        free(out);
        free(want);
    }
    return th_done();
}
