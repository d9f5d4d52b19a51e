/* peers.c - lookup of a peer's single-term functions by facet kernel name. */
#include <string.h>
#include "peers.h"

peer_term_fn peer_term(const peer_set *p, const char *name)
{
    if (!strcmp(name, "fresnel_schlick")) return p->fresnel_schlick;
    if (!strcmp(name, "ggx_d")) return p->ggx_d;
    if (!strcmp(name, "smith_g1")) return p->smith_g1;
    if (!strcmp(name, "smith_g2")) return p->smith_g2;
    if (!strcmp(name, "smith_vis")) return p->smith_vis;
    if (!strcmp(name, "smith_g1_hammon")) return p->smith_g1_hammon;
    if (!strcmp(name, "smith_vis_hammon")) return p->smith_vis_hammon;
    return NULL;
}
