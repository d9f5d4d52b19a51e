# Execution time of the fixed-point kernels on Cortex-M0, M4 and M33
# (include/facet/fx.h "Execution time"), one summary line each:
#   fx-wcet      tests/cortexm/wcet.sh's table (executed instructions under
#                qemu-system-arm, modelled cycles: deterministic counts, no
#                timing) equal, row by row, to fx.h's <wcet-table>; without
#                llvm-mca the M4/M33 cycle columns are skipped.  The compare
#                must reject a table with one figure changed.
#   fx-ct        the fast kernels' machine code (src/fx/fx_fast.c) for
#                Cortex-M4 and M33 at -O2 and -Os has no conditional branch
#                but the stated one (facet_brdf_hammon_rgb_fx_fast: its
#                channel loop); the check must report a probe with a
#                data-dependent loop (tests/cortexm/ct_probe.c).
# lane: emulators
. tests/lib/suite_lib.sh
B=build/emu-wcet # its own tree: it runs beside the host suites
have() { command -v "$1" > /dev/null 2>&1; }
mkdir -p $B

if ! have arm-none-eabi-gcc || ! have arm-none-eabi-objdump; then
    echo "SKIP fx-ct: arm-none-eabi-gcc missing (apt-get install gcc-arm-none-eabi libnewlib-arm-none-eabi)"
    echo "fx-ct: 0 passed, 0 failed, 1 skipped"
else
    p=0 f=0
    # every fast kernel (kernels.def, fx type not none) and the RGB form
    nk=$(($(grep '^FACET_KERNEL(' src/core/kernels.def | grep -vc ', none,') + 1))
    for cpu in cortex-m4 cortex-m33; do
        for o in -O2 -Os; do
            o_=$B/ct-$cpu$o.o
            if ! arm-none-eabi-gcc -mcpu=$cpu -mthumb $o -ffunction-sections -std=c99 -Wall -Wextra -Werror -Iinclude \
                    -c src/fx/fx_fast.c -o $o_; then
                f=$((f + 1)); echo "FAIL fx-ct: $cpu $o: src/fx/fx_fast.c does not build"; continue
            fi
            arm-none-eabi-objdump -d $o_ | awk -f tests/cortexm/ct_branches.awk > $B/ct-$cpu$o.txt
            bad=$(awk '($2 == "facet_brdf_hammon_rgb_fx_fast" && $1 != 1) || ($2 != "facet_brdf_hammon_rgb_fx_fast" && $1 != 0)' \
                $B/ct-$cpu$o.txt | tr '\n' ' ')
            n=$(wc -l < $B/ct-$cpu$o.txt)
            if [ -z "$bad" ] && [ "$n" -eq "$nk" ]; then p=$((p + 1))
            else f=$((f + 1)); echo "FAIL fx-ct: $cpu $o: conditional branches (count function) $bad($n functions, $nk expected)"; fi
        done
        # the check can fail: the probe's loop must be reported
        if arm-none-eabi-gcc -mcpu=$cpu -mthumb -O2 -std=c99 -c tests/cortexm/ct_probe.c -o $B/ct-probe.o &&
           arm-none-eabi-objdump -d $B/ct-probe.o | awk -f tests/cortexm/ct_branches.awk |
               awk '$2 == "facet_ct_probe_fx_fast" && $1 > 0 { ok = 1 } END { exit !ok }'
        then p=$((p + 1)); else f=$((f + 1)); echo "FAIL fx-ct: $cpu: the probe's branch is not reported"; fi
    done
    echo "fx-ct: $p passed, $f failed, 0 skipped"
fi

if ! have arm-none-eabi-gcc || ! have qemu-system-arm; then
    echo "SKIP fx-wcet: arm-none-eabi-gcc or qemu-system-arm missing (apt-get install gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm)"
    echo "fx-wcet: 0 passed, 0 failed, 1 skipped"
elif ! sh tests/cortexm/wcet.sh $B > $B/wcet.log 2>&1; then
    tail -n 20 $B/wcet.log
    echo "ERROR fx-wcet: tests/cortexm/wcet.sh failed (log: $B/wcet.log)"
else
    sed -n '/^ \* <wcet-table>$/,/^ \* <\/wcet-table>$/p' include/facet/fx.h | sed '1d;$d' > $B/wcet-stated.txt
    s=0
    have llvm-mca || { s=1; echo "SKIP fx-wcet: llvm-mca missing: the M4/M33 cycle columns are not compared (apt-get install llvm)"; }
    # cmp STATED MEASURED: one check per row (kernel, tier), "-" where missing
    cmp_rows() {
        awk -v nomca=$s '
            function key(   k) { k = $2 " " $3; return k }
            function row(   r, i) { r = ""; for (i = 4; i <= NF; i++) if (!(nomca && (i == 7 || i == 9))) r = r " " $i; return r }
            FILENAME == ARGV[1] { st[key()] = row(); order[++n] = key(); next }
            { me[key()] = row(); if (!(key() in st)) { extra++; print "FAIL fx-wcet: measured row not in fx.h: " $0 } }
            END { for (i = 1; i <= n; i++) { k = order[i]
                      if (k in me && me[k] == st[k]) p++
                      else { f++; print "FAIL fx-wcet: " k ": fx.h states" st[k] ", measured" (k in me ? me[k] : " nothing") } }
                  printf "fx-wcet: %d passed, %d failed\n", p, f + extra }' "$1" "$2"
    }
    out=$(cmp_rows $B/wcet-stated.txt $B/wcet/table.txt)
    printf '%s\n' "$out" | grep '^FAIL' || true
    # the compare can fail: one figure changed (brdf_hammon fast, M0 insns)
    awk '$2 == "brdf_hammon" && $3 == "fast" { $4 = $4 "9" } { print }' $B/wcet-stated.txt > $B/wcet-broken.txt
    if cmp_rows $B/wcet-broken.txt $B/wcet/table.txt | grep -q 'FAIL fx-wcet: brdf_hammon fast'; then extra_p=1 extra_f=0
    else extra_p=0 extra_f=1; echo "FAIL fx-wcet: a changed figure is not reported"; fi
    printf '%s\n' "$out" | tail -n 1 | awk -v ep=$extra_p -v ef=$extra_f -v s=$s \
        '{ sub(/,/, "", $2); printf "fx-wcet: %d passed, %d failed, %d skipped\n", $2 + ep, $4 + ef, s }'
fi
