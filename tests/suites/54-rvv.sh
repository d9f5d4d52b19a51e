# The RVV port (RISC-V Vector 1.0, vector-length agnostic) under qemu-user:
# the library cross-built for riscv64 with riscv64-linux-gnu-gcc, the two
# port objects with clang (ports/rvv/port.mk), in build/rv64; one binary
# per test, run at VLEN 128, 256 and 512 (qemu -cpu rv64,v=true,vlen=N):
#   rvv-detect         `facet ports`: rvv runs and is auto with V (lanes =
#                      VLEN / 32), is refused without V (AT_HWCAP)
#   test_f32_ports     lanes, every tail up to 3 VLMAX + 1, alignment,
#                      aliasing, symmetry, bad input, both f32 tiers
#   test_fx_ports      fx_fast batches bit for bit against the scalar
#                      specification, tails, aliasing
#   test_fx_hash       the pinned hashes
#   test_sample_ports, test_f32_bad_input, test_f32_rgb  samplers, bad
#                      input, the RGB batches (every layout, tail, alias)
#   test_tails_rvv     a caller's strip-mined loop over facet/rvv.h (vl
#                      loads and stores) equals the batch bit for bit at
#                      every n up to 4 VLMAX + 1, exact-size buffers, a
#                      guard after the output, out == an input
#   test_f32_accuracy  both tiers against the oracle at the facet.h bounds
#                      (FACET_TEST_QUICK=2), at VLEN 128 only: each lane's
#                      arithmetic does not depend on VLEN (the lane and tail
#                      tests above do, and run at every VLEN)
# and the binary16 table rvvfp16 (ports/rvvfp16, facet/rvvfp16.h), under
# -cpu rv64,v=true,Zfh=true (qemu 7.2 has no zvfh property; Zfh makes it
# execute SEW=16 vector floating point):
#   rvvfp16-detect     the dispatcher refuses it here with its reason (qemu
#                      7.2 answers riscv_hwprobe with ENOSYS, so Zvfh cannot
#                      be detected) and the f16 batches run the scalar table
#   rvvfp16-isa        the port's object has binary16 vector arithmetic and
#                      no scalar binary16 instruction beyond Zfhmin (which
#                      Zvfh implies; Zfh it does not), and the check finds
#                      one in a broken copy; facet/rvv.h and facet/rvvfp16.h
#                      (suite 25 compiles every other installed header)
#                      compile as strict C99 and C++11 / C++17 (clang,
#                      -pedantic -Werror, -Wold-style-cast)
#   test_f16_ports, test_f16_accuracy (FACET_TEST_QUICK=1), test_f16_estimates_rvv
#                      with FACET_TEST_F16_FORCE=rvvfp16 (tests/f16/f16_test.h:
#                      the table called directly, as the dispatcher refuses
#                      it): bad input, tails, aliasing, every bound of
#                      facet/f16.h, the estimates exhaustively; at every VLEN
#                      (the lanes, the tails and the f32 lanes' LMUL 2 groups
#                      depend on it)
#   rvvfp16-count      bench/qcount/qcount.sh rv64-f16: executed instructions
#                      per sample of every kernel with a binary16 form (rvv
#                      f32, f32_fast, rvvfp16) at the three VLENs, rows by
#                      bench/qcount/rvv_f16_rows.sh, each present in
#                      ports/README.md's RVV binary16 table (with clang 14
#                      and riscv64-linux-gnu-gcc 12; other compilers' figures
#                      are shown), and a changed figure fails (self-test)
# The three VLENs run side by side.  Skipped, with the reason, where a tool
# is missing (.ci/run installs them).  It runs in the host lane of
# tests/check.sh, not beside 40-arm in the emulator lane: that lane is the
# longer one (40-arm, 50, 52), and the host lane has the room.
. tests/lib/suite_lib.sh
have() { command -v "$1" > /dev/null 2>&1; }
skip() {
    echo "SKIP rvv: $1"
    echo "rvv: 0 passed, 0 failed, 1 skipped"
    exit 0
}
have riscv64-linux-gnu-gcc || skip "riscv64-linux-gnu-gcc not installed (apt-get install gcc-riscv64-linux-gnu libc6-dev-riscv64-cross)"
[ -f /usr/riscv64-linux-gnu/include/stdio.h ] || skip "libc6-dev-riscv64-cross not installed (apt-get install libc6-dev-riscv64-cross)"
have qemu-riscv64 || skip "qemu-riscv64 not installed (apt-get install qemu-user)"
have clang || skip "clang not installed (apt-get install clang: the RVV intrinsics; gcc 12 has none)"
sysroot=/usr/riscv64-linux-gnu
dir=build/rv64
tests="test_f32_ports test_f32_accuracy test_fx_ports test_fx_hash test_sample_ports test_sample_small test_f32_bad_input test_f32_rgb
       test_tails_rvv"
f16tests="test_f16_ports test_f16_accuracy test_f16_estimates_rvv"
bins=""
for t in $tests $f16tests; do bins="$bins $dir/tests/$t"; done
mkdir -p $dir
if ! $MAKE -s -j"$JOBS" BUILD=$dir CC=riscv64-linux-gnu-gcc CFLAGS="-O2 -g" $dir/facet $bins > $dir/build.log 2>&1; then
    cat $dir/build.log
    echo "ERROR rvv: cross build failed (log: $dir/build.log)"
    exit 0
fi
cpu() { echo "rv64,v=true,vext_spec=v1.0,vlen=$1"; }
cpu16() { echo "rv64,v=true,vext_spec=v1.0,Zfh=true,vlen=$1"; }

# detect VLEN: the port is in the build, picked with V, refused without
detect() {
    v=$1 pass=0 fail=0
    out=$(qemu-riscv64 -L $sysroot -cpu $(cpu $v) $dir/facet ports 2>&1)
    if printf '%s\n' "$out" | grep -qE "^rvv +$((v / 32)) lanes +runs on this CPU +auto"; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        printf '%s\n' "$out"
        echo "FAIL rvv-detect: with V at VLEN $v, rvv is not the automatic port with $((v / 32)) lanes"
    fi
    out=$(qemu-riscv64 -L $sysroot -cpu rv64 $dir/facet ports 2>&1)
    if printf '%s\n' "$out" | grep -qE '^rvv .*not on this CPU' && printf '%s\n' "$out" | grep -qE '^scalar .*auto'; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        printf '%s\n' "$out"
        echo "FAIL rvv-detect: without V, rvv must be refused and scalar automatic"
    fi
    echo "rvv-detect: $pass passed, $fail failed, 0 skipped"
}

# the rvvfp16 table refused by the dispatcher under qemu-user 7.2, with its
# reason, and the f16 batches on the scalar table
f16_detect() {
    v=$1 pass=0 fail=0
    out=$(FACET_TEST_QUICK=1 qemu-riscv64 -L $sysroot -cpu $(cpu16 $v) $dir/tests/test_f16_ports 2>&1)
    case $(qemu-riscv64 --version | head -n 1) in
    *"version 7."*)
        if printf '%s\n' "$out" | grep -q "^port rvvfp16: refused: RISC-V V with Zvfh, which only the riscv_hwprobe system call reports: riscv_hwprobe answers ENOSYS here" &&
           printf '%s\n' "$out" | grep -q '^f16 batches on scalar (port rvv)$'; then
            pass=$((pass + 1))
        else
            fail=$((fail + 1))
            printf '%s\n' "$out" | tail -n 5
            echo "FAIL rvvfp16-detect: under qemu-user 7.2 (riscv_hwprobe: ENOSYS) rvvfp16 must be refused with that reason, the scalar f16 table run"
        fi ;;
    *) # a qemu whose riscv_hwprobe may answer: refused with a reason, or run
        if printf '%s\n' "$out" | grep -qE '^port rvvfp16: refused: RISC-V V with Zvfh.+|^f16 batches on rvvfp16 \(port rvv\)$'; then
            pass=$((pass + 1))
        else
            fail=$((fail + 1))
            printf '%s\n' "$out" | tail -n 5
            echo "FAIL rvvfp16-detect: rvvfp16 neither refused with a reason nor run"
        fi ;;
    esac
    echo "rvvfp16-detect: $pass passed, $fail failed, 0 skipped"
}

# beyond_zfhmin OBJECT: the scalar binary16 instructions (mnemonics f*.h) of
# OBJECT beyond Zfhmin's (flh, fsh, fmv.x.h, fmv.h.x, fcvt between h and s
# or d), one line each
beyond_zfhmin() {
    riscv64-linux-gnu-objdump -d "$1" | awk -F'\t' 'NF >= 3 { split($3, w, " "); print w[1] }' |
        grep -E '^f[a-z0-9.]*\.h$' | grep -vE '^(flh|fsh|fmv\.x\.h|fmv\.h\.x|fcvt\.[sd]\.h|fcvt\.h\.[sd])$' | sort -u
}
f16_isa() {
    pass=0 fail=0
    obj=$dir/ports/rvvfp16/f16_rvvfp16.o
    if [ ! -f $obj ]; then
        echo "FAIL rvvfp16-isa: $obj not built (ports/rvvfp16/port.mk: RVV_CC without the binary16 vector intrinsics?)"
        echo "rvvfp16-isa: 0 passed, 1 failed, 0 skipped"
        return
    fi
    n16=$(riscv64-linux-gnu-objdump -d $obj | grep -cE 'vfrec7\.v|vfwcvt\.f\.f\.v|vfncvt\.f\.f\.w')
    bad=$(beyond_zfhmin $obj)
    if [ "$n16" -gt 0 ] && [ -z "$bad" ]; then pass=$((pass + 1))
    else fail=$((fail + 1)); echo "FAIL rvvfp16-isa: $obj: $n16 binary16 vector ops, beyond Zfhmin: $bad"; fi
    # the check finds scalar Zfh arithmetic in a broken copy
    printf '_Float16 f16_isa_probe(_Float16 a, _Float16 b);\n_Float16 f16_isa_probe(_Float16 a, _Float16 b) { return a * b + a; }\n' > $dir/f16_isa_probe.c
    if clang --target=riscv64-linux-gnu -march=rv64gcv_zfh -O2 -c $dir/f16_isa_probe.c -o $dir/f16_isa_probe.o &&
       [ -n "$(beyond_zfhmin $dir/f16_isa_probe.o)" ]; then pass=$((pass + 1))
    else fail=$((fail + 1)); echo "FAIL rvvfp16-isa: the check finds no scalar Zfh arithmetic in the broken copy"; fi
    # the header alone, strict C99 and C++
    printf '#include <facet/rvv.h>\n#include <facet/rvvfp16.h>\nint facet_header_probe_(void);\nint facet_header_probe_(void) { return 0; }\n' > $dir/rvvfp16_h.c
    cp $dir/rvvfp16_h.c $dir/rvvfp16_h.cc
    for c in "clang -std=c99 $dir/rvvfp16_h.c" "clang++ -std=c++11 -Wold-style-cast $dir/rvvfp16_h.cc" \
             "clang++ -std=c++17 -Wold-style-cast $dir/rvvfp16_h.cc"; do
        # shellcheck disable=SC2086
        if o=$($c --target=riscv64-linux-gnu -march=rv64gcv_zfh -pedantic -Wall -Wextra -Werror -Iinclude -c -o $dir/rvvfp16_h.o 2>&1); then
            pass=$((pass + 1))
        else fail=$((fail + 1)); echo "FAIL rvvfp16-isa: facet/rvv.h and facet/rvvfp16.h do not compile ($c): $(printf '%s' "$o" | head -n 3 | tr '\n' ' ')"; fi
    done
    echo "rvvfp16-isa: $pass passed, $fail failed, 0 skipped"
}

f16_count() {
    pass=0 fail=0 rows=$dir/qcount-f16.rows
    fbad() { fail=$((fail + 1)); echo "FAIL rvvfp16-count: $*"; }
    if ! sh bench/qcount/qcount.sh rv64-f16 $dir > $dir/qcount-f16.txt 2> $dir/qcount-f16.log ||
       ! sh bench/qcount/rvv_f16_rows.sh $dir/qcount-f16.txt > $rows ||
       [ "$(grep -c . $rows)" -ne "$(grep -c ', f16, ' src/core/f16_kernels.def)" ]; then
        fbad "the count did not run or missed a kernel ($dir/qcount-f16.log, $rows)"
    else
        sed 's/^/rvvfp16-count: /' $rows
        gv=$(riscv64-linux-gnu-gcc -dumpversion) clv=$(clang -dumpversion)
        if [ "${gv%%.*}" = 12 ] && [ "${clv%%.*}" = 14 ]; then
            doc_rows rvvfp16-count "RVV binary16 table" $rows \
                's/^| brdf_hammon | \([0-9.]*\) \/ \([0-9]\)/| brdf_hammon | \1 \/ 9\2/' brdf_hammon $dir/README.f16broken.md
            n=$?; pass=$((pass + 2 - n)); fail=$((fail + n))
        else
            echo "rvvfp16-count: riscv64-linux-gnu-gcc $gv, clang $clv: the figures are shown, not compared (ports/README.md: gcc 12, clang 14)"
        fi
    fi
    echo "rvvfp16-count: $pass passed, $fail failed, 0 skipped"
}

vlen_run() { # vlen_run VLEN: every test but the f32 accuracy
    v=$1
    run_one rvv-$v detect $v
    for t in $tests; do
        [ $t = test_f32_accuracy ] && continue
        FACET_TEST_QUICK=1 run_one rvv-$v qemu-riscv64 -L $sysroot -cpu $(cpu $v) $dir/tests/$t
    done
    run_one rvvfp16-$v f16_detect $v
    for t in $f16tests; do
        FACET_TEST_F16_FORCE=rvvfp16 FACET_TEST_QUICK=1 run_one rvvfp16-$v qemu-riscv64 -L $sysroot -cpu $(cpu16 $v) \
            $dir/tests/$t
    done
}
# side by side: the accuracy sweep (the longest, ~85 s of CPU) and each VLEN
FACET_TEST_QUICK=2 run_one rvv-128 qemu-riscv64 -L $sysroot -cpu $(cpu 128) $dir/tests/test_f32_accuracy \
    > $dir/accuracy.log 2>&1 &
for v in 256 512; do
    vlen_run $v > $dir/vlen$v.log 2>&1 &
done
run_one rvvfp16 f16_isa
vlen_run 128
wait
run_one rvvfp16 f16_count
cat $dir/accuracy.log $dir/vlen256.log $dir/vlen512.log
