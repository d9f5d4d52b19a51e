# NEON port: aarch64 (NEON is baseline there) and armv7 hard-float, where
# only these objects get -mfpu=neon-vfpv4 (the dispatcher checks HWCAP).
# fx_neon.o: the lane op layer of the fixed-point body (src/fx/fx_body.h) on
# aarch64 NEON; armv7 runs the scalar fixed-point loops (ports/neon/fx_neon.c).
ifneq ($(filter aarch64%,$(TARGET)),)
LIB_OBJ += $(BUILD)/ports/neon/f32_neon.o $(BUILD)/ports/neon/fx_neon.o
NEON_FLAGS :=
endif
ifneq ($(filter arm%linux-gnueabihf,$(TARGET)),) # not arm-none-eabi (bare metal: ports/helium)
LIB_OBJ += $(BUILD)/ports/neon/f32_neon.o
NEON_FLAGS := -mfpu=neon-vfpv4 -mfloat-abi=hard
endif
$(BUILD)/ports/neon/%.o: ports/neon/%.c $(HEADERS) $(SRC_HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) $(PICFLAGS) $(NEON_FLAGS) -c $< -o $@
