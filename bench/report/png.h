/* png.h - a small PNG writer of our own: 8-bit RGB, per-row filter (None,
 * Sub, Up or Paeth, smallest sum of |bytes|), a zlib stream of one deflate
 * block with the fixed Huffman codes and greedy LZ77 matches (hash chains,
 * 32 KiB window), CRC-32 per chunk and Adler-32 over the filtered
 * scanlines.  Enough for report pictures; no dependency. */
#ifndef FACET_BENCH_PNG_H
#define FACET_BENCH_PNG_H

#include <stddef.h>
#include <stdint.h>

uint32_t png_crc32(uint32_t crc, const unsigned char *p, size_t n); /* start with 0 */
uint32_t png_adler32(uint32_t a, const unsigned char *p, size_t n); /* start with 1 */

/* Encodes w x h RGB (row-major, 3 bytes per pixel) into a malloc'd buffer;
 * returns its size (0 on failure), *out owns it. */
size_t png_encode(unsigned char **out, const unsigned char *rgb, int w, int h);

/* png_encode to a file; 0 on success. */
int png_write(const char *path, const unsigned char *rgb, int w, int h);

/* Base64 of a buffer, NUL-terminated, malloc'd (for data: URIs). */
char *png_base64(const unsigned char *p, size_t n);

#endif
