# The x86 build on an older CPU model under qemu-x86_64 (Nehalem: SSE4.2,
# no AVX): the dispatcher must pick sse2, refuse avx2/avx512 with a clear
# error, and nothing outside the AVX objects may execute an AVX instruction
# (qemu would stop the test with SIGILL).  Skipped off x86 or without qemu.
. tests/suite_lib.sh
case "$(${CC:-cc} -dumpmachine)" in
x86_64*) ;;
*) echo "old-cpu: 0 passed, 0 failed, 0 skipped"; exit 0 ;;
esac
if ! command -v qemu-x86_64 > /dev/null 2>&1; then
    echo "SKIP old-cpu: qemu-x86_64 not installed (apt-get install qemu-user)"
    echo "old-cpu: 0 passed, 0 failed, 1 skipped"
    exit 0
fi
q="qemu-x86_64 -cpu Nehalem"
mkdir -p build
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL old-cpu: $*"; }
if ! $MAKE -s -j"$JOBS" tests > build/old-cpu.build.log 2>&1; then
    cat build/old-cpu.build.log; echo "ERROR old-cpu: build failed"; exit 0
fi
ports=$($q build/facet eval --help | sed -n 's/^ports compiled in: //p')
[ "$ports" = "avx512 (not on this CPU) avx2 (not on this CPU) sse2 scalar" ] && ok || bad "ports: $ports"
echo "0.5 0.5" | $q build/facet eval ggx_d --port avx2 > /dev/null 2> build/old-cpu.err
[ $? -eq 2 ] && grep -q "cannot run it" build/old-cpu.err && ok || bad "--port avx2: $(cat build/old-cpu.err)"
out=$(echo "0.6 0.7 0.5 0.1 0.04 0.5" | $q build/facet eval brdf_hammon) && [ -n "$out" ] && ok || bad "eval on auto"
# the test binaries: every check passes; the AVX ports are reported unsupported
for t in test_f32_ports test_f32_accuracy test_fx_ports test_f32_bad_input test_sample_ports; do
    res=$(FACET_TEST_QUICK=1 $q build/tests/$t 2>&1)
    rc=$?
    summary=$(printf '%s\n' "$res" | tail -n 1)
    if [ $rc -eq 0 ] && printf '%s' "$summary" | grep -q ' 0 failed'; then ok; else
        printf '%s\n' "$res" | grep -E 'FAIL|Illegal' | head -5; bad "$t under Nehalem: $summary (exit $rc)"; fi
done
res=$(FACET_TEST_QUICK=1 $q build/tests/test_f32_ports 2>&1)
printf '%s' "$res" | grep -q "port avx2: compiled in, but this CPU cannot run it" && ok || bad "avx2 not reported unsupported"
echo "old-cpu: $pass passed, $fail failed, 0 skipped"
