# The AVX2 and AVX-512 ports (batches and per-sample entries, facet/scalar.h on x86 with
# FMA) with their rcp/rsqrt estimates replaced by values off by the
# architectural error bound (1.5 * 2^-12, 2^-14): the Newton steps must keep every
# kernel inside its bound whatever a vendor's tables return.  Likewise the
# avx512fp16 f16 port (where the CPU has AVX-512 FP16): its unrefined
# vrcpph / vrsqrtph replaced by the binary16 neighbour farthest from the
# exact value within 2^-11 + 2^-14, its f32 estimates off by 2^-14.
. tests/lib/suite_lib.sh
case "$(${CC:-cc} -dumpmachine)" in
x86_64*|i?86*)
    dir=build/worst-est
    mkdir -p $dir
    if $MAKE -s -j"$JOBS" BUILD=$dir CFLAGS="-O2 -g -DFACET_AVX2_TEST_WORST_ESTIMATES -DFACET_AVX512_TEST_WORST_ESTIMATES -DFACET_SCALAR_TEST_WORST_ESTIMATES -DFACET_AVX512FP16_TEST_WORST_ESTIMATES" \
        $dir/tests/test_f32_accuracy $dir/tests/test_sample_accuracy $dir/tests/test_f16_accuracy > $dir/build.log 2>&1; then
        FACET_TEST_QUICK=1 run_one worst-estimates $dir/tests/test_f32_accuracy
        FACET_TEST_QUICK=1 run_one worst-estimates $dir/tests/test_sample_accuracy
        FACET_TEST_QUICK=1 run_one worst-estimates $dir/tests/test_f16_accuracy
    else
        cat $dir/build.log; echo "ERROR worst-estimates: build failed"
    fi ;;
*)
    echo "SKIP worst-estimates: not an x86 target"
    echo "worst-estimates: 0 passed, 0 failed, 1 skipped" ;;
esac
