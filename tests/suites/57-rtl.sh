# The RTL port (ports/rtl/): the fast fixed-point kernels as pipelined
# Verilog-2005, every module bit for bit against the C specification and
# its stated latency (make rtl-check, ports/rtl/run_tests.sh):
#   rtl_vectors    the committed golden vectors are `facet vectors`' today
#   rtl_verilator  Verilator, linked with libfacet: the golden vectors and
#                  1,000,000 random vectors (every int32 pattern class) through
#                  every module, every output compared, valid against the
#                  latency model, bubbles and resets mid-stream
#   rtl_icarus     Icarus Verilog on every module's golden vectors
#   rtl_cost       the committed cost figures (ports/rtl/cost.tsv, which the
#                  report reads) cover every module, the README shows them
# The long random run and the cost figures (Yosys, nextpnr-ice40) are
# `make rtl`.  Skipped, with the reason, where a simulator is missing.
. tests/lib/suite_lib.sh
have() { command -v "$1" > /dev/null 2>&1; }
# the committed cost figures (no tool needed): ports/rtl/cost.tsv has one
# row of 13 fields per module of kernels.txt, in its order, and the
# README's text between its cost markers is cost_md.sh's on them
p=0 f=0
want=$(sed -e '/^#/d' -e '/^$/d' -e 's/ .*//' ports/rtl/kernels.txt)
have_rows=$(awk -F'\t' 'NR > 1 && NF == 13 { print $1 }' ports/rtl/cost.tsv 2>/dev/null)
if [ "$want" = "$have_rows" ] && [ "$(awk 'END { print NR }' ports/rtl/cost.tsv)" -eq $(($(printf '%s\n' "$want" | wc -l) + 1)) ]; then
    p=$((p + 1))
else
    echo "FAIL rtl_cost: ports/rtl/cost.tsv lacks a row of 13 fields per kernel of ports/rtl/kernels.txt, in its order (make rtl remakes it)"
    f=$((f + 1))
fi
if sh ports/rtl/cost_readme.sh ports/rtl 2>&1 | cmp -s - ports/rtl/README.md; then
    p=$((p + 1))
else
    echo "FAIL rtl_cost: ports/rtl/README.md's cost text is not cost_md.sh's on the committed cost.tsv (sh ports/rtl/cost_readme.sh ports/rtl)"
    f=$((f + 1))
fi
echo "rtl_cost: $p passed, $f failed, 0 skipped"
for t in verilator g++ iverilog vvp; do
    if ! have $t; then
        echo "SKIP rtl: $t missing (apt-get install verilator g++ iverilog)"
        echo "rtl: 0 passed, 0 failed, 1 skipped"
        exit 0
    fi
done
if ! $MAKE -s -j"$JOBS" rtl-build > build/rtl-build.log 2>&1; then
    cat build/rtl-build.log
    echo "ERROR rtl: build failed (log: build/rtl-build.log)"
    exit 0
fi
out=$(sh ports/rtl/run_tests.sh build 1000000 1 2>&1)
printf '%s\n' "$out" | grep -v '^PASS'
