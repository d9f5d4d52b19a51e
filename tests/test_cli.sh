#!/bin/sh
# test_cli.sh BUILD_DIR - the `facet` command's contract: list, eval,
# round-tripping output, malformed lines, exit statuses, --help.
facet=${1:-build}/facet
# FACET_EXEC runs target binaries (e.g. "qemu-aarch64 -L /usr/aarch64-linux-gnu")
if [ -n "${FACET_EXEC:-}" ]; then
    real_facet=$facet
    facet=facet_exec
    facet_exec() { $FACET_EXEC "$real_facet" "$@"; }
fi
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL cli: $*"; }
expect() { # expect DESC EXPECTED ACTUAL
    if [ "$2" = "$3" ]; then ok; else bad "$1: expected '$2', got '$3'"; fi
}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# list: one line per kernel, the core table present with its inputs
"$facet" list > "$tmp/list"; expect "list exit" 0 $?
expect "list ggx_d" "ggx_d noh alpha" "$(grep '^ggx_d ' "$tmp/list")"
expect "list brdf_hammon" "brdf_hammon nol nov lov alpha f0 albedo" "$(grep '^brdf_hammon ' "$tmp/list")"
for k in noh_from_dots loh_from_dots fresnel_schlick ggx_d smith_g1 smith_g2 smith_g2_uncorrelated \
         smith_vis smith_g1_hammon smith_g2_hammon smith_vis_hammon diffuse_hammon brdf_hammon; do
    grep -q "^$k " "$tmp/list" && ok || bad "list lacks $k"
done

# eval: every listed kernel accepts a line of 0.5s and prints one number
while read -r name rest; do
    n=$(echo $rest | wc -w)
    line=$(yes 0.5 | head -n "$n" | tr '\n' ' ')
    out=$(echo "$line" | "$facet" eval "$name"); rc=$?
    expect "eval $name exit" 0 $rc
    echo "$out" | grep -qE '^[0-9.e+-]+$' && ok || bad "eval $name printed '$out'"
done < "$tmp/list"

# exact values and the %.9g round trip
expect "fresnel f0 at cos 1" "0.0399999991" "$(echo '0.04 1' | "$facet" eval fresnel_schlick)"
expect "lambert 1" "0.318309873" "$(echo 1 | "$facet" eval lambert --format f32 --port scalar)"
expect "several lines" "3" "$(printf '0.5 0.5\n0.1 0.2\n  1\t1  \n' | "$facet" eval ggx_d | wc -l)"
expect "nan input is documented (as 0), not an error" "0" "$(echo nan | "$facet" eval lambert)"

# malformed input: line number on stderr, exit 2, nothing skipped silently
printf '0.5 0.5\n0.5 x\n0.5 0.5\n' | "$facet" eval ggx_d > "$tmp/out" 2> "$tmp/err"; rc=$?
expect "malformed exit" 2 $rc
grep -q 'line 2' "$tmp/err" && ok || bad "malformed: stderr lacks 'line 2': $(cat "$tmp/err")"
printf '0.5\n' | "$facet" eval ggx_d > /dev/null 2> "$tmp/err"; expect "too few exit" 2 $?
grep -q 'line 1: too few' "$tmp/err" && ok || bad "too few: $(cat "$tmp/err")"
printf '0.5 0.5 0.5\n' | "$facet" eval ggx_d > /dev/null 2>&1; expect "too many exit" 2 $?
printf '\n' | "$facet" eval ggx_d > /dev/null 2>&1; expect "empty line exit" 2 $?
printf '0.5 0.5x\n' | "$facet" eval ggx_d > /dev/null 2>&1; expect "trailing junk exit" 2 $?
"$facet" eval no_such_kernel < /dev/null > /dev/null 2>&1; expect "unknown kernel exit" 2 $?
"$facet" eval ggx_d --port no_such_port < /dev/null > /dev/null 2>&1; expect "unknown port exit" 2 $?
"$facet" eval ggx_d --format q99 < /dev/null > /dev/null 2>&1; expect "unknown format exit" 2 $?
"$facet" frobnicate > /dev/null 2>&1; expect "unknown verb exit" 2 $?
"$facet" > /dev/null 2>&1; expect "no verb exit" 2 $?

# ports: every port compiled in evaluates through the batch path and agrees
# with the scalar port to within the kernel's bound; others are refused
ports=$("$facet" eval --help | sed -n 's/^ports compiled in://p')
[ -n "$ports" ] && ok || bad "eval --help does not list the ports"
ref=$(echo "0.6 0.7 0.5 0.1 0.04 0.5" | "$facet" eval brdf_hammon --port scalar)
for p in $(echo "$ports" | tr ' ' '\n' | grep -v '^(' | grep -vE '^(not|on|this|CPU\))$'); do
    if echo "$ports" | grep -q "$p (not on this CPU)"; then
        echo "0.5 0.5" | "$facet" eval ggx_d --port "$p" > /dev/null 2> "$tmp/err"; expect "unsupported port $p exit" 2 $?
        grep -q 'cannot run' "$tmp/err" && ok || bad "unsupported port $p: $(cat "$tmp/err")"
        continue
    fi
    out=$(echo "0.6 0.7 0.5 0.1 0.04 0.5" | "$facet" eval brdf_hammon --port "$p"); expect "port $p exit" 0 $?
    awk -v a="$out" -v b="$ref" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 6e-6 * b) }' && ok ||
        bad "port $p: $out vs scalar $ref"
    out=$(echo "0.6 0.7 0.5 0.1 0.04 0.5" | FACET_PORT="$p" "$facet" eval brdf_hammon); expect "FACET_PORT=$p exit" 0 $?
done
echo "0.5 0.5" | "$facet" eval ggx_d --port no_such_port > /dev/null 2> "$tmp/err"; expect "bogus port exit" 2 $?
grep -q "unknown port" "$tmp/err" && ok || bad "bogus port: $(cat "$tmp/err")"
echo "0.5 0.5" | FACET_PORT=no_such_port "$facet" eval ggx_d > /dev/null 2>&1; expect "bogus FACET_PORT exit" 2 $?

# help for each verb
for v in "" "list" "eval"; do
    "$facet" $v --help > "$tmp/help"; expect "help '$v' exit" 0 $?
    grep -q usage "$tmp/help" && ok || bad "help '$v' has no usage line"
done

echo "cli: $pass passed, $fail failed, 0 skipped"
[ $fail -eq 0 ]
