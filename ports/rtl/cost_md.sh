#!/bin/sh
# cost_md.sh BUILD/rtl - cost.md from cost.tsv and cost_cells.tsv (cost.sh):
# the per-module table, the anchor, and the cells by type.
set -eu
d=$1
echo "## RTL: the fast fixed-point kernels in hardware (ports/rtl)"
echo
echo "Verilog-2005, fully pipelined (one sample per clock), bit-exact with facet_<kernel>_fx_fast."
echo "Generic: Yosys \`synth\` + \`abc -g cmos\`; gate equivalents = CMOS transistors / 4 (NAND2 = 1, D flip-flop = 4);"
echo "depth = the longest path in cells between flip-flops. iCE40: Yosys \`synth_ice40\`, nextpnr-ice40 (seed 1):"
echo "LUT4 and DSP (SB_MAC16) of the module, LCs and Fmax of the placed module in its I/O wrapper; \"none\": does not fit"
echo "an UP5K (5280 LCs, 8 DSPs) or an HX8K (7680 LCs)."
echo
echo "| module | latency | cells | gate eq. | depth | device | LUT4 | DSP | EBR | LCs | Fmax MHz |"
echo "|---|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|"
awk -F'\t' 'NR > 1 { printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, $5, $9, $6, $7, $11, $10, $8 }' "$d/cost.tsv"
echo "| anchor: log-domain Phong shading engine (Lai, Yu, Chen, ISCAS 2002) | | | 12,061 gates | | ASIC | | | | | 450 |"
echo
echo "Comparisons across processes and libraries are rough: the anchor is a gate count and clock in its own 2002 ASIC"
echo "process; the figures here are a generic CMOS estimate and a small FPGA."
echo
echo "Modules that fit neither device, and what they need (iCE40 mapping of the module alone):"
echo
awk -F'\t' 'NR > 1 && $9 == "none" { print $1, $6, $7 }' "$d/cost.tsv" | while read -r k luts dsps; do
    if [ -f "$d/cost/$k.nodsp" ]; then
        alt="or $(cut -f2 "$d/cost/$k.nodsp") LUT4 with every product in LUTs"
    else
        alt="(the all-LUT mapping not run: some 500 LUT4 per DSP16 is past the HX8K)"
    fi
    echo "- $k: $luts LUT4 + $dsps DSP16 with the products on DSPs, $alt"
done
echo
echo "Cells by type (generic mapping):"
echo
awk -F'\t' 'NR > 1 { t = $2; sub(/^\$_/, "", t); sub(/_$/, "", t); c[$1] = c[$1] (c[$1] == "" ? "" : ", ") t " " $3
                     if (!($1 in seen)) { seen[$1] = 1; order[n++] = $1 } }
            END { for (i = 0; i < n; i++) printf "- %s: %s\n", order[i], c[order[i]] }' "$d/cost_cells.tsv"
