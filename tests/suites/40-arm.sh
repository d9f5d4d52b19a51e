# The library, the NEON port and every C test (and the bench's PNG and
# rasterizer test, NEON path included; build/facet-bench is built, not run)
# cross-built for aarch64 and
# armv7 (hard float; NEON objects alone get -mfpu=neon-vfpv4) and run under
# qemu-user; then the facet command's tests through qemu.  Skipped, with the
# reason, where the cross compiler or qemu is missing (.ci/run installs them).
# lane: emulators
. tests/lib/suite_lib.sh
for target in aarch64 armv7; do
    case $target in
    aarch64) cc=aarch64-linux-gnu-gcc qemu=qemu-aarch64 sysroot=/usr/aarch64-linux-gnu ;;
    armv7) cc=arm-linux-gnueabihf-gcc qemu=qemu-arm sysroot=/usr/arm-linux-gnueabihf ;;
    esac
    if ! command -v $cc > /dev/null 2>&1; then
        echo "SKIP $target: $cc not installed (apt-get install gcc-${cc%-gcc})"
        echo "$target: 0 passed, 0 failed, 1 skipped"
        continue
    fi
    if ! command -v $qemu > /dev/null 2>&1; then
        echo "SKIP $target: $qemu not installed (apt-get install qemu-user)"
        echo "$target: 0 passed, 0 failed, 1 skipped"
        continue
    fi
    dir=build/$target
    mkdir -p $dir
    bins=""
    for t in tests/*/test_*.c bench/test_bench.c; do
        [ -f "$t" ] && bins="$bins $dir/tests/$(basename "$t" .c)"
    done
    if ! $MAKE -s -j"$JOBS" BUILD=$dir CC=$cc CFLAGS="-O2 -g" lib $dir/facet $dir/facet-bench $bins > $dir/build.log 2>&1; then
        cat $dir/build.log
        echo "ERROR $target: cross build failed (log: $dir/build.log)"
        continue
    fi
    # the accuracy sweep at its emulator level (strided 5- and 6-input edge
    # grids, 30000 random samples; bounds unchanged): at level 1 it was over
    # 4 minutes of the suite per target under qemu with the whole menu
    for t in $bins; do
        level=1
        case $t in */test_f32_accuracy) level=2 ;; esac
        FACET_TEST_QUICK=$level run_one $target $qemu -L $sysroot "$t"
    done
    FACET_EXEC="$qemu -L $sysroot" run_one $target sh tests/cli/test_cli.sh $dir
    # f16 on an aarch64 CPU without FP16 arithmetic (Cortex-A57, ARMv8.0):
    # the neonfp16 table refused with its reason, the scalar one runs
    if [ $target = aarch64 ]; then
        res=$(FACET_TEST_QUICK=1 $qemu -cpu cortex-a57 -L $sysroot $dir/tests/test_f16_ports 2>&1)
        if printf '%s' "$res" | grep -q "port neonfp16: refused: ARMv8.2-A FP16" &&
            printf '%s' "$res" | tail -n 1 | grep -q ' 0 failed'; then
            echo "aarch64/cortex-a57: 1 passed, 0 failed, 0 skipped"
        else
            printf '%s\n' "$res" | tail -n 3
            echo "aarch64/cortex-a57: 0 passed, 1 failed, 0 skipped"
        fi
    fi
done
