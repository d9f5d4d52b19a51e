/* f16_neonfp16.c - the ARMv8.2-A FP16 NEON f16 port (8 binary16 lanes):
 * its batches and table (src/f16/f16_port_body.h) over facet/neonfp16.h.
 * The only object built with +fp16; the dispatcher calls it only where
 * facet_cpu_neonfp16() (src/core/cpu.c: HWCAP FPHP and ASIMDHP) holds. */
#include "facet/neonfp16.h"

#define F16_PORT neonfp16
#define F16_W 8
#define F16_NEEDS "ARMv8.2-A FP16 arithmetic (HWCAP FPHP and ASIMDHP)"
#define F16_LOAD(p) facet_neonfp16_load(p)
#define F16_STORE(p, v) facet_neonfp16_store((p), (v))
#define F16_LOAD_N(p, r) facet_neonfp16_load_n((p), (r))
#define F16_STORE_N(p, v, r) facet_neonfp16_store_n((p), (v), (r))
#include "../../src/f16/f16_port_body.h"
