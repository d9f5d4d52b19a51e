#!/bin/sh
# test_install.sh BUILD_DIR - `make install` into a staging directory puts
# the headers, both libraries, a pkg-config file, the CMake package config
# and the facet command where they belong; the installed facet runs, and a
# program builds against the installed copy using what the .pc file says;
# `make uninstall` with the same DESTDIR leaves nothing.  Then a real
# install into a prefix under BUILD_DIR that already holds other packages'
# files: a program builds with pkg-config, a CMake project with
# find_package(facet CONFIG) links facet::facet and facet::facet_static
# (cmake: skipped with the reason when it is not installed) and a version
# the package does not provide is refused; `make uninstall` then leaves the
# prefix exactly as it was (the other files and directories, nothing more).
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
files="include/facet.h include/facet/scalar.h include/facet/oracle.h include/facet/common.h include/facet/fx.h
       include/facet/detail/f32_body.h lib/libfacet.a lib/libfacet.so lib/libfacet.so.0 lib/pkgconfig/facet.pc
       lib/cmake/facet/facet-config.cmake lib/cmake/facet/facet-config-version.cmake bin/facet"
for f in $files; do
    [ -e "$root/$f" ] && ok || bad "missing $f"
done
[ -e "$root/bin/facet-bench" ] && bad "bin/facet-bench installed (the bench is not)" || ok
"$root/bin/facet" list 2>&1 | grep -q '^lambert albedo$' && ok || bad "installed facet list: $("$root/bin/facet" list 2>&1 | head -3)"
pc=$root/lib/pkgconfig/facet.pc
ver=$(sed -n 's/^Version: //p' "$pc")
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
grep -q '^set(PACKAGE_VERSION "'"$ver"'")$' "$root/lib/cmake/facet/facet-config-version.cmake" && ok ||
    bad "facet-config-version.cmake: $(grep 'PACKAGE_VERSION "' "$root/lib/cmake/facet/facet-config-version.cmake")"
if ${MAKE:-make} -s BUILD="$build" uninstall DESTDIR="$stage" PREFIX="$prefix" > "$stage.log" 2>&1; then ok; else
    bad "make uninstall failed: $(cat "$stage.log")"; fi
rm -f "$stage.log"
left=$(cd "$root" && find . -mindepth 1)
[ -z "$left" ] && ok || bad "make uninstall left: $(echo $left)"

# ---- a real prefix under BUILD_DIR, with other packages' files in it --------
skip=0
prefix=$(cd "$build" && pwd)/install-test
rm -rf "$prefix"
mkdir -p "$prefix/bin" "$prefix/include" "$prefix/lib/pkgconfig" "$prefix/lib/cmake/other" "$prefix/share"
echo other > "$prefix/bin/other-tool"
echo '/* other */' > "$prefix/include/other.h"
echo 'Name: other' > "$prefix/lib/pkgconfig/other.pc"
echo '# other' > "$prefix/lib/cmake/other/other-config.cmake"
before=$(cd "$prefix" && find . | sort)
if ${MAKE:-make} -s BUILD="$build" install PREFIX="$prefix" > "$build/install-test.log" 2>&1; then ok; else
    bad "make install PREFIX=$prefix failed: $(cat "$build/install-test.log")"; fi
for f in $files; do [ -e "$prefix/$f" ] && ok || bad "missing $prefix/$f"; done
cat > "$stage/use.c" <<'C'
#include <stdio.h>
#include <facet.h>
#include <facet/oracle.h>
int main(void)
{
    float f = facet_lambert_f32(0.5f);
    double o = facet_oracle_lambert(0.5);
    printf("%.9g %.17g\n", f, o);
    return !(f > 0.159f && f < 0.16f && o > 0.159 && o < 0.16);
}
C
if command -v pkg-config > /dev/null 2>&1; then
    if PKG_CONFIG_PATH=$prefix/lib/pkgconfig ${CC:-cc} $(PKG_CONFIG_PATH=$prefix/lib/pkgconfig pkg-config --cflags facet) \
           -o "$stage/use-pc" "$stage/use.c" $(PKG_CONFIG_PATH=$prefix/lib/pkgconfig pkg-config --libs facet) \
           -Wl,-rpath,"$prefix/lib" && "$stage/use-pc" > /dev/null; then ok
    else bad "a program does not build or run with pkg-config --cflags --libs facet"; fi
else
    echo "SKIP install: pkg-config not installed (apt-get install pkg-config)"; skip=$((skip + 1))
fi
if command -v cmake > /dev/null 2>&1; then
    mkdir -p "$stage/cm"
    cp "$stage/use.c" "$stage/cm/use.c"
    cat > "$stage/cm/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.13)
project(facet_consumer C)
find_package(facet 0.1 CONFIG REQUIRED)
message(STATUS "facet ${facet_VERSION} from ${facet_DIR}")
add_executable(use_shared use.c)
target_link_libraries(use_shared PRIVATE facet::facet)
add_executable(use_static use.c)
target_link_libraries(use_static PRIVATE facet::facet_static)
CMAKE
    if cmake -S "$stage/cm" -B "$stage/cm/build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_C_COMPILER="${CC:-cc}" \
           > "$stage/cm.log" 2>&1 && cmake --build "$stage/cm/build" >> "$stage/cm.log" 2>&1; then ok
    else bad "CMake consumer does not configure or build: $(tail -n 15 "$stage/cm.log")"; fi
    grep -q "facet $ver from $prefix/lib/cmake/facet" "$stage/cm.log" && ok ||
        bad "find_package(facet) did not find $prefix/lib/cmake/facet: $(grep 'facet ' "$stage/cm.log")"
    for t in use_shared use_static; do
        "$stage/cm/build/$t" > /dev/null 2>&1 && ok || bad "CMake consumer $t does not run"
    done
    # linked against the installed libfacet.so, not a copy in the build tree
    ldd "$stage/cm/build/use_shared" 2>/dev/null | grep -q "libfacet.so.0 => $prefix/lib/libfacet.so.0" && ok ||
        bad "use_shared does not load $prefix/lib/libfacet.so.0: $(ldd "$stage/cm/build/use_shared" 2>&1 | grep facet)"
    nm "$stage/cm/build/use_static" | grep -q ' T facet_lambert_f32$' && ok || bad "use_static has no facet_lambert_f32 of its own"
    # a version the package does not provide is refused
    sed 's/find_package(facet 0.1 /find_package(facet 9.0 /' "$stage/cm/CMakeLists.txt" > "$stage/cm/v.txt"
    mv "$stage/cm/v.txt" "$stage/cm/CMakeLists.txt"
    if cmake -S "$stage/cm" -B "$stage/cm/build9" -DCMAKE_PREFIX_PATH="$prefix" > "$stage/cm9.log" 2>&1; then
        bad "find_package(facet 9.0) accepted version $ver"
    else
        grep -q "facet-config.cmake, version: $ver\$" "$stage/cm9.log" && ok || bad "find_package(facet 9.0): $(tail -n 5 "$stage/cm9.log")"
    fi
else
    echo "SKIP install: cmake not installed (apt-get install cmake)"; skip=$((skip + 1))
fi
if ${MAKE:-make} -s BUILD="$build" uninstall PREFIX="$prefix" >> "$build/install-test.log" 2>&1; then ok; else
    bad "make uninstall PREFIX=$prefix failed: $(cat "$build/install-test.log")"; fi
after=$(cd "$prefix" && find . | sort)
if [ "$before" = "$after" ]; then ok; else
    bad "make uninstall did not restore $prefix: $(printf '%s\n' "$before" > "$stage/b"; printf '%s\n' "$after" | diff "$stage/b" - | grep '^[<>]' | tr '\n' ' ')"; fi
rm -rf "$prefix"
echo "install: $pass passed, $fail failed, $skip skipped"
[ $fail -eq 0 ]
