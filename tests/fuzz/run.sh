#!/bin/sh
# run.sh DIR SECONDS TARGET... - runs each libFuzzer target DIR/TARGET for
# SECONDS from its committed seed corpus tests/fuzz/corpus/TARGET/ (new
# inputs go to DIR/corpus/TARGET/, so the tree stays clean); a crash,
# sanitizer report, broken contract (FUZZ FINDING), timeout or OOM fails,
# with the reproducer in DIR/artifacts/.  Ends with the summary line
# "fuzz: N passed, N failed, N skipped".
dir=$1 secs=$2
shift 2
pass=0 fail=0
mkdir -p "$dir/artifacts"
for t in "$@"; do
    if [ ! -x "$dir/$t" ]; then
        echo "FAIL fuzz: $dir/$t not built"; fail=$((fail + 1)); continue
    fi
    mkdir -p "$dir/corpus/$t"
    log="$dir/$t.log"
    "$dir/$t" -max_total_time="$secs" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$dir/artifacts/$t-" "$dir/corpus/$t" "tests/fuzz/corpus/$t" > "$log" 2>&1
    rc=$?
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
    if [ $rc -eq 0 ]; then
        pass=$((pass + 1))
        echo "fuzz $t: ${runs:-?} runs in ${secs} s, no finding"
    else
        fail=$((fail + 1))
        grep -E 'FUZZ FINDING|ERROR: (Address|Undefined|libFuzzer)|runtime error|SUMMARY' "$log" | head -n 5
        echo "FAIL fuzz: $t exited with status $rc; reproducer: $(ls -t "$dir/artifacts/$t-"* 2>/dev/null | head -n 1) (log: $log)"
    fi
done
echo "fuzz: $pass passed, $fail failed, 0 skipped"
[ $fail -eq 0 ]
