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

/* ---- deflate: fixed Huffman codes (RFC 1951 3.2.6) and LZ77 ----------- */

typedef struct bw { unsigned char *p; size_t n; uint32_t acc; int bits; } bw;

static void bw_put(bw *w, uint32_t v, int n) /* n bits of v, LSB first */
{
    w->acc |= v << w->bits;
    w->bits += n;
    while (w->bits >= 8) {
        w->p[w->n++] = (unsigned char)w->acc;
        w->acc >>= 8;
        w->bits -= 8;
    }
}

static void bw_code(bw *w, uint32_t code, int n) /* a Huffman code, MSB first */
{
    uint32_t r = 0;
    int i;
    for (i = 0; i < n; i++)
        r |= ((code >> i) & 1u) << (n - 1 - i);
    bw_put(w, r, n);
}

static void put_litlen(bw *w, unsigned v)
{
    if (v < 144) bw_code(w, 0x30 + v, 8);
    else if (v < 256) bw_code(w, 0x190 + (v - 144), 9);
    else if (v < 280) bw_code(w, v - 256, 7);
    else bw_code(w, 0xc0 + (v - 280), 8);
}

static const unsigned short len_base[29] = { 3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31,
                                             35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258 };
static const unsigned char len_extra[29] = { 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2,
                                             3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0 };
static const unsigned short dist_base[30] = { 1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193,
                                              257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145,
                                              8193, 12289, 16385, 24577 };
static const unsigned char dist_extra[30] = { 0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6,
                                              7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13 };

static void put_match(bw *w, unsigned len, unsigned dist)
{
    int i = 28, j = 29;
    while (len_base[i] > len)
        i--;
    put_litlen(w, 257 + (unsigned)i);
    bw_put(w, len - len_base[i], len_extra[i]);
    while (dist_base[j] > dist)
        j--;
    bw_code(w, (uint32_t)j, 5);
    bw_put(w, dist - dist_base[j], dist_extra[j]);
}

#define HBITS 15
#define WIN 32768
#define CHAIN 32

/* one final fixed-Huffman block with greedy LZ77 matches (hash chains over
 * a 32 KiB window); out needs n + n/8 + 16 bytes (the worst case: every
 * byte a 9-bit literal) */
static size_t deflate_fixed(unsigned char *out, const unsigned char *in, size_t n)
{
    bw w;
    size_t i = 0;
    long *head = malloc(sizeof(long) << HBITS), *prev = malloc(sizeof(long) * WIN);
    if (!head || !prev) {
        free(head);
        free(prev);
        return 0;
    }
    for (i = 0; i < (1u << HBITS); i++)
        head[i] = -1;
    w.p = out;
    w.n = 0;
    w.acc = 0;
    w.bits = 0;
    bw_put(&w, 1, 1); /* BFINAL */
    bw_put(&w, 1, 2); /* BTYPE = 01, fixed codes */
    i = 0;
    while (i < n) {
        unsigned best = 0, bdist = 0;
        if (i + 3 <= n) {
            unsigned h = ((unsigned)in[i] << 10 ^ (unsigned)in[i + 1] << 5 ^ in[i + 2]) & ((1u << HBITS) - 1);
            long c = head[h];
            int depth = CHAIN;
            size_t maxl = n - i < 258 ? n - i : 258;
            while (c >= 0 && i - (size_t)c <= WIN - 1 && depth-- > 0) {
                size_t l = 0;
                while (l < maxl && in[(size_t)c + l] == in[i + l])
                    l++;
                if (l > best) {
                    best = (unsigned)l;
                    bdist = (unsigned)(i - (size_t)c);
                    if (l == maxl)
                        break;
                }
                c = prev[(size_t)c % WIN];
            }
        }
        if (best >= 3) {
            size_t e = i + best;
            put_match(&w, best, bdist);
            for (; i < e; i++)
                if (i + 3 <= n) {
                    unsigned h = ((unsigned)in[i] << 10 ^ (unsigned)in[i + 1] << 5 ^ in[i + 2]) & ((1u << HBITS) - 1);
                    prev[i % WIN] = head[h];
                    head[h] = (long)i;
                }
        } else {
            if (i + 3 <= n) {
                unsigned h = ((unsigned)in[i] << 10 ^ (unsigned)in[i + 1] << 5 ^ in[i + 2]) & ((1u << HBITS) - 1);
                prev[i % WIN] = head[h];
                head[h] = (long)i;
            }
            put_litlen(&w, in[i]);
            i++;
        }
    }
    put_litlen(&w, 256); /* end of block */
    if (w.bits)
        bw_put(&w, 0, 8 - w.bits);
    free(head);
    free(prev);
    return w.n;
}

static int paeth(int a, int b, int c)
{
    int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/* each scanline with the PNG filter (None, Sub, Up, Paeth) whose output has
 * the smallest sum of |signed byte|, the usual heuristic */
static void filter_rows(unsigned char *raw, const unsigned char *rgb, int w, int h)
{
    size_t row = (size_t)w * 3, x;
    unsigned char *cand = malloc(4 * row);
    int y, f;
    for (y = 0; y < h; y++) {
        const unsigned char *cur = rgb + (size_t)y * row, *up = y ? cur - row : NULL;
        long best = -1;
        int bf = 0;
        for (f = 0; f < 4; f++) {
            unsigned char *c = cand + (size_t)f * row;
            long sum = 0;
            for (x = 0; x < row; x++) {
                int a = x >= 3 ? cur[x - 3] : 0, b = up ? up[x] : 0, cc = (x >= 3 && up) ? up[x - 3] : 0;
                int pred = f == 0 ? 0 : f == 1 ? a : f == 2 ? b : paeth(a, b, cc);
                c[x] = (unsigned char)(cur[x] - pred);
                sum += c[x] < 128 ? c[x] : 256 - c[x];
            }
            if (best < 0 || sum < best) {
                best = sum;
                bf = f;
            }
        }
        raw[(size_t)y * (row + 1)] = (unsigned char)(bf == 3 ? 4 : bf); /* Paeth is type 4 */
        memcpy(raw + (size_t)y * (row + 1) + 1, cand + (size_t)bf * row, row);
    }
    free(cand);
}

size_t png_encode(unsigned char **out, const unsigned char *rgb, int w, int h)
{
    size_t row = (size_t)w * 3 + 1, raw_n = row * (size_t)h;
    size_t zn, total, dn;
    unsigned char *raw, *z, *q, *buf;
    unsigned char ihdr[13];
    *out = NULL;
    if (w <= 0 || h <= 0)
        return 0;
    raw = malloc(raw_n);
    z = malloc(2 + raw_n + raw_n / 8 + 16 + 4);
    if (!raw || !z) {
        free(raw);
        free(z);
        return 0;
    }
    filter_rows(raw, rgb, w, h);
    /* zlib: CMF 0x78 (deflate, 32K window), FLG 0x01 so that
     * (CMF*256 + FLG) % 31 == 0, no dictionary */
    q = z;
    *q++ = 0x78;
    *q++ = 0x01;
    dn = deflate_fixed(q, raw, raw_n);
    if (!dn) {
        free(raw);
        free(z);
        return 0;
    }
    q = put32(q + dn, png_adler32(1, raw, raw_n));
    zn = (size_t)(q - z);
    total = 8 + (12 + 13) + (12 + zn) + 12;
    buf = malloc(total);
    if (!buf) {
        free(raw);
        free(z);
        return 0;
    }
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
