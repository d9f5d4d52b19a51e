# bench/microsurface.mk - the microsurface reference (bench/microsurface/README.md):
#   build/microsurface          the simulator and its analyses (double, libm, threads)
#   build/tests/msim_check      its validation and the tables' spot check
#                               (run by tests/suites/65-microsurface.sh)
#   make microsurface           regenerates the committed tables and results
#                               (MSIM_PATHS paths per run, MSIM_THREADS threads,
#                               niced; about 12 CPU-minutes at the default:
#                               README.md gives the time)
# Not part of the library, and not built by `make tests`: the suite builds it.

MSIM_DIR   := bench/microsurface
MSIM_CORE  := msim msim_tables
MSIM_OBJ   := $(MSIM_CORE:%=$(BUILD)/microsurface/%.o)
MSIM_TOOL_OBJ := $(MSIM_OBJ) $(BUILD)/microsurface/msim_main.o $(BUILD)/microsurface/msim_analyse.o
MSIM_FLAGS  = $(BASEFLAGS) -D_DEFAULT_SOURCE -I$(MSIM_DIR) -pthread
MSIM_DEPS  := $(wildcard $(MSIM_DIR)/*.h) $(HEADERS)
MSIM_PATHS   ?= 500000
MSIM_THREADS ?= 2
MSIM_SEED    ?= 1

.PHONY: microsurface
$(BUILD)/microsurface/%.o: $(MSIM_DIR)/%.c $(MSIM_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(MSIM_FLAGS) -c $< -o $@

$(BUILD)/microsurface/microsurface: $(MSIM_TOOL_OBJ) $(BUILD)/libfacet.a
	$(CC) $(CFLAGS) -pthread -o $@ $^ -lm
$(BUILD)/tests/msim_check: tests/microsurface/msim_check.c $(MSIM_OBJ) $(BUILD)/libfacet.a $(MSIM_DEPS) tests/lib/harness.h
	@mkdir -p $(dir $@)
	$(CC) $(MSIM_FLAGS) -I. -o $@ $< $(MSIM_OBJ) $(BUILD)/libfacet.a -lm

# the tables, then the analyses that read them (model error, refit, energy)
microsurface: $(BUILD)/microsurface/microsurface
	nice -n 10 $(BUILD)/microsurface/microsurface table --out $(MSIM_DIR) --paths $(MSIM_PATHS) \
	    --threads $(MSIM_THREADS) --seed $(MSIM_SEED) 2> $(MSIM_DIR)/generation.log
	$(BUILD)/microsurface/microsurface error --dir $(MSIM_DIR)
	$(BUILD)/microsurface/microsurface refit --dir $(MSIM_DIR)
	$(BUILD)/microsurface/microsurface energy --dir $(MSIM_DIR)
