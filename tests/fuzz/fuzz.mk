# fuzz.mk - the libFuzzer targets (tests/fuzz/fuzz_*.c), built with clang
# -fsanitize=fuzzer,address,undefined against a libfacet built the same
# way (coverage-instrumented, every port compiled in).  Included by the
# Makefile.
#   make fuzz-build                 build $(BUILD)/fuzz/fuzz_*
#   make fuzz [FUZZ_SECONDS=300]    run each target that long from its
#                                   committed seed corpus (tests/fuzz/corpus/
#                                   <target>/; new inputs go to
#                                   $(BUILD)/fuzz/corpus/<target>/); any
#                                   finding fails, its reproducer is in
#                                   $(BUILD)/fuzz/artifacts/
# make check runs each for about 20 s (tests/suites/55-fuzz.sh).
FUZZ_CC      ?= clang
FUZZ_SECONDS ?= 300
FUZZ_DIR     := $(BUILD)/fuzz
FUZZ_SAN      = -fsanitize=address,undefined -fno-sanitize-recover=all
FUZZ_CFLAGS   = $(WARN) -D_DEFAULT_SOURCE -ffp-contract=off -fno-fast-math -Iinclude -Isrc/cli -O1 -g
FUZZ_NAMES   := $(patsubst tests/fuzz/%.c,%,$(wildcard tests/fuzz/fuzz_*.c))
FUZZ_BINS    := $(FUZZ_NAMES:%=$(FUZZ_DIR)/%)

.PHONY: fuzz fuzz-build fuzz-force
fuzz-build: $(FUZZ_BINS)

fuzz: fuzz-build
	@sh tests/fuzz/run.sh $(FUZZ_DIR) $(FUZZ_SECONDS) $(FUZZ_NAMES)

# the library, instrumented; the sub-make decides whether anything changed
$(FUZZ_DIR)/lib/libfacet.a: fuzz-force
	@$(MAKE) --no-print-directory BUILD=$(FUZZ_DIR)/lib CC=$(FUZZ_CC) \
	    CFLAGS="-O1 -g -fsanitize=fuzzer-no-link $(FUZZ_SAN)" $(FUZZ_DIR)/lib/libfacet.a

$(FUZZ_DIR)/fuzz_%: tests/fuzz/fuzz_%.c tests/fuzz/fuzz_common.h tests/lib/sample.h src/cli/parse.c src/cli/cli.h \
                    $(FUZZ_DIR)/lib/libfacet.a $(HEADERS)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer $(FUZZ_SAN) -o $@ $< src/cli/parse.c $(FUZZ_DIR)/lib/libfacet.a -lm
