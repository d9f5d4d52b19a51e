/* png.c - see png.h. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "png.h"

uint32_t png_crc32(uint32_t crc, const unsigned char *p, size_t n)
{
    static uint32_t table[256];
    static int ready;
    size_t i;
    if (!ready) {
        uint32_t c, k;
        int b;
        for (k = 0; k < 256; k++) {
            c = k;
            for (b = 0; b < 8; b++)
                c = (c & 1) ? 0xedb88320u ^ (c >> 1) : c >> 1;
            table[k] = c;
        }
        ready = 1;
    }
    crc = ~crc;
    for (i = 0; i < n; i++)
        crc = table[(crc ^ p[i]) & 0xff] ^ (crc >> 8);
    return ~crc;
}

uint32_t png_adler32(uint32_t a, const unsigned char *p, size_t n)
{
    uint32_t s1 = a & 0xffff, s2 = a >> 16;
    size_t i;
    for (i = 0; i < n; i++) {
        s1 = (s1 + p[i]) % 65521u;
        s2 = (s2 + s1) % 65521u;
    }
    return (s2 << 16) | s1;
}

static unsigned char *put32(unsigned char *q, uint32_t v)
{
    q[0] = (unsigned char)(v >> 24);
    q[1] = (unsigned char)(v >> 16);
    q[2] = (unsigned char)(v >> 8);
    q[3] = (unsigned char)v;
    return q + 4;
}

/* writes a chunk (length, type, data, crc) at q */
static unsigned char *chunk(unsigned char *q, const char *type, const unsigned char *data, size_t n)
{
    unsigned char *start;
    q = put32(q, (uint32_t)n);
    start = q;
    memcpy(q, type, 4);
    q += 4;
    if (n)
        memcpy(q, data, n);
    q += n;
    return put32(q, png_crc32(0, start, n + 4));
}

size_t png_encode(unsigned char **out, const unsigned char *rgb, int w, int h)
{
    size_t row = (size_t)w * 3 + 1, raw_n = row * (size_t)h;
    size_t nblocks = (raw_n + 65534) / 65535, zn, total;
    unsigned char *raw, *z, *q, *buf;
    unsigned char ihdr[13];
    size_t i, off;
    int y;
    *out = NULL;
    if (w <= 0 || h <= 0)
        return 0;
    raw = malloc(raw_n);
    zn = 2 + nblocks * 5 + raw_n + 4;
    z = malloc(zn);
    total = 8 + (12 + 13) + (12 + zn) + 12;
    buf = malloc(total);
    if (!raw || !z || !buf) {
        free(raw);
        free(z);
        free(buf);
        return 0;
    }
    for (y = 0; y < h; y++) {
        raw[(size_t)y * row] = 0; /* filter: none */
        memcpy(raw + (size_t)y * row + 1, rgb + (size_t)y * (size_t)w * 3, (size_t)w * 3);
    }
    /* zlib: CMF 0x78 (deflate, 32K window), FLG with FCHECK so that
     * (CMF*256 + FLG) % 31 == 0, no dictionary, "fastest" level */
    q = z;
    *q++ = 0x78;
    *q++ = 0x01;
    for (i = 0, off = 0; i < nblocks; i++) {
        size_t len = raw_n - off < 65535 ? raw_n - off : 65535;
        *q++ = (unsigned char)(i + 1 == nblocks); /* BFINAL, BTYPE = 00 (stored) */
        *q++ = (unsigned char)(len & 0xff);
        *q++ = (unsigned char)(len >> 8);
        *q++ = (unsigned char)(~len & 0xff);
        *q++ = (unsigned char)((~len >> 8) & 0xff);
        memcpy(q, raw + off, len);
        q += len;
        off += len;
    }
    q = put32(q, png_adler32(1, raw, raw_n));
    put32(ihdr, (uint32_t)w);
    put32(ihdr + 4, (uint32_t)h);
    ihdr[8] = 8;  /* bit depth */
    ihdr[9] = 2;  /* colour type: RGB */
    ihdr[10] = 0; /* deflate */
    ihdr[11] = 0; /* adaptive filtering */
    ihdr[12] = 0; /* no interlace */
    memcpy(buf, "\x89PNG\r\n\x1a\n", 8);
    q = chunk(buf + 8, "IHDR", ihdr, 13);
    q = chunk(q, "IDAT", z, zn);
    q = chunk(q, "IEND", NULL, 0);
    free(raw);
    free(z);
    *out = buf;
    return (size_t)(q - buf);
}

int png_write(const char *path, const unsigned char *rgb, int w, int h)
{
    unsigned char *buf;
    size_t n = png_encode(&buf, rgb, w, h);
    FILE *f;
    int rc = 1;
    if (!n)
        return 1;
    f = fopen(path, "wb");
    if (f) {
        rc = fwrite(buf, 1, n, f) != n;
        rc |= fclose(f) != 0;
    }
    free(buf);
    return rc;
}

char *png_base64(const unsigned char *p, size_t n)
{
    static const char a[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    char *s = malloc((n + 2) / 3 * 4 + 1), *q = s;
    size_t i;
    if (!s)
        return NULL;
    for (i = 0; i + 2 < n; i += 3) {
        uint32_t v = (uint32_t)p[i] << 16 | (uint32_t)p[i + 1] << 8 | p[i + 2];
        *q++ = a[v >> 18];
        *q++ = a[(v >> 12) & 63];
        *q++ = a[(v >> 6) & 63];
        *q++ = a[v & 63];
    }
    if (i < n) {
        uint32_t v = (uint32_t)p[i] << 16 | (i + 1 < n ? (uint32_t)p[i + 1] << 8 : 0);
        *q++ = a[v >> 18];
        *q++ = a[(v >> 12) & 63];
        *q++ = i + 1 < n ? a[(v >> 6) & 63] : '=';
        *q++ = '=';
    }
    *q = 0;
    return s;
}
