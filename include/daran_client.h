/** @file daran_client.h
 * daran_client: the master side of the Daran ASCII protocol (docs/client.md).
 *
 * Four layers, each usable alone: build a request line into the caller's
 * buffer; read a reply line (checksum, kind, error phrase) and decode its
 * values, `e` registers, telemetry report, discovery or help line; know what
 * each command is answered with; and a link over a byte transport the port
 * gives, which sends a request, collects its reply lines within a timeout,
 * hands telemetry reports to a callback and retries only queries.
 *
 * The return convention is the core's (daran_result.h): DARAN_OK is success,
 * a drive's error comes back as its own daran_result_t, and the client adds
 * these meanings of existing codes: DARAN_ERR_BAD_ARGUMENT (misuse: NULL, an
 * impossible request), DARAN_ERR_LINE_TOO_LONG (the caller's buffer is too
 * small), DARAN_ERR_INVALID_VALUE (a reply line the client cannot read),
 * DARAN_ERR_INVALID_CHECKSUM / DARAN_ERR_CHECKSUM_MISMATCH (a reply line
 * without its expected `*N` / with a wrong one), DARAN_ERR_NO_REPLY (the
 * drive did not answer within the timeout), DARAN_ERR_BUS_ERROR (the
 * transport could not write).
 *
 * No heap, no stdio, no libc number conversion: numbers go through the core's
 * correctly rounded parser and shortest printer. Every object's size is fixed
 * at compile time; every function is bounded by its input's length. */
#ifndef DARAN_CLIENT_H
#define DARAN_CLIENT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_protocol.h"
#include "daran_result.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The longest line (request or reply, line end included) the link holds.
 * The core's default lines are 128 bytes before `\n`. */
#ifndef DARAN_CLIENT_LINE_MAX
#define DARAN_CLIENT_LINE_MAX 192u
#endif
/** The most float values a request carries (`d`: five). */
#define DARAN_CLIENT_VALUES_MAX 5u
/** The most values one reply line carries that the client decodes (`i`: 3;
 * a telemetry report: 9 fields). */
#define DARAN_CLIENT_REPORT_MAX 9u
/** The lines of an `e` reply (protocol.md 10.4). */
#define DARAN_CLIENT_ERROR_REGISTERS 7u
/** The highest motor id a line can address. */
#define DARAN_CLIENT_ID_MAX 63u

/* ---------------------------------------------------------------- commands */

/** A command: DARAN_CLIENT_CMD_T, ..., one for each row of the protocol
 * table (daran_protocol.h, in its order), which is the one source of the
 * builder's words, value counts, reply expectations and the retry rule. */
typedef enum daran_client_command {
/** @cond INTERNAL */
#define DARAN_CLIENT_CMD_ENUM_(name, c0, c1, feature, cls, reply, retry, handler, arg, can, help, \
                               f1, f2, f3, f4, f5, f6)                                           \
    DARAN_CLIENT_CMD_##name,
    DARAN_PROTOCOL_COMMANDS(DARAN_CLIENT_CMD_ENUM_)
#undef DARAN_CLIENT_CMD_ENUM_
/** @endcond */
    DARAN_CLIENT_CMD_COUNT /**< how many commands; not a command */
} daran_client_command_t;

/** How a drive answers a command that succeeds (any command that fails is
 * answered by one `error: …` line instead, which ends its reply). */
typedef enum daran_client_reply_shape {
    DARAN_CLIENT_REPLY_SILENT,      /**< nothing */
    DARAN_CLIENT_REPLY_ONE_LINE,    /**< one line: `r f g i` */
    DARAN_CLIENT_REPLY_ERROR_LINES, /**< DARAN_CLIENT_ERROR_REGISTERS lines: `e` */
    DARAN_CLIENT_REPLY_UNTIL_END,   /**< lines, then `end`: `h id properties` */
    DARAN_CLIENT_REPLY_UNTIL_QUIET  /**< lines until the link is quiet: `h id` (no end marker) */
} daran_client_reply_shape_t;

/** What a command does, for the retry rule. */
typedef enum daran_client_class {
    DARAN_CLIENT_CLASS_MOTION, /**< moves the motor: never repeated */
    DARAN_CLIENT_CLASS_PRESET, /**< `ms`: replaces the preset */
    DARAN_CLIENT_CLASS_WRITE,  /**< `w` */
    DARAN_CLIENT_CLASS_SYSTEM, /**< `ss se sr sc sz st u` */
    DARAN_CLIENT_CLASS_QUERY,  /**< `r f g i e h`: no effect, safe to repeat */
    DARAN_CLIENT_CLASS_UPDATE  /**< `ub uw uv ug uy ua uq`: a step of a firmware update */
} daran_client_class_t;

/** The command's word ("t", "ms", "h"); NULL outside the enum. O(1). */
const char *daran_client_command_word(daran_client_command_t command);
/** How the drive answers the command on success (SILENT outside the enum). O(1). */
daran_client_reply_shape_t daran_client_reply_shape(daran_client_command_t command);
/** The command's class (MOTION outside the enum: the safe answer). O(1). */
daran_client_class_t daran_client_command_class(daran_client_command_t command);
/** Whether the link may send the command again after a lost or damaged
 * reply: the protocol table's RETRY column (queries). A repeated motion
 * command could move twice (a relative `mt`/`mq`/`mp`, a second `q` from a
 * new start), and a repeated `sz`/`sr`/`ss` acts twice; those are never
 * retried. O(1). */
bool daran_client_may_retry(daran_client_command_t command);

/* ---------------------------------------------------------------- requests */

/** Where the id of an `r`/`w` goes (protocol.md section 3). */
typedef enum daran_client_scope {
    DARAN_CLIENT_SCOPE_AUTO,   /**< the core's property list decides; a path it lacks is AXIS */
    DARAN_CLIENT_SCOPE_AXIS,   /**< axisN.path */
    DARAN_CLIENT_SCOPE_SYSTEM  /**< `path … N` (the id last) */
} daran_client_scope_t;

/** The value of a `w`, printed as its type is printed by the drive. */
typedef enum daran_client_value_kind {
    DARAN_CLIENT_VALUE_F32,  /**< shortest round-trip float */
    DARAN_CLIENT_VALUE_UINT, /**< u32, u64, bool */
    DARAN_CLIENT_VALUE_INT   /**< s32 */
} daran_client_value_kind_t;

/** A `w` value: the member its kind names is the one sent. */
typedef struct daran_client_value {
    daran_client_value_kind_t kind; /**< which member holds the value */
    float f32;                      /**< DARAN_CLIENT_VALUE_F32 */
    uint64_t uint;                  /**< DARAN_CLIENT_VALUE_UINT */
    int64_t sint;                   /**< DARAN_CLIENT_VALUE_INT */
} daran_client_value_t;

/** One request. `values[0..value_count)` follow the id in order (optional
 * ones are left off by a smaller value_count). `path`: the property of
 * `r`/`w` (written with or without an axisN. prefix, which is replaced
 * by the request's id), the prefix of `h id properties` (NULL: none). */
typedef struct daran_client_request {
    daran_client_command_t command; /**< what to send */
    uint8_t id;                     /**< the motor id, 0..63 (0: every drive) */
    uint8_t value_count;            /**< how many of values[] go out */
    float values[DARAN_CLIENT_VALUES_MAX]; /**< the fields after the id */
    const char *path;               /**< `r`/`w` path, discovery prefix (NUL-terminated) */
    daran_client_scope_t scope;     /**< where `r`/`w` put the id */
    daran_client_value_t value;     /**< the value of a `w` */
} daran_client_request_t;

/** Build `request` into buf[0..size) as one line ending in `\n`, with the
 * ` *N` checksum field when `with_checksum`; *len is its length (no NUL).
 * DARAN_ERR_BAD_ARGUMENT: NULL, a command outside the enum, an id above 63,
 * a value count outside the command's, a missing/blank path;
 * DARAN_ERR_INVALID_VALUE: a value that is not finite (no drive takes one);
 * DARAN_ERR_LINE_TOO_LONG: the line does not fit. On error *len is 0 and buf
 * holds no line. O(line length); touches buf and *len only. */
DARAN_NODISCARD daran_result_t daran_client_build(const daran_client_request_t *request,
                                                  bool with_checksum, char *buf, size_t size,
                                                  size_t *len);

/** End the payload buf[0..payload_len) (a raw line, no line end) with
 * ` *N` when `with_checksum`, and `\n`; *len the new length. For lines the
 * caller writes itself (`daran send`). DARAN_ERR_LINE_TOO_LONG when it does
 * not fit (buf unchanged), DARAN_ERR_BAD_ARGUMENT for NULL. O(payload_len). */
DARAN_NODISCARD daran_result_t daran_client_seal(char *buf, size_t size, size_t payload_len,
                                                 bool with_checksum, size_t *len);

/** The scope of a property path written without an axisN. prefix, from the core's
 * property list (daran_properties.h): SYSTEM for the system rows, AXIS for
 * every other path (a port's own axis rows included). O(rows). */
daran_client_scope_t daran_client_path_scope(const char *path, size_t len);

/* ---------------------------------------------------------------- replies */

/** What a received line is. */
typedef enum daran_client_line_kind {
    DARAN_CLIENT_LINE_TEXT,      /**< values, an `e` register, discovery, help */
    DARAN_CLIENT_LINE_ERROR,     /**< `error: <phrase>`: .error holds the result */
    DARAN_CLIENT_LINE_END,       /**< `end`, the last line of discovery */
    DARAN_CLIENT_LINE_TELEMETRY  /**< a telemetry report: the line starts with `@` */
} daran_client_line_kind_t;

/** A received line: a view of its payload (line end and checksum field cut off). */
typedef struct daran_client_line {
    daran_client_line_kind_t kind; /**< what the line is */
    const char *payload;           /**< its text (not NUL-terminated) */
    size_t len;                    /**< the payload's length */
    bool had_checksum;             /**< it carried a valid `*N` */
    daran_result_t error; /**< LINE_ERROR: the drive's result; DARAN_OK otherwise */
} daran_client_line_t;

/** Read one received line text[0..len) (its `\r\n`/`\n` may be included).
 * A trailing ` *N` is verified and cut off. `checksum_expected`: the request
 * carried one, so every reply line must (telemetry reports always must).
 * DARAN_OK: *out set. DARAN_ERR_CHECKSUM_MISMATCH: a wrong `*N`;
 * DARAN_ERR_INVALID_CHECKSUM: a missing or malformed one where expected;
 * DARAN_ERR_INVALID_VALUE: an `error:` line with a phrase the protocol does
 * not have, or a byte outside printable ASCII. O(len); touches *out only. */
DARAN_NODISCARD daran_result_t daran_client_read_line(const char *text, size_t len,
                                                      bool checksum_expected,
                                                      daran_client_line_t *out);

/** A number of a reply: every form the drive prints (protocol.md 4). */
typedef struct daran_client_number {
    float f32;           /**< the value as a float32 (correctly rounded) */
    uint64_t magnitude;  /**< |value| when is_integer */
    bool negative;       /**< a leading '-' */
    bool is_integer;     /**< digits only (after an optional '-') */
} daran_client_number_t;

/** Parse one field: a float in the reply format (`nan`, `inf`, `-inf`
 * included) or an integer up to UINT64_MAX with an optional '-'.
 * DARAN_ERR_INVALID_VALUE otherwise (*out untouched). O(len). */
DARAN_NODISCARD daran_result_t daran_client_parse_number(const char *text, size_t len,
                                                         daran_client_number_t *out);

/** The number as a u32: DARAN_ERR_INVALID_VALUE when it is not an integer,
 * DARAN_ERR_OUT_OF_RANGE when it does not fit (-0 is 0). O(1). */
DARAN_NODISCARD daran_result_t daran_client_number_u32(const daran_client_number_t *n, uint32_t *out);
/** The number as an s32, as daran_client_number_u32(). O(1). */
DARAN_NODISCARD daran_result_t daran_client_number_s32(const daran_client_number_t *n, int32_t *out);
/** The number as a u64 (a serial number), as daran_client_number_u32(). O(1). */
DARAN_NODISCARD daran_result_t daran_client_number_u64(const daran_client_number_t *n, uint64_t *out);

/** Split a values line (`r f g i`) into numbers. Exactly `expected` fields
 * (0: any count up to max), else DARAN_ERR_INVALID_VALUE; *count set on
 * success. O(len). */
DARAN_NODISCARD daran_result_t daran_client_parse_values(const daran_client_line_t *line,
                                                         daran_client_number_t *out, size_t max,
                                                         size_t expected, size_t *count);

/** `e`'s registers, in the drive's order: axis, motor, encoder, controller,
 * fet_thermistor, motor_thermistor, can. */
typedef struct daran_client_errors {
    uint32_t reg[DARAN_CLIENT_ERROR_REGISTERS]; /**< each register's value */
} daran_client_errors_t;

/** The name of `e`'s register `index` ("axis" …); NULL past the last. O(1). */
const char *daran_client_error_register_name(size_t index);

/** Read the `index`th line of an `e` reply (`name: value`) into
 * errors->reg[index]: the name must be that register's.
 * DARAN_ERR_INVALID_VALUE otherwise. O(len). */
DARAN_NODISCARD daran_result_t daran_client_parse_error_line(const daran_client_line_t *line,
                                                             size_t index,
                                                             daran_client_errors_t *errors);

/** A telemetry report (protocol.md 11.2): `@`, the drive's id, its time,
 * then the values in the order of the bits of `axis0.telemetry.fields`. */
typedef struct daran_client_report {
    uint8_t id;        /**< the reporting drive */
    float time_s;      /**< the drive's time since boot, in seconds */
    size_t count;      /**< how many values[] hold */
    daran_client_number_t values[DARAN_CLIENT_REPORT_MAX]; /**< the fields, in bit order */
} daran_client_report_t;

/** Decode a TELEMETRY line (read by daran_client_read_line, which checked
 * its checksum). DARAN_ERR_INVALID_VALUE when it is not a report. O(len). */
DARAN_NODISCARD daran_result_t daran_client_parse_report(const daran_client_line_t *line,
                                                         daran_client_report_t *out);

/** A property's value type, as discovery names it. */
typedef enum daran_client_type {
    DARAN_CLIENT_TYPE_F32,  /**< `f32` */
    DARAN_CLIENT_TYPE_U32,  /**< `u32` */
    DARAN_CLIENT_TYPE_S32,  /**< `s32` */
    DARAN_CLIENT_TYPE_U64,  /**< `u64` */
    DARAN_CLIENT_TYPE_BOOL  /**< `bool` */
} daran_client_type_t;

/** A discovery line `<path> <type> <access> <unit> [<range>]`: views into
 * the line; unit_len 0 for `-`, range_len 0 when there is none. */
typedef struct daran_client_property {
    const char *path;         /**< as the drive writes it (axis0. in front of axis rows) */
    size_t path_len;          /**< its length */
    daran_client_type_t type; /**< the value type */
    bool writable;            /**< `rw` (else `ro`) */
    const char *unit;         /**< the unit */
    size_t unit_len;          /**< its length; 0 for `-` */
    const char *range;        /**< what a write must satisfy */
    size_t range_len;         /**< its length; 0 when any value goes */
} daran_client_property_t;

/** Decode one discovery line (not `end`). DARAN_ERR_INVALID_VALUE when it
 * is not one. O(len). */
DARAN_NODISCARD daran_result_t daran_client_parse_property(const daran_client_line_t *line,
                                                           daran_client_property_t *out);

/** A help line `<word> <arguments>`: the word and the rest (views). */
typedef struct daran_client_help {
    const char *word;     /**< the command word */
    size_t word_len;      /**< its length */
    const char *arguments; /**< the rest of the line */
    size_t arguments_len; /**< its length */
} daran_client_help_t;

/** Decode one `h id` line. DARAN_ERR_INVALID_VALUE for a blank line. O(len). */
DARAN_NODISCARD daran_result_t daran_client_parse_help(const daran_client_line_t *line,
                                                       daran_client_help_t *out);

/* ---------------------------------------------------------------- link */

/** The byte transport a port gives the link. */
typedef struct daran_client_transport {
    /** Write all len bytes; false when the port could not (no partial writes). */
    bool (*write)(void *ctx, const char *bytes, size_t len);
    /** Read up to size bytes, waiting at most timeout_ms for the first one
     * (0: only what is already there); the count read, 0 when none came. */
    size_t (*read)(void *ctx, char *buf, size_t size, uint32_t timeout_ms);
    /** A millisecond clock (wraps at 2^32). */
    uint32_t (*now_ms)(void *ctx);
    void *ctx; /**< passed to each function */
} daran_client_transport_t;

/** Called with each reply line of a request (never with the error line that
 * ends a failed one: that is the result). */
typedef void (*daran_client_line_fn)(void *ctx, const daran_client_line_t *line);
/** Called with each telemetry report that arrives, whenever the link reads. */
typedef void (*daran_client_report_fn)(void *ctx, const daran_client_report_t *report);

/** How a link behaves; copied by daran_client_link_init(). */
typedef struct daran_client_link_config {
    bool checksum;           /**< send every request with `*N` (and verify every reply's) */
    uint8_t retries;         /**< extra attempts of a query after a timeout or damaged reply */
    uint32_t quiet_ms;       /**< `h id`'s reply ends this long after its last line; also
                                  how long the link waits for the tail of a damaged reply */
    daran_client_report_fn on_report; /**< telemetry reports, may be NULL */
    void *report_ctx;                 /**< passed to on_report */
    daran_client_line_fn on_stray; /**< lines that belong to no request (a late error of an
                                         unconfirmed silent command), may be NULL */
    void *stray_ctx;                /**< passed to on_stray */
} daran_client_link_config_t;

/** What a request ended with, beside its result. */
typedef struct daran_client_outcome {
    bool drive_error;   /**< the result is an `error:` line the drive sent */
    uint8_t attempts;   /**< how many times the line went out */
    size_t lines;       /**< reply lines handed over (`end` not counted) */
} daran_client_outcome_t;

/** The link's whole state: caller-owned, no heap. */
typedef struct daran_client_link {
    const daran_client_transport_t *transport; /**< the port's byte link */
    daran_client_link_config_t config;         /**< as given to daran_client_link_init() */
    char tx[DARAN_CLIENT_LINE_MAX];            /**< the request line being sent */
    char rx[DARAN_CLIENT_LINE_MAX]; /**< the line being received */
    size_t rx_len;                  /**< its length so far */
    bool rx_overflow;               /**< the line being received did not fit: dropped at its end */
    char in[64];                    /**< bytes read from the transport, not yet framed */
    size_t in_pos;                  /**< the next byte of in[] to frame */
    size_t in_len;                  /**< how many bytes in[] holds */
    char last[DARAN_CLIENT_LINE_MAX]; /**< the last reply line's payload (for `r f g i`) */
    size_t last_len;                /**< its length (0: none) */
    uint32_t bad_lines;             /**< received lines dropped: damaged, too long, unreadable */
} daran_client_link_t;

/** Set up a link. DARAN_ERR_BAD_ARGUMENT for NULL or a transport missing a
 * function. O(1). */
DARAN_NODISCARD daran_result_t daran_client_link_init(daran_client_link_t *link,
                                                      const daran_client_transport_t *transport,
                                                      const daran_client_link_config_t *config);

/** Send `request` and collect its reply within timeout_ms (per attempt):
 * each reply line goes to on_line (may be NULL), the last one's payload also
 * stays in link->last. Telemetry reports that arrive meanwhile go to the
 * config's on_report, whatever came before the request to on_stray.
 * A silent command waits timeout_ms for an `error:` line (0: does not wait
 * at all, for streaming; its error, if any, then reaches on_stray later).
 * Returns DARAN_OK; the drive's error (outcome->drive_error); DARAN_ERR_NO_REPLY
 * when a query got no complete reply in time; DARAN_ERR_CHECKSUM_MISMATCH /
 * DARAN_ERR_INVALID_CHECKSUM / DARAN_ERR_INVALID_VALUE for a damaged reply;
 * DARAN_ERR_BUS_ERROR when the transport refused to write; or a build error
 * (daran_client_build). Only queries are retried (daran_client_may_retry).
 * Blocks at most (retries + 1) * (timeout_ms + quiet_ms) in the transport's
 * read. outcome may be NULL. */
DARAN_NODISCARD daran_result_t daran_client_transact(daran_client_link_t *link,
                                                     const daran_client_request_t *request,
                                                     uint32_t timeout_ms,
                                                     daran_client_line_fn on_line, void *line_ctx,
                                                     daran_client_outcome_t *outcome);

/** Send a line the caller wrote (payload[0..payload_len), no line end),
 * ended with ` *N` when the link's config asks for checksums, and collect a
 * reply of `shape` exactly as daran_client_transact() does; sent once, never
 * retried (the caller's line may move a motor). For a raw console
 * (`daran send`): the drive's answer to a malformed line is its own.
 * DARAN_ERR_LINE_TOO_LONG when the line does not fit the link's buffer. */
DARAN_NODISCARD daran_result_t daran_client_transact_line(daran_client_link_t *link,
                                                          const char *payload, size_t payload_len,
                                                          daran_client_reply_shape_t shape,
                                                          uint32_t timeout_ms,
                                                          daran_client_line_fn on_line,
                                                          void *line_ctx,
                                                          daran_client_outcome_t *outcome);

/** The reply shape of a line by its command word (and `h id properties`'s
 * third field); SILENT for a word the protocol does not have, which the
 * drive answers with `error: unknown command` unless it is a port's own.
 * *known tells the two apart (may be NULL). O(len). */
daran_client_reply_shape_t daran_client_line_shape(const char *payload, size_t len, bool *known);

/** Read whatever the transport holds now (no waiting): telemetry reports to
 * on_report, other lines to on_stray. For a host that streams. O(bytes). */
void daran_client_link_service(daran_client_link_t *link);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_CLIENT_H */
