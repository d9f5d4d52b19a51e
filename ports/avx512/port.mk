# AVX-512F port: x86-64 only; -mavx512f on its objects alone (the dispatcher
# runs them only where CPUID and XCR0 say the CPU and OS can).
# FACET_PORTS / PORT_FLAGS_avx512: the port is compiled in, with these flags.
ifneq ($(filter x86_64%,$(TARGET)),)
FACET_PORTS += avx512
PORT_FLAGS_avx512 := -mavx512f
LIB_OBJ += $(BUILD)/ports/avx512/f32_avx512.o
$(BUILD)/ports/avx512/%.o: ports/avx512/%.c $(HEADERS) $(SRC_HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) $(PICFLAGS) $(PORT_FLAGS_avx512) -c $< -o $@
endif
