#!/bin/sh
# fw_undef.sh OUT_DIR NM CC [FLAG...] -- SOURCE...: compiles each SOURCE to
# an object in OUT_DIR (CC FLAG... -c) and prints every symbol an object
# leaves undefined that none of the objects defines, as "SOURCE SYMBOL":
# a firmware build of the fixed-point sources must need nothing from libc,
# libgcc or libm (a memcpy a copy loop became, a division or float helper).
# Exit 0: none; 1: some (printed); 2: usage or a compile failed.
# Called by tests/suites/50-fx-targets.sh (fx-fw-undefined).
[ $# -ge 5 ] || { echo "usage: fw_undef.sh OUT_DIR NM CC [FLAG...] -- SOURCE..." >&2; exit 2; }
out=$1 nm=$2
shift 2
cc=
while [ $# -gt 0 ] && [ "$1" != -- ]; do cc="$cc $1"; shift; done
[ "${1:-}" = -- ] || { echo "fw_undef.sh: no -- before the sources" >&2; exit 2; }
shift
mkdir -p "$out"
: > "$out/defined"
: > "$out/undefined"
for s in "$@"; do
    o=$out/$(echo "$s" | tr '/.' '__').o
    # shellcheck disable=SC2086
    $cc -c "$s" -o "$o" || { echo "fw_undef.sh: $s does not compile:$cc" >&2; exit 2; }
    "$nm" --defined-only "$o" | awk 'NF == 3 { print $3 }' >> "$out/defined"
    "$nm" -u "$o" | awk -v s="$s" '{ print s, $NF }' >> "$out/undefined"
done
sort -u "$out/defined" > "$out/defined.sorted"
awk 'NR == FNR { d[$1] = 1; next } !($2 in d)' "$out/defined.sorted" "$out/undefined" | sort -u > "$out/missing"
cat "$out/missing"
[ ! -s "$out/missing" ]
