# AVX-512 FP16 f16 port: x86-64 only; -mavx512fp16 (gcc 12, clang 14) on its
# one object alone: the dispatcher runs it only where CPUID says the CPU has
# AVX-512 FP16 (src/core/cpu.c), so nothing else executes an FP16 instruction.
ifneq ($(filter x86_64%,$(TARGET)),)
PORT_FLAGS_avx512fp16 := -mavx512fp16 -mavx512bw -mavx512vl -mavx512f
LIB_OBJ += $(BUILD)/ports/avx512fp16/f16_avx512fp16.o
$(BUILD)/ports/avx512fp16/%.o: ports/avx512fp16/%.c $(HEADERS) $(SRC_HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) $(PICFLAGS) $(PORT_FLAGS_avx512fp16) -c $< -o $@
endif
