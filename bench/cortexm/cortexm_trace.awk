# cortexm_trace.awk - cuts the calls of the traced functions out of a qemu
# instruction trace (bench/cortexm/cortexm.sh).  Reads three files in order:
#   1. `objdump -d` of the ELF: address -> size and instruction text
#   2. "ADDR NAME" lines: the entry point of every function to trace
#   3. the qemu log of `-singlestep -d exec,nochain`: one line per executed
#      instruction, "Trace N: HOST [CS/PC/FLAGS/CFLAGS] SYMBOL"
# A call runs from the function's entry to the instruction after the call
# site (return address = PC before the entry + that instruction's size);
# everything executed in between counts (callees, libgcc helpers).
# Prints per call "NAME INSNS M0CYCLES TAKEN" (TAKEN: branches, calls and
# returns that changed the flow) and appends the executed
# instruction texts of every call to DIR/NAME.s (for llvm-mca).
# With -v paths=1 (tests/cortexm/wcet.sh) the texts go, once per distinct
# executed path of a function, to DIR/NAME.pK.s instead (K from 1), and each
# call line ends with its path number K.
# With -v pcs=1 the executed addresses (hex, one a line) also go to
# DIR/NAME.pc (bench/cortexm/cortexm_prof.sh's per-function profile).
# M0CYCLES: the Cortex-M0 TRM timings (zero wait states, single-cycle
# multiplier): 1 per instruction, loads/stores 2, LDM/STM/PUSH/POP 1+N,
# POP with PC 3+N, branches 3 when taken (1 when not), BL 4, BX/BLX 3,
# writes to PC 3.  A model, not a measurement.
function hex(s,   i, n, c) { n = 0; s = tolower(s); sub(/^0x/, "", s)
    for (i = 1; i <= length(s); i++) { c = index("0123456789abcdef", substr(s, i, 1)); if (!c) break; n = n * 16 + c - 1 }
    return n }
function nregs(ops,   t, n) { t = ops; sub(/^[^{]*\{/, "", t); sub(/\}.*$/, "", t); n = split(t, _r, ","); return n }
function m0cyc(ins, taken,   m, ops, n) {
    m = ins; sub(/[ \t].*$/, "", m); ops = ins; sub(/^[^ \t]+[ \t]*/, "", ops)
    sub(/\.[nw]$/, "", m)
    if (m == "bl") return 4
    if (m == "bx" || m == "blx") return 3
    if (m ~ /^b(eq|ne|cs|hs|cc|lo|mi|pl|vs|vc|hi|ls|ge|lt|gt|le)?$/) return taken ? 3 : 1
    if (m ~ /^(push|stm|stmia|ldm|ldmia)$/) return 1 + nregs(ops)
    if (m == "pop") return (ops ~ /pc/) ? 3 + nregs(ops) : 1 + nregs(ops)
    if (m ~ /^(ldr|str)/) return 2
    if (ops ~ /^pc,/) return 3
    return 1 }
FILENAME == ARGV[1] {
    if ($0 !~ /^ +[0-9a-f]+:\t/) next
    n = split($0, f, "\t"); sub(/^ +/, "", f[1]); a = hex(f[1])
    raw = f[2]; gsub(/ +$/, "", raw); size[a] = (length(raw) > 4) ? 4 : 2
    t = f[3]; for (i = 4; i <= n; i++) t = t "\t" f[i]
    sub(/[ \t]*[;@].*$/, "", t)           # comments: "@ 0x8000", "; (...)"
    sub(/ <[^>]*>$/, "", t)               # branch target names
    text[a] = t; next }
FILENAME == ARGV[2] { entry[hex($1)] = $2; next }
{
    s = $0; sub(/^[^\[]*\[[^\/]*\//, "", s); sub(/\/.*$/, "", s); pc = hex(s)
    if (inside) {
        if (pc == ret) {
            cyc += m0cyc(text[last], 1)
            taken++
            if (paths) {
                if (!((name, key) in pid)) {
                    pid[name, key] = ++npath[name]
                    printf "%s", body > (dir "/" name ".p" npath[name] ".s")
                    close(dir "/" name ".p" npath[name] ".s")
                }
                printf "%s %d %d %d %d\n", name, cnt, cyc, taken, pid[name, key]
            } else
                printf "%s %d %d %d\n", name, cnt, cyc, taken
            inside = 0
        } else {
            # the previous instruction's timing needs to know if it branched
            cyc += m0cyc(text[last], pc != last + size[last])
            taken += pc != last + size[last]
            cnt++; last = pc
            if (paths) { key = key " " pc; body = body text[pc] "\n" } else print text[pc] >> (dir "/" name ".s")
            if (pcs) printf "%x\n", pc >> (dir "/" name ".pc")
            next
        }
    }
    if (!inside && (pc in entry) && prev != "") {
        inside = 1; name = entry[pc]; ret = prev + size[prev]; cnt = 1; cyc = 0; taken = 0; last = pc
        if (paths) { key = pc; body = text[pc] "\n" } else print text[pc] >> (dir "/" name ".s")
        if (pcs) printf "%x\n", pc >> (dir "/" name ".pc")
    }
    prev = pc
}
