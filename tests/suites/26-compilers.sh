# The firmware sources (`make fx-sources`) as a firmware team builds them:
#   strict     warning-free under -Wall -Wextra -Wconversion -Wsign-conversion
#              -Wcast-align -Wpedantic -Werror (C99), arm-none-eabi-gcc for
#              Cortex-M0, M4, M33 at -O2 and -Os, and the host gcc and clang;
#              a probe with one sign conversion must fail the same command
#              (the check can fail);
#   tcc, pcc   non-GNU C compilers: the sources and the scalar tests that
#              need nothing else (tests/fx/test_fx_hash.c: every kernel of
#              both tiers bit-exact against the pinned hashes;
#              tests/fx/test_fx_prims.c: the exact primitives) built with
#              each and run.
# A missing compiler is named and its checks skipped.
. tests/lib/suite_lib.sh
have() { command -v "$1" > /dev/null 2>&1; }
dir=build/compilers
mkdir -p $dir
srcs=$($MAKE -s fx-sources)
strict="-std=c99 -Wall -Wextra -Wconversion -Wsign-conversion -Wcast-align -Wpedantic -Werror"

pass=0 fail=0 skip=0
printf '#include <stddef.h>\nsize_t probe_(int i);\nsize_t probe_(int i) { return i; }\n' > $dir/probe.c
# strict LABEL CC FLAGS...: every firmware source compiles warning-free, the probe does not
strict() {
    label=$1 cc=$2
    shift 2
    for f in $srcs; do
        # shellcheck disable=SC2086
        if out=$($cc "$@" $strict -Iinclude -c "$f" -o $dir/strict.o 2>&1); then pass=$((pass + 1))
        else fail=$((fail + 1)); echo "FAIL strict: $label $f: $(printf '%s' "$out" | grep -m 3 -E 'error|warning' | tr '\n' ' ')"; fi
    done
    # shellcheck disable=SC2086
    if $cc "$@" $strict -c $dir/probe.c -o $dir/strict.o > /dev/null 2>&1; then
        fail=$((fail + 1)); echo "FAIL strict: $label accepts a sign conversion (the flags do not bite)"
    else pass=$((pass + 1)); fi
}
if have arm-none-eabi-gcc; then
    for cpu in cortex-m0 cortex-m4 cortex-m33; do
        for o in -O2 -Os; do strict "$cpu $o" arm-none-eabi-gcc -mcpu=$cpu -mthumb $o; done
    done
else
    echo "SKIP strict: arm-none-eabi-gcc not installed"
    skip=$((skip + 1))
fi
strict "host gcc -O2" "${CC:-cc}" -O2
if have clang; then strict "clang -O2" clang -O2
else echo "SKIP strict: clang not installed"; skip=$((skip + 1)); fi
echo "strict: $pass passed, $fail failed, $skip skipped"

# the scalar tests with a non-GNU compiler: one summary line each
for c in tcc pcc; do
    if ! have $c; then
        echo "SKIP $c: $c not installed (apt-get install $c)"
        echo "$c: 0 passed, 0 failed, 1 skipped"
        continue
    fi
    for t in fx_hash fx_prims; do
        # shellcheck disable=SC2086
        if $c -Iinclude -o $dir/test_${t}_$c tests/fx/test_$t.c $srcs -lm > $dir/$t.$c.log 2>&1; then
            run_one $c $dir/test_${t}_$c
        else
            cat $dir/$t.$c.log | grep -v 'GNU-stack\|NOTE: This' | head -n 5
            echo "ERROR $c: tests/fx/test_$t.c with the firmware sources does not build (log: $dir/$t.$c.log)"
        fi
    done
done
