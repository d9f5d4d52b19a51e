/* peers.c - the peers built for this target, and a peer's single-term
 * functions by facet kernel name. */
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

int peer_check(FILE *err)
{
    const peer_term_entry *t;
    int s, bad = 0;
    for (s = 0; peer_sets[s]; s++)
        for (t = peer_sets[s]->terms; t && t->kernel; t++)
            if (!facet_kernel_find(t->kernel)) {
                fprintf(err, "peer %s: a term for %s, which is not a kernel of the list\n", peer_sets[s]->name,
                        t->kernel);
                bad++;
            }
    return bad;
}
