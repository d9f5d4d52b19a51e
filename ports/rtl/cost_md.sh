#!/bin/sh
# cost_md.sh DIR - the cost figures as Markdown from DIR/cost.tsv and
# DIR/cost_cells.tsv (cost.sh; DIR is BUILD/rtl, or ports/rtl for the
# committed copy): the per-module table with the anchor, what the modules
# that fit no iCE40 need, and the cells by type.  ports/rtl/README.md holds
# this text for the committed copy between its cost markers (cost.sh writes
# it there; tests/suites/57-rtl.sh checks that the two agree).
set -eu
d=$1
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
if awk -F'\t' 'NR > 1 && $9 == "-" { n++ } END { exit !n }' "$d/cost.tsv"; then
    echo "Not measured (device \`-\`: the last cost run stopped before them; \`make rtl\` or \`sh ports/rtl/cost.sh build KERNEL...\`):"
    echo "$(awk -F'\t' 'NR > 1 && $9 == "-" { printf "%s%s", n++ ? ", " : "", $1 }' "$d/cost.tsv")."
    echo
fi
if awk -F'\t' 'NR > 1 && $9 == "none" { n++ } END { exit !n }' "$d/cost.tsv"; then
    echo "Modules that fit neither device, and what they need (iCE40 mapping of the module alone):"
    echo
    awk -F'\t' 'NR > 1 && $9 == "none" {
        alt = $13 == "-" ? "(the all-LUT mapping not run: at some 500 LUT4 per DSP16 it is past the HX8K)" \
                         : "or " $13 " LUT4 with every product in LUTs"
        printf "- %s: %s LUT4 + %s DSP16 with the products on DSPs, %s\n", $1, $6, $7, alt }' "$d/cost.tsv"
    echo
fi
echo "Cells by type (generic mapping):"
echo
awk -F'\t' 'NR > 1 { t = $2; sub(/^\$_/, "", t); sub(/_$/, "", t); c[$1] = c[$1] (c[$1] == "" ? "" : ", ") t " " $3
                     if (!($1 in seen)) { seen[$1] = 1; order[n++] = $1 } }
            END { for (i = 0; i < n; i++) printf "- %s: %s\n", order[i], c[order[i]] }' "$d/cost_cells.tsv"
