/* f16_peer.h - the binary16 shader-style peer's table (peer_f16_shader.c) */
#ifndef FACET_F16_PEER_H
#define FACET_F16_PEER_H
#include <stddef.h>
#include <stdint.h>
typedef struct {
    const char *name;
    void (*fn)(uint16_t *out, const uint16_t *const *in, size_t n);
} f16_peer_entry;
extern const f16_peer_entry f16_peer_shader[];
#endif
