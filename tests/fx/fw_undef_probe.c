/* fw_undef_probe.c - a source that needs libc (memcpy of a variable size
 * is always a call; declared here: a freestanding RV32 build has no
 * string.h): tests/fx/fw_undef.sh must report it (50-fx-targets). */
#include <stddef.h>
void *memcpy(void *d, const void *s, size_t n);
void fw_undef_probe(void *d, const void *s, size_t n);
void fw_undef_probe(void *d, const void *s, size_t n) { memcpy(d, s, n); }
