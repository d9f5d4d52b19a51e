# The x86 build on an older CPU model under qemu-x86_64 (Nehalem: SSE4.2,
# no AVX): the dispatcher must pick sse2, refuse avx2/avx512 (and the f16
# table avx512fp16) with a clear error, and nothing outside the AVX objects may execute an AVX instruction
# (qemu would stop the test with SIGILL); the same for the bench's SIMD
# loops and rasterizer paths.  Then on Haswell (AVX2 and FMA, no AVX-512,
# so no AVX-512 FP16): the dispatcher picks avx2, refuses avx512 and
# avx512fp16, and the f32 and f16 tests pass there.  And, since no emulator
# here offers an AVX-512 CPU without FP16 (Zen 4 and 5), a build whose CPU
# test reports no AVX-512 FP16 (FACET_TEST_CPU_WITHOUT_AVX512FP16, src/core/
# cpu.c) runs the f16 tests natively: on an AVX-512 CPU the avx512 port with
# the scalar f16 table and avx512fp16 refused with its reason.  Skipped off
# x86 or without qemu.
. tests/lib/suite_lib.sh
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
# facet ports: the AVX ports listed as not running here, auto on sse2
[ "$($q build/facet ports | awk '/ auto$/ { print $1 }')" = sse2 ] && ok || bad "ports: auto is not sse2: $($q build/facet ports)"
[ "$($q build/facet ports | grep -c 'not on this CPU')" = 2 ] && ok || bad "ports: avx512/avx2 not marked: $($q build/facet ports)"
echo "0.5 0.5" | $q build/facet eval ggx_d --port avx2 > /dev/null 2> build/old-cpu.err
[ $? -eq 2 ] && grep -q "cannot run it" build/old-cpu.err && ok || bad "--port avx2: $(cat build/old-cpu.err)"
out=$(echo "0.6 0.7 0.5 0.1 0.04 0.5" | $q build/facet eval brdf_hammon) && [ -n "$out" ] && ok || bad "eval on auto"
# the test binaries: every check passes; the AVX ports are reported unsupported.
# The accuracy sweep runs its emulator level (strided edge grids, 30000
# random samples): what it adds here is that no AVX instruction executes;
# its full sweep of the sse2 and scalar ports runs natively in 10-gcc.
for t in test_f32_ports test_f32_accuracy test_fx_ports test_f32_bad_input test_bench test_sample_ports \
    test_f16_ports test_f16_accuracy; do
    level=1
    [ $t = test_f32_accuracy ] && level=2
    res=$(FACET_TEST_QUICK=$level $q build/tests/$t 2>&1)
    rc=$?
    summary=$(printf '%s\n' "$res" | tail -n 1)
    if [ $rc -eq 0 ] && printf '%s' "$summary" | grep -q ' 0 failed'; then ok; else
        printf '%s\n' "$res" | grep -E 'FAIL|Illegal' | head -5; bad "$t under Nehalem: $summary (exit $rc)"; fi
done
res=$(FACET_TEST_QUICK=1 $q build/tests/test_f32_ports 2>&1)
printf '%s' "$res" | grep -q "port avx2: compiled in, but this CPU cannot run it" && ok || bad "avx2 not reported unsupported"
# f16: the AVX-512 FP16 table refused with what it needs, the scalar one runs
# (nothing outside ports/avx512fp16/ executes an FP16 instruction: qemu
# would stop these with SIGILL)
res=$(FACET_TEST_QUICK=1 $q build/tests/test_f16_ports 2>&1)
printf '%s' "$res" | grep -q "port avx512fp16: not run here: AVX-512 FP16 (CPUID" && ok || bad "avx512fp16 not refused with its reason"
printf '%s' "$res" | grep -q "f16 batches on scalar (port sse2)" && ok || bad "f16 batches not on scalar: $(printf '%s' "$res" | tail -n 2)"
[ "$(echo 1 | $q build/facet eval lambert --format f16)" = 0.318359375 ] && ok || bad "eval --format f16 under Nehalem"
# the bench's SIMD loops and peers ask facet_port_supported(): no avx2 row,
# no SIGILL (the shader peers are built for AVX2 / AVX-512 widths and skipped)
out=$($q build/facet-bench bench ggx_d --quick --format f32 2>&1); rc=$?
if [ $rc -eq 0 ] && printf '%s\n' "$out" | grep -qE '^ggx_d +f32 +textbook +peer' &&
    ! printf '%s\n' "$out" | grep -qE '^ggx_d +f32 +shader_avx'; then ok; else
    printf '%s\n' "$out" | tail -n 5; bad "facet-bench bench with peers under Nehalem (exit $rc)"; fi
# a port (or a peer of a width) this CPU cannot run is refused with 2, as eval does
$q build/facet-bench bench lambert --port avx2 --quick >/dev/null 2>build/old-cpu.err
[ $? -eq 2 ] && grep -q "cannot run port 'avx2'" build/old-cpu.err && ok || bad "bench --port avx2: $(cat build/old-cpu.err)"
$q build/facet-bench bench ggx_d --port shader_avx2_fm --quick >/dev/null 2>build/old-cpu.err
[ $? -eq 2 ] && ok || bad "bench --port shader_avx2_fm: $(cat build/old-cpu.err)"
out=$($q build/facet-bench bench lambert --quick --no-peers --format f32 2>&1); rc=$?
if [ $rc -eq 0 ] && printf '%s\n' "$out" | grep -qE '^lambert +f32 +sse2 +inline' &&
    ! printf '%s\n' "$out" | grep -qE '^lambert +f32 +avx'; then ok; else
    printf '%s\n' "$out" | tail -n 5; bad "facet-bench bench under Nehalem (exit $rc)"; fi
# ---- Haswell: AVX2 and FMA, no AVX-512 (TCG runs AVX2 since qemu 7.2) ----
h="qemu-x86_64 -cpu Haswell"
[ "$($h build/facet ports 2>/dev/null | awk '/ auto$/ { print $1 }')" = avx2 ] && ok ||
    bad "Haswell: auto is not avx2: $($h build/facet ports 2>/dev/null)"
for t in test_f32_ports test_f32_accuracy test_f32_bad_input test_f16_ports test_f16_accuracy; do
    level=1
    [ $t = test_f32_accuracy ] && level=2
    res=$(FACET_TEST_QUICK=$level $h build/tests/$t 2> build/old-cpu.haswell.err)
    rc=$?
    summary=$(printf '%s\n' "$res" | tail -n 1)
    if [ $rc -eq 0 ] && printf '%s' "$summary" | grep -q ' 0 failed'; then ok; else
        { printf '%s\n' "$res"; cat build/old-cpu.haswell.err; } | grep -E 'FAIL|Illegal' | head -5
        bad "$t under Haswell: $summary (exit $rc)"; fi
done
res=$(FACET_TEST_QUICK=1 $h build/tests/test_f16_ports 2>/dev/null)
printf '%s' "$res" | grep -q "port avx512fp16: not run here: AVX-512 FP16 (CPUID" && ok || bad "Haswell: avx512fp16 not refused with its reason"
printf '%s' "$res" | grep -q "f16 batches on scalar (port avx2)" && ok || bad "Haswell: f16 batches not on scalar with avx2: $(printf '%s' "$res" | tail -n 2)"
# ---- an AVX-512 CPU without FP16, by a build whose CPU test says so -------
dir=build/no-fp16
if $MAKE -s -j"$JOBS" BUILD=$dir CFLAGS="-O2 -g -DFACET_TEST_CPU_WITHOUT_AVX512FP16" \
        $dir/tests/test_f16_ports $dir/tests/test_f16_accuracy > $dir.build.log 2>&1; then
    for t in test_f16_ports test_f16_accuracy; do
        res=$(FACET_TEST_QUICK=1 $dir/tests/$t 2>&1)
        rc=$?
        summary=$(printf '%s\n' "$res" | tail -n 1)
        if [ $rc -eq 0 ] && printf '%s' "$summary" | grep -q ' 0 failed'; then ok; else
            printf '%s\n' "$res" | grep FAIL | head -5; bad "$t without AVX-512 FP16: $summary (exit $rc)"; fi
    done
    res=$(FACET_TEST_QUICK=1 $dir/tests/test_f16_ports 2>&1)
    printf '%s' "$res" | grep -q "port avx512fp16: not run here: AVX-512 FP16 (CPUID" && ok ||
        bad "without AVX-512 FP16: avx512fp16 not refused with its reason"
    printf '%s' "$res" | grep -q "f16 batches on scalar (port " && ok ||
        bad "without AVX-512 FP16: f16 batches not on scalar: $(printf '%s' "$res" | tail -n 2)"
else
    cat $dir.build.log; bad "the build without AVX-512 FP16 failed"
fi
echo "old-cpu: $pass passed, $fail failed, 0 skipped"
