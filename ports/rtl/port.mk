# The RTL port (ports/rtl/README.md): the fast fixed-point kernels as
# pipelined Verilog-2005, checked bit for bit against the C.  Nothing here
# joins the library build; the targets:
#   make rtl-check  the quick bit-exact and latency checks (tests/suites/57-rtl.sh):
#                   Verilator against libfacet (RTL_RANDOM random vectors, the
#                   golden vectors), Icarus Verilog on the golden vectors
#   make rtl        the long random run (RTL_LONG), both simulators, and the
#                   cost: Yosys per module, nextpnr-ice40 where it fits ->
#                   $(BUILD)/rtl/cost.tsv and cost.md (ports/rtl/cost.sh)
#   make rtl-vectors  rewrites the committed golden vectors (ports/rtl/vectors/)
# The generated sources (tables and constants from the C, the test top) are
# in $(BUILD)/rtl/gen/, made by the host compiler (HOSTCC).
RTL_DIR     := ports/rtl
RTL_B       := $(BUILD)/rtl
RTL_GEN     := $(RTL_B)/gen
HOSTCC      ?= cc
VERILATOR   ?= verilator
IVERILOG    ?= iverilog
VVP         ?= vvp
RTL_RANDOM  ?= 1000000
RTL_LONG    ?= 20000000
RTL_SEED    ?= 1
RTL_VECTORS := 200
RTL_SRC     := $(sort $(wildcard $(RTL_DIR)/rtl/*.v))
RTL_INC     := $(wildcard $(RTL_DIR)/rtl/*.vh)
RTL_KERNELS := $(shell sed -e '/^\#/d' -e '/^$$/d' -e 's/ .*//' $(RTL_DIR)/kernels.txt)
RTL_GENERATED := $(RTL_GEN)/fx_consts.vh $(RTL_GEN)/fx_tables.v $(RTL_GEN)/rtl_all.v $(RTL_GEN)/rtl_kernels.h
# Verilator lint level: every warning but the width ones (operands are
# zero-extended on purpose, the widths are checked in simulation: fx_fits)
RTL_VFLAGS  := --default-language 1364-2005 -Wall -Wno-WIDTH -Wno-UNUSED -Wno-DECLFILENAME \
               -Wno-PINCONNECTEMPTY -Wno-VARHIDDEN --x-initial 0 -I$(RTL_DIR)/rtl -I$(RTL_GEN)

.PHONY: rtl rtl-build rtl-check rtl-vectors rtl-gen

$(RTL_B)/gen_tables: $(RTL_DIR)/gen_tables.c $(HEADERS) $(SRC_HDRS)
	@mkdir -p $(dir $@)
	$(HOSTCC) -std=c99 -Wall -Wextra -Werror -Iinclude -Isrc/fx -o $@ $<

$(RTL_GEN)/fx_consts.vh: $(RTL_B)/gen_tables
	@mkdir -p $(dir $@)
	$(RTL_B)/gen_tables consts > $@.tmp && mv $@.tmp $@

$(RTL_GEN)/fx_tables.v: $(RTL_B)/gen_tables
	@mkdir -p $(dir $@)
	$(RTL_B)/gen_tables tables > $@.tmp && mv $@.tmp $@

$(RTL_GEN)/rtl_all.v $(RTL_GEN)/rtl_kernels.h: $(RTL_DIR)/kernels.txt $(RTL_DIR)/gen_top.sh
	sh $(RTL_DIR)/gen_top.sh $(RTL_DIR)/kernels.txt $(RTL_GEN)

rtl-gen: $(RTL_GENERATED)

# the Verilator model of the test top, linked with libfacet (the C
# specification); at most two compile jobs
$(RTL_B)/obj/Vrtl_all: $(RTL_GENERATED) $(RTL_SRC) $(RTL_INC) $(RTL_DIR)/tb/tb_verilator.cpp $(BUILD)/libfacet.a
	@mkdir -p $(RTL_B)/obj
	$(VERILATOR) --cc --exe --build -j 2 $(RTL_VFLAGS) --top-module rtl_all -Mdir $(RTL_B)/obj \
	    -CFLAGS "-O1 -I$(abspath include) -I$(abspath $(RTL_GEN))" \
	    $(RTL_GEN)/rtl_all.v $(RTL_GEN)/fx_tables.v $(RTL_SRC) \
	    $(abspath $(RTL_DIR)/tb/tb_verilator.cpp) $(abspath $(BUILD)/libfacet.a) > $(RTL_B)/verilator.log 2>&1 \
	    || { tail -n 30 $(RTL_B)/verilator.log; exit 1; }

# the Icarus Verilog testbench on the same sources, one build per kernel
# with only that kernel's module in the test top (RTL_ONE: a run simulates
# one module, not all of them)
RTL_ICARUS  := $(RTL_KERNELS:%=$(RTL_B)/icarus/%.vvp)
$(RTL_B)/icarus/%.vvp: $(RTL_GENERATED) $(RTL_SRC) $(RTL_INC) $(RTL_DIR)/tb/tb_icarus.v
	@mkdir -p $(dir $@)
	$(IVERILOG) -g2005 -Wall -Wno-timescale -Wno-implicit-dimensions -I$(RTL_DIR)/rtl -I$(RTL_GEN) \
	    -DRTL_ONE -DRTL_ONE_$* -s tb_icarus -o $@ \
	    $(RTL_GEN)/rtl_all.v $(RTL_DIR)/tb/tb_icarus.v $(RTL_GEN)/fx_tables.v $(RTL_SRC)

# what run_tests.sh runs (tests/suites/57-rtl.sh builds it)
rtl-build: $(RTL_B)/obj/Vrtl_all $(RTL_ICARUS) $(BUILD)/facet

rtl-check: rtl-build
	sh $(RTL_DIR)/run_tests.sh $(BUILD) $(RTL_RANDOM) $(RTL_SEED)

# the long run, then the cost (one synthesis or place-and-route at a time)
rtl: rtl-build
	sh $(RTL_DIR)/run_tests.sh $(BUILD) $(RTL_LONG) $(RTL_SEED)
	sh $(RTL_DIR)/cost.sh $(BUILD)

# the committed golden vectors: the edges and RTL_VECTORS random ones per kernel
rtl-vectors: $(BUILD)/facet
	for k in $(filter-out brdf_hammon_rgb,$(RTL_KERNELS)); do \
	    $(BUILD)/facet vectors $$k --format fx_fast --count $(RTL_VECTORS) --seed 1 --hex > $(RTL_DIR)/vectors/$$k.hex || exit 1; \
	done
