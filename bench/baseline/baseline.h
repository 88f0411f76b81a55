/* YARDSTICK ONLY - never linked into the daran-ascii library.
 *
 * A comparison parser for the same protocol written the way ODrive-style
 * firmware parses its ASCII commands: one sscanf per line to split the
 * fields, strtof/strtod for the numbers, a linear strcmp search of the
 * command and property names, snprintf("%f") replies and an XOR checksum.
 * It exists so the host and Cortex-M4 benchmarks have something honest to
 * compare daran-ascii with: it accepts the same lines, answers the same
 * errors and makes the same HAL calls (bench/host/compare_traces.py checks
 * that on every recorded stream). It is not tuned and not meant for use. */
#ifndef BASELINE_H
#define BASELINE_H

#include <stddef.h>
#include <stdint.h>

#include "daran_hal.h"
#include "daran_result.h"

/* Receives one reply line, line end included (same shape as daran_write_fn). */
typedef void (*baseline_write_fn)(void *ctx, const char *line, size_t len);

typedef struct baseline {
    const daran_hal_t *hal;
    void *hal_ctx;
    baseline_write_fn write;
    void *write_ctx;
    int reply_checksum; /* the request carried a well-formed checksum field */
    int prop; /* r/w: the property the dispatcher found */
    int has_preset;
    float preset[3];
    char reply[96];
} baseline_t;

void baseline_init(baseline_t *b, const daran_hal_t *hal, void *hal_ctx, baseline_write_fn write,
                   void *write_ctx);

/* Process one NUL-terminated line without its '\n'. Returns DARAN_OK when the
 * line was executed, blank or for another drive, else the error answered. */
daran_result_t baseline_process_line(baseline_t *b, const char *line);

/* The property lookup alone (linear strcmp), exposed so the benchmark can
 * count its instructions: scope 0 system, 1 axis. Returns DARAN_PROP_COUNT
 * when the name is unknown. */
daran_prop_t baseline_find_property(int scope, const char *name);

#endif /* BASELINE_H */
