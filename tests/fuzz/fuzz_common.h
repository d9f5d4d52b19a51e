/* fuzz_common.h - what the libFuzzer targets share: reading the fuzz input
 * as a little header and then raw 32-bit words, and failing loudly (abort,
 * so libFuzzer saves the input) on a broken contract. */
#ifndef FACET_FUZZ_COMMON_H
#define FACET_FUZZ_COMMON_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FUZZ_FAIL(...)                                                   \
    do {                                                                 \
        fprintf(stderr, "FUZZ FINDING %s:%d: ", __FILE__, __LINE__);     \
        fprintf(stderr, __VA_ARGS__);                                    \
        fputc('\n', stderr);                                             \
        abort();                                                         \
    } while (0)

/* bytes [at, at + 4) as a word, cycling over the data (zeros if none) */
static inline uint32_t fuzz_word(const uint8_t *data, size_t size, size_t at)
{
    uint32_t w = 0;
    int b;
    if (size == 0)
        return 0;
    for (b = 0; b < 4; b++)
        w |= (uint32_t)data[(at + (size_t)b) % size] << (8 * b);
    return w;
}

/* a buffer of exactly n elements of size el at element offset off, so that
 * AddressSanitizer sees any access outside [0, n) */
static inline void *fuzz_buf(size_t n, size_t el, size_t off, void **base)
{
    *base = malloc((n + off) * el + 1);
    if (!*base)
        abort();
    return (char *)*base + off * el;
}

#endif
