# RISC-V Vector binary16 f16 port (RVV 1.0 with Zvfh): built where the rvv
# port is (ports/rvv/port.mk: a riscv64 target whose RVV_CC compiles
# <riscv_vector.h>) and RVV_CC also takes the binary16 vector intrinsics:
# clang 14 has no `zvfh` and gates them on `zfh` (-march=rv64gcv_zfh; the
# objects use no scalar Zfh arithmetic, which Zvfh does not imply: suite 54
# checks).  FACET_PORT_RVVFP16 tells src/core/platform.h (FACET_ON_RVVFP16),
# so the rvv line of src/core/ports.def names the rvvfp16 table only here.
# The dispatcher runs it where AT_HWCAP has V and riscv_hwprobe reports
# Zvfh (src/core/cpu.c).
ifneq ($(filter riscv64%,$(TARGET)),)
ifeq ($(RVV_OK),1)
RVVFP16_CCFLAGS := --target=riscv64-linux-gnu -march=rv64gcv_zfh
RVVFP16_OK := $(shell printf '\043include <riscv_vector.h>\nvfloat16m1_t f(vfloat16m1_t a);\nvfloat16m1_t f(vfloat16m1_t a) { return vfadd_vv_f16m1(a, a, 1); }\n' | \
                $(RVV_CC) $(RVVFP16_CCFLAGS) -x c -fsyntax-only - 2>/dev/null && echo 1)
ifeq ($(RVVFP16_OK),1)
BASEFLAGS += -DFACET_PORT_RVVFP16=1
LIB_OBJ += $(BUILD)/ports/rvvfp16/f16_rvvfp16.o
$(BUILD)/ports/rvvfp16/%.o: ports/rvvfp16/%.c $(HEADERS) $(SRC_HDRS)
	@mkdir -p $(dir $@)
	$(RVV_CC) $(RVVFP16_CCFLAGS) $(BASEFLAGS) $(PICFLAGS) -c $< -o $@
endif
endif
endif
