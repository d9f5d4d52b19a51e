# MISRA C:2012 for the firmware sources (`make fx-sources`; src/fx/MISRA.md):
# Debian's cppcheck with its misra addon, once per firmware target
# (arm-none-eabi-gcc's predefined macros for Cortex-M0, M4, M33 at -Os: the
# ARMv6-M and the ARMv7-M/ARMv8-M code paths), every finding classified by
# src/fx/misra_c2012_categories.tsv (tests/misra/misra_check.sh).  Fails on
# any mandatory finding, on a required finding whose rule and file have no
# entry in MISRA.md's deviation record or whose count is not the entry's, on
# an entry that no longer occurs, and on an advisory total unlike MISRA.md's
# advisory table (with another cppcheck than the record's, counts are not
# compared).  Self-tests: a broken copy of the tree (a required violation
# added) must fail, and so must a stale entry, a mandatory finding, a
# changed count and an unclassified rule.
pass=0 fail=0 skip=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL misra: $*"; }
have() { command -v "$1" > /dev/null 2>&1; }
dir=build/misra
check=tests/misra/misra_check.sh
record=src/fx/MISRA.md
cats=src/fx/misra_c2012_categories.tsv
mkdir -p $dir
why=""
have cppcheck || why="cppcheck not installed (apt-get install cppcheck)"
[ -n "$why" ] || have python3 || why="python3 missing (cppcheck's misra addon is a Python script)"
[ -n "$why" ] || have arm-none-eabi-gcc || why="arm-none-eabi-gcc not installed (the firmware targets' predefined macros)"
if [ -z "$why" ]; then
    printf 'int probe_(void);\nint probe_(void) { return 0; }\n' > $dir/probe.c
    cppcheck -q --addon=misra --cppcheck-build-dir=$dir $dir/probe.c > $dir/probe.log 2>&1 &&
        ! grep -qi 'error\|not found\|failed' $dir/probe.log || why="cppcheck's misra addon missing ($(head -n 1 $dir/probe.log))"
fi
if [ -n "$why" ]; then
    echo "SKIP misra: $why"
    echo "misra: 0 passed, 0 failed, 1 skipped"
    exit 0
fi
version=$(cppcheck --version | awk '{ print $2 }')
cpus="cortex-m0 cortex-m4 cortex-m33"

# shellcheck disable=SC2086
if ! out=$(sh $check scan $dir/findings.txt $cpus 2>&1); then
    bad "cppcheck did not run: $out"
else
    ok
    if sh $check compare $dir/findings.txt $record $cats "$version" > $dir/verdict.txt; then ok
    else fail=$((fail + $(grep -c '^FAIL' $dir/verdict.txt))); fi
    cat $dir/verdict.txt
    awk '{ print $1 }' $dir/findings.txt | sort | uniq -c | sort -k2,2V |
        awk '{ printf "%s %s:%s", (NR == 1 ? "misra findings per rule:" : ","), $2, $1 } END { print "" }'

    # self-tests of the verdict (each must fail, for its own reason)
    # expect_fail LABEL PATTERN FINDINGS RECORD CATEGORIES
    expect_fail() {
        if sh $check compare "$3" "$4" "$5" "$version" > $dir/self.txt; then
            bad "self-test $1: the verdict passes"
        elif grep -q "$2" $dir/self.txt; then ok
        else bad "self-test $1: fails, but not with '$2' ($(head -n 1 $dir/self.txt))"; fi
    }
    { cat $record; echo "| D99 | 17.7 | required | src/fx/fx_rgb.c | 1 | self-test |"; } > $dir/stale.md
    expect_fail stale "record entry 17.7 src/fx/fx_rgb.c no longer occurs" $dir/findings.txt $dir/stale.md $cats
    { cat $dir/findings.txt; echo "9.1 src/fx/fx_rgb.c 1 1"; } > $dir/mandatory.txt
    expect_fail mandatory "mandatory rule 9.1" $dir/mandatory.txt $record $cats
    grep -v "^12.2 " $dir/findings.txt > $dir/count.txt
    grep "^12.2 " $dir/findings.txt | tail -n +2 >> $dir/count.txt
    expect_fail count "required rule 12.2 in .* the record states" $dir/count.txt $record $cats
    grep -v "^12\.3	" $cats > $dir/cats.tsv
    expect_fail unclassified "rule 12.3 .* not in the category table" $dir/findings.txt $record $dir/cats.tsv

    # a broken copy of the tree: the braces of facet_fx_isqrt64_rem's last
    # if dropped (required rule 15.6), that file scanned for Cortex-M4 alone
    rm -rf $dir/broken
    mkdir -p $dir/broken
    cp -R src include $dir/broken/
    awk '/^    if \(s != 0\) \{$/ { print "    if (s != 0)"; getline; print; getline; next } { print }' \
        src/fx/fx_prims.c > $dir/broken/src/fx/fx_prims.c
    if cmp -s src/fx/fx_prims.c $dir/broken/src/fx/fx_prims.c; then
        bad "self-test broken copy: src/fx/fx_prims.c no longer has 'if (s != 0) {' (update the test)"
    else
        if (cd $dir/broken && FACET_FX_SOURCES=src/fx/fx_prims.c sh ../../../$check scan findings.txt cortex-m4) > $dir/broken.log 2>&1; then
            expect_fail "broken copy" "required rule 15.6: 1 findings in src/fx/fx_prims.c not in the record" \
                $dir/broken/findings.txt $record $cats
        else
            bad "self-test broken copy: cppcheck did not run ($(head -n 2 $dir/broken.log))"
        fi
    fi
fi
echo "misra: $pass passed, $fail failed, $skip skipped"
