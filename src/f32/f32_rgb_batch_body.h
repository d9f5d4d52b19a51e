/* rgb_batch_body.h - a port's brdf_hammon RGB batch (one function per tier,
 * the member brdf_hammon_rgb of its facet_f32_port), included by
 * src/f32/f32_batch_body.h with the same BATCH_* macros plus BATCH_V (the vector
 * type).  Every layout goes through one loop: each stream has an element
 * stride (facet_rgb_io, src/core/port.h): 1 = planar arrays, 3 = interleaved
 * RGB, 0 = one uniform value (broadcast once, before the loop).  Whole
 * blocks of unit-stride streams are loaded straight from the arrays; other
 * strides and the tail (n % W) go through a stack copy (the tail padded
 * with 0.5, inside every domain).  All of a block's inputs are loaded
 * before its outputs are stored: an output may be the very same array (same
 * layout) as an input.  Each channel is the port's brdf_hammon_rgb, i.e.
 * equal to its brdf_hammon to the bit. */
#ifndef RGB_BATCH_HELPERS_
#define RGB_BATCH_HELPERS_
#define RGB_SET_ BATCH_CAT(facet_, BATCH_PORT, _set)

/* r valid elements of stream p (stride s) from element i */
static BATCH_V rgb_load_(const float *p, ptrdiff_t s, size_t i, size_t r)
{
    float t[BATCH_W];
    size_t j;
    if (s == 1 && r == BATCH_W)
        return BATCH_LOAD(p + i);
    for (j = 0; j < BATCH_W; j++)
        t[j] = j < r ? p[(ptrdiff_t)(i + j) * s] : BATCH_PAD;
    return BATCH_LOAD(t);
}

static void rgb_store_(float *p, ptrdiff_t s, size_t i, size_t r, BATCH_V v)
{
    float t[BATCH_W];
    size_t j;
    if (s == 1 && r == BATCH_W) {
        BATCH_STORE(p + i, v);
        return;
    }
    BATCH_STORE(t, v);
    for (j = 0; j < r; j++)
        p[(ptrdiff_t)(i + j) * s] = t[j];
}
#endif

static void BATCH_FN(brdf_hammon_rgb)(const facet_rgb_io *io, const float *nol, const float *nov,
                                      const float *lov, size_t count)
{
    BATCH_V u_a, u_f0[3], u_alb[3];
    size_t i, r;
    int c;
    if (count == 0)
        return;
    u_a = RGB_SET_(io->alpha[0]);
    for (c = 0; c < 3; c++) {
        u_f0[c] = RGB_SET_(io->f0[c][0]);
        u_alb[c] = RGB_SET_(io->albedo[c][0]);
    }
    for (i = 0; i < count; i += BATCH_W) {
        BATCH_V nl, nv, lv, a, f0[3], alb[3], o[3];
        r = count - i < BATCH_W ? count - i : BATCH_W;
        nl = rgb_load_(nol, 1, i, r);
        nv = rgb_load_(nov, 1, i, r);
        lv = rgb_load_(lov, 1, i, r);
        a = io->alpha_stride ? rgb_load_(io->alpha, io->alpha_stride, i, r) : u_a;
        for (c = 0; c < 3; c++) {
            f0[c] = io->material_stride ? rgb_load_(io->f0[c], io->material_stride, i, r) : u_f0[c];
            alb[c] = io->material_stride ? rgb_load_(io->albedo[c], io->material_stride, i, r) : u_alb[c];
        }
        BATCH_KERNEL(brdf_hammon_rgb)(&o[0], &o[1], &o[2], nl, nv, lv, a, f0[0], f0[1], f0[2], alb[0],
                                      alb[1], alb[2]);
        for (c = 0; c < 3; c++)
            rgb_store_(io->out[c], io->out_stride, i, r, o[c]);
    }
}
