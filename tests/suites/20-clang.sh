# The same tests built with clang: warnings-clean and passing.
. tests/lib/suite_lib.sh
if command -v clang >/dev/null 2>&1; then
    run_build_and_tests build/clang clang clang "-O2 -g"
else
    echo "SKIP clang: clang not installed (apt-get install clang)"
    echo "clang: 0 passed, 0 failed, 1 skipped"
fi
