/* fx.c - the fixed-point face of the facet command:
 *   facet eval KERNEL --format fx|fx_fast [--raw]
 *   facet vectors KERNEL [--format fx|fx_fast] [--count N] [--seed S] [--hex]
 * Inputs given as decimals are rounded to Q15 exactly from their digits
 * (floor(x 32768 + 1/2), saturated to int32: src/cli/parse.c); outputs
 * print exactly (every Q value has a finite decimal expansion) or as raw
 * integers.  Input rules and exit statuses: src/cli/cli.h. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "facet/fx.h"
#include "cli.h"

/* the limit of vectors --count */
#define COUNT_MAX 1000000000ull /* 10^9 random vectors (tens of GB of text) */

static void usage_eval(FILE *f)
{
    fprintf(f,
            "usage: facet eval KERNEL --format fx|fx_fast [--raw]\n"
            "Evaluates the fixed-point KERNEL on the samples read from stdin.  Each\n"
            "input is rounded to Q15 once, exactly from its decimal digits: raw =\n"
            "floor(x * 32768 + 1/2) (nearest, ties up), saturated to int32 for any\n"
            "finite value however large (the kernel then clamps it to its domain); NaN\n"
            "and infinities are refused (fixed point has none).  Writes one line per\n"
            "sample: the output's exact value (it has a finite decimal expansion), or\n"
            "with --raw the raw integer of its format (see 'facet vectors --help').\n%s%s",
            facet_cli_input_help, facet_cli_exit_help);
}

static void usage_vectors(FILE *f)
{
    fprintf(f,
            "usage: facet vectors KERNEL [--format fx|fx_fast] [--count N] [--seed S] [--hex]\n"
            "Writes golden vectors of a fixed-point kernel: first the edge cases (every\n"
            "input at its domain ends, their neighbours, out-of-domain values and the\n"
            "key points; each distinct vector once), then N pseudo-random in-domain\n"
            "samples from seed S.  One vector per line: the raw inputs (int32, Q15,\n"
            "1.0 = 32768) in 'facet list' order, then the raw output.\n"
            "  --format fx  the fixed-point kernels (the default); fx_fast their fast tier\n"
            "  --count N    decimal digits only, 0 <= N <= %llu (default 1000)\n"
            "  --seed S     decimal digits only, 0 <= S <= 18446744073709551615\n"
            "               (2^64 - 1; default 1)\n"
            "  --hex        one hexadecimal word per line for Verilog $readmemh: the inputs\n"
            "               as 8 digits each (32-bit two's complement), then the output as 8\n"
            "               digits (16 for brdf_hammon, UQ40.24), most significant field\n"
            "               first; '//' comment header.  E.g. ggx_d: reg [95:0] v [0:N-1];\n"
            "               noh = v[i][95:64], alpha = v[i][63:32], D = v[i][31:0].\n"
            "Without --hex: decimal integers separated by spaces; '#' comment header.\n%s",
            COUNT_MAX, facet_cli_exit_help);
}

/* the fixed-point kernel NAME, or NULL after reporting that there is none
 * (the f32-only kernels get their own message) */
static const facet_fx_kernel *find_fx_kernel(const char *verb, const char *name)
{
    const facet_fx_kernel *k = facet_fx_kernel_find(name);
    if (k)
        return k;
    if (facet_kernel_find(name))
        fprintf(stderr, "facet %s: '%s' has no fixed-point form (only --format f32)\n", verb, name);
    else
        facet_cli_unknown_kernel(verb, "fx kernel", name);
    return NULL;
}

/* a kernel with the fast tier only (no facet_<name>_fx) asked for --format fx */
static void only_fast(const char *verb, const char *name)
{
    fprintf(stderr, "facet %s: '%s' has only the fast fixed-point tier (--format fx_fast)\n", verb, name);
}

/* the exact decimal of raw / 2^frac */
static void print_fixed(FILE *f, uint64_t raw, int frac)
{
    uint64_t ip = raw >> frac, fp = raw & (((uint64_t)1 << frac) - 1);
    fprintf(f, "%llu", (unsigned long long)ip);
    if (fp) {
        fputc('.', f);
        while (fp) { /* fp < 2^24: fp * 10 fits */
            fp *= 10;
            fputc('0' + (int)(fp >> frac), f);
            fp &= ((uint64_t)1 << frac) - 1;
        }
    }
    fputc('\n', f);
}

/* how a row is evaluated and printed (a facet_cli_evaluator flush) */
static void fx_row(const facet_cli_evaluator *e, const facet_cli_rows *rows, size_t n)
{
    const facet_fx_kernel *k = e->what;
    size_t s;
    for (s = 0; s < n; s++) {
        uint64_t out = (e->fast ? k->fx_fast : k->fx)(rows->q15[s]);
        if (e->raw)
            printf("%llu\n", (unsigned long long)out);
        else
            print_fixed(stdout, out, k->out_frac);
    }
}

/* argv[0] is "eval"; the f32 eval hands over when it sees --format fx */
int facet_cli_fx_eval(int argc, char **argv)
{
    static const facet_cli_option opts[] = { { "--format", 1 }, { "--raw", 0 }, { "--port", 1 }, { NULL, 0 } };
    enum { OPT_FORMAT, OPT_RAW, OPT_PORT };
    facet_cli_args a = facet_cli_args_of(argc, argv, "eval", opts, usage_eval);
    facet_cli_evaluator e = { 0 };
    const facet_fx_kernel *k = NULL;
    const char *v;
    int arg;
    while ((arg = facet_cli_next_arg(&a, &v)) != FACET_CLI_ARG_END) {
        switch (arg) {
        case FACET_CLI_ARG_DONE:
            return a.status;
        case FACET_CLI_ARG_NAME:
            if (!(k = find_fx_kernel("eval", v)))
                return FACET_EXIT_USAGE;
            break;
        case OPT_FORMAT:
            e.fast = !strcmp(v, "fx_fast");
            if (strcmp(v, "fx") && !e.fast) {
                fprintf(stderr, "facet eval: unknown format '%s'\n", v);
                return FACET_EXIT_USAGE;
            }
            break;
        case OPT_RAW:
            e.raw = 1;
            break;
        case OPT_PORT:
            if (strcmp(v, "auto") && strcmp(v, "scalar")) {
                fprintf(stderr, "facet eval: unknown port '%s' for fx (known: auto, scalar)\n", v);
                return FACET_EXIT_USAGE;
            }
            break;
        }
    }
    if (!k) {
        fprintf(stderr, "facet eval: missing KERNEL\n");
        usage_eval(stderr);
        return FACET_EXIT_USAGE;
    }
    if (!e.fast && !k->fx) {
        only_fast("eval", k->name);
        return FACET_EXIT_USAGE;
    }
    e.number = FACET_CLI_Q15;
    e.chunk = 1; /* line by line */
    e.n_inputs = k->n_inputs;
    e.inputs = k->inputs;
    e.what = k;
    e.flush = fx_row;
    return facet_cli_eval_lines(&e);
}

static uint64_t rng_next(uint64_t *s) /* splitmix64 */
{
    uint64_t z = (*s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static int vectors_fast; /* vectors --format fx_fast */

static void put_vector(const facet_fx_kernel *k, const int32_t *in, int hex)
{
    uint64_t out = (vectors_fast ? k->fx_fast : k->fx)(in);
    int i;
    for (i = 0; i < k->n_inputs; i++) {
        if (hex)
            printf("%08lx", (unsigned long)(uint32_t)in[i]);
        else
            printf("%ld ", (long)in[i]);
    }
    if (hex && k->out_bits == 64)
        printf("%08lx%08lx\n", (unsigned long)(out >> 32), (unsigned long)(out & 0xFFFFFFFFu));
    else if (hex)
        printf("%08lx\n", (unsigned long)out);
    else
        printf("%llu\n", (unsigned long long)out);
}

/* decimal digits only (no sign, blank, 0x or octal reading), value <= max */
static int parse_count(const char *s, unsigned long long max, unsigned long long *v)
{
    unsigned long long x = 0;
    if (!*s)
        return 0;
    for (; *s; s++) {
        unsigned d = (unsigned)(*s - '0');
        if (*s < '0' || *s > '9' || x > (max - d) / 10)
            return 0;
        x = x * 10 + d;
    }
    *v = x;
    return 1;
}

/* each distinct edge vector once: seen[] holds those written */
#define MAX_EDGES (FACET_FX_MAX_INPUTS * 14 + 2)

static void put_edge(const facet_fx_kernel *k, const int32_t *in, int hex, int32_t seen[][FACET_FX_MAX_INPUTS],
                     int *n_seen)
{
    int i;
    for (i = 0; i < *n_seen; i++)
        if (!memcmp(seen[i], in, (size_t)k->n_inputs * sizeof *in))
            return;
    memcpy(seen[(*n_seen)++], in, (size_t)k->n_inputs * sizeof *in);
    put_vector(k, in, hex);
}

int facet_cli_vectors(int argc, char **argv)
{
    static const facet_cli_option opts[] = { { "--format", 1 }, { "--count", 1 }, { "--seed", 1 }, { "--hex", 0 }, { NULL, 0 } };
    enum { OPT_FORMAT, OPT_COUNT, OPT_SEED, OPT_HEX };
    facet_cli_args a = facet_cli_args_of(argc, argv, "vectors", opts, usage_vectors);
    const facet_fx_kernel *k = NULL;
    const char *format = "fx", *v;
    unsigned long long count = 1000, seed_arg = 1, j;
    uint64_t seed;
    int i, hex = 0, arg;
    while ((arg = facet_cli_next_arg(&a, &v)) != FACET_CLI_ARG_END) {
        switch (arg) {
        case FACET_CLI_ARG_DONE:
            return a.status;
        case FACET_CLI_ARG_NAME:
            if (!(k = find_fx_kernel("vectors", v)))
                return FACET_EXIT_USAGE;
            break;
        case OPT_FORMAT:
            format = v;
            break;
        case OPT_COUNT:
            if (!parse_count(v, COUNT_MAX, &count)) {
                fprintf(stderr, "facet vectors: bad --count '%s' (decimal digits, at most %llu)\n", v, COUNT_MAX);
                return FACET_EXIT_USAGE;
            }
            break;
        case OPT_SEED:
            if (!parse_count(v, ~0ull, &seed_arg)) {
                fprintf(stderr, "facet vectors: bad --seed '%s' (decimal digits, at most 2^64 - 1)\n", v);
                return FACET_EXIT_USAGE;
            }
            break;
        case OPT_HEX:
            hex = 1;
            break;
        }
    }
    if (!k) {
        fprintf(stderr, "facet vectors: missing KERNEL\n");
        usage_vectors(stderr);
        return FACET_EXIT_USAGE;
    }
    vectors_fast = !strcmp(format, "fx_fast");
    if (strcmp(format, "fx") && !vectors_fast) {
        fprintf(stderr, "facet vectors: unknown format '%s' (known: fx, fx_fast)\n", format);
        return FACET_EXIT_USAGE;
    }
    if (!vectors_fast && !k->fx) {
        only_fast("vectors", k->name);
        return FACET_EXIT_USAGE;
    }
    seed = seed_arg;
    printf("%s %s: inputs", hex ? "//" : "#", k->name);
    for (i = 0; i < k->n_inputs; i++)
        printf(" %s", k->inputs[i]);
    printf(" (int32 Q15), %soutput %s in %s%d bits; seed %llu, %llu random\n", vectors_fast ? "fx_fast " : "", k->out_format,
           hex ? "" : "u", k->out_bits, seed_arg, count);
    {
        /* edges: each input in turn at its special values, the others mid-domain */
        const int32_t extra[] = { INT32_MIN, -1, 0, 1, 32767, 32768, 32769, INT32_MAX };
        int32_t mid[FACET_FX_MAX_INPUTS], in[FACET_FX_MAX_INPUTS];
        int32_t seen[MAX_EDGES][FACET_FX_MAX_INPUTS];
        int e, n_seen = 0;
        for (i = 0; i < k->n_inputs; i++)
            mid[i] = k->lo[i] + (k->hi[i] - k->lo[i]) / 2;
        for (i = 0; i < k->n_inputs; i++) {
            const int32_t own[] = { k->lo[i], k->lo[i] + 1, k->hi[i] - 1, k->hi[i], k->lo[i] - 1, k->hi[i] + 1 };
            for (e = 0; e < (int)(sizeof own / sizeof own[0] + sizeof extra / sizeof extra[0]); e++) {
                memcpy(in, mid, sizeof in);
                in[i] = e < 6 ? own[e] : extra[e - 6];
                put_edge(k, in, hex, seen, &n_seen);
            }
        }
        for (e = 0; e < 2; e++) { /* all inputs at the low, then the high end */
            for (i = 0; i < k->n_inputs; i++)
                in[i] = e ? k->hi[i] : k->lo[i];
            put_edge(k, in, hex, seen, &n_seen);
        }
    }
    for (j = 0; j < count; j++) {
        int32_t in[FACET_FX_MAX_INPUTS];
        for (i = 0; i < k->n_inputs; i++)
            in[i] = k->lo[i] + (int32_t)(rng_next(&seed) % (uint64_t)(k->hi[i] - k->lo[i] + 1));
        put_vector(k, in, hex);
        if ((j & 1023) == 0 && ferror(stdout))
            break; /* e.g. /dev/full: no point in going on */
    }
    return facet_cli_finish("vectors");
}
