/* test_bench.c - the bench machinery works: the PNG encoder (known CRC-32
 * and Adler-32 values, and a round trip through our own small inflate and
 * unfilter that checks every chunk CRC and the Adler-32, on noise, a
 * gradient and a rendered frame, plus compression on the frame), and the rasterizer on a 64x64 frame, every
 * shading path against the oracle-shaded frame. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tests/lib/harness.h"
#include "report/png.h"
#include "raster/raster.h"

static uint32_t get32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* ---- a small inflate (stored and fixed-Huffman blocks: what png_encode
 * writes; dynamic blocks are rejected) and the PNG unfilter --------------- */

typedef struct br { const unsigned char *p; size_t n, pos; int bit; } br;

static int br_bit(br *r)
{
    int v;
    if (r->pos >= r->n)
        return -1;
    v = (r->p[r->pos] >> r->bit) & 1;
    if (++r->bit == 8) {
        r->bit = 0;
        r->pos++;
    }
    return v;
}

static long br_bits(br *r, int n) /* n bits, LSB first */
{
    long v = 0;
    int i, b;
    for (i = 0; i < n; i++) {
        if ((b = br_bit(r)) < 0)
            return -1;
        v |= (long)b << i;
    }
    return v;
}

/* a fixed-code literal/length symbol (codes MSB first) */
static int fixed_litlen(br *r)
{
    int code = 0, len, b;
    for (len = 1; len <= 9; len++) {
        if ((b = br_bit(r)) < 0)
            return -1;
        code = code << 1 | b;
        if (len == 7 && code <= 0x17)
            return 256 + code;
        if (len == 8 && code >= 0x30 && code <= 0xbf)
            return code - 0x30;
        if (len == 8 && code >= 0xc0 && code <= 0xc7)
            return 280 + code - 0xc0;
        if (len == 9 && code >= 0x190)
            return 144 + code - 0x190;
    }
    return -1;
}

static const unsigned short t_lbase[29] = { 3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31,
                                            35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258 };
static const unsigned char t_lext[29] = { 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2,
                                          3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0 };
static const unsigned short t_dbase[30] = { 1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193,
                                            257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145,
                                            8193, 12289, 16385, 24577 };
static const unsigned char t_dext[30] = { 0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6,
                                          7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13 };

/* inflates z (after the 2-byte zlib header) into out (cap bytes); returns
 * the output size, -1 on a malformed or over-long stream; *end: the byte
 * after the last block */
static long inflate_simple(const unsigned char *z, size_t zn, unsigned char *out, size_t cap, size_t *end)
{
    br r;
    size_t o = 0;
    long final = 0;
    r.p = z;
    r.n = zn;
    r.pos = 0;
    r.bit = 0;
    while (!final) {
        long type;
        final = br_bits(&r, 1);
        type = br_bits(&r, 2);
        if (final < 0 || type < 0)
            return -1;
        if (type == 0) {
            unsigned len, nlen;
            if (r.bit) {
                r.bit = 0;
                r.pos++;
            }
            if (r.pos + 4 > zn)
                return -1;
            len = z[r.pos] | z[r.pos + 1] << 8;
            nlen = z[r.pos + 2] | z[r.pos + 3] << 8;
            r.pos += 4;
            if ((len ^ 0xffffu) != nlen || r.pos + len > zn || o + len > cap)
                return -1;
            memcpy(out + o, z + r.pos, len);
            o += len;
            r.pos += len;
        } else if (type == 1) {
            for (;;) {
                int sym = fixed_litlen(&r);
                long len, dsym, dist;
                if (sym < 0)
                    return -1;
                if (sym < 256) {
                    if (o >= cap)
                        return -1;
                    out[o++] = (unsigned char)sym;
                    continue;
                }
                if (sym == 256)
                    break;
                if (sym > 285)
                    return -1;
                len = br_bits(&r, t_lext[sym - 257]);
                dsym = br_bits(&r, 5); /* fixed distance codes: 5 bits, MSB first */
                if (len < 0 || dsym < 0)
                    return -1;
                dsym = ((dsym & 1) << 4) | ((dsym & 2) << 2) | (dsym & 4) | ((dsym & 8) >> 2) | ((dsym & 16) >> 4);
                if (dsym > 29)
                    return -1;
                len += t_lbase[sym - 257];
                dist = br_bits(&r, t_dext[dsym]);
                if (dist < 0)
                    return -1;
                dist += t_dbase[dsym];
                if ((size_t)dist > o || o + (size_t)len > cap)
                    return -1;
                for (; len > 0; len--, o++)
                    out[o] = out[o - (size_t)dist];
            }
        } else {
            return -1;
        }
    }
    *end = r.pos + (r.bit != 0);
    return (long)o;
}

static int t_paeth(int a, int b, int c)
{
    int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/* decodes what png_encode writes (RGB8, filters 0-4, stored or fixed-code
 * deflate blocks), checking every chunk CRC and the Adler-32; 0 on success */
static int decode(const unsigned char *b, size_t n, unsigned char *rgb, int w, int h)
{
    size_t off = 8, row = (size_t)w * 3 + 1, end = 0;
    unsigned char *z = malloc(n), *raw = malloc(row * (size_t)h + 1);
    size_t zn = 0, x;
    long rn;
    int y, seen_end = 0, rc = 0;
    if (memcmp(b, "\x89PNG\r\n\x1a\n", 8))
        rc = 1;
    while (!rc && off + 12 <= n) {
        uint32_t len = get32(b + off);
        const unsigned char *type = b + off + 4, *data = b + off + 8;
        if (off + 12 + len > n || png_crc32(0, type, len + 4) != get32(data + len)) {
            rc = 2;
            break;
        }
        if (!memcmp(type, "IHDR", 4) && (get32(data) != (uint32_t)w || get32(data + 4) != (uint32_t)h || data[8] != 8 || data[9] != 2))
            rc = 3;
        if (!memcmp(type, "IDAT", 4)) {
            memcpy(z + zn, data, len);
            zn += len;
        }
        if (!memcmp(type, "IEND", 4))
            seen_end = 1;
        off += 12 + len;
    }
    if (!rc && (!seen_end || zn < 6 || ((z[0] << 8) | z[1]) % 31 || (z[0] & 15) != 8))
        rc = 4;
    if (!rc) {
        rn = inflate_simple(z + 2, zn - 2, raw, row * (size_t)h, &end);
        if (rn != (long)(row * (size_t)h))
            rc = 5;
        else if (2 + end + 4 > zn || get32(z + 2 + end) != png_adler32(1, raw, (size_t)rn))
            rc = 6;
    }
    for (y = 0; !rc && y < h; y++) {
        unsigned char *cur = raw + (size_t)y * row + 1, *up = y ? cur - row : NULL;
        int f = raw[(size_t)y * row];
        if (f > 4)
            rc = 7;
        for (x = 0; !rc && x < row - 1; x++) {
            int a = x >= 3 ? cur[x - 3] : 0, bb = up ? up[x] : 0, c = (x >= 3 && up) ? up[x - 3] : 0;
            int pred = f == 0 ? 0 : f == 1 ? a : f == 2 ? bb : f == 3 ? (a + bb) / 2 : t_paeth(a, bb, c);
            cur[x] = (unsigned char)(cur[x] + pred);
        }
        memcpy(rgb + (size_t)y * (size_t)w * 3, cur, (size_t)w * 3);
    }
    free(z);
    free(raw);
    return rc;
}

static void test_png(void)
{
    static const int sizes[][2] = { { 1, 1 }, { 7, 3 }, { 64, 64 }, { 300, 80 } }; /* last > 64 KiB */
    unsigned i;
    CHECK(png_crc32(0, (const unsigned char *)"123456789", 9) == 0xcbf43926u, "crc32 check value");
    CHECK(png_adler32(1, (const unsigned char *)"Wikipedia", 9) == 0x11e60398u, "adler32 check value");
    for (i = 0; i < 2 * sizeof sizes / sizeof sizes[0]; i++) {
        int w = sizes[i / 2][0], h = sizes[i / 2][1], rc;
        uint32_t lcg = 12345;
        size_t np = (size_t)w * (size_t)h * 3, k, n;
        unsigned char *img = malloc(np), *back = malloc(np), *enc;
        char *b64;
        for (k = 0; k < np; k++) /* a pattern, or noise (no matches) */
            img[k] = (unsigned char)(i % 2 ? (lcg = lcg * 1664525u + 1013904223u) >> 24 : k * 7 + k / 5);
        n = png_encode(&enc, img, w, h);
        CHECK(n > 0, "png_encode %dx%d", w, h);
        rc = n ? decode(enc, n, back, w, h) : -1;
        CHECK(rc == 0, "png round trip %dx%d: decoder error %d", w, h, rc);
        CHECK(rc != 0 || !memcmp(img, back, np), "png round trip %dx%d: pixels differ", w, h);
        b64 = png_base64(enc, n);
        CHECK(b64 && strlen(b64) == (n + 2) / 3 * 4 && !strncmp(b64, "iVBORw0KGgo", 11),
              "base64 of %dx%d", w, h);
        free(b64);
        free(enc);
        free(img);
        free(back);
    }
}

/* SIMD paths exist only for their own architecture; elsewhere they are not
 * skipped checks, they are not checks at all */
static int applies(const char *path)
{
#if defined(__x86_64__) || defined(__i386__)
    return strcmp(path, "neon") != 0;
#elif defined(__aarch64__) || defined(__arm__)
    return strcmp(path, "avx2") != 0 && strcmp(path, "sse2") != 0;
#else
    return strcmp(path, "neon") && strcmp(path, "avx2") && strcmp(path, "sse2");
#endif
}

static void test_raster(void)
{
    rs_gbuf *g = rs_render(64, 64);
    size_t np = 64 * 64 * 3;
    unsigned char *ref = malloc(np), *img = malloc(np);
    int maxd;
    double meand;
    CHECK(g->n > 64 * 64 / 4 && g->n < 64 * 64, "rasterizer covered %d of 4096 pixels", g->n);
    CHECK(g->triangles > 500, "rasterizer drew %ld front-facing triangles", g->triangles);
    rs_shade_oracle(g);
    rs_to_srgb(g, ref);
    {
        unsigned char *enc;
        size_t n = png_encode(&enc, ref, 64, 64);
        int rc = n ? decode(enc, n, img, 64, 64) : -1;
        CHECK(rc == 0 && !memcmp(ref, img, np), "png round trip of the rendered frame (rc %d)", rc);
        CHECK(n < np / 3, "png compresses the rendered frame: %zu bytes for %zu raw", n, np);
        free(enc);
    }

#define PATH(name, call) PATH_TOL(name, call, 1)
    /* fx: the dots are rounded to Q15 first, which moves the sharp highlights of
     * small alpha by a code value or two (bench/raster.c) */
#define PATH_TOL(name, call, tol)                                                          \
    do {                                                                                   \
        memset(img, 0, np);                                                                \
        if (call) {                                                                        \
            rs_to_srgb(g, img);                                                            \
            rs_diff(g, ref, img, &maxd, &meand);                                           \
            CHECK(maxd <= (tol) && meand < 0.01, "raster %s vs oracle: max %d, mean %.4f", \
                  name, maxd, meand);                                                      \
        } else if (applies(name)) {                                                        \
            SKIP("raster %s: this CPU cannot run it", name);                               \
        }                                                                                  \
    } while (0)
    PATH("scalar", (rs_shade_scalar(g), 1));
    PATH("batch", (rs_shade_batch(g), 1));
    PATH("rgb", (rs_shade_rgb(g), 1));
    PATH("material", (rs_shade_material(g), 1));
    PATH("pixel", (rs_shade_pixel(g), 1));
    PATH("avx2", rs_shade_avx2(g));
    PATH("sse2", rs_shade_sse2(g));
    PATH("neon", rs_shade_neon(g));
    PATH_TOL("fx", rs_shade_fx(g), 4);
    free(ref);
    free(img);
    rs_free(g);
}

int main(void)
{
    th_name = "bench";
    test_png();
    test_raster();
    return th_done();
}
