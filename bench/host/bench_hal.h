/* The trivial drive the host benchmarks run both parsers against: property
 * values in an array, moves and actions recorded, nothing simulated. Both
 * parsers see the same state, so their HAL calls can be compared one to one. */
#ifndef BENCH_HAL_H
#define BENCH_HAL_H

#include <stdio.h>

#include "daran_hal.h"

typedef struct bench_hal_state {
    daran_value_t values[DARAN_PROP_COUNT];
    FILE *trace;       /* every set/move/action call is printed here; NULL: none */
    unsigned long line; /* the request being processed, for the trace */
    unsigned long reply_bytes;
} bench_hal_state_t;

/* Power-up values: id 1, closed loop, no flags, 24 V bus. */
void bench_hal_reset(bench_hal_state_t *state, FILE *trace);

/* The reply sink: counts the bytes, traces the line. */
void bench_write(void *ctx, const char *text, size_t len);

/* The HAL's functions and bench_write; the context is a bench_hal_state_t. */
extern const daran_hal_t bench_hal;

#endif /* BENCH_HAL_H */
