#!/bin/sh
# bench/report/arm_targets.sh OUT_DIR - the chooser's costs on the two Arm
# vector ports, which this machine cannot time (called by report.sh):
#   neon    aarch64 (build/aarch64, the 40-arm suite's cross build):
#           llvm-mca (LLVM's cortex-a57 model) on the EXECUTED instruction
#           trace of one batch call (qemu-aarch64 -cpu max -singlestep -d
#           exec,nochain), callees and the tail included, / samples: MODELLED
#           cycles per sample (one pass over the 64-sample trace: 4 passes
#           changed brdf_hammon's figures by under 1.5 %); and every call,
#           the binary16 table neonfp16's too (format f16), on LLVM's
#           cortex-a55 model (mca-cortex-a55): an ARMv8.2-A core with FP16
#           whose model has its own entries for the binary16 vector forms
#           (a .8h fadd or fmla costs what a .4s one does); the A57 model
#           has no FP16 (cortex-a76 and neoverse-n1 map to it in LLVM 14
#           and 16, and it charges a .8h op as a 64-bit one)
#   helium  Cortex-M55 (build/m55-clang, the helium objects from clang 14,
#           as the README's Helium table): instructions executed per sample
#           under qemu-system-arm -M mps3-an547 (MEASURED instruction
#           counts), and beside them llvm-mca-16's Cortex-M55 model
#           (-mtriple=thumbv8.1m.main -mcpu=cortex-m55 -mattr=+mve.fp) on
#           the executed trace of each call (bench/qcount/m55_mca.awk) /
#           samples: MODELLED cycles per sample (without llvm-mca-16 the
#           counts alone, and the status says so)
#   rvv     RV64GCV (build/rv64, the rvv objects from clang 14, as
#           bench/qcount's RVV table): instructions executed per sample
#           under qemu-riscv64 -cpu rv64,v=true,Zfh=true,vlen=128: MEASURED
#           instruction counts, not cycles (the speed table's RVV column),
#           the rvv line's binary16 table rvvfp16 too (format f16, called
#           directly: the dispatcher refuses it under qemu-user 7.2)
# for every kernel and every tier the port runs (f32, f32_fast, fx,
# fx_fast), from one image per target (bench/report/armcount_main.c); and
# format f16 where the port's line of src/core/ports.def names an f16
# table of its own (armcount_main.c finds it in the port list: the neon
# line's neonfp16 on aarch64, the helium line's heliumfp16 on the M55, the
# rvv line's rvvfp16 on RV64GCV; a
# port whose line runs the scalar f16 table has "no f16 port yet", and
# picks one up when its line names one).  NEON is modelled twice: by the
# A57 model for every format (one axis for the chooser; f16 with
# -mattr=+fullfp16, though the A57 itself is ARMv8.0 without FP16
# arithmetic), and by the A55 model (an FP16 core, which LLVM costs for
# .8h like .4s) for every format too: the f16 / f32 ratios of the speed
# section come from that one.
# Writes OUT_DIR/arm_vec.tsv ("format port kernel measure value") and
# OUT_DIR/arm_vec.status (per target "PORT ok HOW" or "PORT skipped WHY",
# and "PORT-f16 ok HOW" or "PORT-f16 skipped WHY" for its binary16 table,
# which the report prints).  A missing tool or a failed build skips that
# target with the reason; it never fails the report.  The figures are
# cached in build/armcount/ and reused while the library, this script and
# the program are older than them.
set -u
out=$1
MAKE=${MAKE:-make}
dir=build/armcount
mkdir -p "$dir" "$out"
have() { command -v "$1" > /dev/null 2>&1; }
missing() { m=; for t in "$@"; do have "$t" || m="$m${m:+, }$t"; done; echo "$m"; }
: > "$out/arm_vec.status"
echo "# format port kernel measure value" > "$out/arm_vec.tsv"
status() { echo "$*" >> "$out/arm_vec.status"; echo "report: arm targets: $*"; }
fresh() { # fresh CACHE FILES...: CACHE exists and is newer than every FILE
    c=$1; shift
    [ -s "$c" ] || return 1
    for f in "$@"; do [ "$c" -nt "$f" ] || return 1; done
}
# counts ELF DIS TRACE LABELS [MCADIR [RAW]]: per marked call "FORMAT KERNEL
# INSNS"; with MCADIR, the executed instruction texts of call i go to
# MCADIR/i.s (branch, call and literal targets as one label; RAW=1: as
# objdump prints them, for bench/qcount/m55_mca.awk)
counts() {
    b=$($NM "$1" | awk '$3 == "armcount_begin" { print $1 }')
    e=$($NM "$1" | awk '$3 == "armcount_end" { print $1 }')
    awk -v b="$b" -v e="$e" -v mca="${5:-}" -v raw="${6:-0}" '
        BEGIN { k = 0; nl = 0 }
        function hex(s,   i, n, c) { n = 0; s = tolower(s); sub(/^0x/, "", s)
            for (i = 1; i <= length(s); i++) { c = index("0123456789abcdef", substr(s, i, 1)); if (!c) break; n = n * 16 + c - 1 }
            return n }
        FILENAME == ARGV[1] { if ($0 !~ /^ *[0-9a-f]+:\t/) next
            n = split($0, f, "\t"); a = f[1]; sub(/^ +/, "", a); sub(/:$/, "", a)
            t = f[2]; for (i = 3; i <= n; i++) t = t "\t" f[i]
            if (raw) { text[hex(a)] = t; next }
            sub(/[ \t]*\/\/.*$/, "", t)
            if (t ~ / <[^>]*>$/) { sub(/ <[^>]*>$/, "", t); sub(/[0-9a-f]+$/, ".Lt", t) }
            m = t; sub(/[ \t].*$/, "", m)
            if (m == "bl") sub(/^bl/, "b", t)     # llvm-mca charges a call 100 cycles;
            if (m == "blr") sub(/^blr/, "br", t)  # the callee follows in the trace
            text[hex(a)] = t; next }
        FILENAME == ARGV[2] { label[nl++] = $1 " " $2; next }
        { s = $0; sub(/^[^\[]*\[[^\/]*\//, "", s); sub(/\/.*$/, "", s); pc = hex(s)
          if (pc == hex(b)) { on = 1; n = 0; next }
          if (pc == hex(e) && on) { print label[k], n; on = 0; if (mca) close(mca "/" k ".s"); k++; next }
          if (on) { n++; if (mca) print text[pc] > (mca "/" k ".s") } }' "$2" "$4" "$3"
}
samples=64
# f16status PORT LABELS|-: the PORT-f16 status line from the counting run's
# "armcount-f16: TABLE" line (or, with -, from the cached PORT.f16)
f16status() {
    if [ "$2" != - ]; then sed -n 's/^armcount-f16: //p' "$2" | tr -d '\r' > "$dir/$1.f16"; fi
    t=$(cat "$dir/$1.f16" 2>/dev/null)
    case $t in
    "") status "$1-f16 skipped: the counting image did not say which f16 table the $1 line runs" ;;
    none) status "$1-f16 skipped: no f16 port yet (src/core/ports.def: the $1 line runs the scalar f16 table)" ;;
    *) status "$1-f16 ok the $t table, $3" ;;
    esac
}

# ---- NEON (aarch64): llvm-mca on the executed trace -------------------------
cpu=cortex-a57 cpu16=cortex-a55
neon_f16_how="llvm-mca -mcpu=$cpu -mattr=+fullfp16 on the executed trace (the A57 itself is ARMv8.0, without FP16 arithmetic: LLVM 14 schedules A72, A76 and Neoverse N1 with the same model), and -mcpu=$cpu16 (an FP16 core) for the f16 / f32 ratios"
if ! have aarch64-linux-gnu-gcc || ! have qemu-aarch64 || ! have llvm-mca; then
    status "neon skipped: not installed: $(missing aarch64-linux-gnu-gcc qemu-aarch64 llvm-mca)"
    status "neon-f16 skipped: not installed: $(missing aarch64-linux-gnu-gcc qemu-aarch64 llvm-mca)"
elif ! $MAKE -s BUILD=build/aarch64 CC=aarch64-linux-gnu-gcc CFLAGS="-O2 -g" build/aarch64/libfacet.a > "$dir/aarch64.build.log" 2>&1; then
    status "neon skipped: the aarch64 cross build of the library failed ($dir/aarch64.build.log)"
    status "neon-f16 skipped: the aarch64 cross build of the library failed ($dir/aarch64.build.log)"
elif fresh "$dir/neon.tsv" build/aarch64/libfacet.a bench/report/armcount_main.c bench/report/arm_targets.sh &&
     [ -s "$dir/neon.f16" ]; then
    cat "$dir/neon.tsv" >> "$out/arm_vec.tsv"
    status "neon ok llvm-mca -mcpu=$cpu on the executed trace, every tier also -mcpu=$cpu16 (cached)"
    f16status neon - "$neon_f16_how (cached)"
else
    NM=aarch64-linux-gnu-nm
    rm -rf "$dir/neon.d" && mkdir -p "$dir/neon.d"
    if aarch64-linux-gnu-gcc -O2 -std=c99 -static -Iinclude -DARMCOUNT_PORT=neon -DN=$samples \
            bench/report/armcount_main.c build/aarch64/libfacet.a -lm -o "$dir/neon.elf" 2> "$dir/neon.log" &&
       qemu-aarch64 -cpu max -singlestep -d exec,nochain -D "$dir/neon.trace" "$dir/neon.elf" > "$dir/neon.labels" 2>> "$dir/neon.log"; then
        aarch64-linux-gnu-objdump -d --no-show-raw-insn "$dir/neon.elf" > "$dir/neon.dis"
        grep -v '^armcount' "$dir/neon.labels" > "$dir/neon.lab"
        counts "$dir/neon.elf" "$dir/neon.dis" "$dir/neon.trace" "$dir/neon.lab" "$dir/neon.d" > "$dir/neon.calls"
        rm -f "$dir/neon.trace"
        i=0
        : > "$dir/neon.tsv.tmp"
        while read -r fmt k insns; do
            attr=; [ "$fmt" = f16 ] && attr=-mattr=+fullfp16
            c=$(llvm-mca -mtriple=aarch64 -mcpu=$cpu $attr -iterations=1 "$dir/neon.d/$i.s" 2>> "$dir/neon.log" |
                awk -v n=$samples '/^Iterations:/ {it = $2} /^Total Cycles:/ {c = $3} END { if (it) printf "%.2f", c / it / n }')
            [ -n "$c" ] && echo "$fmt neon $k mca-$cpu $c" >> "$dir/neon.tsv.tmp"
            c=$(llvm-mca -mtriple=aarch64 -mcpu=$cpu16 -iterations=1 "$dir/neon.d/$i.s" 2>> "$dir/neon.log" |
                awk -v n=$samples '/^Iterations:/ {it = $2} /^Total Cycles:/ {c = $3} END { if (it) printf "%.2f", c / it / n }')
            [ -n "$c" ] && echo "$fmt neon $k mca-$cpu16 $c" >> "$dir/neon.tsv.tmp"
            echo "$fmt neon $k qemu-insn $(awk -v i="$insns" -v n=$samples 'BEGIN { printf "%.1f", i / n }')" >> "$dir/neon.tsv.tmp"
            i=$((i + 1))
        done < "$dir/neon.calls"
        rm -rf "$dir/neon.d"
        if [ -s "$dir/neon.tsv.tmp" ]; then
            mv "$dir/neon.tsv.tmp" "$dir/neon.tsv"
            cat "$dir/neon.tsv" >> "$out/arm_vec.tsv"
            status "neon ok llvm-mca -mcpu=$cpu on the executed trace, every tier also -mcpu=$cpu16"
            f16status neon "$dir/neon.labels" "$neon_f16_how"
        else
            status "neon skipped: no call was traced ($dir/neon.log)"
            status "neon-f16 skipped: no call was traced ($dir/neon.log)"
        fi
    else
        status "neon skipped: the counting image failed to build or run ($dir/neon.log)"
        status "neon-f16 skipped: the counting image failed to build or run ($dir/neon.log)"
    fi
fi

# ---- Helium (Cortex-M55): executed instructions under qemu-system-arm ----------
lib=build/m55-clang/libfacet.a
if ! have arm-none-eabi-gcc || ! have qemu-system-arm || ! have clang; then
    status "helium skipped: not installed: $(missing arm-none-eabi-gcc qemu-system-arm clang)"
    status "helium-f16 skipped: not installed: $(missing arm-none-eabi-gcc qemu-system-arm clang)"
elif ! $MAKE -s BUILD=build/m55-clang CC=arm-none-eabi-gcc AR=arm-none-eabi-ar PICFLAGS= HELIUM_CC=clang \
        CFLAGS="-mcpu=cortex-m55 -mfloat-abi=hard -mthumb -O2 -g" $lib > "$dir/m55.build.log" 2>&1; then
    status "helium skipped: the Cortex-M55 build of the library failed ($dir/m55.build.log)"
    status "helium-f16 skipped: the Cortex-M55 build of the library failed ($dir/m55.build.log)"
elif fresh "$dir/helium.tsv" $lib bench/report/armcount_main.c bench/report/arm_targets.sh bench/qcount/m55_mca.awk &&
     { ! have llvm-mca-16 || grep -q ' mca-cortex-m55 ' "$dir/helium.tsv"; } && [ -s "$dir/helium.f16" ]; then
    cat "$dir/helium.tsv" >> "$out/arm_vec.tsv"
    status "helium ok $(cat "$dir/helium.how" 2>/dev/null) (cached)"
    f16status helium - "$(cat "$dir/helium.how" 2>/dev/null) (cached)"
else
    NM=arm-none-eabi-nm
    m55mca="llvm-mca-16 -mtriple=thumbv8.1m.main -mcpu=cortex-m55 -mattr=+mve.fp"
    if arm-none-eabi-gcc -mcpu=cortex-m55 -mfloat-abi=hard -mthumb -O2 -std=c99 -Iinclude -DARMCOUNT_PORT=helium \
            -DN=$samples --specs=rdimon.specs -nostartfiles -T tests/cortexm/an547.ld tests/cortexm/startup_m55.c \
            bench/report/armcount_main.c $lib -lm -o "$dir/m55.elf" 2> "$dir/m55.log" &&
       timeout 300 qemu-system-arm -M mps3-an547 -nographic -semihosting-config enable=on,target=native \
            -kernel "$dir/m55.elf" -singlestep -d exec,nochain -D "$dir/m55.trace" > "$dir/m55.labels" 2>> "$dir/m55.log"; then
        arm-none-eabi-objdump -d --no-show-raw-insn -m armv8.1-m.main "$dir/m55.elf" > "$dir/m55.dis"
        grep -v '^armcount' "$dir/m55.labels" | tr -d '\r' > "$dir/m55.lab"
        rm -rf "$dir/m55.d" && mkdir -p "$dir/m55.d"
        counts "$dir/m55.elf" "$dir/m55.dis" "$dir/m55.trace" "$dir/m55.lab" "$dir/m55.d" 1 > "$dir/m55.calls"
        rm -f "$dir/m55.trace"
        i=0 nd=0 dmax=0 dk=
        : > "$dir/helium.tsv.tmp"
        while read -r fmt k insns; do
            echo "$fmt helium $k qemu-insn $(awk -v i="$insns" -v n=$samples 'BEGIN { printf "%.1f", i / n }')" >> "$dir/helium.tsv.tmp"
            if have llvm-mca-16; then
                awk -f bench/qcount/m55_mca.awk "$dir/m55.d/$i.s" > "$dir/m55.d/$i.mca.s"
                c=$($m55mca -iterations=1 "$dir/m55.d/$i.mca.s" 2>> "$dir/m55.log" |
                    awk -v n=$samples '/^Iterations:/ {it = $2} /^Total Cycles:/ {c = $3} END { if (it) printf "%.2f", c / it / n }')
                [ -n "$c" ] && echo "$fmt helium $k mca-cortex-m55 $c" >> "$dir/helium.tsv.tmp"
                # VMRS APSR_nzcv, FPSCR: no data in the model, left out (m55_mca.awk)
                d=$(grep -c '^vmrs[[:space:]]*APSR_nzcv' "$dir/m55.d/$i.s")
                if [ "$d" -gt 0 ]; then
                    nd=$((nd + 1))
                    [ "$d" -gt "$dmax" ] && dmax=$d dk="$fmt $k"
                fi
            fi
            i=$((i + 1))
        done < "$dir/m55.calls"
        rm -rf "$dir/m55.d"
        if have llvm-mca-16; then
            how="qemu-system-arm instruction counts; $m55mca cycles on the executed trace"
            [ $nd -gt 0 ] && how="$how (VMRS APSR_nzcv, FPSCR left out, no model data: in $nd of $i calls, at most $(awk -v d=$dmax -v n=$samples 'BEGIN { printf "%.1f", d / n }') per sample, $dk)"
        else how="qemu-system-arm instruction counts (no modelled cycles: llvm-mca-16 not installed)"; fi
        echo "$how" > "$dir/helium.how"
        if [ -s "$dir/helium.tsv.tmp" ]; then
            mv "$dir/helium.tsv.tmp" "$dir/helium.tsv"
            cat "$dir/helium.tsv" >> "$out/arm_vec.tsv"
            status "helium ok $how"
            f16status helium "$dir/m55.labels" "$how"
        else
            status "helium skipped: no call was traced ($dir/m55.log)"
            status "helium-f16 skipped: no call was traced ($dir/m55.log)"
        fi
    else
        status "helium skipped: the counting image failed to build or run ($dir/m55.log)"
        status "helium-f16 skipped: the counting image failed to build or run ($dir/m55.log)"
    fi
fi
# ---- RVV (RV64GCV, VLEN 128): executed instructions under qemu-riscv64 ------------
lib=build/rv64/libfacet.a
if ! have riscv64-linux-gnu-gcc || ! have qemu-riscv64 || ! have clang; then
    status "rvv skipped: not installed: $(missing riscv64-linux-gnu-gcc qemu-riscv64 clang)"
    status "rvv-f16 skipped: not installed: $(missing riscv64-linux-gnu-gcc qemu-riscv64 clang)"
elif ! $MAKE -s BUILD=build/rv64 CC=riscv64-linux-gnu-gcc CFLAGS="-O2 -g" $lib > "$dir/rv64.build.log" 2>&1; then
    status "rvv skipped: the riscv64 cross build of the library failed ($dir/rv64.build.log)"
    status "rvv-f16 skipped: the riscv64 cross build of the library failed ($dir/rv64.build.log)"
elif fresh "$dir/rvv.tsv" $lib bench/report/armcount_main.c bench/report/arm_targets.sh && [ -s "$dir/rvv.f16" ]; then
    cat "$dir/rvv.tsv" >> "$out/arm_vec.tsv"
    status "rvv ok qemu-riscv64 instruction counts at VLEN 128 (cached)"
    f16status rvv - "qemu-riscv64 instruction counts at VLEN 128, -cpu rv64,v=true,Zfh=true (cached)"
else
    NM=riscv64-linux-gnu-nm
    # the ports the library holds, as its build told src/core/platform.h
    # (the RISC-V rungs follow the build's flags: armcount_main.c finds the
    # rvv line's f16 table, rvvfp16, only with them); Zfh=true: qemu 7.2
    # executes the binary16 vector arithmetic of Zvfh with it
    pf=$($NM $lib | awk '$3 == "facet_port_rvv_f32" { print "-DFACET_PORT_RVV=1" }
                        $3 == "facet_f16_port_rvvfp16" { print "-DFACET_PORT_RVVFP16=1" }' | sort -u)
    # shellcheck disable=SC2086
    if riscv64-linux-gnu-gcc -O2 -std=c99 -static -Iinclude $pf -DARMCOUNT_PORT=rvv -DN=$samples \
            bench/report/armcount_main.c $lib -lm -o "$dir/rvv.elf" 2> "$dir/rvv.log" &&
       timeout 600 qemu-riscv64 -cpu rv64,v=true,vext_spec=v1.0,Zfh=true,vlen=128 -singlestep -d exec,nochain \
            -D "$dir/rvv.trace" "$dir/rvv.elf" > "$dir/rvv.labels" 2>> "$dir/rvv.log"; then
        riscv64-linux-gnu-objdump -d "$dir/rvv.elf" > "$dir/rvv.dis"
        grep -v '^armcount' "$dir/rvv.labels" > "$dir/rvv.lab"
        counts "$dir/rvv.elf" "$dir/rvv.dis" "$dir/rvv.trace" "$dir/rvv.lab" |
            awk -v n=$samples '{ printf "%s rvv %s qemu-insn %.1f\n", $1, $2, $3 / n }' > "$dir/rvv.tsv.tmp"
        rm -f "$dir/rvv.trace"
        if [ -s "$dir/rvv.tsv.tmp" ]; then
            mv "$dir/rvv.tsv.tmp" "$dir/rvv.tsv"
            cat "$dir/rvv.tsv" >> "$out/arm_vec.tsv"
            status "rvv ok qemu-riscv64 instruction counts at VLEN 128"
            f16status rvv "$dir/rvv.labels" "qemu-riscv64 instruction counts at VLEN 128, -cpu rv64,v=true,Zfh=true"
        else
            status "rvv skipped: no call was traced ($dir/rvv.log)"
            status "rvv-f16 skipped: no call was traced ($dir/rvv.log)"
        fi
    else
        status "rvv skipped: the counting image failed to build or run ($dir/rvv.log)"
        status "rvv-f16 skipped: the counting image failed to build or run ($dir/rvv.log)"
    fi
fi
exit 0
