#!/bin/sh
# digest.sh OUTDIR - the output digest of this tree on every target that
# runs here (tests/digest/digest.c, plus `facet vectors` of every fixed-point kernel
# and tier, the pinned hashes test and the accuracy table of each target),
# one file per target in OUTDIR.  A refactor that changes no output bit
# gives byte-identical files:
#   sh tests/digest/digest.sh /tmp/before    (on the old tree)
#   sh tests/digest/digest.sh /tmp/after     (on the new one)
#   diff -r /tmp/before /tmp/after
# Targets: the host (every x86 port it runs), aarch64 and armv7 under
# qemu-user, riscv64 with V at VLEN 128 and 512, the Cortex-M55 image under
# qemu-system-arm.  A target whose tools are missing is named and skipped.
set -u
out=${1:?usage: digest.sh OUTDIR}
MAKE=${MAKE:-make}
JOBS=${JOBS:-2}
mkdir -p "$out"
have() { command -v "$1" > /dev/null 2>&1; }

vectors() { # vectors FACET_CMD...: facet vectors of every fixed-point kernel and tier
    "$@" list --formats | while read -r k formats; do
        for f in $formats; do
            case $f in fx|fx_fast) ;; *) continue ;; esac
            echo "== vectors $k $f"
            "$@" vectors "$k" --format $f --count 300 --seed 11 --hex 2>&1
        done
    done
}

host() {
    d=build/digest-host
    $MAKE -s -j"$JOBS" BUILD=$d $d/facet $d/tests/digest $d/tests/test_fx_hash $d/tests/test_f32_accuracy \
        $d/tests/test_fx_accuracy > $d.log 2>&1 || { cat $d.log; return; }
    { $d/tests/digest; vectors $d/facet; $d/tests/test_fx_hash; } > "$out/host.txt" 2>&1
    # the accuracy tables (a fixed sample set; the quick level)
    { FACET_TEST_QUICK=2 $d/tests/test_f32_accuracy 20000; FACET_TEST_QUICK=1 $d/tests/test_fx_accuracy; } \
        > "$out/host-accuracy.txt" 2>&1
}

cross() { # cross NAME CC QEMU SYSROOT
    name=$1 cc=$2 qemu=$3 sysroot=$4
    if ! have "$cc" || ! have "$qemu"; then echo "digest: $name skipped ($cc or $qemu missing)"; return; fi
    d=build/digest-$name
    $MAKE -s -j"$JOBS" BUILD=$d CC=$cc CFLAGS="-O2 -g" $d/facet $d/tests/digest $d/tests/test_fx_hash > $d.log 2>&1 ||
        { cat $d.log; return; }
    { $qemu -L $sysroot $d/tests/digest; vectors $qemu -L $sysroot $d/facet
      $qemu -L $sysroot $d/tests/test_fx_hash; } > "$out/$name.txt" 2>&1
}

rvv() {
    if ! have riscv64-linux-gnu-gcc || ! have qemu-riscv64 || ! have clang; then echo "digest: rvv skipped"; return; fi
    d=build/digest-rv64
    $MAKE -s -j"$JOBS" BUILD=$d CC=riscv64-linux-gnu-gcc CFLAGS="-O2 -g" $d/facet $d/tests/digest > $d.log 2>&1 ||
        { cat $d.log; return; }
    for v in 128 512; do
        qemu-riscv64 -L /usr/riscv64-linux-gnu -cpu rv64,v=true,vext_spec=v1.0,vlen=$v $d/tests/digest \
            > "$out/rv64-vlen$v.txt" 2>&1
    done
}

m55() {
    if ! have arm-none-eabi-gcc || ! have qemu-system-arm; then echo "digest: m55 skipped"; return; fi
    d=build/digest-m55
    $MAKE -s -j"$JOBS" BUILD=$d CC=arm-none-eabi-gcc AR=arm-none-eabi-ar PICFLAGS= \
        CFLAGS="-mcpu=cortex-m55 -mfloat-abi=hard -mthumb -O2 -g" $d/tests/digest.elf > $d.log 2>&1 ||
        { cat $d.log; return; }
    timeout 600 qemu-system-arm -M mps3-an547 -nographic -semihosting-config enable=on,target=native \
        -kernel $d/tests/digest.elf > "$out/m55.txt" 2>&1
}

host
cross aarch64 aarch64-linux-gnu-gcc qemu-aarch64 /usr/aarch64-linux-gnu
cross armv7 arm-linux-gnueabihf-gcc qemu-arm /usr/arm-linux-gnueabihf
rvv
m55
wc -l "$out"/*.txt
