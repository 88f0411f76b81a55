/** @file daran_port.h
 * Extending a drive without editing the library: the port's own commands,
 * the field parsers their handlers use, reply lines, and telemetry reports.
 *
 * The port's own properties and the vendor properties it leaves out are
 * described in its options header (DARAN_PORT_PROPERTY_LIST and
 * DARAN_OMIT_PROPERTIES, see daran_properties.h): they are part of the table
 * the build generates, found and range-checked like the vendor's, and reach
 * the HAL's get/set with their own DARAN_PROP_<ID>.
 *
 * Its commands are a table of daran_port_command_t in the port's memory
 * (usually `static const`), given once with daran_set_port_commands(); their handlers get the
 * drive's one context (daran_init()). The
 * core frames, checks the checksum, the motor id and the number of values of
 * a port command exactly as for its own, then calls the handler, which reads
 * every value with the daran_args_*() parsers (the library's grammar and
 * error replies) before it touches the hardware: a handler that returns an
 * error must have had no effect, as for the core's own commands. */
#ifndef DARAN_PORT_H
#define DARAN_PORT_H

#include <stddef.h>
#include <stdint.h>

#include "daran_drive.h"
#include "daran_result.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The values of a port command's line, for the daran_args_*() parsers. */
typedef struct daran_request daran_args_t;

/** A port command's handler. @p ctx is the drive's (daran_init()).
 * Return DARAN_OK (replies, if any, already sent with daran_reply()) or
 * the error to answer. Runs in daran_poll()'s context. */
typedef daran_result_t (*daran_port_handler_fn)(daran_drive_t *drive, const daran_args_t *args,
                                                void *ctx);

/** Longest port command word. */
#define DARAN_PORT_WORD_MAX 8u
/** daran_port_command_t.flags: a query, answered when sent to id 0 and
 * never forwarded (as `r`, `f`, `g`); other commands sent to id 0 run here
 * and go to the forward hook too. */
#define DARAN_PORT_COMMAND_QUERY 0x01u

/** One command of the port's own: `<word> <id> <values...>`. */
typedef struct daran_port_command {
    const char *word;      /**< 1..DARAN_PORT_WORD_MAX lower-case letters, not a vendor word */
    uint8_t min_values;    /**< values after the id, at least */
    uint8_t max_values;    /**< and at most (<= DARAN_FIELDS_MAX - 3) */
    uint8_t flags;         /**< DARAN_PORT_COMMAND_QUERY or 0 */
    daran_port_handler_fn handler; /**< called with the values after the id */
    const char *help;      /**< arguments after the id for `h` ("" when none) */
} daran_port_command_t;

/** Give the drive the port's commands (or none: @p count 0). The table is
 * read in place: it must outlive the drive. All-or-nothing: a table with a
 * word that is empty, too long, not lower-case letters, a vendor word or
 * twice in the table, a NULL handler or help, or min_values > max_values or
 * max_values above the line's field limit, is refused with
 * DARAN_ERR_BAD_ARGUMENT and the drive keeps what it had. O(count^2). */
DARAN_NODISCARD daran_result_t daran_set_port_commands(daran_drive_t *drive,
                                                       const daran_port_command_t *commands,
                                                       size_t count);

/** How many values follow the id (between min_values and max_values). */
size_t daran_args_count(const daran_args_t *args);
/** The line's command word (not NUL-terminated), its length in @p len: a
 * handler that serves several words, or a shim that hands a command on to
 * the port's own handler (the test kit's), tells them apart by it. */
const char *daran_args_word(const daran_args_t *args, size_t *len);
/** The id the line was sent to: the drive's own, or 0 (every drive). */
uint8_t daran_args_motor(const daran_args_t *args);
/** Value @p index (0 = the first after the id) as a float32, correctly
 * rounded: DARAN_ERR_INVALID_VALUE for bad grammar, DARAN_ERR_OUT_OF_RANGE
 * beyond FLT_MAX, DARAN_ERR_INVALID_FORMAT for an index past the values. */
daran_result_t daran_args_f32(const daran_args_t *args, size_t index, float *out);
/** Value @p index as an exact unsigned 32-bit integer (`5.0` is 5):
 * DARAN_ERR_INVALID_VALUE for a non-integer, DARAN_ERR_OUT_OF_RANGE for a
 * negative one or one above UINT32_MAX. */
daran_result_t daran_args_u32(const daran_args_t *args, size_t index, uint32_t *out);
/** Value @p index as a mode: an integer whose bit is set in @p allowed
 * (bit m = mode m); DARAN_ERR_INVALID_MODE otherwise. */
daran_result_t daran_args_mode(const daran_args_t *args, size_t index, uint32_t allowed,
                               uint32_t *out);

/** Send one reply line: @p payload without its line end (no `\n` or `\r`
 * inside); the core adds ` *N` when the request carried a checksum, and the
 * line end. Longer than DARAN_REPLY_MAX leaves is cut. */
void daran_reply(daran_drive_t *drive, const char *payload, size_t len);

/** Longest text of daran_format_float(): a buffer of this size always fits. */
#define DARAN_FLOAT_TEXT_MAX 16
/** Longest text of daran_format_uint(): a buffer of this size always fits. */
#define DARAN_UINT_TEXT_MAX 20
/** A float32 in the reply number format (the shortest decimal that reads
 * back to the same float; "nan", "inf", "-inf", "-0") into buf[0..size), no
 * NUL. Returns the length written; when the text is longer than @p size,
 * writes nothing and returns 0 (a number is never cut). A @p size of
 * DARAN_FLOAT_TEXT_MAX always fits; a smaller one works whenever the text
 * fits. */
size_t daran_format_float(float value, char *buf, size_t size);
/** An unsigned integer in decimal into buf[0..size), no NUL. Returns the
 * length written; when the text is longer than @p size, writes nothing and
 * returns 0. A @p size of DARAN_UINT_TEXT_MAX always fits (3 is enough
 * below 1000). */
size_t daran_format_uint(uint64_t value, char *buf, size_t size);

/** Telemetry (protocol.md 11.2). Call once per control tick, with the tick
 * count since boot and the tick rate, from the context that calls
 * daran_poll() (never from an interrupt that could preempt it: a report
 * must not fall into the middle of a reply). When
 * `axis0.telemetry.period` is above 0 and a period has passed, it reads
 * the fields `axis0.telemetry.fields` selects through the HAL and writes
 * one report line `@<id> <t> <values> *N`. Costs one HAL get per call when
 * telemetry is off. Returns DARAN_OK, or the HAL's error (no report). */
daran_result_t daran_telemetry_tick(daran_drive_t *drive, uint32_t tick, uint32_t tick_hz);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_PORT_H */
