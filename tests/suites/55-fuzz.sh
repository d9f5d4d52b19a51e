# The libFuzzer targets (tests/fuzz/: the f32 batch API, the fixed-point
# kernels on every port, the command's line parser), each run for
# FACET_FUZZ_SECONDS (default 20) from its committed seed corpus; any
# finding fails.  `make fuzz` runs them longer.  Skipped, with the reason,
# where clang or its libFuzzer runtime is missing.
. tests/lib/suite_lib.sh
secs=${FACET_FUZZ_SECONDS:-20}
dir=build/fuzz
mkdir -p $dir
if ! command -v clang > /dev/null 2>&1; then
    echo "SKIP fuzz: clang not installed (apt-get install clang)"
    echo "fuzz: 0 passed, 0 failed, 1 skipped"
    exit 0
fi
printf '#include <stddef.h>\n#include <stdint.h>\nint LLVMFuzzerTestOneInput(const uint8_t *d, size_t n);\nint LLVMFuzzerTestOneInput(const uint8_t *d, size_t n) { (void)d; (void)n; return 0; }\n' > $dir/probe.c
if ! clang -fsanitize=fuzzer,address,undefined $dir/probe.c -o $dir/probe > $dir/probe.log 2>&1; then
    echo "SKIP fuzz: libFuzzer (clang -fsanitize=fuzzer) not installed (apt-get install libclang-rt-dev or clang's compiler-rt)"
    echo "fuzz: 0 passed, 0 failed, 1 skipped"
    exit 0
fi
if ! $MAKE -s -j"$JOBS" fuzz-build > $dir/build.log 2>&1; then
    cat $dir/build.log
    echo "ERROR fuzz: build failed (log: $dir/build.log)"
    exit 0
fi
targets=$(ls tests/fuzz/fuzz_*.c | sed 's|tests/fuzz/||; s|\.c$||')
run_one fuzz sh tests/fuzz/run.sh $dir "$secs" $targets
