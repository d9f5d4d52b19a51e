#!/bin/sh
# check.sh - `make check`: runs every suite in tests/suites/ and sums their
# summary lines ("<name>: N passed, N failed, N skipped") into the closing
# line.  A suite that cannot run here (no clang, no cross toolchain) reports
# itself skipped with the reason.  Under CI=true a skip whose reason says a
# tool is "not installed" or "missing" fails the run, because .ci/run
# installs every tool; skips for what a target cannot do (a CPU without AVX2,
# a libc without 80-bit long double) stay skips.
#
# Two lanes: the suites marked "# lane: emulators" (cross builds run under
# qemu, each in its own build directory, one emulator process at a time) run
# beside the host suites, which run in name order; on 2 cores that halves
# the wall time, because most of either lane is one single-threaded test
# process.  FACET_SERIAL=1 runs every suite in name order, one at a time.
# Each suite's output is printed when it finishes, with its time.
# Environment: MAKE, JOBS (parallel builds), FACET_SUITES (glob filter),
# FACET_SERIAL.
set -u
cd "$(dirname "$0")/.." || exit 2
MAKE=${MAKE:-make}
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
export MAKE JOBS
mkdir -p build
log=$(mktemp build/check.XXXXXX.log) # private: concurrent runs must not mix
ln -sf "$(basename "$log")" build/check.log
logs=$(mktemp -d build/check.XXXXXX.d)
start=$(date +%s)

# run_suite FILE: runs one suite into $logs/<name>.log, then prints its
# failures, skips and summary lines under a header with its time
run_suite() {
    name=$(basename "$1" .sh)
    t0=$(date +%s)
    sh "$1" > "$logs/$name.log" 2>&1
    printf '== %s (%d s)\n' "$name" $(($(date +%s) - t0)) > "$logs/$name.head"
    { cat "$logs/$name.head"
      grep -E '(FAIL|SKIP|ERROR)|: [0-9]+ passed, [0-9]+ failed, [0-9]+ skipped$' "$logs/$name.log"
    } > "$logs/$name.out"
}

host="" emu=""
for s in tests/suites/${FACET_SUITES:-*}.sh; do
    [ -f "$s" ] || continue
    if [ "${FACET_SERIAL:-0}" != 1 ] && grep -q '^# lane: emulators' "$s"; then
        emu="$emu $s"
    else
        host="$host $s"
    fi
done
emu_pid=""
if [ -n "$emu" ]; then
    (for s in $emu; do run_suite "$s"; done) &
    emu_pid=$!
fi
for s in $host; do
    run_suite "$s"
    cat "$logs/$(basename "$s" .sh).out"
done
if [ -n "$emu_pid" ]; then
    wait "$emu_pid"
    for s in $emu; do cat "$logs/$(basename "$s" .sh).out"; done
fi
# the full log, in suite name order
for s in tests/suites/${FACET_SUITES:-*}.sh; do
    [ -f "$s" ] || continue
    n=$(basename "$s" .sh)
    [ -f "$logs/$n.log" ] && { cat "$logs/$n.head"; cat "$logs/$n.log"; }
done > "$log"
rm -rf "$logs"

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
