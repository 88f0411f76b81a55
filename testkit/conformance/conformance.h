/* The conformance suite's internals: the requirements, the harness that
 * runs one check at a time against the adopter's HAL (wrapped in the
 * recording HAL), and the model of the build's properties.
 *
 * A check resets the port, binds a fresh drive to it, sends lines, and
 * compares the replies and the HAL calls with what the requirement says;
 * the transcript of each line is kept so a failure can be reported with the
 * lines sent, the replies and the HAL calls seen. docs/conformance.md lists
 * the requirements. */
#ifndef DARAN_CONFORMANCE_H
#define DARAN_CONFORMANCE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_ascii.h"
#include "daran_recorder.h"
#include "daran_test_port.h"

/* Builds whose core has no checksum option check checksums always. */
#ifndef DARAN_ENABLE_CHECKSUM
#define CONF_CHECKSUMS 1
#else
#define CONF_CHECKSUMS DARAN_ENABLE_CHECKSUM
#endif

/* The requirements, in the order of docs/conformance.md (C1 is the first). */
typedef enum conf_req {
    REQ_FACTORY_STATE,
    REQ_READ,
    REQ_DISCOVERY,
    REQ_SERVED,
    REQ_WRITE,
    REQ_READ_ONLY,
    REQ_WRITE_OUT_OF_RANGE,
    REQ_WRITE_MALFORMED,
    REQ_UNKNOWN_PATH,
    REQ_MOVE,
    REQ_MOVE_TARGETS,
    REQ_ACTION,
    REQ_QUERY,
    REQ_ESTOP,
    REQ_CLEAR_ERRORS,
    REQ_CLEAR_REGISTER,
    REQ_SET_ZERO,
    REQ_NODE_ID,
    REQ_REQUESTED_STATE,
    REQ_SAVE,
    REQ_ERASE,
    REQ_BAD_CHECKSUM,
    REQ_CHECKSUM_MISMATCH,
    REQ_CHECKSUM_OK,
    REQ_INVALID_CHARACTER,
    REQ_LINE_TOO_LONG,
    REQ_UNKNOWN_COMMAND,
    REQ_FIELD_COUNT,
    REQ_INVALID_VALUE,
    REQ_OUT_OF_RANGE,
    REQ_INVALID_MODE,
    REQ_INVALID_MOTOR,
    REQ_OTHER_ID,
    REQ_NOT_RUNNING,
    REQ_NO_PRESET,
    REQ_REPLY_FORM,
    /* the CAN front end (check_can.c), numbered CAN1.. in the report */
    REQ_CAN_STATUS,
    REQ_CAN_REPLY_STATE,
    REQ_CAN_FILTER,
    REQ_CAN_DUPLICATE_ID,
    REQ_CAN_NODE_GUARD,
    REQ_CAN_HEARTBEAT,
    REQ_CAN_REFUSED,
    REQ_COUNT
} conf_req_t;

#define REQ_CAN_FIRST REQ_CAN_STATUS

/* The drive's id after a reset (daran_test_port.h) and one that is not it. */
#define CONF_ID 1u
#define CONF_OTHER_ID 2u

/* ---- harness.c ---- */

void conf_harness_init(const daran_test_port_t *port, bool verbose, bool transcripts);
const daran_test_port_t *conf_port(void);
/* Begin a check of @p req about @p subject (a path, a line): reset the port,
 * bind a fresh drive. False when the reset failed (the check has failed). */
bool conf_begin(conf_req_t req, const char *subject);
/* Within a check: reset the port and bind a fresh drive again (false: the
 * reset failed, and the check with it). */
bool conf_restart(void);
/* Leave a check without counting it (it turned out not to apply). */
void conf_abandon(void);
/* Send one line (without its '\n') through daran_process_line(). */
void conf_send(const char *line);
void conf_send_n(const char *line, size_t len);
/* Let drive time pass when the port can (daran_test_port_t.advance). */
void conf_advance(uint32_t ms);
/* The drive the check bound (for the CAN front end). */
daran_drive_t *conf_drive(void);
/* The drive's port description: the recorder's functions and the reply sink
 * (a CAN check wraps its CAN functions, can_harness.c). The drive reads it
 * at each call. */
daran_hal_t *conf_drive_port(void);
/* Add to the check's transcript (printf-style), and the HAL calls the
 * recorder holds, as conf_send() writes them. */
void conf_transcript(const char *fmt, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
void conf_transcript_calls(void);
/* The last exchange: the replies as written (line ends included), their
 * line count, the result daran_process_line() returned, the recorder. */
const char *conf_reply(void);
size_t conf_reply_len(void);
size_t conf_reply_lines(void);
const daran_recorder_t *conf_rec(void);
void conf_rec_clear(void);
/* The check fails; the message says what was expected (printf-style). */
void conf_fail(const char *fmt, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
bool conf_failed(void);
/* End the check: count it, report it when it failed. */
void conf_end(void);
/* A check that cannot run on this build or port, with the reason. */
void conf_skip(conf_req_t req, const char *subject, const char *why);
/* An observation for the report's notes (printf-style). */
void conf_note(const char *fmt, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
/* Print the notes, the table of requirements and the summary line; the
 * program's exit status. */
int conf_report(void);
const char *conf_req_id(conf_req_t req);
const char *conf_req_title(conf_req_t req);
void conf_list_requirements(void);
/* Count one check of @p req passed or failed without a transcript (the
 * reply-form check is made on every line and counted once). */
void conf_count(conf_req_t req, bool passed);

/* Expectations on the last exchange; each fails the check with a message
 * and returns false when it does not hold. */
bool conf_expect_error(const char *phrase, bool checksum);
bool conf_expect_silent(void);       /* no reply */
bool conf_expect_no_effect(void);    /* no HAL set, move or action */
bool conf_expect_one_line(void);     /* exactly one reply line */
/* The exchange had a checksum field: ` *N` of "<payload> ". */
unsigned conf_xor(const char *text, size_t len);

/* ---- model.c: the build's properties ---- */

typedef enum conf_range_kind {
    RANGE_ANY,
    RANGE_NON_NEGATIVE,
    RANGE_POSITIVE,
    RANGE_NON_POSITIVE,
    RANGE_SET,
    RANGE_INTERVAL,
    RANGE_UNKNOWN
} conf_range_kind_t;

#define CONF_SET_MAX 16

typedef struct conf_range {
    conf_range_kind_t kind;
    double lo, hi;               /* RANGE_INTERVAL */
    double set[CONF_SET_MAX];    /* RANGE_SET */
    size_t set_count;
} conf_range_t;

typedef enum conf_presence {
    PRESENT_UNKNOWN, /* not probed yet */
    PRESENT_IN_BUILD,
    PRESENT_LEFT_OUT /* `r` answers invalid property without a HAL call */
} conf_presence_t;

typedef struct conf_prop {
    const char *path;       /* as in the list: without "axisN." */
    bool axis;              /* an axisN. path */
    daran_prop_type_t type;
    bool rw;
    const char *range_text; /* the range `w` checks (discovery's text when it differs) */
    conf_range_t range;
    const char *unit;
    bool header_omits;      /* DARAN_OMIT_PROPERTIES lists it */
    conf_presence_t presence;
    bool read_refused;      /* `r` answered the HAL's refusal */
    bool write_refused;     /* a valid `w` answered the HAL's refusal */
    bool write_ok;          /* a valid `w` was accepted and read back */
    daran_value_t factory;  /* read after a reset (when readable) */
    bool factory_known;
} conf_prop_t;

extern conf_prop_t conf_props[DARAN_PROP_COUNT];

void conf_model_init(void);
void conf_parse_range(const char *text, conf_range_t *range);
bool conf_in_build(daran_prop_t prop);
/* The wire path for id @p id ("axis1.controller.config.pos_gain"). */
void conf_wire_path(daran_prop_t prop, unsigned id, char *buf, size_t size);
/* `r` / `w` lines for id @p id: "r axis1.x", "r x 1", "w axis1.x V", "w x V 1". */
void conf_read_line(daran_prop_t prop, unsigned id, char *buf, size_t size);
void conf_write_line(daran_prop_t prop, unsigned id, const char *value, char *buf, size_t size);
/* Parse a reply value of @p type (one token, the reply number format). */
bool conf_parse_reply_value(daran_prop_type_t type, const char *text, size_t len,
                            daran_value_t *out);
/* Text of a value of @p type (floats: enough digits to read back exactly). */
void conf_format_value(daran_prop_type_t type, daran_value_t value, char *buf, size_t size);
/* Values equal within the type's rounding (floats: a relative 1e-5, so a
 * HAL may convert units on the way). */
bool conf_same_value(daran_prop_type_t type, daran_value_t a, daran_value_t b);
/* The value a text stands for, as the core reads it. */
bool conf_value_of_text(daran_prop_type_t type, const char *text, daran_value_t *out);
/* Valid values of the row's range (the first differs from @p current when
 * the range allows), as texts; returns how many. */
size_t conf_valid_values(daran_prop_t prop, const daran_value_t *current, char values[][40],
                         size_t max);
/* Values the range refuses (value out of range), as texts. */
size_t conf_invalid_values(daran_prop_t prop, char values[][40], size_t max);
/* Read @p prop through `r` for id @p id within the current check; false
 * (and the check failed, unless @p quiet) when the reply is not one value. */
bool conf_read_value(daran_prop_t prop, unsigned id, daran_value_t *out, bool quiet);
/* A property path that no build has. */
#define CONF_NO_SUCH_PATH "no.such.property"

/* ---- the checks ---- */

bool conf_check_factory_state(void);
void conf_check_properties(void);
void conf_check_commands(void);
void conf_check_persistence(void);
void conf_check_bad_input(void);
void conf_check_can(void);

/* ---- can_harness.c: the CAN front end of a check (DARAN_ENABLE_CAN) ---- */


#if DARAN_ENABLE_CAN
/* Begin a CAN check: conf_begin(), then a fresh daran_can_t bound to the
 * drive, the port's CAN functions in its description (can_send wrapped). False when the check
 * has failed already (reset, daran_can_init(), can.config.protocol 0). */
bool conf_can_begin(conf_req_t req, const char *subject);
/* Within a CAN check: reset and bind both front ends again. */
bool conf_can_restart(void);
/* An 8-byte standard data frame at @p node with @p code. */
daran_can_frame_t conf_can_frame(unsigned node, unsigned code, const uint8_t data[8]);
/* Hand @p frame over (through the port's can_deliver when it has one), then
 * daran_can_poll(): the frames sent and the HAL calls are this frame's. */
void conf_can_deliver(const daran_can_frame_t *frame);
/* @p ms of drive time, one millisecond at a time, each followed by
 * daran_can_poll(): the frames sent and the setter, move and action calls
 * are collected with the time they came at. */
void conf_can_wait(uint32_t ms);
/* What the last deliver or wait sent: count, frame, when (ms into the wait). */
size_t conf_can_sent_count(void);
const daran_can_frame_t *conf_can_sent(size_t i);
uint32_t conf_can_sent_at(size_t i);
/* Actions of @p kind the last wait made, and when the first came. */
size_t conf_can_wait_actions(daran_action_t kind, uint32_t *first_at);
/* Setters, moves and actions the last wait made. */
size_t conf_can_wait_effects(void);
/* Expectations on the last deliver; each fails the check and returns false
 * when it does not hold. */
bool conf_can_expect_nothing_sent(void);
/* Exactly one frame, the status frame of node @p node with T, E, position,
 * velocity and torque as `r` reads them now. */
bool conf_can_expect_status(unsigned node);
/* Every frame sent was taken by the port's send (it answered true). */
bool conf_can_expect_taken(void);
#endif

/* The families of commands the bad-input checks vary (check_commands.c). */
typedef struct conf_family {
    const char *word;
    const char *setup;       /* a line sent first ("ms {id} ..."), or NULL */
    const char *valid;       /* a valid line, "{id}" for the motor id */
    bool motion;             /* needs closed loop: a HAL move */
    bool multi;              /* a multi-motor command */
    bool help;               /* the `h` command */
    bool query;              /* answers lines, no HAL effect */
    const char *too_few;     /* lines with a wrong field count (NULL: none) */
    const char *too_many;
    const char *malformed;   /* invalid value */
    const char *out_of_range;
    const char *out_of_range_setup; /* a preset whose value is out of range */
    const char *bad_mode;
    const char *bad_mode_setup;
} conf_family_t;

/* The families of this build (multi and help only when compiled in), with
 * the r and w lines filled in from the build's properties. */
size_t conf_families(const conf_family_t **families);
/* "{id}" in @p template replaced by @p id. */
void conf_fill(const char *template_text, const char *id, char *buf, size_t size);
/* Send a family's setup line (if any) then its line with the id text. */
void conf_send_family_line(const conf_family_t *family, const char *line_template,
                           const char *setup_template, const char *id);

#endif /* DARAN_CONFORMANCE_H */
