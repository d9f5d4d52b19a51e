# The Helium port on a Cortex-M55: the library built with arm-none-eabi-gcc
# for -mcpu=cortex-m55 (helium and scalar ports, MVE and the FPU), and the C
# tests that exercise the ports linked as bare-metal images (tests/ports/helium.mk)
# run on qemu-system-arm -M mps3-an547 with semihosting:
#   test_f32_ports     lanes, every tail, alignment, aliasing, symmetry, bad
#                      input, on both f32 tiers of each port
#   test_f32_accuracy  both tiers against the oracle at the facet.h bounds
#                      (FACET_TEST_QUICK=2 counts, 30000 random samples)
#   test_fx_ports      fx and fx_fast batches bit for bit against the scalar
#                      specification, tails, aliasing, the pinned hashes
#   test_fx_hash       the pinned hashes of the scalar kernels on the M55
#   test_sample_ports, test_f32_bad_input  the samplers' and the bad-input contracts
#   test_f32_rgb, test_fx_rgb  the RGB batches (every layout, tail, alias) and RGB fixed point
# Skipped, with the reason, where the toolchain or qemu is missing.
# lane: emulators
. tests/lib/suite_lib.sh
have() { command -v "$1" > /dev/null 2>&1; }
if ! have arm-none-eabi-gcc; then
    echo "SKIP helium: arm-none-eabi-gcc missing (apt-get install gcc-arm-none-eabi libnewlib-arm-none-eabi)"
    echo "helium: 0 passed, 0 failed, 1 skipped"
    exit 0
fi
if ! have qemu-system-arm; then
    echo "SKIP helium: qemu-system-arm missing (apt-get install qemu-system-arm)"
    echo "helium: 0 passed, 0 failed, 1 skipped"
    exit 0
fi
# build/m55: everything with arm-none-eabi-gcc; build/m55-clang: the two
# helium objects with clang (HELIUM_CC, ports/helium/port.mk; the README's
# instruction counts), its port tests only.  Skipped without clang.
m55() { # m55 DIR LABEL HELIUM_CC TESTS...
    dir=$1 label=$2 hcc=$3
    shift 3
    mkdir -p $dir
    elfs=""
    for t in "$@"; do elfs="$elfs $dir/tests/$t.elf"; done
    if ! $MAKE -s -j"$JOBS" BUILD=$dir CC=arm-none-eabi-gcc AR=arm-none-eabi-ar PICFLAGS= M55_ARG=30000 \
            HELIUM_CC=$hcc CFLAGS="-mcpu=cortex-m55 -mfloat-abi=hard -mthumb -O2 -g" $elfs > $dir/build.log 2>&1; then
        cat $dir/build.log
        echo "ERROR $label: Cortex-M55 build failed (log: $dir/build.log)"
        return
    fi
    for t in "$@"; do
        run_one $label timeout 600 qemu-system-arm -M mps3-an547 -nographic \
            -semihosting-config enable=on,target=native -kernel $dir/tests/$t.elf
    done
}
m55 build/m55 helium arm-none-eabi-gcc test_f32_ports test_f32_accuracy test_fx_ports test_fx_hash \
    test_sample_ports test_sample_small test_f32_bad_input test_f32_rgb test_fx_rgb test_tails
if have clang; then
    m55 build/m55-clang helium-clang clang test_f32_ports test_f32_accuracy test_fx_ports test_sample_ports
else
    echo "SKIP helium-clang: clang missing (apt-get install clang)"
    echo "helium-clang: 0 passed, 0 failed, 1 skipped"
fi
