/* peers.c - the peers built for this target, and a peer's single-term
 * functions by facet kernel name. */
#include <math.h>
#include <string.h>
#include "facet.h"
#include "peers.h"

extern const peer_set peer_textbook;
#if defined(__x86_64__) || defined(__i386__)
extern const peer_set peer_shader_avx2, peer_shader_avx2_fm, peer_shader_avx512, peer_shader_avx512_fm;
#else
extern const peer_set peer_shader, peer_shader_fm;
#endif

const peer_set *const peer_sets[] = {
    &peer_textbook,
#if defined(__x86_64__) || defined(__i386__)
    &peer_shader_avx2, &peer_shader_avx2_fm, &peer_shader_avx512, &peer_shader_avx512_fm,
#else
    &peer_shader, &peer_shader_fm,
#endif
    NULL,
};

int peer_available(const peer_set *p) { return !p->width || facet_port_supported(p->width); }

peer_term_fn peer_term(const peer_set *p, const char *name)
{
    const peer_term_entry *t;
    for (t = p->terms; t && t->kernel; t++)
        if (!strcmp(t->kernel, name))
            return t->fn;
    return NULL;
}

/* ---- the arithmetic check ----------------------------------------------------
 * A peer computes its kernel's own formula, so against that kernel's oracle
 * its error is arithmetic error only.  On a well-conditioned set (below:
 * cosines and N.H in [0.1, 0.95], alpha in [0.1, 1], consistent L.V and unit
 * h, the other inputs in [0.05, 1]; away from the specular peak and the
 * grazing and mirror limits, where a peer's own arithmetic may lose digits)
 * float arithmetic of any of the peers' forms stays within 1.4e-5 (2^-16,
 * brdf_hammon's fast-math peer; most terms 1e-7 .. 1e-6); another model is
 * off by 3% or more there (of the kernels with the same inputs, the closest
 * two that are not one function, smith_vis_fit against exact smith_vis,
 * 3.1% apart on this set).  PEER_ARITH_MAX between the two. */
#define PEER_ARITH_N 2048
#define PEER_ARITH_MAX 0x1p-10

static double u01_(unsigned long long *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) * 0x1p-53;
}

/* column j of the well-conditioned set of kernel k: in[j][i] (float), and
 * the oracle of k at each row (of the float inputs) */
static void arith_set(const facet_kernel *k, float *in[FACET_MAX_INPUTS], double *want)
{
    unsigned long long s = 0x9eed21ull;
    int i, j, nl = -1, nv = -1, lv = -1, nh = -1, th = -1, bh = -1;
    for (j = 0; j < k->n_inputs; j++) {
        const char *n = k->inputs[j];
        if (!strcmp(n, "nol")) nl = j;
        else if (!strcmp(n, "nov")) nv = j;
        else if (!strcmp(n, "lov")) lv = j;
        else if (!strcmp(n, "noh")) nh = j;
        else if (!strcmp(n, "toh")) th = j;
        else if (!strcmp(n, "boh")) bh = j;
    }
    for (i = 0; i < PEER_ARITH_N; i++) {
        double d[FACET_MAX_INPUTS];
        for (j = 0; j < k->n_inputs; j++) {
            const char *n = k->inputs[j];
            double u = u01_(&s), x;
            if (j == nl || j == nv || j == nh)
                x = 0.1 + 0.85 * u;
            else if (!strncmp(n, "alpha", 5))
                x = 0.1 + 0.9 * u;
            else if (!strcmp(n, "gamma"))
                x = 4.0 * u;
            else if (j == lv || j == th || j == bh)
                x = 1.8 * u - 0.9; /* replaced below where the geometry defines it */
            else
                x = 0.05 + 0.95 * u;
            in[j][i] = (float)x;
        }
        if (lv >= 0 && nl >= 0 && nv >= 0) { /* a consistent L.V */
            double cl = in[nl][i], cv = in[nv][i], phi = 2.0 * M_PI * u01_(&s);
            in[lv][i] = (float)(cl * cv + sqrt((1 - cl * cl) * (1 - cv * cv)) * cos(phi));
        }
        if (nh >= 0 && th >= 0 && bh >= 0) { /* a unit h */
            double c = in[nh][i], st = sqrt(1 - c * c), phi = 2.0 * M_PI * u01_(&s);
            in[th][i] = (float)(st * cos(phi));
            in[bh][i] = (float)(st * sin(phi));
        }
        for (j = 0; j < k->n_inputs; j++)
            d[j] = in[j][i];
        want[i] = k->oracle(d);
    }
}

/* the max relative error of fn against kernel k's oracle on its set */
static double arith_err(peer_term_fn fn, const facet_kernel *k)
{
    static float col[FACET_MAX_INPUTS][PEER_ARITH_N], out[PEER_ARITH_N];
    static double want[PEER_ARITH_N];
    float *in[FACET_MAX_INPUTS];
    double m = 0;
    int i;
    for (i = 0; i < FACET_MAX_INPUTS; i++)
        in[i] = col[i];
    arith_set(k, in, want);
    fn(out, (const float *const *)in, PEER_ARITH_N);
    for (i = 0; i < PEER_ARITH_N; i++) {
        double e = out[i] != out[i] ? INFINITY : fabs(out[i] - want[i]) / fmax(fabs(want[i]), 0x1p-100);
        if (e > m)
            m = e;
    }
    return m;
}

double peer_arith_err(peer_term_fn fn, const char *kernel)
{
    const facet_kernel *k = facet_kernel_find(kernel);
    return k ? arith_err(fn, k) : INFINITY;
}

int peer_check(FILE *err)
{
    const peer_term_entry *t;
    int s, bad = 0, control = 0, listed = 0;
    for (s = 0; peer_sets[s]; s++)
        for (t = peer_sets[s]->terms; t && t->kernel; t++) {
            const facet_kernel *k = facet_kernel_find(t->kernel);
            double e;
            listed |= !strcmp(t->kernel, "smith_vis_fit");
            if (!k) {
                fprintf(err, "peer %s: a term for %s, which is not a kernel of the list\n", peer_sets[s]->name,
                        t->kernel);
                bad++;
                continue;
            }
            if (!peer_available(peer_sets[s]))
                continue;
            e = arith_err(t->fn, k);
            if (!(e <= PEER_ARITH_MAX)) {
                fprintf(err, "peer %s: its %s is %.3g off %s's oracle on the well-conditioned set (arithmetic "
                        "error is <= %.3g there): not the kernel's formula\n", peer_sets[s]->name, t->kernel, e,
                        t->kernel, PEER_ARITH_MAX);
                bad++;
            }
            /* the control: the check must fail a peer of another model, the
             * closest one (the fitted visibility judged as exact smith_vis) */
            if (!strcmp(t->kernel, "smith_vis_fit") && facet_kernel_find("smith_vis")) {
                control = 1;
                if (arith_err(t->fn, facet_kernel_find("smith_vis")) <= PEER_ARITH_MAX) {
                    fprintf(err, "peer check: %s's smith_vis_fit passes as smith_vis (3%% apart): the check "
                            "cannot tell another model\n", peer_sets[s]->name);
                    bad++;
                }
            }
        }
    /* a CPU that runs none of the sets with that peer (the shader sets need
     * AVX2: qemu's Nehalem) cannot run the control; a list without the
     * peer fails everywhere */
    if (!listed) {
        fprintf(err, "peer check: no smith_vis_fit peer to run the check's control on\n");
        bad++;
    } else if (!control)
        fprintf(err, "peer check: the control not run here: no peer set with smith_vis_fit runs on this CPU\n");
    return bad;
}
