# rvv.mk - tests/f32/test_tails.c for the RVV port (a caller's strip-mined loop
# over facet/rvv.h), compiled by RVV_CC (clang: gcc 12 has no RVV
# intrinsics) and linked by $(CC) with the library, where ports/rvv/port.mk
# builds the port (tests/suites/54-rvv.sh runs it at each VLEN).  The
# whole test is compiled for rv64gcv (clang may use V anywhere in it), so
# it runs only where the CPU has V: without, it stops at an illegal
# instruction before its skip (the library's own objects are safe: only
# the port's batch functions are V code, called only where AT_HWCAP has V).
ifneq ($(filter riscv64%,$(TARGET)),)
ifeq ($(RVV_OK),1)
$(BUILD)/tests/test_tails_rvv: tests/f32/test_tails.c tests/lib/harness.h $(HEADERS) $(BUILD)/libfacet.a
	@mkdir -p $(dir $@)
	$(RVV_CC) $(RVV_CCFLAGS) $(BASEFLAGS) -D_DEFAULT_SOURCE -c $< -o $@.o
	$(CC) $(CFLAGS) -o $@ $@.o $(BUILD)/libfacet.a -lm
endif
endif
# The rvvfp16 port's own tests, compiled by RVV_CC for rv64gcv_zfh where
# ports/rvvfp16/port.mk builds the port: test_f16_estimates.c (vfrec7 /
# vfrsqrt7 and the port's Newton steps, exhaustively: its rvvfp16 branch).
# Run only where the CPU has V and binary16 vector arithmetic (qemu -cpu
# rv64,v=true,Zfh=true).
ifeq ($(RVVFP16_OK),1)
$(BUILD)/tests/test_f16_estimates_rvv: tests/f16/test_f16_estimates.c tests/lib/harness.h $(HEADERS) $(BUILD)/libfacet.a
	@mkdir -p $(dir $@)
	$(RVV_CC) $(RVVFP16_CCFLAGS) $(BASEFLAGS) -D_DEFAULT_SOURCE -c $< -o $@.o
	$(CC) $(CFLAGS) -o $@ $@.o $(BUILD)/libfacet.a -lm
endif
