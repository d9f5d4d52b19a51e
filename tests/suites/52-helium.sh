# The Helium port on a Cortex-M55: the library built with arm-none-eabi-gcc
# for -mcpu=cortex-m55 (helium and scalar ports, MVE and the FPU), and the C
# tests that exercise the ports linked as bare-metal images (tests/ports/helium.mk)
# run on qemu-system-arm -M mps3-an547 with semihosting:
#   test_f32_ports     lanes, every tail, alignment, aliasing, symmetry, bad
#                      input, on both f32 tiers of each port
#   test_f32_accuracy  both tiers against the oracle at the facet.h bounds
#                      (FACET_TEST_QUICK=2 counts, 30000 random samples)
#   test_fx_ports      fx and fx_fast batches bit for bit against the scalar
#                      specification, tails, aliasing, the pinned hashes
#   test_fx_hash       the pinned hashes of the scalar kernels on the M55
#   test_sample_ports, test_f32_bad_input  the samplers' and the bad-input contracts
#   test_f32_rgb, test_fx_rgb  the RGB batches (every layout, tail, alias) and RGB fixed point
#   test_f16_accuracy  every f16 kernel on heliumfp16 (MVE binary16 lanes),
#                      the scalar table and the per-sample entry at the
#                      facet/f16.h bounds (30000 random samples a kernel)
#   test_f16_ports     the f16 bad-input, saturation, tail and alias
#                      contracts on heliumfp16, and the port choice
#   test_f16_estimates heliumfp16's seeded rcp and rsqrt (binary16 and f32
#                      lanes) exhaustively against their stated errors
# helium-cycles: brdf_hammon's executed instructions and llvm-mca-16's
# Cortex-M55 cycles per sample (bench/qcount/qcount.sh m55, both builds)
# must be ports/README.md's Helium table (qemu's counts and the model are
# deterministic; compared with the gcc 12 / clang 14 the table names, shown
# otherwise), every call modelled (no instruction llvm-mca-16 rejects), and
# a copy of the table with one figure changed must fail the comparison.
# helium-f16-cycles: the same count for every kernel with a binary16 form
# (bench/qcount/qcount.sh m55-f16: helium f32, f32_fast and heliumfp16
# f16, both builds) must be ports/README.md's Helium binary16 table
# (bench/qcount/f16_rows.sh), with the same self-test.
# Skipped, with the reason, where the toolchain or qemu is missing.
# lane: emulators
. tests/lib/suite_lib.sh
have() { command -v "$1" > /dev/null 2>&1; }
if ! have arm-none-eabi-gcc; then
    echo "SKIP helium: arm-none-eabi-gcc missing (apt-get install gcc-arm-none-eabi libnewlib-arm-none-eabi)"
    echo "helium: 0 passed, 0 failed, 1 skipped"
    exit 0
fi
if ! have qemu-system-arm; then
    echo "SKIP helium: qemu-system-arm missing (apt-get install qemu-system-arm)"
    echo "helium: 0 passed, 0 failed, 1 skipped"
    exit 0
fi
# build/m55: everything with arm-none-eabi-gcc; build/m55-clang: the three
# helium objects (f32, fx, f16) with clang (HELIUM_CC, ports/helium/port.mk; the README's
# instruction counts), its port tests only.  Skipped without clang.
m55() { # m55 DIR LABEL HELIUM_CC TESTS...
    dir=$1 label=$2 hcc=$3
    shift 3
    mkdir -p $dir
    elfs=""
    for t in "$@"; do elfs="$elfs $dir/tests/$t.elf"; done
    if ! $MAKE -s -j"$JOBS" BUILD=$dir CC=arm-none-eabi-gcc AR=arm-none-eabi-ar PICFLAGS= M55_ARG=30000 \
            HELIUM_CC=$hcc CFLAGS="-mcpu=cortex-m55 -mfloat-abi=hard -mthumb -O2 -g" $elfs > $dir/build.log 2>&1; then
        cat $dir/build.log
        echo "ERROR $label: Cortex-M55 build failed (log: $dir/build.log)"
        return
    fi
    for t in "$@"; do
        run_one $label timeout 600 qemu-system-arm -M mps3-an547 -nographic \
            -semihosting-config enable=on,target=native -kernel $dir/tests/$t.elf
    done
}
m55 build/m55 helium arm-none-eabi-gcc test_f32_ports test_f32_accuracy test_fx_ports test_fx_hash \
    test_sample_ports test_sample_small test_f32_bad_input test_f32_rgb test_fx_rgb test_tails \
    test_f16_accuracy test_f16_ports test_f16_estimates
if have clang; then
    m55 build/m55-clang helium-clang clang test_f32_ports test_f32_accuracy test_fx_ports test_sample_ports \
        test_f16_accuracy test_f16_ports test_f16_estimates
else
    echo "SKIP helium-clang: clang missing (apt-get install clang)"
    echo "helium-clang: 0 passed, 0 failed, 1 skipped"
fi

# helium-cycles (above): the README's figures, "instr / cyc" per cell
if ! have clang; then
    echo "SKIP helium-cycles: clang missing (apt-get install clang)"
    echo "helium-cycles: 0 passed, 0 failed, 1 skipped"
elif ! have llvm-mca-16; then
    echo "SKIP helium-cycles: llvm-mca-16 not installed (apt-get install llvm-16: LLVM 14 has no Cortex-M55 model)"
    echo "helium-cycles: 0 passed, 0 failed, 1 skipped"
else
    cp=0 cf=0
    cbad() { cf=$((cf + 1)); echo "FAIL helium-cycles: $*"; }
    # row TIER GCC CLANG: the table's row of the figures in the two qcount outputs
    row() {
        awk -v t="$1" 'FILENAME == ARGV[1] && $3 == t { if ($2 == "scalar") s = $4 " / " $5; else g = $4 " / " $5 }
            FILENAME == ARGV[2] && $3 == t && $2 == "helium" { c = $4 " / " $5; ci = $4; cc = $5 }
            FILENAME == ARGV[2] && $3 == t && $2 == "scalar" { si = $4; sc = $5 }
            END { printf "| %s | %s | %s | %s | %.2fx / %.2fx |\n", t, s, g, c, si / ci, sc / cc }' "$2" "$3"
    }
    mkdir -p build/qcount build/m55-clang   # a fresh clone has neither
    if ! $MAKE -s BUILD=build/m55-clang CC=arm-none-eabi-gcc AR=arm-none-eabi-ar PICFLAGS= HELIUM_CC=clang \
            CFLAGS="-mcpu=cortex-m55 -mfloat-abi=hard -mthumb -O2 -g" build/m55-clang/libfacet.a > build/m55-clang/lib.log 2>&1 ||
       ! sh bench/qcount/qcount.sh m55 build/m55 > build/qcount/m55-gcc.txt 2> build/qcount/m55.log ||
       ! sh bench/qcount/qcount.sh m55 build/m55-clang > build/qcount/m55-clang.txt 2>> build/qcount/m55.log; then
        cbad "the count did not run (build/qcount/m55.log, build/m55-clang/lib.log)"
    else
        cat build/qcount/m55-gcc.txt build/qcount/m55-clang.txt | sed 's/^/helium-cycles: /'
        if awk '$5 == "-" { exit 1 }' build/qcount/m55-gcc.txt build/qcount/m55-clang.txt; then cp=$((cp + 1))
        else cbad "a call without modelled cycles (llvm-mca-16 rejected its trace: build/qcount/m55.d with QCOUNT_KEEP=1)"; fi
        gv=$(arm-none-eabi-gcc -dumpversion) clv=$(clang -dumpversion)
        if [ "${gv%%.*}" = 12 ] && [ "${clv%%.*}" = 14 ]; then
            for t in f32 f32_fast fx_fast; do
                row $t build/qcount/m55-gcc.txt build/qcount/m55-clang.txt
            done > build/qcount/m55.rows
            doc_rows helium-cycles "Helium table" build/qcount/m55.rows \
                's/^| fx_fast | \([0-9.]*\) \/ \([0-9]\)/| fx_fast | \1 \/ 9\2/' fx_fast build/qcount/README.broken.md
            n=$?; cp=$((cp + 2 - n)); cf=$((cf + n))
        else
            echo "helium-cycles: arm-none-eabi-gcc $gv, clang $clv: the figures are shown, not compared (ports/README.md: gcc 12, clang 14)"
        fi
    fi
    echo "helium-cycles: $cp passed, $cf failed, 0 skipped"
    # helium-f16-cycles (above)
    fp=0 ff=0 gv=$(arm-none-eabi-gcc -dumpversion) clv=$(clang -dumpversion)
    fbad() { ff=$((ff + 1)); echo "FAIL helium-f16-cycles: $*"; }
    if ! sh bench/qcount/qcount.sh m55-f16 build/m55 > build/qcount/m55f16-gcc.txt 2> build/qcount/m55f16.log ||
       ! sh bench/qcount/qcount.sh m55-f16 build/m55-clang > build/qcount/m55f16-clang.txt 2>> build/qcount/m55f16.log ||
       ! sh bench/qcount/f16_rows.sh build/qcount/m55f16-gcc.txt build/qcount/m55f16-clang.txt > build/qcount/m55f16.rows ||
       [ "$(grep -c . build/qcount/m55f16.rows)" -ne "$(grep -c ', f16, ' src/core/f16_kernels.def)" ]; then
        fbad "the count did not run or missed a kernel (build/qcount/m55f16.log, build/qcount/m55f16.rows)"
    else
        sed 's/^/helium-f16-cycles: /' build/qcount/m55f16.rows
        if awk '$5 == "-" { exit 1 }' build/qcount/m55f16-gcc.txt build/qcount/m55f16-clang.txt; then fp=$((fp + 1))
        else fbad "a call without modelled cycles (llvm-mca-16 rejected its trace: QCOUNT_KEEP=1 keeps build/qcount/m55f16.d)"; fi
        if [ "${gv%%.*}" = 12 ] && [ "${clv%%.*}" = 14 ]; then
            doc_rows helium-f16-cycles "Helium binary16 table" build/qcount/m55f16.rows \
                's/^| brdf_hammon | \([0-9.]*\) \/ \([0-9]\)/| brdf_hammon | \1 \/ 9\2/' brdf_hammon build/qcount/README.f16broken.md
            n=$?; fp=$((fp + 2 - n)); ff=$((ff + n))
        else
            echo "helium-f16-cycles: arm-none-eabi-gcc $gv, clang $clv: the figures are shown, not compared (ports/README.md: gcc 12, clang 14)"
        fi
    fi
    echo "helium-f16-cycles: $fp passed, $ff failed, 0 skipped"
fi
