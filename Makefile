# facet - one non-recursive Makefile.
#   make            build/libfacet.a, build/libfacet.so, build/facet
#   make check      every test (gcc, clang, sanitizers, cross ports); closing
#                   line "N passed, N failed, N skipped"
#   make report     accuracy sweep (+ bench, build/facet-bench) -> build/report/
#   make fuzz       libFuzzer targets, FUZZ_SECONDS (300) each (tests/fuzz/fuzz.mk;
#                   the one recursive make: an instrumented libfacet)
#   make install PREFIX=/usr/local   (headers, libraries, pkg-config, CMake
#                   package config, bin/facet); make uninstall (same PREFIX)
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

# the library: src/core (the lists, the dispatcher, the CPU module), one
# folder per format (src/f32, src/fx) and the reference (src/oracle); the
# firmware's batch loops (src/fx/fx_firmware_batch.c) replace the dispatched
# batches there, never here
LIB_SRC  := $(filter-out src/fx/fx_firmware_batch.c,$(wildcard src/core/*.c src/f32/*.c src/f16/*.c src/fx/*.c src/oracle/*.c))
LIB_OBJ  := $(LIB_SRC:%.c=$(BUILD)/%.o)
CLI_SRC  := $(wildcard src/cli/*.c)
CLI_OBJ  := $(CLI_SRC:%.c=$(BUILD)/%.o)
# the tests, one folder per area (tests/README.md); every binary lands in
# $(BUILD)/tests/ under its own name
TEST_SRC := $(wildcard tests/*/test_*.c)
TEST_BIN := $(addprefix $(BUILD)/tests/,$(notdir $(TEST_SRC:.c=)))
TEST_DIRS := $(sort $(dir $(wildcard tests/*/*.c)))
vpath %.c $(TEST_DIRS)
HEADERS  := $(wildcard include/*.h include/facet/*.h include/facet/detail/*.h src/core/*.def)
SRC_HDRS := $(wildcard src/*/*.h)
# The fixed-point kernels on their own (firmware): the kernels of both tiers,
# their batch API as plain loops (no port table, no dispatcher: with
# --gc-sections a firmware keeps only the kernels it calls), the RGB forms,
# the kernel table.  Compile with -Iinclude.
FX_SOURCES := src/fx/fx_prims.c src/fx/fx_kernels.c src/fx/fx_fast.c src/fx/fx_table.c src/fx/fx_rgb.c \
              src/fx/fx_firmware_batch.c

# Parts add their own rules here (ports/<isa>/port.mk, tests/*/*.mk, bench/*.mk);
# they may append to LIB_OBJ, CLI_OBJ, TEST_BIN and EXTRA_TESTS.  The ports
# first: each adds its name to FACET_PORTS (and its ISA flags,
# PORT_FLAGS_<name>), which the others read.
EXTRA_TESTS :=
FACET_PORTS :=
-include $(sort $(wildcard ports/*/port.mk))
-include $(sort $(wildcard tests/*/*.mk bench/*.mk))

.PHONY: all lib tests check report install uninstall clean fx-sources
all: lib $(BUILD)/facet
lib: $(BUILD)/libfacet.a $(BUILD)/libfacet.so

$(BUILD)/src/%.o: src/%.c $(HEADERS) $(SRC_HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) $(PICFLAGS) -c $< -o $@

$(BUILD)/libfacet.a: $(LIB_OBJ)
	@rm -f $@
	$(AR) rcs $@ $^

$(BUILD)/libfacet.so: $(LIB_OBJ)
	$(CC) $(CFLAGS) -shared -Wl,--no-undefined -Wl,-soname,libfacet.so.0 -o $@ $^ -lm

$(BUILD)/facet: $(CLI_OBJ) $(BUILD)/libfacet.a
	$(CC) $(CFLAGS) -o $@ $^ -lm

$(BUILD)/tests/%: %.c $(wildcard tests/lib/*.h) $(BUILD)/libfacet.a
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) -D_DEFAULT_SOURCE -o $@ $< $(BUILD)/libfacet.a -lm $(if $(findstring test_threads,$@),-pthread)

tests: $(TEST_BIN) $(BUILD)/facet $(EXTRA_TESTS)

check:
	@tests/check.sh

fx-sources:
	@echo $(FX_SOURCES)

report: all
	@tests/report/report.sh $(BUILD)

# What `make install` puts under $(DESTDIR)$(PREFIX), one list that
# `make uninstall` removes again (and then the directories left empty).
VERSION        := $(shell sed -n 's/^\#define FACET_VERSION "\(.*\)"/\1/p' include/facet.h)
INSTALL_HDRS   := include/facet.h $(wildcard include/facet/*.h include/facet/detail/*.h)
INSTALL_CMAKE  := lib/cmake/facet/facet-config.cmake lib/cmake/facet/facet-config-version.cmake
INSTALL_FILES  := bin/facet $(INSTALL_HDRS) lib/libfacet.a lib/libfacet.so.0 lib/libfacet.so \
                  lib/pkgconfig/facet.pc $(INSTALL_CMAKE)
INSTALL_DIRS   := include/facet/detail include/facet include lib/cmake/facet lib/cmake lib/pkgconfig lib bin
IROOT = $(DESTDIR)$(PREFIX)

install: lib $(BUILD)/facet
	install -d $(IROOT)/include/facet/detail $(IROOT)/lib/pkgconfig $(IROOT)/lib/cmake/facet $(IROOT)/bin
	install -m 755 $(BUILD)/facet $(IROOT)/bin/
	install -m 644 include/facet.h $(IROOT)/include/
	install -m 644 $(filter include/facet/%,$(filter-out include/facet/detail/%,$(INSTALL_HDRS))) $(IROOT)/include/facet/
	install -m 644 $(filter include/facet/detail/%,$(INSTALL_HDRS)) $(IROOT)/include/facet/detail/
	install -m 644 $(BUILD)/libfacet.a $(IROOT)/lib/
	install -m 755 $(BUILD)/libfacet.so $(IROOT)/lib/libfacet.so.0
	ln -sf libfacet.so.0 $(IROOT)/lib/libfacet.so
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(VERSION)|' src/install/facet.pc.in > $(IROOT)/lib/pkgconfig/facet.pc
	install -m 644 src/install/facet-config.cmake $(IROOT)/lib/cmake/facet/facet-config.cmake
	sed -e 's|@VERSION@|$(VERSION)|' \
	    -e "s|@SIZEOF_VOID_P@|$$(echo __SIZEOF_POINTER__ | $(CC) -E -P - | tr -d ' \n')|" \
	    src/install/facet-config-version.cmake.in > $(IROOT)/lib/cmake/facet/facet-config-version.cmake

uninstall:
	rm -f $(addprefix $(IROOT)/,$(INSTALL_FILES))
	for d in $(INSTALL_DIRS); do [ ! -d "$(IROOT)/$$d" ] || rmdir "$(IROOT)/$$d" 2>/dev/null || true; done

clean:
	rm -rf build
