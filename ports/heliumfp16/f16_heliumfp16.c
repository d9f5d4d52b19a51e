/* f16_heliumfp16.c - the Helium MVE binary16 f16 port (8 binary16 lanes,
 * Cortex-M55 / M85 with MVE floating point): its batches and table
 * (src/f16/f16_port_body.h) over facet/heliumfp16.h.  The tail is
 * predicated by VCTP (nothing read or written past the count).  The
 * dispatcher runs it where facet_cpu_helium() (src/core/cpu.c: MVFR1.MVE
 * is 2, MVE with half- and single-precision floating point) holds. */
#include "facet/heliumfp16.h"

#define F16_PORT heliumfp16
#define F16_W 8
#define F16_NEEDS "Armv8.1-M MVE with floating point (MVFR1.MVE = 2: half and single precision lanes)"
#define F16_LOAD(p) facet_heliumfp16_load(p)
#define F16_STORE(p, v) facet_heliumfp16_store((p), (v))
#define F16_LOAD_N(p, r) facet_heliumfp16_load_n((p), (r))
#define F16_STORE_N(p, v, r) facet_heliumfp16_store_n((p), (v), (r))
#include "../../src/f16/f16_port_body.h"
