/* sample_peer.h - the textbook peers of the samplers, for the bench and the
 * report: the direct formulas in float with libm (atanf, sinf, cosf, sqrtf,
 * powf, acosf), as a renderer would write them from the papers, no care for
 * cancellation or bad input.  Not part of the library (it uses libm). */
#ifndef FACET_TEST_SAMPLE_PEER_H
#define FACET_TEST_SAMPLE_PEER_H

#include <math.h>

#define PEER_PI_ 3.14159265f

/* GGX D: theta = atan(alpha sqrt(u1 / (1 - u1))), phi = 2 pi u2 */
static inline void peer_ggx_sample_d(float h[3], float u1, float u2, float alpha)
{
    float t = atanf(alpha * sqrtf(u1 / (1.0f - u1))), p = 2.0f * PEER_PI_ * u2, s = sinf(t);
    h[0] = s * cosf(p);
    h[1] = s * sinf(p);
    h[2] = cosf(t);
}

/* D(h) N.H = alpha^2 N.H / (pi (N.H^2 (alpha^2 - 1) + 1)^2) */
static inline float peer_ggx_pdf_d(float noh, float alpha)
{
    float a2 = alpha * alpha, d = noh * noh * (a2 - 1.0f) + 1.0f;
    return a2 * noh / (PEER_PI_ * d * d);
}

/* Heitz 2018 as usually transcribed: stretch, basis, warped disk, lift, unstretch */
static inline void peer_ggx_sample_vndf(float h[3], float vx, float vy, float vz, float u1, float u2,
                                        float alpha)
{
    float Vx = alpha * vx, Vy = alpha * vy, Vz = vz, n = sqrtf(Vx * Vx + Vy * Vy + Vz * Vz), l2;
    float T1x, T1y, T1z, T2x, T2y, T2z, r, p, t1, t2, s, z, Nx, Ny, Nz;
    Vx /= n; Vy /= n; Vz /= n;
    l2 = Vx * Vx + Vy * Vy;
    if (l2 > 0) {
        float il = 1.0f / sqrtf(l2);
        T1x = -Vy * il; T1y = Vx * il; T1z = 0;
    } else {
        T1x = 1; T1y = 0; T1z = 0;
    }
    T2x = Vy * T1z - Vz * T1y;
    T2y = Vz * T1x - Vx * T1z;
    T2z = Vx * T1y - Vy * T1x;
    r = sqrtf(u1);
    p = 2.0f * PEER_PI_ * u2;
    t1 = r * cosf(p);
    t2 = r * sinf(p);
    s = 0.5f * (1.0f + Vz);
    t2 = (1.0f - s) * sqrtf(1.0f - t1 * t1) + s * t2;
    z = sqrtf(fmaxf(0.0f, 1.0f - t1 * t1 - t2 * t2));
    Nx = t1 * T1x + t2 * T2x + z * Vx;
    Ny = t1 * T1y + t2 * T2y + z * Vy;
    Nz = t1 * T1z + t2 * T2z + z * Vz;
    Nx *= alpha; Ny *= alpha; Nz = fmaxf(0.0f, Nz);
    n = sqrtf(Nx * Nx + Ny * Ny + Nz * Nz);
    h[0] = Nx / n; h[1] = Ny / n; h[2] = Nz / n;
}

/* G1(v) max(0, V.H) D / N.V with Lambda = (-1 + sqrt(1 + alpha^2 tan^2)) / 2 */
static inline float peer_ggx_pdf_vndf(float nov, float noh, float voh, float alpha)
{
    float a2 = alpha * alpha, t2 = (1.0f - nov * nov) / (nov * nov);
    float g1 = 2.0f / (1.0f + sqrtf(1.0f + a2 * t2));
    return g1 * fmaxf(0.0f, voh) * peer_ggx_pdf_d(noh, alpha) / (noh * nov);
}

/* GTR1: cos^2 theta = (1 - alpha^(2 (1 - u1))) / (1 - alpha^2) */
static inline void peer_gtr1_sample_d(float h[3], float u1, float u2, float alpha)
{
    float a2 = alpha * alpha, c = sqrtf((1.0f - powf(a2, 1.0f - u1)) / (1.0f - a2));
    float s = sqrtf(1.0f - c * c), p = 2.0f * PEER_PI_ * u2;
    h[0] = s * cosf(p);
    h[1] = s * sinf(p);
    h[2] = c;
}

#endif
