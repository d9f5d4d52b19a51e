/* info.c - `facet list` and `facet ports`: the kernels, samplers and ports
 * compiled in.  Input rules and exit statuses: src/cli/cli.h. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "facet/fx.h"
#include "facet/f16.h"
#include "cli.h"

static const char *prog = "facet";

static void usage_list(FILE *f)
{
    fprintf(f, "usage: %s list [--formats | --f16]\n"
               "Prints one line per kernel: its name, then the names of its inputs in the\n"
               "order 'eval' reads them.  With --formats: its name, then the formats it\n"
               "comes in (f32 f32_fast; fx fx_fast where it has a fixed-point form, fx_fast\n"
               "alone where it has only the fast fixed-point tier; then f16 where it has a\n"
               "binary16 form).  With --f16: its name, then 'f16' or 'none:' and why it\n"
               "has no binary16 form (src/core/f16_kernels.def).\n%s",
            prog, facet_cli_exit_help);
}

static void usage_ports(FILE *f)
{
    fprintf(f, "usage: %s ports\n"
               "Prints one line per port compiled in, best first: its name, its lanes,\n"
               "whether this CPU runs it, and 'auto' on the port the automatic choice\n"
               "picks here.  With FACET_PORT set, a last line says what the library does\n"
               "with it: a port this CPU runs is the library's initial port; any other\n"
               "value is ignored by the library (it starts on auto; facet_port_name()\n"
               "tells), whereas 'facet eval' (f32) refuses it (exit status 2).\n%s",
            prog, facet_cli_exit_help);
}

/* a verb given only --help / -h; 1 if it was (and the help is printed) */
static int wants_help(int argc, char **argv)
{
    return argc == 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"));
}

int facet_cli_list(int argc, char **argv)
{
    size_t i;
    int j, f16;
    if (wants_help(argc, argv)) {
        usage_list(stdout);
        return facet_cli_finish("list");
    }
    if (argc > 2 || (argc == 2 && strcmp(argv[1], "--formats") && strcmp(argv[1], "--f16"))) {
        fprintf(stderr, "%s list: unexpected argument '%s'\n", prog, argv[1]);
        usage_list(stderr);
        return FACET_EXIT_USAGE;
    }
    f16 = argc == 2 && !strcmp(argv[1], "--f16");
    for (i = 0; i < facet_kernel_count(); i++) {
        const facet_kernel *k = facet_kernel_at(i);
        printf("%s", k->name);
        if (argc == 2) {
            const facet_fx_kernel *fk = facet_fx_kernel_find(k->name);
            const facet_f16_kernel *hk = facet_f16_kernel_find(k->name);
            if (f16)
                printf(hk && hk->f16 ? " f16" : " none: %s", hk ? hk->why : "not in the f16 list");
            else
                printf(" f32 f32_fast%s%s%s", fk && fk->fx ? " fx" : "", fk ? " fx_fast" : "",
                       hk && hk->f16 ? " f16" : "");
        }
        else
            for (j = 0; j < k->n_inputs; j++)
                printf(" %s", k->inputs[j]);
        printf("\n");
    }
    /* the importance samplers: inputs, then '->' and their outputs */
    for (i = 0; i < facet_sampler_count(); i++) {
        const facet_sampler *smp = facet_sampler_at(i);
        printf("%s", smp->name);
        if (argc == 2)
            printf(f16 ? " none: the samplers are f32 only\n" : " f32 f32_fast\n");
        else {
            for (j = 0; j < smp->n_inputs; j++)
                printf(" %s", smp->inputs[j]);
            printf(" ->");
            for (j = 0; j < smp->n_outputs; j++)
                printf(" %s", smp->outputs[j]);
            printf("\n");
        }
    }
    return facet_cli_finish("list");
}

int facet_cli_ports(int argc, char **argv)
{
    size_t i;
    int picked = 0;
    const char *env = getenv("FACET_PORT");
    if (wants_help(argc, argv)) {
        usage_ports(stdout);
        return facet_cli_finish("ports");
    }
    if (argc > 1) {
        fprintf(stderr, "%s ports: unexpected argument '%s'\n", prog, argv[1]);
        usage_ports(stderr);
        return FACET_EXIT_USAGE;
    }
    for (i = 0; i < facet_port_count(); i++) {
        int sup, lanes;
        const char *n = facet_port_at(i, &sup, &lanes);
        printf("%-8s %2d lane%s  %s%s\n", n, lanes, lanes == 1 ? " " : "s",
               sup ? "runs on this CPU" : "not on this CPU", sup && !picked ? "  auto" : "");
        picked |= sup; /* best first: auto is the first one this CPU runs */
    }
    if (env && *env && strcmp(env, "auto")) {
        int sup = 0, known = 0;
        for (i = 0; i < facet_port_count(); i++)
            if (!strcmp(env, facet_port_at(i, &sup, NULL))) {
                known = 1;
                break;
            }
        if (known && sup)
            printf("FACET_PORT=%s: the library starts on %s\n", env, env);
        else
            printf("FACET_PORT=%s: %s; the library ignores it (starts on auto), "
                   "'%s eval' (f32) refuses it\n", env, known ? "this CPU cannot run it" : "not a port compiled in",
                   prog);
    }
    return facet_cli_finish("ports");
}
