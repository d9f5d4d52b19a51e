/* sample.c - `facet eval SAMPLER`: the importance samplers (facet.h), one
 * output line per sample holding the sampled vector's components (or the
 * pdf), in f32, f32_fast or the double oracle.  Input rules and exit
 * statuses as for the kernels (cli.h). */
#include <stdio.h>
#include <string.h>
#include "facet.h"
#include "cli.h"

#define CHUNK_ 1024 /* samples per batch call */

int facet_cli_sample_eval(const facet_sampler *s, int fast, int oracle)
{
    static float cols[FACET_SAMPLER_MAX_INPUTS][CHUNK_], outs[FACET_SAMPLER_MAX_OUTPUTS][CHUNK_];
    facet_cli_reader r;
    const char *err = NULL;
    int i, o, got = 1;
    r.f = stdin;
    r.lineno = 0;
    while (got == 1) {
        int n = 0;
        /* a chunk of lines; a malformed one ends the chunk and the run after
         * the lines before it are printed */
        while (n < CHUNK_ && (got = facet_cli_read_line(&r, &err)) == 1) {
            if (oracle) {
                double din[FACET_SAMPLER_MAX_INPUTS], dout[FACET_SAMPLER_MAX_OUTPUTS];
                err = facet_cli_parse_f64(r.buf, s->n_inputs, din);
                if (err) {
                    got = -1;
                    break;
                }
                s->oracle(dout, din);
                for (o = 0; o < s->n_outputs; o++)
                    printf("%s%.17g", o ? " " : "", dout[o]);
                printf("\n");
                continue;
            } else {
                float in[FACET_SAMPLER_MAX_INPUTS];
                err = facet_cli_parse_f32(r.buf, s->n_inputs, in);
                if (err) {
                    got = -1;
                    break;
                }
                for (i = 0; i < s->n_inputs; i++)
                    cols[i][n] = in[i];
                n++;
            }
        }
        if (n > 0) {
            const float *in[FACET_SAMPLER_MAX_INPUTS];
            float *out[FACET_SAMPLER_MAX_OUTPUTS];
            for (i = 0; i < FACET_SAMPLER_MAX_INPUTS; i++)
                in[i] = cols[i];
            for (o = 0; o < FACET_SAMPLER_MAX_OUTPUTS; o++)
                out[o] = outs[o];
            (fast ? s->f32_fast_batch : s->f32_batch)(out, in, (size_t)n);
            for (i = 0; i < n; i++) {
                for (o = 0; o < s->n_outputs; o++)
                    printf("%s%.9g", o ? " " : "", outs[o][i]);
                printf("\n");
            }
        }
        if (ferror(stdout))
            return facet_cli_finish("eval");
    }
    if (got == -2) {
        fprintf(stderr, "facet eval: error reading the input\n");
        return FACET_EXIT_IO;
    }
    if (got == -1) {
        int rc = facet_cli_finish("eval");
        facet_cli_line_error(r.lineno, err, s->n_inputs, s->inputs);
        return rc ? rc : FACET_EXIT_USAGE;
    }
    return facet_cli_finish("eval");
}
