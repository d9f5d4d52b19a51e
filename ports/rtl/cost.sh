#!/bin/sh
# cost.sh BUILD [KERNEL...] - the hardware cost of every RTL module (make
# rtl), written to BUILD/rtl/cost.tsv (the format: ports/rtl/README.md),
# BUILD/rtl/cost_cells.tsv (module, cell type, count) and BUILD/rtl/cost.md;
# logs and netlists in BUILD/rtl/cost/.  The two .tsv are copied to
# ports/rtl/ (committed: the report's hardware row and section read them)
# and cost.md's text into ports/rtl/README.md (cost_readme.sh).
#   generic  Yosys `synth -flatten`, then `abc -g cmos` (NAND, NOR, AOI/OAI,
#            MUX, XOR, NOT; flip-flops legalised to plain D flip-flops):
#            cells by type, gate equivalents = Yosys's CMOS transistor
#            estimate (`stat -tech cmos`) / 4 (a NAND2 is 4 transistors, a
#            D flip-flop 16), depth = the longest combinational path in
#            cells between flip-flops (`ltp -noff`): the deepest stage
#   iCE40    `synth_ice40` of the module alone (LUT4, DSP, EBR, flip-flops):
#            with its 16x16 products on SB_MAC16 for the UP5K (8 DSPs, 5280
#            LCs; a partial product with an operand of 4 bits or fewer stays
#            in LUTs, and ports/rtl/fit.txt may move named products to LUTs so
#            a module fits), else all in LUTs for the HX8K (7680 LCs); where it
#            fits, nextpnr-ice40 (seed 1) places and routes it inside a
#            wrapper that feeds the inputs from a serial shift register and
#            folds the outputs into one pin by a pipelined XOR (so nothing is
#            optimised away; its flip-flops are in the LC count): LCs, DSPs and
#            the maximum clock from the router's timing report
# Skipped, with the reason, where yosys or nextpnr-ice40 is missing.
set -u
build=$1
shift
b=$build/rtl
c=$b/cost
dir=ports/rtl
mkdir -p "$c"
for t in yosys nextpnr-ice40; do
    if ! command -v $t > /dev/null 2>&1; then
        echo "SKIP rtl cost: $t missing (apt-get install yosys nextpnr-ice40)"
        exit 0
    fi
done
srcs="$b/gen/fx_tables.v $(ls $dir/rtl/*.v | tr '\n' ' ')"
inc="-DSYNTHESIS -I$dir/rtl -I$b/gen"
only="$*"
# the HX8K is tried up to this many LUT4 (of its 7680: nextpnr's router does
# not converge on these multiplier-dense netlists much above it); each
# place-and-route gets at most RTL_PNR_TIMEOUT seconds
hx8k_luts=${RTL_HX8K_LUTS:-5600}
pnr_timeout=${RTL_PNR_TIMEOUT:-1200}
tsv=$b/cost.tsv
cells_tsv=$b/cost_cells.tsv
printf 'module\tlatency\tcells\tgate_equivalents\tdepth\tluts\tdsps\tfmax_mhz\tdevice\tlcs\tebr\tffs\tluts_no_dsp\n' > "$tsv.tmp"
printf 'module\tcell\tcount\n' > "$cells_tsv.tmp"

# stat_of LOG TYPE: the count of cells TYPE in the last statistics of LOG
stat_of() {
    awk -v t="$2" '/Printing statistics/ { n = 0 } $1 == t { n = $2 } END { print n + 0 }' "$1"
}

# wrapper K NIN BITS OUTS: the place-and-route top around fx_K
wrapper() {
    k=$1 nin=$2 bits=$3 outs=$4
    w=$((32 * nin)) ny=$((bits * outs + 1))
    args="" j=0
    while [ $j -lt "$nin" ]; do args="$args sh[$((32 * j + 31)):$((32 * j))],"; j=$((j + 1)); done
    ys="" o=0
    while [ $o -lt "$outs" ]; do ys="$ys, y[$((bits * o + bits - 1)):$((bits * o))]"; o=$((o + 1)); done
    cat <<EOF
// the place-and-route wrapper of fx_$k (ports/rtl/cost.sh): inputs from a
// serial shift register, outputs folded into one pin, in three XOR stages
module pnr_top (input clk, input rst, input sin, output reg sout);
    localparam N = $ny, M1 = (N + 3) / 4, M2 = (M1 + 3) / 4, M3 = (M2 + 3) / 4;
    reg [$((w - 1)):0] sh;
    reg iv;
    wire ov;
    wire [$((ny - 2)):0] y;
    wire [4*M1-1:0] d1 = {y, ov};
    reg [4*M2-1:0] r1;
    reg [4*M3-1:0] r2;
    reg [3:0] r3;
    integer i;
    always @(posedge clk) begin
        sh <= {sh[$((w - 2)):0], sin};
        iv <= sh[$((w - 1))];
        r1 <= 0;
        r2 <= 0;
        r3 <= 0;
        for (i = 0; i < M1; i = i + 1) r1[i] <= ^d1[4*i +: 4];
        for (i = 0; i < M2; i = i + 1) r2[i] <= ^r1[4*i +: 4];
        for (i = 0; i < M3; i = i + 1) r3[i] <= ^r2[4*i +: 4];
        sout <= ^r3;
    end
    fx_$k k (clk, rst, iv,$args ov$ys);
endmodule
EOF
}

# ice40 K TOP DSP DEMOTE OUT: synth_ice40 of TOP (fx_K or pnr_top) into OUT.json / OUT.log;
# DSP = -dsp or empty; DEMOTE = instance paths inside fx_K whose products stay
# in LUTs.  With -dsp the coarse step is spelled out (synth_ice40's own, with
# the demotions before the DSP mapping); Yosys 0.23's ice40_dsp (which packs
# registers into the DSP blocks) crashes on some modules: there the step is
# run without it, the DSP blocks' registers in the fabric, and OUT.nopack says so.
ice40() {
    k=$1 top=$2 dsp=$3 demote=$4 out=$5
    pre=""
    [ "$top" = pnr_top ] && pre="k."
    sel=""
    for p in $demote; do
        pat=$(printf '%s%s' "$pre" "$p" | sed 's/\./.?/g')
        sel="$sel chtype -set \$__soft_mul $top/*$pat.* $top/t:\$mul %i;"
    done
    extra=""
    [ "$top" = pnr_top ] && extra="$c/$k.wrap.v"
    rm -f "$out.nopack" "$out.json" "$out.log"
    if [ -z "$dsp" ]; then
        yosys -q -l "$out.log" -p "read_verilog $inc $srcs $extra; synth_ice40 -top $top -json $out.json; stat" \
            > /dev/null 2>&1
        return
    fi
    packs='ice40_dsp ""'
    [ -n "$nopack_known" ] && packs='""'
    for pack in $packs; do
        [ "$pack" = '""' ] && pack=""
        if yosys -q -l "$out.log" -p "read_verilog $inc $srcs $extra; synth_ice40 -dsp -top $top -run :coarse; $sel
            opt_expr; opt_clean; check; opt -nodffe -nosdff; fsm; opt; wreduce; peepopt; opt_clean; share;
            techmap -map +/cmp2lut.v -D LUT_WIDTH=4; opt_expr; opt_clean; memory_dff; wreduce t:\$mul;
            techmap -map +/mul2dsp.v -map +/ice40/dsp_map.v -D DSP_A_MAXWIDTH=16 -D DSP_B_MAXWIDTH=16 -D DSP_A_MINWIDTH=5 -D DSP_B_MINWIDTH=5 -D DSP_Y_MINWIDTH=11 -D DSP_NAME=\$__MUL16X16;
            select a:mul2dsp; setattr -unset mul2dsp; opt_expr -fine; wreduce; select -clear; $pack
            chtype -set \$mul t:\$__soft_mul; alumacc; opt; memory -nomap; opt_clean;
            synth_ice40 -dsp -top $top -run map_ram: -json $out.json; stat" > /dev/null 2>&1; then
            [ -z "$pack" ] && echo "ice40_dsp crashed: DSP registers in the fabric" > "$out.nopack"
            return 0
        fi
    done
    return 1
}

awk '!/^#/ && NF { print $1, $2, $3, $4, $5 }' $dir/kernels.txt | while read -r k nin bits outs lat; do
    if [ -n "$only" ] && ! printf ' %s ' "$only" | grep -q " $k "; then continue; fi
    echo "rtl cost: $k ..."
    # ---- generic: cells, gate equivalents, depth
    yosys -q -l "$c/$k.generic.log" -p "read_verilog $inc $srcs; synth -flatten -top fx_$k;
        dfflegalize -cell \$_DFF_P_ 01; abc -g cmos; opt_clean; tee -o $c/$k.stat stat -tech cmos;
        tee -o $c/$k.ltp ltp -noff" > /dev/null 2>&1 || { echo "ERROR rtl cost: yosys failed on $k"; continue; }
    cells=$(awk '/Number of cells:/ { n = $4 } END { print n }' "$c/$k.stat")
    tr=$(awk '/Estimated number of transistors/ { n = $5 } END { print n }' "$c/$k.stat")
    case $tr in *+) echo "ERROR rtl cost: $k has cells without a transistor estimate" ;; esac
    ge=$(( ${tr%+} / 4 ))
    depth=$(sed -n 's/.*(length=\([0-9]*\)).*/\1/p' "$c/$k.ltp")
    awk -v m="$k" '$1 ~ /^\$_/ { printf "%s\t%s\t%s\n", m, $1, $2 }' "$c/$k.stat" >> "$cells_tsv.tmp"
    # ---- iCE40: the UP5K with DSPs (and this module's fit demotions), else the HX8K in LUTs
    demote=$(awk -v k="$k" '$1 == k && $2 == "up5k" { for (i = 3; i <= NF; i++) printf "%s ", $i }' $dir/fit.txt)
    nopack_known=""
    ice40 "$k" "fx_$k" -dsp "$demote" "$c/$k.up5k" || echo "ERROR rtl cost: synth_ice40 -dsp failed on $k"
    [ -f "$c/$k.up5k.nopack" ] && nopack_known=1
    luts=$(stat_of "$c/$k.up5k.log" SB_LUT4)
    dsps=$(stat_of "$c/$k.up5k.log" SB_MAC16)
    ebr=$(stat_of "$c/$k.up5k.log" SB_RAM40_4K)
    ffs=$(awk '/Printing statistics/ { n = 0 } $1 ~ /^SB_DFF/ { n += $2 } END { print n + 0 }' "$c/$k.up5k.log")
    device=none fmax=- lcs=- nodsp=-
    wrapper "$k" "$nin" "$bits" "$outs" > "$c/$k.wrap.v"
    try_pnr() { # try_pnr DEVICE PACKAGE DSP DEMOTE NAME
        rm -f "$c/$k.$5.pnr.log" "$c/$k.$5.asc"
        ice40 "$k" pnr_top "$3" "$4" "$c/$k.$5.wrap" || return 1
        if timeout "$pnr_timeout" nextpnr-ice40 --$1 --package $2 --json "$c/$k.$5.wrap.json" \
                --pcf-allow-unconstrained --freq 12 --seed 1 --asc "$c/$k.$5.asc" > "$c/$k.$5.pnr.log" 2>&1; then
            device=$1
            fmax=$(sed -n "s/.*Max frequency for clock '[^']*': \([0-9.]*\) MHz.*/\1/p" "$c/$k.$5.pnr.log" | tail -n 1)
            lcs=$(sed -n 's/.*ICESTORM_LC: *\([0-9]*\)\/.*/\1/p' "$c/$k.$5.pnr.log" | tail -n 1)
            return 0
        fi
        grep -q 'ERROR' "$c/$k.$5.pnr.log" || echo "rtl cost: $k: nextpnr-ice40 --$1 stopped after $pnr_timeout s"
        return 1
    }
    if [ "$dsps" -le 8 ] && [ "$luts" -le 5000 ] && [ "$ebr" -le 30 ] && try_pnr up5k sg48 -dsp "$demote" up5k; then
        :
    else
        # a 16x16 product in LUTs is some 500 LUT4 here: past the HX8K by that
        # estimate, the (slow) all-LUT mapping is not run
        if [ $((luts + 500 * dsps)) -gt "$hx8k_luts" ]; then
            echo "rtl cost: $k does not fit: $luts LUT4 + $dsps DSP16 with DSPs (all-LUT mapping not run)"
            printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$k" "$lat" "$cells" "$ge" "$depth" "$luts" \
                "$dsps" - none - "$ebr" "$ffs" - >> "$tsv.tmp"
            continue
        fi
        ice40 "$k" "fx_$k" "" "" "$c/$k.hx8k" || echo "ERROR rtl cost: synth_ice40 failed on $k"
        nluts=$(stat_of "$c/$k.hx8k.log" SB_LUT4)
        nebr=$(stat_of "$c/$k.hx8k.log" SB_RAM40_4K)
        nffs=$(awk '/Printing statistics/ { n = 0 } $1 ~ /^SB_DFF/ { n += $2 } END { print n + 0 }' "$c/$k.hx8k.log")
        if [ "$nluts" -le "$hx8k_luts" ] && [ "$nebr" -le 32 ] && try_pnr hx8k ct256 "" "" hx8k; then
            luts=$nluts dsps=0 ebr=$nebr ffs=$nffs nodsp=$nluts
        else
            # no fit: the needs, with DSPs (luts, dsps) and without (in the log)
            echo "rtl cost: $k does not fit: $luts LUT4 + $dsps DSP16 with DSPs, or $nluts LUT4 without"
            nodsp=$nluts
        fi
    fi
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$k" "$lat" "$cells" "$ge" "$depth" "$luts" "$dsps" \
        "$fmax" "$device" "$lcs" "$ebr" "$ffs" "$nodsp" >> "$tsv.tmp"
done
# a run on some kernels keeps the other kernels' rows of the last run
if [ -n "$only" ] && [ -f "$tsv" ]; then
    awk -F'\t' -v only=" $only " 'FNR == 1 { next } index(only, " " $1 " ") == 0 { print }' "$tsv" >> "$tsv.tmp"
    awk -F'\t' -v only=" $only " 'FNR == 1 { next } index(only, " " $1 " ") == 0 { print }' "$cells_tsv" >> "$cells_tsv.tmp"
fi
# rows in kernels.txt order
order=$(awk '!/^#/ && NF { printf "%s ", $1 }' $dir/kernels.txt)
for f in "$tsv" "$cells_tsv"; do
    { head -n 1 "$f.tmp"
      for k in $order; do awk -F'\t' -v k="$k" 'FNR > 1 && $1 == k' "$f.tmp"; done
    } > "$f"
    rm -f "$f.tmp"
done
sh $dir/cost_md.sh "$b" > "$b/cost.md"
# the committed copy the report reads (make report runs no synthesis), and
# its text in ports/rtl/README.md between the cost markers
cp "$tsv" "$cells_tsv" $dir/
sh $dir/cost_readme.sh $dir > $dir/README.md.tmp && mv $dir/README.md.tmp $dir/README.md
echo "rtl cost: wrote $tsv, $cells_tsv, $b/cost.md; $dir/cost.tsv, $dir/cost_cells.tsv and the README's table"
