#!/bin/sh
# tests/cortexm/wcet.sh [--write] [BUILD_DIR] - executed instructions and
# modelled cycles per call of every fixed-point kernel, both tiers, minimum
# and maximum over its golden vectors (tests/cortexm/wcet_main.c: the edge
# cases and WCET_RANDOM = 256 random vectors of `facet vectors`), on
# Cortex-M0, M4 and M33, arm-none-eabi-gcc -mthumb -O2:
#   insns   executed instructions (qemu-system-arm -singlestep -d
#           exec,nochain; deterministic): entry to return, callees included
#   cycles  M0: the Cortex-M0 TRM timings on each executed trace
#           (bench/cortexm/cortexm_trace.awk, zero wait states); M4, M33:
#           llvm-mca -mcpu=cortex-m4 / cortex-m33 -iterations=1 on each
#           distinct executed path as straight-line code (MODELLED: no
#           fetch or branch penalty, bench/cortexm/cortexm_mca.awk)
# M0 runs on mps2-an385, M4 and M33 code on mps2-an386 (the executed path is
# ISA-determined; bench/cortexm/cortexm.sh says why).  Prints the table
# include/facet/fx.h holds (its "Execution time" block); --write puts it
# there.  The one command to regenerate it after a change of the bodies or
# the op layer:  sh tests/cortexm/wcet.sh --write
# Also writes BUILD_DIR/wcet/table.txt.  Needs arm-none-eabi-gcc with
# newlib, qemu-system-arm, llvm-mca (without it the M4/M33 cycle columns
# read "-").
set -u
write=0
[ "${1:-}" = --write ] && { write=1; shift; }
build=${1:-build}
dir=$build/wcet
mkdir -p "$dir"
have() { command -v "$1" >/dev/null 2>&1; }
if ! have arm-none-eabi-gcc || ! have qemu-system-arm; then
    echo "wcet: needs arm-none-eabi-gcc and qemu-system-arm" >&2
    exit 2
fi
mca=0
have llvm-mca && mca=1
fx_src=$(make -s fx-sources) || exit 2
link="--specs=rdimon.specs -nostartfiles -T tests/cortexm/mps2.ld tests/cortexm/startup.c"
for cpu in cortex-m0 cortex-m4 cortex-m33; do
    case $cpu in
    cortex-m0) mach=mps2-an385 triple=thumbv6m-none-eabi ;;
    cortex-m33) mach=mps2-an386 triple=thumbv8m.main-none-eabi ;;
    *) mach=mps2-an386 triple=thumbv7em-none-eabi ;;
    esac
    b=$dir/$cpu
    rm -rf "$b.d" "$b.fifo"
    mkdir -p "$b.d"
    # shellcheck disable=SC2086
    arm-none-eabi-gcc -mcpu=$cpu -mthumb -O2 -std=c99 -Wall -Wextra -Werror -Iinclude $link \
        tests/cortexm/wcet_main.c $fx_src -o "$b.elf" || exit 2
    arm-none-eabi-objdump -d "$b.elf" > "$b.dis"
    arm-none-eabi-nm "$b.elf" | awk '$2 ~ /^[Tt]$/ && $3 ~ /^facet_.*_fx(_fast)?$/ && $3 !~ /^facet_fx_/ { print $1, $3 }' |
        sed -e 's/ facet_/ /' > "$b.sym"
    mkfifo "$b.fifo"
    awk -v dir="$b.d" -v paths=1 -f bench/cortexm/cortexm_trace.awk "$b.dis" "$b.sym" "$b.fifo" > "$b.calls" &
    if ! timeout 900 qemu-system-arm -M $mach -nographic -semihosting-config enable=on,target=native \
            -kernel "$b.elf" -singlestep -d exec,nochain -D "$b.fifo" >/dev/null 2>&1; then
        echo "wcet: $cpu: qemu run failed" >&2
        exit 2
    fi
    wait
    rm -f "$b.fifo"
    # per distinct path: llvm-mca cycles (M4, M33)
    : > "$b.pcyc"
    if [ $cpu != cortex-m0 ] && [ $mca = 1 ]; then
        awk '{ print $1, $5 }' "$b.calls" | sort -u | while read -r k p; do
            awk -v noit=0 -f bench/cortexm/cortexm_mca.awk "$b.d/$k.p$p.s" > "$b.d/$k.p$p.mca.s"
            c=$(llvm-mca -mtriple=$triple -mcpu=$cpu -iterations=1 "$b.d/$k.p$p.mca.s" 2>/dev/null |
                awk '/^Total Cycles:/ { print $3 }')
            echo "$k $p ${c:--}"
        done > "$b.pcyc"
    fi
    # kernel insns-min insns-max cycles-min cycles-max calls paths
    awk -v m0=$([ $cpu = cortex-m0 ] && echo 1 || echo 0) '
        FILENAME == ARGV[1] { cyc[$1, $2] = $3; next }
        { k = $1; n[k]++
          c = m0 ? $3 : (($1, $5) in cyc ? cyc[$1, $5] : "-")
          if (!(k in imin) || $2 < imin[k]) imin[k] = $2
          if (!(k in imax) || $2 > imax[k]) imax[k] = $2
          if (c == "-") bad[k] = 1
          else { if (!(k in cmin) || c + 0 < cmin[k]) cmin[k] = c + 0
                 if (!(k in cmax) || c + 0 > cmax[k]) cmax[k] = c + 0 }
          if (!((k, $5) in seen)) { seen[k, $5] = 1; np[k]++ } }
        END { for (k in n) print k, imin[k], imax[k], (k in bad) ? "-" : cmin[k], (k in bad) ? "-" : cmax[k], n[k], np[k] }' \
        "$b.pcyc" "$b.calls" | sort > "$b.sum"
    echo "wcet: $cpu traced ($(wc -l < "$b.calls") calls)" >&2
done

# the table: one line per kernel and tier, in kernels.def order
range() { if [ "$1" = "$2" ]; then printf '%s' "$1"; else printf '%s-%s' "$1" "$2"; fi; }
{
    printf ' *   %-26s %-4s  %-9s %-9s  %-9s %-9s  %-9s %s\n' kernel tier "M0 insns" cycles "M4 insns" cycles "M33 insns" cycles
    sed -n 's/^FACET_KERNEL(\([a-z0-9_]*\),.*/\1/p' src/core/kernels.def | while read -r k; do
        for t in fx fx_fast; do
            line=" *   $(printf '%-26s %-4s' "$k" "$([ $t = fx ] && echo fx || echo fast)")"
            ok=0
            for cpu in cortex-m0 cortex-m4 cortex-m33; do
                r=$(awk -v k="${k}_$t" '$1 == k' "$dir/$cpu.sum")
                [ -n "$r" ] || continue
                ok=1
                set -- $r
                line="$line  $(printf '%-9s %-9s' "$(range "$2" "$3")" "$(range "$4" "$5")")"
            done
            [ $ok = 1 ] && echo "$line" | sed 's/ *$//'
        done
    done
} > "$dir/table.txt"
cat "$dir/table.txt"
if [ $write = 1 ]; then
    awk -v tab="$dir/table.txt" '
        /^ \* <wcet-table>$/ { print; while ((getline l < tab) > 0) print l; skip = 1; next }
        /^ \* <\/wcet-table>$/ { skip = 0 }
        !skip' include/facet/fx.h > "$dir/fx.h.new" &&
        grep -q '<wcet-table>' "$dir/fx.h.new" && mv "$dir/fx.h.new" include/facet/fx.h &&
        echo "wcet: include/facet/fx.h updated" >&2
fi
