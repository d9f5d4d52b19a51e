/* f16_avx512fp16.c - the AVX-512 FP16 f16 port (32 binary16 lanes): its
 * batches and table (src/f16/f16_port_body.h) over facet/avx512fp16.h.
 * The only object built with -mavx512fp16; the dispatcher calls it only
 * where facet_cpu_avx512fp16() (src/core/cpu.c) says the CPU has it. */
#include "facet/avx512fp16.h"

#define F16_PORT avx512fp16
#define F16_W 32
#define F16_NEEDS "AVX-512 FP16 (CPUID.(EAX=7,ECX=0):EDX[23]) with AVX-512 F, BW, VL and the OS saving ZMM state"
#define F16_LOAD(p) facet_avx512fp16_load(p)
#define F16_STORE(p, v) facet_avx512fp16_store((p), (v))
#define F16_LOAD_N(p, r) facet_avx512fp16_load_n((p), (r))
#define F16_STORE_N(p, v, r) facet_avx512fp16_store_n((p), (v), (r))
#include "../../src/f16/f16_port_body.h"
