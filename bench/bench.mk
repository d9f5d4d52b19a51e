# bench/bench.mk - the bench's own binary, build/facet-bench (bench/README.md):
# the cycle harness and peers (bench/harness/), the report and pictures
# (bench/report/), the rasterizer (bench/raster/), dispatched by verb from
# bench/facet_bench.c.  Included by the Makefile.  The library's `facet`
# command links none of it.  Adds the bench test to TEST_BIN and
# facet-bench to EXTRA_TESTS (every compiler suite builds it).
# Per-object flags: the peers are built the way their users would build
# them (see bench/harness/peers.h), for the vector width of the facet port
# they are compared with: -march=x86-64-v3 (AVX2) / -march=x86-64-v4
# (AVX-512) on x86, -march=native elsewhere; -ffast-math on the *_fm
# objects only.

BENCH_TARGET := $(shell $(CC) -dumpmachine)
BENCH_X86    := $(filter x86_64% i686% i586% i386%,$(BENCH_TARGET))
BENCH_NATIVE := $(shell $(CC) -march=native -E -x c /dev/null >/dev/null 2>&1 && echo -march=native)
# -I. : what the bench takes from outside bench/, named by its folder in the
# #include line: tests/lib/sample.h (the bench judges error on the same samplers
# as the tests), src/core/kernels.def and src/core/kernel_list.h (every loop is
# generated from the library's kernel list), src/core/port.h (the port tables,
# read by report/symbols.c), src/core/sample_port.h (a sampler's call by its
# kind, for the samplers' loops).  -Ibench: a part's header from another part
# is included as "harness/bench.h", "raster/raster.h", ...
BENCH_FLAGS   = $(BASEFLAGS) -D_GNU_SOURCE -I. -Ibench
BENCH_DEPS    = $(HEADERS) $(wildcard bench/*.h bench/*/*.h) tests/lib/sample.h tests/lib/sample_common.h src/core/kernel_list.h \
                src/core/port.h src/core/sample_port.h

ifneq ($(BENCH_X86),)
BENCH_SHADER_PEERS := peers_shader_avx2 peers_shader_avx2_fm peers_shader_avx512 peers_shader_avx512_fm
else
BENCH_SHADER_PEERS := peers_shader peers_shader_fm
endif
BENCH_HARNESS := cycles bench cli_bench api_bench speed_bench loops_scalar loops_call loops_sse2 loops_avx2 loops_neon \
                 loops_batch loops_tables peers peers_textbook peers_sample fxhook $(BENCH_SHADER_PEERS)
BENCH_HARNESS_OBJ := $(BENCH_HARNESS:%=$(BUILD)/bench/harness/%.o)
BENCH_RASTER_OBJ  := $(patsubst %,$(BUILD)/bench/raster/%.o,raster raster_avx2 raster_sse2 raster_neon)
BENCH_REPORT_OBJ  := $(patsubst %,$(BUILD)/bench/report/%.o,report symbols pictures png image_error geom samplers)
BENCH_OBJ := $(BUILD)/bench/facet_bench.o $(BENCH_HARNESS_OBJ) $(BENCH_REPORT_OBJ) $(BENCH_RASTER_OBJ)

TEST_BIN    += $(BUILD)/tests/test_bench
EXTRA_TESTS += $(BUILD)/facet-bench

.PHONY: bench-report
bench-report: $(BUILD)/facet $(BUILD)/facet-bench

$(BUILD)/facet-bench: $(BENCH_OBJ) $(BUILD)/libfacet.a
	$(CC) $(CFLAGS) -o $@ $^ -lm

$(BUILD)/bench/%.o: bench/%.c $(BENCH_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_FLAGS) -c $< -o $@

# the inline SIMD loops and shading paths: that ISA's flags on these objects
# alone; each asks facet_port_supported() before it runs
BENCH_SIMD_OBJ := $(patsubst %,$(BUILD)/bench/harness/loops_%.o,sse2 avx2 neon) \
                  $(patsubst %,$(BUILD)/bench/raster/raster_%.o,sse2 avx2 neon)
ifneq ($(BENCH_X86),)
$(BUILD)/bench/harness/loops_avx2.o $(BUILD)/bench/raster/raster_avx2.o: BENCH_ISA = -mavx2 -mfma
$(BUILD)/bench/harness/loops_sse2.o $(BUILD)/bench/raster/raster_sse2.o: BENCH_ISA = -msse2
endif
# armv7: NEON objects alone get the NEON flags
ifneq ($(filter arm%,$(BENCH_TARGET)),)
$(BUILD)/bench/harness/loops_neon.o $(BUILD)/bench/raster/raster_neon.o: BENCH_ISA = -mfpu=neon-vfpv4 -mfloat-abi=hard
endif
$(BENCH_SIMD_OBJ): $(BUILD)/bench/%.o: bench/%.c $(BENCH_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_FLAGS) $(BENCH_ISA) -c $< -o $@

# textbook: a first C port, -O2, default floating point (no contraction)
$(BUILD)/bench/harness/peers_textbook.o: bench/harness/peers_textbook.c bench/harness/peers.h $(HEADERS)
	@mkdir -p $(dir $@)
	$(CC) $(WARN) -Iinclude $(CFLAGS) -O2 -ffp-contract=off -c $< -o $@
# the samplers' textbook peer, built the same way (its formulas: tests/lib/sample_peer.h)
$(BUILD)/bench/harness/peers_sample.o: bench/harness/peers_sample.c bench/harness/peers.h tests/lib/sample_peer.h $(HEADERS)
	@mkdir -p $(dir $@)
	$(CC) $(WARN) -Iinclude -I. $(CFLAGS) -O2 -ffp-contract=off -c $< -o $@

# shader-style: -O3, errno-free sqrt, fused multiply-add and no trapping
# math (clang's default; GCC needs it to if-convert the clamps' compares at
# AVX2 width) so the compiler vectorizes it, at the width of the facet port
# it is compared with; and the same source with -ffast-math
BENCH_SHADER = $(WARN) -Iinclude $(CFLAGS) -O3 -fno-math-errno -fno-trapping-math -ffp-contract=fast
BENCH_SHADER_SRC = bench/harness/peers_shader.c bench/harness/peers.h $(HEADERS)
$(BUILD)/bench/harness/peers_shader_avx2.o $(BUILD)/bench/harness/peers_shader_avx2_fm.o: \
    BENCH_PEER = -march=x86-64-v3 -DPEER_WIDTH=avx2 -DPEER_MARCH='"-march=x86-64-v3"'
$(BUILD)/bench/harness/peers_shader_avx512.o $(BUILD)/bench/harness/peers_shader_avx512_fm.o: \
    BENCH_PEER = -march=x86-64-v4 -DPEER_WIDTH=avx512 -DPEER_MARCH='"-march=x86-64-v4"'
$(BUILD)/bench/harness/peers_shader.o $(BUILD)/bench/harness/peers_shader_fm.o: BENCH_PEER = $(BENCH_NATIVE)
$(BUILD)/bench/harness/%_fm.o: BENCH_FM = -ffast-math -DPEER_FASTMATH
$(BENCH_SHADER_PEERS:%=$(BUILD)/bench/harness/%.o): $(BENCH_SHADER_SRC)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_SHADER) $(BENCH_PEER) $(BENCH_FM) -c $< -o $@

# the PNG encoder and the rasterizer (every shading path against the oracle)
$(BUILD)/tests/test_bench: bench/test_bench.c $(BUILD)/bench/report/png.o $(BENCH_RASTER_OBJ) \
        $(BUILD)/bench/harness/cycles.o $(BUILD)/libfacet.a $(BENCH_DEPS) tests/lib/harness.h
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_FLAGS) -o $@ $< $(filter %.o %.a,$^) -lm
