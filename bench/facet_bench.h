/* facet_bench.h - the verbs of build/facet-bench (bench/facet_bench.c), one
 * function each, implemented in the part that owns it.  argv[0] is the verb. */
#ifndef FACET_BENCH_VERBS_H
#define FACET_BENCH_VERBS_H

int facet_cmd_bench(int argc, char **argv);         /* harness/cli_bench.c */
int facet_bench_api(int argc, char **argv);         /* harness/api_bench.c */
int facet_bench_speed(int argc, char **argv);       /* harness/speed_bench.c */
int facet_bench_report(int argc, char **argv);      /* report/report.c */
int facet_bench_batch_symbols(int argc, char **argv); /* report/symbols.c */

#endif
