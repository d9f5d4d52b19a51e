# fx_stack.awk - the worst-case stack depth of every global function in
# gcc's -fcallgraph-info=su files (*.ci, VCG): its own frame (-fstack-usage,
# "N bytes (static)") plus the deepest chain of its callees.  Prints
# "depth name" per global function (the library's API: facet_*), then
# "max N NAME".  Fails (exit 1, a "BAD" line) on a frame that is not static
# (dynamic or bounded: alloca, VLA), a callee without a frame (an external
# function: a helper or libc call outside the sources), an indirect call,
# or recursion: for those no bound follows from the graph.
function depth(n,    i, d, m, t) {
    if (n in memo) return memo[n]
    if (n in busy) { print "BAD recursion through " n; bad = 1; return 0 }
    if (!(n in frame)) { print "BAD no frame for " n " (an external callee)"; bad = 1; return 0 }
    busy[n] = 1
    m = 0
    for (i = 1; i <= ncall[n]; i++) {
        d = depth(call[n, i])
        if (d > m) m = d
    }
    delete busy[n]
    memo[n] = frame[n] + m
    return memo[n]
}
/^node:/ {
    t = $0; sub(/.*title: "/, "", t); sub(/".*/, "", t)
    l = $0; sub(/.*label: "/, "", l); sub(/".*/, "", l)
    if (l ~ /bytes \(static\)/) {
        b = l; sub(/ bytes \(static\).*/, "", b); sub(/.*\\n/, "", b)
        frame[t] = b + 0
    } else if (l ~ /bytes/) {
        print "BAD frame not static: " t " (" l ")"; bad = 1; frame[t] = 0
    }
    if (t !~ /:/) global[t] = 1
    next
}
/^edge:/ {
    s = $0; sub(/.*sourcename: "/, "", s); sub(/".*/, "", s)
    d = $0; sub(/.*targetname: "/, "", d); sub(/".*/, "", d)
    if (d ~ /__indirect_call/) { print "BAD indirect call in " s; bad = 1; next }
    call[s, ++ncall[s]] = d
}
END {
    mx = -1
    for (g in global) {
        if (g !~ /^facet_/) continue
        v = depth(g)
        print v, g
        if (v > mx) { mx = v; mn = g }
    }
    print "max", mx, mn
    exit bad
}
