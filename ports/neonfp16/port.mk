# ARMv8.2-A FP16 NEON f16 port: aarch64 only; -march=armv8.2-a+fp16 on its
# one object alone (the dispatcher runs it only where HWCAP says the CPU has
# FP16 arithmetic, src/core/cpu.c).
ifneq ($(filter aarch64%,$(TARGET)),)
LIB_OBJ += $(BUILD)/ports/neonfp16/f16_neonfp16.o
$(BUILD)/ports/neonfp16/%.o: ports/neonfp16/%.c $(HEADERS) $(SRC_HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) $(PICFLAGS) -march=armv8.2-a+fp16 -c $< -o $@
endif
