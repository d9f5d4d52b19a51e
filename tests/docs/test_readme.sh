#!/bin/sh
# test_readme.sh BUILD_DIR - every C block in a README.md of the tree (the
# top one and each folder's) preceded by a line
# "<!-- compiled by tests: NAME -->" is extracted, compiled with the
# project's warning flags against the built library, and run; it must exit 0
# (NAME unique across the READMEs; the top README must have some).
# And the quick start at the top, as written: the blocks after "<!-- quick
# start: NAME -->" (install, build, app.c, CMakeLists.txt).  HOME is a
# temporary directory, so `make install PREFIX=$HOME/.local` installs there;
# the "install" block runs in this tree, the "build" block in a project
# directory holding app.c and CMakeLists.txt, each line as written: the
# pkg-config line and the CMake line must build and run app, and its output
# must be what the installed `facet eval` prints for the same inputs.  For
# the default build only (the quick start's plain `make` builds into build/);
# a missing pkg-config or cmake skips its line with the reason.
build=${1:-build}
cc=${CC:-cc}
case "$build" in *clang*) cc=clang ;; esac
pass=0 fail=0 skip=0
target=$($cc -dumpmachine)
dir=$build/readme
mkdir -p "$dir"
readmes=$(find . -name README.md ! -path './build*' ! -path './.git/*' | sed 's|^\./||' | sort)
sed -n 's/^<!-- compiled by tests: \([a-z0-9_]*\) -->$/\1/p' README.md | grep -q . ||
    { echo "FAIL readme: no compiled examples found in README.md"; fail=1; }
for f in $readmes; do
    sed -n 's/^<!-- compiled by tests: \([a-z0-9_]*\) -->$/\1/p' "$f" | sed "s|^|$f |"
done > "$dir/examples"
dups=$(awk '{ print $2 }' "$dir/examples" | sort | uniq -d)
[ -z "$dups" ] || { echo "FAIL readme: example names used twice: $dups"; fail=$((fail + 1)); }
while read -r f n; do
    awk -v n="$n" '
        $0 == "<!-- compiled by tests: " n " -->" { want = 1; next }
        want && /^```c$/ { inside = 1; next }
        inside && /^```$/ { exit }
        inside { print }' "$f" > "$dir/$n.c"
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
done < "$dir/examples"

# ---- the quick start ---------------------------------------------------------
block() { # the fenced block after "<!-- quick start: $1 -->"
    awk -v n="$1" '
        $0 == "<!-- quick start: " n " -->" { want = 1; next }
        want && /^```/ && !inside { inside = 1; next }
        inside && /^```$/ { exit }
        inside { print }' README.md
}
if [ "$build" = build ]; then
    qs=$(mktemp -d)
    mkdir -p "$qs/home" "$qs/app"
    for b in install build app.c CMakeLists.txt; do
        block $b > "$qs/$b.block"
        [ -s "$qs/$b.block" ] || { echo "FAIL readme: no quick start block \"$b\""; fail=$((fail + 1)); }
    done
    cp "$qs/app.c.block" "$qs/app/app.c"
    cp "$qs/CMakeLists.txt.block" "$qs/app/CMakeLists.txt"
    if HOME=$qs/home sh -e "$qs/install.block" > "$qs/install.log" 2>&1 && [ -x "$qs/home/.local/bin/facet" ]; then
        pass=$((pass + 1))
    else
        echo "FAIL readme: the quick start's install block:"; tail -n 20 "$qs/install.log"; fail=$((fail + 1))
    fi
    want=$(echo "0.8 0.6 0.2 0.25 0.04 0.5" | "$qs/home/.local/bin/facet" eval brdf_hammon 2>&1)
    # the build block: its first line (the environment) and then each command
    # line on its own, in the project directory
    env_line=$(sed -n 1p "$qs/build.block")
    sed -n '2,$p' "$qs/build.block" | while IFS= read -r line; do
        case $line in
        *pkg-config*) tool=pkg-config ;;
        *cmake*) tool=cmake ;;
        *) tool=sh ;;
        esac
        rm -rf "$qs/app/app" "$qs/app/b"
        if ! command -v $tool > /dev/null 2>&1; then
            echo "SKIP readme: quick start line for $tool: $tool not installed (apt-get install $tool)"; echo skip
        elif out=$(cd "$qs/app" && HOME=$qs/home sh -ec "$env_line
$line" 2>&1) && [ "$(printf '%s\n' "$out" | tail -n 1)" = "$want" ]; then
            echo pass
        else
            echo "FAIL readme: quick start: \"$line\" (want \"$want\"):"; printf '%s\n' "$out" | tail -n 15; echo fail
        fi
    done > "$qs/lines.log"
    grep -v '^\(pass\|skip\|fail\)$' "$qs/lines.log"
    n=$(grep -c '^pass$' "$qs/lines.log"); pass=$((pass + n))
    n=$(grep -c '^skip$' "$qs/lines.log"); skip=$((skip + n))
    n=$(grep -c '^fail$' "$qs/lines.log"); fail=$((fail + n))
    [ "$(grep -c '^\(pass\|skip\|fail\)$' "$qs/lines.log")" -eq 2 ] ||
        { echo "FAIL readme: the quick start's build block has not 2 command lines"; fail=$((fail + 1)); }
    # the app is the library's: same digits as `facet eval`
    case $want in 0.*) pass=$((pass + 1)) ;; *) echo "FAIL readme: installed facet eval printed \"$want\""; fail=$((fail + 1)) ;; esac
    rm -rf "$qs"
fi
echo "readme: $pass passed, $fail failed, $skip skipped"
[ $fail -eq 0 ]
