/* Declarations shared by the core's modules; not part of the public API. */
#ifndef DARAN_INTERNAL_H
#define DARAN_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_drive.h"
#include "number.h"

/* A condition the build must meet: a table edit that breaks a handler's
 * assumption stops the compiler (C11 or a C99 negative array size). */
#if defined(__STDC_VERSION__) && __STDC_VERSION__ >= 201112L
#define DARAN_STATIC_ASSERT(condition, what) _Static_assert(condition, #what)
#else
#define DARAN_STATIC_ASSERT(condition, what) \
    typedef char daran_static_assert_##what[(condition) ? 1 : -1]
#endif

/* The most values a motion command (t q p v c d) has after its id. */
#define DARAN_MOTION_VALUES_MAX 5u

#if defined(__GNUC__) || defined(__clang__)
#define DARAN_NOINLINE __attribute__((noinline))
#else
#define DARAN_NOINLINE
#endif

/* A field: a view into the line, never a copy. */
typedef struct daran_field {
    const char *text;
    uint16_t len;
} daran_field_t;

/* Field i of a line as a view. */
static inline daran_field_t daran_field_of(const char *line, const daran_fields_t *fields,
                                           unsigned i)
{
    daran_field_t field = {line + fields->start[i], fields->len[i]};
    return field;
}

/* One request on its way from the table to the HAL (also what a port
 * command's handler gets, as daran_args_t). */
struct daran_command;

typedef struct daran_request {
    const struct daran_command *command; /* NULL for a port command */
    const char *line;
    const daran_fields_t *fields;
    uint8_t motor;      /* addressed id; 0 = every drive */
    daran_prop_t prop;  /* r/w only */
} daran_request_t;

/* Field i of a request's line. */
static inline daran_field_t daran_field_at(const daran_request_t *request, unsigned i)
{
    return daran_field_of(request->line, request->fields, i);
}

typedef daran_result_t (*daran_handler_fn)(daran_drive_t *drive, const daran_request_t *request);

/* daran_drive_t.line_flags */
#define DARAN_LINE_TOO_LONG 0x01u
#define DARAN_LINE_INVALID_BYTE 0x02u
#define DARAN_LINE_DAMAGED 0x04u  /* the ring lost bytes of this line */
#define DARAN_LINE_IN_FIELD 0x08u /* the last byte framed was inside a field */

/* How the ring stores a line end whose line lost bytes, and what it stores
 * for a received byte of that value (both are invalid characters). */
#define DARAN_RX_DAMAGED_END 0x8Au
#define DARAN_RX_INVALID_BYTE 0x80u

/* Command flags. */
#define DARAN_CMD_READ 0x01u /* answered for id 0 and never forwarded */
#define DARAN_CMD_PATH 0x02u /* the id comes from a property path (r, w) */

/* 6 bytes a row: the handler is an index into a table of functions. */
typedef struct daran_command {
    char word[2];       /* lower case; word[1] is 0 for one-letter words */
    uint8_t fields;     /* min << 4 | max, command word included */
    uint8_t flags;
    uint8_t arg;        /* handler-specific: the shape of a motion command, the HAL action of a system one */
    uint8_t handler;
} daran_command_t;

#define DARAN_MIN_FIELDS(command) ((command)->fields >> 4)
#define DARAN_MAX_FIELDS(command) ((command)->fields & 0x0Fu)

typedef enum daran_scope { DARAN_SCOPE_SYSTEM, DARAN_SCOPE_AXIS } daran_scope_t;
typedef enum daran_access { DARAN_ACCESS_RO, DARAN_ACCESS_RW } daran_access_t;

/* One property's attributes in 16 bits: type (3), access (1), scope (1),
 * range (5), unit number (6; 0 = none). Made by tools/gen_property_index.py. */
typedef uint16_t daran_property_t;
#define DARAN_PROPERTY_TYPE(row) ((daran_prop_type_t)((row) & 7u))
#define DARAN_PROPERTY_ACCESS(row) ((daran_access_t)(((row) >> 3) & 1u))
#define DARAN_PROPERTY_SCOPE(row) ((daran_scope_t)(((row) >> 4) & 1u))
#define DARAN_PROPERTY_RANGE(row) ((daran_range_t)(((row) >> 5) & 31u))
#define DARAN_PROPERTY_UNIT(row) ((unsigned)((row) >> 10))

/* A framed line and what the framer learnt of it on the way in, so later
 * stages need not scan it again. */
typedef struct daran_line {
    const char *text;
    size_t len;
    size_t star_at; /* index of the first '*'; len when there is none */
    uint8_t xor_before_star;
} daran_line_t;

/* result.c: string n (0-based) of a block of NUL-separated strings */
const char *daran_nth_text(const char *block, unsigned n);

/* checksum.c */
uint8_t daran_xor(const char *text, size_t len);
/* Check the "*N" field of a line (D4). DARAN_OK with *has_checksum 0 when
 * there is none, 1 when it is well-formed and matches;
 * DARAN_ERR_CHECKSUM_MISMATCH (*has_checksum 1) or DARAN_ERR_INVALID_CHECKSUM
 * (*has_checksum 0) otherwise. */
daran_result_t daran_checksum_check(const daran_line_t *line, uint8_t *has_checksum);

/* Bytes as the framer classifies them */
/* A blank in a line the framer accepted: space, tab or '\r' are the only
 * accepted bytes at or below ' ', so one comparison tells. */
static inline bool daran_is_blank(char c)
{
    return (unsigned char)c <= (unsigned char)' ';
}
/* Printable ASCII, tab or '\r': branch-light, for the per-byte path. */
static inline bool daran_byte_allowed(uint8_t byte)
{
    return (uint8_t)(byte - 0x20u) < 0x5Fu || byte == '\t' || byte == '\r';
}

/* command_table.c */
const daran_command_t *daran_find_command(const daran_field_t *word);
/* DARAN_OK from the command's handler, or its error. */
daran_result_t daran_run_command(daran_drive_t *drive, const daran_request_t *request);

/* The word before an axis path's motor id (`axis1.…`, D8), and the name
 * `e` gives axis0.error's line: one spelling for both. */
#define DARAN_AXIS_WORD "axis"
#define DARAN_AXIS_WORD_LEN (sizeof DARAN_AXIS_WORD - 1u)

/* property_table.c */
daran_property_t daran_property_row(daran_prop_t prop);

/* A range as the text discovery prints (">=0", "1..63", "{9600,...}",
 * "0|1", "" for none), and whether an integer, or a float's sign, is within
 * it: `w` checks with the very text discovery shows. */
const char *daran_range_text(daran_range_t range);
bool daran_range_holds(daran_range_t range, int64_t value);
/* Does a float satisfy a float row's range (a sign condition, or an
 * interval "lo..hi" when the build has one)? */
bool daran_range_holds_f32(daran_range_t range, float value);

/* Discovery: every property this build knows, in path order: start with
 * *cursor 0; DARAN_PROP_COUNT after the last. */
daran_prop_t daran_discovery_next(size_t *cursor);
/* Property @p prop's path (without `axisN.`) into out[0..DARAN_PATH_MAX);
 * returns its length, 0 for a row left out of this build. */
#define DARAN_PATH_MAX 64u
size_t daran_property_path(daran_prop_t prop, char *out);
/* Append property @p prop's path as a host writes it (`axis0.` for AXIS). */
void daran_reply_path(daran_drive_t *drive, daran_prop_t prop);
/* The unit text of a property, or "-" when it has none. */
const char *daran_unit_text(daran_property_t row);

/* telemetry.c: can a report with these field bits always fit a reply? */
bool daran_telemetry_fits(uint32_t fields);
/* DARAN_OK with *prop set, or DARAN_ERR_INVALID_PROPERTY. */
daran_result_t daran_find_property(daran_scope_t scope, const char *name, size_t len,
                                   daran_prop_t *prop);

/* reply.c: one line at a time in drive->reply */
void daran_reply_begin(daran_drive_t *drive);
void daran_reply_text(daran_drive_t *drive, const char *text, size_t len);
void daran_reply_cstr(daran_drive_t *drive, const char *text);
void daran_reply_f32(daran_drive_t *drive, float value);
void daran_reply_u64(daran_drive_t *drive, uint64_t value);
void daran_reply_space(daran_drive_t *drive);
void daran_reply_end(daran_drive_t *drive);
void daran_reply_error(daran_drive_t *drive, daran_result_t result);

/* framer.c: bytes -> the instance's line buffer and its fields */
void daran_framer_reset(daran_drive_t *drive);
/* Frame bytes[0..n) into the current line up to and including the first
 * line end ('\n'; from the ring also DARAN_RX_DAMAGED_END); returns how many
 * bytes it took and sets *ended when a line end was among them. */
size_t daran_framer_feed(daran_drive_t *drive, const uint8_t *bytes, size_t n, bool from_ring,
                         bool *ended);

/* drive.c: run the line the framer finished (or reject it), and reset the
 * framer. Returns what daran_process_line() returns. */
daran_result_t daran_run_framed_line(daran_drive_t *drive);

/* port_commands.c: the port's command of that word, or NULL */
const struct daran_port_command *daran_find_port_command(const daran_drive_t *drive,
                                                         const daran_field_t *word);

/* commands_common.c: what every handler needs */
daran_result_t daran_field_f32(const daran_field_t *field, float *out);
/* An integer mode field: DARAN_ERR_INVALID_VALUE when malformed or not an
 * integer, DARAN_ERR_INVALID_MODE when an integer whose bit is not set in
 * @p allowed (bit m = mode m). */
daran_result_t daran_field_mode(const daran_field_t *field, uint32_t allowed, uint32_t *out);
daran_result_t daran_field_motor(const daran_field_t *field, uint8_t *out);
daran_result_t daran_get(daran_drive_t *drive, daran_prop_t prop, daran_value_t *out);
/* What the core answers for a HAL's result: protocol errors as they are,
 * anything else (DARAN_ERR_BAD_ARGUMENT, unknown values) `motor fault`. */
daran_result_t daran_from_hal(daran_result_t result);
/* The drive accepts motion: closed loop, no blocking flag. */
daran_result_t daran_check_motion_allowed(daran_drive_t *drive);
/* Hand a validated move to the HAL and feed the watchdog (D22). */
daran_result_t daran_start_move(daran_drive_t *drive, const daran_move_t *move);
bool daran_is_finite(float value);

/* commands_motion.c: the value layouts of t q p v c d, shared by the starts. */
typedef enum daran_shape {
    DARAN_SHAPE_FILTERED,    /* t, mt */
    DARAN_SHAPE_TRAPEZOID,   /* q, mq */
    DARAN_SHAPE_PASSTHROUGH, /* p, mp */
    DARAN_SHAPE_VELOCITY,    /* v, mv */
    DARAN_SHAPE_TORQUE,      /* c, mc */
    DARAN_SHAPE_IMPEDANCE,   /* d */
    DARAN_SHAPE_COUNT
} daran_shape_t;
/* Check @p count values (the line's, after the id, or a preset's) against a
 * shape, in order (the first failing value answers, D11), and build the
 * move; the ramp rate, which depends on the mode, is checked last. */
daran_result_t daran_shape_move(daran_shape_t shape, const float *values, uint8_t count,
                                daran_move_t *move);

/* Read @p count (<= DARAN_APPEND_MAX) properties, then append them to the
 * line being built, each formatted by its type and after a space unless the
 * line is still empty; nothing is appended when a read fails. */
#define DARAN_APPEND_MAX 9u
daran_result_t daran_append_properties(daran_drive_t *drive, const daran_prop_t *props,
                                       size_t count);
/* The same as a whole reply line (`r`, `f`, `g`, `i`). */
daran_result_t daran_reply_properties(daran_drive_t *drive, const daran_prop_t *props,
                                      size_t count);

/* The handlers, one per command family; command->arg selects the shape or
 * action. */
daran_result_t daran_cmd_motion(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_ms(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_start(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_r(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_w(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_action(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_feedback(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_power(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_identity(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_errors(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_discovery(daran_drive_t *drive, const daran_request_t *request);

#endif /* DARAN_INTERNAL_H */
