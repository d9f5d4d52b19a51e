/* symbols.c - `facet-bench batch-symbols`: where each port's f32 batch
 * function of each kernel sits in this binary, so report.sh can size it and
 * hand its loop to llvm-mca without knowing the library's private names for
 * these functions.  Read from the library's port tables (src/core/port.h, the
 * dispatcher's contract: a port's name, its lanes, then one function per
 * kernel in src/core/kernels.def order).  One line per tier, compiled-in port and
 * kernel:
 *   FORMAT PORT KERNEL OFFSET       (FORMAT: f32 or f32_fast)
 * OFFSET: the function's address minus the address of the public
 * facet_port_supported, in bytes (decimal, may be negative); add it to
 * facet_port_supported's address in `nm build/facet-bench`.  Ports not
 * compiled for this target are weak references, absent (NULL) here. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "facet.h"
#include "src/core/port.h"
#include "harness/port_tables.h"
#include "facet_bench.h"


static void print_port(const char *format, const facet_f32_port *p)
{
    uintptr_t anchor = (uintptr_t)facet_port_supported;
    const char *port;
    if (!p)
        return;
    port = p->name; /* (inside the macro, `name` is the kernel's) */
#define FACET_KERNEL(name, ...) \
    printf("%s %s %s %lld\n", format, port, #name, (long long)((intptr_t)(uintptr_t)p->name - (intptr_t)anchor));
#include "src/core/kernels.def"
#undef FACET_KERNEL
}

int facet_bench_batch_symbols(int argc, char **argv)
{
    if (argc > 1) {
        if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
            printf("usage: facet-bench batch-symbols\n"
                   "One line per tier, compiled-in port and kernel: FORMAT PORT KERNEL OFFSET,\n"
                   "the batch function's address minus facet_port_supported's, in bytes.\n");
            return 0;
        }
        fprintf(stderr, "facet-bench batch-symbols: unexpected argument '%s'\n", argv[1]);
        return 2;
    }
    print_port("f32", &facet_port_avx512_f32);
    print_port("f32", &facet_port_avx2_f32);
    print_port("f32", &facet_port_sse2_f32);
    print_port("f32", &facet_port_neon_f32);
    print_port("f32", &facet_port_scalar_f32);
    print_port("f32_fast", &facet_port_avx512_f32_fast);
    print_port("f32_fast", &facet_port_avx2_f32_fast);
    print_port("f32_fast", &facet_port_sse2_f32_fast);
    print_port("f32_fast", &facet_port_neon_f32_fast);
    print_port("f32_fast", &facet_port_scalar_f32_fast);
    return 0;
}
