/* f16_peer.h - the binary16 shader-style peer's table (peer_f16_shader.c) */
#ifndef FACET_F16_PEER_H
#define FACET_F16_PEER_H
#include <stddef.h>
#include <stdint.h>
#include <string.h>
typedef struct {
    const char *name;
    void (*fn)(uint16_t *out, const uint16_t *const *in, size_t n);
} f16_peer_entry;
extern const f16_peer_entry f16_peer_shader[];

/* the peer of the kernel NAME, or NULL where it has none */
static inline const f16_peer_entry *f16_peer_find(const char *name)
{
    const f16_peer_entry *p;
    for (p = f16_peer_shader; p->name; p++)
        if (!strcmp(p->name, name))
            return p;
    return NULL;
}
#endif
