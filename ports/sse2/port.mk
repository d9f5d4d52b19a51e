# SSE2 port: x86 targets only; -msse2 on its objects alone.
ifneq ($(filter x86_64% i686% i586% i386%,$(TARGET)),)
LIB_OBJ += $(BUILD)/ports/sse2/f32_sse2.o
$(BUILD)/ports/sse2/%.o: ports/sse2/%.c $(HEADERS) $(SRC_HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) $(PICFLAGS) -msse2 -c $< -o $@
endif
