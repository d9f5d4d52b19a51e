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
#include "fx_hash.h"

struct hctx { const facet_fx_kernel *k; uint64_t h; };
static void visit(const int32_t *in, void *ctx)
{
    struct hctx *c = (struct hctx *)ctx;
    fxh_feed(&c->h, c->k->fx(in), c->k->out_bits / 8);
}

static uint64_t kernel_hash(const facet_fx_kernel *k)
{
    struct hctx c;
    c.k = k;
    c.h = FXH_INIT;
    fxh_walk(k, visit, &c);
    return c.h;
}

int main(void)
{
    size_t i;
    th_name = "fx_hash";
    CHECK(facet_fx_kernel_count() == FXH_N_PINNED, "kernel count %u",
          (unsigned)facet_fx_kernel_count());
    for (i = 0; i < FXH_N_PINNED; i++) {
        const facet_fx_kernel *k = facet_fx_kernel_find(fxh_pinned[i].name);
        uint64_t h;
        if (!k) {
            CHECK(0, "%s: not in the fx table", fxh_pinned[i].name);
            continue;
        }
        h = kernel_hash(k);
        printf("    { \"%s\", 0x%08lx%08lxull },\n", k->name, (unsigned long)(h >> 32),
               (unsigned long)(h & 0xFFFFFFFFu));
        CHECK(h == fxh_pinned[i].hash, "%s: hash %08lx%08lx, pinned %08lx%08lx", k->name,
              (unsigned long)(h >> 32), (unsigned long)(h & 0xFFFFFFFFu),
              (unsigned long)(fxh_pinned[i].hash >> 32), (unsigned long)(fxh_pinned[i].hash & 0xFFFFFFFFu));
    }
    return th_done();
}
