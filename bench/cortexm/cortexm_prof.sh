#!/bin/sh
# bench/cortexm/cortexm_prof.sh [BUILD_DIR] [KERNEL...] - where the fixed-point
# kernels spend their executed instructions on Cortex-M0 and M4 (run as
# `bench/cortexm/cortexm.sh --profile ...`).  Same build and qemu trace as
# bench/cortexm/cortexm.sh (-O2, the 4 inputs of bench/cortexm/cortexm_main.c), plus -g:
# every executed address of a kernel call is mapped through the DWARF
# inline chain (addr2line -i) and counted twice, per call (mean of the 4):
#   op    the outermost fx primitive the instruction belongs to: an fxe_*
#         pseudo-float operation, an fxq_* fast-tier helper (not the kernel's
#         own fxq_<kernel>), a facet_fx_* out-of-line primitive (rcp32,
#         div2by1, isqrt64, rsqrt32), or an fxv_* lane op or fxp_* exact
#         primitive used directly by the kernel's body;
#         "(kernel)" for the kernel's own code (clamps, exact products)
#   self  the innermost (inlined) function: fxp_mul64, fxv_sel, ...
# MEASURED executed instructions (qemu), not cycles.  Default kernels:
# brdf_hammon ggx_d smith_vis diffuse_hammon.  CORTEXM_TIER=fast profiles the
# fast tier (facet_<kernel>_fx_fast) instead; CORTEXM_CPUS restricts the cores.
set -u
case ${CORTEXM_TIER:-} in
fast) tsrc="-DBENCH_FX_FAST src/fx/fx_fast.c" tpat='_fx_fast$' ;;
*) tsrc="" tpat='_fx$' ;;
esac
build=${1:-build}
[ $# -gt 0 ] && shift
kernels=${*:-brdf_hammon ggx_d smith_vis diffuse_hammon}
dir=$build/bench/cortexm-prof
mkdir -p "$dir"
have() { command -v "$1" >/dev/null 2>&1; }
if ! have arm-none-eabi-gcc || ! have qemu-system-arm; then
    echo "cortexm-prof: skipped (needs arm-none-eabi-gcc and qemu-system-arm)"
    exit 0
fi
link="--specs=rdimon.specs -nostartfiles -T tests/cortexm/mps2.ld tests/cortexm/startup.c"
cflags="-mthumb -O2 -g -std=c99 -Wall -Wextra -Werror -Iinclude"
for cpu in ${CORTEXM_CPUS:-cortex-m0 cortex-m4}; do
    case $cpu in cortex-m0) mach=mps2-an385 ;; *) mach=mps2-an386 ;; esac
    b=$dir/$cpu
    rm -rf "$b.d"
    mkdir -p "$b.d"
    # shellcheck disable=SC2086
    arm-none-eabi-gcc -mcpu=$cpu $cflags $link -DBENCH_FX $tsrc src/fx/fx_prims.c src/fx/fx_kernels.c \
        bench/cortexm/cortexm_main.c -o "$b.elf" || exit 1
    arm-none-eabi-objdump -d "$b.elf" > "$b.dis"
    arm-none-eabi-nm "$b.elf" | awk -v p="^facet_.*$tpat" '$2 ~ /^[Tt]$/ && $3 ~ p { print $1, $3 }' |
        sed -e 's/ facet_\(.*\)_fx_fast$/ \1/' -e 's/ facet_\(.*\)_fx$/ \1/' > "$b.sym"
    timeout 120 qemu-system-arm -M $mach -nographic -semihosting-config enable=on,target=native \
        -kernel "$b.elf" -singlestep -d exec,nochain -D "$b.trace" >/dev/null 2>&1 || exit 1
    awk -v dir="$b.d" -v pcs=1 -f bench/cortexm/cortexm_trace.awk "$b.dis" "$b.sym" "$b.trace" > "$b.calls"
    rm -f "$b.trace"
    for k in $kernels; do
        [ -f "$b.d/$k.pc" ] || { echo "cortexm-prof: no calls of $k"; continue; }
        ncalls=$(awk -v k="$k" '$1 == k' "$b.calls" | wc -l)
        sort "$b.d/$k.pc" | uniq -c > "$b.d/$k.cnt"
        awk '{ print "0x" $2 }' "$b.d/$k.cnt" | arm-none-eabi-addr2line -a -f -i -e "$b.elf" > "$b.d/$k.a2l"
        echo "== $k on $cpu: executed instructions per call (mean of $ncalls), by fx op and by innermost function"
        awk -v n="$ncalls" -v k="$k" '
            function flush() { if (addr == "") return
                self = chain[1]; op = "(kernel)"
                for (i = nch; i >= 1; i--) if (chain[i] ~ /^(fxe_|fxv_|fxp_|fxq_|facet_fx_)/ && chain[i] != "fxq_" k) { op = chain[i]; break }
                if (op == "(kernel)") for (i = 1; i <= nch; i++) if (chain[i] !~ /^facet_.*_fx(_fast)?$/) { op = chain[i] "()"; break }
                byop[op] += cnt[addr]; byself[self] += cnt[addr]; tot += cnt[addr]; addr = "" }
            function norm(a) { a = tolower(a); sub(/^0x/, "", a); sub(/^0+/, "", a); return a }
            FILENAME == ARGV[1] { cnt[norm($2)] = $1; next }
            /^0x/ { flush(); addr = norm($1); nch = 0; next }
            /:[0-9?]+( \(discriminator [0-9]+\))?$/ { next }
            { chain[++nch] = $1 }
            END { flush()
                printf "  total %.1f\n", tot / n
                for (o in byop) printf "  op   %-28s %8.1f %5.1f%%\n", o, byop[o] / n, 100 * byop[o] / tot | "sort -k3 -nr"
                close("sort -k3 -nr")
                for (o in byself) printf "  self %-28s %8.1f %5.1f%%\n", o, byself[o] / n, 100 * byself[o] / tot | "sort -k3 -nr"
                close("sort -k3 -nr") }' "$b.d/$k.cnt" "$b.d/$k.a2l"
    done
done
