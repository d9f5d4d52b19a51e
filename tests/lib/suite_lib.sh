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

# doc_rows_miss DOC ROWS: prints the first line of the file ROWS that does
# not occur in DOC (status 1), or nothing (status 0)
doc_rows_miss() {
    while IFS= read -r r; do grep -qF -- "$r" "$1" || { printf '%s\n' "$r"; return 1; }; done < "$2"
}

# doc_rows LABEL TABLE ROWS BREAK ROW BROKEN: the measured table rows in
# the file ROWS must each occur in ports/README.md's TABLE, and must not all
# occur in a copy (written to BROKEN) whose ROW row has a figure changed by
# the sed expression BREAK (so the comparison can fail).  Prints
# "FAIL LABEL: ..." for each failure and returns their count (0, 1 or 2 of
# the 2 checks).
doc_rows() {
    doc_rows_fails=0
    if ! doc_rows_m=$(doc_rows_miss ports/README.md "$3"); then
        doc_rows_fails=$((doc_rows_fails + 1))
        echo "FAIL $1: ports/README.md's $2 lacks the measured row: $doc_rows_m"
    fi
    sed "$4" ports/README.md > "$6"
    if cmp -s ports/README.md "$6"; then
        doc_rows_fails=$((doc_rows_fails + 1))
        echo "FAIL $1: self-test: no $5 row to break"
    elif doc_rows_miss "$6" "$3" > /dev/null; then
        doc_rows_fails=$((doc_rows_fails + 1))
        echo "FAIL $1: self-test: a changed figure passes the comparison"
    fi
    return $doc_rows_fails
}
