/* YARDSTICK ONLY - never linked into the daran-ascii library.
 *
 * The second yardstick: the protocol parsed the way a firmware engineer
 * writes a parser by hand, without libc. One loop checks the line (length,
 * characters, XOR up to the '*', where each field starts and ends); then a
 * switch on the command letter and one reader per field, each field's bytes
 * read once: numbers in grbl's read_float style (an integer mantissa
 * accumulated while reading, then one multiplication by a power of ten from
 * a float table: fast, and NOT correctly rounded, as such parsers are), the
 * property path hashed into a table built once at start-up, replies printed
 * in fixed point (six decimals, like "%f", with integer arithmetic).
 *
 * It accepts the same lines, answers the same errors in the same order and
 * makes the same HAL calls as the core, except where its rounding of a
 * decimal differs from the correctly rounded float32 (bench/host/
 * compare_traces.py --yardstick handwritten counts those). Not implemented:
 * `h id properties [prefix]` (discovery), the port's own commands and
 * properties, the forward hook. */
#ifndef HANDWRITTEN_H
#define HANDWRITTEN_H

#include <stddef.h>
#include <stdint.h>

#include "daran_config.h"
#include "daran_hal.h"
#include "daran_result.h"

/* Receives one reply line, line end included (same shape as daran_write_fn). */
typedef void (*handwritten_write_fn)(void *ctx, const char *line, size_t len);

typedef struct handwritten {
    const daran_hal_t *hal;
    void *hal_ctx;
    handwritten_write_fn write;
    void *write_ctx;
    uint8_t reply_checksum; /* the request carried a well-formed checksum field */
    uint8_t has_preset;
    float preset[3];
    uint16_t reply_len;
    char reply[96];
    uint16_t rx_len;        /* bytes of the line being received (handwritten_rx_write) */
    uint8_t rx_overflow;    /* it grew past the line buffer */
    char rx[DARAN_LINE_MAX];
} handwritten_t;

void handwritten_init(handwritten_t *h, const daran_hal_t *hal, void *hal_ctx,
                      handwritten_write_fn write, void *write_ctx);

/* Process one line without its '\n' (text[0..len), no NUL needed). Returns
 * DARAN_OK when the line was executed, blank or for another drive, else the
 * error answered. */
daran_result_t handwritten_process_line(handwritten_t *h, const char *text, size_t len);

/* The byte path as such firmware writes it: append the bytes to a line
 * buffer (the receive interrupt's job), run each line at its '\n' (the main
 * loop's job), both here in one call. A line longer than the buffer is
 * answered `line too long`. */
void handwritten_rx_write(handwritten_t *h, const char *data, size_t len);

/* The property lookup alone (hash, probe, one comparison), exposed so the
 * benchmark can count it: scope 0 system, 1 axis. DARAN_PROP_COUNT when the
 * name is unknown. */
daran_prop_t handwritten_find_property(int scope, const char *name, size_t len);

/* The number reader alone, for the rounding study (bench/host/rounding.c):
 * the protocol's float grammar, DARAN_OK / DARAN_ERR_INVALID_VALUE /
 * DARAN_ERR_OUT_OF_RANGE (beyond FLT_MAX). */
daran_result_t handwritten_parse_f32(const char *text, size_t len, float *out);

#endif /* HANDWRITTEN_H */
