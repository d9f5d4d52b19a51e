#!/bin/sh
# bench/qcount/report_md.sh - the Helium section of `make report` (Markdown
# on stdout): builds the Cortex-M55 library twice (build/m55: gcc 12;
# build/m55-clang: the helium objects from clang, ports/helium/port.mk) if
# needed and counts brdf_hammon's executed instructions per sample with
# bench/qcount/qcount.sh.  Skipped, with the reason, without the tools.
set -u
MAKE=${MAKE:-make}
have() { command -v "$1" > /dev/null 2>&1; }
echo "## Helium (Cortex-M55): brdf_hammon, executed instructions per sample"
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
echo "qemu-system-arm -M mps3-an547, -singlestep -d exec,nochain, 64-sample batch calls (MEASURED instruction counts, not cycles); scalar code from arm-none-eabi-gcc -O2 on the M55's FPU / integer unit."
echo
echo "| tier | scalar | helium (gcc 12) | helium (clang 14) | ratio (clang) | target >= 3x |"
echo "|---|---|---|---|---|---|"
for t in f32 f32_fast fx_fast; do
    s=$(awk -v t=$t '$2 == "scalar" && $3 == t { print $4 }' build/qcount/gcc.txt)
    g=$(awk -v t=$t '$2 == "helium" && $3 == t { print $4 }' build/qcount/gcc.txt)
    c=$(awk -v t=$t '$2 == "helium" && $3 == t { print $4 }' build/qcount/clang.txt)
    awk -v t=$t -v s="$s" -v g="$g" -v c="$c" 'BEGIN {
        r = (c > 0) ? s / c : 0
        printf "| %s | %s | %s | %s | %.2fx | %s |\n", t, s, g, c, r, (r >= 3) ? "met" : "missed" }'
done
echo
