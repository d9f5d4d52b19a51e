#!/bin/sh
# mca.sh OBJDUMP OBJ SYMBOL TRIPLE CPU... - llvm-mca on the hot loop of SYMBOL
# in OBJ (SYMBOL: a name, or 0xADDR+0xSIZE for the function there): the
# longest backward branch of the function's disassembly (the main vector
# loop of a batch function), branch dropped; x86 jumps within the loop go
# to labels, so the figure does not depend on where the function sits.
# Prints "CPU cycles_per_iteration" per CPU (Total Cycles / Iterations),
# nothing if no loop is found.  MCA_WHOLE=1: the whole function body
# instead, every instruction once, branches/calls/returns dropped (callees
# not included).  Modelled figures, not measurements.
objdump=$1 obj=$2 sym=$3 triple=$4
shift 4
tmp=$(mktemp)
trap 'rm -f "$tmp" "$tmp.s"' EXIT
case $sym in
0x*+0x*) start=${sym%+*} size=${sym#*+}
         sel="--start-address=$start --stop-address=$(printf '0x%x' $((start + size)))" ;;
*) sel="--disassemble=$sym" ;;
esac
"$objdump" -d --no-show-raw-insn $sel "$obj" 2>/dev/null |
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
      m = 0
      for (i = 1; i <= NR; i++) if (addr[i] >= lo && addr[i] < hi) {
          s = ins[i]; sub(cm ".*$", "", s)
          if (whole && s ~ /^(b|bl|blx|bx|b[a-z][a-z]|b[a-z][a-z]\.[wn]|b\.[wn]|cbn?z|pop|ldmia|ldmia\.w)[ \t]/ && s ~ /(^b|pc)/) continue
          # x86 jumps inside the loop: to a label, not an absolute address,
          # so the figures do not depend on where the function was placed
          if (!whole && cm == "[#<]" && split(s, w, /[ \t]+/) >= 2 && w[1] ~ /^j[a-z]+$/ && w[2] ~ /^[0-9a-f]+$/) {
              t = hex(w[2])
              if (t >= lo && t < hi) { s = w[1] " .Lt" t; want[t] = 1 } else { s = w[1] " .Lout"; out = 1 }
          }
          m++; at[m] = addr[i]; line[m] = s }
      for (i = 1; i <= m; i++) { if (at[i] in want) print ".Lt" at[i] ":"; print line[i] }
      if (out) print ".Lout:" }
' "$tmp" > "$tmp.s" 2>/dev/null || exit 0
[ -s "$tmp.s" ] || exit 0
for cpu in "$@"; do
    llvm-mca -mtriple="$triple" -mcpu="$cpu" -iterations=200 "$tmp.s" 2>/dev/null |
        awk -v cpu="$cpu" '/^Iterations:/ {it = $2} /^Total Cycles:/ {c = $3} END { if (it) printf "%s %.3f\n", cpu, c / it }'
done
