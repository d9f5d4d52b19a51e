# fx.mk - cross and bare-metal builds of the fixed-point kernels (included
# by the Makefile; driven by tests/suites/50-fx-targets.sh).  Every build
# compiles only the Makefile's FX_SOURCES (`make fx-sources`: the kernels,
# their batch API on the scalar loop, the table), so nothing else of the
# library has to port, and the firmware list is what these targets test.
#   $(BUILD)/fx/<target>/test_fx_hash[.elf]   the pinned-hash test per target
#   $(BUILD)/fx/<cpu>/fx_kernels.o, fx_fast.o Cortex-M objects for the size table
#   $(BUILD)/fx/rv32/fx.elf                   freestanding RV32IMC link check
#   $(BUILD)/fx/cortex-m<0|4>/fw*.elf         firmware images (tests/cortexm/fw_main.c):
#       -Os, --gc-sections, newlib, exactly as src/fx/README.md's "Firmware builds"
#       fw.elf       facet_brdf_hammon_fx_batch     fw_fast.elf  the _fx_fast_batch
#       fw_base.elf  the same image, no facet call (the size baseline)
#       fw_oracle.elf  also calls the oracle: the symbol check must flag it
FX_KSRC   := $(filter-out src/fx/fx_table.c,$(FX_SOURCES)) # the Makefile's firmware list
FX_TSRC   := $(FX_KSRC) src/fx/fx_table.c
FX_HDRS   := include/facet/fx.h $(wildcard src/fx/*.h) src/core/port.h src/core/kernel_list.h src/core/kernels.def \
             tests/lib/harness.h tests/lib/fx_hash.h
FX_CFLAGS := $(WARN) -Iinclude -O2
FX_CM_CC  ?= arm-none-eabi-gcc
FX_RV_CC  ?= riscv64-linux-gnu-gcc
FX_A64_CC ?= aarch64-linux-gnu-gcc
FX_A32_CC ?= arm-linux-gnueabihf-gcc
FX_CM_FLAGS = -mthumb -ffunction-sections -fdata-sections
FX_CM_LINK  = --specs=rdimon.specs -nostartfiles -T tests/cortexm/mps2.ld tests/cortexm/startup.c

.PHONY: fx-cortex-m fx-rv32 fx-linux-cross fx-portable fx-host-syms
fx-cortex-m: $(BUILD)/fx/cortex-m0/test_fx_hash.elf $(BUILD)/fx/cortex-m4/test_fx_hash.elf \
             $(foreach c,0 4,$(foreach f,fw fw_fast fw_base fw_oracle,$(BUILD)/fx/cortex-m$c/$f.elf)) \
             $(BUILD)/fx/cortex-m0/fx_kernels.o $(BUILD)/fx/cortex-m4/fx_kernels.o \
             $(BUILD)/fx/cortex-m0/fx_prims.o $(BUILD)/fx/cortex-m4/fx_prims.o \
             $(BUILD)/fx/cortex-m0/fx_fast.o $(BUILD)/fx/cortex-m4/fx_fast.o
fx-rv32: $(BUILD)/fx/rv32/fx.elf
fx-linux-cross: $(BUILD)/fx/aarch64/test_fx_hash $(BUILD)/fx/armv7/test_fx_hash \
                $(BUILD)/fx/aarch64/integer-only.stamp
fx-portable: $(BUILD)/fx/portable/test_fx_hash

$(BUILD)/fx/cortex-m%/test_fx_hash.elf: tests/fx/test_fx_hash.c $(FX_TSRC) $(FX_HDRS) tests/cortexm/startup.c tests/cortexm/mps2.ld
	@mkdir -p $(dir $@)
	$(FX_CM_CC) -mcpu=cortex-m$* $(FX_CM_FLAGS) $(FX_CFLAGS) $(FX_CM_LINK) $(FX_TSRC) $< -o $@

# firmware images: the README's flags, --gc-sections, newlib (semihosting
# exit through tests/cortexm/startup.c, so qemu can run them)
FX_FW_FLAGS = -mthumb -Os -ffunction-sections -fdata-sections $(WARN) -Iinclude $(FX_CM_LINK) -Wl,--gc-sections
FX_FW_DEPS  = tests/cortexm/fw_main.c $(FX_SOURCES) $(FX_HDRS) tests/cortexm/startup.c tests/cortexm/mps2.ld
$(BUILD)/fx/cortex-m%/fw.elf: $(FX_FW_DEPS)
	@mkdir -p $(dir $@)
	$(FX_CM_CC) -mcpu=cortex-m$* $(FX_FW_FLAGS) -DFW_TIER=1 tests/cortexm/fw_main.c $(FX_SOURCES) -o $@
$(BUILD)/fx/cortex-m%/fw_fast.elf: $(FX_FW_DEPS)
	@mkdir -p $(dir $@)
	$(FX_CM_CC) -mcpu=cortex-m$* $(FX_FW_FLAGS) -DFW_TIER=2 tests/cortexm/fw_main.c $(FX_SOURCES) -o $@
$(BUILD)/fx/cortex-m%/fw_base.elf: $(FX_FW_DEPS)
	@mkdir -p $(dir $@)
	$(FX_CM_CC) -mcpu=cortex-m$* $(FX_FW_FLAGS) -DFW_TIER=0 tests/cortexm/fw_main.c $(FX_SOURCES) -o $@
$(BUILD)/fx/cortex-m%/fw_oracle.elf: $(FX_FW_DEPS) src/oracle/oracle.c
	@mkdir -p $(dir $@)
	$(FX_CM_CC) -mcpu=cortex-m$* $(FX_FW_FLAGS) -DFW_TIER=9 tests/cortexm/fw_main.c $(FX_SOURCES) src/oracle/oracle.c -o $@ -lm

# every library source's global symbols ("src/x.c name"), compiled for the
# host at -O0 for the names alone: what the firmware check forbids outside
# the fixed-point sources (50-fx-targets.sh)
fx-host-syms: $(BUILD)/fx/host-syms.txt
$(BUILD)/fx/host-syms.txt: $(LIB_SRC) $(HEADERS) $(SRC_HDRS)
	@mkdir -p $(BUILD)/fx/host-syms
	for f in $(LIB_SRC); do $(CC) $(BASEFLAGS) -O0 -g0 -c $$f -o $(BUILD)/fx/host-syms/x.o && \
	    nm -g --defined-only $(BUILD)/fx/host-syms/x.o | awk -v f=$$f 'NF == 3 { print f, $$3 }' || exit 1; done > $@.tmp
	mv $@.tmp $@

# -Os objects: the size table (README) and the no-helper-call check
$(BUILD)/fx/cortex-m%/fx_kernels.o: src/fx/fx_kernels.c $(FX_HDRS)
	@mkdir -p $(dir $@)
	$(FX_CM_CC) -mcpu=cortex-m$* $(FX_CM_FLAGS) $(WARN) -Iinclude -Os -c $< -o $@
$(BUILD)/fx/cortex-m%/fx_prims.o: src/fx/fx_prims.c $(FX_HDRS)
	@mkdir -p $(dir $@)
	$(FX_CM_CC) -mcpu=cortex-m$* $(FX_CM_FLAGS) $(WARN) -Iinclude -Os -c $< -o $@
$(BUILD)/fx/cortex-m%/fx_fast.o: src/fx/fx_fast.c $(FX_HDRS)
	@mkdir -p $(dir $@)
	$(FX_CM_CC) -mcpu=cortex-m$* $(FX_CM_FLAGS) $(WARN) -Iinclude -Os -c $< -o $@

# RV32IMC, freestanding, no libc, no libgcc: the link fails on any
# undefined symbol (a float, division or clz helper call would be one)
# (all of `make fx-sources`, the kernel table too)
$(BUILD)/fx/rv32/fx.elf: $(FX_SOURCES) $(FX_HDRS)
	@mkdir -p $(dir $@)
	$(FX_RV_CC) -march=rv32imc -mabi=ilp32 -ffreestanding -nostdlib $(FX_CFLAGS) \
	    -Wl,-e,facet_brdf_hammon_fx -Wl,--no-gc-sections $(FX_SOURCES) -o $@

$(BUILD)/fx/aarch64/test_fx_hash: tests/fx/test_fx_hash.c $(FX_TSRC) $(FX_HDRS)
	@mkdir -p $(dir $@)
	$(FX_A64_CC) $(FX_CFLAGS) $(FX_TSRC) $< -o $@
$(BUILD)/fx/armv7/test_fx_hash: tests/fx/test_fx_hash.c $(FX_TSRC) $(FX_HDRS)
	@mkdir -p $(dir $@)
	$(FX_A32_CC) $(FX_CFLAGS) $(FX_TSRC) $< -o $@
# integer only, enforced: with -mgeneral-regs-only any float or SIMD
# register use in the kernels is a compile error
$(BUILD)/fx/aarch64/integer-only.stamp: $(FX_TSRC) $(FX_HDRS)
	@mkdir -p $(dir $@)
	for f in $(FX_TSRC); do $(FX_A64_CC) $(FX_CFLAGS) -mgeneral-regs-only -c $$f -o $(dir $@)/gro.o || exit 1; done
	touch $@

# the host with the ARMv6-M code paths (16x16 partial products, portable clz)
$(BUILD)/fx/portable/test_fx_hash: tests/fx/test_fx_hash.c $(FX_TSRC) $(FX_HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(FX_CFLAGS) -DFACET_FX_PORTABLE $(FX_TSRC) $< -o $@
