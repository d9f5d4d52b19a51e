#!/bin/sh
# check.sh - `make check`: runs every suite in tests/suites/ (in name order)
# and sums their summary lines ("<name>: N passed, N failed, N skipped")
# into the closing line.  A suite that cannot run here (no clang, no cross
# toolchain) reports itself skipped with the reason.  Under CI=true a skip
# whose reason says a tool is "not installed" or "missing" fails the run,
# because .ci/run installs every tool; skips for what a target cannot do (a
# CPU without AVX2, a libc without 80-bit long double) stay skips.
# Environment: MAKE, JOBS (parallel builds), FACET_SUITES (glob filter).
set -u
cd "$(dirname "$0")/.." || exit 2
MAKE=${MAKE:-make}
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
export MAKE JOBS
mkdir -p build
log=$(mktemp build/check.XXXXXX.log) # private: concurrent runs must not mix
ln -sf "$(basename "$log")" build/check.log
start=$(date +%s)
for s in tests/suites/${FACET_SUITES:-*}.sh; do
    [ -f "$s" ] || continue
    name=$(basename "$s" .sh)
    printf '== %s\n' "$name"
    sh "$s" 2>&1 | tee -a "$log" | grep -E '(FAIL|SKIP|ERROR)|: [0-9]+ passed, [0-9]+ failed, [0-9]+ skipped$'
done
awk -v ci="${CI:-}" '
/: [0-9]+ passed, [0-9]+ failed, [0-9]+ skipped$/ {
    n = split($0, w, " "); p += w[n-5]; f += w[n-3]; s += w[n-1]
}
/^ERROR / { f++ }
/SKIP .*(not installed|missing)/ { missing++ }
END {
    if (ci == "true" && missing > 0) { print "CI: " missing " checks skipped for a missing tool count as failures"; f += missing }
    printf "%d passed, %d failed, %d skipped\n", p, f, s
    exit (f > 0)
}' "$log"
rc=$?
echo "(check took $(( $(date +%s) - start )) s; full log: $log)"
exit $rc
