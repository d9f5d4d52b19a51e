# facet - one non-recursive Makefile.
#   make            build/libfacet.a, build/libfacet.so, build/facet
#   make check      every test (gcc, clang, sanitizers, cross ports); closing
#                   line "N passed, N failed, N skipped"
#   make report     accuracy sweep (+ bench, build/facet-bench) -> build/report/
#   make fuzz       libFuzzer targets, FUZZ_SECONDS (300) each (tests/fuzz.mk;
#                   the one recursive make: an instrumented libfacet)
#   make install PREFIX=/usr/local   (headers, libraries, pkg-config, bin/facet)
#   make fx-sources  the C files a firmware build compiles for the fixed-point
#                   kernels (no f32 code, no dispatcher, no oracle, no libm)
# Variables: CC, BUILD (output dir), CFLAGS (optimisation/debug/sanitizers).

# `make` alone builds `all`: the parts included below define rules of their
# own, and the first rule would otherwise be the default goal
.DEFAULT_GOAL := all

CC      ?= cc
BUILD   ?= build
CFLAGS  ?= -O2 -g
PREFIX  ?= /usr/local
AR      ?= ar

# Baseline flags for every object: no ISA flags here (ports add their own),
# no fast-math, no contraction (fma only where the code asks for it).
WARN      = -std=c99 -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes
BASEFLAGS = $(WARN) -ffp-contract=off -fno-fast-math -Iinclude $(CFLAGS)
PICFLAGS  = -fPIC

TARGET  := $(shell $(CC) -dumpmachine)

LIB_SRC  := $(wildcard src/*.c)
LIB_OBJ  := $(LIB_SRC:%.c=$(BUILD)/%.o)
CLI_SRC  := $(wildcard src/cli/*.c)
CLI_OBJ  := $(CLI_SRC:%.c=$(BUILD)/%.o)
TEST_SRC := $(wildcard tests/test_*.c)
TEST_BIN := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
HEADERS  := $(wildcard include/*.h include/facet/*.h include/facet/detail/*.h) src/kernels.def src/sample_kernels.def
# The fixed-point kernels on their own (firmware): the kernels of both tiers,
# their batch API on the scalar loop, the kernel table.  Compile with -Iinclude.
FX_SOURCES := src/fx_core.c src/fx_kernels.c src/fx_fast.c src/fx_batch.c src/fx_table.c src/fx_rgb.c \
              src/fx_only/fx_active_scalar.c

# Parts add their own rules here (ports/<isa>/port.mk, tests/*.mk, bench/*.mk);
# they may append to LIB_OBJ, CLI_OBJ, TEST_BIN and EXTRA_TESTS.
EXTRA_TESTS :=
-include $(sort $(wildcard ports/*/port.mk tests/*.mk bench/*.mk))

.PHONY: all lib tests check report install clean fx-sources
all: lib $(BUILD)/facet
lib: $(BUILD)/libfacet.a $(BUILD)/libfacet.so

$(BUILD)/src/%.o: src/%.c $(HEADERS) $(wildcard src/*.h src/cli/*.h)
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) $(PICFLAGS) -c $< -o $@

$(BUILD)/libfacet.a: $(LIB_OBJ)
	@rm -f $@
	$(AR) rcs $@ $^

$(BUILD)/libfacet.so: $(LIB_OBJ)
	$(CC) $(CFLAGS) -shared -Wl,--no-undefined -Wl,-soname,libfacet.so.0 -o $@ $^ -lm

$(BUILD)/facet: $(CLI_OBJ) $(BUILD)/libfacet.a
	$(CC) $(CFLAGS) -o $@ $^ -lm

$(BUILD)/tests/%: tests/%.c tests/harness.h tests/sample.h $(BUILD)/libfacet.a
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) -D_DEFAULT_SOURCE -o $@ $< $(BUILD)/libfacet.a -lm $(if $(findstring test_threads,$@),-pthread)

tests: $(TEST_BIN) $(BUILD)/facet $(EXTRA_TESTS)

check:
	@tests/check.sh

fx-sources:
	@echo $(FX_SOURCES)

report: all
	@tests/report.sh $(BUILD)

install: lib $(BUILD)/facet
	install -d $(DESTDIR)$(PREFIX)/include/facet/detail $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/bin
	install -m 755 $(BUILD)/facet $(DESTDIR)$(PREFIX)/bin/
	install -m 644 include/facet.h $(DESTDIR)$(PREFIX)/include/
	install -m 644 include/facet/*.h $(DESTDIR)$(PREFIX)/include/facet/
	install -m 644 include/facet/detail/*.h $(DESTDIR)$(PREFIX)/include/facet/detail/
	install -m 644 $(BUILD)/libfacet.a $(DESTDIR)$(PREFIX)/lib/
	install -m 755 $(BUILD)/libfacet.so $(DESTDIR)$(PREFIX)/lib/libfacet.so.0
	ln -sf libfacet.so.0 $(DESTDIR)$(PREFIX)/lib/libfacet.so
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(shell sed -n 's/^#define FACET_VERSION "\(.*\)"/\1/p' include/facet.h)|' \
	    src/facet.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/facet.pc

clean:
	rm -rf build
