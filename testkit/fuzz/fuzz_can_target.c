/* The adopter's CAN fuzz target (daran_ascii_add_can_fuzz_target): frames
 * given through the port's own receive path (daran_test_port_t.can_deliver,
 * its acceptance filter; daran_can_receive() when it has none) into a CAN
 * front end bound to a drive whose HAL is the adopter's, wrapped in the
 * recording HAL, and whose transmit and clock are the port's (its
 * can_send wrapped so every frame the drive sends is seen). Every input starts
 * from reset().
 *
 * Input: records of DARAN_FUZZ_CAN_RECORD (12) bytes, one frame each (a
 * shorter tail is dropped):
 *   [0]     milliseconds of drive time before the frame: advance(1) and
 *           daran_can_poll() for each (none when the port has no advance());
 *   [1]     bits 0-3 the DLC (above 8: 8); bit 7 set: bits 4-6 are the
 *           flags (remote, extended id, FD), else none;
 *   [2..3]  the id, little-endian (11 bits; an extended id keeps 16);
 *   [4..11] the data bytes.
 * Time passes only between frames, each millisecond followed by a poll, and
 * a frame is polled at the millisecond of the poll before it, when the guard
 * and the heartbeat are not looked at again (docs/can.md): so the frames
 * sent and the HAL calls of a frame's poll are that frame's.
 *
 * After each frame, by this harness's own reading of docs/can.md:
 *  - a frame the drive must ignore (not an 8-byte standard data frame, for
 *    another node, an unknown code, or any frame while can.config.protocol
 *    was 0 at init) gets no frame back and makes no setter, move or action
 *    call; a status frame with the own id at most writes can.error with bit
 *    0 set (a duplicate id);
 *  - a frame for the drive feeds the watchdog first (C18), then makes at
 *    most what its code allows (a system command its one action or a
 *    start's move; a motion its move, then a feed; a write a set of the row
 *    at its address; a read or preset nothing; a motion whose target is not
 *    finite, whose bandwidth, acceleration or ramp rate is negative, whose
 *    cruise is not above 0 or whose mode is outside C1's sets nothing but
 *    the feed, and no frame back), and sends at most what its
 *    code allows: a fast read exactly one status frame, a read one reply of
 *    a known address echoing it with the row's type code and the value the
 *    HAL's getter gives, a motion or preset at most one status frame,
 *    system commands and writes nothing;
 *  - every frame sent is an 8-byte standard data frame of the own node, a
 *    read reply or a status frame whose T, E and position are the HAL's;
 *  - every HAL call keeps daran_hal.h's promises (daran_fuzz_call_problem()).
 * After each millisecond: no call but the node guard's NODE_GUARD action,
 * exactly when the guard is due (armed by a frame for the drive, not tripped
 * since, can.config.timeout_ms of drive time without one), and at most one
 * frame, a status frame, exactly when the heartbeat is due
 * (can.config.heartbeat_ms since the last): a clock that is not the drive
 * time advance() passes breaks these.
 * Crashes, undefined behaviour and hangs are the sanitizers', libFuzzer's
 * -timeout and the replay's alarm. A violation prints what broke, the
 * frame, the frames sent and the HAL calls, then aborts. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "daran_fuzz.h"
#include "daran_recorder.h"
#include "daran_test_port.h"

#if !DARAN_ENABLE_CAN
#error "the CAN fuzz target needs a core with DARAN_ENABLE_CAN 1"
#endif

#define SENT_MAX 16u
#define CODE_SYSTEM 0x08u
#define CODE_PRESET 0x0Cu
#define CODE_READ 0x1Eu
#define CODE_WRITE 0x1Fu

typedef struct can_harness {
    const daran_test_port_t *port;
    daran_recorder_t rec;
    daran_drive_t drive;
    daran_can_t can;
    daran_hal_t shim; /* the drive's: the recorder's, no replies, the port's CAN functions wrapped */
    bool enabled;        /* can.config.protocol was 1 (or unreadable) at init */
    uint32_t now;        /* drive time since reset(), as this harness passed it */
    bool armed, tripped; /* the node guard, as docs/can.md says it goes */
    uint32_t fed_at;
    uint32_t heartbeat_at;
    /* the step being checked */
    const char *step;
    daran_can_frame_t frame;
    bool has_frame;
    daran_can_frame_t sent[SENT_MAX];
    size_t n_sent;
} can_harness_t;

static can_harness_t harness;
static daran_fuzz_totals_t totals;

const daran_fuzz_totals_t *daran_fuzz_totals(void)
{
    return &totals;
}

static void describe(const daran_can_frame_t *f, char *buf, size_t size)
{
    int n = snprintf(buf, size, "0x%03lX DLC %u flags %u:", (unsigned long)f->id, f->dlc, f->flags);
    size_t used = n > 0 ? (size_t)n : 0u;
    for (unsigned i = 0; i < 8u && used + 4u < size; i++) {
        n = snprintf(buf + used, size - used, " %02x", f->data[i]);
        used += n > 0 ? (size_t)n : 0u;
    }
}

#if defined(__GNUC__) || defined(__clang__)
__attribute__((noreturn, format(printf, 1, 2)))
#endif
static void violated(const char *fmt, ...)
{
    const can_harness_t *h = &harness;
    static char text[4096];
    va_list ap;
    va_start(ap, fmt);
    daran_fuzz_report_violation("CAN, ", h->port, fmt, ap);
    va_end(ap);
    fprintf(stderr, "  step:       %s, %lu ms into the input\n", h->step != NULL ? h->step : "?",
            (unsigned long)h->now);
    if (h->has_frame) {
        describe(&h->frame, text, sizeof text);
        fprintf(stderr, "  frame:      %s\n", text);
    }
    for (size_t i = 0; i < h->n_sent; i++) {
        describe(&h->sent[i], text, sizeof text);
        fprintf(stderr, "  sent:       %s\n", text);
    }
    daran_fuzz_report_calls(&h->rec, "  HAL calls:  ");
    fflush(stderr);
    abort();
}

/* ---- the port's glue, wrapped ---- */

/* The drive's context is the recorder; the harness is this file's one. */
static bool wrapped_send(void *ctx, const daran_can_frame_t *frame)
{
    (void)ctx;
    can_harness_t *h = &harness;
    if (h->n_sent == SENT_MAX) {
        violated("more than %u frames sent in one step", SENT_MAX);
    }
    h->sent[h->n_sent++] = *frame;
    return h->port->hal->can_send(h->port->ctx, frame);
}

static uint32_t wrapped_now(void *ctx)
{
    (void)ctx;
    const can_harness_t *h = &harness;
    return h->port->hal->now_ms(h->port->ctx);
}

static void wrapped_hook(void *ctx, uint32_t subcode, uint16_t data1, uint16_t data2)
{
    (void)ctx;
    const can_harness_t *h = &harness;
    if (h->port->hal->can_system != NULL) {
        h->port->hal->can_system(h->port->ctx, subcode, data1, data2);
    }
}

/* The HAL's value, read past the recorder; a row left out reads 0, as the
 * core reads it. */
static bool port_get(const can_harness_t *h, daran_prop_t prop, daran_value_t *out)
{
    out->u64 = 0;
    if (daran_fuzz_prop_omitted(prop)) {
        return false;
    }
    if (h->port->hal->get(h->port->ctx, prop, out) != DARAN_OK) {
        out->u64 = 0;
        return false;
    }
    return true;
}

static uint32_t port_u32(const can_harness_t *h, daran_prop_t prop)
{
    daran_value_t v;
    (void)port_get(h, prop, &v);
    return v.u32;
}

/* ---- the checks ---- */

static bool is_status_code(uint32_t code)
{
    return (code & 1u) != 0u && code < 0x18u;
}

static bool known_code(uint32_t code)
{
    return code == CODE_SYSTEM || code == CODE_PRESET || (code >= 0x19u && code <= CODE_WRITE);
}

static uint32_t get_u16(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8;
}

static uint32_t get_u32(const uint8_t *p)
{
    return get_u16(p) | get_u16(p + 2) << 16;
}

/* Every frame the drive sent in this step: its shape, its node, and for a
 * status frame T, E and the position the HAL gives now. */
static void check_sent(const can_harness_t *h, uint32_t own)
{
    for (size_t i = 0; i < h->n_sent; i++) {
        const daran_can_frame_t *f = &h->sent[i];
        uint32_t code = f->id & 0x1Fu;
        if (f->dlc != 8u || f->flags != 0u || f->id > 0x7FFu) {
            violated("a frame sent that is not an 8-byte standard data frame");
        }
        if (f->id >> 5 != own) {
            violated("a frame sent from node %lu; the drive is node %lu", (unsigned long)(f->id >> 5),
                     (unsigned long)own);
        }
        if (code == CODE_READ) {
            continue;
        }
        if (!is_status_code(code) || (code & 0x18u) != 0u) {
            violated("a frame sent with code 0x%02lX: neither a read reply nor a status frame",
                     (unsigned long)code);
        }
        bool done = port_u32(h, DARAN_PROP_TRAJECTORY_DONE) != 0u;
        bool error = port_u32(h, DARAN_PROP_AXIS_ERROR) != 0u;
        if (((code & 2u) != 0u) != done || ((code & 4u) != 0u) != error) {
            violated("a status frame whose T or E bit is not controller.trajectory_done / "
                     "axis0.error != 0 as the HAL gives them (%d, %d)",
                     done, error);
        }
        if (get_u32(f->data) != port_u32(h, DARAN_PROP_POS_ESTIMATE)) {
            violated("a status frame whose position is not output_shaft.pos_estimate");
        }
    }
}

static void check_promises(const can_harness_t *h, bool state_known, bool may_move)
{
    for (size_t i = 0; i < h->rec.n_calls; i++) {
        const char *problem = daran_fuzz_call_problem(&h->rec.calls[i], state_known, may_move);
        if (problem != NULL) {
            violated("%s", problem);
        }
    }
    if (h->rec.n_dropped > 0u) {
        violated("more than %u HAL calls in one step", (unsigned)DARAN_RECORDER_CALLS_MAX);
    }
}

/* The setter, move and action calls of the step, in order. */
static size_t effects(const can_harness_t *h, const daran_call_t **out, size_t max)
{
    size_t n = 0;
    for (size_t i = 0; i < h->rec.n_calls; i++) {
        if (h->rec.calls[i].kind != DARAN_CALL_GET) {
            if (n < max) {
                out[n] = &h->rec.calls[i];
            }
            n++;
        }
    }
    return n;
}

static bool is_action(const daran_call_t *c, daran_action_t action)
{
    return c->kind == DARAN_CALL_ACTION && c->action == action;
}

/* A direct motion (0x019-0x01D) whose fields the drive must refuse
 * (can.md 2.1, C1, C27): a target that is not finite, a trapezoid's cruise
 * not above 0 or acceleration below 0, a mode outside C1's sets. NULL when
 * the harness sees no such field. */
static const char *refused_motion(const daran_can_frame_t *f)
{
    uint32_t code = f->id & 0x1Fu;
    uint32_t bits = get_u32(f->data);
    float target;
    memcpy(&target, &bits, sizeof target);
    int16_t field4 = (int16_t)(uint16_t)get_u16(f->data + 4);
    int16_t field6 = (int16_t)(uint16_t)get_u16(f->data + 6);
    uint32_t mode = get_u16(f->data + 6);
    if (code < 0x19u || code > 0x1Du) {
        return NULL;
    }
    if (!isfinite(target)) {
        return "a target that is not finite";
    }
    if (code == 0x19u && field6 < 0) {
        return "a negative bandwidth";
    }
    if (code == 0x1Au && (field4 <= 0 || field6 < 0)) {
        return "a trapezoid's cruise not above 0 or acceleration below 0";
    }
    if ((code == 0x1Cu && (mode == 2u || mode == 200u) && field4 < 0) ||
        (code == 0x1Du && mode != 1u && mode != 100u && field4 < 0)) {
        return "a negative ramp rate";
    }
    if (code == 0x1Cu && mode != 1u && mode != 100u && mode != 2u && mode != 200u) {
        return "a velocity mode outside 1, 2 (or x 100)";
    }
    if (code == 0x1Du && mode != 1u && mode != 100u && mode != 6u && mode != 600u && mode != 2u &&
        mode != 200u) {
        return "a torque mode outside 1, 6, 2 (or x 100)";
    }
    return NULL;
}

/* What may follow the feed of a frame for the drive (@p rest, @p n of them). */
static void check_frame_effects(const can_harness_t *h, const daran_call_t *const *rest, size_t n)
{
    static const daran_action_t system_actions[] = {
        DARAN_ACTION_SAVE_CONFIG, DARAN_ACTION_ERASE_CONFIG, DARAN_ACTION_REBOOT,
        DARAN_ACTION_CLEAR_ERRORS, DARAN_ACTION_SET_ZERO, DARAN_ACTION_ESTOP};
    const daran_can_frame_t *f = &h->frame;
    uint32_t code = f->id & 0x1Fu;
    uint32_t subcode = get_u32(f->data);
    bool moving = (code >= 0x19u && code <= 0x1Du) ||
                  (code == CODE_SYSTEM && subcode >= 0x10u && subcode <= 0x15u);
    const char *refused = refused_motion(f);
    if (refused != NULL && (n != 0u || h->n_sent != 0u)) {
        violated("a motion frame with %s made a setter, move or action call beyond the feed, or "
                 "was answered (C27: ignored as a whole)",
                 refused);
    }
    if (moving) {
        bool ok = n == 0u || (n <= 2u && rest[0]->kind == DARAN_CALL_MOVE &&
                              (n == 1u || is_action(rest[1], DARAN_ACTION_FEED_WATCHDOG)));
        if (!ok) {
            violated("a motion or start made more than its move and the watchdog feed after it");
        }
        return;
    }
    if (code == CODE_SYSTEM && subcode >= 1u && subcode <= 6u) {
        if (n > 1u || (n == 1u && !is_action(rest[0], system_actions[subcode - 1u]))) {
            violated("system sub-code 0x%02lX made more than its one action", (unsigned long)subcode);
        }
        return;
    }
    if (code == CODE_WRITE) {
        daran_prop_t prop;
        bool row = get_u16(f->data + 2) <= 4u && daran_fuzz_can_row(get_u16(f->data), &prop);
        if (n > 1u || (n == 1u && (!row || rest[0]->kind != DARAN_CALL_SET || rest[0]->prop != prop))) {
            violated("a write made more than one set of the row at its address");
        }
        return;
    }
    if (n != 0u) {
        violated("a read, a preset or an ignored system sub-code made a setter, move or action call");
    }
}

/* What a frame for the drive may send. */
static void check_frame_replies(const can_harness_t *h)
{
    const daran_can_frame_t *f = &h->frame;
    uint32_t code = f->id & 0x1Fu;
    if (code == CODE_SYSTEM || code == CODE_WRITE) {
        if (h->n_sent != 0u) {
            violated("a system command or a write was answered (they never are)");
        }
        return;
    }
    if (code != CODE_READ) {
        if (h->n_sent > 1u || (h->n_sent == 1u && !is_status_code(h->sent[0].id & 0x1Fu))) {
            violated("a motion or preset answered with more than one status frame");
        }
        return;
    }
    uint32_t address = get_u16(f->data);
    if (address == 0u) {
        if (h->n_sent != 1u || !is_status_code(h->sent[0].id & 0x1Fu)) {
            violated("a fast read not answered with exactly one status frame");
        }
        return;
    }
    daran_prop_t prop;
    bool row = daran_fuzz_can_row(address, &prop);
    if (h->n_sent == 0u) {
        return; /* no such address, or the HAL refused the read */
    }
    const daran_can_frame_t *reply = &h->sent[0];
    daran_value_t value;
    if (!row || h->n_sent != 1u || (reply->id & 0x1Fu) != CODE_READ) {
        violated("a read of address %lu answered with other than one read reply of a row of the build",
                 (unsigned long)address);
    }
    if (get_u16(reply->data) != address || get_u16(reply->data + 2) != daran_fuzz_can_type_code(prop)) {
        violated("a read reply that does not echo address %lu with the row's type code %u",
                 (unsigned long)address, daran_fuzz_can_type_code(prop));
    }
    if (port_get(h, prop, &value) && get_u32(reply->data + 4) != value.u32) {
        violated("a read reply whose value is not the one the HAL's getter gives");
    }
}

static void run_frame(can_harness_t *h, const daran_can_frame_t *frame)
{
    daran_value_t own_value;
    bool own_known = port_get(h, DARAN_PROP_CAN_NODE_ID, &own_value) && own_value.u32 >= 1u &&
                     own_value.u32 <= 63u;
    uint32_t own = own_value.u32;
    uint32_t state = port_u32(h, DARAN_PROP_CURRENT_STATE);
    bool may_move = state == DARAN_STATE_CLOSED_LOOP && port_u32(h, DARAN_PROP_AXIS_ERROR) == 0u;
    h->step = "a frame";
    h->frame = *frame;
    h->has_frame = true;
    h->n_sent = 0;
    daran_recorder_clear(&h->rec);
    if (h->port->can_deliver != NULL) {
        h->port->can_deliver(h->port->ctx, &h->can, frame);
    } else {
        (void)daran_can_receive(&h->can, frame);
    }
    (void)daran_can_poll(&h->can);

    check_promises(h, true, may_move);
    uint32_t node = frame->id >> 5;
    uint32_t code = frame->id & 0x1Fu;
    bool shaped = frame->dlc == 8u && frame->flags == 0u && frame->id <= 0x7FFu;
    bool live = h->enabled && own_known && shaped;
    bool duplicate = live && is_status_code(code) && node == own;
    bool for_drive = live && !is_status_code(code) && (node == own || node == 0u) && known_code(code);
    const daran_call_t *calls[4];
    size_t n = effects(h, calls, 4u);
    totals.lines++;
    totals.other_drive += live && node != own && node != 0u ? 1u : 0u;
    totals.mutating += n > 0u ? 1u : 0u;
    if (duplicate) {
        if (h->n_sent != 0u || n > 1u ||
            (n == 1u && (calls[0]->kind != DARAN_CALL_SET || calls[0]->prop != DARAN_PROP_CAN_ERROR ||
                         (calls[0]->value.u32 & 1u) == 0u))) {
            violated("a status frame with the own id did more than write can.error with bit 0 set");
        }
        return;
    }
    if (!for_drive) {
        totals.answered_error++;
        if (h->n_sent != 0u || n != 0u) {
            violated("a frame the drive must ignore (%s) was answered or made a setter, move or "
                     "action call",
                     !h->enabled ? "can.config.protocol was 0 at init"
                     : !shaped   ? "not an 8-byte standard data frame"
                     : node != own && node != 0u ? "another node's"
                                                 : "an unknown command code");
        }
        return;
    }
    h->armed = true;
    h->tripped = false;
    h->fed_at = h->now;
    if (n == 0u || !is_action(calls[0], DARAN_ACTION_FEED_WATCHDOG)) {
        violated("a frame for the drive did not feed the watchdog first (C18)");
    }
    check_frame_effects(h, calls + 1, n - 1u);
    check_frame_replies(h);
    check_sent(h, own);
}

/* One millisecond of drive time and its poll: the guard and the heartbeat. */
static void run_millisecond(can_harness_t *h)
{
    h->port->advance(h->port->ctx, 1u);
    h->now++;
    h->step = "a millisecond of drive time";
    h->has_frame = false;
    h->n_sent = 0;
    daran_recorder_clear(&h->rec);
    (void)daran_can_poll(&h->can);
    check_promises(h, false, false);

    uint32_t timeout = port_u32(h, DARAN_PROP_CAN_TIMEOUT_MS);
    bool guard_due = h->enabled && h->armed && !h->tripped && timeout != 0u &&
                     h->now - h->fed_at >= timeout;
    const daran_call_t *calls[2];
    size_t n = effects(h, calls, 2u);
    bool tripped = n == 1u && is_action(calls[0], DARAN_ACTION_NODE_GUARD);
    if (n > 1u || (n == 1u && !tripped)) {
        violated("drive time made a setter, move or action call other than the node guard's");
    }
    if (tripped != guard_due) {
        violated(tripped ? "the node guard tripped %lu ms after the last frame for the drive "
                           "(can.config.timeout_ms %lu; armed %d)"
                         : "the node guard did not trip %lu ms after the last frame for the drive "
                           "(can.config.timeout_ms %lu; armed %d): is now_ms() the drive time "
                           "advance() passes?",
                 (unsigned long)(h->now - h->fed_at), (unsigned long)timeout, h->armed);
    }
    h->tripped = h->tripped || tripped;

    daran_value_t own;
    bool own_known = port_get(h, DARAN_PROP_CAN_NODE_ID, &own);
    uint32_t period = port_u32(h, DARAN_PROP_CAN_HEARTBEAT_MS);
    bool heartbeat_due = h->enabled && own_known && period != 0u && h->now - h->heartbeat_at >= period;
    if (h->n_sent > 1u || (h->n_sent == 1u) != heartbeat_due) {
        violated(heartbeat_due ? "no heartbeat %lu ms after the last (can.config.heartbeat_ms %lu): "
                                 "is now_ms() the drive time advance() passes?"
                               : "a frame sent %lu ms after the last heartbeat though none was due "
                                 "(can.config.heartbeat_ms %lu)",
                 (unsigned long)(h->now - h->heartbeat_at), (unsigned long)period);
    }
    if (h->n_sent == 1u) {
        h->heartbeat_at = h->now;
        check_sent(h, own.u32);
    }
}

/* The ASCII side is not fed: a line's reply cannot come. */
static void no_reply(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    (void)line;
    (void)len;
    violated("an ASCII reply, though no line was given");
}

static void bind_port(can_harness_t *h)
{
    h->port = daran_test_port();
    const daran_test_port_t *p = h->port;
    const char *problem = daran_fuzz_port_problem(p);
    if (problem != NULL) {
        violated("%s", problem);
    }
    if (p->hal->can_send == NULL || p->hal->now_ms == NULL) {
        violated("the test port's hal gives no can_send() and now_ms(): nothing to fuzz");
    }
    h->shim = daran_recorder_hal;
    h->shim.write = no_reply;
    h->shim.can_send = wrapped_send;
    h->shim.now_ms = wrapped_now;
    h->shim.can_system = wrapped_hook;
}

static void start_input(can_harness_t *h)
{
    h->step = "reset and init";
    h->has_frame = false;
    h->n_sent = 0;
    const char *problem = daran_fuzz_start_drive(h->port, &h->rec, &h->drive, &h->shim);
    if (problem != NULL) {
        violated("%s", problem);
    }
    daran_result_t result = daran_can_init(&h->can, &h->drive);
    if (result != DARAN_OK) {
        violated("daran_can_init() refused the drive and the port's CAN functions (%s)",
                 daran_result_phrase(result));
    }
    daran_value_t protocol;
    h->enabled = !port_get(h, DARAN_PROP_CAN_PROTOCOL, &protocol) || protocol.u32 == 1u;
    h->now = 0;
    h->armed = false;
    h->tripped = false;
    h->fed_at = 0;
    h->heartbeat_at = 0;
    /* the first poll looks at the guard and the heartbeat at time 0 */
    daran_recorder_clear(&h->rec);
    (void)daran_can_poll(&h->can);
    if (h->n_sent != 0u || effects(h, NULL, 0u) != 0u) {
        violated("the first poll after init sent a frame or made a setter, move or action call");
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    can_harness_t *h = &harness;
    if (h->port == NULL) {
        bind_port(h);
    }
    start_input(h);
    for (size_t at = 0; at + DARAN_FUZZ_CAN_RECORD <= size; at += DARAN_FUZZ_CAN_RECORD) {
        const uint8_t *r = data + at;
        for (unsigned ms = 0; h->port->advance != NULL && ms < r[0]; ms++) {
            run_millisecond(h);
        }
        daran_can_frame_t frame;
        frame.dlc = (uint8_t)((r[1] & 0x0Fu) > 8u ? 8u : r[1] & 0x0Fu);
        frame.flags = (uint8_t)((r[1] & 0x80u) != 0u ? (r[1] >> 4) & 0x07u : 0u);
        frame.id = get_u16(r + 2);
        if ((frame.flags & DARAN_CAN_FRAME_EXTENDED) == 0u) {
            frame.id &= 0x7FFu;
        }
        memcpy(frame.data, r + 4, sizeof frame.data);
        run_frame(h, &frame);
    }
    return 0;
}
