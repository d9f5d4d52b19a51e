#!/bin/sh
# bench/qcount/rvv_f16_rows.sh COUNTS - the rows of ports/README.md's RVV
# binary16 table from one `qcount.sh rv64-f16` output (VLEN 128, 256, 512):
# per kernel with an f16 form, executed instructions per sample of the rvv
# f32 and f32_fast batches and the rvvfp16 f16 batch, each cell the three
# VLENs "128 / 256 / 512", then f16's ratios against both (f32 instructions
# over f16's: above 1 f16 executes fewer).  tests/suites/54-rvv.sh compares
# them with the README.
set -u
awk '{ c = $1; sub(/^rv64-vlen/, "", c); n[$2 " " $3 " " c] = $4
       if (!($2 in seen)) { seen[$2] = 1; k[nk++] = $2 }
       if (!(c in vs)) { vs[c] = 1; v[nv++] = c } }
     function cell(kn, f,   i, s) { s = ""; for (i = 0; i < nv; i++) s = s (i ? " / " : "") n[kn " " f " " v[i]]; return s }
     function ratio(kn, f,   i, s) { s = ""
         for (i = 0; i < nv; i++) s = s (i ? " / " : "") sprintf("%.2fx", n[kn " " f " " v[i]] / n[kn " f16 " v[i]])
         return s }
     END {
         for (j = 0; j < nk; j++) {
             kn = k[j]
             if (!((kn " f16 " v[0]) in n)) continue
             printf "| %s | %s | %s | %s | %s | %s |\n", kn, cell(kn, "f32"), cell(kn, "f32_fast"), cell(kn, "f16"),
                    ratio(kn, "f32"), ratio(kn, "f32_fast")
         }
     }' "$1"
