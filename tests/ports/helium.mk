# helium.mk - the library's C tests as bare-metal images for qemu's
# mps3-an547 (Cortex-M55 with Helium), for a build of the library with
# arm-none-eabi-gcc (tests/suites/52-helium.sh):
#   make BUILD=build/m55 CC=arm-none-eabi-gcc AR=arm-none-eabi-ar PICFLAGS= \
#        CFLAGS="-mcpu=cortex-m55 -mfloat-abi=hard -mthumb -O2" build/m55/tests/<test>.elf
# Each image: the test, libfacet.a (helium and scalar ports, the oracle),
# newlib with semihosting (rdimon), tests/cortexm/startup_m55.c and an547.ld.
# M55_ARG: the image's argv[1] (the accuracy test's random sample count).
ifneq ($(filter arm-none-eabi%,$(TARGET)),)
M55_LINK = --specs=rdimon.specs -nostartfiles -T tests/cortexm/an547.ld tests/cortexm/startup_m55.c
$(BUILD)/tests/%.elf: %.c $(wildcard tests/lib/*.h) $(BUILD)/libfacet.a tests/cortexm/startup_m55.c tests/cortexm/an547.ld
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) -D_DEFAULT_SOURCE $(if $(M55_ARG),-DFACET_M55_ARG='"$(M55_ARG)"') -o $@ $< $(M55_LINK) $(BUILD)/libfacet.a -lm
endif
