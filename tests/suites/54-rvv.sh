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
bins=""
for t in $tests; do bins="$bins $dir/tests/$t"; done
mkdir -p $dir
if ! $MAKE -s -j"$JOBS" BUILD=$dir CC=riscv64-linux-gnu-gcc CFLAGS="-O2 -g" $dir/facet $bins > $dir/build.log 2>&1; then
    cat $dir/build.log
    echo "ERROR rvv: cross build failed (log: $dir/build.log)"
    exit 0
fi
cpu() { echo "rv64,v=true,vext_spec=v1.0,vlen=$1"; }

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

vlen_run() { # vlen_run VLEN: every test but accuracy
    v=$1
    run_one rvv-$v detect $v
    for t in $tests; do
        [ $t = test_f32_accuracy ] && continue
        FACET_TEST_QUICK=1 run_one rvv-$v qemu-riscv64 -L $sysroot -cpu $(cpu $v) $dir/tests/$t
    done
}
# side by side: the accuracy sweep (the longest, ~85 s of CPU) and each VLEN
FACET_TEST_QUICK=2 run_one rvv-128 qemu-riscv64 -L $sysroot -cpu $(cpu 128) $dir/tests/test_f32_accuracy \
    > $dir/accuracy.log 2>&1 &
for v in 256 512; do
    vlen_run $v > $dir/vlen$v.log 2>&1 &
done
vlen_run 128
wait
cat $dir/accuracy.log $dir/vlen256.log $dir/vlen512.log
