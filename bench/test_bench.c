/* test_bench.c - the bench machinery works: the PNG encoder (known CRC-32
 * and Adler-32 values, and a round trip through a stored-block decoder that
 * checks every chunk CRC), and the rasterizer on a 64x64 frame, every
 * shading path against the oracle-shaded frame. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../tests/harness.h"
#include "png.h"
#include "raster.h"

static uint32_t get32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* decodes what png_encode writes (RGB8, stored deflate blocks); 0 on success */
static int decode(const unsigned char *b, size_t n, unsigned char *rgb, int w, int h)
{
    size_t off = 8, row = (size_t)w * 3 + 1;
    unsigned char *z = malloc(n), *raw = malloc(row * (size_t)h + 1);
    size_t zn = 0, rn = 0, q;
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
    for (q = 2; !rc;) {
        unsigned hdr = z[q], len = z[q + 1] | z[q + 2] << 8, nlen = z[q + 3] | z[q + 4] << 8;
        if ((hdr & 6) != 0 || (len ^ 0xffffu) != nlen || rn + len > row * (size_t)h) {
            rc = 5;
            break;
        }
        memcpy(raw + rn, z + q + 5, len);
        rn += len;
        q += 5 + len;
        if (hdr & 1)
            break;
    }
    if (!rc && (rn != row * (size_t)h || get32(z + q) != png_adler32(1, raw, rn)))
        rc = 6;
    for (y = 0; !rc && y < h; y++) {
        if (raw[(size_t)y * row] != 0)
            rc = 7;
        memcpy(rgb + (size_t)y * (size_t)w * 3, raw + (size_t)y * row + 1, (size_t)w * 3);
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
    for (i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        int w = sizes[i][0], h = sizes[i][1], rc;
        size_t np = (size_t)w * (size_t)h * 3, k, n;
        unsigned char *img = malloc(np), *back = malloc(np), *enc;
        char *b64;
        for (k = 0; k < np; k++)
            img[k] = (unsigned char)(k * 7 + k / 5);
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
        } else {                                                                           \
            SKIP("raster %s: not available here", name);                                   \
        }                                                                                  \
    } while (0)
    PATH("scalar", (rs_shade_scalar(g), 1));
    PATH("batch", (rs_shade_batch(g), 1));
    PATH("avx2", rs_shade_avx2(g));
    PATH("sse2", rs_shade_sse2(g));
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
