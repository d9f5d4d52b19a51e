/* peers.c - lookup of a peer's single-term functions by facet kernel name. */
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
    if (!strcmp(name, "brdf_hammon")) return p->brdf_hammon;
    if (!strcmp(name, "fresnel_schlick")) return p->fresnel_schlick;
    if (!strcmp(name, "ggx_d")) return p->ggx_d;
    if (!strcmp(name, "smith_g1")) return p->smith_g1;
    if (!strcmp(name, "smith_g2")) return p->smith_g2;
    if (!strcmp(name, "smith_vis")) return p->smith_vis;
    if (!strcmp(name, "smith_g1_hammon")) return p->smith_g1_hammon;
    if (!strcmp(name, "smith_vis_hammon")) return p->smith_vis_hammon;
    return NULL;
}
