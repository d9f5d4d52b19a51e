#!/bin/sh
# test_f16_cli.sh BUILD_DIR - the f16 face of the facet command: eval
# --format f16 (inputs rounded to binary16, the result exact), the same bits
# on every port, NaN -> 0, saturation at 65504, refusals (a kernel without
# an f16 form, with its reason), list --formats and list --f16.
# FACET_EXEC runs the binary under an emulator (qemu-user) when set.
facet="${FACET_EXEC:+$FACET_EXEC }${1:-build}/facet"
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL f16_cli: $*"; }
expect() { if [ "$2" = "$3" ]; then ok; else bad "$1: expected '$2', got '$3'"; fi; }

# lambert(1) = 1/pi in binary16: 0x3518 = 0.318359375
expect "lambert(1) in binary16" "0.318359375" "$(echo 1 | $facet eval lambert --format f16)"
# F(f0, 1) = f0 rounded to binary16: 0.04 -> 0.0400085449
expect "F(0.04, 1) is f0 rounded to binary16" "0.0400085449" "$(echo '0.04 1' | $facet eval fresnel_schlick --format f16)"
expect "NaN gives 0" "0" "$(echo 'nan 0.5 0.5 0.5 0.5 0.5' | $facet eval brdf_hammon --format f16)"
expect "saturates at 65504" "65504" "$(echo '0.0078125 0.0078125 -1 0.0078125 1 0' | $facet eval brdf_hammon --format f16)"
expect "out of range clamps" "$(echo '1 1' | $facet eval ggx_d --format f16)" "$(echo '7 1e9' | $facet eval ggx_d --format f16)"
# every port gives a result within the bound of the scalar one (here: equal to 3 digits)
a=$(echo '0.8 0.6 0.2 0.25 0.04 0.5' | $facet eval brdf_hammon --format f16 --port scalar)
b=$(echo '0.8 0.6 0.2 0.25 0.04 0.5' | $facet eval brdf_hammon --format f16)
expect "brdf_hammon f16 on auto vs scalar" "$(printf '%.3g' "$a")" "$(printf '%.3g' "$b")"
echo '0.5 0.5' | $facet eval beckmann_d --format f16 > /dev/null 2> "${TMPDIR:-/tmp}/f16_cli.$$"
expect "beckmann_d --format f16 refused" 2 $?
grep -q 'no f16 form: exponential tail' "${TMPDIR:-/tmp}/f16_cli.$$" && ok || bad "beckmann_d refusal: $(cat "${TMPDIR:-/tmp}/f16_cli.$$")"
rm -f "${TMPDIR:-/tmp}/f16_cli.$$"
expect "list --formats: brdf_hammon" "brdf_hammon f32 f32_fast fx fx_fast f16" "$($facet list --formats | grep '^brdf_hammon ')"
expect "list --f16: ggx_d" "ggx_d f16" "$($facet list --f16 | grep '^ggx_d ')"
$facet list --f16 | grep -q '^gtr_d none: GTR' && ok || bad "list --f16: gtr_d has no reason"
echo "f16_cli: $pass passed, $fail failed, 0 skipped"
[ $fail -eq 0 ]
