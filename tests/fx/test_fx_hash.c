/* test_fx_hash.c - pinned output hashes of every fixed-point kernel over
 * fixed input grids.  Integer only and libc-light (printf), so the same
 * file runs on the host (make check), under qemu-user (aarch64, armv7) and
 * bare-metal on Cortex-M0/M4 (tests/fx/fx.mk): every target must print the
 * same hashes, the ones pinned here.
 * The grids and pinned values are in tests/lib/fx_hash.h (shared with
 * tests/fx/test_fx_ports.c, which hashes the batch API on every port). */
#include <stdio.h>
#include <string.h>
#include "../lib/harness.h"
#include "facet/fx.h"
#define FXH_FAST
#include "../lib/fx_hash.h"

typedef uint64_t (*fxh_fn)(const int32_t *in);
struct hctx { fxh_fn fn; int bytes; uint64_t h; };
static void visit(const int32_t *in, void *ctx)
{
    struct hctx *c = (struct hctx *)ctx;
    fxh_feed(&c->h, c->fn(in), c->bytes);
}

/* the hash of one tier of kernel `name` over its grid (the table's fx or
 * fx_fast: every fixed-point kernel has fx_fast, all but the fast-tier-only
 * ones fx) */
static void check_one(const char *tier, const char *name, int fast, uint64_t pinned)
{
    const facet_fx_kernel *k = facet_fx_kernel_find(name);
    struct hctx c;
    uint64_t h;
    if (!k) {
        CHECK(0, "%s: not in the fx table", name);
        return;
    }
    c.fn = fast ? k->fx_fast : k->fx;
    if (!c.fn) {
        CHECK(0, "%s %s: no such tier in the fx table", tier, name);
        return;
    }
    c.bytes = k->out_bits / 8;
    c.h = FXH_INIT;
    fxh_walk(k, visit, &c);
    h = c.h;
    printf("    { \"%s\", 0x%08lx%08lxull }, /* %s */\n", k->name, (unsigned long)(h >> 32),
           (unsigned long)(h & 0xFFFFFFFFu), tier);
    CHECK(h == pinned, "%s %s: hash %08lx%08lx, pinned %08lx%08lx", tier, k->name,
          (unsigned long)(h >> 32), (unsigned long)(h & 0xFFFFFFFFu),
          (unsigned long)(pinned >> 32), (unsigned long)(pinned & 0xFFFFFFFFu));
}

/* the kernels of the fx table with the tier but no pinned hash: each
 * printed with its hash (the line to pin, once its values are checked) */
static int unpinned(const char *tier, int fast, const char *const *names, size_t n)
{
    size_t i, j;
    int missing = 0;
    for (i = 0; i < facet_fx_kernel_count(); i++) {
        const facet_fx_kernel *k = facet_fx_kernel_at(i);
        struct hctx c;
        if (!(fast ? k->fx_fast : k->fx))
            continue;
        for (j = 0; j < n && strcmp(names[j], k->name); j++)
            ;
        if (j < n)
            continue;
        c.fn = fast ? k->fx_fast : k->fx;
        c.bytes = k->out_bits / 8;
        c.h = FXH_INIT;
        fxh_walk(k, visit, &c);
        printf("    { \"%s\", 0x%08lx%08lxull }, /* %s: not pinned in tests/lib/fx_hash.h */\n", k->name,
               (unsigned long)(c.h >> 32), (unsigned long)(c.h & 0xFFFFFFFFu), tier);
        missing++;
    }
    return missing;
}

int main(void)
{
    const char *names[FXH_N_PINNED_FAST > FXH_N_PINNED ? FXH_N_PINNED_FAST : FXH_N_PINNED];
    size_t i, n_precise = 0;
    int missing;
    th_name = "fx_hash";
    for (i = 0; i < facet_fx_kernel_count(); i++) /* fast-tier-only kernels have no fx */
        n_precise += facet_fx_kernel_at(i)->fx != NULL;
    for (i = 0; i < FXH_N_PINNED; i++)
        names[i] = fxh_pinned[i].name;
    missing = unpinned("fx", 0, names, FXH_N_PINNED);
    CHECK(n_precise == FXH_N_PINNED && !missing, "precise kernel count %u, pinned %u, %d not pinned (above)",
          (unsigned)n_precise, (unsigned)FXH_N_PINNED, missing);
    for (i = 0; i < FXH_N_PINNED; i++)
        check_one("fx", fxh_pinned[i].name, 0, fxh_pinned[i].hash);
    for (i = 0; i < FXH_N_PINNED_FAST; i++)
        names[i] = fxh_pinned_fast[i].name;
    missing = unpinned("fx_fast", 1, names, FXH_N_PINNED_FAST);
    CHECK(FXH_N_PINNED_FAST == facet_fx_kernel_count() && !missing,
          "fast kernel count %u, pinned %u, %d not pinned (above)", (unsigned)facet_fx_kernel_count(),
          (unsigned)FXH_N_PINNED_FAST, missing);
    for (i = 0; i < FXH_N_PINNED_FAST; i++)
        check_one("fx_fast", fxh_pinned_fast[i].name, 1, fxh_pinned_fast[i].hash);
    return th_done();
}
