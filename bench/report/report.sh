#!/bin/sh
# bench/report/report.sh BUILD_DIR - the benchmark part of `make report` (called
# from the marked block at the end of tests/report/report.sh).  Writes, under
# BUILD_DIR/report/ (or FACET_REPORT_OUT): mca.tsv (llvm-mca cycles per sample of each port's
# batch loop), size.tsv (bytes of each batch function), arm.tsv (Cortex-M
# figures from bench/cortexm/cortexm.sh, when its tools exist), arm_vec.tsv
# and arm_vec.status (the NEON and Helium ports' costs, arm_targets.sh), then
# runs `build/facet-bench report`, which measures everything else (recorded
# in measured.tsv: `facet-bench report DIR --replay FILE` re-renders it) and
# writes bench.md, then report.md and index.html: accuracy.md (the accuracy
# part tests/report/report.sh left, if any) followed by this run's bench part.
# Progress goes to the terminal.
set -u
build=${1:-build}
out=${FACET_REPORT_OUT:-$build/report}
mkdir -p "$out"
MAKE=${MAKE:-make}
$MAKE -s BUILD="$build" bench-report || exit 1
lanes_of() { case $1 in avx512) echo 16 ;; avx2) echo 8 ;; sse2|neon) echo 4 ;; *) echo 1 ;; esac; }
bin=$build/facet-bench

# ---- x86: llvm-mca on each batch loop, code size ---------------------------
# Where each port's batch function is: `facet-bench batch-symbols` reads the
# library's port tables and prints each function's offset from the public
# facet_port_supported; nm gives that symbol's address and, at the sum, the
# function's size.  No private symbol name is used here.
: > "$out/mca.tsv"
: > "$out/size.tsv"
echo "# format port kernel cpu cycles_per_sample (llvm-mca, modelled)" >> "$out/mca.tsv"
echo "# format port kernel bytes" >> "$out/size.tsv"
case $(${CC:-cc} -dumpmachine) in
x86_64*|i?86*) x86=1 ;;
*) x86=0 ;;
esac
syms=$(nm -S --defined-only "$bin")
anchor=$(printf '%s\n' "$syms" | awk '$NF == "facet_port_supported" { print $1; exit }')
[ -n "$anchor" ] || { echo "report: no facet_port_supported in $bin"; exit 1; }
"$bin" batch-symbols > "$out/batch-symbols.txt" || exit 1
last=
while read -r fmt port k off; do
    [ "$fmt $port" != "$last" ] && [ -n "$last" ] && echo "report: llvm-mca + sizes: $last done"
    last="$fmt $port"
    addr=$(printf "%0${#anchor}x" $((0x$anchor + off)))
    sz=$(printf '%s\n' "$syms" | awk -v a="$addr" '$1 == a && NF == 4 && $3 ~ /^[tT]$/ { print $2; exit }')
    [ -n "$sz" ] || { echo "report: no function at 0x$addr ($port $k) in $bin"; continue; }
    echo "$fmt $port $k $(printf '%d' "0x$sz")" >> "$out/size.tsv"
    if [ $x86 = 1 ] && command -v llvm-mca >/dev/null 2>&1; then
        sh bench/report/mca.sh objdump "$bin" "0x$addr+0x$sz" x86_64 znver3 skylake |
            while read -r cpu cyc; do
                echo "$fmt $port $k $cpu $(awk -v c="$cyc" -v l="$(lanes_of $port)" 'BEGIN { printf "%.3f", c / l }')"
            done >> "$out/mca.tsv"
    fi
done < "$out/batch-symbols.txt"
[ -n "$last" ] && echo "report: llvm-mca + sizes: $last done"

# ---- Cortex-M: fixed point and soft-float f32, traced under qemu -----------
# (bench/cortexm/cortexm.sh: executed-instruction counts, llvm-mca on the executed
# trace, Cortex-M0 TRM timings; every figure labelled measured or modelled)
echo "report: Cortex-M traces (qemu-system-arm) + llvm-mca ..."
sh bench/cortexm/cortexm.sh "$build" "$out/arm.tsv"

# ---- NEON and Helium: the chooser's costs on the Arm vector ports ----------
# (bench/report/arm_targets.sh: llvm-mca on qemu-aarch64 traces, qemu-system-arm
# instruction counts; a missing tool skips a target with the reason)
echo "report: NEON and Helium costs (qemu traces, llvm-mca) ..."
MAKE=$MAKE sh bench/report/arm_targets.sh "$out"

# the samplers' chi-square table (read by `facet-bench report`)
sh bench/report/sample_chi2.sh "$build" "$out" || exit 1

echo "report: measuring (benchmarks, tradeoffs, pictures, rasterizer) ..."
"$bin" report "$out" ${FACET_REPORT_QUICK:+--quick}
