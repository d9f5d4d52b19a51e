# NEON port: aarch64 (NEON is baseline there) and armv7 hard-float, where
# only these objects get -mfpu=neon-vfpv4 (the dispatcher checks HWCAP).
# fx_neon.o: the fixed-point kernels on NEON integer lanes (src/fx_vbody.h).
ifneq ($(filter aarch64%,$(TARGET)),)
LIB_OBJ += $(BUILD)/ports/neon/f32_neon.o $(BUILD)/ports/neon/fx_neon.o
NEON_FLAGS :=
endif
ifneq ($(filter arm%,$(TARGET)),)
LIB_OBJ += $(BUILD)/ports/neon/f32_neon.o $(BUILD)/ports/neon/fx_neon.o
NEON_FLAGS := -mfpu=neon-vfpv4 -mfloat-abi=hard
endif
$(BUILD)/ports/neon/%.o: ports/neon/%.c $(HEADERS) src/port.h src/batch_body.h src/fx_port.h src/fx_vbody.h
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) $(PICFLAGS) $(NEON_FLAGS) -c $< -o $@
