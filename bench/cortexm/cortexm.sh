#!/bin/sh
# bench/cortexm/cortexm.sh BUILD_DIR OUT_TSV - Cortex-M figures for the report, from
# executed-instruction traces.  For each build (fixed point: src/fx/*.c;
# f32: facet/scalar.h with soft float) and core, bench/cortexm/cortexm_main.c is
# linked with tests/cortexm/ (startup, mps2.ld) and run under
# qemu-system-arm -singlestep -d exec,nochain (one log line per executed
# instruction).  bench/cortexm/cortexm_trace.awk cuts each kernel call out of the
# trace (entry to return, callees and libgcc helpers included, argument
# set-up and the call instruction not) for 4 representative inputs.
# Written to OUT_TSV ("what kernel cpu value source"):
#   <fmt>-insns   executed instructions per call, mean of the 4 inputs
#                 (MEASURED by qemu; instruction counts, not cycles)
#   <fmt>-m0cyc   Cortex-M0 cycles per call from the TRM timing table applied
#                 to the executed trace (MODELLED, zero wait states)
#   <fmt>-mca     llvm-mca cycles per call for the core, on the executed
#                 instruction sequence of the 4 calls as straight-line code
#                 (MODELLED: no fetch/branch penalties, no wait states;
#                 branch targets become one local label, BL becomes B so
#                 llvm-mca does not charge its 100-cycle call placeholder:
#                 the callee's instructions are in the trace already;
#                 cortex-m7: IT dropped, its block unpredicated, since the
#                 LLVM M7 model does not support IT)
#   <fmt>-taken   taken branches, calls and returns per call (from the
#                 trace): each costs a pipeline refill (1-3 cycles on M4)
#                 that llvm-mca does not add
# <fmt> is fx, fxfast (the fast tier), f32soft (soft float) or f32fpu (the
# core's FPU, hard-float ABI; not on M0).  Builds: cortex-m0 (ARMv6-M code, run on
# mps2-an385, a Cortex-M3 model: the executed path is ISA-determined),
# cortex-m4 (mps2-an386), cortex-m7 (mps2-an500), cortex-m33 (ARMv8-M
# mainline code run on the mps2-an386 Cortex-M4 model; our startup does
# not fit the AN505 secure memory map).  Needs arm-none-eabi-gcc with
# newlib, qemu-system-arm, and llvm-mca for the -mca lines.
# CORTEXM_FMTS / CORTEXM_CPUS (space-separated) restrict the builds, e.g.
# CORTEXM_FMTS=fxfast CORTEXM_CPUS=cortex-m4 for one figure.
# `bench/cortexm/cortexm.sh --profile [BUILD_DIR] [KERNEL...]`: the per-function
# profile of the fixed-point kernels instead (bench/cortexm/cortexm_prof.sh).
set -u
if [ "${1:-}" = --profile ]; then
    shift
    exec sh bench/cortexm/cortexm_prof.sh "$@"
fi
build=${1:-build}
tsv=${2:-$build/report/arm.tsv}
dir=$build/bench/cortexm
mkdir -p "$dir" "$(dirname "$tsv")"
have() { command -v "$1" >/dev/null 2>&1; }
if ! have arm-none-eabi-gcc || ! have qemu-system-arm; then
    echo "cortexm: skipped (needs arm-none-eabi-gcc and qemu-system-arm)"
    exit 0
fi
echo "# what kernel cpu value source" > "$tsv"
link="--specs=rdimon.specs -nostartfiles -T tests/cortexm/mps2.ld tests/cortexm/startup.c"
cflags="-mthumb -O2 -std=c99 -Wall -Wextra -Werror -Iinclude"
for fmt in ${CORTEXM_FMTS:-fx fxfast f32soft f32fpu}; do
    for cpu in ${CORTEXM_CPUS:-cortex-m0 cortex-m4 cortex-m7 cortex-m33}; do
        # f32fpu: not on M0 (no FPU) nor M33 (its code runs on the M4 model,
        # which has no FPv5)
        [ $fmt = f32fpu ] && { [ $cpu = cortex-m0 ] || [ $cpu = cortex-m33 ]; } && continue
        case $cpu in
        cortex-m0) mach=mps2-an385 triple=thumbv6m-none-eabi ;;
        cortex-m7) mach=mps2-an500 triple=thumbv7em-none-eabi ;;
        cortex-m33) mach=mps2-an386 triple=thumbv8m.main-none-eabi ;;
        *) mach=mps2-an386 triple=thumbv7em-none-eabi ;;
        esac
        b=$dir/${fmt}_$cpu
        rm -rf "$b.d"
        mkdir -p "$b.d"
        case $fmt in
        fx) src="-DBENCH_FX src/fx/fx_prims.c src/fx/fx_kernels.c"; pat='^facet_.*_fx$' ;;
        fxfast) src="-DBENCH_FX -DBENCH_FX_FAST src/fx/fx_prims.c src/fx/fx_kernels.c src/fx/fx_fast.c"; pat='^facet_.*_fx_fast$' ;;
        f32soft) src="-mfloat-abi=soft"; pat='^bench_f32_' ;;
        *) case $cpu in # the core's single-precision FPU, hard-float ABI
           cortex-m4) src="-mfloat-abi=hard -mfpu=fpv4-sp-d16" ;;
           cortex-m7) src="-mfloat-abi=hard -mfpu=fpv5-d16" ;;
           *) src="-mfloat-abi=hard -mfpu=fpv5-sp-d16" ;;
           esac
           pat='^bench_f32_' ;;
        esac
        # shellcheck disable=SC2086
        if ! arm-none-eabi-gcc -mcpu=$cpu $cflags $link $src bench/cortexm/cortexm_main.c -o "$b.elf" 2>"$b.log"; then
            echo "cortexm: $fmt $cpu: build failed (see $b.log)"
            continue
        fi
        arm-none-eabi-objdump -d "$b.elf" > "$b.dis"
        arm-none-eabi-nm "$b.elf" | awk -v p="$pat" '$2 ~ /^[Tt]$/ && $3 ~ p { print $1, $3 }' |
            sed -e 's/ facet_\(.*\)_fx_fast$/ \1/' -e 's/ facet_\(.*\)_fx$/ \1/' -e 's/ bench_f32_/ /' > "$b.sym"
        if ! timeout 120 qemu-system-arm -M $mach -nographic -semihosting-config enable=on,target=native \
                -kernel "$b.elf" -singlestep -d exec,nochain -D "$b.trace" >/dev/null 2>&1; then
            echo "cortexm: $fmt $cpu: qemu run failed"
            continue
        fi
        awk -v dir="$b.d" -f bench/cortexm/cortexm_trace.awk "$b.dis" "$b.sym" "$b.trace" > "$b.calls"
        rm -f "$b.trace"
        short=${cpu#cortex-}
        for k in $(cut -d' ' -f1 "$b.calls" | sort -u); do
            awk -v k="$k" '$1 == k { n++; i += $2; c += $3; t += $4 } END { printf "%.1f %.1f %d %.1f\n", i / n, c / n, n, t / n }' \
                "$b.calls" | {
                read -r insns m0 ncalls taken
                echo "$fmt-insns $k $cpu $insns qemu-executed-instructions-measured-mean-of-$ncalls-inputs"
                echo "$fmt-taken $k $cpu $taken taken-branches-per-call-from-the-trace"
                [ $cpu = cortex-m0 ] && echo "$fmt-m0cyc $k $cpu $m0 m0-trm-timings-on-executed-trace-modelled"
                if have llvm-mca && [ $cpu != cortex-m0 ]; then
                    awk -v noit=$([ $cpu = cortex-m7 ] && echo 1 || echo 0) -f bench/cortexm/cortexm_mca.awk "$b.d/$k.s" > "$b.d/$k.mca.s"
                    c=$(llvm-mca -mtriple=$triple -mcpu=$cpu -iterations=10 "$b.d/$k.mca.s" 2>"$b.d/$k.mca.err" |
                        awk -v n="$ncalls" '/^Total Cycles:/ { printf "%.1f", $3 / (10 * n) }')
                    [ -n "$c" ] && echo "$fmt-mca $k $cpu $c llvm-mca-on-executed-trace-modelled"
                fi
                true
            }
        done >> "$tsv"
        echo "cortexm: $fmt $short traced ($(wc -l < "$b.calls") calls)"
    done
done
