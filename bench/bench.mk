# bench/bench.mk - the benchmarks, peers, report and rasterizer (issue 5).
# Included by the Makefile.  Appends the `facet bench` objects to CLI_OBJ,
# the bench test to TEST_BIN, and adds $(BUILD)/facet-report.
# Per-object flags: the peers are built the way their users would build
# them (see bench/peers.h); -ffast-math appears on peers_shader_fm.o only.

BENCH_TARGET := $(shell $(CC) -dumpmachine)
BENCH_X86    := $(filter x86_64% i686% i586% i386%,$(BENCH_TARGET))
BENCH_NATIVE := $(shell $(CC) -march=native -E -x c /dev/null >/dev/null 2>&1 && echo -march=native)
BENCH_FLAGS   = $(BASEFLAGS) -D_GNU_SOURCE -Ibench
BENCH_DEPS    = $(HEADERS) $(wildcard bench/*.h) tests/sample.h

BENCH_CORE := cycles bench loops_scalar loops_call loops_sse2 loops_avx2 loops_neon \
              loops_batch loops_tables peers peers_textbook peers_shader peers_shader_fm fxhook
BENCH_CORE_OBJ := $(BENCH_CORE:%=$(BUILD)/bench/%.o)
BENCH_RASTER_OBJ := $(BUILD)/bench/raster.o $(BUILD)/bench/raster_avx2.o $(BUILD)/bench/raster_sse2.o \
                    $(BUILD)/bench/raster_neon.o
BENCH_REPORT_OBJ := $(BUILD)/bench/png.o $(BENCH_RASTER_OBJ) \
                    $(BUILD)/bench/pictures.o

CLI_OBJ  += $(BENCH_CORE_OBJ) $(BUILD)/bench/cli_bench.o
TEST_BIN += $(BUILD)/tests/test_bench

.PHONY: bench-report
bench-report: $(BUILD)/facet $(BUILD)/facet-report

$(BUILD)/bench/%.o: bench/%.c $(BENCH_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_FLAGS) -c $< -o $@

ifneq ($(BENCH_X86),)
$(BUILD)/bench/loops_avx2.o $(BUILD)/bench/raster_avx2.o: BENCH_ISA = -mavx2 -mfma
$(BUILD)/bench/loops_sse2.o $(BUILD)/bench/raster_sse2.o: BENCH_ISA = -msse2
endif
# armv7: NEON objects alone get the NEON flags (they check HWCAP at run time)
ifneq ($(filter arm%,$(BENCH_TARGET)),)
$(BUILD)/bench/loops_neon.o $(BUILD)/bench/raster_neon.o: BENCH_ISA = -mfpu=neon-vfpv4 -mfloat-abi=hard
endif
$(BUILD)/bench/loops_avx2.o $(BUILD)/bench/loops_sse2.o $(BUILD)/bench/raster_avx2.o $(BUILD)/bench/raster_sse2.o \
$(BUILD)/bench/loops_neon.o $(BUILD)/bench/raster_neon.o: $(BUILD)/bench/%.o: bench/%.c $(BENCH_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_FLAGS) $(BENCH_ISA) -c $< -o $@

# textbook: a first C port, -O2, default floating point (no contraction)
$(BUILD)/bench/peers_textbook.o: bench/peers_textbook.c bench/peers.h $(HEADERS)
	@mkdir -p $(dir $@)
	$(CC) $(WARN) -Iinclude $(CFLAGS) -O2 -ffp-contract=off -c $< -o $@

# shader-style: -O3 -march=native, errno-free sqrt and fused multiply-add so
# the compiler vectorizes it; and the same source with -ffast-math
BENCH_SHADER = $(WARN) -Iinclude $(CFLAGS) -O3 $(BENCH_NATIVE) -fno-math-errno -ffp-contract=fast
$(BUILD)/bench/peers_shader.o: bench/peers_shader.c bench/peers.h $(HEADERS)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_SHADER) -c $< -o $@
$(BUILD)/bench/peers_shader_fm.o: bench/peers_shader.c bench/peers.h $(HEADERS)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_SHADER) -ffast-math -DPEER_FASTMATH -c $< -o $@

$(BUILD)/facet-report: $(BUILD)/bench/report.o $(BENCH_REPORT_OBJ) $(BENCH_CORE_OBJ) $(BUILD)/libfacet.a
	$(CC) $(CFLAGS) -o $@ $^ -lm

$(BUILD)/tests/test_bench: bench/test_bench.c $(BUILD)/bench/png.o $(BENCH_RASTER_OBJ) \
        $(BUILD)/bench/cycles.o $(BUILD)/libfacet.a $(BENCH_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_FLAGS) -o $@ $< $(filter %.o %.a,$^) -lm
