# RISC-V Vector port (RVV 1.0, vector-length agnostic): riscv64 Linux
# targets (CC=riscv64-linux-gnu-gcc).  gcc 12 has no RVV intrinsics, so the
# two port objects are compiled by RVV_CC (default clang, >= 14:
# --target=riscv64-linux-gnu -march=rv64gcv) and linked with the rest; the
# dispatcher asks AT_HWCAP (bit 'V') at run time (src/core/cpu.c).  Where RVV_CC
# cannot compile <riscv_vector.h> the library is built without the port
# (FACET_PORT_RVV unset); tests/suites/54-rvv.sh checks that it is there.
# FACET_RVV_LMUL=2 (make RVV_LMUL=2) selects m2 vectors for the f32 port.
ifneq ($(filter riscv64%,$(TARGET)),)
RVV_CC ?= clang
RVV_CCFLAGS := --target=riscv64-linux-gnu -march=rv64gcv $(if $(RVV_LMUL),-DFACET_RVV_LMUL=$(RVV_LMUL))
RVV_OK := $(shell printf '\043include <riscv_vector.h>\n' | $(RVV_CC) $(RVV_CCFLAGS) -x c -fsyntax-only - 2>/dev/null && echo 1)
ifeq ($(RVV_OK),1)
FACET_PORTS += rvv
BASEFLAGS += -DFACET_PORT_RVV=1
LIB_OBJ += $(BUILD)/ports/rvv/f32_rvv.o $(BUILD)/ports/rvv/fx_rvv.o
$(BUILD)/ports/rvv/%.o: ports/rvv/%.c $(HEADERS) $(SRC_HDRS)
	@mkdir -p $(dir $@)
	$(RVV_CC) $(RVV_CCFLAGS) $(BASEFLAGS) $(PICFLAGS) -c $< -o $@
endif
endif
