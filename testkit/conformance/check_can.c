/* The CAN requirements (CAN1-CAN7): what the port's CAN glue (its
 * transmit, clock and receive filter) and its HAL (the node guard's action,
 * the can.error write, the settings it must keep) owe the CAN front end
 * (docs/can.md). They run when the test port's hal gives can_send and are
 * counted as skipped otherwise; the filter requirement needs can_deliver,
 * the guard and heartbeat advance(). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "conformance.h"

#if DARAN_ENABLE_CAN

/* Command codes and system sub-codes (docs/can.md). */
#define CODE_SYSTEM 0x08u
#define CODE_TRACK 0x19u
#define CODE_TRAPEZOID 0x1Au
#define CODE_VELOCITY 0x1Cu
#define CODE_READ 0x1Eu
#define CODE_WRITE 0x1Fu
#define ADDRESS_NODE_ID 31001u
#define ADDRESS_FW_VERSION 6u
#define GUARD_MS 50u
#define HEARTBEAT_MS 10u

static void put_u16(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
}

static void put_u32(uint8_t *p, uint32_t v)
{
    put_u16(p, v);
    put_u16(p + 2, v >> 16);
}

static void put_f32(uint8_t *p, float v)
{
    uint32_t bits;
    memcpy(&bits, &v, sizeof bits);
    put_u32(p, bits);
}

static daran_can_frame_t fast_read(unsigned node)
{
    return conf_can_frame(node, CODE_READ, NULL);
}

/* A property write frame: address, type code 3 (u32), value. */
static daran_can_frame_t write_u32(unsigned node, uint32_t address, uint32_t value)
{
    uint8_t data[8] = {0};
    put_u16(data, address);
    put_u16(data + 2, 3u);
    put_u32(data + 4, value);
    return conf_can_frame(node, CODE_WRITE, data);
}

/* A direct motion frame: f32 @0, two 16-bit fields. */
static daran_can_frame_t motion(unsigned code, float target, uint32_t field4, uint32_t field6)
{
    uint8_t data[8] = {0};
    put_f32(data, target);
    put_u16(data + 4, field4);
    put_u16(data + 6, field6);
    return conf_can_frame(CONF_ID, code, data);
}

static void deliver(daran_can_frame_t frame)
{
    conf_can_deliver(&frame);
}

/* Send an ASCII line that must be accepted silently (a setting, sc, st). */
static bool accepted(const char *line)
{
    conf_send(line);
    if (conf_reply_len() == 0u) {
        return true;
    }
    conf_fail("`%s` to be accepted with no reply", line);
    return false;
}

/* `w <prop> <value>` for the drive at @p id, accepted silently. */
static bool write_setting(daran_prop_t prop, unsigned id, unsigned long value)
{
    char text[24];
    char line[160];
    (void)snprintf(text, sizeof text, "%lu", value);
    conf_write_line(prop, id, text, line, sizeof line);
    return accepted(line);
}

/* Setters, moves and actions of the last exchange: their count, and how many
 * are of @p kind (and, for actions, @p action). */
static size_t effects(daran_call_kind_t kind, daran_action_t action, size_t *of_kind)
{
    const daran_recorder_t *rec = conf_rec();
    size_t n = 0;
    *of_kind = 0;
    for (size_t i = 0; i < rec->n_calls; i++) {
        const daran_call_t *call = &rec->calls[i];
        if (call->kind == DARAN_CALL_GET) {
            continue;
        }
        n++;
        if (call->kind == kind && (kind != DARAN_CALL_ACTION || call->action == action)) {
            (*of_kind)++;
        }
    }
    return n;
}

/* The frame made no HAL effect but, when @p fed, the watchdog feed every
 * frame for the drive makes (can.md C18). */
static bool expect_only_feed(bool fed)
{
    size_t feeds = 0;
    size_t n = effects(DARAN_CALL_ACTION, DARAN_ACTION_FEED_WATCHDOG, &feeds);
    if (fed && (n != 1u || feeds != 1u)) {
        conf_fail("one FEED_WATCHDOG action and no other setter, move or action (C18: a "
                  "well-formed frame for the drive feeds, whatever its content)");
        return false;
    }
    if (!fed && n != 0u) {
        conf_fail("no HAL setter, move or action (not even the watchdog feed: the frame is not "
                  "for this drive, or not a frame of the protocol)");
        return false;
    }
    return true;
}

static bool expect_moves(size_t want)
{
    size_t moves = 0;
    (void)effects(DARAN_CALL_MOVE, DARAN_ACTION_FEED_WATCHDOG, &moves);
    if (moves == want) {
        return true;
    }
    conf_fail("%lu HAL move (saw %lu)", (unsigned long)want, (unsigned long)moves);
    return false;
}

static bool read_u32(daran_prop_t prop, unsigned id, uint32_t *out)
{
    daran_value_t v;
    if (!conf_read_value(prop, id, &v, false)) {
        return false;
    }
    *out = v.u32;
    return true;
}

static bool expect_reads(daran_prop_t prop, unsigned id, uint32_t mask, uint32_t want,
                         const char *what)
{
    uint32_t value = 0;
    if (!read_u32(prop, id, &value)) {
        return false;
    }
    if ((value & mask) == want) {
        return true;
    }
    conf_fail("%s (it reads %lu)", what, (unsigned long)value);
    return false;
}

static bool skipped_without(conf_req_t req, daran_prop_t prop, const char *path)
{
    if (conf_in_build(prop)) {
        return false;
    }
    char why[160];
    (void)snprintf(why, sizeof why, "%s is not in this build", path);
    conf_skip(req, "every check", why);
    return true;
}

static bool skipped_without_time(conf_req_t req)
{
    if (conf_port()->advance != NULL) {
        return false;
    }
    conf_skip(req, "every check", "the test port has no advance(): no drive time passes");
    return true;
}

/* ---- CAN1: the status frame ---- */

static void check_status(void)
{
    static const struct {
        const char *subject;
        unsigned node;
        const char *before;
        uint32_t ms;
    } cases[] = {
        {"fast read at node 1", CONF_ID, NULL, 0},
        {"fast read at node 0 (broadcast)", 0, NULL, 0},
        {"fast read after st 1 (E set)", CONF_ID, "st 1", 0},
        {"fast read 300 ms into t 1 30 (moving)", CONF_ID, "t 1 30", 300},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        if (cases[i].ms > 0u && conf_port()->advance == NULL) {
            conf_skip(REQ_CAN_STATUS, cases[i].subject, "the test port has no advance()");
            continue;
        }
        if (conf_can_begin(REQ_CAN_STATUS, cases[i].subject) &&
            (cases[i].before == NULL || accepted(cases[i].before))) {
            conf_advance(cases[i].ms);
            deliver(fast_read(cases[i].node));
            (void)expect_only_feed(true);
            (void)conf_can_expect_taken();
            (void)conf_can_expect_status(CONF_ID);
        }
        conf_end();
    }
}

/* ---- CAN2: the automatic status reply ---- */

static void check_reply_state(void)
{
    const float nan_value = (float)NAN;
    static const char *const refused_subjects[] = {
        "0x01A with cruise 0 (refused: value out of range)",
        "0x01C with mode 7 (refused: invalid mode)",
        "0x019 with a NaN target (refused: invalid value)",
    };
    daran_can_frame_t refused[3];
    refused[0] = motion(CODE_TRAPEZOID, 10.0f, 0u, 1000u);
    refused[1] = motion(CODE_VELOCITY, 10.0f, 0u, 7u);
    refused[2] = motion(CODE_TRACK, nan_value, 0u, 0u);
    if (skipped_without(REQ_CAN_REPLY_STATE, DARAN_PROP_ENABLE_REPLY_STATE,
                        "config.extra_setting.enable_reply_state")) {
        return;
    }
    if (conf_can_begin(REQ_CAN_REPLY_STATE, "0x019 to 10 deg, enable_reply_state 0: no frame")) {
        deliver(motion(CODE_TRACK, 10.0f, 0u, 0u));
        (void)expect_moves(1u);
        (void)conf_can_expect_nothing_sent();
    }
    conf_end();
    if (conf_can_begin(REQ_CAN_REPLY_STATE, "0x019 to 10 deg, enable_reply_state 1: one status frame") &&
        write_setting(DARAN_PROP_ENABLE_REPLY_STATE, CONF_ID, 1u)) {
        deliver(motion(CODE_TRACK, 10.0f, 0u, 0u));
        (void)expect_moves(1u);
        (void)conf_can_expect_taken();
        (void)conf_can_expect_status(CONF_ID);
    }
    conf_end();
    if (conf_can_begin(REQ_CAN_REPLY_STATE,
                       "0x019 after st 1, enable_reply_state 1: one status frame (E set), no move") &&
        write_setting(DARAN_PROP_ENABLE_REPLY_STATE, CONF_ID, 1u) && accepted("st 1")) {
        deliver(motion(CODE_TRACK, 10.0f, 0u, 0u));
        (void)expect_moves(0u);
        (void)conf_can_expect_status(CONF_ID);
    }
    conf_end();
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        if (conf_can_begin(REQ_CAN_REPLY_STATE, refused_subjects[i]) &&
            write_setting(DARAN_PROP_ENABLE_REPLY_STATE, CONF_ID, 1u)) {
            deliver(refused[i]);
            (void)expect_only_feed(true);
            (void)conf_can_expect_nothing_sent();
        }
        conf_end();
    }
}

/* ---- CAN3: the acceptance filter ---- */

/* A status frame at @p node reached the drive: the core read and wrote
 * can.error (C22). */
static bool expect_duplicate_seen(unsigned node)
{
    deliver(conf_can_frame(node, 0x01u, NULL));
    size_t sets = 0;
    (void)effects(DARAN_CALL_SET, DARAN_ACTION_FEED_WATCHDOG, &sets);
    if (sets == 1u) {
        return true;
    }
    conf_fail("a status frame at node %u (the own id) to pass the filter: the drive writes "
              "can.error when it sees one (no set came)",
              node);
    return false;
}

static void check_filter(void)
{
    if (conf_port()->can_deliver == NULL) {
        conf_skip(REQ_CAN_FILTER, "every check",
                  "the test port has no can_deliver: frames reach daran_can_receive() past no filter");
        return;
    }
    if (conf_can_begin(REQ_CAN_FILTER, "a fast read at node 1 passes")) {
        deliver(fast_read(CONF_ID));
        (void)conf_can_expect_status(CONF_ID);
    }
    conf_end();
    if (conf_can_begin(REQ_CAN_FILTER, "a fast read at node 0 (broadcast) passes")) {
        deliver(fast_read(0));
        (void)conf_can_expect_status(CONF_ID);
    }
    conf_end();
    bool duplicates = conf_in_build(DARAN_PROP_CAN_ERROR);
    if (!duplicates) {
        conf_skip(REQ_CAN_FILTER, "status frames at the own node", "can.error is not in this build");
    } else {
        if (conf_can_begin(REQ_CAN_FILTER, "a status frame at node 1 passes")) {
            (void)expect_duplicate_seen(CONF_ID);
        }
        conf_end();
    }
    if (conf_can_begin(REQ_CAN_FILTER, "after w axis1.config.can_node_id 5, node 5 passes") &&
        write_setting(DARAN_PROP_CAN_NODE_ID, CONF_ID, 5u)) {
        deliver(fast_read(5u));
        if (conf_can_expect_status(5u) && duplicates) {
            (void)expect_duplicate_seen(5u);
        }
    }
    conf_end();
    if (conf_can_begin(REQ_CAN_FILTER, "after a CAN write of can_node_id 7, node 7 passes")) {
        deliver(write_u32(CONF_ID, ADDRESS_NODE_ID, 7u));
        deliver(fast_read(7u));
        (void)conf_can_expect_status(7u);
    }
    conf_end();
}

/* ---- CAN4: duplicate ids ---- */

static void check_duplicate_id(void)
{
    if (skipped_without(REQ_CAN_DUPLICATE_ID, DARAN_PROP_CAN_ERROR, "can.error")) {
        return;
    }
    for (unsigned code = 1u; code <= 7u; code += 2u) {
        char subject[96];
        (void)snprintf(subject, sizeof subject, "status frame 0x%03X (code 0x%02X) at node 1",
                       CONF_ID << 5 | code, code);
        if (conf_can_begin(REQ_CAN_DUPLICATE_ID, subject)) {
            deliver(conf_can_frame(CONF_ID, code, NULL));
            (void)conf_can_expect_nothing_sent();
            (void)expect_moves(0u);
            (void)expect_reads(DARAN_PROP_CAN_ERROR, CONF_ID, 1u, 1u,
                               "can.error bit 0 set (duplicate CAN id, can.md C22): the HAL must "
                               "keep the core's write");
            if (code == 1u) {
                (void)expect_reads(DARAN_PROP_CURRENT_STATE, CONF_ID, 0xFFFFFFFFu,
                                   DARAN_STATE_CLOSED_LOOP,
                                   "the drive to keep running (current_state 8)");
                (void)accepted("t 1 10");
            }
        }
        conf_end();
    }
    static const char *const clears[] = {"sc 1", "w can.error 0 1"};
    for (size_t i = 0; i < 2u; i++) {
        char subject[96];
        (void)snprintf(subject, sizeof subject, "%s after a duplicate clears can.error", clears[i]);
        if (conf_can_begin(REQ_CAN_DUPLICATE_ID, subject)) {
            deliver(conf_can_frame(CONF_ID, 0x01u, NULL));
            if (accepted(clears[i])) {
                (void)expect_reads(DARAN_PROP_CAN_ERROR, CONF_ID, 0xFFFFFFFFu, 0u,
                                   "can.error to read 0");
            }
        }
        conf_end();
    }
}

/* ---- CAN5: the node guard ---- */

/* Arm the guard with a frame and let it trip; false when it did not. */
static bool trip_guard(void)
{
    deliver(fast_read(CONF_ID));
    conf_can_wait(GUARD_MS + 10u);
    uint32_t at = 0;
    if (conf_can_wait_actions(DARAN_ACTION_NODE_GUARD, &at) != 1u) {
        conf_fail("one NODE_GUARD action %u ms after the last frame", GUARD_MS);
        return false;
    }
    return true;
}

static void check_node_guard(void)
{
    if (skipped_without(REQ_CAN_NODE_GUARD, DARAN_PROP_CAN_TIMEOUT_MS, "can.config.timeout_ms") ||
        skipped_without_time(REQ_CAN_NODE_GUARD)) {
        return;
    }
    if (conf_can_begin(REQ_CAN_NODE_GUARD, "timeout_ms 50: not armed before a frame for the drive") &&
        write_setting(DARAN_PROP_CAN_TIMEOUT_MS, CONF_ID, GUARD_MS)) {
        conf_can_wait(3u * GUARD_MS);
        if (conf_can_wait_effects() != 0u) {
            conf_fail("no setter, move or action while the guard is not armed");
        }
        (void)expect_reads(DARAN_PROP_CURRENT_STATE, CONF_ID, 0xFFFFFFFFu, DARAN_STATE_CLOSED_LOOP,
                           "the drive to keep running (current_state 8)");
    }
    conf_end();
    if (conf_can_begin(REQ_CAN_NODE_GUARD,
                       "timeout_ms 50: frames at node 1 and node 0 feed it; it trips 50 ms after the last") &&
        write_setting(DARAN_PROP_CAN_TIMEOUT_MS, CONF_ID, GUARD_MS)) {
        deliver(fast_read(CONF_ID));
        conf_can_wait(GUARD_MS - 10u);
        bool early = conf_can_wait_actions(DARAN_ACTION_NODE_GUARD, NULL) != 0u;
        deliver(fast_read(0));
        conf_can_wait(GUARD_MS - 10u);
        early = early || conf_can_wait_actions(DARAN_ACTION_NODE_GUARD, NULL) != 0u;
        if (early) {
            conf_fail("no NODE_GUARD action while frames come within %u ms (is now_ms() the drive "
                      "time advance() passes, in milliseconds?)",
                      GUARD_MS);
        }
        conf_can_wait(30u);
        uint32_t at = 0;
        size_t trips = conf_can_wait_actions(DARAN_ACTION_NODE_GUARD, &at);
        if (!early && (trips != 1u || at < 10u || at > 12u)) {
            conf_fail("one NODE_GUARD action %u ms after the last frame (the 10th ms of this wait; "
                      "saw %lu, the first at %lu ms)",
                      GUARD_MS, (unsigned long)trips, (unsigned long)at);
        }
        (void)expect_reads(DARAN_PROP_CURRENT_STATE, CONF_ID, 0xFFFFFFFFu, DARAN_STATE_IDLE,
                           "the drive idle after the guard tripped (current_state 1)");
        (void)expect_reads(DARAN_PROP_AXIS_ERROR, CONF_ID, DARAN_FLAG_WATCHDOG, DARAN_FLAG_WATCHDOG,
                           "axis0.error to have the watchdog flag (0x800) after the guard tripped");
        conf_can_wait(2u * GUARD_MS);
        if (conf_can_wait_actions(DARAN_ACTION_NODE_GUARD, NULL) != 0u) {
            conf_fail("the guard to trip once, until a frame arms it again");
        }
    }
    conf_end();
    if (conf_can_begin(REQ_CAN_NODE_GUARD,
                       "after the guard tripped: sc 1 and w axis1.requested_state 8 close the loop") &&
        write_setting(DARAN_PROP_CAN_TIMEOUT_MS, CONF_ID, GUARD_MS) && trip_guard() &&
        accepted("sc 1") && write_setting(DARAN_PROP_REQUESTED_STATE, CONF_ID, DARAN_STATE_CLOSED_LOOP)) {
        (void)expect_reads(DARAN_PROP_CURRENT_STATE, CONF_ID, 0xFFFFFFFFu, DARAN_STATE_CLOSED_LOOP,
                           "closed loop again (current_state 8)");
        (void)accepted("t 1 10");
    }
    conf_end();
}

/* ---- CAN6: the heartbeat ---- */

/* Every frame of the last wait is a status frame of @p node, taken. */
static bool expect_heartbeats(unsigned node, size_t least, size_t most)
{
    size_t n = conf_can_sent_count();
    if (n < least || n > most) {
        conf_fail("%lu to %lu heartbeats (saw %lu: is now_ms() the drive time advance() passes, "
                  "in milliseconds?)",
                  (unsigned long)least, (unsigned long)most, (unsigned long)n);
        return false;
    }
    for (size_t i = 0; i < n; i++) {
        const daran_can_frame_t *f = conf_can_sent(i);
        if (f->dlc != 8u || f->flags != 0u || (f->id >> 5) != node || (f->id & 0x19u) != 1u) {
            conf_fail("every heartbeat a status frame of node %u", node);
            return false;
        }
    }
    return conf_can_expect_taken();
}

static void check_heartbeat(void)
{
    if (skipped_without(REQ_CAN_HEARTBEAT, DARAN_PROP_CAN_HEARTBEAT_MS, "can.config.heartbeat_ms") ||
        skipped_without_time(REQ_CAN_HEARTBEAT)) {
        return;
    }
    if (conf_can_begin(REQ_CAN_HEARTBEAT, "heartbeat_ms 0 (factory): nothing in 200 ms")) {
        conf_can_wait(200u);
        (void)conf_can_expect_nothing_sent();
    }
    conf_end();
    if (conf_can_begin(REQ_CAN_HEARTBEAT,
                       "heartbeat_ms 10 after a fast read: 10 status frames in 100 ms, none heard "
                       "back as a duplicate id") &&
        write_setting(DARAN_PROP_CAN_HEARTBEAT_MS, CONF_ID, HEARTBEAT_MS)) {
        deliver(fast_read(CONF_ID));
        conf_can_wait(10u * HEARTBEAT_MS);
        (void)expect_heartbeats(CONF_ID, 9u, 11u);
        if (conf_in_build(DARAN_PROP_CAN_ERROR)) {
            /* a controller that hears its own frames (loopback) makes them duplicates */
            (void)expect_reads(DARAN_PROP_CAN_ERROR, CONF_ID, 0xFFFFFFFFu, 0u,
                               "can.error to stay 0: the drive must not receive its own frames");
        }
    }
    conf_end();
    if (conf_can_begin(REQ_CAN_HEARTBEAT, "heartbeat_ms 10 after can_node_id 5: from node 5") &&
        write_setting(DARAN_PROP_CAN_HEARTBEAT_MS, CONF_ID, HEARTBEAT_MS) &&
        write_setting(DARAN_PROP_CAN_NODE_ID, CONF_ID, 5u)) {
        conf_can_wait(3u * HEARTBEAT_MS);
        (void)expect_heartbeats(5u, 2u, 4u);
    }
    conf_end();
}

/* ---- CAN7: frames to ignore ---- */

static void check_refused(void)
{
    uint8_t data[8] = {0};
    struct refused_frame {
        const char *subject;
        daran_can_frame_t frame;
        bool fed;
    } frames[16];
    size_t n = 0;
    daran_can_frame_t f = fast_read(CONF_ID);
    f.dlc = 7;
    frames[n++] = (struct refused_frame){"a fast read with DLC 7", f, false};
    f = conf_can_frame(0, 0x09u, NULL);
    f.dlc = 0;
    frames[n++] = (struct refused_frame){"0x009 with DLC 0 (send_command()'s default)", f, false};
    f = fast_read(CONF_ID);
    f.flags = DARAN_CAN_FRAME_REMOTE;
    frames[n++] = (struct refused_frame){"a fast read as a remote frame", f, false};
    f = fast_read(CONF_ID);
    f.flags = DARAN_CAN_FRAME_EXTENDED;
    frames[n++] = (struct refused_frame){"a fast read's id 0x03E as an extended id", f, false};
    f = fast_read(CONF_ID);
    f.flags = DARAN_CAN_FRAME_FD;
    frames[n++] = (struct refused_frame){"a fast read as a CAN FD frame", f, false};
    frames[n++] = (struct refused_frame){"unknown code 0x0E at node 1", conf_can_frame(CONF_ID, 0x0Eu, NULL),
                                         false};
    frames[n++] = (struct refused_frame){"a fast read at node 2", fast_read(CONF_OTHER_ID), false};
    put_u32(data, 0x30u);
    frames[n++] = (struct refused_frame){"system sub-code 0x30 (unknown)",
                                         conf_can_frame(CONF_ID, CODE_SYSTEM, data), true};
    put_u32(data, 0x10u);
    frames[n++] = (struct refused_frame){"start 0x10 without a preset",
                                         conf_can_frame(CONF_ID, CODE_SYSTEM, data), true};
    frames[n++] = (struct refused_frame){"a write of can_node_id 0 (out of range)",
                                         write_u32(CONF_ID, ADDRESS_NODE_ID, 0u), true};
    frames[n++] = (struct refused_frame){"a write of fw_version (read only)",
                                         write_u32(CONF_ID, ADDRESS_FW_VERSION, 7u), true};
    memset(data, 0, sizeof data);
    put_u16(data, 0xFFFFu);
    frames[n++] = (struct refused_frame){"a read of address 65535 (none)",
                                         conf_can_frame(CONF_ID, CODE_READ, data), true};
    frames[n++] = (struct refused_frame){"0x01A with cruise 0", motion(CODE_TRAPEZOID, 10.0f, 0u, 1000u),
                                         true};
    for (size_t i = 0; i < n; i++) {
        if (conf_can_begin(REQ_CAN_REFUSED, frames[i].subject)) {
            deliver(frames[i].frame);
            (void)conf_can_expect_nothing_sent();
            (void)expect_only_feed(frames[i].fed);
        }
        conf_end();
    }
}

void conf_check_can(void)
{
    if (conf_port()->hal->can_send == NULL) {
        for (int r = REQ_CAN_FIRST; r < REQ_COUNT; r++) {
            conf_skip((conf_req_t)r, "every check", "the test port's hal gives no can_send");
        }
        conf_note("CAN: the test port's hal gives no can_send, so CAN1-CAN7 were skipped "
                  "(daran_test_port.h, docs/conformance.md)");
        return;
    }
    check_status();
    check_reply_state();
    check_filter();
    check_duplicate_id();
    check_node_guard();
    check_heartbeat();
    check_refused();
}

#else /* DARAN_ENABLE_CAN */

void conf_check_can(void)
{
    for (int r = REQ_CAN_FIRST; r < REQ_COUNT; r++) {
        conf_skip((conf_req_t)r, "every check", "the CAN front end is compiled out (DARAN_ENABLE_CAN 0)");
    }
}

#endif /* DARAN_ENABLE_CAN */
