/* digest.c - one line per (path, kernel, tier, port): a 64-bit FNV-1a hash
 * of the output bits over a fixed input set.  Not a test: the instrument a
 * refactor is checked with ("no output bit changed").  Run it on the tree
 * before and after, on every target (host, qemu-user, the Cortex-M55 image),
 * and compare the two files byte for byte (tests/digest/digest.sh).
 *
 * Covered: every kernel of the table in both f32 tiers through the batch API
 * on every port this CPU runs and the per-sample call; the oracle; the RGB
 * batches (planar, interleaved, material, textured) and the RGB per-sample call and
 * the shade entry; every sampler (batch on every port, per sample, oracle);
 * every fixed-point kernel in both tiers (per sample, and the batch on every
 * port), and the fixed-point RGB forms.  Inputs: the tests' generators
 * (tests/lib/sample.h) plus special values (NaN, +-Inf, +-0, subnormals,
 * out-of-domain) in every position; fixed point: domain, edges and every
 * int32 pattern class. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#include <math.h>
#include "facet.h"
#include "facet/fx.h"
#include "../lib/sample.h"
#include "../lib/sample_common.h"

#define N 6144

static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    size_t i;
    for (i = 0; i < n; i++) {
        h ^= b[i];
        h *= 0x100000001b3ull;
    }
    return h;
}
#define H0 0xcbf29ce484222325ull

static const float specials[] = {
    NAN, -NAN, INFINITY, -INFINITY, 0.0f, -0.0f, 1e-45f, -1e-45f, 1.17549435e-38f, 1.0f, -1.0f,
    2.0f, 0.5f, 1e30f, -1e30f, 3.9e-3f, 9.765625e-4f, 1e-7f, 0.99999994f, 1.00000012f,
};
#define N_SPECIALS (sizeof specials / sizeof specials[0])

static float in_[10][N]; /* the most inputs: the RGB form, 4 + 3 + 3 */
static float out_[3][N];
static double dout_[3][N];

static void special_mix(smp_rng *r, int n_in, int j)
{
    int i;
    if (j < N - 1536)
        return;
    for (i = 0; i < n_in; i++)
        if (smp_next(r) % 3 == 0)
            in_[i][j] = specials[smp_next(r) % N_SPECIALS];
}

static int n_ports;
static const char *port_name[16];

static void ports_init(void)
{
    size_t i;
    for (i = 0; i < facet_port_count(); i++) {
        int sup;
        const char *nm = facet_port_at(i, &sup, NULL);
        if (sup && n_ports < 16)
            port_name[n_ports++] = nm;
    }
}

static void kernels(void)
{
    size_t ki;
    for (ki = 0; ki < facet_kernel_count(); ki++) {
        const facet_kernel *k = facet_kernel_at(ki);
        smp_rng r = { 1000 + ki };
        const float *ins[FACET_MAX_INPUTS];
        uint64_t h;
        int i, j, p, tier;
        for (j = 0; j < N; j++) {
            float x[FACET_MAX_INPUTS];
            smp_inputs(&r, k, x);
            for (i = 0; i < k->n_inputs; i++)
                in_[i][j] = x[i];
            special_mix(&r, k->n_inputs, j);
        }
        for (i = 0; i < k->n_inputs; i++)
            ins[i] = in_[i];
        for (tier = 0; tier < 2; tier++) {
            h = H0;
            for (j = 0; j < N; j++) {
                float x[FACET_MAX_INPUTS], y;
                for (i = 0; i < k->n_inputs; i++)
                    x[i] = in_[i][j];
                y = (tier ? k->f32_fast : k->f32)(x);
                h = fnv(h, &y, sizeof y);
            }
            printf("f32-call %s %s %016llx\n", k->name, tier ? "f32_fast" : "f32", (unsigned long long)h);
            for (p = 0; p < n_ports; p++) {
                facet_set_port(port_name[p]);
                (tier ? k->f32_fast_batch : k->f32_batch)(out_[0], ins, N);
                h = fnv(H0, out_[0], N * sizeof(float));
                printf("f32-batch %s %s %s %016llx\n", k->name, tier ? "f32_fast" : "f32", port_name[p],
                       (unsigned long long)h);
            }
        }
        h = H0;
        for (j = 0; j < N; j++) {
            double x[FACET_MAX_INPUTS], y;
            for (i = 0; i < k->n_inputs; i++)
                x[i] = in_[i][j];
            y = k->oracle(x);
            h = fnv(h, &y, sizeof y);
        }
        printf("oracle %s %016llx\n", k->name, (unsigned long long)h);
    }
}

static void rgb(void)
{
    smp_rng r = { 4242 };
    const facet_kernel *k = facet_kernel_find("brdf_hammon");
    static float il[3 * N], f0i[3 * N], albi[3 * N], oil[3 * N];
    const float *f0[3], *alb[3];
    float *o[3];
    facet_material_f32 m = { 0.3f, { 0.04f, 0.5f, 0.9f }, { 0.8f, 0.2f, 0.05f } };
    int i, j, p, tier, c;
    /* nol nov lov alpha f0 x3 albedo x3 in in_[0..9] */
    for (j = 0; j < N; j++) {
        float x[FACET_MAX_INPUTS];
        smp_inputs(&r, k, x);
        for (i = 0; i < 4; i++)
            in_[i][j] = x[i];
        for (c = 0; c < 3; c++) {
            in_[4 + c][j] = smp_unit(&r);
            in_[7 + c][j] = smp_unit(&r);
        }
        special_mix(&r, 10, j);
        for (c = 0; c < 3; c++) {
            f0i[3 * j + c] = in_[4 + c][j];
            albi[3 * j + c] = in_[7 + c][j];
        }
    }
    for (c = 0; c < 3; c++) {
        f0[c] = in_[4 + c];
        alb[c] = in_[7 + c];
        o[c] = out_[c];
    }
    for (tier = 0; tier < 2; tier++) {
        const char *tn = tier ? "f32_fast" : "f32";
        uint64_t h = H0;
        for (j = 0; j < N; j++) {
            float y[3], f[3], a[3];
            facet_dirs_f32 d;
            for (c = 0; c < 3; c++) {
                f[c] = in_[4 + c][j];
                a[c] = in_[7 + c][j];
            }
            (tier ? facet_brdf_hammon_rgb_f32_fast : facet_brdf_hammon_rgb_f32)(y, in_[0][j], in_[1][j],
                                                                               in_[2][j], in_[3][j], f, a);
            h = fnv(h, y, sizeof y);
            /* a direction triple from the dots' values (any finite vectors do) */
            d.n.x = 0, d.n.y = 0, d.n.z = 1;
            d.l.x = in_[4][j], d.l.y = in_[5][j], d.l.z = in_[0][j];
            d.v.x = in_[7][j], d.v.y = in_[8][j], d.v.z = in_[1][j];
            (tier ? facet_shade_hammon_rgb_f32_fast : facet_shade_hammon_rgb_f32)(y, &d, &m);
            h = fnv(h, y, sizeof y);
        }
        printf("rgb-call brdf_hammon_rgb %s %016llx\n", tn, (unsigned long long)h);
        for (p = 0; p < n_ports; p++) {
            facet_set_port(port_name[p]);
            h = H0;
            (tier ? facet_brdf_hammon_rgb_f32_fast_batch : facet_brdf_hammon_rgb_f32_batch)(
                o, in_[0], in_[1], in_[2], in_[3], f0, alb, N);
            for (c = 0; c < 3; c++)
                h = fnv(h, out_[c], N * sizeof(float));
            (tier ? facet_brdf_hammon_rgb_f32_fast_batch_interleaved : facet_brdf_hammon_rgb_f32_batch_interleaved)(
                oil, in_[0], in_[1], in_[2], in_[3], f0i, albi, N);
            h = fnv(h, oil, sizeof oil);
            (tier ? facet_brdf_hammon_rgb_f32_fast_batch_material : facet_brdf_hammon_rgb_f32_batch_material)(
                o, in_[0], in_[1], in_[2], &m, N);
            for (c = 0; c < 3; c++)
                h = fnv(h, out_[c], N * sizeof(float));
            (tier ? facet_brdf_hammon_rgb_f32_fast_batch_material_interleaved
                  : facet_brdf_hammon_rgb_f32_batch_material_interleaved)(oil, in_[0], in_[1], in_[2], &m, N);
            h = fnv(h, oil, sizeof oil);
            printf("rgb-batch brdf_hammon_rgb %s %s %016llx\n", tn, port_name[p], (unsigned long long)h);
            /* the textured forms (their own line: the lines above predate them) */
            h = H0;
            (tier ? facet_brdf_hammon_rgb_f32_fast_batch_textured : facet_brdf_hammon_rgb_f32_batch_textured)(
                o, in_[0], in_[1], in_[2], &m, alb, N);
            for (c = 0; c < 3; c++)
                h = fnv(h, out_[c], N * sizeof(float));
            (tier ? facet_brdf_hammon_rgb_f32_fast_batch_textured_rough : facet_brdf_hammon_rgb_f32_batch_textured_rough)(
                o, in_[0], in_[1], in_[2], in_[3], &m, alb, N);
            for (c = 0; c < 3; c++)
                h = fnv(h, out_[c], N * sizeof(float));
            printf("rgb-textured brdf_hammon_rgb %s %s %016llx\n", tn, port_name[p], (unsigned long long)h);
        }
    }
    (void)il;
}

static void samplers(void)
{
    size_t si;
    for (si = 0; si < facet_sampler_count(); si++) {
        const facet_sampler *s = facet_sampler_at(si);
        smp_rng r = { 77 + si };
        const float *ins[FACET_SAMPLER_MAX_INPUTS];
        float *outs[3] = { out_[0], out_[1], out_[2] };
        uint64_t h;
        int i, j, o, p, tier;
        for (j = 0; j < N; j++) {
            float x[FACET_SAMPLER_MAX_INPUTS];
            ss_inputs(&r, s, x);
            for (i = 0; i < s->n_inputs; i++)
                in_[i][j] = x[i];
            special_mix(&r, s->n_inputs, j);
        }
        for (i = 0; i < s->n_inputs; i++)
            ins[i] = in_[i];
        for (tier = 0; tier < 2; tier++) {
            const char *tn = tier ? "f32_fast" : "f32";
            h = H0;
            for (j = 0; j < N; j++) {
                float x[FACET_SAMPLER_MAX_INPUTS], y[3];
                for (i = 0; i < s->n_inputs; i++)
                    x[i] = in_[i][j];
                (tier ? s->f32_fast : s->f32)(y, x);
                h = fnv(h, y, (size_t)s->n_outputs * sizeof(float));
            }
            printf("sample-call %s %s %016llx\n", s->name, tn, (unsigned long long)h);
            for (p = 0; p < n_ports; p++) {
                facet_set_port(port_name[p]);
                (tier ? s->f32_fast_batch : s->f32_batch)(outs, ins, N);
                h = H0;
                for (o = 0; o < s->n_outputs; o++)
                    h = fnv(h, out_[o], N * sizeof(float));
                printf("sample-batch %s %s %s %016llx\n", s->name, tn, port_name[p], (unsigned long long)h);
            }
        }
        h = H0;
        for (j = 0; j < N; j++) {
            double x[FACET_SAMPLER_MAX_INPUTS], y[3];
            for (i = 0; i < s->n_inputs; i++)
                x[i] = in_[i][j];
            s->oracle(y, x);
            h = fnv(h, y, (size_t)s->n_outputs * sizeof(double));
        }
        printf("sample-oracle %s %016llx\n", s->name, (unsigned long long)h);
    }
    (void)dout_;
}

static int32_t fx_in_[FACET_FX_MAX_INPUTS][N];
static uint64_t fx_out64_[N];

static int32_t fx_pick(smp_rng *r, const facet_fx_kernel *k, int i)
{
    int32_t lo = k->lo[i], hi = k->hi[i];
    switch (smp_next(r) % 8) {
    case 0: /* any int32 pattern */
        return (int32_t)(uint32_t)smp_next(r);
    case 1: /* the edges */
        switch (smp_next(r) % 6) {
        case 0: return lo;
        case 1: return hi;
        case 2: return lo - 1;
        case 3: return hi + 1;
        case 4: return INT32_MIN;
        default: return INT32_MAX;
        }
    case 2: /* near the low end */
        return lo + (int32_t)(smp_next(r) % 64);
    case 3: /* near the high end */
        return hi - (int32_t)(smp_next(r) % 64);
    default:
        return lo + (int32_t)(smp_next(r) % (uint64_t)((int64_t)hi - lo + 1));
    }
}

static void fixed(void)
{
    size_t ki;
    int p;
    for (ki = 0; ki < facet_fx_kernel_count(); ki++) {
        const facet_fx_kernel *k = facet_fx_kernel_at(ki);
        smp_rng r = { 9000 + ki };
        const int32_t *ins[FACET_FX_MAX_INPUTS];
        int i, j, tier;
        for (j = 0; j < N; j++)
            for (i = 0; i < k->n_inputs; i++)
                fx_in_[i][j] = fx_pick(&r, k, i);
        for (i = 0; i < k->n_inputs; i++)
            ins[i] = fx_in_[i];
        for (tier = 0; tier < 2; tier++) {
            uint64_t (*f)(const int32_t *) = tier ? k->fx_fast : k->fx;
            void (*b)(void *, const int32_t *const *, size_t) = tier ? k->fx_fast_batch : k->fx_batch;
            const char *tn = tier ? "fx_fast" : "fx";
            uint64_t h = H0;
            if (!f)
                continue;
            for (j = 0; j < N; j++) {
                int32_t x[FACET_FX_MAX_INPUTS];
                uint64_t y;
                for (i = 0; i < k->n_inputs; i++)
                    x[i] = fx_in_[i][j];
                y = f(x);
                h = fnv(h, &y, sizeof y);
            }
            printf("fx-call %s %s %016llx\n", k->name, tn, (unsigned long long)h);
            for (p = 0; p < n_ports; p++) {
                facet_set_port(port_name[p]);
                memset(fx_out64_, 0, sizeof fx_out64_);
                b(fx_out64_, ins, N);
                h = fnv(H0, fx_out64_, (size_t)N * (size_t)k->out_bits / 8);
                printf("fx-batch %s %s %s %016llx\n", k->name, tn, port_name[p], (unsigned long long)h);
            }
        }
    }
    /* the RGB forms */
    {
        const facet_fx_kernel *k = facet_fx_kernel_find("brdf_hammon");
        smp_rng r = { 31337 };
        static int32_t f0[3][N], alb[3][N], f0i[3 * N], albi[3 * N];
        static uint64_t o[3][N], oi[3 * N];
        const int32_t *f[3] = { f0[0], f0[1], f0[2] }, *a[3] = { alb[0], alb[1], alb[2] };
        uint64_t *op[3] = { o[0], o[1], o[2] };
        int i, j, c, tier;
        for (j = 0; j < N; j++) {
            for (i = 0; i < 4; i++)
                fx_in_[i][j] = fx_pick(&r, k, i);
            for (c = 0; c < 3; c++) {
                f0[c][j] = f0i[3 * j + c] = fx_pick(&r, k, 4);
                alb[c][j] = albi[3 * j + c] = fx_pick(&r, k, 5);
            }
        }
        for (tier = 0; tier < 2; tier++) {
            uint64_t h = H0;
            for (j = 0; j < N; j++) {
                int32_t ff[3], aa[3];
                uint64_t y[3];
                for (c = 0; c < 3; c++) {
                    ff[c] = f0[c][j];
                    aa[c] = alb[c][j];
                }
                (tier ? facet_brdf_hammon_rgb_fx_fast : facet_brdf_hammon_rgb_fx)(y, fx_in_[0][j], fx_in_[1][j],
                                                                                fx_in_[2][j], fx_in_[3][j], ff, aa);
                h = fnv(h, y, sizeof y);
            }
            (tier ? facet_brdf_hammon_rgb_fx_fast_batch : facet_brdf_hammon_rgb_fx_batch)(
                op, fx_in_[0], fx_in_[1], fx_in_[2], fx_in_[3], f, a, N);
            h = fnv(h, o, sizeof o);
            (tier ? facet_brdf_hammon_rgb_fx_fast_batch_interleaved : facet_brdf_hammon_rgb_fx_batch_interleaved)(
                oi, fx_in_[0], fx_in_[1], fx_in_[2], fx_in_[3], f0i, albi, N);
            h = fnv(h, oi, sizeof oi);
            printf("fx-rgb brdf_hammon_rgb %s %016llx\n", tier ? "fx_fast" : "fx", (unsigned long long)h);
        }
    }
}

int main(void)
{
    ports_init();
    kernels();
    rgb();
    samplers();
    fixed();
    facet_set_port("auto");
    return 0;
}
