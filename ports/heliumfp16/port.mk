# Helium MVE binary16 f16 port (Cortex-M55, M85): built where the helium
# port is (ports/helium/port.mk: an arm-none-eabi target whose CFLAGS give
# MVE with floating point, which has binary16 lanes), with the same
# compiler choice HELIUM_CC (gcc 12 or clang 14) and no flags of its own:
# the -mcpu of CFLAGS is the ISA.  The dispatcher runs it where MVFR1 says
# the core has MVE-F (src/core/cpu.c).
ifneq ($(filter arm-none-eabi%,$(TARGET)),)
ifneq ($(HELIUM_MVE_FP),0)
LIB_OBJ += $(BUILD)/ports/heliumfp16/f16_heliumfp16.o
$(BUILD)/ports/heliumfp16/%.o: ports/heliumfp16/%.c $(HEADERS) $(SRC_HDRS)
	@mkdir -p $(dir $@)
	$(HELIUM_CC) $(HELIUM_CCFLAGS) $(BASEFLAGS) -c $< -o $@
endif
endif
