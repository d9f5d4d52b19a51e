/* f16_list.h - helpers for expanding src/core/f16_kernels.def (private to
 * the library, the tests and the bench).
 *   FACET_IF_F16(form, ...)  the rest of the arguments where the line's form
 *                            is f16, nothing where it is none
 * The parameter-list helpers are src/core/kernel_list.h's
 * (FACET_EACH_INPUT). */
#ifndef FACET_F16_LIST_H
#define FACET_F16_LIST_H

#include "kernel_list.h"

#define FACET_IF_F16(form, ...) FACET_IF_F16_##form(__VA_ARGS__)
#define FACET_IF_F16_f16(...) __VA_ARGS__
#define FACET_IF_F16_none(...)

#endif
