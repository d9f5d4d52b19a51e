/* test_f16_estimates.c - the reciprocal and rsqrt of the f16 ports that
 * build them from bit-level seeds (facet/heliumfp16.h: MVE has no estimate
 * instruction), checked exhaustively against the errors their header
 * states, on the port's own ops:
 *   binary16 rcp    every binary16 x in [2^-14, 2^14] (1/x normal):
 *                   |r x - 1| (exact in double) <= HFP16_RCP
 *   binary16 rsqrt  every positive normal binary16 x: |y sqrt(x) - 1| <=
 *                   HFP16_RSQRT
 *   f32 rcp (FACET_W)   every float x in [1, 2): the seed's relative error
 *                   is the same in every binade (bits(2x) = bits(x) + 2^23,
 *                   the seed halves, the steps scale exactly), so this is
 *                   every normal x whose 1/x is normal; |1 - x r| by one
 *                   fused op (x r exact inside it, then one rounding of a
 *                   value below 2^-16: 2^-40 absolute) <= HFP16_W_RCP
 *   f32 rsqrt (FACET_W) every float x in [1, 4) (the seed halves the
 *                   exponent: a period of two binades): e = 1 - x y^2 with
 *                   y^2 rounded once (2^-24), the error of y
 *                   |e|/2 + e^2/2 + 2^-24 <= HFP16_W_RSQRT
 * The binary16 checks are exact; the f32 ones are upper bounds.  Under
 * other flags (no MVE floating point) there is no such port: skipped. */
#include <stdio.h>
#include <math.h>
#include "../lib/harness.h"

#if defined(__ARM_FEATURE_MVE) && (__ARM_FEATURE_MVE & 2)
#include "facet/heliumfp16.h"

/* the errors facet/heliumfp16.h states (measured here, rounded up) */
#define HFP16_RCP 5.54e-4
#define HFP16_RSQRT 5.84e-4
#define HFP16_W_RCP 6.6e-6   /* 0.0505^4 = 2^-17.2 */
#define HFP16_W_RSQRT 5.0e-6 /* 1.5 (1.5 0.0345^2)^2 = 2^-17.6 */

static void binary16(void)
{
    uint16_t xb[8], rb[8], yb[8];
    double m_rcp = 0.0, m_rsqrt = 0.0, a_rcp = 0.0, a_rsqrt = 0.0;
    unsigned b, j;
    for (b = 0x0400u; b < 0x7c00u; b += 8) {
        float16x8_t x;
        for (j = 0; j < 8; j++)
            xb[j] = (uint16_t)(b + j);
        x = facet_heliumfp16_load(xb);
        facet_heliumfp16_store(rb, facet_heliumfp16_h_rcp(x));
        facet_heliumfp16_store(yb, facet_heliumfp16_h_rsqrt(x));
        for (j = 0; j < 8; j++) {
            double xv = facet_f32_from_f16(xb[j]), e;
            if (xb[j] <= 0x7400u) { /* x <= 2^14 */
                e = fabs((double)facet_f32_from_f16(rb[j]) * xv - 1.0);
                if (e > m_rcp) {
                    m_rcp = e;
                    a_rcp = xv;
                }
            }
            e = fabs((double)facet_f32_from_f16(yb[j]) * sqrt(xv) - 1.0);
            if (e > m_rsqrt) {
                m_rsqrt = e;
                a_rsqrt = xv;
            }
        }
    }
    printf("binary16 rcp:   max rel. error %.4g (2^%.2f) at x = %.9g, over [2^-14, 2^14]\n", m_rcp, log2(m_rcp),
           a_rcp);
    printf("binary16 rsqrt: max rel. error %.4g (2^%.2f) at x = %.9g, over [2^-14, 65504]\n", m_rsqrt,
           log2(m_rsqrt), a_rsqrt);
    CHECK(m_rcp <= HFP16_RCP, "binary16 rcp: error %.4g above the stated %.4g", m_rcp, HFP16_RCP);
    CHECK(m_rsqrt <= HFP16_RSQRT, "binary16 rsqrt: error %.4g above the stated %.4g", m_rsqrt, HFP16_RSQRT);
    /* the checks can fail: an exact 1/x is not within 1e-9 everywhere */
    CHECK(m_rcp > 1e-9 && m_rsqrt > 1e-9, "the measure finds no error at all");
}

/* f32: max |1 - x r| over x = bits lo .. hi - 1, four lanes a vector */
static float w_rcp_max(uint32_t lo, uint32_t hi)
{
    float32x4_t one = vdupq_n_f32(1.0f), m = vdupq_n_f32(0.0f);
    uint32x4_t bits = vaddq_u32(vdupq_n_u32(lo), vidupq_n_u32(0, 1));
    float out[4];
    uint32_t i;
    for (i = lo; i < hi; i += 4) {
        facet_heliumfp16_w x, r;
        x.lo = x.hi = vreinterpretq_f32_u32(bits);
        r = facet_heliumfp16_h_w_rcp(x);
        m = vmaxnmq_f32(m, vabsq_f32(vfmsq_f32(one, x.lo, r.lo)));
        bits = vaddq_u32(bits, vdupq_n_u32(4));
    }
    vst1q_f32(out, m);
    return fmaxf(fmaxf(out[0], out[1]), fmaxf(out[2], out[3]));
}

/* f32: max |1 - x y^2| (y^2 rounded) over x = bits lo .. hi - 1 */
static float w_rsqrt_max(uint32_t lo, uint32_t hi)
{
    float32x4_t one = vdupq_n_f32(1.0f), m = vdupq_n_f32(0.0f);
    uint32x4_t bits = vaddq_u32(vdupq_n_u32(lo), vidupq_n_u32(0, 1));
    float out[4];
    uint32_t i;
    for (i = lo; i < hi; i += 4) {
        facet_heliumfp16_w x, y;
        x.lo = x.hi = vreinterpretq_f32_u32(bits);
        y = facet_heliumfp16_h_w_rsqrt(x);
        m = vmaxnmq_f32(m, vabsq_f32(vfmsq_f32(one, x.lo, vmulq_f32(y.lo, y.lo))));
        bits = vaddq_u32(bits, vdupq_n_u32(4));
    }
    vst1q_f32(out, m);
    return fmaxf(fmaxf(out[0], out[1]), fmaxf(out[2], out[3]));
}

static void f32_lanes(void)
{
    double r = w_rcp_max(0x3f800000u, 0x40000000u);
    double e = w_rsqrt_max(0x3f800000u, 0x40800000u);
    double s = e / 2 + e * e / 2 + 0x1p-24;
    printf("f32 rcp:   max rel. error %.4g (2^%.2f), every float in [1, 2)\n", r, log2(r));
    printf("f32 rsqrt: max rel. error <= %.4g (2^%.2f), every float in [1, 4)\n", s, log2(s));
    CHECK(r <= HFP16_W_RCP, "f32 rcp: error %.4g above the stated %.4g", r, HFP16_W_RCP);
    CHECK(s <= HFP16_W_RSQRT, "f32 rsqrt: error %.4g above the stated %.4g", s, HFP16_W_RSQRT);
    CHECK(r > 1e-9 && e > 1e-9, "the f32 measure finds no error at all");
}

int main(void)
{
    th_name = "test_f16_estimates";
    binary16();
    f32_lanes();
    return th_done();
}
#else
int main(void)
{
    th_name = "test_f16_estimates";
    SKIP("no f16 port with seeded estimates under this build's flags (heliumfp16: MVE floating point)");
    return th_done();
}
#endif
