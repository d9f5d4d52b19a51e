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

# list: one line per kernel, then per sampler, exactly the lists
# (src/core/kernels.def, src/core/sample_kernels.def, expanded by the C
# preprocessor: name, inputs; a sampler's "-> outputs") in their order
"$facet" list > "$tmp/list"; expect "list exit" 0 $?
expect "list ggx_d" "ggx_d noh alpha" "$(grep '^ggx_d ' "$tmp/list")"
expect "list brdf_hammon" "brdf_hammon nol nov lov alpha f0 albedo" "$(grep '^brdf_hammon ' "$tmp/list")"
top=$(cd "$(dirname "$0")/../.." && pwd)
printf '%s\n' '#define FACET_IN(input, domain) input' \
    '#define FACET_KERNEL(name, NAME, n, t, f, m, q, c, ...) name __VA_ARGS__' \
    "#include \"$top/src/core/kernels.def\"" \
    '#define FACET_SAMPLER(name, NAME, kind, err, n_out, n_in, outs, ins) name ins -> outs' \
    "#include \"$top/src/core/sample_kernels.def\"" |
    ${CC:-cc} -E -P -x c - 2> "$tmp/cpp.err" | tr -d '(),"' | awk 'NF { $1 = $1; print }' > "$tmp/list.def"
[ -s "$tmp/list.def" ] && ok || bad "the lists did not expand: $(cat "$tmp/cpp.err")"
if cmp -s "$tmp/list.def" "$tmp/list"; then ok; else
    bad "facet list differs from the lists (< lists, > facet list): $(diff "$tmp/list.def" "$tmp/list" | grep '^[<>]' | tr '\n' ' ')"
fi

# eval: every listed kernel accepts a line of 0.5s and prints one number;
# every sampler ("name inputs -> outputs") one number per output, in f32,
# f32_fast and the oracle
while read -r name rest; do
    case "$rest" in
    *'->'*) n=$(echo "${rest%%->*}" | wc -w); nout=$(echo "${rest#*->}" | wc -w) ;;
    *) n=$(echo $rest | wc -w); nout=1 ;;
    esac
    line=$(yes 0.5 | head -n "$n" | tr '\n' ' ')
    pat="^[0-9.e+-]+( [0-9.e+-]+){$((nout - 1))}\$"
    for fmt in f32 f32_fast; do
        out=$(echo "$line" | "$facet" eval "$name" --format $fmt); rc=$?
        expect "eval $name --format $fmt exit" 0 $rc
        echo "$out" | grep -qE "$pat" && ok || bad "eval $name --format $fmt printed '$out'"
    done
    out=$(echo "$line" | "$facet" eval "$name" --oracle); rc=$?
    expect "eval $name --oracle exit" 0 $rc
    echo "$out" | grep -qE "$pat" && ok || bad "eval $name --oracle printed '$out'"
done < "$tmp/list"
expect "list: a sampler with its outputs" "ggx_sample_vndf vx vy vz u1 u2 alpha -> hx hy hz" \
    "$(grep '^ggx_sample_vndf ' "$tmp/list")"

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
printf '0.5 0.5x\n' | "$facet" eval ggx_d > /dev/null 2>&1; expect "trailing junk exit" 2 $?
"$facet" eval no_such_kernel < /dev/null > /dev/null 2>&1; expect "unknown kernel exit" 2 $?
"$facet" eval ggx_d --port no_such_port < /dev/null > /dev/null 2>&1; expect "unknown port exit" 2 $?
"$facet" eval ggx_d --format q99 < /dev/null > /dev/null 2>&1; expect "unknown format exit" 2 $?
"$facet" frobnicate > /dev/null 2>&1; expect "unknown verb exit" 2 $?
"$facet" > /dev/null 2>&1; expect "no verb exit" 2 $?

# input rules (src/cli/cli.h): blank and '#' lines skipped, VT/FF are white space
expect "blank and comment lines skipped" "0.0339389108" \
    "$(printf '# noh alpha\n\n  \t\n   # indented comment\n0.5 0.25\n\n' | "$facet" eval ggx_d)"
printf '\n\n' | "$facet" eval ggx_d > "$tmp/out" 2>&1; expect "only blank lines: exit" 0 $?
expect "only blank lines: no output" "" "$(cat "$tmp/out")"
expect "VT and FF are white space" "0.0339389108" "$(printf '\v0.5\f0.25\v\r\n' | "$facet" eval ggx_d)"
# a NUL byte is reported as such, on any line, newline or not
printf '0.5 0.25\0garbage' | "$facet" eval ggx_d > /dev/null 2> "$tmp/err"; expect "NUL, last line exit" 2 $?
grep -q 'line 1: contains a NUL byte' "$tmp/err" && ok || bad "NUL on a last line: $(cat "$tmp/err")"
printf '0.5 0.25\n0.5\0 0.25\n' | "$facet" eval ggx_d > /dev/null 2> "$tmp/err"; expect "NUL exit" 2 $?
grep -q 'line 2: contains a NUL byte' "$tmp/err" && ok || bad "NUL: $(cat "$tmp/err")"
printf '# a\0comment\n0.5 0.25\n' | "$facet" eval ggx_d > /dev/null 2> "$tmp/err"; expect "NUL in a comment exit" 2 $?
head -c 5000 /dev/zero | tr '\0' 1 | "$facet" eval lambert > /dev/null 2> "$tmp/err"; expect "long line exit" 2 $?
grep -q 'line 1: longer than 4094 characters' "$tmp/err" && ok || bad "long line: $(cat "$tmp/err")"
# decimal only; one rounding to float (0.5 + 2^-25 + 10^-31 is above the tie: 0.5 + 2^-24)
echo "0x1p-1 0.5" | "$facet" eval ggx_d > /dev/null 2>&1; expect "hex float exit" 2 $?
expect "decimal rounded once to float" "$(echo 0.50000006 | "$facet" eval lambert)" \
    "$(echo 0.5000000298023223876953125000001 | "$facet" eval lambert)"
expect "finite beyond float range is +Inf: clamps" "$(echo '1 1' | "$facet" eval ggx_d)" "$(echo '1e999 1e400' | "$facet" eval ggx_d)"
# a malformed line: the lines before it are printed, then the error, exit 2
yes '0.5 0.25' | head -n 1500 > "$tmp/in"; echo '0.5 x' >> "$tmp/in"; echo '0.5 0.25' >> "$tmp/in"
"$facet" eval ggx_d < "$tmp/in" > "$tmp/out" 2> "$tmp/err"; expect "malformed line 1501 exit" 2 $?
expect "malformed line 1501: lines before it printed" 1500 "$(wc -l < "$tmp/out")"
grep -q 'line 1501: not a decimal number' "$tmp/err" && ok || bad "malformed line 1501: $(cat "$tmp/err")"
"$facet" eval ggx_d --format fx < "$tmp/in" > "$tmp/out" 2> /dev/null; expect "fx malformed line 1501 exit" 2 $?
expect "fx malformed line 1501: lines before it printed" 1500 "$(wc -l < "$tmp/out")"
"$facet" eval ggx_d --oracle < "$tmp/in" > "$tmp/out" 2> /dev/null; expect "oracle malformed line 1501 exit" 2 $?
expect "oracle malformed line 1501: lines before it printed" 1500 "$(wc -l < "$tmp/out")"

# exit status 1 for an I/O error, the same for every verb
if [ -w /dev/full ]; then
    for v in "list" "ports" "--version" "--help" "list --help" "eval --help" "vectors --help" \
             "vectors ggx_d" "vectors ggx_d --count 1000000000"; do
        "$facet" $v < /dev/null > /dev/full 2>/dev/null; expect "'$v' > /dev/full exit" 1 $?
    done
    for f in f32 fx; do
        echo "0.5 0.25" | "$facet" eval ggx_d --format $f > /dev/full 2>/dev/null; expect "eval $f > /dev/full exit" 1 $?
    done
    echo "0.5 0.25" | "$facet" eval ggx_d --oracle > /dev/full 2>/dev/null; expect "eval --oracle > /dev/full exit" 1 $?
else
    echo "SKIP cli: /dev/full not writable here"
fi

# the oracle: %.17g of the double oracle at double inputs
expect "eval --oracle lambert 1 = 1/pi" "0.31830988618379069" "$(echo 1 | "$facet" eval lambert --oracle)"
o=$(echo "0.6 0.7 0.5 0.1 0.04 0.5" | "$facet" eval brdf_hammon --oracle)
f=$(echo "0.6 0.7 0.5 0.1 0.04 0.5" | "$facet" eval brdf_hammon)
awk -v a="$f" -v b="$o" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 3e-6 * b) }' && ok || bad "oracle $o vs f32 $f"
expect "oracle accepts nan (clamped)" "0" "$(echo nan | "$facet" eval lambert --oracle)"

# unknown kernels: a hint when one is close
"$facet" eval ggx_dd < /dev/null > /dev/null 2> "$tmp/err"; expect "typo kernel exit" 2 $?
grep -q "did you mean 'ggx_d'" "$tmp/err" && ok || bad "typo kernel: $(cat "$tmp/err")"
"$facet" eval brdf < /dev/null > /dev/null 2> "$tmp/err"
grep -q "did you mean 'brdf_hammon'" "$tmp/err" && ok || bad "partial kernel: $(cat "$tmp/err")"

# ports: one line per port compiled in, 'auto' on exactly one, FACET_PORT explained
"$facet" ports > "$tmp/ports"; expect "ports exit" 0 $?
expect "ports: one line each" "$("$facet" eval --help | sed -n 's/^ports compiled in://p' | sed 's/ (not on this CPU)//g' | wc -w)" \
    "$(wc -l < "$tmp/ports")"
expect "ports: one auto" 1 "$(grep -c ' auto$' "$tmp/ports")"
expect "ports: auto is the first this CPU runs" "$(grep -m1 'runs on this CPU' "$tmp/ports" | awk '{ print $1 }')" \
    "$(grep ' auto$' "$tmp/ports" | awk '{ print $1 }')"
FACET_PORT=no_such_port "$facet" ports > "$tmp/ports"; expect "ports with a bogus FACET_PORT exit" 0 $?
grep -q '^FACET_PORT=no_such_port: not a port compiled in; the library ignores it' "$tmp/ports" && ok ||
    bad "ports does not explain a bogus FACET_PORT: $(cat "$tmp/ports")"
"$facet" ports extra > /dev/null 2>&1; expect "ports extra argument exit" 2 $?

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
for v in "" "list" "eval" "ports"; do
    "$facet" $v --help > "$tmp/help"; expect "help '$v' exit" 0 $?
    grep -q usage "$tmp/help" && ok || bad "help '$v' has no usage line"
done

echo "cli: $pass passed, $fail failed, 0 skipped"
[ $fail -eq 0 ]
