# cortexm_mca.awk - an executed-instruction listing (objdump syntax, from
# bench/cortexm/cortexm_trace.awk) as llvm-mca input: .w/.n width suffixes dropped
# (LLVM's assembler picks the encoding), every branch target replaced by
# one local label, BL/BLX turned into B (llvm-mca charges a call 100
# cycles; the callee's instructions follow in the trace anyway).
# -v noit=1 (cortex-m7: LLVM 14's M7 model rejects IT): IT dropped and the
# instructions of its block unpredicated (same operations and registers).
BEGIN { print ".Lt:" }
{
    m = $1; o = $0; sub(/^[^ \t]+[ \t]*/, "", o); sub(/\.[wn]$/, "", m)
    if (noit && m ~ /^it[te]*$/) { left = length(m) - 1; next }
    if (noit && left > 0) { left--; sub(/(eq|ne|cs|hs|cc|lo|mi|pl|vs|vc|hi|ls|ge|lt|gt|le)$/, "", m) }
    if (m == "bl") { print "b\t.Lt"; next }
    if (m == "blx") { print "bx\t" o; next }
    if (m ~ /^b(eq|ne|cs|hs|cc|lo|mi|pl|vs|vc|hi|ls|ge|lt|gt|le|al)?$/) { print m "\t.Lt"; next }
    if (m ~ /^cbn?z$/) { sub(/,.*/, "", o); print m "\t" o ", .Lt"; next }
    print m "\t" o
}
