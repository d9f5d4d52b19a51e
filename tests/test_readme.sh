#!/bin/sh
# test_readme.sh BUILD_DIR - every C block in README.md preceded by a line
# "<!-- compiled by tests: NAME -->" is extracted, compiled with the
# project's warning flags against the built library, and run; it must exit 0.
build=${1:-build}
cc=${CC:-cc}
case "$build" in *clang*) cc=clang ;; esac
pass=0 fail=0 skip=0
target=$($cc -dumpmachine)
dir=$build/readme
mkdir -p "$dir"
names=$(sed -n 's/^<!-- compiled by tests: \([a-z0-9_]*\) -->$/\1/p' README.md)
[ -n "$names" ] || { echo "FAIL readme: no compiled examples found"; fail=1; }
for n in $names; do
    awk -v n="$n" '
        $0 == "<!-- compiled by tests: " n " -->" { want = 1; next }
        want && /^```c$/ { inside = 1; next }
        inside && /^```$/ { exit }
        inside { print }' README.md > "$dir/$n.c"
    flags="-std=c99 -Wall -Wextra -Werror -Iinclude"
    case "$build" in *asan*) flags="$flags -fsanitize=address,undefined" ;; esac
    if grep -q '^// cflags: -m' "$dir/$n.c" && ! case $target in x86_64*|i?86*) true ;; *) false ;; esac; then
        echo "SKIP readme: example $n needs x86 ISA flags; this target is $target"; skip=$((skip + 1))
    elif [ ! -s "$dir/$n.c" ]; then
        echo "FAIL readme: example $n is empty"; fail=$((fail + 1))
    elif ! $cc $flags $(sed -n 's|^// cflags: ||p' "$dir/$n.c") -o "$dir/$n" "$dir/$n.c" "$build/libfacet.a" -lm 2> "$dir/$n.err"; then
        echo "FAIL readme: example $n does not compile:"; cat "$dir/$n.err"; fail=$((fail + 1))
    elif ! "$dir/$n" > "$dir/$n.out" 2>&1; then
        echo "FAIL readme: example $n exited non-zero:"; cat "$dir/$n.out"; fail=$((fail + 1))
    else
        pass=$((pass + 1))
    fi
done
echo "readme: $pass passed, $fail failed, $skip skipped"
[ $fail -eq 0 ]
