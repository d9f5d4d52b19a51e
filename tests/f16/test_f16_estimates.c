/* test_f16_estimates.c - the reciprocal and rsqrt of the f16 ports that
 * refine them themselves, checked exhaustively against the errors their
 * header states, on the port's own ops.  rvvfp16 (facet/rvvfp16.h, built
 * for rv64gcv_zfh as test_f16_estimates_rvv: tests/ports/rvv.mk): vfrec7 /
 * vfrsqrt7 and one Newton step, every positive normal binary16 x (1/x:
 * those whose 1/x is normal) and every float of the estimate tables'
 * period, the raw estimates within 2^-7 and the refined ones within the
 * figures the header states, errors computed in double.
 * heliumfp16 (facet/heliumfp16.h: MVE has no estimate instruction: bit-level
 * seeds):
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
#elif defined(__riscv_vector) && defined(__riscv_zfh)
#include <string.h>
#include "facet/rvvfp16.h"

/* the errors facet/rvvfp16.h states (measured here, rounded up): the raw
 * estimates (the premise of one Newton step: at most 2^-7), and after the
 * step */
#define RVV_EST7 0x1p-7
#define RVVFP16_RCP 4.94e-4   /* 2^-10.99; the correctly rounded 1/x: 4.88e-4 */
#define RVVFP16_RSQRT 5.79e-4 /* 2^-10.76 */
#define RVVFP16_W_RCP 3.13e-5 /* 2^-14.97 */
#define RVVFP16_W_RSQRT 5.92e-5 /* 2^-14.05: below f16_body.h's 2^-14 budget */

typedef struct { double max, at; } rvv_err;
static void rvv_note(rvv_err *e, double err, double x)
{
    if (err > e->max) {
        e->max = err;
        e->at = x;
    }
}
static void rvv_print(const char *what, rvv_err e, const char *over)
{
    printf("%-24s max rel. error %.4g (2^%.2f) at x = %.9g, over %s\n", what, e.max, log2(e.max), e.at, over);
}

/* binary16: every x from bits lo to hi - 1, the raw estimates and the port's
 * rcp and rsqrt, each strip with its own vl (vsetvl: an explicit vtype) */
static void binary16(void)
{
    static uint16_t xb[0x7c00], r7[0x7c00], y7[0x7c00], rb[0x7c00], yb[0x7c00];
    rvv_err e_r7 = { 0, 0 }, e_y7 = { 0, 0 }, e_r = { 0, 0 }, e_y = { 0, 0 };
    size_t i, n = 0x7c00u - 0x0400u, vl;
    for (i = 0; i < n; i++)
        xb[i] = (uint16_t)(0x0400u + i); /* every positive normal, 2^-14 .. 65504 */
    for (i = 0; i < n; i += vl) {
        facet_rvvfp16_v x;
        vl = facet_rvvfp16_vl(n - i);
        x = facet_rvvfp16_load(xb + i, vl);
        facet_rvvfp16_store(r7 + i, vfrec7_v_f16m1(x, vl), vl);
        facet_rvvfp16_store(y7 + i, vfrsqrt7_v_f16m1(x, vl), vl);
        vl = facet_rvvfp16_vl(n - i);
        x = facet_rvvfp16_load(xb + i, vl);
        facet_rvvfp16_store(rb + i, facet_rvvfp16_h_rcp(x), vl);
        vl = facet_rvvfp16_vl(n - i);
        x = facet_rvvfp16_load(xb + i, vl);
        facet_rvvfp16_store(yb + i, facet_rvvfp16_h_rsqrt(x), vl);
    }
    for (i = 0; i < n; i++) {
        double x = facet_f32_from_f16(xb[i]), s = sqrt(x);
        if (xb[i] <= 0x7400u) { /* x <= 2^14: 1/x normal */
            rvv_note(&e_r7, fabs((double)facet_f32_from_f16(r7[i]) * x - 1.0), x);
            rvv_note(&e_r, fabs((double)facet_f32_from_f16(rb[i]) * x - 1.0), x);
        }
        rvv_note(&e_y7, fabs((double)facet_f32_from_f16(y7[i]) * s - 1.0), x);
        rvv_note(&e_y, fabs((double)facet_f32_from_f16(yb[i]) * s - 1.0), x);
    }
    rvv_print("binary16 vfrec7:", e_r7, "[2^-14, 2^14]");
    rvv_print("binary16 vfrsqrt7:", e_y7, "[2^-14, 65504]");
    rvv_print("binary16 rcp:", e_r, "[2^-14, 2^14]");
    rvv_print("binary16 rsqrt:", e_y, "[2^-14, 65504]");
    CHECK(e_r7.max <= RVV_EST7 && e_y7.max <= RVV_EST7, "binary16 estimates: %.4g, %.4g above 2^-7", e_r7.max,
          e_y7.max);
    CHECK(e_r.max <= RVVFP16_RCP, "binary16 rcp: error %.4g above the stated %.4g", e_r.max, RVVFP16_RCP);
    CHECK(e_y.max <= RVVFP16_RSQRT, "binary16 rsqrt: error %.4g above the stated %.4g", e_y.max, RVVFP16_RSQRT);
    CHECK(e_r.max > 1e-9 && e_y.max > 1e-9, "the binary16 measure finds no error at all");
}

/* f32 (FACET_W): every float from bits lo to hi - 1 (the tables' period:
 * vfrec7 reads the significand's top 7 bits, the exponent only to form the
 * result's, so [1, 2) is every normal x whose 1/x is normal; vfrsqrt7 the
 * exponent's parity and 6 bits: [1, 4)), errors in double (r x exact, y
 * sqrt(x) to 2^-52) */
static void f32_range(uint32_t lo, uint32_t hi, int rsqrt, rvv_err *raw, rvv_err *ref)
{
    enum { B = 1 << 16 };
    static float xs[B], r7[B], rr[B];
    uint32_t base, j;
    size_t i, n, vl;
    for (base = lo; base < hi; base += B) {
        n = hi - base < B ? hi - base : B;
        for (j = 0; j < n; j++) {
            uint32_t b = base + j;
            memcpy(&xs[j], &b, sizeof b);
        }
        for (i = 0; i < n; i += vl) {
            facet_rvvfp16_w x;
            vl = vsetvl_e32m2(n - i);
            x = vle32_v_f32m2(xs + i, vl);
            vse32_v_f32m2(r7 + i, rsqrt ? vfrsqrt7_v_f32m2(x, vl) : vfrec7_v_f32m2(x, vl), vl);
            vl = vsetvl_e32m2(n - i);
            x = vle32_v_f32m2(xs + i, vl);
            vse32_v_f32m2(rr + i, rsqrt ? facet_rvvfp16_h_w_rsqrt(x) : facet_rvvfp16_h_w_rcp(x), vl);
        }
        for (j = 0; j < n; j++) {
            double x = xs[j], m = rsqrt ? sqrt(x) : x;
            rvv_note(raw, fabs((double)r7[j] * m - 1.0), x);
            rvv_note(ref, fabs((double)rr[j] * m - 1.0), x);
        }
    }
}

static void f32_lanes(void)
{
    rvv_err r7 = { 0, 0 }, r = { 0, 0 }, y7 = { 0, 0 }, y = { 0, 0 };
    f32_range(0x3f800000u, 0x40000000u, 0, &r7, &r);
    f32_range(0x3f800000u, 0x40800000u, 1, &y7, &y);
    rvv_print("f32 vfrec7:", r7, "[1, 2)");
    rvv_print("f32 vfrsqrt7:", y7, "[1, 4)");
    rvv_print("f32 rcp:", r, "[1, 2)");
    rvv_print("f32 rsqrt:", y, "[1, 4)");
    CHECK(r7.max <= RVV_EST7 && y7.max <= RVV_EST7, "f32 estimates: %.4g, %.4g above 2^-7", r7.max, y7.max);
    CHECK(r.max <= RVVFP16_W_RCP, "f32 rcp: error %.4g above the stated %.4g", r.max, RVVFP16_W_RCP);
    CHECK(y.max <= RVVFP16_W_RSQRT, "f32 rsqrt: error %.4g above the stated %.4g", y.max, RVVFP16_W_RSQRT);
    CHECK(r.max > 1e-9 && y.max > 1e-9, "the f32 measure finds no error at all");
}

int main(void)
{
    th_name = "test_f16_estimates";
    printf("rvvfp16 at VLEN %u\n", (unsigned)(vsetvlmax_e8m1() * 8));
    binary16();
    f32_lanes();
    return th_done();
}
#else
int main(void)
{
    th_name = "test_f16_estimates";
    SKIP("no f16 port with its own estimates under this build's flags (heliumfp16: MVE floating point; rvvfp16: "
         "rv64gcv_zfh, the RVV build's test_f16_estimates_rvv)");
    return th_done();
}
#endif
