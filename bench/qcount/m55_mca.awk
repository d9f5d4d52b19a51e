# m55_mca.awk - a Cortex-M55 executed-instruction listing (objdump
# --no-show-raw-insn syntax, one instruction a line, in execution order:
# bench/qcount/qcount.sh, bench/report/arm_targets.sh) as input for
# llvm-mca-16 -mtriple=thumbv8.1m.main -mcpu=cortex-m55 -mattr=+mve.fp.
# The listing must come from objdump -m armv8.1-m.main (without it MVE
# decodes as coprocessor instructions).  The trace holds the callees'
# instructions already, so: every branch
# target becomes one local label (the listing is straight-line code),
# BL/BLX become B/BX (llvm-mca charges a call 100 cycles), objdump's
# comments and .w/.n width suffixes go (a VMOV's floating-point immediate
# is taken from its comment), and the low-overhead-loop
# instructions LLVM 16's assembler-to-MCA path does not accept are
# replaced by their register effect plus a branch: DLS/DLSTP lr, rN -> mov
# lr, rN; WLS/WLSTP lr, rN, L -> mov lr, rN and b .Lt; LE/LETP lr, L -> b .Lt
# (the decrement is folded into the loop hardware); VMRS APSR_nzcv, FPSCR
# is dropped (below).  MODELLED cycles: no
# fetch or branch penalty, no wait states.
BEGIN { print ".Lt:" }
/^[ \t]*$/ { next }
{
    line = $0
    # VMOV.F32 sN, #imm8: objdump prints the encoded imm8 and the value in
    # its comment ("#112 @ 0x3f800000  1.0"); the assembler wants the value
    if (line ~ /^vmov[a-z]*\.f(16|32|64)[ \t]/ && line ~ /#[0-9]+[ \t]*@ 0x[0-9a-f]+[ \t]+-?[0-9.]+$/) {
        v = line; sub(/^.*[ \t]/, "", v); sub(/#[0-9]+[ \t]*@.*$/, "#" v, line) }
    sub(/[ \t]*[@;].*$/, "", line)       # "@ (8b40 <main+0x90>)", "; ..."
    sub(/^[ \t]+/, "", line)
    m = line; sub(/[ \t].*$/, "", m)
    o = line; sub(/^[^ \t]+[ \t]*/, "", o)
    sub(/\.[wn]$/, "", m)
    if (m == "bl") { print "b\t.Lt"; next }
    if (m == "blx") { print "bx\t" o; next }
    if (m ~ /^b(eq|ne|cs|hs|cc|lo|mi|pl|vs|vc|hi|ls|ge|lt|gt|le|al)?$/) { print m "\t.Lt"; next }
    if (m ~ /^cbn?z$/) { sub(/,.*/, "", o); print m "\t" o ", .Lt"; next }
    if (m == "dls" || m == "dlstp.8" || m == "dlstp.16" || m == "dlstp.32" || m == "dlstp.64") {
        r = o; sub(/^[^,]*,[ \t]*/, "", r); print "mov\tlr, " r; next }
    if (m == "wls" || m ~ /^wlstp\./) {
        r = o; sub(/^[^,]*,[ \t]*/, "", r); sub(/,.*/, "", r); print "mov\tlr, " r; print "b\t.Lt"; next }
    if (m == "le" || m == "letp") { print "b\t.Lt"; next }
    # VMRS APSR_nzcv, FPSCR (the FP compare's flags to the core): LLVM 16's
    # M55 model has no scheduling data for it and llvm-mca rejects it, so it
    # is left out (the callers report how many per sample)
    if (m == "vmrs" && o ~ /^APSR_nzcv/) next
    print m "\t" o
}
