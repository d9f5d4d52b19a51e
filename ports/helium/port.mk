# Helium port (Armv8.1-M MVE with floating point: Cortex-M55, M85): built
# into the library where the compiler targets it (bare-metal arm-none-eabi
# with e.g. CFLAGS="-mcpu=cortex-m55 -mfloat-abi=hard -mthumb"; the
# dispatcher asks MVFR1 at run time, src/core/cpu.c).  tests/ports/helium.mk links the
# test images; tests/suites/52-helium.sh runs them on qemu's mps3-an547.
# HELIUM_CC: the compiler of the port objects alone (these two and
# ports/heliumfp16/f16_heliumfp16.o; default $(CC));
# HELIUM_CC=clang builds them with clang 14 for the same core
# (--target=arm-none-eabi, newlib's headers, gcc's short enums), which
# spills far fewer Q registers than gcc 12 (README "Helium").
ifneq ($(filter arm-none-eabi%,$(TARGET)),)
HELIUM_MVE_FP := $(shell $(CC) $(CFLAGS) -dM -E - < /dev/null 2>/dev/null | grep -c '__ARM_FEATURE_MVE [23]')
ifneq ($(HELIUM_MVE_FP),0)
FACET_PORTS += helium
HELIUM_CC ?= $(CC)
HELIUM_CCFLAGS := $(if $(filter clang%,$(notdir $(HELIUM_CC))),--target=arm-none-eabi -fshort-enums \
                  -isystem $(dir $(shell $(CC) -print-file-name=libc.a))../include)
LIB_OBJ += $(BUILD)/ports/helium/f32_helium.o $(BUILD)/ports/helium/fx_helium.o
$(BUILD)/ports/helium/%.o: ports/helium/%.c $(HEADERS) $(SRC_HDRS)
	@mkdir -p $(dir $@)
	$(HELIUM_CC) $(HELIUM_CCFLAGS) $(BASEFLAGS) -c $< -o $@
endif
endif
