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
#   fx-firmware    the README's firmware link (`make fx-sources`, -Os,
#                  --gc-sections, newlib) on M0 and M4, both tiers' batch:
#                  runs on qemu (batch == scalar kernel), holds no symbol of
#                  the library outside the fixed-point sources (f32 kernels,
#                  dispatcher, CPU detection, samplers, oracle: src/*.c
#                  compiled for the host, names only), no libm function and no
#                  float helper; the same check must reject an image that
#                  calls the oracle; prints the image sizes
# A missing toolchain or emulator skips its target with the reason.
# lane: emulators
. tests/lib/suite_lib.sh
B=build/emu # its own tree: it runs beside the host suites (tests/check.sh)
skip() { echo "SKIP $1: $2"; echo "$1: 0 passed, 0 failed, 1 skipped"; }
have() { command -v "$1" > /dev/null 2>&1; }
mk() { $MAKE -s -j"$JOBS" BUILD=$B "$@" > "$B/fx-$1.build.log" 2>&1; }
mkdir -p $B

# fw_bad ELF: the symbols of ELF that a firmware link of the fixed-point
# sources must not hold: a global that a library source outside them
# defines (src/*.c compiled for the host, names only: tests/fx/fx.mk
# fx-host-syms; src/fx/fx_batch.c is libfacet's dispatched batch API, which
# src/fx/fx_firmware_batch.c defines for firmware, with
# facet_fx_port_name), a libm function, a soft-float helper
fw_bad() {
    arm-none-eabi-nm "$1" | awk '{ print $NF }' | sort -u > "$B/fx-fw.syms"
    { awk -v ok="$($MAKE -s fx-sources) src/fx/fx_batch.c" '
          BEGIN { n = split(ok, a, " "); for (i = 1; i <= n; i++) allowed[a[i]] = 1 }
          !($1 in allowed) && $2 != "facet_fx_port_name" { print $2 }' "$B/fx/host-syms.txt"
      grep -E '^(__aeabi_([fd]|[ui]?[il]2[fd])|__(add|sub|mul|div)[sd]f3|__float|__fix|__extend|__trunc|__ieee754|(sqrt|pow|exp|expm1|log|log1p|sin|cos|tan|atan2|cbrt|hypot)f?$)' "$B/fx-fw.syms"
    } | sort -u | comm -12 - "$B/fx-fw.syms"
}
fw_check() {
    if ! mk fx-host-syms || ! grep -q '^src/oracle/oracle.c facet_oracle_lambert$' "$B/fx/host-syms.txt"; then
        cat "$B/fx-fx-host-syms.build.log"; echo "ERROR fx-firmware: the host symbol list failed"; return
    fi
    p=0 f=0
    for c in m0 m4; do
        for t in fw fw_fast; do
            e=$B/fx/cortex-$c/$t.elf
            bad=$(fw_bad "$e" | tr '\n' ' ')
            if [ -z "$bad" ]; then p=$((p + 1)); else f=$((f + 1)); echo "FAIL fx-firmware: $e holds $bad"; fi
            if have qemu-system-arm; then
                m=mps2-an385; [ $c = m4 ] && m=mps2-an386
                if timeout 120 qemu-system-arm -M $m -nographic -semihosting-config enable=on,target=native \
                       -kernel "$e" > "$B/fx-fw.run.log" 2>&1; then p=$((p + 1))
                else f=$((f + 1)); echo "FAIL fx-firmware: $e on qemu $m: batch != scalar kernel (or a fault)"; fi
            fi
        done
        # the check can fail: the image that also calls the oracle holds its
        # symbol and the soft-float double helpers
        bad=$(fw_bad $B/fx/cortex-$c/fw_oracle.elf | tr '\n' ' ')
        case "$bad" in *facet_oracle_lambert*__aeabi_d*|*__aeabi_d*facet_oracle_lambert*) p=$((p + 1)) ;;
            *) f=$((f + 1)); echo "FAIL fx-firmware: the check does not reject fw_oracle.elf ($c): '$bad'" ;; esac
        echo "fx-firmware: cortex-$c .text+.data bytes (arm-none-eabi-size): $(for t in fw_base fw fw_fast; do
            arm-none-eabi-size $B/fx/cortex-$c/$t.elf | awk -v t=$t 'NR == 2 { printf "%s %d+%d  ", t, $1, $2 }'; done)"
    done
    s=0
    have qemu-system-arm || { s=1; echo "SKIP fx-firmware: qemu-system-arm missing (the images are checked, not run)"; }
    echo "fx-firmware: $p passed, $f failed, $s skipped"
}

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
    calls=$(arm-none-eabi-nm -u $B/fx/cortex-m0/fx_kernels.o $B/fx/cortex-m0/fx_prims.o \
            $B/fx/cortex-m4/fx_kernels.o $B/fx/cortex-m4/fx_prims.o \
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
    fw_check
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
