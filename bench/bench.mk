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
BENCH_DEPS    = $(HEADERS) $(wildcard bench/*.h bench/*/*.h) tests/lib/sample.h tests/lib/sample_common.h tests/f16/f16_test.h \
                src/core/kernel_list.h \
                src/core/port.h src/core/sample_port.h

ifneq ($(BENCH_X86),)
BENCH_SHADER_PEERS := peers_shader_avx2 peers_shader_avx2_fm peers_shader_avx512 peers_shader_avx512_fm
else
BENCH_SHADER_PEERS := peers_shader peers_shader_fm
endif
# Per port: bench/harness/loops_<port>.c (its inline loops) is built where
# the port is compiled in (FACET_PORTS, ports/<isa>/port.mk) and listed in
# loops_tables.c; bench/raster/raster_<port>.c (its inline shading path,
# called by name: a stub where the port is not compiled in) is built on
# every target.  Both get the port's own ISA flags (PORT_FLAGS_<port>).
BENCH_LOOP_PORTS := $(filter $(patsubst bench/harness/loops_%.c,%,$(wildcard bench/harness/loops_*.c)),$(FACET_PORTS))
BENCH_HARNESS := cycles bench cli_bench api_bench speed_bench loops_scalar loops_call $(BENCH_LOOP_PORTS:%=loops_%) \
                 loops_batch loops_tables peers peers_textbook peers_sample fxhook $(BENCH_SHADER_PEERS) \
                 percall_inline percall_peer
BENCH_HARNESS_OBJ := $(BENCH_HARNESS:%=$(BUILD)/bench/harness/%.o)
BENCH_RASTER_OBJ  := $(patsubst bench/raster/%.c,$(BUILD)/bench/raster/%.o,$(wildcard bench/raster/raster*.c))
BENCH_REPORT_OBJ  := $(patsubst %,$(BUILD)/bench/report/%.o,report data doc doc_md doc_html svg kernel_facts \
                     sec_choose sec_clock sec_pareto sec_image sec_furnace sec_model sec_pictures sec_samplers \
                     sec_arm sec_wcet sec_rtl sec_raster sec_targets sec_speed sec_kernels symbols pictures png image_error geom)
BENCH_OBJ := $(BUILD)/bench/facet_bench.o $(BENCH_HARNESS_OBJ) $(BENCH_REPORT_OBJ) $(BENCH_RASTER_OBJ)
# x86-64: the binary16 shader-style peer (bench/f16/peer_f16_shader.c, its
# rule in bench/f16.mk: -march=sapphirerapids -ffast-math) joins the speed
# rounds beside the avx512fp16 table, called only where the CPU runs that
ifneq ($(filter x86_64%,$(BENCH_TARGET)),)
BENCH_OBJ += $(BUILD)/bench/f16/peer_f16_shader.o
$(BUILD)/bench/harness/speed_bench.o: BENCH_FLAGS += -DBENCH_F16_PEER
endif

TEST_BIN    += $(BUILD)/tests/test_bench
EXTRA_TESTS += $(BUILD)/facet-bench

.PHONY: bench-report
bench-report: $(BUILD)/facet $(BUILD)/facet-bench

$(BUILD)/facet-bench: $(BENCH_OBJ) $(BUILD)/libfacet.a
	$(CC) $(CFLAGS) -o $@ $^ -lm

$(BUILD)/bench/%.o: bench/%.c $(BENCH_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_FLAGS) -c $< -o $@

# the interactive chooser's script, inlined in index.html by sec_choose.c:
# one C string a line (backslash, quote and '?' escaped: no trigraphs)
$(BUILD)/bench/report/chooser_js.h: bench/report/chooser.js
	@mkdir -p $(dir $@)
	sed -e 's/\\/\\\\/g' -e 's/"/\\"/g' -e 's/?/\\?/g' -e 's/^/    "/' -e 's/$$/\\n",/' $< > $@.tmp && mv $@.tmp $@
$(BUILD)/bench/report/sec_choose.o: $(BUILD)/bench/report/chooser_js.h
$(BUILD)/bench/report/sec_choose.o: BENCH_FLAGS += -I$(BUILD)/bench/report

# the inline SIMD loops and shading paths: their port's ISA flags on these
# objects alone; each asks facet_port_supported() before it runs
$(foreach p,$(FACET_PORTS),$(eval $(BUILD)/bench/harness/loops_$(p).o $(BUILD)/bench/raster/raster_$(p).o: \
    BENCH_ISA = $(PORT_FLAGS_$(p))))
$(BUILD)/bench/harness/loops_tables.o: BENCH_ISA = '-DBENCH_INLINE_PORTS(X)=$(foreach p,$(BENCH_LOOP_PORTS),X($(p)))'
$(BUILD)/bench/harness/loops_%.o: bench/harness/loops_%.c $(BENCH_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_FLAGS) $(BENCH_ISA) -c $< -o $@
$(BUILD)/bench/raster/raster_%.o: bench/raster/raster_%.c $(BENCH_DEPS)
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

# the per-call comparison (bench/harness/percall.h): one sample per loop
# iteration, not vectorized, for -march=x86-64-v3 on x86 (-march=native
# elsewhere): facet/scalar.h inline at -O2, and the engine-style peer
# (peers_shader.c's brdf_hammon formula) at -O2 -ffast-math
BENCH_PERCALL_MARCH := $(if $(BENCH_X86),-march=x86-64-v3,$(BENCH_NATIVE))
BENCH_PERCALL = -O2 -fno-tree-vectorize $(BENCH_PERCALL_MARCH) '-DPERCALL_MARCH=$(or $(BENCH_PERCALL_MARCH),default)'
$(BUILD)/bench/harness/percall_inline.o: bench/harness/percall_inline.c $(BENCH_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_FLAGS) $(BENCH_PERCALL) -c $< -o $@
$(BUILD)/bench/harness/percall_peer.o: $(BENCH_SHADER_SRC) bench/harness/percall.h
	@mkdir -p $(dir $@)
	$(CC) $(WARN) -Wno-unused-function -Iinclude $(CFLAGS) $(BENCH_PERCALL) -ffast-math -DPEER_PERCALL -c $< -o $@

# the PNG encoder and the rasterizer (every shading path against the oracle)
$(BUILD)/tests/test_bench: bench/test_bench.c $(BUILD)/bench/report/png.o $(BENCH_RASTER_OBJ) \
        $(BUILD)/bench/harness/cycles.o $(BUILD)/libfacet.a $(BENCH_DEPS) tests/lib/harness.h
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_FLAGS) -o $@ $< $(filter %.o %.a,$^) -lm
