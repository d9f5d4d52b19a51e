/* facet_bench.c - build/facet-bench, the bench's own command (bench/README.md).
 *   facet-bench bench [KERNEL] [options]  cycles and error of every kernel x
 *                                         format x port x path, and the peers
 *   facet-bench speed [KERNEL] [options] both f32 tiers against the same-formula
 *                                         peers, interleaved rounds
 *   facet-bench report OUTDIR [--quick]   the benchmark part of `make report`
 *   facet-bench batch-symbols             where each port's batch functions are
 *                                         in this binary (for report/report.sh)
 * Not installed, and not the library's `facet` command: it links the peers,
 * built with -march=native, so it runs on the machine that built it. */
#include <stdio.h>
#include <string.h>
#include "facet.h"
#include "facet_bench.h"

static void usage(FILE *f)
{
    fprintf(f, "usage: facet-bench <verb> [options]\n"
               "verbs:\n"
               "  bench [KERNEL]       cycles per sample of every kernel, port and format\n"
               "  api                  the RGB, uniform-material, per-pixel and fx RGB entry\n"
               "                       points, timed in one run (issue 15)\n"
               "  speed [KERNEL]       both f32 tiers on every port beside the same-formula\n"
               "                       peers of the same width, in interleaved rounds\n"
               "  report OUTDIR        the benchmark part of `make report` (bench.md, index.html)\n"
               "  batch-symbols        each port's batch function per kernel, as an offset from\n"
               "                       facet_port_supported in this binary\n"
               "Run 'facet-bench <verb> --help' for a verb's options.\n");
}

static const struct {
    const char *name;
    int (*run)(int argc, char **argv);
} verbs[] = {
    { "bench", facet_cmd_bench },
    { "api", facet_bench_api },
    { "speed", facet_bench_speed },
    { "report", facet_bench_report },
    { "batch-symbols", facet_bench_batch_symbols },
};

int main(int argc, char **argv)
{
    size_t i;
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
        usage(stdout);
        return 0;
    }
    if (!strcmp(argv[1], "--version")) {
        printf("facet-bench %s\n", FACET_VERSION);
        return 0;
    }
    for (i = 0; i < sizeof verbs / sizeof verbs[0]; i++)
        if (!strcmp(argv[1], verbs[i].name))
            return verbs[i].run(argc - 1, argv + 1);
    fprintf(stderr, "facet-bench: unknown verb '%s'\n", argv[1]);
    usage(stderr);
    return 2;
}
