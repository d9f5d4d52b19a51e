/* ct_probe.c - a function with a data-dependent loop, named like a fast
 * kernel: tests/suites/51-fx-wcet.sh's branch check must report it (the
 * check can fail). */
#include <stdint.h>
int32_t facet_ct_probe_fx_fast(int32_t x);
int32_t facet_ct_probe_fx_fast(int32_t x)
{
    int32_t n = 0;
    while (x > 0) {
        x >>= 1;
        n++;
    }
    return n;
}
