# The same tests under AddressSanitizer + UndefinedBehaviorSanitizer; any
# report aborts the test, which then counts as failed.
. tests/lib/suite_lib.sh
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
FACET_TEST_QUICK=1 run_build_and_tests build/asan asan "${CC:-cc}" \
    "-O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
