/* cpu.h - what this CPU (and its OS) can run: the one place CPU features are
 * read (src/core/cpu.c).  Private to the library; everyone else asks through
 * facet_port_supported() (facet.h).
 * Names generated here from src/core/ports.def: one test per port line,
 * facet_cpu_<cpu>(void), 1 where this CPU and OS run the port (declared for
 * every line; each is defined only where its port's guard holds). */
#ifndef FACET_CPU_H
#define FACET_CPU_H

#define FACET_PORT(name, guard, cpu, ...) int facet_cpu_##cpu(void);
#include "ports.def"
#undef FACET_PORT

#endif
