#!/bin/sh
# test_fx_cli.sh BUILD_DIR - the fixed-point face of the facet command:
# eval --format fx|fx_fast [--raw], vectors --format fx|fx_fast [--count]
# [--seed] [--hex], agreement between the two, list --formats, and the
# error exits.  FACET_EXEC runs the
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
$facet list --formats > "$tmp/formats"
expect "lambert has no fixed-point version" "lambert f32 f32_fast f16" "$(grep '^lambert ' "$tmp/formats")"
while read -r name rest; do
    n=$(echo $rest | wc -w)
    if ! grep -qE "^$name .* fx( |$)" "$tmp/formats"; then
        # no precise fixed-point kernel (lambert, the f32-only menu kernels,
        # the fast-tier-only ones): --format fx refused
        case "$rest" in *'->'*) continue ;; esac
        echo "$(yes 0.5 | head -n "$n" | tr '\n' ' ')" | $facet eval "$name" --format fx > /dev/null 2>&1
        expect "eval $name --format fx refused (no precise fixed-point version)" 2 $?
        grep -qE "^$name .* fx_fast( f16)?$" "$tmp/formats" || continue
        # the fast tier only: vectors --format fx refused too, fx_fast works
        $facet vectors "$name" --format fx --count 1 > /dev/null 2> "$tmp/err"
        expect "vectors $name --format fx refused (fast tier only)" 2 $?
        grep -q 'only the fast' "$tmp/err" && ok || bad "vectors $name --format fx: '$(cat "$tmp/err")'"
        $facet vectors "$name" --format fx_fast --count 50 --seed 7 > "$tmp/vf" || bad "vectors $name --format fx_fast exit $?"
        grep -v '^#' "$tmp/vf" | awk -v n="$n" '{ s = ""; for (i = 1; i <= n; i++) s = s sprintf("%.17g ", $i / 32768); print s }' > "$tmp/in"
        grep -v '^#' "$tmp/vf" | awk '{ print $NF }' > "$tmp/wantf"
        $facet eval "$name" --format fx_fast --raw < "$tmp/in" > "$tmp/gotf"
        cmp -s "$tmp/wantf" "$tmp/gotf" && ok || bad "vectors $name --format fx_fast disagree with eval --format fx_fast --raw"
        continue
    fi
    case "$rest" in *'->'*) continue ;; esac # a sampler (f32 only)
    line=$(yes 0.5 | head -n "$n" | tr '\n' ' ')
    out=$(echo "$line" | $facet eval "$name" --format fx); rc=$?
    expect "eval $name exit" 0 $rc
    echo "$out" | grep -qE '^[0-9]+(\.[0-9]+)?$' && ok || bad "eval $name --format fx printed '$out'"
    # vectors: header + the distinct edge vectors + count random, each eval-consistent
    $facet vectors "$name" --format fx --count 50 --seed 7 > "$tmp/v" || bad "vectors $name exit $?"
    $facet vectors "$name" --count 0 > "$tmp/v0" || bad "vectors $name --count 0 exit $?"
    expect "vectors $name: edge vectors distinct" "" "$(grep -v '^#' "$tmp/v0" | sort | uniq -d)"
    expect "vectors $name: every input takes the 8 special raw values" $((n * 8)) \
        "$(grep -v '^#' "$tmp/v0" | awk -v n="$n" '{ for (i = 1; i <= n; i++) print i, $i }' | sort -u |
           grep -cE ' (-2147483648|-1|0|1|32767|32768|32769|2147483647)$')"
    expect "vectors $name lines" $(($(wc -l < "$tmp/v0") + 50)) "$(wc -l < "$tmp/v")"
    grep -v '^#' "$tmp/v" | awk -v n="$n" '{ s = ""; for (i = 1; i <= n; i++) s = s sprintf("%.17g ", $i / 32768); print s }' > "$tmp/in"
    grep -v '^#' "$tmp/v" | awk '{ print $NF }' > "$tmp/want"
    $facet eval "$name" --format fx --raw < "$tmp/in" > "$tmp/got"
    cmp -s "$tmp/want" "$tmp/got" && ok || bad "vectors $name disagree with eval --raw"
    # the fast tier: the same input vectors, its outputs agree with its eval
    $facet vectors "$name" --format fx_fast --count 50 --seed 7 > "$tmp/vf" || bad "vectors $name --format fx_fast exit $?"
    expect "vectors $name fx_fast: the same inputs as fx" "$(awk '!/^#/ { $NF = ""; print }' "$tmp/v")" \
        "$(awk '!/^#/ { $NF = ""; print }' "$tmp/vf")"
    grep -v '^#' "$tmp/vf" | awk '{ print $NF }' > "$tmp/wantf"
    $facet eval "$name" --format fx_fast --raw < "$tmp/in" > "$tmp/gotf"
    cmp -s "$tmp/wantf" "$tmp/gotf" && ok || bad "vectors $name --format fx_fast disagree with eval --format fx_fast --raw"
    $facet vectors "$name" --format fx --count 5 --hex > "$tmp/h"
    width=$(( 8 * (n + 1) )); [ "$name" = brdf_hammon ] && width=$((width + 8))
    expect "hex $name width" "" "$(grep -v '^//' "$tmp/h" | awk -v w=$width 'length($0) != w || $0 !~ /^[0-9a-f]+$/')"
done < "$tmp/list"
# ggx_d: 2 x 14 + 2 edge vectors, of which 9 repeat others (e.g. noh = 0 is
# both the domain end and the special value 0)
expect "ggx_d: 21 distinct edge vectors" 21 "$($facet vectors ggx_d --count 0 | grep -vc '^#')"
expect "same seed, same vectors" "$($facet vectors smith_g2 --format fx --seed 3 --count 9 | md5sum)" \
       "$($facet vectors smith_g2 --format fx --seed 3 --count 9 | md5sum)"

echo 'nan 0.5' | $facet eval ggx_d --format fx > /dev/null 2>&1; expect "nan exit" 2 $?
printf '0.5 0.5\n0.5 x\n' | $facet eval ggx_d --format fx > /dev/null 2> "$tmp/err"; expect "malformed exit" 2 $?
grep -q 'line 2' "$tmp/err" && ok || bad "malformed: stderr lacks 'line 2'"
$facet vectors ggx_d > /dev/null 2>&1; expect "vectors without --format (fx is the default)" 0 $?
$facet vectors ggx_d --format f32 > /dev/null 2>&1; expect "vectors --format f32" 2 $?
$facet vectors ggx_d --format fx_fast --count 0 | head -1 > "$tmp/hdr"
grep -q 'fx_fast output' "$tmp/hdr" && ok || bad "vectors --format fx_fast header does not name the tier: $(cat "$tmp/hdr")"
expect "list --formats: fixed-point kernels" "brdf_hammon f32 f32_fast fx fx_fast f16" "$($facet list --formats | grep '^brdf_hammon ')"
expect "list --formats: lambert" "lambert f32 f32_fast f16" "$($facet list --formats | grep '^lambert ')"
expect "eval --format f32_fast" 1 "$(echo '0.5 0.25' | $facet eval ggx_d --format f32_fast | grep -cE '^0\.0339[0-9]+$')"
echo '0.5 0.25' | $facet eval ggx_d --format fx_slow > /dev/null 2>&1; expect "eval unknown format" 2 $?
$facet vectors nope --format fx > /dev/null 2>&1; expect "vectors unknown kernel" 2 $?
$facet vectors ggx_d --format fx --count -1 > /dev/null 2>&1; expect "vectors bad count" 2 $?
$facet eval ggx_d --format fx --bogus < /dev/null > /dev/null 2>&1; expect "eval fx bad option" 2 $?

# decimal -> Q15 rounded once, exactly from the digits (not via double)
expect "just below a tie rounds down" "16384" "$(echo '0.50001525878906249999999 1' | $facet eval fresnel_schlick --format fx --raw)"
expect "a tie rounds up" "16385" "$(echo '0.500015258789062500 1' | $facet eval fresnel_schlick --format fx --raw)"
expect "just above a tie rounds up" "16385" "$(echo '0.50001525878906250000001 1' | $facet eval fresnel_schlick --format fx --raw)"
# finite values saturate, however large; only NaN and infinities are refused
expect "1e301 saturates (clamps to 1)" "$(echo '1 0.5' | $facet eval ggx_d --format fx --raw)" \
    "$(echo '1e301 0.5' | $facet eval ggx_d --format fx --raw 2>&1)"
expect "-1e999999 saturates (clamps to 0)" "$(echo '0 0.5' | $facet eval ggx_d --format fx --raw)" \
    "$(echo '-1e999999 0.5' | $facet eval ggx_d --format fx --raw 2>&1)"
echo 'inf 0.5' | $facet eval ggx_d --format fx > /dev/null 2>&1; expect "inf exit" 2 $?
echo '0.5 -Infinity' | $facet eval ggx_d --format fx > /dev/null 2>&1; expect "-Infinity exit" 2 $?
# the input rules are those of --format f32
expect "fx: blank and comment lines skipped" "1" "$(printf '# x\n\n1 0.3\n' | $facet eval smith_g1 --format fx)"
printf '1 0.3\0junk' | $facet eval smith_g1 --format fx > /dev/null 2> "$tmp/err"; expect "fx NUL exit" 2 $?
grep -q 'line 1: contains a NUL byte' "$tmp/err" && ok || bad "fx NUL: $(cat "$tmp/err")"
$facet eval lambert --format fx < /dev/null > /dev/null 2> "$tmp/err"; expect "lambert fx exit" 2 $?
grep -q 'no fixed-point form' "$tmp/err" && ok || bad "lambert fx: $(cat "$tmp/err")"
$facet vectors smith_g11 < /dev/null > /dev/null 2> "$tmp/err"; expect "vectors typo exit" 2 $?
grep -q "did you mean 'smith_g1'" "$tmp/err" && ok || bad "vectors typo: $(cat "$tmp/err")"

# --count and --seed: decimal digits only, within the documented limits
# (a refused value prints nothing; " -1" used to stream 2^64 - 1 vectors, hence head)
for c in " -1" "-1" "+5" "010x" "0x10" " 5" "5 " "" "1000000001" "99999999999999999999999"; do
    n=$({ $facet vectors ggx_d --format fx --count "$c" 2> /dev/null; echo $? > "$tmp/rc"; } | head -n 40 | wc -l)
    expect "vectors --count '$c' exit" 2 "$(cat "$tmp/rc")"
    expect "vectors --count '$c' prints nothing" 0 "$n"
done
expect "--count 010 is ten" "10" "$($facet vectors ggx_d --format fx --count 010 | head -n 1 | sed 's/.*, \([0-9]*\) random$/\1/')"
for s in " -1" "-1" "0x10" "18446744073709551616" "1e3"; do
    $facet vectors ggx_d --format fx --count 1 --seed "$s" > /dev/null 2>&1; expect "vectors --seed '$s'" 2 $?
done
$facet vectors ggx_d --count 1 --seed 18446744073709551615 > /dev/null 2>&1; expect "vectors --seed 2^64 - 1" 0 $?
$facet vectors ggx_d --count 0 > /dev/null 2>&1; expect "vectors --count 0" 0 $?

echo "fx_cli: $pass passed, $fail failed, 0 skipped"
[ $fail -eq 0 ]
