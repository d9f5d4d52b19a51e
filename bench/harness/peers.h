/* peers.h - what a user would otherwise write, for the benchmark to beat.
 * Written for the benchmark from the formulas in the source documents; no
 * code from anywhere.  Each peer exists as batch loops over SoA arrays.
 *
 *   textbook   (peers_textbook.c, -O2): straight from the papers.  H =
 *              normalize(L + V) from the vectors, powf(), D in its tan form,
 *              Smith G2 height-correlated through Lambda with sqrtf, plain
 *              divisions.  The whole BRDF is D G2 F / (4 N.L N.V) + Hammon
 *              diffuse.
 *   shader     (peers_shader.c, -O3 -fno-math-errno -fno-trapping-math
 *              -ffp-contract=fast;
 *              the compiler auto-vectorizes it): the engine-shader
 *              sequences.  H by 1/sqrtf, D in the a2 form, exact correlated
 *              Vis with two sqrtf, pow5 by multiplication, Hammon diffuse.
 *              Built for the vector width of the facet port it is compared
 *              with: on x86 shader_avx2 (-march=x86-64-v3) and
 *              shader_avx512 (-march=x86-64-v4), each run only where that
 *              facet port runs; elsewhere shader (-march=native).
 *   *_fm       the same source and width with -ffast-math as well.
 *
 * Two whole-BRDF peers per set, kept apart by their bench path:
 *   "peer"          brdf_hammon's OWN formula (Hammon's Vis
 *                   0.5 / (2 N.L N.V + (N.L + N.V - 2 N.L N.V) alpha), D, F,
 *                   Hammon's diffuse) from the same inputs as facet (N.L,
 *                   N.V, L.V, alpha, f0, albedo): N.H and L.H from one
 *                   rsqrt of 2 + 2 L.V, as engines derive them from dots.
 *                   The same work as facet's kernel, so its error column is
 *                   arithmetic error against brdf_hammon's oracle and its
 *                   time is comparable (the fair peer of issue 21).
 *   "peer-vectors"  D * EXACT correlated Vis (two sqrtf) * F + Hammon's
 *                   diffuse from vectors L and V in tangent space (N = +z),
 *                   computing every dot itself: another model (the exact
 *                   Vis differs from Hammon's by up to 29%), judged against
 *                   its own double oracle (bench_oracle_brdf_exact); kept to
 *                   show what a renderer holding vectors pays.
 * Single-term peers take the same scalar inputs and compute the same
 * formula as the facet kernel of the same name: every term brdf_hammon is
 * made of (noh_from_dots, loh_from_dots: one rsqrt / sqrt of 2 + 2 L.V;
 * ggx_d; smith_vis_hammon and smith_g2_hammon: Hammon's lerp;
 * fresnel_schlick; diffuse_hammon: N.H from the dots, (0.5 + N.H) / N.H)
 * and the exact Smith terms smith_g1, smith_g2, smith_vis (sqrtf; textbook
 * through Lambda), smith_g1_hammon.  The shader sets (not the textbook
 * one) also have every other kernel of the list, each its own formula from
 * its own inputs, as a shader writes it (peers_shader.c says which form):
 * fresnel_cook_torrance (the Fresnel equations as printed, eta from sqrt
 * f0), fresnel_schlick_f90, fresnel_schlick_sg (exp2f), blinn_phong_d
 * (powf), beckmann_d (expf), ggx_aniso_d (UE4's form), gtr_d (powf, c by
 * expm1f), smith_g2_uncorrelated, smith_g1_gtr (the five closed forms with
 * logf / log1pf and the pchip interpolation), g_implicit, g_neumann
 * (N.L N.V / max), g_cook_torrance, g_kelemen, smith_g1_beckmann
 * (Walter's rational), smith_g1_schlick_beckmann, smith_vis_joint_approx
 * (UE4's form), smith_vis_fit (facet/detail/vis_fit.h's constants),
 * diffuse_burley, diffuse_oren_nayar, diffuse_hammon_hybrid,
 * diffuse_hammon_cheap, lambert.  All peers clamp their inputs to the
 * kernel's domain (N.L, N.V to [FACET_COS_MIN, 1], alpha to
 * [FACET_ALPHA_MIN, 1], L.V, T.H, B.H to [-1, 1], gamma to [0, 4], the rest
 * to [0, 1]) like facet, so all are measured on the same domain; none has a
 * NaN rule or exact peak arithmetic (their error near the specular peak at
 * small alpha, and at f0 -> 0 for Cook-Torrance's Fresnel, is theirs).
 * peer_check (below) proves each term is its kernel's formula.
 */
#ifndef FACET_BENCH_PEERS_H
#define FACET_BENCH_PEERS_H

#include <stddef.h>
#include <stdio.h>

/* the full-BRDF inputs (SoA) */
typedef struct peer_brdf_in {
    const float *lx, *ly, *lz, *vx, *vy, *vz, *alpha, *f0, *albedo;
} peer_brdf_in;

/* a single-term peer: out[i] = term(in[0][i], in[1][i], ...) */
typedef void (*peer_term_fn)(float *out, const float *const *in, size_t n);
typedef void (*peer_brdf_fn)(float *out, const peer_brdf_in *in, size_t n);

/* a single term a peer computes: the facet kernel of that name, with the
 * same inputs */
typedef struct peer_term_entry {
    const char *kernel;
    peer_term_fn fn;
} peer_term_entry;

typedef struct peer_set {
    const char *name;       /* "textbook", "shader_avx2", "shader_avx2_fm", ... */
    const char *build;      /* compiler flags, for the report */
    const char *width;      /* the facet port of the same vector width (run
                             * only where facet_port_supported() says so), or
                             * NULL: the build machine's own */
    peer_brdf_fn brdf;      /* D Vis_exact F + diffuse_hammon, from vectors:
                             * another model (exact correlated Vis), bench rows
                             * path "peer-vectors" */
    /* the single terms it computes, up to { NULL, NULL }: same inputs and
     * formula as the facet kernel of the same name (brdf_hammon: Hammon's
     * Vis, from the dots) */
    const peer_term_entry *terms;
} peer_set;

/* every peer built for this target, NULL-terminated (peers.c) */
extern const peer_set *const peer_sets[];
/* 1 if this CPU runs p (its width's facet port is supported) */
int peer_available(const peer_set *p);

/* Returns the peer's function for facet kernel `name`, or NULL. */
peer_term_fn peer_term(const peer_set *p, const char *name);
/* Every peer's terms name a kernel of the list (a misspelt or removed one
 * would drop its rows silently), and every term of a peer this CPU runs
 * computes its kernel's formula: on a well-conditioned set (peers.c) its
 * error against the kernel's oracle is arithmetic error, <= 2^-10 (every
 * peer measures <= 1.4e-5 there; another model is off by 3% or more); a
 * control (the smith_vis_fit peer judged as exact smith_vis, 3.1% apart)
 * proves in every run that the check fails another model.
 * Prints each failure to err and returns their count. */
int peer_check(FILE *err);
/* the max relative error of fn against kernel's oracle on that set */
double peer_arith_err(peer_term_fn fn, const char *kernel);

/* The samplers' textbook peer (peers_sample.c, built like the textbook
 * peer: tests/lib/sample_peer.h's direct libm formulas, -O2): out[o][i] =
 * output o of the sampler or pdf `name` (facet.h) at in[0][i], ..., or
 * NULL where it has none.  *same_map (if not NULL): 1 where it computes
 * the same map as facet's oracle (so its error against it means
 * something), 0 for ggx_sample_vndf (Heitz's disk map: the same law, not
 * the same point for a given (u1, u2)). */
typedef void (*peer_sample_fn)(float *const *out, const float *const *in, size_t n);
peer_sample_fn peer_sample_textbook(const char *name, int *same_map);

#endif
