# The thread test under ThreadSanitizer: the first-use port choice and
# facet_set_port must not race (dispatch.c installs the first choice by
# compare-and-swap; test_threads also races the two in 2000 fresh processes).
. tests/lib/suite_lib.sh
dir=build/tsan
mkdir -p $dir
if $MAKE -s -j"$JOBS" BUILD=$dir CFLAGS="-O1 -g -fsanitize=thread" $dir/tests/test_threads > $dir/build.log 2>&1; then
    TSAN_OPTIONS=halt_on_error=1 run_one tsan $dir/tests/test_threads
else
    cat $dir/build.log
    echo "ERROR tsan: build failed (log: $dir/build.log)"
fi
