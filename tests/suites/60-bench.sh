# The bench machinery (bench/): `facet bench` runs and prints well-formed
# JSON with the expected fields, rejects bad selections, and the report
# driver builds.  The PNG encoder and rasterizer tests are build/tests/
# test_bench, run by the compiler suites.  Timing figures are not judged.
. tests/suite_lib.sh
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL bench: $*"; }
if ! $MAKE -s -j"$JOBS" BUILD=build tests build/facet-report >build/bench-suite.build.log 2>&1; then
    cat build/bench-suite.build.log
    echo "ERROR bench: build failed (log: build/bench-suite.build.log)"
    exit 0
fi
out=$(build/facet bench ggx_d --json --quick 2>/dev/null); rc=$?
[ $rc -eq 0 ] && ok || bad "facet bench ggx_d --json exited $rc"
j=$(printf '%s' "$out" | tr -d '\n')
for key in '"clock": {"source": "' '"unit": "' '"measured_core_cycles": ' '"results": \[' \
           '"kernel": "ggx_d", "format": "f32", "port": "scalar", "path": "batch"' \
           '"path": "inline"' '"path": "call"' '"max_err": [0-9]' '"argmax": \[' \
           '"throughput": {"min": [0-9]' '"latency": {"min": [0-9]' '"spread": ' '"within_bound": true' ; do
    printf '%s' "$j" | grep -qE "$key" && ok || bad "JSON lacks /$key/"
done
# balanced braces and brackets, and a closing ']}'
opens=$(printf '%s' "$j" | tr -cd '{' | wc -c); closes=$(printf '%s' "$j" | tr -cd '}' | wc -c)
[ "$opens" -eq "$closes" ] && ok || bad "JSON braces unbalanced ($opens vs $closes)"
printf '%s' "$j" | grep -qE '\]\}$' && ok || bad "JSON does not end with ]}"
if command -v python3 >/dev/null 2>&1; then
    printf '%s' "$out" | python3 -c 'import json,sys; d=json.load(sys.stdin); assert d["results"]' \
        && ok || bad "python3 json.load rejects the output"
fi
# every ggx_d row within its facet bound (error is a property, not a timing)
n_bad=$(printf '%s' "$out" | grep -c '"within_bound": false')
[ "$n_bad" -eq 0 ] && ok || bad "$n_bad ggx_d rows outside the bound"
# text form and bad input
build/facet bench lambert --quick --no-peers | grep -qE '^lambert +f32 +scalar +batch' && ok || bad "text table"
build/facet bench nosuch >/dev/null 2>&1; [ $? -eq 2 ] && ok || bad "unknown kernel: want exit 2"
build/facet bench ggx_d --port nosuch --quick >/dev/null 2>&1; [ $? -eq 2 ] && ok || bad "unknown port: want exit 2"
build/facet bench ggx_d --format q15 >/dev/null 2>&1; [ $? -eq 2 ] && ok || bad "unknown format: want exit 2"
build/facet bench --help | grep -q 'usage: facet bench' && ok || bad "--help"
echo "bench: $pass passed, $fail failed, 0 skipped"
