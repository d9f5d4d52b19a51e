#!/bin/sh
# bench/report/sample_chi2.sh BUILD_DIR OUT_DIR - the samplers' chi-square
# table for the report: builds and runs tests/sample/test_sample_chi2.c (its
# markdown output, 10^6 samples per configuration; 2 10^5 with
# FACET_REPORT_QUICK) into OUT_DIR/sample_chi2.txt, which `facet-bench
# report` puts in the "Importance sampling" section.  A failed check is in
# the table and its last line, and said here; the report goes on (make
# check is what fails on it).
set -u
build=${1:-build}
out=${2:-$build/report}
mkdir -p "$out"
${MAKE:-make} -s BUILD="$build" "$build/tests/test_sample_chi2" || exit 1
echo "report: chi-square goodness of fit of the samplers (tests/sample/test_sample_chi2.c) ..."
if [ -n "${FACET_REPORT_QUICK:-}" ]; then
    FACET_TEST_QUICK=1 "$build/tests/test_sample_chi2" > "$out/sample_chi2.txt"
else
    "$build/tests/test_sample_chi2" > "$out/sample_chi2.txt"
fi || echo "report: tests/test_sample_chi2 FAILED a check (see $out/sample_chi2.txt)"
exit 0
