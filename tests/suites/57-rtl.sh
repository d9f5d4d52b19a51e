# The RTL port (ports/rtl/): the fast fixed-point kernels as pipelined
# Verilog-2005, every module bit for bit against the C specification and
# its stated latency (make rtl-check, ports/rtl/run_tests.sh):
#   rtl_vectors    the committed golden vectors are `facet vectors`' today
#   rtl_verilator  Verilator, linked with libfacet: the golden vectors and
#                  1,000,000 random vectors (every int32 pattern class) through
#                  every module, every output compared, valid against the
#                  latency model, bubbles and resets mid-stream
#   rtl_icarus     Icarus Verilog on every module's golden vectors
# The long random run and the cost figures (Yosys, nextpnr-ice40) are
# `make rtl`.  Skipped, with the reason, where a simulator is missing.
. tests/lib/suite_lib.sh
have() { command -v "$1" > /dev/null 2>&1; }
for t in verilator g++ iverilog vvp; do
    if ! have $t; then
        echo "SKIP rtl: $t missing (apt-get install verilator g++ iverilog)"
        echo "rtl: 0 passed, 0 failed, 1 skipped"
        exit 0
    fi
done
if ! $MAKE -s -j"$JOBS" build/rtl/obj/Vrtl_all build/rtl/tb_icarus.vvp build/facet > build/rtl-build.log 2>&1; then
    cat build/rtl-build.log
    echo "ERROR rtl: build failed (log: build/rtl-build.log)"
    exit 0
fi
out=$(sh ports/rtl/run_tests.sh build 1000000 1 2>&1)
printf '%s\n' "$out" | grep -v '^PASS'
