#!/bin/sh
# bench/report/report.sh BUILD_DIR - the benchmark part of `make report` (called
# from the marked block at the end of tests/report.sh).  Writes, under
# BUILD_DIR/report/: mca.tsv (llvm-mca cycles per sample of each port's
# batch loop), size.tsv (bytes of each batch function), arm.tsv (Cortex-M
# figures from bench/cortexm/cortexm.sh, when its tools exist), then
# runs `build/facet-bench report`, which measures everything else and
# writes bench.md and index.html.  Progress goes to the terminal.
set -u
build=${1:-build}
out=$build/report
mkdir -p "$out"
MAKE=${MAKE:-make}
$MAKE -s BUILD="$build" bench-report || exit 1
lanes_of() { case $1 in avx512) echo 16 ;; avx2) echo 8 ;; sse2|neon) echo 4 ;; *) echo 1 ;; esac; }
bin=$build/facet-bench
obj_of() { if [ "$1" = scalar ]; then echo "$build/src/f32_batch_scalar.o"; else echo "$build/ports/$1/f32_$1.o"; fi; }
kernels=$("$build/facet" list | cut -d' ' -f1)

# ---- x86: llvm-mca on each batch loop, code size ---------------------------
: > "$out/mca.tsv"
: > "$out/size.tsv"
echo "# port kernel cpu cycles_per_sample (llvm-mca, modelled)" >> "$out/mca.tsv"
echo "# format port kernel bytes" >> "$out/size.tsv"
case $(${CC:-cc} -dumpmachine) in
x86_64*|i?86*) x86=1 ;;
*) x86=0 ;;
esac
for port in scalar sse2 avx2 avx512 neon; do
    obj=$(obj_of $port)
    [ -f "$obj" ] || continue
    lanes=$(lanes_of $port)
    for k in $kernels; do
        sz=$(nm -S --defined-only "$obj" 2>/dev/null | awk -v s="batch_${k}_" '$4 == s { print $2 }')
        [ -n "$sz" ] && echo "f32 $port $k $(printf '%d' "0x$sz")" >> "$out/size.tsv"
        if [ $x86 = 1 ] && command -v llvm-mca >/dev/null 2>&1; then
            sh bench/report/mca.sh objdump "$obj" "batch_${k}_" x86_64 znver3 skylake |
                while read -r cpu cyc; do
                    echo "$port $k $cpu $(awk -v c="$cyc" -v l="$lanes" 'BEGIN { printf "%.3f", c / l }')"
                done >> "$out/mca.tsv"
        fi
    done
    echo "report: llvm-mca + sizes: $port done"
done

# ---- Cortex-M: fixed point and soft-float f32, traced under qemu -----------
# (bench/cortexm/cortexm.sh: executed-instruction counts, llvm-mca on the executed
# trace, Cortex-M0 TRM timings; every figure labelled measured or modelled)
echo "report: Cortex-M traces (qemu-system-arm) + llvm-mca ..."
sh bench/cortexm/cortexm.sh "$build" "$out/arm.tsv"

echo "report: measuring (benchmarks, tradeoffs, pictures, rasterizer) ..."
"$bin" report "$out" ${FACET_REPORT_QUICK:+--quick}
