#!/bin/sh
# bench/qcount/report_md.sh - the Helium and RISC-V Vector sections of
# `make report` (Markdown on stdout): builds the Cortex-M55 library twice
# (build/m55: gcc 12; build/m55-clang: the helium objects from clang,
# ports/helium/port.mk) and the riscv64 one (build/rv64: gcc 12, the rvv
# objects from clang, ports/rvv/port.mk) if needed and counts brdf_hammon's
# executed instructions per sample with bench/qcount/qcount.sh (on the M55
# also llvm-mca-16's modelled cycles on the executed trace; the cycle
# columns say why where llvm-mca-16 is missing), and on the M55 every
# kernel's binary16 batch against the f32 tiers (qcount.sh m55-f16; on RVV
# qcount.sh rv64-f16).  Each section skipped,
# with the reason, without its tools.
set -u
MAKE=${MAKE:-make}
have() { command -v "$1" > /dev/null 2>&1; }
rvv_section() {
    echo "## RISC-V Vector (RV64GCV, qemu-riscv64): brdf_hammon, executed instructions per sample"
    echo
    if ! have riscv64-linux-gnu-gcc || ! have qemu-riscv64 || ! have clang; then
        echo "Skipped: needs riscv64-linux-gnu-gcc (with libc6-dev-riscv64-cross), qemu-riscv64 and clang."
        echo
        return
    fi
    mkdir -p build/qcount
    if ! $MAKE -s BUILD=build/rv64 CC=riscv64-linux-gnu-gcc CFLAGS="-O2 -g" build/rv64/libfacet.a > /dev/null 2>&1 ||
        ! sh bench/qcount/qcount.sh rv64 build/rv64 128 256 512 2>/dev/null > build/qcount/rv64.txt; then
        echo "Skipped: the riscv64 build or the count failed."
        echo
        return
    fi
    echo "qemu-riscv64 -cpu rv64,v=true,vlen=N, -singlestep -d exec,nochain, 64-sample batch calls (MEASURED instruction counts, not cycles); scalar code from riscv64-linux-gnu-gcc -O2 (rv64gc), rvv from clang -O2 (LMUL 1)."
    echo
    echo "| tier | scalar RV64 | rvv VLEN 128 | ratio | rvv VLEN 256 | ratio | rvv VLEN 512 | ratio | target >= 3x at 128 |"
    echo "|---|---|---|---|---|---|---|---|---|"
    for t in f32 f32_fast fx_fast; do
        awk -v t=$t '$3 == t { v[$1 " " $2] = $4 }
            END {
                s = v["rv64-vlen128 scalar"]; a = v["rv64-vlen128 rvv"]; b = v["rv64-vlen256 rvv"]; c = v["rv64-vlen512 rvv"]
                if (a <= 0 || b <= 0 || c <= 0) { printf "| %s | %s | - | | - | | - | | count missing |\n", t, s; exit }
                printf "| %s | %s | %s | %.2fx | %s | %.2fx | %s | %.2fx | %s |\n", t, s, a, s / a, b, s / b, c, s / c,
                       (s / a >= 3) ? "met" : "missed" }' build/qcount/rv64.txt
    done
    echo
    echo "Binary16 (rvvfp16, Zvfh; qemu -cpu rv64,v=true,Zfh=true: the table called directly, as the dispatcher refuses it under qemu-user 7.2) against the rvv f32 tiers, every kernel with an f16 form (bench/qcount/qcount.sh rv64-f16; instructions per sample, each cell VLEN 128 / 256 / 512; an f32-lane op of rvvfp16 is one LMUL 2 instruction). Target (issue 22): brdf_hammon f16 >= 1.7x f32."
    echo
    echo "| kernel | f32 | f32_fast | f16 | f16 vs f32 | f16 vs f32_fast |"
    echo "|---|---|---|---|---|---|"
    if sh bench/qcount/qcount.sh rv64-f16 build/rv64 128 256 512 2>/dev/null > build/qcount/rv64f16.txt; then
        sh bench/qcount/rvv_f16_rows.sh build/qcount/rv64f16.txt
    else
        echo "| (the count failed: no rvvfp16 table in build/rv64?) | | | | | |"
    fi
    echo
}
rvv_section
echo "## Helium (Cortex-M55): brdf_hammon, executed instructions and modelled cycles per sample"
echo
if ! have arm-none-eabi-gcc || ! have qemu-system-arm || ! have clang; then
    echo "Skipped: needs arm-none-eabi-gcc, qemu-system-arm and clang."
    exit 0
fi
for v in m55:arm-none-eabi-gcc m55-clang:clang; do
    $MAKE -s BUILD=build/${v%%:*} CC=arm-none-eabi-gcc AR=arm-none-eabi-ar PICFLAGS= HELIUM_CC=${v#*:} \
        CFLAGS="-mcpu=cortex-m55 -mfloat-abi=hard -mthumb -O2 -g" build/${v%%:*}/libfacet.a > /dev/null 2>&1 ||
        { echo "Skipped: the Cortex-M55 build failed."; exit 0; }
done
sh bench/qcount/qcount.sh m55 build/m55 2>/dev/null > build/qcount/gcc.txt
sh bench/qcount/qcount.sh m55 build/m55-clang 2>/dev/null > build/qcount/clang.txt
echo "qemu-system-arm -M mps3-an547, -singlestep -d exec,nochain, 64-sample batch calls: instr = MEASURED executed instructions; cyc = MODELLED cycles, llvm-mca-16 -mtriple=thumbv8.1m.main -mcpu=cortex-m55 -mattr=+mve.fp on the executed instruction sequence of the call as straight-line code (bench/qcount/m55_mca.awk: no fetch or branch penalty, no wait states), as the Cortex-M4 figures are modelled. Scalar code from arm-none-eabi-gcc -O2 on the M55's FPU / integer unit."
echo
if ! have llvm-mca-16; then
    echo "No modelled cycles: llvm-mca-16 not installed (Debian llvm-16; LLVM 14's llvm-mca has no Cortex-M55 model)."
    echo
fi
echo "| tier | scalar instr | scalar cyc | helium (gcc 12) instr | cyc | helium (clang 14) instr | cyc | ratio instr (clang) | ratio cyc (clang) | target >= 3x (instr) |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for t in f32 f32_fast fx_fast; do
    awk -v t=$t 'FILENAME ~ /gcc/ && $3 == t { if ($2 == "scalar") { s = $4; sc = $5 } else { g = $4; gc = $5 } }
        FILENAME ~ /clang/ && $3 == t && $2 == "helium" { c = $4; cc = $5 }
        END {
            r = (c > 0) ? s / c : 0
            rc = (cc + 0 > 0 && sc + 0 > 0) ? sprintf("%.2fx", sc / cc) : "-"
            printf "| %s | %s | %s | %s | %s | %s | %s | %.2fx | %s | %s |\n", t, s, sc, g, gc, c, cc, r, rc,
                   (r >= 3) ? "met" : "missed" }' build/qcount/gcc.txt build/qcount/clang.txt
done
echo
echo "Binary16 (heliumfp16) against the helium f32 tiers, every kernel with an f16 form (bench/qcount/qcount.sh m55-f16; instr / cyc per sample as above, clang 14; ratios instructions / cycles; the last column heliumfp16 from gcc 12). Target (issue 22): brdf_hammon f16 >= 1.7x f32."
echo
echo "| kernel | f32 | f32_fast | f16 | f16 vs f32 | f16 vs f32_fast | f16 (gcc 12) |"
echo "|---|---|---|---|---|---|---|"
if sh bench/qcount/qcount.sh m55-f16 build/m55 2>/dev/null > build/qcount/f16-gcc.txt &&
   sh bench/qcount/qcount.sh m55-f16 build/m55-clang 2>/dev/null > build/qcount/f16-clang.txt; then
    sh bench/qcount/f16_rows.sh build/qcount/f16-gcc.txt build/qcount/f16-clang.txt
else
    echo "| (the count failed) | | | | | | |"
fi
echo
awk '$6 + 0 > 0 { d = d (d ? ", " : "") $2 " " $3 " " $6 } END {
    if (d) printf "The cycles leave out the executed VMRS APSR_nzcv, FPSCR (the FP compare'"'"'s flags to the core; LLVM 16'"'"'s M55 model has no data for it), per sample: %s.\n\n", d }' \
    build/qcount/gcc.txt
