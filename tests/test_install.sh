#!/bin/sh
# test_install.sh BUILD_DIR - `make install` into a staging directory puts
# the headers, both libraries, a pkg-config file and the facet command where
# they belong; the installed facet runs, and a program builds against the
# installed copy using what the .pc file says.
build=${1:-build}
case "$build" in *asan*|*clang*) echo "install: 0 passed, 0 failed, 0 skipped"; exit 0 ;; esac
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL install: $*"; }
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
prefix=/opt/facet-test
if ${MAKE:-make} -s BUILD="$build" install DESTDIR="$stage" PREFIX="$prefix" > "$stage.log" 2>&1; then ok; else
    bad "make install failed: $(cat "$stage.log")"; fi
rm -f "$stage.log"
root=$stage$prefix
for f in include/facet.h include/facet/scalar.h include/facet/oracle.h include/facet/common.h \
         include/facet/detail/f32_body.h lib/libfacet.a lib/libfacet.so lib/pkgconfig/facet.pc bin/facet; do
    [ -e "$root/$f" ] && ok || bad "missing $f"
done
[ -e "$root/bin/facet-bench" ] && bad "bin/facet-bench installed (the bench is not)" || ok
"$root/bin/facet" list 2>&1 | grep -q '^lambert albedo$' && ok || bad "installed facet list: $("$root/bin/facet" list 2>&1 | head -3)"
pc=$root/lib/pkgconfig/facet.pc
grep -q "^prefix=$prefix\$" "$pc" && ok || bad "facet.pc prefix: $(grep prefix= "$pc")"
grep -qE '^Version: [0-9]+\.[0-9]+\.[0-9]+$' "$pc" && ok || bad "facet.pc version: $(grep Version "$pc")"
# build against the staged tree with the flags the .pc file gives
cflags=$(sed -n 's/^Cflags: //p' "$pc" | sed "s|\${includedir}|$root/include|")
libs=$(sed -n 's/^Libs: //p' "$pc" | sed "s|\${libdir}|$root/lib|")
cat > "$stage/app.c" <<'C'
#include <facet.h>
int main(void) { return !(facet_lambert_f32(1.0f) > 0.318f); }
C
if ${CC:-cc} $cflags -o "$stage/app" "$stage/app.c" $libs -lm -Wl,-rpath,"$root/lib" && "$stage/app"; then ok; else
    bad "a program does not build or run against the installed library"; fi
echo "install: $pass passed, $fail failed, 0 skipped"
[ $fail -eq 0 ]
