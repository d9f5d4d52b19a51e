#!/bin/sh
# mca.sh OBJDUMP OBJ SYMBOL TRIPLE CPU... - llvm-mca on the hot loop of SYMBOL
# in OBJ: the longest backward branch of the function's disassembly (the
# main vector loop of a batch function), branch dropped.  Prints
# "CPU cycles_per_iteration" per CPU (Total Cycles / Iterations), nothing
# if no loop is found.  MCA_WHOLE=1: the whole function body instead, every
# instruction once, branches/calls/returns dropped (callees not included).
# Modelled figures, not measurements.
objdump=$1 obj=$2 sym=$3 triple=$4
shift 4
tmp=$(mktemp)
trap 'rm -f "$tmp" "$tmp.s"' EXIT
"$objdump" -d --no-show-raw-insn --disassemble="$sym" "$obj" 2>/dev/null |
    grep -E '^ +[0-9a-f]+:' > "$tmp"
# loop: from the target of the backward jump with the largest span to it
case $triple in x86*|i?86*) cm='[#<]' ;; *) cm='[;@<]' ;; esac
awk -v whole="${MCA_WHOLE:-0}" -v cm="$cm" -F'\t' '
function hex(s,   i, n, c) { n = 0; s = tolower(s)
  for (i = 1; i <= length(s); i++) { c = index("0123456789abcdef", substr(s, i, 1)); if (!c) break; n = n * 16 + c - 1 }
  return n }
{ h = $1; sub(/^ +/, "", h); sub(/:.*$/, "", h); a = hex(h); x = $2
  for (f = 3; f <= NF; f++) x = x " " $f
  addr[NR] = a; ins[NR] = x
  n = split(x, w, /[ \t,]+/)
  if (w[1] ~ /^(j[a-z]+|b[a-z][a-z]|b[a-z][a-z]\.[wn]|cbn?z)$/ && w[1] != "jmp" && w[1] !~ /^bl/ && n >= 2) {
      t = w[n - 0]; if (w[1] ~ /^cbn?z/) t = w[3]; else t = w[2]
      sub(/^#?(0x)?/, "", t); tgt = hex(t)
      if (tgt < a && a - tgt > best) { best = a - tgt; lo = tgt; hi = a }
  } }
END { if (whole) { lo = 0; hi = 1e18; best = 1 }
      if (!best) exit 1
      for (i = 1; i <= NR; i++) if (addr[i] >= lo && addr[i] < hi) {
          s = ins[i]; sub(cm ".*$", "", s)
          if (whole && s ~ /^(b|bl|blx|bx|b[a-z][a-z]|b[a-z][a-z]\.[wn]|b\.[wn]|cbn?z|pop|ldmia|ldmia\.w)[ \t]/ && s ~ /(^b|pc)/) continue
          print s } }
' "$tmp" > "$tmp.s" 2>/dev/null || exit 0
[ -s "$tmp.s" ] || exit 0
for cpu in "$@"; do
    llvm-mca -mtriple="$triple" -mcpu="$cpu" -iterations=200 "$tmp.s" 2>/dev/null |
        awk -v cpu="$cpu" '/^Iterations:/ {it = $2} /^Total Cycles:/ {c = $3} END { if (it) printf "%s %.3f\n", cpu, c / it }'
done
