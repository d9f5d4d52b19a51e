/* fw_main.c - a firmware image that shades with the fixed-point batch API
 * alone, built from `make fx-sources` the way src/fx/README.md's "Firmware builds"
 * says (arm-none-eabi-gcc -Os -ffunction-sections -fdata-sections,
 * -Wl,--gc-sections, newlib; tests/fx/fx.mk: fx-firmware).  It runs on
 * qemu-system-arm (each batch result must equal the scalar kernel's: exit
 * status 0), tests/suites/50-fx-targets.sh fails if the image holds any f32,
 * dispatcher, CPU-detection or oracle symbol, a libm function or a float
 * helper, and its size is the README's firmware figure.
 * FW_TIER: 0 the same image without any facet call (the size baseline),
 * 1 facet_brdf_hammon_fx_batch, 2 facet_brdf_hammon_fx_fast_batch, 9 the
 * batch and the double oracle (src/oracle/oracle.c, libm): an image the symbol
 * check must reject. */
#include <stdint.h>
#include <facet/fx.h>
#if FW_TIER == 9
#include <facet/oracle.h>
#endif

#ifndef FW_TIER
#define FW_TIER 1
#endif
#define N 64

static int32_t nol[N], nov[N], lov[N], alpha[N], f0[N], albedo[N];
static uint64_t out[N];

int main(void)
{
    uint32_t s = 12345u;
    int i, bad = 0;
    for (i = 0; i < N; i++) { /* any int32 is a valid input: the kernels clamp */
        s = s * 1664525u + 1013904223u;
        nol[i] = (int32_t)(s >> 17);
        nov[i] = (int32_t)((s >> 3) & 0x7fff);
        lov[i] = (int32_t)(s & 0xffff) - 32768;
        alpha[i] = (int32_t)((s >> 9) & 0x7fff) + 1;
        f0[i] = (int32_t)((s >> 11) & 0x1fff);
        albedo[i] = (int32_t)((s >> 13) & 0x7fff);
    }
#if FW_TIER == 1 || FW_TIER == 9
    facet_brdf_hammon_fx_batch(out, nol, nov, lov, alpha, f0, albedo, N);
    for (i = 0; i < N; i++)
        bad += out[i] != facet_brdf_hammon_fx(nol[i], nov[i], lov[i], alpha[i], f0[i], albedo[i]);
#if FW_TIER == 9
    bad += !(facet_oracle_lambert(nol[0] / 32768.0) >= 0);
#endif
#elif FW_TIER == 2
    facet_brdf_hammon_fx_fast_batch(out, nol, nov, lov, alpha, f0, albedo, N);
    for (i = 0; i < N; i++)
        bad += out[i] != facet_brdf_hammon_fx_fast(nol[i], nov[i], lov[i], alpha[i], f0[i], albedo[i]);
#else
    for (i = 0; i < N; i++)
        out[i] = (uint64_t)nol[i] * (uint64_t)albedo[i];
    bad = out[0] == 1;
#endif
    return bad != 0;
}
