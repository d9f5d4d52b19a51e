# The AVX2 and AVX-512 ports (batches and per-sample entries, facet/scalar.h on x86 with
# FMA) with their rcp/rsqrt estimates replaced by values off by the
# architectural error bound (1.5 * 2^-12, 2^-14): the Newton steps must keep every
# kernel inside its bound whatever a vendor's tables return.  And the
# binary16 port avx512fp16 with its unrefined vrcpph / vrsqrtph replaced by
# the binary16 value farthest from the exact result within their bound
# (2^-11 + 2^-14, Intel SDM) and its f32-lane estimates off by 2^-14, every
# f16 kernel within facet/f16.h's bounds (test_f16_accuracy, 400000 samples
# a kernel); on a CPU without AVX-512 FP16 that part is skipped and says so.
. tests/lib/suite_lib.sh
case "$(${CC:-cc} -dumpmachine)" in
x86_64*|i?86*)
    dir=build/worst-est
    mkdir -p $dir
    if $MAKE -s -j"$JOBS" BUILD=$dir CFLAGS="-O2 -g -DFACET_AVX2_TEST_WORST_ESTIMATES -DFACET_AVX512_TEST_WORST_ESTIMATES -DFACET_SCALAR_TEST_WORST_ESTIMATES -DFACET_AVX512FP16_TEST_WORST_ESTIMATES" \
        $dir/tests/test_f32_accuracy $dir/tests/test_sample_accuracy $dir/tests/test_f16_accuracy > $dir/build.log 2>&1; then
        FACET_TEST_QUICK=1 run_one worst-estimates $dir/tests/test_f32_accuracy
        FACET_TEST_QUICK=1 run_one worst-estimates $dir/tests/test_sample_accuracy
        # avx512fp16: only where this CPU runs it (the test names the refusal)
        out=$($dir/tests/test_f16_accuracy 1 2>&1)
        if printf '%s\n' "$out" | grep -q '^[a-z_]* *avx512fp16  *not run: '; then
            echo "SKIP worst-estimates-f16: avx512fp16 not run here: $(printf '%s\n' "$out" | sed -n 's/^[a-z_]* *avx512fp16  *not run: //p' | head -n 1)"
            echo "worst-estimates-f16: 0 passed, 0 failed, 1 skipped"
        else
            run_one worst-estimates-f16 $dir/tests/test_f16_accuracy 400000
        fi
    else
        cat $dir/build.log; echo "ERROR worst-estimates: build failed"
    fi ;;
*)
    echo "SKIP worst-estimates: not an x86 target"
    echo "worst-estimates: 0 passed, 0 failed, 1 skipped" ;;
esac
