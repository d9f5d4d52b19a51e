/* port_tables.h - every f32 port table of src/core/ports.def declared weak
 * (src/core/port.h declares them), so that a bench unit can name each one
 * and find it NULL where the port is not compiled in. */
#ifndef FACET_BENCH_PORT_TABLES_H
#define FACET_BENCH_PORT_TABLES_H

#include "src/core/port.h"

#define FACET_BENCH_PRAGMA_(x) _Pragma(#x)
#define FACET_PORT(name, guard, cpu, fx, fx_fast, ...)         \
    FACET_BENCH_PRAGMA_(weak facet_port_##name##_f32)     \
    FACET_BENCH_PRAGMA_(weak facet_port_##name##_f32_fast)
#include "src/core/ports.def"
#undef FACET_PORT
#undef FACET_BENCH_PRAGMA_

#endif
