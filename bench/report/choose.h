/* choose.h - the chooser's data (sec_choose.c): the targets a reader
 * chooses for, and per term and target every candidate (kernel x format x
 * tier) with its cost in that target's unit and its two errors.  The
 * chooser section renders them as tables; a page that answers
 * interactively reads the same candidates. */
#ifndef FACET_REPORT_CHOOSE_H
#define FACET_REPORT_CHOOSE_H

#include "data.h"

typedef struct choose_target {
    const char *name;         /* "AVX2 (this machine)" */
    const char *port;         /* a port of this machine (the bench rows), or NULL */
    const char *cpu;          /* a Cortex-M core (arm.tsv), or NULL */
    const char *unit;         /* the cost's unit, "cyc (llvm-mca)" */
    int f32soft, f32fpu;      /* Cortex-M: its f32 is soft-float / on the FPU */
    const char *vec, *measure; /* an Arm vector port (arm_vec.tsv) and its measure, or NULL */
} choose_target;

int choose_target_count(void);
const choose_target *choose_target_at(int t);

typedef struct choice {
    const char *kernel, *format;
    double cost;  /* in the target's unit */
    double impl;  /* implementation error: max rel. vs its own formula (value >= 2^-8) */
    double model; /* model error vs the term's exact form; 0 exact; < 0 a model of its own */
} choice;

/* the candidates of term (kernel_facts.h) on target t that have a cost
 * there, at most max; returns the count */
int choose_candidates(const report_data *d, int term, int t, choice *c, int max);

#endif
