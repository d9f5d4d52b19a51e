#!/bin/sh
# report.sh BUILD_DIR - `make report`: the accuracy sweep (and, below, the
# benchmarks) written to BUILD_DIR/report/ (or FACET_REPORT_OUT).  This part
# writes accuracy.md, the report's head; the bench part writes bench.md and
# composes report.md and index.html from the two (a quick bench-only run,
# bench/report/report.sh, recomposes them the same way).
set -eu
build=${1:-build}
out=${FACET_REPORT_OUT:-$build/report}
mkdir -p "$out"
n=${FACET_REPORT_SAMPLES:-3000000}
make -s BUILD="$build" tests
echo "report: f32 accuracy sweep, $n random samples per kernel + grids + edges ..."
"$build/tests/test_f32_accuracy" "$n" "$out/accuracy_f32.md" > "$out/accuracy_f32.txt" || {
    cat "$out/accuracy_f32.txt"
    echo "report: accuracy sweep FAILED a bound (see $out/accuracy_f32.txt)"
    exit 1
}
{
    echo "# facet report"
    echo
    echo "Machine: $(uname -m), $(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | cut -d: -f2- | sed 's/^ *//')"
    echo "Date: $(date -u +%Y-%m-%d)  facet $(sed -n 's/^#define FACET_VERSION "\(.*\)"/\1/p' include/facet.h)"
    echo
    echo "## f32 accuracy vs the double oracle, every port this machine runs"
    echo
    echo "Maximum relative error at the same float inputs (values below 2^-100 compared absolutely), $n random samples per kernel plus grids and edges; the bound is the one facet.h documents and the tests enforce."
    echo
    cat "$out/accuracy_f32.md"
    # the Helium port's instruction counts (bench/qcount/)
    sh bench/qcount/report_md.sh
} > "$out/accuracy.md"
cp "$out/accuracy.md" "$out/report.md"
# ---- bench: benchmarks, plots, rasterizer (bench/) ------------------------
# (owned by bench/report/: writes bench.md, report.md = accuracy.md + bench.md, index.html)
if [ -f bench/report/report.sh ]; then
    FACET_REPORT_OUT=$out MAKE=${MAKE:-make} sh bench/report/report.sh "$build" || { echo "report: bench part FAILED"; exit 1; }
    echo "report: wrote $out/index.html"
fi
# ---- end bench --------------------------------------------------------------
echo "report: wrote $out/report.md"
