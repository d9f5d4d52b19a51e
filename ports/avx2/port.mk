# AVX2 + FMA port: x86 targets only; -mavx2 -mfma on its objects alone (the
# dispatcher runs them only where CPUID and XCR0 say the CPU and OS can).
# fx_avx2.o: the lane op layer of the fixed-point body (src/fx/fx_body.h) on AVX2.
# FACET_PORTS / PORT_FLAGS_avx2: the port is compiled in, with these flags
# (bench/bench.mk builds the port's bench objects with the same).
ifneq ($(filter x86_64% i686% i586% i386%,$(TARGET)),)
FACET_PORTS += avx2
PORT_FLAGS_avx2 := -mavx2 -mfma
LIB_OBJ += $(BUILD)/ports/avx2/f32_avx2.o $(BUILD)/ports/avx2/fx_avx2.o
$(BUILD)/ports/avx2/%.o: ports/avx2/%.c $(HEADERS) $(SRC_HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) $(PICFLAGS) $(PORT_FLAGS_avx2) -c $< -o $@
endif
