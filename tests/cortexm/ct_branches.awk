# ct_branches.awk - the conditional branches in `objdump -d` output, per
# function whose name matches -v pat (an ERE; default: the fast kernels
# facet_*_fx_fast): prints "COUNT NAME" for every such function, 0 included
# (tests/suites/51-fx-wcet.sh compares them with the stated ones).  A
# conditional branch: B<cond>, CBZ, CBNZ (IT-predicated instructions are
# not branches).
BEGIN { if (pat == "") pat = "^facet_.*_fx_fast$" }
/^[0-9a-f]+ <[^>]*>:$/ { fn = $2; gsub(/[<>:]/, "", fn); if (fn ~ pat) n[fn] += 0; next }
fn ~ pat && /\t(b(eq|ne|cs|hs|cc|lo|mi|pl|vs|vc|hi|ls|ge|lt|gt|le)(\.[nw])?|cbn?z)\t/ { n[fn]++ }
END { for (f in n) print n[f], f }
