/* cpu.h - what this CPU (and its OS) can run: the one place CPU features are
 * read (src/core/cpu.c).  Private to the library; everyone else asks through
 * facet_port_supported() (facet.h).
 * Names generated here from src/core/ports.def: one test per port line,
 * facet_cpu_<cpu>(void), 1 where this CPU and OS run the port (declared for
 * every line; each is defined only where its port's guard holds), and the
 * f16 column's test facet_cpu_<f16_cpu>(void) the same way. */
#ifndef FACET_CPU_H
#define FACET_CPU_H

#define FACET_PORT(name, guard, cpu, fx, fx_fast, f16, f16_cpu) int facet_cpu_##cpu(void); int facet_cpu_##f16_cpu(void);
#include "ports.def"
#undef FACET_PORT

/* what a failed test (one of the above) saw, as a refusal says it, where
 * it knows more than the table's `needs` (rvvfp16: why riscv_hwprobe gave
 * no Zvfh); NULL elsewhere */
const char *facet_cpu_why(int (*test)(void));

#endif
