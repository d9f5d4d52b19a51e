#!/bin/sh
# bench/qcount/f16_rows.sh GCC CLANG - the rows of ports/README.md's Helium
# binary16 table from two `qcount.sh m55-f16` outputs (build/m55: gcc 12;
# build/m55-clang: the helium objects from clang 14): per kernel with an f16
# form, "instr / cyc" per sample of the helium f32 and f32_fast batches and
# the heliumfp16 f16 batch (clang), f16's ratios against both (instructions
# / cycles, slower over faster: above 1 f16 is faster) and the f16 batch
# built with gcc.  tests/suites/52-helium.sh compares them with the README;
# bench/qcount/report_md.sh prints them in the report.
set -u
awk 'FILENAME == ARGV[2] { i[$2 " " $3] = $4; c[$2 " " $3] = $5; if (!($2 in seen)) { seen[$2] = 1; k[n++] = $2 } }
     FILENAME == ARGV[1] && $3 == "f16" { g[$2] = $4 " / " $5 }
     END {
         for (j = 0; j < n; j++) {
             kn = k[j]; a = kn " f32"; b = kn " f32_fast"; h = kn " f16"
             if (!(h in i)) continue
             printf "| %s | %s / %s | %s / %s | %s / %s | %.2fx / %.2fx | %.2fx / %.2fx | %s |\n", kn,
                    i[a], c[a], i[b], c[b], i[h], c[h], i[a] / i[h], c[a] / c[h], i[b] / i[h], c[b] / c[h],
                    (kn in g) ? g[kn] : "-"
         }
     }' "$1" "$2"
