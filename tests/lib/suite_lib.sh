# lib.sh - helpers for the suites (sourced).

# run_build_and_tests BUILD_DIR LABEL CC CFLAGS
# Builds lib + tests into BUILD_DIR and runs every build/tests/test_* and
# tests/*/test_*.sh; a build failure counts as one failure.
run_build_and_tests() {
    dir=$1 label=$2 cc=$3 cflags=$4
    mkdir -p "$dir"
    if ! $MAKE -s -j"$JOBS" BUILD="$dir" CC="$cc" CFLAGS="$cflags" tests >"$dir/build.log" 2>&1; then
        mkdir -p "$dir"
        cat "$dir/build.log"
        echo "ERROR $label: build failed (log: $dir/build.log)"
        return
    fi
    for t in "$dir"/tests/test_*; do
        [ -x "$t" ] || continue
        run_one "$label" "$t"
    done
    for t in tests/*/test_*.sh; do
        [ -f "$t" ] || continue
        run_one "$label" sh "$t" "$dir"
    done
}

# run_one LABEL CMD...: runs a test; a crash or a missing summary line fails.
run_one() {
    label=$1
    shift
    out=$("$@" 2>&1)
    rc=$?
    printf '%s\n' "$out" | sed "s|^|[$label] |" | grep -vE ': [0-9]+ passed, [0-9]+ failed, [0-9]+ skipped$' | grep -E '^\[.*\] (FAIL|SKIP)' || true
    summary=$(printf '%s\n' "$out" | grep -E ': [0-9]+ passed, [0-9]+ failed, [0-9]+ skipped$' | tail -n 1)
    if [ -n "$summary" ]; then
        echo "$label/$summary"
    fi
    if [ -z "$summary" ] || { [ $rc -ne 0 ] && ! printf '%s' "$summary" | grep -qE '[1-9][0-9]* failed'; }; then
        printf '%s\n' "$out" | tail -n 20
        echo "ERROR $label: $* exited with status $rc"
    fi
}
