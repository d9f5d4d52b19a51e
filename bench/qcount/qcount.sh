#!/bin/sh
# bench/qcount/qcount.sh - executed instructions per sample of brdf_hammon's
# batch functions (64 samples a call; bench/qcount/qcount_main.c) in each
# tier, scalar code vs the vector port on the same core, counted by qemu:
# -singlestep -d exec,nochain logs one line per executed instruction; the
# lines between the markers qcount_begin and qcount_end are one call.
#   qcount.sh m55 [LIBDIR]  Cortex-M55 (qemu-system-arm -M mps3-an547):
#                           scalar FPU / integer code vs helium, from
#                           LIBDIR/libfacet.a (default build/m55; build/m55-clang
#                           has the helium objects from clang; both made by
#                           tests/suites/52-helium.sh)
#   qcount.sh rv64 [LIBDIR] [VLEN...]  RV64GC + V under qemu-riscv64 (-cpu
#                           rv64,v=true,vlen=N; VLEN default 128 256 512):
#                           scalar code (riscv64-linux-gnu-gcc -O2) vs rvv
#                           (clang 14), from LIBDIR/libfacet.a (default
#                           build/rv64, made by tests/suites/54-rvv.sh);
#                           linked static, so the trace's pcs are nm's
# Prints "<core> <code> <tier> <instructions per sample>" lines.
set -u
what=${1:-m55}
libdir=${2:-}
dir=build/qcount
mkdir -p "$dir"
# count ELF TRACE LABEL: the per-sample counts of the six marked calls
count() {
    b=$($NM "$1" 2>/dev/null | awk '$3 == "qcount_begin" { print $1 }')
    e=$($NM "$1" 2>/dev/null | awk '$3 == "qcount_end" { print $1 }')
    awk -v b="$b" -v e="$e" -v core="$3" '
        { split($4, a, "/"); pc = a[2]
          while (length(pc) < length(b)) pc = "0" pc }
        pc == b { on = 1; n = 0; next }
        pc == e && on { c[k++] = n; on = 0 }
        on { n++ }
        END {
            split("scalar f32|scalar f32_fast|scalar fx_fast|vector f32|vector f32_fast|vector fx_fast", nm, "|")
            for (i = 0; i < k; i++) printf "%s %s %.1f\n", core, nm[i + 1], c[i] / 64.0
        }' "$2"
}
NM=nm
case $what in
m55)
    NM=arm-none-eabi-nm
    lib=${libdir:-build/m55}/libfacet.a
    [ -f "$lib" ] || { echo "qcount: $lib missing (run the 52-helium suite first)"; exit 1; }
    arm-none-eabi-gcc -mcpu=cortex-m55 -mfloat-abi=hard -mthumb -O2 -std=c99 -Iinclude \
        -DQCOUNT_F32=facet_port_helium_f32 -DQCOUNT_F32_FAST=facet_port_helium_f32_fast \
        -DQCOUNT_FX_FAST=facet_fx_fast_port_helium --specs=rdimon.specs -nostartfiles \
        -T tests/cortexm/an547.ld tests/cortexm/startup_m55.c bench/qcount/qcount_main.c "$lib" -lm \
        -o "$dir/m55.elf" || exit 1
    timeout 300 qemu-system-arm -M mps3-an547 -nographic -semihosting-config enable=on,target=native \
        -kernel "$dir/m55.elf" -singlestep -d exec,nochain -D "$dir/m55.trace" > /dev/null || exit 1
    count "$dir/m55.elf" "$dir/m55.trace" cortex-m55 | sed 's/ vector / helium /'
    rm -f "$dir/m55.trace"
    ;;
rv64)
    NM=riscv64-linux-gnu-nm
    lib=${libdir:-build/rv64}/libfacet.a
    [ -f "$lib" ] || { echo "qcount: $lib missing (run the 54-rvv suite first)"; exit 1; }
    shift $(($# < 2 ? $# : 2))
    riscv64-linux-gnu-gcc -O2 -std=c99 -Iinclude -static \
        -DQCOUNT_F32=facet_port_rvv_f32 -DQCOUNT_F32_FAST=facet_port_rvv_f32_fast \
        -DQCOUNT_FX_FAST=facet_fx_fast_port_rvv bench/qcount/qcount_main.c "$lib" -lm \
        -o "$dir/rv64.elf" || exit 1
    for v in ${*:-128 256 512}; do
        timeout 300 qemu-riscv64 -cpu rv64,v=true,vext_spec=v1.0,vlen=$v -singlestep -d exec,nochain \
            -D "$dir/rv64.trace" "$dir/rv64.elf" > /dev/null || exit 1
        count "$dir/rv64.elf" "$dir/rv64.trace" rv64-vlen$v | sed 's/ vector / rvv /'
        rm -f "$dir/rv64.trace"
    done
    ;;
esac
