/* The adopter's fuzz target: the bytes of one input, as a host would send
 * them, go through daran_rx_write() and daran_poll() into a drive whose HAL
 * is the adopter's (daran_test_port()), wrapped in the recording HAL
 * (daran_recorder.h). Every input starts from the port's factory state
 * (reset()); after every request line the port's advance() (when it has one)
 * lets DARAN_FUZZ_ADVANCE_MS pass.
 *
 * Input model: the input is cut at each '\n' into request lines (a last line
 * without one gets one). Each line is queued in as many writes as the
 * receive ring has room for, polling when it is full, so no byte is lost,
 * then polled: the replies and HAL calls seen until then are that line's.
 *
 * After every line it asserts the invariants of docs/security.md that an
 * adopter's port can break or can make visible:
 *  - 4: every reply line is well-formed (daran_fuzz_reply_problem()), and
 *    the answer to one line is bounded (DARAN_FUZZ_REPLY_LINES_MAX lines);
 *  - 2: a line answered with an error made no setter, move or action call,
 *    unless the HAL refused that call (D26): then it was the last call and
 *    the answer is the HAL's error, alone; a HAL refusal is always answered
 *    (except a watchdog feed after an accepted move, D22); a line makes at
 *    most one setter, move or action call, plus that feed;
 *  - 3: a line this harness reads as for another drive (daran_fuzz_line_motor(),
 *    against the id the port's getter gives) has no reply, no setter, move or
 *    action call and no getter call but of axis0.config.can_node_id;
 *  - the core's promises to the HAL (daran_hal.h): ids within the build's
 *    table and not left out by DARAN_OMIT_PROPERTIES, no write of a
 *    read-only property, finite floats and 0/1 bools, valid move kinds and
 *    actions with finite values, moves only in closed loop without a
 *    blocking flag;
 *  - each '\n' ends exactly one line (daran_poll() counts it once).
 * Invariant 1 (no crash, no undefined behaviour, no hang) is the
 * sanitizers', libFuzzer's -timeout and the replay's alarm.
 *
 * A violation prints what was broken, the request, its replies and the HAL
 * calls the recorder saw, then aborts. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "daran_fuzz.h"
#include "daran_recorder.h"
#include "daran_test_port.h"

/* The most reply lines one request may get: `h id properties` lists every
 * property and `end`, `h id` every command. */
#ifndef DARAN_FUZZ_REPLY_LINES_MAX
#define DARAN_FUZZ_REPLY_LINES_MAX ((size_t)DARAN_PROP_COUNT + 64u + 255u)
#endif

/* The drive's state before a line, read through the port's own getters. */
typedef struct before_line {
    bool id_known;
    uint32_t own_id;
    bool state_known;
    bool may_move; /* closed loop, no blocking flag */
} before_line_t;

typedef struct harness {
    const daran_test_port_t *port;
    const char *words[256]; /* the port's command words */
    size_t word_count;
    daran_recorder_t rec;
    daran_drive_t drive;
    /* the request line being run, and its replies */
    const char *line;
    size_t line_len;
    size_t n_replies;
    size_t n_errors;
    char error_payload[DARAN_REPLY_MAX + 1]; /* of the first error reply */
    size_t error_payload_len;
    char replies[1024]; /* the first reply bytes, for messages */
    size_t replies_len;
} harness_t;

static harness_t harness;
static daran_fuzz_totals_t totals;

const daran_fuzz_totals_t *daran_fuzz_totals(void)
{
    return &totals;
}

/* ---- reporting ---- */

#if defined(__GNUC__) || defined(__clang__)
__attribute__((noreturn, format(printf, 1, 2)))
#endif
static void violated(const char *fmt, ...)
{
    const harness_t *h = &harness;
    static char text[4096];
    va_list ap;
    va_start(ap, fmt);
    daran_fuzz_report_violation("", h->port, fmt, ap);
    va_end(ap);
    if (h->line != NULL) {
        fprintf(stderr, "  request:   \"%s\"\n",
                daran_recorder_escape(h->line, h->line_len, text, sizeof text));
        fprintf(stderr, "  replies:   \"%s\"\n",
                daran_recorder_escape(h->replies, h->replies_len, text, sizeof text));
        daran_fuzz_report_calls(&h->rec, "  HAL calls: ");
    }
    fflush(stderr);
    abort();
}

/* ---- the drive ---- */

static void reply_sink(void *ctx, const char *line, size_t len)
{
    (void)ctx; /* the recorder */
    harness_t *h = &harness;
    const char *problem = daran_fuzz_reply_problem(line, len);
    if (problem != NULL) {
        static char text[4 * DARAN_REPLY_MAX + 64];
        violated("invariant 4: the reply \"%s\" (%zu bytes) has %s",
                 daran_recorder_escape(line, len, text, sizeof text), len, problem);
    }
    if (h->line == NULL) {
        violated("invariant 4: a reply written outside daran_poll()");
    }
    h->n_replies++;
    if (h->n_replies > DARAN_FUZZ_REPLY_LINES_MAX) {
        violated("invariant 4: more than %zu reply lines for one request",
                 (size_t)DARAN_FUZZ_REPLY_LINES_MAX);
    }
    size_t keep = sizeof h->replies - h->replies_len;
    memcpy(h->replies + h->replies_len, line, len < keep ? len : keep);
    h->replies_len += len < keep ? len : keep;
    if (len >= 7u && memcmp(line, "error: ", 7) == 0) {
        if (h->n_errors == 0u) {
            /* the payload: without the line end and the checksum tail */
            size_t payload = len - (DARAN_REPLY_CRLF ? 2u : 1u);
            const char *star = memchr(line, '*', payload);
            if (star != NULL) {
                payload = (size_t)(star - line) - 1u;
            }
            memcpy(h->error_payload, line, payload);
            h->error_payload_len = payload;
        }
        h->n_errors++;
    }
}

static void bind_port(harness_t *h)
{
    h->port = daran_test_port();
    const daran_test_port_t *p = h->port;
    const char *problem = daran_fuzz_port_problem(p);
    if (problem != NULL) {
        violated("%s", problem);
    }
    if (p->command_count > sizeof h->words / sizeof h->words[0] ||
        (p->command_count > 0u && p->commands == NULL)) {
        violated("the test port's command table is missing or has over 255 commands");
    }
    for (size_t i = 0; i < p->command_count; i++) {
        h->words[i] = p->commands[i].word != NULL ? p->commands[i].word : "";
    }
    h->word_count = p->command_count;
}

/* Factory state, a fresh recorder around the port's HAL, a fresh drive. */
static void start_input(harness_t *h)
{
    const daran_test_port_t *p = h->port;
    h->line = NULL;
    static daran_hal_t shim;
    shim = daran_recorder_hal;
    shim.write = reply_sink;
    const char *problem = daran_fuzz_start_drive(p, &h->rec, &h->drive, &shim);
    if (problem != NULL) {
        violated("%s", problem);
    }
    if (p->command_count > 0u &&
        daran_recorder_attach_commands(&h->rec, &h->drive, p->commands, p->command_count) !=
            DARAN_OK) {
        violated("daran_set_port_commands() refused the test port's command table");
    }
}

static bool port_get(const harness_t *h, daran_prop_t prop, uint32_t *out)
{
    daran_value_t v;
    v.u64 = 0;
    if (h->port->hal->get(h->port->ctx, prop, &v) != DARAN_OK) {
        return false;
    }
    *out = v.u32;
    return true;
}

static before_line_t read_before(const harness_t *h)
{
    before_line_t b = {false, 0u, false, false};
    uint32_t state = 0;
    uint32_t flags = 0;
    b.id_known = port_get(h, DARAN_PROP_CAN_NODE_ID, &b.own_id) && b.own_id >= 1u &&
                 b.own_id <= DARAN_MOTOR_ID_MAX;
    b.state_known = port_get(h, DARAN_PROP_CURRENT_STATE, &state) &&
                    port_get(h, DARAN_PROP_AXIS_ERROR, &flags);
    b.may_move = state == DARAN_STATE_CLOSED_LOOP && flags == 0u;
    return b;
}

/* Queue @p len bytes without losing one: poll when the ring is full. A
 * poll before the line's '\n' must process no line. */
static void feed(harness_t *h, const void *bytes, size_t len)
{
    const uint8_t *p = bytes;
    while (len > 0u) {
        size_t room = daran_rx_free(&h->drive);
        if (room == 0u) {
            if (daran_poll(&h->drive) != 0u) {
                violated("daran_poll() processed a line before its '\\n' arrived");
            }
            room = daran_rx_free(&h->drive);
            if (room == 0u) {
                violated("the receive ring stays full after daran_poll()");
            }
        }
        size_t chunk = len < room ? len : room;
        size_t queued = daran_rx_write(&h->drive, p, chunk);
        if (queued != chunk) {
            violated("daran_rx_write() queued %zu of %zu bytes it had room for", queued, chunk);
        }
        p += chunk;
        len -= chunk;
    }
}

/* ---- the checks after a line ---- */

/* What daran_hal.h promises the HAL about one call. */
static void check_promises(const daran_call_t *c, const before_line_t *before)
{
    const char *problem = daran_fuzz_call_problem(c, before->state_known, before->may_move);
    if (problem != NULL) {
        violated("%s", problem);
    }
}

/* The phrase the core owes for a HAL refusal (D26: a result that is not a
 * protocol error answers motor fault). */
static const char *refusal_phrase(daran_result_t result)
{
    static const char *const phrases[] = {
        "ok", "unknown command", "invalid command format", "invalid motor", "invalid value",
        "value out of range", "invalid mode", "invalid property", "read only property",
        "invalid checksum", "checksum mismatch", "line too long", "invalid character",
        "no preset", "trajectory infeasible", "estop active", "motor fault", "motor idle",
    };
    unsigned r = (unsigned)result;
    return phrases[r > 0u && r < (unsigned)DARAN_ERR_NO_REPLY ? r
                                                                  : (unsigned)DARAN_ERR_MOTOR_FAULT];
}

static void check_line(const harness_t *h, const before_line_t *before)
{
    const daran_recorder_t *rec = &h->rec;
    if (rec->n_dropped > 0u) {
        violated("more than %u HAL calls for one line", (unsigned)DARAN_RECORDER_CALLS_MAX);
    }
    const daran_call_t *mutations[3] = {NULL, NULL, NULL};
    size_t n_mutations = 0;
    const daran_call_t *refused = NULL;
    size_t refused_at = 0;
    for (size_t i = 0; i < rec->n_calls; i++) {
        const daran_call_t *c = &rec->calls[i];
        check_promises(c, before);
        if (c->kind == DARAN_CALL_GET) {
            continue;
        }
        if (n_mutations < 3u) {
            mutations[n_mutations] = c;
        }
        n_mutations++;
        if (refused == NULL && c->result != DARAN_OK) {
            refused = c;
            refused_at = i;
        }
    }
    bool move_then_feed = n_mutations == 2u && mutations[0]->kind == DARAN_CALL_MOVE &&
                          mutations[1]->kind == DARAN_CALL_ACTION &&
                          mutations[1]->action == DARAN_ACTION_FEED_WATCHDOG;
    if (n_mutations > 2u || (n_mutations == 2u && !move_then_feed)) {
        violated("invariant 2: %zu setter, move or action calls for one line (one at most, "
                 "and a watchdog feed after an accepted move, D22)",
                 n_mutations);
    }
    if (h->n_errors > 0u && h->n_replies != 1u) {
        violated("an error answered with %zu other reply lines (an error is the whole answer)",
                 h->n_replies - 1u);
    }
    totals.lines++;
    totals.answered_error += h->n_errors > 0u ? 1u : 0u;
    totals.mutating += n_mutations > 0u ? 1u : 0u;
    totals.refused += refused != NULL ? 1u : 0u;
    if (refused != NULL) {
        if (refused_at + 1u != rec->n_calls) {
            violated("invariant 2: the HAL refused a call and the core called it again (D26: "
                     "nothing after a refusal)");
        }
        if (move_then_feed && refused == mutations[1]) {
            if (h->n_errors != 0u) {
                violated("a failed watchdog feed after an accepted move was answered with an "
                         "error (D22: the move stands)");
            }
        } else {
            const char *phrase = refusal_phrase(refused->result);
            size_t n = strlen(phrase);
            if (h->n_errors != 1u || h->error_payload_len != 7u + n ||
                memcmp(h->error_payload + 7, phrase, n) != 0) {
                violated("D26: the HAL refused a call with %d, which the line must answer "
                         "alone as `error: %s`",
                         (int)refused->result, phrase);
            }
        }
    } else if (h->n_errors > 0u && n_mutations > 0u) {
        violated("invariant 2: a line answered with an error made a setter, move or action "
                 "call the HAL did not refuse");
    }

    int motor = daran_fuzz_line_motor(h->line, h->line_len, h->words, h->word_count);
    if (before->id_known && motor > 0 && (uint32_t)motor != before->own_id) {
        totals.other_drive++;
        bool other_getter = false;
        for (size_t i = 0; i < rec->n_calls; i++) {
            other_getter = other_getter || rec->calls[i].kind != DARAN_CALL_GET ||
                           rec->calls[i].prop != DARAN_PROP_CAN_NODE_ID;
        }
        if (h->n_replies > 0u || n_mutations > 0u || other_getter) {
            violated("invariant 3: a line for drive %d (this one is %u) was answered or reached "
                     "the HAL beyond reading axis0.config.can_node_id",
                     motor, (unsigned)before->own_id);
        }
    }
}

/* One request line: its bytes, its '\n', the poll, the checks. */
static void run_line(harness_t *h, const uint8_t *bytes, size_t len)
{
    before_line_t before = read_before(h);
    daran_recorder_clear(&h->rec);
    h->line = (const char *)bytes;
    h->line_len = len;
    h->n_replies = 0;
    h->n_errors = 0;
    h->error_payload_len = 0;
    h->replies_len = 0;
    feed(h, bytes, len);
    feed(h, "\n", 1u);
    size_t lines = daran_poll(&h->drive);
    if (lines != 1u) {
        violated("daran_poll() processed %zu lines for one '\\n'", lines);
    }
    check_line(h, &before);
    h->line = NULL;
    if (h->port->advance != NULL) {
        h->port->advance(h->port->ctx, DARAN_FUZZ_ADVANCE_MS);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    harness_t *h = &harness;
    if (h->port == NULL) {
        bind_port(h);
    }
    start_input(h);
    size_t start = 0;
    for (size_t i = 0; i < size; i++) {
        if (data[i] == '\n') {
            run_line(h, data + start, i - start);
            start = i + 1u;
        }
    }
    if (start < size) {
        run_line(h, data + start, size - start);
    }
    return 0;
}
