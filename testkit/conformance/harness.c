/* The conformance suite's harness: one check at a time against the port,
 * each line's replies and HAL calls kept for the report, the requirements'
 * counts and the summary. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "conformance.h"

/* What each requirement says, in docs/conformance.md's words (shortened). */
static const char *const titles[REQ_COUNT] = {
    [REQ_FACTORY_STATE] = "reset gives the factory state (node id 1, closed loop, no error flag)",
    [REQ_READ] = "r answers one value of the property's type, the value get returned, with no HAL effect",
    [REQ_DISCOVERY] = "discovery lists exactly the build's properties with their type, access and range",
    [REQ_SERVED] = "the properties the protocol reads itself are served, never refused",
    [REQ_WRITE] = "w of a valid value makes one set with that value and reads back (or the HAL refuses: motor fault)",
    [REQ_READ_ONLY] = "w of a read-only property answers read only property, no HAL effect",
    [REQ_WRITE_OUT_OF_RANGE] = "w of a value outside the declared range answers value out of range, no HAL effect",
    [REQ_WRITE_MALFORMED] = "w of a malformed value answers invalid value, no HAL effect",
    [REQ_UNKNOWN_PATH] = "r and w of a path the build lacks answer invalid property, no HAL effect",
    [REQ_MOVE] = "a valid motion line makes one move of the right kind and values, then one FEED_WATCHDOG",
    [REQ_MOVE_TARGETS] = "after a move, r reads its targets and given rates back from their properties",
    [REQ_ACTION] = "ss se sr sc sz st u make one action of their kind and answer nothing; ms makes none",
    [REQ_QUERY] = "f g i e h answer their lines in their format, with no HAL effect",
    [REQ_ESTOP] = "st puts the drive idle (current_state 1) with the e-stop flag in axis0.error",
    [REQ_CLEAR_ERRORS] = "sc clears the flags, the drive stays idle; requested_state 8 closes the loop",
    [REQ_CLEAR_REGISTER] = "w <error register> 0 clears that register, the drive stays idle",
    [REQ_SET_ZERO] = "sz makes the current position 0",
    [REQ_NODE_ID] = "a new can_node_id is the drive's id from the next line on",
    [REQ_REQUESTED_STATE] = "w requested_state 1 idles the drive (current_state 1), 8 closes the loop",
    [REQ_SAVE] = "a value saved with ss survives sr; a change made after ss does not",
    [REQ_ERASE] = "se erases the saved configuration: defaults after sr",
    [REQ_BAD_CHECKSUM] = "a malformed checksum field answers invalid checksum, no HAL effect",
    [REQ_CHECKSUM_MISMATCH] = "a wrong checksum answers checksum mismatch *N, no HAL effect",
    [REQ_CHECKSUM_OK] = "a right checksum runs the line the same way and every reply carries its own",
    [REQ_INVALID_CHARACTER] = "a byte outside printable ASCII answers invalid character, no HAL effect",
    [REQ_LINE_TOO_LONG] = "a line longer than DARAN_LINE_MAX answers line too long, no HAL effect",
    [REQ_UNKNOWN_COMMAND] = "an unknown command word answers unknown command, no HAL effect",
    [REQ_FIELD_COUNT] = "a wrong number of fields answers invalid command format, no HAL effect",
    [REQ_INVALID_VALUE] = "a malformed value answers invalid value, no HAL effect",
    [REQ_OUT_OF_RANGE] = "a value out of its range answers value out of range, no HAL effect",
    [REQ_INVALID_MODE] = "a mode outside its set answers invalid mode, no HAL effect",
    [REQ_INVALID_MOTOR] = "a malformed or too large motor id answers invalid motor, no HAL effect",
    [REQ_OTHER_ID] = "a line for another id is silent: no reply, no HAL effect, no get but can_node_id",
    [REQ_NOT_RUNNING] = "motion after st answers estop active, after st + sc motor idle; no move",
    [REQ_NO_PRESET] = "a multi-motor start without a preset answers no preset, no HAL effect",
    [REQ_REPLY_FORM] = "every reply line is printable ASCII, ends in the line end, fits DARAN_REPLY_MAX, right *N",
    [REQ_CAN_STATUS] = "a fast read at the own node or node 0 answers one status frame with T, E and the values r reads",
    [REQ_CAN_REPLY_STATE] = "with enable_reply_state 1 a valid motion frame answers one status frame, a refused one none",
    [REQ_CAN_FILTER] = "the port's filter passes the own node, node 0 and status frames, and follows a new node id",
    [REQ_CAN_DUPLICATE_ID] = "a status frame with the own id sets can.error bit 0 through the HAL, keeps running, sc clears",
    [REQ_CAN_NODE_GUARD] = "with can.config.timeout_ms, frames feed the guard; without one for that long the drive idles",
    [REQ_CAN_HEARTBEAT] = "can.config.heartbeat_ms sends the status frame every that many ms of drive time, 0 none",
    [REQ_CAN_REFUSED] = "a frame the drive must ignore gets no frame back and no HAL effect (a well-formed one: the feed)",
};

/* Detailed reports per requirement; later failures get one line each. */
#define DETAILED_FAILURES 3u
#define TRANSCRIPT_MAX 24576u
#define REPLY_MAX_KEPT 65536u
#define NOTES_MAX 8192u
#define FORM_REPORTS_MAX 10u

typedef struct conf_count {
    unsigned passed, failed, skipped;
} conf_count_t;

static struct harness {
    const daran_test_port_t *port;
    bool verbose;
    bool transcripts; /* every check's, not only the failures' */
    daran_drive_t drive;
    daran_hal_t hal; /* the drive's: the recorder's, with this file's reply sink and the CAN watch */
    daran_recorder_t rec;

    /* the check in progress */
    bool in_check;
    conf_req_t req;
    char subject[160];
    bool failed;
    char expected[1024];
    char transcript[TRANSCRIPT_MAX];
    size_t transcript_len;

    /* the last exchange */
    char reply[REPLY_MAX_KEPT + 1];
    size_t reply_len;
    size_t reply_lines;
    char line[2048];
    size_t line_len;

    conf_count_t counts[REQ_COUNT];
    char notes[NOTES_MAX];
    size_t notes_len;
    unsigned form_failures;
} h;

const char *conf_req_id(conf_req_t req)
{
    static char ids[REQ_COUNT][8];
    if (ids[req][0] == '\0' && req >= REQ_CAN_FIRST) {
        (void)snprintf(ids[req], sizeof ids[req], "CAN%u", (unsigned)(req - REQ_CAN_FIRST) % 100u + 1u);
    } else if (ids[req][0] == '\0') {
        (void)snprintf(ids[req], sizeof ids[req], "C%u", (unsigned)req % 1000u + 1u);
    }
    return ids[req];
}

const char *conf_req_title(conf_req_t req)
{
    return titles[req];
}

void conf_list_requirements(void)
{
    for (int r = 0; r < REQ_COUNT; r++) {
        printf("%-4s %s\n", conf_req_id((conf_req_t)r), titles[r]);
    }
}

/* ---- text helpers ---- */

unsigned conf_xor(const char *text, size_t len)
{
    unsigned x = 0;
    for (size_t i = 0; i < len; i++) {
        x ^= (unsigned char)text[i];
    }
    return x;
}

/* ---- the reply sink: every line checked as it is written ---- */

static void form_failure(const char *what, const char *line, size_t len)
{
    h.form_failures++;
    if (h.form_failures > FORM_REPORTS_MAX) {
        return;
    }
    char sent[512];
    char got[512];
    (void)daran_recorder_escape(h.line, h.line_len, sent, sizeof sent);
    (void)daran_recorder_escape(line, len, got, sizeof got);
    printf("FAIL %s %s\n  expected: %s\n  > %s\n    reply line: \"%s\"\n",
           conf_req_id(REQ_REPLY_FORM), titles[REQ_REPLY_FORM], what, sent, got);
}

static void check_form(const char *line, size_t len)
{
    const char *end = DARAN_REPLY_CRLF ? "\r\n" : "\n";
    size_t end_len = strlen(end);
    if (len < end_len || len > DARAN_REPLY_MAX || memcmp(line + len - end_len, end, end_len) != 0) {
        form_failure(DARAN_REPLY_CRLF ? "one whole line ending in \\r\\n, at most DARAN_REPLY_MAX bytes"
                                      : "one whole line ending in \\n, at most DARAN_REPLY_MAX bytes",
                     line, len);
        return;
    }
    size_t payload = len - end_len;
    for (size_t i = 0; i < payload; i++) {
        unsigned char c = (unsigned char)line[i];
        if (c < 0x20u || c > 0x7Eu) {
            form_failure("printable ASCII only before the line end", line, len);
            return;
        }
    }
    /* a checksum tail " *N" must carry the XOR of what precedes the '*' */
    const char *star = memchr(line, '*', payload);
    if (star != NULL && star > line && star[-1] == ' ') {
        size_t digits = payload - (size_t)(star + 1 - line);
        unsigned value = 0;
        bool numeric = digits >= 1u && digits <= 3u;
        for (size_t i = 0; numeric && i < digits; i++) {
            char c = star[1 + i];
            numeric = c >= '0' && c <= '9';
            value = value * 10u + (unsigned)(c - '0');
        }
        if (numeric && value != conf_xor(line, (size_t)(star - line))) {
            form_failure("the checksum tail to be the XOR of the bytes before its '*'", line, len);
        }
    }
}

static void sink(void *ctx, const char *line, size_t len)
{
    check_form(line, len);
    daran_recorder_write(ctx, line, len);
    size_t room = REPLY_MAX_KEPT - h.reply_len;
    size_t kept = len < room ? len : room;
    memcpy(h.reply + h.reply_len, line, kept);
    h.reply_len += kept;
    h.reply[h.reply_len] = '\0';
    h.reply_lines++;
}

/* ---- checks ---- */

void conf_harness_init(const daran_test_port_t *port, bool verbose, bool transcripts)
{
    memset(&h, 0, sizeof h);
    h.port = port;
    h.verbose = verbose || transcripts;
    h.transcripts = transcripts;
}

const daran_test_port_t *conf_port(void)
{
    return h.port;
}

daran_hal_t *conf_drive_port(void)
{
    return &h.hal;
}

static void bind_drive(void)
{
    daran_recorder_init(&h.rec, h.port->hal, h.port->ctx);
    h.rec.log_gets = true;
    h.hal = daran_recorder_hal;
    h.hal.write = sink;
    daran_result_t result = daran_init(&h.drive, &h.hal, &h.rec);
    if (result != DARAN_OK) {
        /* nothing can be checked: the program and its core disagree */
        printf("FATAL daran_init() refused the drive (%s): this program and its core were built "
               "with different options headers\n0 passed, 1 failed\n",
               daran_result_phrase(result));
        exit(2);
    }
    if (h.port->commands != NULL && h.port->command_count > 0u &&
        daran_recorder_attach_commands(&h.rec, &h.drive, h.port->commands,
                                       h.port->command_count) != DARAN_OK) {
        printf("FATAL daran_set_port_commands() refused the test port's command table\n"
               "0 passed, 1 failed\n");
        exit(2);
    }
}

bool conf_restart(void)
{
    h.reply_len = 0;
    h.reply[0] = '\0';
    h.reply_lines = 0;
    if (!h.port->reset(h.port->ctx)) {
        conf_fail("the test port's reset() to succeed (it returned false)");
        return false;
    }
    bind_drive();
    if (h.transcript_len > 0u) {
        conf_transcript("  (reset)\n");
    }
    return true;
}

bool conf_begin(conf_req_t req, const char *subject)
{
    h.in_check = true;
    h.req = req;
    h.failed = false;
    h.expected[0] = '\0';
    h.transcript_len = 0;
    h.transcript[0] = '\0';
    (void)snprintf(h.subject, sizeof h.subject, "%s", subject);
    return conf_restart();
}

void conf_abandon(void)
{
    h.in_check = false;
}

void conf_transcript(const char *fmt, ...)
{
    if (h.transcript_len + 1u >= sizeof h.transcript) {
        return;
    }
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(h.transcript + h.transcript_len, sizeof h.transcript - h.transcript_len, fmt, ap);
    va_end(ap);
    if (n > 0) {
        h.transcript_len += (size_t)n;
        if (h.transcript_len >= sizeof h.transcript) {
            h.transcript_len = sizeof h.transcript - 1u;
        }
    }
}

void conf_transcript_calls(void)
{
    if (h.rec.n_calls == 0u && h.rec.n_dropped == 0u) {
        conf_transcript("    HAL calls seen: none\n");
        return;
    }
    conf_transcript("    HAL calls seen:\n");
    for (size_t i = 0; i < h.rec.n_calls; i++) {
        char call[256];
        (void)daran_call_describe(&h.rec.calls[i], call, sizeof call);
        conf_transcript("      %s\n", call);
    }
    if (h.rec.n_dropped > 0u) {
        conf_transcript("      ... and %lu more\n", (unsigned long)h.rec.n_dropped);
    }
}

void conf_rec_clear(void)
{
    daran_recorder_clear(&h.rec);
}

daran_drive_t *conf_drive(void)
{
    return &h.drive;
}

void conf_send_n(const char *line, size_t len)
{
    daran_recorder_clear(&h.rec);
    h.reply_len = 0;
    h.reply[0] = '\0';
    h.reply_lines = 0;
    h.line_len = len < sizeof h.line ? len : sizeof h.line - 1u;
    memcpy(h.line, line, h.line_len);
    h.line[h.line_len] = '\0';

    (void)daran_process_line(&h.drive, line, len);

    char text[700];
    (void)daran_recorder_escape(line, len, text, sizeof text);
    conf_transcript("  > %s%s\n", text, len > 300u ? " ..." : "");
    if (h.reply_len == 0u) {
        conf_transcript("    reply: (none)\n");
    } else {
        size_t shown = h.reply_len < 600u ? h.reply_len : 600u;
        (void)daran_recorder_escape(h.reply, shown, text, sizeof text);
        conf_transcript("    reply: \"%s\"%s\n", text,
                       shown < h.reply_len ? " ... (cut; more lines)" : "");
    }
    conf_transcript_calls();
}

void conf_send(const char *line)
{
    conf_send_n(line, strlen(line));
}

void conf_advance(uint32_t ms)
{
    if (h.port->advance != NULL) {
        h.port->advance(h.port->ctx, ms);
        conf_transcript("  (drive time: %lu ms)\n", (unsigned long)ms);
    }
}

const char *conf_reply(void)
{
    return h.reply;
}

size_t conf_reply_len(void)
{
    return h.reply_len;
}

size_t conf_reply_lines(void)
{
    return h.reply_lines;
}

const daran_recorder_t *conf_rec(void)
{
    return &h.rec;
}

void conf_fail(const char *fmt, ...)
{
    size_t used = strlen(h.expected);
    if (used + 8u >= sizeof h.expected) {
        h.failed = true;
        return;
    }
    if (used > 0u) {
        memcpy(h.expected + used, "\n            ", 13);
        used += 13u;
        h.expected[used] = '\0';
    }
    va_list ap;
    va_start(ap, fmt);
    (void)vsnprintf(h.expected + used, sizeof h.expected - used, fmt, ap);
    va_end(ap);
    h.failed = true;
}

bool conf_failed(void)
{
    return h.failed;
}

void conf_end(void)
{
    conf_count_t *count = &h.counts[h.req];
    h.in_check = false;
    if (!h.failed) {
        count->passed++;
        if (h.verbose) {
            printf("ok   %s %s\n", conf_req_id(h.req), h.subject);
        }
        if (h.transcripts) {
            printf("%s", h.transcript);
        }
        return;
    }
    count->failed++;
    printf("FAIL %s %s: %s\n", conf_req_id(h.req), titles[h.req], h.subject);
    printf("  expected: %s\n", h.expected);
    if (count->failed <= DETAILED_FAILURES || h.verbose) {
        printf("%s", h.transcript);
    } else if (count->failed == DETAILED_FAILURES + 1u) {
        printf("  (later failures of %s: without their transcripts; --verbose shows them)\n",
               conf_req_id(h.req));
    }
}

void conf_count(conf_req_t req, bool passed)
{
    if (passed) {
        h.counts[req].passed++;
    } else {
        h.counts[req].failed++;
    }
}

void conf_skip(conf_req_t req, const char *subject, const char *why)
{
    h.counts[req].skipped++;
    if (h.verbose) {
        printf("skip %s %s: %s\n", conf_req_id(req), subject, why);
    }
}

void conf_note(const char *fmt, ...)
{
    if (h.notes_len + 2u >= sizeof h.notes) {
        return;
    }
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(h.notes + h.notes_len, sizeof h.notes - h.notes_len - 1u, fmt, ap);
    va_end(ap);
    if (n > 0) {
        h.notes_len += (size_t)n;
        if (h.notes_len > sizeof h.notes - 2u) {
            h.notes_len = sizeof h.notes - 2u;
        }
        h.notes[h.notes_len++] = '\n';
        h.notes[h.notes_len] = '\0';
    }
}

/* ---- expectations ---- */

bool conf_expect_no_effect(void)
{
    if (daran_recorder_no_effect(&h.rec)) {
        return true;
    }
    conf_fail("no HAL set, move or action for this line");
    return false;
}

bool conf_expect_silent(void)
{
    if (h.reply_len == 0u) {
        return true;
    }
    conf_fail("no reply");
    return false;
}

bool conf_expect_one_line(void)
{
    if (h.reply_lines == 1u) {
        return true;
    }
    conf_fail("exactly one reply line (got %lu)", (unsigned long)h.reply_lines);
    return false;
}

bool conf_expect_error(const char *phrase, bool checksum)
{
    char want[160];
    int n = snprintf(want, sizeof want, "error: %s", phrase);
    size_t len = n > 0 ? (size_t)n : 0u;
    if (checksum) {
        unsigned sum = conf_xor(want, len) ^ (unsigned)' ';
        n = snprintf(want + len, sizeof want - len, " *%u", sum);
        len += n > 0 ? (size_t)n : 0u;
    }
    (void)snprintf(want + len, sizeof want - len, "%s", DARAN_REPLY_CRLF ? "\r\n" : "\n");
    bool ok = strcmp(h.reply, want) == 0;
    if (!ok) {
        char text[200];
        (void)daran_recorder_escape(want, strlen(want), text, sizeof text);
        conf_fail("the reply \"%s\"", text);
    }
    if (!daran_recorder_no_effect(&h.rec)) {
        conf_fail("no HAL set, move or action for a refused line");
        ok = false;
    }
    return ok;
}

/* ---- the report ---- */

int conf_report(void)
{
    unsigned passed = 0;
    unsigned failed = 0;
    unsigned skipped = 0;
    conf_count(REQ_REPLY_FORM, h.form_failures == 0u);
    if (h.form_failures > FORM_REPORTS_MAX) {
        printf("  (%u more malformed reply lines not shown)\n", h.form_failures - FORM_REPORTS_MAX);
    }
    if (h.notes_len > 0u) {
        printf("\nnotes:\n%s", h.notes);
    }
    printf("\nrequirements (checks passed / failed / skipped):\n");
    for (int r = 0; r < REQ_COUNT; r++) {
        const conf_count_t *c = &h.counts[r];
        const char *verdict = c->failed > 0u ? "FAILED" : (c->passed > 0u ? "ok" : "skipped");
        printf("  %-4s %-7s %4u / %u / %u  %s\n", conf_req_id((conf_req_t)r), verdict, c->passed,
               c->failed, c->skipped, titles[r]);
        passed += c->passed;
        failed += c->failed;
        skipped += c->skipped;
    }
    printf("\nport: %s; %u checks skipped (not in this build, or nothing to check: --verbose says why)\n",
           h.port->name != NULL ? h.port->name : "(unnamed)", skipped);
    printf("%u passed, %u failed\n", passed, failed);
    return failed == 0u ? 0 : 1;
}
