#!/bin/sh
# run_tests.sh BUILD RANDOM SEED - the RTL's bit-exactness and latency
# checks (make rtl-check, make rtl; tests/suites/57-rtl.sh):
#   rtl_vectors    the committed golden vectors are what `facet vectors`
#                  writes today (the C and the files have not drifted)
#   rtl_verilator  every kernel against libfacet: the golden vectors and
#                  RANDOM random vectors from SEED (tb/tb_verilator.cpp)
#   rtl_icarus     every kernel's golden vectors under Icarus Verilog
#                  (tb/tb_icarus.v, built per kernel: BUILD/rtl/icarus/K.vvp)
# Any FX_WIDTH_ERROR (a width claim of the RTL broken in simulation) fails
# its simulator's run.  Prints "<name>: N passed, N failed, N skipped" lines.
set -u
build=$1 n=$2 seed=$3
b=$build/rtl
dir=ports/rtl
count=200 # make rtl-vectors' RTL_VECTORS

# the committed files against the CLI's output today
p=0 f=0
for k in $(sed -e '/^#/d' -e '/^$/d' -e 's/ .*//' $dir/kernels.txt); do
    [ "$k" = brdf_hammon_rgb ] && continue
    if "$build/facet" vectors "$k" --format fx_fast --count $count --seed 1 --hex | cmp -s - "$dir/vectors/$k.hex"; then
        p=$((p + 1))
    else
        echo "FAIL rtl_vectors: $dir/vectors/$k.hex differs from 'facet vectors $k --format fx_fast --count $count --seed 1 --hex' (make rtl-vectors rewrites it)"
        f=$((f + 1))
    fi
done
echo "rtl_vectors: $p passed, $f failed, 0 skipped"

# Verilator against the C
out=$("$b/obj/Vrtl_all" --random "$n" --seed "$seed" --vectors "$dir/vectors" 2>&1)
rc=$?
printf '%s\n' "$out" | grep -v '^rtl_verilator:'
w=$(printf '%s\n' "$out" | grep -c FX_WIDTH_ERROR)
summary=$(printf '%s\n' "$out" | grep '^rtl_verilator:')
if [ -z "$summary" ] || [ $rc -ne 0 ] && ! printf '%s' "$summary" | grep -q '[1-9][0-9]* failed'; then
    echo "ERROR rtl_verilator: exited with status $rc"
fi
if [ "$w" -gt 0 ]; then
    echo "FAIL rtl_verilator: $w width errors"
    summary=$(printf '%s' "$summary" | awk '{ $(NF-3) = $(NF-3) + 1; print }')
fi
echo "$summary"

# Icarus on the golden vectors, one kernel per run
p=0 f=0
awk '!/^#/ && NF { print $1, $2, $3, $4, $5, s; s += $4 }' $dir/kernels.txt > "$b/kernels.slots"
while read -r k nin bits outs lat slot; do
    file=$dir/vectors/$k.hex
    [ "$outs" = 3 ] && { file=$dir/vectors/brdf_hammon.hex; nin=6; }
    nv=$(grep -vc '^//' "$file")
    out=$(vvp -n "$b/icarus/$k.vvp" +vec="$file" +n="$nv" +name="$k" +slot="$slot" +nin="$nin" +bits="$bits" \
        +outs="$outs" +lat="$lat" 2>&1)
    if printf '%s\n' "$out" | grep -q "^PASS $k:" && ! printf '%s\n' "$out" | grep -q 'FAIL\|FX_WIDTH_ERROR'; then
        printf '%s\n' "$out" | grep '^PASS'
        p=$((p + 1))
    else
        printf '%s\n' "$out" | grep -v '^PASS' | head -n 8 | sed 's/^\([^F]\)/FAIL rtl_icarus: \1/'
        f=$((f + 1))
    fi
done < "$b/kernels.slots"
echo "rtl_icarus: $p passed, $f failed, 0 skipped"
