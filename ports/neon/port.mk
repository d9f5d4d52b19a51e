# NEON port: aarch64 (NEON is baseline there) and armv7 hard-float, where
# only these objects get -mfpu=neon-vfpv4 (the dispatcher checks HWCAP).
# fx_neon.o: the lane op layer of the fixed-point body (src/fx/fx_body.h) on
# aarch64 NEON; armv7 runs the scalar fixed-point loops (ports/neon/fx_neon.c).
# FACET_PORTS / PORT_FLAGS_neon: the port is compiled in, with these flags
# (bench/bench.mk builds the port's bench objects with the same).
ifneq ($(filter aarch64%,$(TARGET)),)
FACET_PORTS += neon
PORT_FLAGS_neon :=
LIB_OBJ += $(BUILD)/ports/neon/f32_neon.o $(BUILD)/ports/neon/fx_neon.o
endif
ifneq ($(filter arm%linux-gnueabihf,$(TARGET)),) # not arm-none-eabi (bare metal: ports/helium)
FACET_PORTS += neon
PORT_FLAGS_neon := -mfpu=neon-vfpv4 -mfloat-abi=hard
LIB_OBJ += $(BUILD)/ports/neon/f32_neon.o
endif
$(BUILD)/ports/neon/%.o: ports/neon/%.c $(HEADERS) $(SRC_HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) $(PICFLAGS) $(PORT_FLAGS_neon) -c $< -o $@
