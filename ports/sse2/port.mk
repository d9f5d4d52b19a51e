# SSE2 port: x86 targets only; -msse2 on its objects alone.
# FACET_PORTS / PORT_FLAGS_sse2: the port is compiled in, with these flags
# (bench/bench.mk builds the port's bench objects with the same).
ifneq ($(filter x86_64% i686% i586% i386%,$(TARGET)),)
FACET_PORTS += sse2
PORT_FLAGS_sse2 := -msse2
LIB_OBJ += $(BUILD)/ports/sse2/f32_sse2.o
$(BUILD)/ports/sse2/%.o: ports/sse2/%.c $(HEADERS) $(SRC_HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) $(PICFLAGS) $(PORT_FLAGS_sse2) -c $< -o $@
endif
