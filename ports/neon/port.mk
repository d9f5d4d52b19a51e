# NEON port: aarch64 (NEON is baseline there) and armv7 hard-float, where
# only these objects get -mfpu=neon-vfpv4 (the dispatcher checks HWCAP).
ifneq ($(filter aarch64%,$(TARGET)),)
LIB_OBJ += $(BUILD)/ports/neon/f32_neon.o
NEON_FLAGS :=
endif
ifneq ($(filter arm%,$(TARGET)),)
LIB_OBJ += $(BUILD)/ports/neon/f32_neon.o
NEON_FLAGS := -mfpu=neon-vfpv4 -mfloat-abi=hard
endif
$(BUILD)/ports/neon/%.o: ports/neon/%.c $(HEADERS) src/port.h src/batch_body.h
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) $(PICFLAGS) $(NEON_FLAGS) -c $< -o $@
