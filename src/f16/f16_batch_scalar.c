/* f16_batch_scalar.c - the scalar f16 port (the specification, and the
 * fallback of every CPU): its batches and table (src/f16/f16_port_body.h)
 * over facet/f16_scalar.h, one lane. */
#include "facet/f16_scalar.h"

#define F16_PORT scalar
#define F16_W 1
#define F16_NEEDS ""
#define F16_LOAD(p) facet_f16_scalar_from_bits(*(p))
#define F16_STORE(p, v) (*(p) = facet_f16_scalar_to_bits(v))
#define F16_LOAD_N(p, r) F16_LOAD(p)
#define F16_STORE_N(p, v, r) F16_STORE(p, v)
#include "f16_port_body.h"
