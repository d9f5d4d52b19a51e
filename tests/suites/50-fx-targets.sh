# The fixed-point kernels on every target they promise, one summary line each:
#   fx-portable    host build with the ARMv6-M code paths (no UMULL, no CLZ)
#   fx-aarch64     pinned hashes under qemu-aarch64 + integer-only compile
#                  (-mgeneral-regs-only: a float register use is an error)
#   fx-armv7       pinned hashes under qemu-arm
#   fx-cortex-m0   pinned hashes on qemu-system-arm mps2-an385 (ARMv6-M code)
#   fx-cortex-m4   pinned hashes on qemu-system-arm mps2-an386
#   fx-cortex-m-calls  the M0/M4 kernel objects (precise and fx_fast) call no helper (no soft
#                  float, no __aeabi_lmul/llsl/uidiv): nm -u lists only fx's own
#   fx-rv32        freestanding RV32IMC link with -nostdlib: no undefined symbol
# A missing toolchain or emulator skips its target with the reason.
# lane: emulators
. tests/suite_lib.sh
B=build/emu # its own tree: it runs beside the host suites (tests/check.sh)
skip() { echo "SKIP $1: $2"; echo "$1: 0 passed, 0 failed, 1 skipped"; }
have() { command -v "$1" > /dev/null 2>&1; }
mk() { $MAKE -s -j"$JOBS" BUILD=$B "$@" > "$B/fx-$1.build.log" 2>&1; }
mkdir -p $B

if mk fx-portable; then run_one fx-portable $B/fx/portable/test_fx_hash
else cat $B/fx-fx-portable.build.log; echo "ERROR fx-portable: build failed"; fi

if ! have aarch64-linux-gnu-gcc || ! have arm-linux-gnueabihf-gcc; then
    skip fx-aarch64 "aarch64-linux-gnu-gcc or arm-linux-gnueabihf-gcc missing (apt-get install gcc-aarch64-linux-gnu gcc-arm-linux-gnueabihf)"
    skip fx-armv7 "cross compiler missing"
elif ! mk fx-linux-cross; then
    cat $B/fx-fx-linux-cross.build.log; echo "ERROR fx-aarch64: cross build (or integer-only compile) failed"
elif ! have qemu-aarch64 || ! have qemu-arm; then
    skip fx-aarch64 "qemu-aarch64/qemu-arm missing (apt-get install qemu-user)"
    skip fx-armv7 "qemu-user missing"
else
    run_one fx-aarch64 qemu-aarch64 -L /usr/aarch64-linux-gnu $B/fx/aarch64/test_fx_hash
    run_one fx-armv7 qemu-arm -L /usr/arm-linux-gnueabihf $B/fx/armv7/test_fx_hash
fi

if ! have arm-none-eabi-gcc; then
    skip fx-cortex-m0 "arm-none-eabi-gcc missing (apt-get install gcc-arm-none-eabi libnewlib-arm-none-eabi)"
    skip fx-cortex-m4 "arm-none-eabi-gcc missing"
    skip fx-cortex-m-calls "arm-none-eabi-gcc missing"
elif ! mk fx-cortex-m; then
    cat $B/fx-fx-cortex-m.build.log; echo "ERROR fx-cortex-m: build failed (newlib missing? apt-get install libnewlib-arm-none-eabi)"
else
    calls=$(arm-none-eabi-nm -u $B/fx/cortex-m0/fx_kernels.o $B/fx/cortex-m0/fx_core.o \
            $B/fx/cortex-m4/fx_kernels.o $B/fx/cortex-m4/fx_core.o \
            $B/fx/cortex-m0/fx_fast.o $B/fx/cortex-m4/fx_fast.o | grep ' U ' | grep -v ' U facet_fx_' | sort -u)
    if [ -z "$calls" ]; then echo "fx-cortex-m-calls: 1 passed, 0 failed, 0 skipped"
    else echo "FAIL fx-cortex-m-calls: helper calls in the kernels: $calls"; echo "fx-cortex-m-calls: 0 passed, 1 failed, 0 skipped"; fi
    if ! have qemu-system-arm; then
        skip fx-cortex-m0 "qemu-system-arm missing (apt-get install qemu-system-arm)"
        skip fx-cortex-m4 "qemu-system-arm missing"
    else
        for m in m0:mps2-an385 m4:mps2-an386; do
            run_one fx-cortex-${m%%:*} timeout 600 qemu-system-arm -M ${m#*:} -nographic \
                -semihosting-config enable=on,target=native -kernel $B/fx/cortex-${m%%:*}/test_fx_hash.elf
        done
    fi
fi

if ! have riscv64-linux-gnu-gcc; then
    skip fx-rv32 "riscv64-linux-gnu-gcc missing (apt-get install gcc-riscv64-linux-gnu)"
elif mk fx-rv32 && [ -z "$(riscv64-linux-gnu-nm -u $B/fx/rv32/fx.elf)" ]; then
    echo "fx-rv32: 1 passed, 0 failed, 0 skipped"
else
    cat $B/fx-fx-rv32.build.log
    echo "FAIL fx-rv32: freestanding RV32IMC link has undefined symbols"
    echo "fx-rv32: 0 passed, 1 failed, 0 skipped"
fi
