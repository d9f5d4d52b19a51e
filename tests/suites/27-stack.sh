# The stack bound of every fixed-point call (facet/fx.h "Stack"): the
# firmware sources (`make fx-sources`) compiled with arm-none-eabi-gcc for
# Cortex-M0, M4 and M33 at -O2 and -Os with -fstack-usage
# -fcallgraph-info=su; tests/fx/fx_stack.awk adds each function's frame to
# its deepest chain of callees (and fails on recursion, a dynamic frame, an
# indirect call or a callee outside the sources).  Per build, the maxima
# over the precise kernels (facet_*_fx), the fast kernels (facet_*_fx_fast)
# and every batch and RGB call must be the figures fx.h states (with the
# compiler fx.h names; another gcc must stay within them), and no call may
# exceed FACET_FX_STACK_BYTES.  A self-test: a source with a recursive or a
# dynamic frame must fail the script.
pass=0 fail=0 skip=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL stack: $*"; }
have() { command -v "$1" > /dev/null 2>&1; }
dir=build/stack
mkdir -p $dir
if ! have arm-none-eabi-gcc; then
    echo "SKIP stack: arm-none-eabi-gcc not installed"
    echo "stack: 0 passed, 0 failed, 1 skipped"
    exit 0
fi
srcs=$(${MAKE:-make} -s fx-sources)
gccv=$(arm-none-eabi-gcc -dumpfullversion 2>/dev/null || arm-none-eabi-gcc -dumpversion)
want_gcc=$(sed -n 's/.*arm-none-eabi-gcc \([0-9.]*\) -mthumb on the firmware.*/\1/p' include/facet/fx.h | head -n 1)
limit=$(awk '$1 == "#define" && $2 == "FACET_FX_STACK_BYTES" { print $3 }' include/facet/fx.h)
[ -n "$want_gcc" ] && [ -n "$limit" ] && ok || bad "fx.h states no Stack compiler or FACET_FX_STACK_BYTES"
# graph DIR FLAGS...: compiles the sources into DIR with call-graph info
graph() {
    d=$1
    shift
    rm -rf "$d"
    mkdir -p "$d"
    for f in $srcs; do
        # shellcheck disable=SC2086
        arm-none-eabi-gcc "$@" -mthumb -std=c99 -Iinclude -fstack-usage -fcallgraph-info=su \
            -c "$f" -o "$d/$(basename "$f" .c).o" 2> "$d/build.log" || return 1
    done
}
for cpu in cortex-m0 cortex-m4 cortex-m33; do
    for o in -O2 -Os; do
        d=$dir/$cpu$o
        if ! graph "$d" -mcpu=$cpu $o; then bad "$cpu $o: the sources do not build ($(head -n 2 "$d/build.log"))"; continue; fi
        if ! (cd "$d" && awk -f ../../../tests/fx/fx_stack.awk ./*.ci) > "$d/depth.txt"; then
            bad "$cpu $o: $(grep BAD "$d/depth.txt" | head -n 3 | tr '\n' ' ')"
            continue
        fi
        fx=$(awk '$2 ~ /_fx$/ && $2 !~ /rgb/ { if ($1 > m) m = $1 } END { print m + 0 }' "$d/depth.txt")
        fast=$(awk '$2 ~ /_fx_fast$/ && $2 !~ /rgb/ { if ($1 > m) m = $1 } END { print m + 0 }' "$d/depth.txt")
        batch=$(awk '$1 != "max" && ($2 ~ /batch/ || $2 ~ /rgb/) { if ($1 > m) m = $1 } END { print m + 0 }' "$d/depth.txt")
        over=$(awk -v l="$limit" '$1 != "max" && $1 > l + 0 { print $2 }' "$d/depth.txt" | head -n 3)
        [ -z "$over" ] && ok || bad "$cpu $o: above FACET_FX_STACK_BYTES ($limit): $over"
        line=$(grep -E "^ \*   $cpu $o " include/facet/fx.h | head -n 1)
        sfx=$(echo "$line" | awk '{ print $4 }') sfast=$(echo "$line" | awk '{ print $5 }') sbatch=$(echo "$line" | awk '{ print $6 }')
        echo "stack $cpu $o: fx $fx, fx_fast $fast, batch/rgb $batch bytes (fx.h: $sfx $sfast $sbatch; $(grep -vc "^max" "$d/depth.txt") calls)"
        if [ -z "$line" ]; then bad "fx.h has no Stack line for $cpu $o"
        elif [ "$gccv" = "$want_gcc" ]; then
            [ "$fx $fast $batch" = "$sfx $sfast $sbatch" ] && ok ||
                bad "$cpu $o: measured fx $fx, fx_fast $fast, batch $batch; fx.h states $sfx $sfast $sbatch"
        else
            [ "$fx" -le "$sfx" ] && [ "$fast" -le "$sfast" ] && [ "$batch" -le "$sbatch" ] && ok ||
                bad "$cpu $o (gcc $gccv, fx.h's figures are gcc $want_gcc's): fx $fx, fx_fast $fast, batch $batch above $sfx $sfast $sbatch"
        fi
    done
done
# the script must refuse what it cannot bound
d=$dir/selftest
mkdir -p $d
printf 'int f(int n);\nint f(int n) { return n ? f(n - 1) + 1 : 0; }\nint facet_r(int n);\nint facet_r(int n) { return f(n); }\n' > $d/rec.c
printf 'int facet_v(int n);\nint facet_v(int n) { volatile char b[n + 1]; b[0] = 1; return b[0]; }\n' > $d/vla.c
for t in rec vla; do
    rm -f $d/*.ci
    arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -O0 -std=c99 -fstack-usage -fcallgraph-info=su -c $d/$t.c -o $d/$t.o 2> /dev/null
    if (cd $d && awk -f ../../../tests/fx/fx_stack.awk ./*.ci > /dev/null); then bad "fx_stack.awk accepts a $t frame"; else ok; fi
done
echo "stack: $pass passed, $fail failed, $skip skipped"
