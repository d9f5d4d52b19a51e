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
#   qcount.sh m55-f16 [LIBDIR]  the same core and counting, every kernel
#                           with a binary16 form: helium f32 and f32_fast
#                           against heliumfp16 f16 (lines "cortex-m55
#                           <kernel> <format> ..."; ports/README.md's f16
#                           table, suite 52)
#   qcount.sh rv64 [LIBDIR] [VLEN...]  RV64GC + V under qemu-riscv64 (-cpu
#                           rv64,v=true,vlen=N; VLEN default 128 256 512):
#                           scalar code (riscv64-linux-gnu-gcc -O2) vs rvv
#                           (clang 14), from LIBDIR/libfacet.a (default
#                           build/rv64, made by tests/suites/54-rvv.sh);
#                           linked static, so the trace's pcs are nm's
#   qcount.sh rv64-f16 [LIBDIR] [VLEN...]  the same cores (-cpu
#                           rv64,v=true,Zfh=true,vlen=N), every kernel with a
#                           binary16 form: rvv f32 and f32_fast against the
#                           rvv line's f16 table rvvfp16, called directly
#                           (bench/report/armcount_main.c, ARMCOUNT_F16_ONLY;
#                           lines "rv64-vlenN <kernel> <format> ...";
#                           ports/README.md's RVV binary16 table, by
#                           bench/qcount/rvv_f16_rows.sh, suite 54)
# Prints "<core> <code> <tier> <instructions per sample> <cycles per sample>
# <left out per sample>" lines; the cycles (m55 only, "-" elsewhere or
# without llvm-mca-16) are
# llvm-mca-16's Cortex-M55 model (-mtriple=thumbv8.1m.main -mcpu=cortex-m55
# -mattr=+mve.fp) on the executed instruction sequence of the call as
# straight-line code (bench/qcount/m55_mca.awk): MODELLED, as the
# Cortex-M4 figures of bench/cortexm/ are, beside the MEASURED count; the
# last field counts the executed VMRS APSR_nzcv, FPSCR the model has no
# data for and the cycles leave out.
set -u
what=${1:-m55}
libdir=${2:-}
dir=build/qcount
mkdir -p "$dir"
# count ELF TRACE LABEL [DIS MCADIR [NAMES [BEGIN END]]]: the per-sample
# counts of the six marked calls; with DIS (objdump -d --no-show-raw-insn
# of ELF) and MCADIR, the executed instruction texts of call i go to
# MCADIR/i.s; with NAMES (a file, "FORMAT KERNEL" per call in call order:
# bench/report/armcount_main.c's output), every call is named by it
# ("<core> <kernel> <format>") and BEGIN, END are the marker functions
count() {
    b=$($NM "$1" 2>/dev/null | awk -v m="${7:-qcount_begin}" '$3 == m { print $1 }')
    e=$($NM "$1" 2>/dev/null | awk -v m="${8:-qcount_end}" '$3 == m { print $1 }')
    awk -v b="$b" -v e="$e" -v core="$3" -v mca="${5:-}" -v names="${6:-}" '
        BEGIN { k = 0; nn = 0
                if (names != "") while ((getline l < names) > 0) { split(l, w, " "); nf[nn] = w[1]; nk[nn++] = w[2] } }
        FILENAME == dis { if ($0 !~ /^ *[0-9a-f]+:\t/) next
            ad = $0; sub(/^ +/, "", ad); sub(/:.*$/, "", ad); t = $0; sub(/^ *[0-9a-f]+:\t/, "", t)
            while (length(ad) < 8) ad = "0" ad
            text[ad] = t; next }
        { split($4, a, "/"); pc = a[2]
          while (length(pc) < length(b)) pc = "0" pc }
        pc == b { on = 1; n = 0; next }
        pc == e && on { if (mca) close(mca "/" k ".s"); c[k++] = n; on = 0 }
        on { n++; if (mca) { p = pc; while (length(p) < 8) p = "0" p; print text[p] > (mca "/" k ".s") } }
        END {
            split("scalar f32|scalar f32_fast|scalar fx_fast|vector f32|vector f32_fast|vector fx_fast", nm, "|")
            for (i = 0; i < k; i++)
                if (names != "") printf "%s %s %s %.1f\n", core, nk[i], nf[i], c[i] / 64.0
                else printf "%s %s %.1f\n", core, nm[i + 1], c[i] / 64.0
        }' dis="${4:-}" ${4:+"$4"} "$2"
}
# mca LINES MCADIR: appends llvm-mca-16's Cortex-M55 cycles per sample of
# call i (MCADIR/i.s) to line i of LINES ("-" without llvm-mca-16), and
# the VMRS APSR_nzcv per sample m55_mca.awk leaves out
mca() {
    i=0
    while read -r core code tier insns; do
        c=- d=-
        if command -v llvm-mca-16 > /dev/null 2>&1 && [ -s "$2/$i.s" ]; then
            awk -f bench/qcount/m55_mca.awk "$2/$i.s" > "$2/$i.mca.s"
            c=$(llvm-mca-16 -mtriple=thumbv8.1m.main -mcpu=cortex-m55 -mattr=+mve.fp -iterations=1 "$2/$i.mca.s" 2> "$2/$i.err" |
                awk '/^Iterations:/ { it = $2 } /^Total Cycles:/ { c = $3 } END { if (it) printf "%.1f", c / it / 64 }')
            [ -n "$c" ] || c=-
            d=$(grep -c '^vmrs[[:space:]]*APSR_nzcv' "$2/$i.s" | awk '{ printf "%.1f", $1 / 64 }')
        fi
        echo "$core $code $tier $insns $c $d"
        i=$((i + 1))
    done < "$1"
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
    arm-none-eabi-objdump -d --no-show-raw-insn -m armv8.1-m.main "$dir/m55.elf" > "$dir/m55.dis"
    rm -rf "$dir/m55.d" && mkdir -p "$dir/m55.d"
    count "$dir/m55.elf" "$dir/m55.trace" cortex-m55 "$dir/m55.dis" "$dir/m55.d" | sed 's/ vector / helium /' > "$dir/m55.calls"
    rm -f "$dir/m55.trace"
    mca "$dir/m55.calls" "$dir/m55.d"
    [ -n "${QCOUNT_KEEP:-}" ] || rm -rf "$dir/m55.d"
    ;;
m55-f16)
    # every kernel with a binary16 form: helium f32, f32_fast and heliumfp16
    # f16 batches (bench/report/armcount_main.c, ARMCOUNT_F16_ONLY), the
    # same trace and model as m55; lines "cortex-m55 <kernel> <format> ..."
    NM=arm-none-eabi-nm
    lib=${libdir:-build/m55}/libfacet.a
    [ -f "$lib" ] || { echo "qcount: $lib missing (run the 52-helium suite first)"; exit 1; }
    arm-none-eabi-gcc -mcpu=cortex-m55 -mfloat-abi=hard -mthumb -O2 -std=c99 -Iinclude -DARMCOUNT_PORT=helium \
        -DARMCOUNT_F16_ONLY -DN=64 --specs=rdimon.specs -nostartfiles \
        -T tests/cortexm/an547.ld tests/cortexm/startup_m55.c bench/report/armcount_main.c "$lib" -lm \
        -o "$dir/m55f16.elf" || exit 1
    timeout 300 qemu-system-arm -M mps3-an547 -nographic -semihosting-config enable=on,target=native \
        -kernel "$dir/m55f16.elf" -singlestep -d exec,nochain -D "$dir/m55f16.trace" |
        tr -d '\r' | grep -v '^armcount' > "$dir/m55f16.names" || exit 1
    arm-none-eabi-objdump -d --no-show-raw-insn -m armv8.1-m.main "$dir/m55f16.elf" > "$dir/m55f16.dis"
    rm -rf "$dir/m55f16.d" && mkdir -p "$dir/m55f16.d"
    count "$dir/m55f16.elf" "$dir/m55f16.trace" cortex-m55 "$dir/m55f16.dis" "$dir/m55f16.d" "$dir/m55f16.names" \
        armcount_begin armcount_end > "$dir/m55f16.calls"
    rm -f "$dir/m55f16.trace"
    mca "$dir/m55f16.calls" "$dir/m55f16.d"
    [ -n "${QCOUNT_KEEP:-}" ] || rm -rf "$dir/m55f16.d"
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
        count "$dir/rv64.elf" "$dir/rv64.trace" rv64-vlen$v | sed -e 's/ vector / rvv /' -e 's/$/ - -/'
        rm -f "$dir/rv64.trace"
    done
    ;;
rv64-f16)
    NM=riscv64-linux-gnu-nm
    lib=${libdir:-build/rv64}/libfacet.a
    [ -f "$lib" ] || { echo "qcount: $lib missing (run the 54-rvv suite first)"; exit 1; }
    shift $(($# < 2 ? $# : 2))
    # the ports the library holds, as its build told src/core/platform.h
    # (the RISC-V rungs follow the build's flags, not the compiler's target)
    pf=$(riscv64-linux-gnu-nm "$lib" | awk '$3 == "facet_port_rvv_f32" { print "-DFACET_PORT_RVV=1" }
                                          $3 == "facet_f16_port_rvvfp16" { print "-DFACET_PORT_RVVFP16=1" }' | sort -u)
    # shellcheck disable=SC2086
    riscv64-linux-gnu-gcc -O2 -std=c99 -Iinclude -static $pf -DARMCOUNT_PORT=rvv -DARMCOUNT_F16_ONLY -DN=64 \
        bench/report/armcount_main.c "$lib" -lm -o "$dir/rv64f16.elf" || exit 1
    for v in ${*:-128 256 512}; do
        timeout 300 qemu-riscv64 -cpu rv64,v=true,vext_spec=v1.0,Zfh=true,vlen=$v -singlestep -d exec,nochain \
            -D "$dir/rv64f16.trace" "$dir/rv64f16.elf" > "$dir/rv64f16.out" || exit 1
        grep -q '^armcount-f16: rvvfp16$' "$dir/rv64f16.out" || { echo "qcount: the rvv line runs no rvvfp16 table"; exit 1; }
        grep -v '^armcount' "$dir/rv64f16.out" > "$dir/rv64f16.names"
        count "$dir/rv64f16.elf" "$dir/rv64f16.trace" rv64-vlen$v "" "" "$dir/rv64f16.names" armcount_begin armcount_end |
            sed 's/$/ - -/'
        rm -f "$dir/rv64f16.trace"
    done
    ;;
esac
