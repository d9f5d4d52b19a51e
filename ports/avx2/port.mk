# AVX2 + FMA port: x86 targets only; -mavx2 -mfma on its objects alone (the
# dispatcher runs them only where CPUID and XCR0 say the CPU and OS can).
# fx_avx2.o: the lane op layer of the fixed-point body (src/fx/fx_body.h) on AVX2.
ifneq ($(filter x86_64% i686% i586% i386%,$(TARGET)),)
LIB_OBJ += $(BUILD)/ports/avx2/f32_avx2.o $(BUILD)/ports/avx2/fx_avx2.o
$(BUILD)/ports/avx2/%.o: ports/avx2/%.c $(HEADERS) $(SRC_HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) $(PICFLAGS) -mavx2 -mfma -c $< -o $@
endif
