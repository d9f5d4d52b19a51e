#!/bin/sh
# test_fx_cli.sh BUILD_DIR - the fixed-point face of the facet command:
# eval --format fx [--raw], vectors --format fx [--count] [--seed] [--hex],
# agreement between the two, and the error exits.  FACET_EXEC runs the
# binary under an emulator (qemu-user) when set.
facet="${FACET_EXEC:+$FACET_EXEC }${1:-build}/facet"
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL fx_cli: $*"; }
expect() { if [ "$2" = "$3" ]; then ok; else bad "$1: expected '$2', got '$3'"; fi; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

expect "F(0.04, 1) is f0 rounded to Q15" "0.040008544921875" "$(echo '0.04 1' | $facet eval fresnel_schlick --format fx)"
expect "D(1, alpha_min) raw" "2734261102" "$(echo '1 0.0009765625' | $facet eval ggx_d --format fx --raw)"
expect "D(1, alpha_min) value" "333772.107177734375" "$(echo '1 0.0009765625' | $facet eval ggx_d --format fx)"
expect "G1(1, a) = 1" "1" "$(echo '1 0.3' | $facet eval smith_g1 --format fx)"
expect "ties up: 0.5/32768 -> raw 1" "1" "$(echo '0.0000152587890625 1' | $facet eval fresnel_schlick --format fx --raw)"
expect "out of range clamps" "$(echo '1 1' | $facet eval smith_g1 --format fx --raw)" "$(echo '7 1e9' | $facet eval smith_g1 --format fx --raw)"

$facet list > "$tmp/list"
while read -r name rest; do
    n=$(echo $rest | wc -w)
    [ "$name" = lambert ] && continue # not in the fx table (not a core kernel)
    line=$(yes 0.5 | head -n "$n" | tr '\n' ' ')
    out=$(echo "$line" | $facet eval "$name" --format fx); rc=$?
    expect "eval $name exit" 0 $rc
    echo "$out" | grep -qE '^[0-9]+(\.[0-9]+)?$' && ok || bad "eval $name --format fx printed '$out'"
    # vectors: header + 6*(n + 8) + 2 edge vectors + count random, each eval-consistent
    $facet vectors "$name" --format fx --count 50 --seed 7 > "$tmp/v" || bad "vectors $name exit $?"
    expect "vectors $name lines" $((1 + n * 14 + 2 + 50)) "$(wc -l < "$tmp/v")"
    grep -v '^#' "$tmp/v" | awk -v n="$n" '{ s = ""; for (i = 1; i <= n; i++) s = s sprintf("%.17g ", $i / 32768); print s }' > "$tmp/in"
    grep -v '^#' "$tmp/v" | awk '{ print $NF }' > "$tmp/want"
    $facet eval "$name" --format fx --raw < "$tmp/in" > "$tmp/got"
    cmp -s "$tmp/want" "$tmp/got" && ok || bad "vectors $name disagree with eval --raw"
    $facet vectors "$name" --format fx --count 5 --hex > "$tmp/h"
    width=$(( 8 * (n + 1) )); [ "$name" = brdf_hammon ] && width=$((width + 8))
    expect "hex $name width" "" "$(grep -v '^//' "$tmp/h" | awk -v w=$width 'length($0) != w || $0 !~ /^[0-9a-f]+$/')"
done < "$tmp/list"
expect "same seed, same vectors" "$($facet vectors smith_g2 --format fx --seed 3 --count 9 | md5sum)" \
       "$($facet vectors smith_g2 --format fx --seed 3 --count 9 | md5sum)"

echo 'nan 0.5' | $facet eval ggx_d --format fx > /dev/null 2>&1; expect "nan exit" 2 $?
printf '0.5 0.5\n0.5 x\n' | $facet eval ggx_d --format fx > /dev/null 2> "$tmp/err"; expect "malformed exit" 2 $?
grep -q 'line 2' "$tmp/err" && ok || bad "malformed: stderr lacks 'line 2'"
$facet vectors ggx_d > /dev/null 2>&1; expect "vectors without --format fx" 2 $?
$facet vectors nope --format fx > /dev/null 2>&1; expect "vectors unknown kernel" 2 $?
$facet vectors ggx_d --format fx --count -1 > /dev/null 2>&1; expect "vectors bad count" 2 $?
$facet eval ggx_d --format fx --bogus < /dev/null > /dev/null 2>&1; expect "eval fx bad option" 2 $?

echo "fx_cli: $pass passed, $fail failed, 0 skipped"
[ $fail -eq 0 ]
