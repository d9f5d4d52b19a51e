/* fx.c - the fixed-point face of the facet command:
 *   facet eval KERNEL --format fx [--raw]
 *   facet vectors KERNEL --format fx [--count N] [--seed S] [--hex]
 * Inputs given as decimals are rounded to Q15 by the fx rule (nearest, ties
 * up); outputs print exactly (every Q value has a finite decimal expansion)
 * or as raw integers.  Exit status: 0 success, 2 usage or malformed input,
 * 1 I/O error. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet/fx.h"
#include "cli.h"


#define LINE_MAX_ 4096

int facet_cli_fx_eval(int argc, char **argv);
int facet_cli_vectors(int argc, char **argv);

static void usage_eval(FILE *f)
{
    fprintf(f,
            "usage: facet eval KERNEL --format fx [--raw]\n"
            "Reads samples from stdin, one per line: the kernel's inputs as decimal numbers\n"
            "in 'facet list' order.  Each is rounded to Q15 (raw = floor(x * 32768 + 1/2),\n"
            "saturated to int32; the kernel then clamps it to its domain).  Writes one line\n"
            "per sample: the output's exact value (it has a finite decimal expansion), or\n"
            "with --raw the raw integer of its format (see 'facet vectors --help').\n");
}

static void usage_vectors(FILE *f)
{
    fprintf(f,
            "usage: facet vectors KERNEL --format fx [--count N] [--seed S] [--hex]\n"
            "Writes golden vectors of a fixed-point kernel: first the edge cases (every\n"
            "input at its domain ends, their neighbours, out-of-domain values and the\n"
            "key points), then N (default 1000) pseudo-random in-domain samples from\n"
            "seed S (default 1).  One vector per line: the raw inputs (int32, Q15,\n"
            "1.0 = 32768) in 'facet list' order, then the raw output.\n"
            "  default  decimal integers separated by spaces; '#' comment header\n"
            "  --hex    one hexadecimal word per line for Verilog $readmemh: the inputs\n"
            "           as 8 digits each (32-bit two's complement), then the output as 8\n"
            "           digits (16 for brdf_hammon, UQ40.24), most significant field\n"
            "           first; '//' comment header.  E.g. ggx_d: reg [95:0] v [0:N-1];\n"
            "           noh = v[i][95:64], alpha = v[i][63:32], D = v[i][31:0].\n");
}

/* x rounded to Q15 by the fx rule, saturated to int32; 0 if not finite */
static int to_q15(double x, int32_t *raw)
{
    double y, r;
    if (!(x == x) || x > 1e300 || x < -1e300)
        return 0;
    y = x * 32768.0; /* exact: a power of two */
    r = floor(y);
    if (y - r >= 0.5) /* exact too: no y + 0.5 rounding */
        r += 1.0;
    *raw = r >= 2147483647.0 ? INT32_MAX : r <= -2147483648.0 ? INT32_MIN : (int32_t)r;
    return 1;
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

static const char *parse_line(const char *line, int n, int32_t *in)
{
    double v[FACET_FX_MAX_INPUTS];
    const char *err = facet_cli_parse_numbers(line, n, v);
    int i;
    for (i = 0; !err && i < n; i++)
        if (!to_q15(v[i], &in[i]))
            return "not a finite number (fixed point has no NaN or infinity)";
    return err;
}

/* argv[0] is "eval"; the f32 eval hands over when it sees --format fx */
int facet_cli_fx_eval(int argc, char **argv)
{
    const facet_fx_kernel *k = NULL;
    char line[LINE_MAX_];
    long lineno = 0;
    int i, raw = 0;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            usage_eval(stdout);
            return 0;
        } else if (!strcmp(argv[i], "--format") && i + 1 < argc) {
            if (strcmp(argv[++i], "fx")) {
                fprintf(stderr, "facet eval: unknown format '%s'\n", argv[i]);
                return 2;
            }
        } else if (!strcmp(argv[i], "--raw")) {
            raw = 1;
        } else if (!strcmp(argv[i], "--port") && i + 1 < argc) {
            if (strcmp(argv[++i], "auto") && strcmp(argv[i], "scalar")) {
                fprintf(stderr, "facet eval: unknown port '%s' for fx (known: auto, scalar)\n", argv[i]);
                return 2;
            }
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            fprintf(stderr, "facet eval: unknown or incomplete option '%s'\n", argv[i]);
            usage_eval(stderr);
            return 2;
        } else if (!k) {
            k = facet_fx_kernel_find(argv[i]);
            if (!k) {
                fprintf(stderr, "facet eval: unknown fx kernel '%s' (see 'facet list')\n", argv[i]);
                return 2;
            }
        } else {
            fprintf(stderr, "facet eval: unexpected argument '%s'\n", argv[i]);
            return 2;
        }
    }
    if (!k) {
        fprintf(stderr, "facet eval: missing KERNEL\n");
        usage_eval(stderr);
        return 2;
    }
    while (fgets(line, sizeof line, stdin)) {
        int32_t in[FACET_FX_MAX_INPUTS];
        const char *err;
        uint64_t out;
        lineno++;
        if (!strchr(line, '\n') && !feof(stdin)) {
            fprintf(stderr, "facet eval: line %ld: longer than %d characters\n", lineno, LINE_MAX_ - 2);
            return 2;
        }
        err = parse_line(line, k->n_inputs, in);
        if (err) {
            fprintf(stderr, "facet eval: line %ld: %s (expected %d numbers:", lineno, err, k->n_inputs);
            for (i = 0; i < k->n_inputs; i++)
                fprintf(stderr, " %s", k->inputs[i]);
            fprintf(stderr, ")\n");
            return 2;
        }
        out = k->fx(in);
        if (raw)
            printf("%llu\n", (unsigned long long)out);
        else
            print_fixed(stdout, out, k->out_frac);
    }
    if (ferror(stdin) || fflush(stdout) != 0) {
        fprintf(stderr, "facet eval: I/O error\n");
        return 1;
    }
    return 0;
}

static uint64_t rng_next(uint64_t *s) /* splitmix64 */
{
    uint64_t z = (*s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static void put_vector(const facet_fx_kernel *k, const int32_t *in, int hex)
{
    uint64_t out = k->fx(in);
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

static int parse_count(const char *s, unsigned long long *v)
{
    char *end;
    if (!*s || *s == '-')
        return 0;
    errno = 0;
    *v = strtoull(s, &end, 0);
    return !*end && errno == 0;
}

int facet_cli_vectors(int argc, char **argv)
{
    const facet_fx_kernel *k = NULL;
    const char *format = NULL;
    unsigned long long count = 1000, seed_arg = 1, j;
    uint64_t seed;
    int i, hex = 0;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            usage_vectors(stdout);
            return 0;
        } else if (!strcmp(argv[i], "--format") && i + 1 < argc) {
            format = argv[++i];
        } else if (!strcmp(argv[i], "--count") && i + 1 < argc) {
            if (!parse_count(argv[++i], &count)) {
                fprintf(stderr, "facet vectors: bad --count '%s'\n", argv[i]);
                return 2;
            }
        } else if (!strcmp(argv[i], "--seed") && i + 1 < argc) {
            if (!parse_count(argv[++i], &seed_arg)) {
                fprintf(stderr, "facet vectors: bad --seed '%s'\n", argv[i]);
                return 2;
            }
        } else if (!strcmp(argv[i], "--hex")) {
            hex = 1;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            fprintf(stderr, "facet vectors: unknown or incomplete option '%s'\n", argv[i]);
            usage_vectors(stderr);
            return 2;
        } else if (!k) {
            k = facet_fx_kernel_find(argv[i]);
            if (!k) {
                fprintf(stderr, "facet vectors: unknown fx kernel '%s' (see 'facet list')\n", argv[i]);
                return 2;
            }
        } else {
            fprintf(stderr, "facet vectors: unexpected argument '%s'\n", argv[i]);
            return 2;
        }
    }
    if (!k) {
        fprintf(stderr, "facet vectors: missing KERNEL\n");
        usage_vectors(stderr);
        return 2;
    }
    if (!format || strcmp(format, "fx")) {
        fprintf(stderr, "facet vectors: --format fx is required (the only vector format)\n");
        return 2;
    }
    seed = seed_arg;
    printf("%s %s: inputs", hex ? "//" : "#", k->name);
    for (i = 0; i < k->n_inputs; i++)
        printf(" %s", k->inputs[i]);
    printf(" (int32 Q15), output %s in %s%d bits; seed %llu, %llu random\n", k->out_format,
           hex ? "" : "u", k->out_bits, seed_arg, count);
    {
        /* edges: each input in turn at its special values, the others mid-domain */
        const int32_t extra[] = { INT32_MIN, -1, 0, 1, 32767, 32768, 32769, INT32_MAX };
        int32_t mid[FACET_FX_MAX_INPUTS], in[FACET_FX_MAX_INPUTS];
        int e;
        for (i = 0; i < k->n_inputs; i++)
            mid[i] = k->lo[i] + (k->hi[i] - k->lo[i]) / 2;
        for (i = 0; i < k->n_inputs; i++) {
            const int32_t own[] = { k->lo[i], k->lo[i] + 1, k->hi[i] - 1, k->hi[i], k->lo[i] - 1, k->hi[i] + 1 };
            for (e = 0; e < (int)(sizeof own / sizeof own[0] + sizeof extra / sizeof extra[0]); e++) {
                memcpy(in, mid, sizeof in);
                in[i] = e < 6 ? own[e] : extra[e - 6];
                put_vector(k, in, hex);
            }
        }
        for (e = 0; e < 2; e++) { /* all inputs at the low, then the high end */
            for (i = 0; i < k->n_inputs; i++)
                in[i] = e ? k->hi[i] : k->lo[i];
            put_vector(k, in, hex);
        }
    }
    for (j = 0; j < count; j++) {
        int32_t in[FACET_FX_MAX_INPUTS];
        for (i = 0; i < k->n_inputs; i++)
            in[i] = k->lo[i] + (int32_t)(rng_next(&seed) % (uint64_t)(k->hi[i] - k->lo[i] + 1));
        put_vector(k, in, hex);
    }
    if (fflush(stdout) != 0) {
        fprintf(stderr, "facet vectors: I/O error\n");
        return 1;
    }
    return 0;
}
