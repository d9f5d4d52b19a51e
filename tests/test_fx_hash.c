/* test_fx_hash.c - pinned output hashes of every fixed-point kernel over
 * fixed input grids.  Integer only and libc-light (printf), so the same
 * file runs on the host (make check), under qemu-user (aarch64, armv7) and
 * bare-metal on Cortex-M0/M4 (tests/fx.mk): every target must print the
 * same hashes, the ones pinned here.
 * The grids and pinned values are in tests/fx_hash.h (shared with
 * tests/test_fx_ports.c, which hashes the batch API on every port). */
#include <stdio.h>
#include <string.h>
#include "harness.h"
#include "facet/fx.h"
#define FXH_FAST
#include "fx_hash.h"

typedef uint64_t (*fxh_fn)(const int32_t *in);
struct hctx { const facet_fx_kernel *k; fxh_fn fast; uint64_t h; };
static void visit(const int32_t *in, void *ctx)
{
    struct hctx *c = (struct hctx *)ctx;
    fxh_feed(&c->h, c->fast ? c->fast(in) : c->k->fx(in), c->k->out_bits / 8);
}

static uint64_t kernel_hash(const facet_fx_kernel *k, fxh_fn fast)
{
    struct hctx c;
    c.k = k;
    c.fast = fast;
    c.h = FXH_INIT;
    fxh_walk(k, visit, &c);
    return c.h;
}

/* the fast tier, by name (same order as fxh_pinned_fast) */
#define F1(k) static uint64_t f_##k(const int32_t *x) { return (uint32_t)facet_##k##_fx_fast(x[0]); }
#define F2(k) static uint64_t f_##k(const int32_t *x) { return (uint32_t)facet_##k##_fx_fast(x[0], x[1]); }
#define F3(k) static uint64_t f_##k(const int32_t *x) { return (uint32_t)facet_##k##_fx_fast(x[0], x[1], x[2]); }
F3(noh_from_dots) F1(loh_from_dots) F2(fresnel_schlick) F2(ggx_d) F2(smith_g1) F3(smith_g2)
F3(smith_g2_uncorrelated) F3(smith_vis) F2(smith_g1_hammon) F3(smith_g2_hammon) F3(smith_vis_hammon)
static uint64_t f_diffuse_hammon(const int32_t *x) { return facet_diffuse_hammon_fx_fast(x[0], x[1], x[2], x[3], x[4]); }
static uint64_t f_brdf_hammon(const int32_t *x) { return facet_brdf_hammon_fx_fast(x[0], x[1], x[2], x[3], x[4], x[5]); }
static const fxh_fn fast_fns[] = {
    f_noh_from_dots, f_loh_from_dots, f_fresnel_schlick, f_ggx_d, f_smith_g1, f_smith_g2,
    f_smith_g2_uncorrelated, f_smith_vis, f_smith_g1_hammon, f_smith_g2_hammon, f_smith_vis_hammon,
    f_diffuse_hammon, f_brdf_hammon,
};

static void check_one(const char *tier, const char *name, fxh_fn fast, uint64_t pinned)
{
    const facet_fx_kernel *k = facet_fx_kernel_find(name);
    uint64_t h;
    if (!k) {
        CHECK(0, "%s: not in the fx table", name);
        return;
    }
    h = kernel_hash(k, fast);
    printf("    { \"%s\", 0x%08lx%08lxull }, /* %s */\n", k->name, (unsigned long)(h >> 32),
           (unsigned long)(h & 0xFFFFFFFFu), tier);
    CHECK(h == pinned, "%s %s: hash %08lx%08lx, pinned %08lx%08lx", tier, k->name,
          (unsigned long)(h >> 32), (unsigned long)(h & 0xFFFFFFFFu),
          (unsigned long)(pinned >> 32), (unsigned long)(pinned & 0xFFFFFFFFu));
}

int main(void)
{
    size_t i;
    th_name = "fx_hash";
    CHECK(facet_fx_kernel_count() == FXH_N_PINNED, "kernel count %u",
          (unsigned)facet_fx_kernel_count());
    for (i = 0; i < FXH_N_PINNED; i++)
        check_one("fx", fxh_pinned[i].name, NULL, fxh_pinned[i].hash);
    CHECK(FXH_N_PINNED_FAST == sizeof fast_fns / sizeof fast_fns[0], "fast kernel count");
    for (i = 0; i < FXH_N_PINNED_FAST; i++)
        check_one("fx_fast", fxh_pinned_fast[i].name, fast_fns[i], fxh_pinned_fast[i].hash);
    return th_done();
}
