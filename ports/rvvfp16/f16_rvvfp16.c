/* f16_rvvfp16.c - the RISC-V Vector binary16 f16 port (RVV 1.0 with Zvfh,
 * vector-length agnostic: VLMAX = VLEN / 16 binary16 lanes, the f32 lanes
 * of the same samples in LMUL 2): its batches and table
 * (src/f16/f16_port_body.h) over facet/rvvfp16.h.  Whole vectors of VLMAX
 * lanes, then the tail loaded and stored with vl = the values left, so
 * nothing past the count is read or written.  The dispatcher runs it where
 * facet_cpu_rvvfp16() (src/core/cpu.c: AT_HWCAP's V and riscv_hwprobe's
 * Zvfh) holds.  Built with clang (RVV_CC, ports/rvvfp16/port.mk). */
#include "facet/rvvfp16.h"

#define F16_PORT rvvfp16
#define F16_W 0 /* vector-length agnostic: F16_STEP */
#define F16_STEP facet_rvvfp16_vlmax()
#define F16_NEEDS "RISC-V V with Zvfh, as the riscv_hwprobe system call reports it (RISCV_HWPROBE_EXT_ZVFH)"
/* a whole vector's vl from vsetvlmax() at each load, not the ops' all-ones
 * vl: with the latter clang 14 miscompiles the loop (its vsetvli insertion
 * lets the loop's first vle16 run under the e32/m2 vtype the preheader's
 * f32 constants left, as the same SEW/LMUL ratio, and then runs the
 * binary16 compares under it too: an illegal instruction on odd register
 * numbers, wrong lanes otherwise); an explicit vsetvli per load sets e16/m1 */
#define F16_LOAD(p) facet_rvvfp16_load((p), facet_rvvfp16_vlmax())
#define F16_STORE(p, v) facet_rvvfp16_store((p), (v), FACET_RVVFP16_VL_)
#define F16_LOAD_N(p, r) facet_rvvfp16_load((p), (r))
#define F16_STORE_N(p, v, r) facet_rvvfp16_store((p), (v), (r))
#include "../../src/f16/f16_port_body.h"
