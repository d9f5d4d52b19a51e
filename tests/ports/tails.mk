# tails.mk - tests/f32/test_tails.c once more per x86 port that needs ISA flags
# (the plain build tests the target's baseline port: sse2 on x86-64, neon
# on aarch64); each skips where the CPU cannot run it.
ifneq ($(filter x86_64%,$(TARGET)),)
TEST_BIN += $(BUILD)/tests/test_tails_avx2 $(BUILD)/tests/test_tails_avx512
$(BUILD)/tests/test_tails_avx2: tests/f32/test_tails.c tests/lib/harness.h $(HEADERS) $(BUILD)/libfacet.a
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) -mavx2 -mfma -DTAILS_AVX2 -o $@ $< $(BUILD)/libfacet.a -lm
$(BUILD)/tests/test_tails_avx512: tests/f32/test_tails.c tests/lib/harness.h $(HEADERS) $(BUILD)/libfacet.a
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) -mavx512f -mavx2 -mfma -DTAILS_AVX512 -o $@ $< $(BUILD)/libfacet.a -lm
endif
