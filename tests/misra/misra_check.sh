#!/bin/sh
# misra_check.sh - MISRA C:2012 findings of the firmware sources (cppcheck's
# misra addon) against the deviation record (src/fx/MISRA.md).
#
#   misra_check.sh scan OUT CPU...   run from a tree's top: cppcheck --addon=misra
#       on `make fx-sources` (or $FACET_FX_SOURCES) once per firmware target (arm-none-eabi-gcc's
#       predefined macros for -mcpu=CPU -mthumb -Os, forced in as a header;
#       include/ on the include path; the arm32 platform), every finding in
#       src/ or include/ once (the union over the targets) into OUT as
#       "rule file line column" lines
#   misra_check.sh compare FINDINGS RECORD CATEGORIES [VERSION]
#       the verdict: a "FAIL misra: ..." line per defect, exit 1 if any.
#       Defects: a rule CATEGORIES does not classify; any mandatory finding
#       (MISRA Compliance: no deviation permitted); a required finding whose
#       rule and file have no record entry, or whose count differs from the
#       entry's; an entry that no longer occurs, or whose category is not
#       the table's; an advisory rule whose total differs from the record's
#       advisory table (or has no row, or a row that no longer occurs).
#       With VERSION (the cppcheck found) unlike the record's, counts are
#       not compared (another cppcheck counts differently), coverage is.
set -u
cmd=${1:-}
case $cmd in
scan)
    out=$2
    shift 2
    tmp=$out.d
    rm -rf "$tmp"
    mkdir -p "$tmp"
    # the list of a copy of the tree (the suite's self-test) may be given
    srcs=${FACET_FX_SOURCES:-$(${MAKE:-make} -s fx-sources)} || exit 2
    # the targets side by side (one cppcheck process each), then wait for all
    pids=""
    for cpu in "$@"; do
        arm-none-eabi-gcc -mcpu="$cpu" -mthumb -Os -dM -E -xc /dev/null > "$tmp/$cpu.h" || exit 2
        # -D__arm__: one configuration (the target's), not every #if combination
        # shellcheck disable=SC2086
        # each its own build directory: the addon reads cppcheck's dump files
        # from there (not beside the sources, where runs would collide)
        mkdir -p "$tmp/$cpu.build"
        { cppcheck -q --addon=misra --std=c99 --platform=arm32-wchar_t4 --include="$tmp/$cpu.h" \
            --cppcheck-build-dir="$tmp/$cpu.build" \
            -D__arm__=1 -Iinclude --template='{file}:{line}:{column}:{id}' $srcs \
            > "$tmp/$cpu.log" 2> "$tmp/$cpu.err" || echo "cppcheck exited with status $? ($cpu)" >> "$tmp/$cpu.err"; } &
        pids="$pids $!"
    done
    for p in $pids; do wait "$p"; done
    cat "$tmp"/*.err | awk -F: '$4 ~ /^misra-c2012-/ && $1 ~ /^(src|include)\// {
        sub(/^misra-c2012-/, "", $4); print $4, $1, $2, $3 }' | sort -u > "$out"
    # anything else cppcheck said (a syntax error, a missing addon) is a defect
    cat "$tmp"/*.err | grep -v ':misra-c2012-' | grep -v '^\s*$' | head -n 5 > "$tmp/other"
    if [ -s "$tmp/other" ]; then
        sed 's/^/cppcheck: /' "$tmp/other"
        exit 2
    fi
    ;;
compare)
    awk -v want_version="${5:-}" '
    FNR == 1 { fileno++ }
    fileno == 1 { n[$1 SUBSEP $2]++; total[$1]++; next }          # findings
    fileno == 2 {                                                  # the record
        if ($0 ~ /<!-- misra: cppcheck [0-9.]+ -->/) { v = $0; sub(/.*cppcheck /, "", v); sub(/ .*/, "", v); version = v }
        if ($0 !~ /^\|/) next
        split($0, f, "|")
        for (i in f) gsub(/^ +| +$/, "", f[i])
        if (f[2] ~ /^D[0-9]+$/) { rec[f[3] SUBSEP f[5]] = f[6]; reccat[f[3] SUBSEP f[5]] = f[4]; entries++ }
        else if (f[3] == "advisory" && f[2] ~ /^[0-9]+\.[0-9]+$/) adv[f[2]] = f[4]
        next
    }
    /^#/ { next }                                                  # categories
    { split($0, c, "\t"); cat[c[1]] = c[2] }
    END {
        counts = (want_version == "" || want_version == version)
        if (version == "") bad("the record states no cppcheck version (<!-- misra: cppcheck X -->)")
        if (entries == 0) bad("the record has no deviation entry")
        for (k in n) {
            split(k, p, SUBSEP); r = p[1]; file = p[2]
            if (!(r in cat)) { bad("rule " r " (" file ", " n[k] " findings) is not in the category table"); continue }
            if (cat[r] == "mandatory") { bad("mandatory rule " r ": " n[k] " findings in " file " (no deviation is permitted)"); continue }
            if (cat[r] != "required") continue
            req += n[k]
            if (!(k in rec)) bad("required rule " r ": " n[k] " findings in " file " not in the record")
            else if (counts && rec[k] != n[k]) bad("required rule " r " in " file ": " n[k] " findings, the record states " rec[k])
        }
        for (k in rec) {
            split(k, p, SUBSEP); r = p[1]
            if (!(k in n)) bad("record entry " r " " p[2] " no longer occurs (remove it)")
            if (reccat[k] != cat[r]) bad("record entry " r " " p[2] " says " reccat[k] ", the table " (r in cat ? cat[r] : "has no such rule"))
            if (cat[r] == "mandatory") bad("record entry " r " " p[2] ": a mandatory rule cannot be deviated")
        }
        for (r in total) if (cat[r] == "advisory") {
            advn += total[r]
            if (!(r in adv)) bad("advisory rule " r ": " total[r] " findings, no row in the record")
            else if (counts && adv[r] != total[r]) bad("advisory rule " r ": " total[r] " findings, the record states " adv[r])
        }
        for (r in adv) if (!(r in total)) bad("advisory row " r " no longer occurs (remove it)")
        printf "misra: %d required findings under %d record entries, %d advisory", req, entries, advn
        if (!counts) printf " (cppcheck %s, the record %s: counts not compared)", want_version, version
        printf "\n"
        exit failed > 0
    }
    function bad(s) { print "FAIL misra: " s; failed++ }
    ' "$2" "$3" "$4"
    ;;
*)
    echo "usage: misra_check.sh scan OUT CPU... | compare FINDINGS RECORD CATEGORIES [VERSION]" >&2
    exit 2
    ;;
esac
