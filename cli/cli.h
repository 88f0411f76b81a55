/* daran, the command-line tool (docs/cli.md): what its parts share.
 *
 * A session is one opened port with a daran_client link over it. Commands
 * get a session and their own arguments and return an exit status; every
 * failure is reported once, as one line on stderr, by the function that
 * found it (cli_fail). Output for people goes to stdout; with --json each
 * command prints one JSON document instead. */
#ifndef DARAN_CLI_H
#define DARAN_CLI_H

#include <signal.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "daran_client.h"

/** The exit statuses (docs/cli.md, "Exit status"). */
typedef enum cli_status {
    CLI_OK = 0,          /**< done */
    CLI_DRIVE_ERROR = 1, /**< a drive answered `error: …` (not a gateway's `no reply` or
                              `bus error`), or refused what was asked */
    CLI_USAGE = 2,       /**< the command line is wrong */
    CLI_NO_REPLY = 3,    /**< no (readable) reply in time */
    CLI_PORT_ERROR = 4,  /**< the port could not be found, opened, read or written */
    CLI_GATEWAY_BUS_ERROR = 5 /**< a CAN gateway answered `error: bus error`: it could not
                                   send the request on its bus, so the drive behind it
                                   neither got nor refused it */
} cli_status_t;

/** The options every command shares. */
typedef struct cli_options {
    const char *port;    /**< NULL: $DARAN_PORT, else the one /dev/ttyACM* or /dev/ttyUSB* */
    uint32_t baud;       /**< line speed; a pseudo-terminal ignores it */
    bool checksum;       /**< send ` *N` and require it on every reply line */
    uint32_t timeout_ms; /**< how long one request waits for its reply */
    bool timeout_given;  /**< --timeout was on the command line */
    bool json;           /**< one JSON document on stdout instead of text */
} cli_options_t;

#define CLI_DEFAULT_BAUD 115200u
#define CLI_DEFAULT_TIMEOUT_MS 200u
/** How long `h id`'s reply (no end marker) is taken to be over after a gap. */
#define CLI_QUIET_MS 30u

/** Where a telemetry report goes while a command runs. */
typedef void (*cli_report_fn)(void *ctx, const daran_client_report_t *report);

/** One opened port and its link. */
typedef struct cli_session {
    cli_options_t options;
    char port_path[256];
    int fd;
    bool port_failed;      /**< the port reported an error (see port_errno) */
    int port_errno;        /**< the errno of that error */
    const char *port_what; /**< "read" or "write": what failed */
    daran_client_transport_t transport;
    daran_client_link_t link;
    cli_report_fn on_report; /**< the command's report handler; NULL: reports are counted only */
    void *report_ctx;
    uint32_t reports_seen;   /**< reports read while no handler was set */
    daran_client_line_fn on_stray; /**< lines outside any request; NULL: dropped */
    void *stray_ctx;
} cli_session_t;

/* ------------------------------------------------------------ session.c */

/** A session with these options, not connected yet. */
void cli_session_init(cli_session_t *s, const cli_options_t *options);
/** Open the port the options name (or find one) and set up the link, once:
 * commands call it after checking their arguments, so a usage error is
 * told before a missing port. Reports its own failure (CLI_PORT_ERROR,
 * CLI_USAGE). */
cli_status_t cli_session_connect(cli_session_t *s);
/** Close the port. */
void cli_session_close(cli_session_t *s);

/** Send `request`, hand each reply line to on_line, and turn the result into
 * an exit status. On failure one line goes to stderr naming the drive, the
 * request and what happened, unless `quiet` (a caller that reports it
 * itself, like `scan` for the ids that do not answer). *result (may be
 * NULL) gets the link's result. */
cli_status_t cli_transact(cli_session_t *s, const daran_client_request_t *request,
                          daran_client_line_fn on_line, void *line_ctx, bool quiet,
                          daran_result_t *result);

/** Room for one failure's text (cli_failure_text): a request, a port path
 * and the words around them. */
#define CLI_FAILURE_MAX 640u

/** The failure of a request (status and result as cli_transact gave them)
 * as one sentence in buf ("" for CLI_OK), for a caller that words its own
 * message around it; nothing is reported. Returns the status, which is
 * CLI_PORT_ERROR whenever the port failed. A gateway's `error: no reply` is
 * told as such, apart from the link's own timeout, and its `error: bus
 * error` as a request the drive did not get. */
cli_status_t cli_failure_text(cli_session_t *s, const daran_client_request_t *request,
                              cli_status_t status, daran_result_t result, char *buf, size_t size);

/** Report the failure of a request made with `quiet` (status and result as
 * cli_transact gave them) and return status. */
cli_status_t cli_transact_failed(cli_session_t *s, const daran_client_request_t *request,
                                 cli_status_t status, daran_result_t result);

/** The exit status for a link result (`drive_error`: the drive sent it).
 * DARAN_ERR_NO_REPLY is CLI_NO_REPLY whoever said it: the link's timeout
 * or a gateway's `error: no reply` (the drive behind it did not answer).
 * A gateway's `error: bus error` is CLI_GATEWAY_BUS_ERROR, never a refusal. */
cli_status_t cli_status_of(daran_result_t result, bool drive_error);

/** The request as text (no checksum, no line end), for messages. */
size_t cli_request_text(const daran_client_request_t *request, char *buf, size_t size);
/** Report the port's failure (s->port_errno) and return CLI_PORT_ERROR. */
cli_status_t cli_port_status(cli_session_t *s);

/** Wait up to ms for port input (0: only look), handing what arrives to the
 * link (telemetry to the session's handler, other lines to on_stray).
 * Returns early on a signal. */
void cli_session_pump(cli_session_t *s, uint32_t ms);

/* ------------------------------------------------------------ fail.c */

/** Print "daran: <message>" on stderr and return `status`. */
cli_status_t cli_fail(cli_status_t status, const char *format, ...)
    __attribute__((format(printf, 2, 3)));

/* ------------------------------------------------------------ signals.c */

/** Catch SIGINT, SIGTERM and SIGHUP from now on, for a command that must
 * clean up (watch, shell): they set cli_interrupted() and end any wait. */
void cli_catch_signals(void);
/** A caught signal came. */
bool cli_interrupted(void);

/* ------------------------------------------------------------ serial.c */

/** A millisecond clock (monotonic): the link's, and every wait's. */
uint32_t cli_now_ms(void);

/* ------------------------------------------------------------ readback.c */

/** Write `value` to `path` of drive `id` and read it back in one round
 * trip. CLI_OK: kept[] holds what the drive kept. CLI_DRIVE_ERROR: the
 * drive refused the write, *refused says why (nothing reported: the caller
 * words it; kept[] holds the value it still has when it could be read).
 * Other statuses are reported here; when the write went out and only its
 * read-back failed, the message says the write may have taken effect, and
 * when a gateway could not send the write, that the drive did not get it. */
cli_status_t cli_write_read_back(cli_session_t *s, uint8_t id, const char *path,
                                 const daran_client_value_t *value, char *kept, size_t kept_size,
                                 daran_result_t *refused);

/** What a write and its read-back came to. */
typedef struct cli_read_back {
    char kept[DARAN_CLIENT_LINE_MAX]; /**< the value read back; "" when none could be read */
    daran_result_t refused;           /**< CLI_DRIVE_ERROR: the drive's answer to the write */
    daran_result_t result;            /**< any other status: the link's result of the request
                                           that failed (DARAN_ERR_NO_REPLY, a damaged reply's,
                                           a gateway's DARAN_ERR_BUS_ERROR) */
    bool may_have_taken_effect;       /**< the write went out and was not refused: it took
                                           effect (CLI_OK) or may have; false: it had none
                                           (refused, or a gateway could not send it) */
    char failure[CLI_FAILURE_MAX];    /**< any other status: what happened (nothing reported) */
} cli_read_back_t;

/** cli_write_read_back() with the scope given (a drive's own system-scope
 * row, which the tool's table does not know, needs SYSTEM), reporting
 * nothing: the status, and *out says what happened, and whether the write
 * may have taken effect. */
cli_status_t cli_write_read_back_scoped(cli_session_t *s, uint8_t id, const char *path,
                                        daran_client_scope_t scope,
                                        const daran_client_value_t *value, cli_read_back_t *out);

/* ------------------------------------------------------------ args.c */

/** Parse a motor id 1..63 (0 when allow_broadcast). false: not one. */
bool cli_parse_id(const char *text, bool allow_broadcast, uint8_t *id);
/** Parse a `w` value: an integer keeps its kind (UINT, or INT when
 * negative), anything else is a float. false: not a number. */
bool cli_parse_value(const char *text, daran_client_value_t *value);
/** A view of one field of a line. */
typedef struct cli_field {
    const char *text;
    size_t len;
} cli_field_t;
/** Split text[0..len) at blanks: how many fields (the first max in out). */
size_t cli_split_fields(const char *text, size_t len, cli_field_t *out, size_t max);
/** One reply line's text: the ctx of cli_take_line. */
typedef struct cli_text_line {
    char text[DARAN_CLIENT_LINE_MAX];
    size_t len;
} cli_text_line_t;
/** A daran_client_line_fn that copies the line into a cli_text_line_t. */
void cli_take_line(void *ctx, const daran_client_line_t *line);
/** Whether two numbers as the drive prints them are the same value (1e3
 * and 1000, -0 and 0; nan is nan). */
bool cli_same_number(const char *a, const char *b);
/** Parse seconds ("0.5") into milliseconds, 0..3,600,000. */
bool cli_parse_seconds(const char *text, uint32_t *ms);

/* ------------------------------------------------------------ json.c */

/** Write s[0..len) as a JSON string. */
void cli_json_string(FILE *out, const char *s, size_t len);
/** Write `,"name":"text"` (a member after the first, text escaped). */
void cli_json_member(FILE *out, const char *name, const char *text);
/** Write a drive's number text as a JSON number (nan/inf as strings). */
void cli_json_number(FILE *out, const char *s, size_t len);

/* ------------------------------------------------------------ properties.c */

#define CLI_PATH_MAX 96u
#define CLI_PROPERTIES_MAX 256u

/** One property, as discovery lists it (`axis0.` in front of axis rows). */
typedef struct cli_property {
    char path[CLI_PATH_MAX];
    daran_client_type_t type;
    bool writable;
    char unit[24];
    char range[64];
} cli_property_t;

/** A drive's properties. */
typedef struct cli_property_list {
    cli_property_t items[CLI_PROPERTIES_MAX];
    size_t count;
    bool from_drive; /**< from `h id properties` (else the built-in vendor table) */
} cli_property_list_t;

/** The properties of drive `id` whose path starts with `prefix` (NULL: all):
 * from the drive's discovery when it has it, else from the vendor's table
 * built into the tool. Reports its own failure (no reply, port). */
cli_status_t cli_properties_load(cli_session_t *s, uint8_t id, const char *prefix,
                                 cli_property_list_t *out);
/** The built-in table alone (no drive needed). */
void cli_properties_builtin(const char *prefix, cli_property_list_t *out);
/** The property of `path` (with or without `axisN.`) in the list; NULL if absent. */
const cli_property_t *cli_property_find(const cli_property_list_t *list, const char *path);

#endif /* DARAN_CLI_H */
