# bench/f16.mk - build/facet-f16-bench (bench/f16/f16_bench.c): the f16
# kernels' speed beside f32 and f32_fast, and the binary16 shader-style peer
# (bench/f16/peer_f16_shader.c, the only object built with -ffast-math and
# -march=sapphirerapids: it runs only where facet_f16_port_supported says
# the CPU has AVX-512 FP16).  x86-64 only.  Run: build/facet-f16-bench [calls]
ifneq ($(filter x86_64%,$(shell $(CC) -dumpmachine)),)
EXTRA_TESTS += $(BUILD)/facet-f16-bench
$(BUILD)/bench/f16/peer_f16_shader.o: bench/f16/peer_f16_shader.c bench/f16/f16_peer.h
	@mkdir -p $(dir $@)
	$(CC) $(WARN) -Ibench $(CFLAGS) -O3 -march=sapphirerapids -mprefer-vector-width=512 -ffast-math -c $< -o $@
$(BUILD)/bench/f16/f16_bench.o: bench/f16/f16_bench.c bench/f16/f16_peer.h tests/f16/f16_test.h $(BENCH_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_FLAGS) -c $< -o $@
$(BUILD)/facet-f16-bench: $(BUILD)/bench/f16/f16_bench.o $(BUILD)/bench/f16/peer_f16_shader.o \
        $(BUILD)/bench/harness/cycles.o $(BUILD)/libfacet.a
	$(CC) $(CFLAGS) -o $@ $^ -lm
endif
