/* peers.h - what a user would otherwise write, for the benchmark to beat.
 * Written for the benchmark from the formulas in the source documents; no
 * code from anywhere.  Each peer exists as batch loops over SoA arrays.
 *
 *   textbook   (peers_textbook.c, -O2): straight from the papers.  H =
 *              normalize(L + V) from the vectors, powf(), D in its tan form,
 *              Smith G2 height-correlated through Lambda with sqrtf, plain
 *              divisions.  The whole BRDF is D G2 F / (4 N.L N.V) + Hammon
 *              diffuse.
 *   shader     (peers_shader.c, -O3 -fno-math-errno -ffp-contract=fast;
 *              the compiler auto-vectorizes it): the engine-shader
 *              sequences.  H by 1/sqrtf, D in the a2 form, exact correlated
 *              Vis with two sqrtf, pow5 by multiplication, Hammon diffuse.
 *              Built for the vector width of the facet port it is compared
 *              with: on x86 shader_avx2 (-march=x86-64-v3) and
 *              shader_avx512 (-march=x86-64-v4), each run only where that
 *              facet port runs; elsewhere shader (-march=native).
 *   *_fm       the same source and width with -ffast-math as well.
 *
 * The full-BRDF peers take vectors L and V in tangent space (N = +z, so
 * N.L = L.z, N.V = V.z cost nothing) plus alpha, f0, albedo, the way a
 * renderer holds them; they compute every other dot themselves.  facet's
 * brdf_hammon takes (N.L, N.V, L.V): a caller with vectors pays one 3-term
 * dot product for L.V on top.  Single-term peers take the same scalar inputs
 * as the facet kernel of the same name.  Both peers clamp N.L, N.V to
 * [FACET_COS_MIN, 1] and alpha to [FACET_ALPHA_MIN, 1] like facet, so all
 * are measured on the same domain.
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
    peer_brdf_fn brdf;      /* D Vis_exact F + diffuse_hammon, from vectors */
    const peer_term_entry *terms; /* the single terms it computes, up to { NULL, NULL } */
} peer_set;

/* every peer built for this target, NULL-terminated (peers.c) */
extern const peer_set *const peer_sets[];
/* 1 if this CPU runs p (its width's facet port is supported) */
int peer_available(const peer_set *p);

/* Returns the peer's function for facet kernel `name`, or NULL. */
peer_term_fn peer_term(const peer_set *p, const char *name);
/* Every peer's terms name a kernel of the list (a misspelt or removed one
 * would drop its rows silently): prints each that does not to err and
 * returns their count. */
int peer_check(FILE *err);

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
