# tails.mk - tests/f32/test_tails.c once more per x86 port that needs ISA flags,
# and tests/f32/test_scalar_inline.c for -march=x86-64-v3
# (the plain build tests the target's baseline port: sse2 on x86-64, neon
# on aarch64); each skips where the CPU cannot run it.
ifneq ($(filter x86_64%,$(TARGET)),)
TEST_BIN += $(BUILD)/tests/test_tails_avx2 $(BUILD)/tests/test_tails_avx512
$(BUILD)/tests/test_tails_avx2: tests/f32/test_tails.c tests/lib/harness.h $(HEADERS) $(BUILD)/libfacet.a
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) -mavx2 -mfma -DTAILS_AVX2 -o $@ $< $(BUILD)/libfacet.a -lm
# facet/scalar.h inline under -march=x86-64-v3 (tests/f32/test_scalar_inline.c;
# the plain build is its portable-ops case)
TEST_BIN += $(BUILD)/tests/test_scalar_inline_v3
$(BUILD)/tests/test_scalar_inline_v3: tests/f32/test_scalar_inline.c $(wildcard tests/lib/*.h) $(HEADERS) $(BUILD)/libfacet.a
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) -D_DEFAULT_SOURCE -march=x86-64-v3 -DSCALAR_INLINE_V3 -o $@ $< $(BUILD)/libfacet.a -lm
$(BUILD)/tests/test_tails_avx512: tests/f32/test_tails.c tests/lib/harness.h $(HEADERS) $(BUILD)/libfacet.a
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) -mavx512f -mavx2 -mfma -DTAILS_AVX512 -o $@ $< $(BUILD)/libfacet.a -lm
endif
