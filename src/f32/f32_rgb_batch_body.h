/* f32_rgb_batch_body.h - one tier of a port's brdf_hammon RGB batch (the
 * member brdf_hammon_rgb of its facet_f32_port), included by
 * src/f32/f32_batch_body.h with the port's hooks (src/f32/f32_port_body.h).
 * Every layout goes through one loop: each stream has an element stride
 * (facet_rgb_io, src/core/port.h): 1 = planar arrays, 3 = interleaved
 * RGB, 0 = one uniform value (broadcast once, before the loop).  Each block
 * of r <= BATCH_STEP elements is loaded and stored through the port's
 * strided loads and stores (BATCH_LOAD_S / BATCH_STORE_S: whole unit-stride
 * blocks straight from the arrays, the rest through a stack copy padded
 * with 0.5, or the port's own).  All of a block's inputs are loaded before
 * its outputs are stored: an output may be the very same array (same
 * layout) as an input.  Each channel is the port's brdf_hammon_rgb, i.e.
 * equal to its brdf_hammon to the bit. */
/* one material stream (f0 or albedo) of channel c: strided, or the value
 * broadcast before the loop (no arrays of vectors: RVV's are sizeless) */
#define BATCH_RGB_MAT_(m, c, u) \
    (io->material_stride ? BATCH_LOAD_S(io->m[c], io->material_stride, i, r) : (u))

static void BATCH_FN(brdf_hammon_rgb)(const facet_rgb_io *io, const float *nol, const float *nov,
                                      const float *lov, size_t count)
{
    const size_t w_ = BATCH_STEP;
    BATCH_V u_a, u_f0r, u_f0g, u_f0b, u_alr, u_alg, u_alb;
    size_t i, r;
    if (count == 0)
        return;
    u_a = BATCH_SET(io->alpha[0]);
    u_f0r = BATCH_SET(io->f0[0][0]);
    u_f0g = BATCH_SET(io->f0[1][0]);
    u_f0b = BATCH_SET(io->f0[2][0]);
    u_alr = BATCH_SET(io->albedo[0][0]);
    u_alg = BATCH_SET(io->albedo[1][0]);
    u_alb = BATCH_SET(io->albedo[2][0]);
    for (i = 0; i < count; i += w_) {
        BATCH_V nl, nv, lv, a, o_r, o_g, o_b;
        r = count - i < w_ ? count - i : w_;
        nl = BATCH_LOAD_S(nol, 1, i, r);
        nv = BATCH_LOAD_S(nov, 1, i, r);
        lv = BATCH_LOAD_S(lov, 1, i, r);
        a = io->alpha_stride ? BATCH_LOAD_S(io->alpha, io->alpha_stride, i, r) : u_a;
        BATCH_KERNEL(brdf_hammon_rgb)(&o_r, &o_g, &o_b, nl, nv, lv, a, BATCH_RGB_MAT_(f0, 0, u_f0r),
                                      BATCH_RGB_MAT_(f0, 1, u_f0g), BATCH_RGB_MAT_(f0, 2, u_f0b),
                                      BATCH_RGB_MAT_(albedo, 0, u_alr), BATCH_RGB_MAT_(albedo, 1, u_alg),
                                      BATCH_RGB_MAT_(albedo, 2, u_alb));
        BATCH_STORE_S(io->out[0], io->out_stride, i, r, o_r);
        BATCH_STORE_S(io->out[1], io->out_stride, i, r, o_g);
        BATCH_STORE_S(io->out[2], io->out_stride, i, r, o_b);
    }
}
#undef BATCH_RGB_MAT_
