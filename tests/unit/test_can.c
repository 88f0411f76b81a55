/* Unit tests of the CAN front end (daran_can.h) against its contract, the
 * project's can.md specification (decisions C1..C30 on the drive side) as
 * docs/can.md builds it. The drive is the recording mock HAL of mock_hal.h
 * behind daran_init(); the front end gets a test port whose transmit
 * function records every frame the drive sends, a settable millisecond clock
 * and a system hook. Frames go in through daran_can_receive() and run in
 * daran_can_poll(): the public API only.
 *
 * The ASCII front end is the reference: a frame and its ASCII twin (can.md
 * 2.1, 5.2) must make the same HAL calls, so most checks compare a drive fed
 * frames with a second drive fed the twin lines. The vendor's python-can
 * recording (can_recording_data.h) runs through three drives that way, frame
 * by frame. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "can_recording_data.h"
#include "float_bits.h"
#include "mock_hal.h"

#if DARAN_ENABLE_CAN

/* ---- the test port ---- */

/* a full ring of reads, and then some */
#define BUS_SENT_MAX (DARAN_CAN_RX_FRAMES > 32 ? DARAN_CAN_RX_FRAMES + 8 : 40)

typedef struct bus {
    daran_can_frame_t sent[BUS_SENT_MAX];
    size_t calls_before[BUS_SENT_MAX]; /* HAL calls the drive had made when each went out */
    size_t n_sent;
    bool refuse;      /* the controller takes nothing (bus-off) */
    bool forget_calls; /* each frame sent clears the drive's call log (a ring of reads
                          outgrows it) */
    size_t n_refused; /* transmissions refused */
    uint32_t now_ms;
    size_t n_hook;
    uint32_t hook_subcode;
    uint16_t hook_data1;
    uint16_t hook_data2;
    mock_t *mock;
} bus_t;

static bus_t bus;
static daran_can_t can;
static mock_t *m; /* the drive behind the front end (mock slot 0) */
static char last_frame[96]; /* the frame being run, for failure messages */
static const char *context;  /* the recorded call being replayed, or NULL */

/* The drive's port description gets these beside the mock's HAL; their
 * context is the mock, the bus is this file's. */
static bool bus_send(void *ctx, const daran_can_frame_t *frame)
{
    (void)ctx;
    bus_t *b = &bus;
    if (b->refuse) {
        b->n_refused++;
        return false;
    }
    TEST_ASSERT_TRUE_MESSAGE(b->n_sent < BUS_SENT_MAX, "the drive sent more frames than the test bus holds");
    b->sent[b->n_sent] = *frame;
    b->calls_before[b->n_sent] = b->mock->n_calls;
    b->n_sent++;
    if (b->forget_calls) {
        mock_clear(b->mock);
    }
    return true;
}

static uint32_t bus_now(void *ctx)
{
    (void)ctx;
    return bus.now_ms;
}

static void bus_system_hook(void *ctx, uint32_t subcode, uint16_t data1, uint16_t data2)
{
    (void)ctx;
    bus_t *b = &bus;
    b->n_hook++;
    b->hook_subcode = subcode;
    b->hook_data1 = data1;
    b->hook_data2 = data2;
}

/* Give @p mock's port description the test bus (with or without the system
 * hook). */
static void plug_into_bus(mock_t *mock, bool with_hook)
{
    mock->hal.now_ms = bus_now;
    mock->hal.can_send = bus_send;
    mock->hal.can_system = with_hook ? bus_system_hook : NULL;
}

/* A drive with node id @p id, CAN protocol 1, bound to a fresh front end on
 * the test bus, its port with or without the system hook; the clock reads 0. */
static mock_t *start_drive_on(uint32_t id, bool with_hook)
{
    memset(&bus, 0, sizeof bus);
    m = mock_new_id(id);
    m->props[DARAN_PROP_CAN_PROTOCOL].u32 = 1;
    bus.mock = m;
    plug_into_bus(m, with_hook);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_can_init(&can, &m->drive));
    return m;
}

static mock_t *start_drive(uint32_t id)
{
    return start_drive_on(id, true);
}

void setUp(void)
{
    context = NULL;
    (void)start_drive(1);
}

void tearDown(void)
{
}

/* ---- frames ---- */

static void put_u16(uint8_t *bytes, uint32_t value)
{
    bytes[0] = (uint8_t)value;
    bytes[1] = (uint8_t)(value >> 8);
}

static void put_u32(uint8_t *bytes, uint32_t value)
{
    put_u16(bytes, value);
    put_u16(bytes + 2, value >> 16);
}

static uint16_t get_u16(const uint8_t *bytes)
{
    return (uint16_t)(bytes[0] | bytes[1] << 8);
}

static uint32_t get_u32(const uint8_t *bytes)
{
    return (uint32_t)get_u16(bytes) | (uint32_t)get_u16(bytes + 2) << 16;
}

/* A frame from its id and up to eight hex bytes ("00 00 b4 42 ..."); the
 * DLC is the number of bytes given. */
static daran_can_frame_t frame_hex(uint32_t id, const char *hex)
{
    daran_can_frame_t frame;
    memset(&frame, 0, sizeof frame);
    frame.id = id;
    const char *p = hex;
    while (*p != '\0') {
        char *end;
        unsigned long byte = strtoul(p, &end, 16);
        TEST_ASSERT_TRUE_MESSAGE(end != p && byte <= 0xFF && frame.dlc < 8, "bad hex in a test frame");
        frame.data[frame.dlc++] = (uint8_t)byte;
        p = end;
        while (*p == ' ') {
            p++;
        }
    }
    return frame;
}

/* A frame written out: its id and its hex bytes. */
typedef struct hex_frame {
    uint32_t id;
    const char *hex;
} hex_frame_t;

/* 0x00C, 0x019..0x01D: f32 @0, two s16 fields @4 and @6. */
static daran_can_frame_t motion_frame(uint32_t node, uint32_t code, float value, int32_t raw4, int32_t raw6)
{
    daran_can_frame_t frame;
    memset(&frame, 0, sizeof frame);
    frame.id = node << 5 | code;
    frame.dlc = 8;
    put_u32(frame.data, daran_bits_of(value));
    put_u16(frame.data + 4, (uint32_t)raw4);
    put_u16(frame.data + 6, (uint32_t)raw6);
    return frame;
}

static daran_can_frame_t system_frame(uint32_t node, uint32_t subcode, uint32_t data1, uint32_t data2)
{
    daran_can_frame_t frame;
    memset(&frame, 0, sizeof frame);
    frame.id = node << 5 | 0x08u;
    frame.dlc = 8;
    put_u32(frame.data, subcode);
    put_u16(frame.data + 4, data1);
    put_u16(frame.data + 6, data2);
    return frame;
}

static daran_can_frame_t property_frame(uint32_t node, uint32_t code, uint32_t address, uint32_t type,
                                        uint32_t value)
{
    daran_can_frame_t frame;
    memset(&frame, 0, sizeof frame);
    frame.id = node << 5 | code;
    frame.dlc = 8;
    put_u16(frame.data, address);
    put_u16(frame.data + 2, type);
    put_u32(frame.data + 4, value);
    return frame;
}

#define READ_FRAME(node, address, type) property_frame((node), 0x1Eu, (address), (type), 0u)
#define WRITE_FRAME(node, address, type, value) property_frame((node), 0x1Fu, (address), (type), (value))

static void describe(const daran_can_frame_t *frame)
{
    int n = snprintf(last_frame, sizeof last_frame, "0x%03X dlc %u flags %u:", (unsigned)frame->id,
                     (unsigned)frame->dlc, (unsigned)frame->flags);
    for (unsigned i = 0; i < 8u && n > 0 && (size_t)n < sizeof last_frame - 4u; i++) {
        n += snprintf(last_frame + n, sizeof last_frame - (size_t)n, " %02x", frame->data[i]);
    }
}

/* Forget the logs, then hand @p frame to the front end and poll: returns
 * what daran_can_receive() said; a taken frame must be run by the poll. */
static bool offer(const daran_can_frame_t *frame)
{
    mock_clear(m);
    bus.n_sent = 0;
    describe(frame);
    bool taken = daran_can_receive(&can, frame);
    TEST_ASSERT_EQUAL_UINT_MESSAGE(taken ? 1u : 0u, daran_can_poll(&can), last_frame);
    return taken;
}

/* A well-formed frame: taken by the ring and run. */
static void deliver(daran_can_frame_t frame)
{
    TEST_ASSERT_TRUE_MESSAGE(offer(&frame), "an 8-byte standard data frame was not taken");
}

/* ---- checks ---- */

static const char *call_text(const mock_call_t *call)
{
    static char text[64];
    switch (call->kind) {
    case MOCK_CALL_SET:
        snprintf(text, sizeof text, "set(prop %d = 0x%08x)", (int)call->prop, (unsigned)call->value.u32);
        break;
    case MOCK_CALL_MOVE:
        snprintf(text, sizeof text, "move(kind %d)", (int)call->move.kind);
        break;
    default:
        snprintf(text, sizeof text, call->action == DARAN_ACTION_FEED_WATCHDOG ? "feed" : "action(%d)",
                 (int)call->action);
        break;
    }
    return text;
}

static void can_fail(int line, const char *fmt, ...)
{
    static char message[1024];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(message, sizeof message, fmt, ap);
    va_end(ap);
    if (n < 0 || (size_t)n >= sizeof message) {
        n = (int)strlen(message);
    }
    n += snprintf(message + n, sizeof message - (size_t)n, "\n  frame: %s%s%s\n  calls:", last_frame,
                  context != NULL ? " from " : "", context != NULL ? context : "");
    for (size_t i = 0; i < m->n_calls && (size_t)n < sizeof message - 64u; i++) {
        n += snprintf(message + n, sizeof message - (size_t)n, " %s", call_text(&m->calls[i]));
    }
    if ((size_t)n < sizeof message - 64u) {
        snprintf(message + n, sizeof message - (size_t)n, "\n  frames sent: %u", (unsigned)bus.n_sent);
    }
    UNITY_TEST_FAIL((UNITY_LINE_TYPE)line, message);
}

static bool is_feed(const mock_call_t *call)
{
    return call->kind == MOCK_CALL_ACTION && call->action == DARAN_ACTION_FEED_WATCHDOG;
}

/* No HAL setter, move or action at all, nothing sent (C21, C22, C28). */
static void expect_untouched(int line)
{
    if (m->n_calls != 0u || bus.n_sent != 0u) {
        can_fail(line, "expected no effect at all (not even a watchdog feed)");
    }
}
#define EXPECT_UNTOUCHED() expect_untouched(__LINE__)

/* The first call is the watchdog feed every frame for the drive makes (C18). */
static void expect_fed_first(int line)
{
    if (m->n_calls == 0u || !is_feed(&m->calls[0])) {
        can_fail(line, "expected the frame to feed the watchdog first (C18)");
    }
}

/* A frame for the drive that the drive refused or that does nothing: the
 * watchdog feed and nothing else, nothing sent (C18 and section 4). */
static void expect_only_fed(int line)
{
    if (m->n_calls != 1u || !is_feed(&m->calls[0]) || bus.n_sent != 0u) {
        can_fail(line, "expected the watchdog feed alone and nothing sent");
    }
}
#define EXPECT_ONLY_FED() expect_only_fed(__LINE__)

/* The feed, exactly one move, only feeds besides; returns the move. */
static const daran_move_t *expect_move(int line, size_t frames_sent)
{
    expect_fed_first(line);
    const daran_move_t *move = NULL;
    for (size_t i = 1; i < m->n_calls; i++) {
        if (m->calls[i].kind == MOCK_CALL_MOVE && move == NULL) {
            move = &m->calls[i].move;
        } else if (!is_feed(&m->calls[i])) {
            can_fail(line, "expected one move and feeds only");
        }
    }
    if (move == NULL) {
        can_fail(line, "expected a move");
    }
    if (bus.n_sent != frames_sent) {
        can_fail(line, "expected %u frames sent", (unsigned)frames_sent);
    }
    return move;
}
#define EXPECT_MOVE() expect_move(__LINE__, 0u)

static daran_value_t expect_set(int line, daran_prop_t prop)
{
    expect_fed_first(line);
    if (m->n_calls != 2u || m->calls[1].kind != MOCK_CALL_SET || m->calls[1].prop != prop ||
        bus.n_sent != 0u) {
        can_fail(line, "expected the feed, then set(prop %d) alone, nothing sent", (int)prop);
    }
    return m->calls[1].value;
}
#define EXPECT_SET(prop) expect_set(__LINE__, (prop))

static void expect_action(int line, daran_action_t action)
{
    expect_fed_first(line);
    if (m->n_calls != 2u || m->calls[1].kind != MOCK_CALL_ACTION || m->calls[1].action != action ||
        bus.n_sent != 0u) {
        can_fail(line, "expected the feed, then action(%d) alone, nothing sent", (int)action);
    }
}
#define EXPECT_ACTION(action) expect_action(__LINE__, (action))

static void expect_frame(int line, size_t index, const daran_can_frame_t *want)
{
    if (index >= bus.n_sent) {
        can_fail(line, "expected frame %u 0x%03X to be sent", (unsigned)index, (unsigned)want->id);
        return;
    }
    const daran_can_frame_t *got = &bus.sent[index];
    if (got->id != want->id || got->dlc != 8u || got->flags != 0u || memcmp(got->data, want->data, 8) != 0) {
        can_fail(line,
                 "frame %u sent: expected 0x%03X %02x %02x %02x %02x %02x %02x %02x %02x, got 0x%03X dlc %u "
                 "flags %u %02x %02x %02x %02x %02x %02x %02x %02x",
                 (unsigned)index, (unsigned)want->id, want->data[0], want->data[1], want->data[2],
                 want->data[3], want->data[4], want->data[5], want->data[6], want->data[7],
                 (unsigned)got->id, (unsigned)got->dlc, (unsigned)got->flags, got->data[0], got->data[1],
                 got->data[2], got->data[3], got->data[4], got->data[5], got->data[6], got->data[7]);
    }
}
#define EXPECT_SENT(index, id, hex)                         \
    do {                                                    \
        const daran_can_frame_t want_ = frame_hex((id), (hex)); \
        expect_frame(__LINE__, (index), &want_);            \
    } while (0)

/* ---- what the contract says the drive sends ---- */

/* value x 100 rounded to nearest, ties away from zero, saturated to the
 * s16 field (1.3, 2.7); exact: a float times 100 fits a double. */
static int32_t scaled_of(float value)
{
    double x = (double)value * 100.0;
    double r = x < 0.0 ? -floor(-x + 0.5) : floor(x + 0.5);
    if (r > 32767.0) {
        return 32767;
    }
    if (r < -32768.0) {
        return -32768;
    }
    return (int32_t)r;
}

/* The status frame of 2.7 for the drive's store as it is now. */
static daran_can_frame_t status_of(const mock_t *drive, uint32_t node)
{
    const daran_value_t *p = drive->props;
    uint32_t code = 0x01u | (p[DARAN_PROP_TRAJECTORY_DONE].u32 != 0u ? 0x02u : 0u) |
                    (p[DARAN_PROP_AXIS_ERROR].u32 != 0u ? 0x04u : 0u);
    return motion_frame(node, code, p[DARAN_PROP_POS_ESTIMATE].f32, scaled_of(p[DARAN_PROP_VEL_ESTIMATE].f32),
                        scaled_of(p[DARAN_PROP_TORQUE_ESTIMATE].f32));
}

/* The property list's CAN column, read here from the one list. */
typedef struct can_row {
    uint32_t address;
    daran_prop_t prop;
    const char *path;
    bool axis;
    daran_prop_type_t type;
    bool writable;
} can_row_t;

#define SCOPE_IS_AXIS true
#define SCOPE_IS_SYSTEM false
#define ACCESS_IS_RW true
#define ACCESS_IS_RO false
#define CAN_ROW(id, path, scope, type, access, range, unit, can) \
    {can, DARAN_PROP_##id, path, SCOPE_IS_##scope, DARAN_TYPE_##type, ACCESS_IS_##access},
static const can_row_t can_rows[] = {DARAN_PROPERTY_LIST(CAN_ROW)};
#undef CAN_ROW
#define CAN_ROWS (sizeof can_rows / sizeof can_rows[0])

static const can_row_t *row_at(uint32_t address)
{
    for (size_t i = 0; i < CAN_ROWS; i++) {
        if (address != 0u && can_rows[i].address == address) {
            return &can_rows[i];
        }
    }
    return NULL;
}

static const can_row_t *row_of(daran_prop_t prop)
{
    for (size_t i = 0; i < CAN_ROWS; i++) {
        if (can_rows[i].prop == prop) {
            return &can_rows[i];
        }
    }
    TEST_FAIL_MESSAGE("a property the list does not have");
    return NULL;
}

/* The type code a property travels with (1.3, C7): f32 0, s32 4, else 3. */
static uint32_t type_code_of(daran_prop_type_t type)
{
    return type == DARAN_TYPE_F32 ? 0u : type == DARAN_TYPE_S32 ? 4u : 3u;
}

/* The read reply of 2.6 for the drive's store as it is now. */
static daran_can_frame_t read_reply_of(const mock_t *drive, uint32_t node, const can_row_t *row)
{
    return property_frame(node, 0x1Eu, row->address, type_code_of(row->type), drive->props[row->prop].u32);
}

/* ---- the ASCII twin ---- */

/* A float as text that reads back as the same float32 (integral values
 * without an exponent, as an integer property needs them). */
static void text_f32(char *buf, size_t size, float value)
{
    if (value == floorf(value) && fabsf(value) < 4294967296.0f) {
        snprintf(buf, size, "%.1f", (double)value);
    } else {
        snprintf(buf, size, "%.9g", (double)value);
    }
}

/* A scaled field as the exact decimal raw / 100. */
static void text_scaled(char *buf, size_t size, int32_t raw)
{
    uint32_t magnitude = raw < 0 ? (uint32_t)-raw : (uint32_t)raw;
    snprintf(buf, size, "%s%u.%02u", raw < 0 ? "-" : "", (unsigned)(magnitude / 100u),
             (unsigned)(magnitude % 100u));
}

/* The ASCII mode of a raw mode field (C1): 1 or 100 -> 1, 2 or 200 -> 2, 6
 * or 600 -> 6 for torque; any other raw value stays itself, which ASCII
 * refuses as a mode just as CAN must. */
static int32_t ascii_mode_of(uint32_t raw, bool torque)
{
    if (raw == 1u || raw == 100u) {
        return 1;
    }
    if (raw == 2u || raw == 200u) {
        return 2;
    }
    if (torque && (raw == 6u || raw == 600u)) {
        return 6;
    }
    return (int32_t)raw;
}

/* The HAL calls other than the watchdog feeds: what a frame and its twin
 * line must agree on (the feeds differ by design, C18). */
static size_t effects_of(const mock_t *drive, const mock_call_t **out, size_t max)
{
    size_t n = 0;
    for (size_t i = 0; i < drive->n_calls; i++) {
        if (!is_feed(&drive->calls[i]) && n < max) {
            out[n++] = &drive->calls[i];
        }
    }
    return n;
}

static bool same_float(float a, float b)
{
    return daran_bits_of(a) == daran_bits_of(b);
}

static bool same_call(const mock_call_t *a, const mock_call_t *b)
{
    if (a->kind != b->kind) {
        return false;
    }
    switch (a->kind) {
    case MOCK_CALL_SET:
        return a->prop == b->prop && (row_of(a->prop)->type == DARAN_TYPE_U64 ? a->value.u64 == b->value.u64
                                                                               : a->value.u32 == b->value.u32);
    case MOCK_CALL_MOVE: {
        const daran_move_t *x = &a->move, *y = &b->move;
        bool given_defined = x->kind == DARAN_MOVE_FILTERED_POSITION || x->kind == DARAN_MOVE_TRAPEZOID;
        return x->kind == y->kind && (!given_defined || x->given == y->given) &&
               same_float(x->pos_deg, y->pos_deg) && same_float(x->vel_rpm, y->vel_rpm) &&
               same_float(x->torque_nm, y->torque_nm) && same_float(x->rate, y->rate) &&
               same_float(x->kp, y->kp) && same_float(x->kd, y->kd);
    }
    default:
        return a->action == b->action;
    }
}

/* The drive fed frames (m) made exactly the calls of the drive fed the
 * twin lines, feeds aside. */
static void expect_same_effects(int line, const mock_t *twin, const char *twin_line)
{
    const mock_call_t *mine[16], *theirs[16];
    size_t n = effects_of(m, mine, 16);
    size_t k = effects_of(twin, theirs, 16);
    bool same = n == k;
    for (size_t i = 0; same && i < n; i++) {
        same = same_call(mine[i], theirs[i]);
    }
    if (!same) {
        can_fail(line, "the frame's HAL calls (%u besides feeds) differ from those of the line \"%s\" (%u, first %s; "
                 "its reply \"%s\")",
                 (unsigned)n, twin_line, (unsigned)k, k > 0u ? call_text(theirs[0]) : "-",
                 mock_escape(twin->out, twin->out_len));
    }
}

#define REPLY_IS_ERROR(drive) (strncmp((drive)->out, "error: ", 7) == 0)

/* A refusal for the drive's state (C29), which still gets a status reply
 * (C10), as opposed to one for the frame's values. */
static bool refused_for_state(const mock_t *drive)
{
    static const char *const phrases[] = {"error: estop active\n", "error: motor fault\n",
                                          "error: motor idle\n"};
    for (size_t i = 0; i < sizeof phrases / sizeof phrases[0]; i++) {
        if (strcmp(drive->out, phrases[i]) == 0) {
            return true;
        }
    }
    return false;
}

/* ---- 6.6: the drive on the receiving side, the worked examples ---- */

static void test_get_id_broadcast_is_answered_by_drive_1_with_its_own_id(void)
{
    deliver(frame_hex(0x01E, "19 79 03 00 00 00 00 00"));
    TEST_ASSERT_EQUAL_UINT(1, m->n_calls);
    TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
    EXPECT_SENT(0, 0x03E, "19 79 03 00 01 00 00 00");
}

static void test_get_state_3_answers_the_status_frame_of_the_worked_example(void)
{
    start_drive(3);
    m->props[DARAN_PROP_POS_ESTIMATE].f32 = 90.0f;
    m->props[DARAN_PROP_VEL_ESTIMATE].f32 = 12.34f;
    m->props[DARAN_PROP_TORQUE_ESTIMATE].f32 = -0.5f;
    deliver(frame_hex(0x07E, "00 00 00 00 00 00 00 00"));
    TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
    EXPECT_SENT(0, 0x063, "00 00 b4 42 d2 04 ce ff");
    /* read_property(3, 0) asks with type code 3: the same frame (C7) */
    deliver(frame_hex(0x07E, "00 00 03 00 00 00 00 00"));
    TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
    EXPECT_SENT(0, 0x063, "00 00 b4 42 d2 04 ce ff");
}

static void test_preset_torque_then_a_torque_start_ramps_to_minus_1_2_nm_at_0_2_nm_per_s(void)
{
    SKIP_IF_NO_MULTI();
    deliver(frame_hex(0x02C, "9a 99 99 bf 14 00 58 02"));
    EXPECT_ONLY_FED();
    deliver(frame_hex(0x008, "14 00 00 00 00 00 00 00"));
    const daran_move_t *move = EXPECT_MOVE();
    ASSERT_MOVE_EQUALS(m, move, {DARAN_MOVE_TORQUE_RAMP, 0, 0.0f, 0.0f, -1.2f, 0.2f, 0.0f, 0.0f});
    /* the start consumed the preset: a second one finds none (C23) */
    deliver(frame_hex(0x008, "14 00 00 00 00 00 00 00"));
    EXPECT_ONLY_FED();
}

static void test_set_speeds_presets_with_raw_100_run_each_drive_in_feed_forward_mode(void)
{
    SKIP_IF_NO_MULTI();
    static const float speeds[] = {10.0f, 20.0f, 30.0f};
    for (uint32_t id = 1; id <= 3u; id++) {
        start_drive(id);
        deliver(frame_hex(0x02C, "00 00 20 41 00 00 64 00"));
        deliver(frame_hex(0x04C, "00 00 a0 41 00 00 64 00"));
        deliver(frame_hex(0x06C, "00 00 f0 41 00 00 64 00"));
        deliver(frame_hex(0x008, "13 00 00 00 00 00 00 00"));
        const daran_move_t *move = EXPECT_MOVE();
        ASSERT_MOVE_EQUALS(m, move, {DARAN_MOVE_VELOCITY, 0, 0.0f, speeds[id - 1u], 0.0f, 0.0f, 0.0f, 0.0f});
    }
}

static void test_impedance_control_runs_drive_1_and_any_drive_holding_a_preset(void)
{
    SKIP_IF_NO_MULTI();
    deliver(frame_hex(0x02C, "00 00 f0 41 f4 01 32 00"));
    deliver(frame_hex(0x008, "15 00 00 00 14 00 05 00"));
    const daran_move_t *move = EXPECT_MOVE();
    ASSERT_MOVE_EQUALS(m, move, {DARAN_MOVE_IMPEDANCE, 0, 30.0f, 5.0f, 0.5f, 0.0f, 0.2f, 0.05f});

    /* drive 2 holds a preset of its own: the broadcast start runs it with
     * this call's kp and kd (C12) */
    start_drive(2);
    deliver(frame_hex(0x04C, "00 00 20 41 00 00 00 00"));
    deliver(frame_hex(0x02C, "00 00 f0 41 f4 01 32 00"));
    EXPECT_UNTOUCHED();
    deliver(frame_hex(0x008, "15 00 00 00 14 00 05 00"));
    move = EXPECT_MOVE();
    ASSERT_MOVE_EQUALS(m, move, {DARAN_MOVE_IMPEDANCE, 0, 10.0f, 0.0f, 0.0f, 0.0f, 0.2f, 0.05f});

    /* drive 3 holds none: nothing moves */
    start_drive(3);
    deliver(frame_hex(0x008, "15 00 00 00 14 00 05 00"));
    EXPECT_ONLY_FED();
}

static void test_stm32_u16_bool_write_is_accepted_and_its_bytes_6_and_7_ignored(void)
{
    deliver(frame_hex(0x03F, "e2 79 01 00 01 00 ab cd"));
    TEST_ASSERT_EQUAL_UINT32(1, EXPECT_SET(DARAN_PROP_ENABLE_CIRCULAR_SETPOINT_LIMIT).u32);
}

static void test_set_id_default_writing_id_0_is_ignored(void)
{
    deliver(frame_hex(0x01F, "19 79 03 00 00 00 00 00"));
    EXPECT_ONLY_FED();
    TEST_ASSERT_EQUAL_UINT32(1, m->props[DARAN_PROP_CAN_NODE_ID].u32);
}

static void test_send_command_default_with_dlc_0_is_dropped_by_the_ring(void)
{
    daran_can_frame_t frame = frame_hex(0x009, "");
    TEST_ASSERT_EQUAL_UINT(0, frame.dlc);
    TEST_ASSERT_FALSE(offer(&frame));
    EXPECT_UNTOUCHED();
}

static void test_an_estop_with_dlc_7_is_dropped_by_the_ring(void)
{
    start_drive(2);
    daran_can_frame_t frame = frame_hex(0x048, "06 00 00 00 00 00 00");
    TEST_ASSERT_FALSE(offer(&frame));
    EXPECT_UNTOUCHED();
    TEST_ASSERT_EQUAL_UINT32(0, m->props[DARAN_PROP_AXIS_ERROR].u32);
}

static void test_a_status_frame_with_the_own_id_sets_can_error_bit_0(void)
{
    deliver(frame_hex(0x023, "00 00 b4 42 00 00 00 00"));
    TEST_ASSERT_EQUAL_UINT(1, m->n_calls);
    TEST_ASSERT_EQUAL_INT(MOCK_CALL_SET, m->calls[0].kind);
    TEST_ASSERT_EQUAL_INT(DARAN_PROP_CAN_ERROR, m->calls[0].prop);
    TEST_ASSERT_EQUAL_UINT32(1, m->calls[0].value.u32);
    TEST_ASSERT_EQUAL_UINT(0, bus.n_sent);
}

static void test_with_reply_state_set_angle_is_answered_after_the_move_with_the_state_after_it(void)
{
    m->props[DARAN_PROP_ENABLE_REPLY_STATE].u32 = 1;
    m->props[DARAN_PROP_POS_ESTIMATE].f32 = 12.5f;
    m->props[DARAN_PROP_VEL_ESTIMATE].f32 = -3.0f;
    m->props[DARAN_PROP_TORQUE_ESTIMATE].f32 = 0.25f;
    deliver(frame_hex(0x039, "00 00 b4 42 00 00 e8 03"));
    const daran_move_t *move = expect_move(__LINE__, 1u);
    ASSERT_MOVE_EQUALS(m, move, {DARAN_MOVE_FILTERED_POSITION, DARAN_GIVEN_RATE, 90.0f, 0.0f, 0.0f, 10.0f, 0.0f, 0.0f});
    daran_can_frame_t want = status_of(m, 1);
    expect_frame(__LINE__, 0, &want);
    EXPECT_SENT(0, 0x023, "00 00 48 41 d4 fe 19 00");
    /* sent once the move was made */
    TEST_ASSERT_TRUE(bus.calls_before[0] >= 2u);
    TEST_ASSERT_EQUAL_INT(MOCK_CALL_MOVE, m->calls[1].kind);
}

/* ---- 2.1: each code and its ASCII twin make the same HAL calls ---- */

typedef struct twin_row {
    const char *what;
    uint32_t id[2];      /* one or two frames (0: none) */
    const char *hex[2];
    const char *line[2]; /* their ASCII twin: one or two lines */
} twin_row_t;

static const twin_row_t twin_rows[] = {
    {"t with bandwidth", {0x039, 0}, {"00 00 b4 42 00 00 e8 03", NULL}, {"t 1 90 0 10", NULL}},
    {"t with bandwidth 0 keeps it", {0x039, 0}, {"00 00 48 41 00 00 00 00", NULL}, {"t 1 12.5", NULL}},
    {"t ignores its velocity", {0x039, 0}, {"00 00 48 41 39 30 e8 03", NULL}, {"t 1 12.5 -7 10", NULL}},
    {"q", {0x03A, 0}, {"00 00 16 c3 e8 03 f4 01", NULL}, {"q 1 -150 10 5", NULL}},
    {"q with acceleration 0", {0x03A, 0}, {"00 00 20 43 b8 0b 00 00", NULL}, {"q 1 160 30 0", NULL}},
    {"p", {0x03B, 0}, {"00 00 f0 41 f4 01 1e 00", NULL}, {"p 1 30 5 0.3", NULL}},
    {"v mode 1", {0x03C, 0}, {"00 00 a0 41 96 00 01 00", NULL}, {"v 1 20 1.5 1", NULL}},
    {"v mode 100", {0x03C, 0}, {"00 00 a0 41 96 00 64 00", NULL}, {"v 1 20 1.5 1", NULL}},
    {"v mode 2", {0x03C, 0}, {"00 00 a0 41 f4 01 02 00", NULL}, {"v 1 20 5 2", NULL}},
    {"v mode 200", {0x03C, 0}, {"00 00 a0 41 f4 01 c8 00", NULL}, {"v 1 20 5 2", NULL}},
    {"v beyond 327.67 r per min", {0x03C, 0}, {"00 00 c8 43 64 00 01 00", NULL}, {"v 1 400 1 1", NULL}},
    {"c mode 1", {0x03D, 0}, {"00 00 c0 3f 00 00 01 00", NULL}, {"c 1 1.5 0 1", NULL}},
    {"c mode 100", {0x03D, 0}, {"00 00 c0 3f 00 00 64 00", NULL}, {"c 1 1.5 0 1", NULL}},
    {"c mode 6", {0x03D, 0}, {"cd cc 4c bf 32 00 06 00", NULL}, {"c 1 -0.8 0.5 6", NULL}},
    {"c mode 600", {0x03D, 0}, {"cd cc 4c bf 32 00 58 02", NULL}, {"c 1 -0.8 0.5 6", NULL}},
    {"c mode 2", {0x03D, 0}, {"cd cc 4c bf 32 00 02 00", NULL}, {"c 1 -0.8 0.5 2", NULL}},
    {"c mode 200", {0x03D, 0}, {"cd cc 4c bf 32 00 c8 00", NULL}, {"c 1 -0.8 0.5 6", NULL}},
    {"broadcast t", {0x019, 0}, {"00 00 b4 42 00 00 e8 03", NULL}, {"t 0 90 0 10", NULL}},
    {"preset and mt", {0x02C, 0x028}, {"00 00 f0 42 f4 01 e8 03", "10 00 00 00 00 00 00 00"},
     {"ms 1 120 5 10", "mt 1 0"}},
    {"preset and relative mt", {0x02C, 0x028}, {"00 00 f0 42 f4 01 e8 03", "10 00 00 00 01 00 00 00"},
     {"ms 1 120 5 10", "mt 1 1"}},
    {"preset and mq", {0x02C, 0x028}, {"00 00 f0 41 f4 01 e8 03", "11 00 00 00 00 00 00 00"},
     {"ms 1 30 5 10", "mq 1 0"}},
    {"preset and relative broadcast mq", {0x02C, 0x008}, {"00 00 20 41 f4 01 e8 03", "11 00 00 00 01 00 00 00"},
     {"ms 1 10 5 10", "mq 0 1"}},
    {"preset and mp", {0x02C, 0x028}, {"00 00 f0 41 f4 01 1e 00", "12 00 00 00 00 00 00 00"},
     {"ms 1 30 5 0.3", "mp 1 0"}},
    {"preset and relative mp", {0x02C, 0x028}, {"00 00 f0 41 f4 01 1e 00", "12 00 00 00 01 00 00 00"},
     {"ms 1 30 5 0.3", "mp 1 1"}},
    {"preset and mv mode 1", {0x02C, 0x028}, {"00 00 a0 41 96 00 64 00", "13 00 00 00 00 00 00 00"},
     {"ms 1 20 1.5 1", "mv 1"}},
    {"preset and mv mode 2", {0x02C, 0x008}, {"00 00 f0 c1 f4 01 c8 00", "13 00 00 00 00 00 00 00"},
     {"ms 1 -30 5 2", "mv 0"}},
    {"preset and mc mode 1", {0x02C, 0x028}, {"00 00 00 3f 00 00 64 00", "14 00 00 00 00 00 00 00"},
     {"ms 1 0.5 0 1", "mc 1"}},
    {"preset and mc mode 6", {0x02C, 0x028}, {"9a 99 99 bf 14 00 58 02", "14 00 00 00 00 00 00 00"},
     {"ms 1 -1.2 0.2 6", "mc 1"}},
    {"preset and mc mode 2", {0x02C, 0x028}, {"9a 99 99 bf 14 00 c8 00", "14 00 00 00 00 00 00 00"},
     {"ms 1 -1.2 0.2 2", "mc 1"}},
    {"preset and the impedance start", {0x02C, 0x008}, {"00 00 f0 41 f4 01 32 00", "15 00 00 00 14 00 05 00"},
     {"d 1 30 5 0.5 0.2 0.05", NULL}},
    {"w f32", {0x03F, 0}, {"7c 94 00 00 00 00 70 42", NULL}, {"w axis1.output_shaft.vel_limit 60", NULL}},
    {"w u32", {0x03F, 0}, {"11 27 03 00 80 25 00 00", NULL}, {"w config.uart_baudrate 9600 1", NULL}},
    {"w bool", {0x03F, 0}, {"ee 79 03 00 01 00 00 00", NULL},
     {"w axis1.config.extra_setting.enable_reply_state 1", NULL}},
    {"w s32", {0x03F, 0}, {"54 81 04 00 ff ff ff ff", NULL}, {"w axis1.motor.config.direction -1", NULL}},
    {"w requested_state", {0x03F, 0}, {"33 75 03 00 01 00 00 00", NULL}, {"w axis1.requested_state 1", NULL}},
    {"w can_node_id", {0x03F, 0}, {"19 79 03 00 06 00 00 00", NULL}, {"w axis1.config.can_node_id 6", NULL}},
    {"w broadcast", {0x01F, 0}, {"09 52 03 00 20 a1 07 00", NULL}, {"w can.config.baud_rate 500000", NULL}},
    {"ss", {0x028, 0}, {"01 00 00 00 00 00 00 00", NULL}, {"ss 1", NULL}},
    {"se", {0x028, 0}, {"02 00 00 00 00 00 00 00", NULL}, {"se 1", NULL}},
    {"sr", {0x028, 0}, {"03 00 00 00 00 00 00 00", NULL}, {"sr 1", NULL}},
    {"sc", {0x028, 0}, {"04 00 00 00 00 00 00 00", NULL}, {"sc 1", NULL}},
    {"sz", {0x028, 0}, {"05 00 00 00 00 00 00 00", NULL}, {"sz 1", NULL}},
    {"st", {0x028, 0}, {"06 00 00 00 00 00 00 00", NULL}, {"st 1", NULL}},
    {"broadcast st", {0x008, 0}, {"06 00 00 00 00 00 00 00", NULL}, {"st 0", NULL}},
};

/* The reference drive for the ASCII twins (mock slot 1), with the store of
 * the drive behind the front end. */
static mock_t *new_twin(uint32_t id)
{
    mock_t *twin = mock_new_slot(1, id);
    twin->props[DARAN_PROP_CAN_PROTOCOL].u32 = 1;
    return twin;
}

/* Both drives start alike, away from zero so that relative starts show. */
static void twin_state(mock_t *drive)
{
    drive->props[DARAN_PROP_POS_SETPOINT].f32 = 15.0f;
    drive->props[DARAN_PROP_INPUT_POS].f32 = 15.0f;
    drive->props[DARAN_PROP_POS_ESTIMATE].f32 = 15.0f;
}

static void run_twin_row(const void *arg)
{
    const twin_row_t *row = arg;
    if (!DARAN_ENABLE_MULTI_MOTOR && (mock_uses_multi(row->line[0]) || row->line[0][0] == 'd')) {
        TEST_IGNORE();
    }
    mock_t *twin = new_twin(1);
    twin_state(twin);
    twin_state(m);
    for (size_t i = 0; i < 2u && row->line[i] != NULL; i++) {
        mock_send_line(twin, row->line[i]);
        TEST_ASSERT_EQUAL_STRING_MESSAGE("", twin->out, row->line[i]);
    }
    /* the twin's calls are those of its last line; a preset line makes none */
    const mock_call_t *unused[16];
    TEST_ASSERT_TRUE_MESSAGE(effects_of(twin, unused, 16) > 0u, "the twin line did nothing");
    for (size_t i = 0; i < 2u && row->id[i] != 0u; i++) {
        deliver(frame_hex(row->id[i], row->hex[i]));
        expect_fed_first(__LINE__);
    }
    expect_same_effects(__LINE__, twin, row->line[row->line[1] != NULL ? 1 : 0]);
    TEST_ASSERT_EQUAL_UINT(0, bus.n_sent);
    TEST_ASSERT_EQUAL_MEMORY(twin->props, m->props, sizeof m->props);
}

/* A read frame and `r` give the same value (C7: in the property's own type). */
typedef struct read_twin_row {
    const char *line;
    uint32_t address;
} read_twin_row_t;

static const read_twin_row_t read_twin_rows[] = {
    {"r vbus_voltage 1", 1},
    {"r config.uart_baudrate 1", 10001},
    {"r axis1.motor.config.direction", 33108},
    {"r axis1.config.extra_setting.enable_reply_state", 31214},
    {"r fw_version 1", 6},
    {"r serial_number_l 1", 3},
    {"r serial_number_h 1", 4},
    {"r axis1.output_shaft.pos_estimate", 38007},
    {"r axis1.controller.trajectory_done", 32008},
    {"r axis1.config.watchdog_timeout", 50002},
};

static void run_read_twin_row(const void *arg)
{
    const read_twin_row_t *row = arg;
    mock_t *twin = new_twin(1);
    m->props[DARAN_PROP_MOTOR_DIRECTION].s32 = -1;
    twin->props[DARAN_PROP_MOTOR_DIRECTION].s32 = -1;
    m->props[DARAN_PROP_POS_ESTIMATE].f32 = -92.46918f;
    twin->props[DARAN_PROP_POS_ESTIMATE].f32 = -92.46918f;
    m->props[DARAN_PROP_SERIAL_NUMBER_L].u32 = 0x12345679u;
    twin->props[DARAN_PROP_SERIAL_NUMBER_L].u32 = 0x12345679u;
    m->props[DARAN_PROP_SERIAL_NUMBER_H].u32 = 42u;
    twin->props[DARAN_PROP_SERIAL_NUMBER_H].u32 = 42u;
    const char *text = ASSERT_QUERY(twin, row->line);
    /* a request asking with another type code and garbage in bytes 4..7 */
    daran_can_frame_t frame = property_frame(1, 0x1Eu, row->address, 1u, 0xDEADBEEFu);
    deliver(frame);
    TEST_ASSERT_EQUAL_UINT(1, m->n_calls);
    TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
    const can_row_t *prop = row_at(row->address);
    TEST_ASSERT_NOT_NULL(prop);
    const daran_can_frame_t *reply = &bus.sent[0];
    TEST_ASSERT_EQUAL_HEX32(0x03E, reply->id);
    TEST_ASSERT_EQUAL_HEX16(row->address, get_u16(reply->data));
    TEST_ASSERT_EQUAL_UINT16(type_code_of(prop->type), get_u16(reply->data + 2));
    uint32_t value = get_u32(reply->data + 4);
    switch (prop->type) {
    case DARAN_TYPE_F32:
        TEST_ASSERT_EQUAL_HEX32(daran_bits_of(strtof(text, NULL)), value);
        break;
    case DARAN_TYPE_S32:
        TEST_ASSERT_EQUAL_INT32((int32_t)strtol(text, NULL, 10), (int32_t)value);
        break;
    default:
        TEST_ASSERT_EQUAL_UINT32((uint32_t)strtoul(text, NULL, 10), value);
        break;
    }
}

/* ---- C1: the mode field, raw or x 100, in direct frames and in presets ---- */

typedef struct mode_case {
    uint32_t raw;
    daran_move_kind_t kind; /* what it runs as; DARAN_MOVE_IMPEDANCE: refused */
} mode_case_t;

#define REFUSED DARAN_MOVE_IMPEDANCE

static const mode_case_t velocity_modes[] = {
    {1, DARAN_MOVE_VELOCITY}, {100, DARAN_MOVE_VELOCITY}, {2, DARAN_MOVE_VELOCITY_RAMP},
    {200, DARAN_MOVE_VELOCITY_RAMP}, {0, REFUSED}, {3, REFUSED}, {6, REFUSED}, {300, REFUSED},
    {600, REFUSED}, {101, REFUSED}, {1000, REFUSED}, {0xFFFF, REFUSED}, {0x8064, REFUSED},
};

static const mode_case_t torque_modes[] = {
    {1, DARAN_MOVE_TORQUE}, {100, DARAN_MOVE_TORQUE}, {6, DARAN_MOVE_TORQUE_RAMP},
    {600, DARAN_MOVE_TORQUE_RAMP}, {2, DARAN_MOVE_TORQUE_RAMP}, {200, DARAN_MOVE_TORQUE_RAMP},
    {0, REFUSED}, {3, REFUSED}, {5, REFUSED}, {7, REFUSED}, {300, REFUSED}, {700, REFUSED},
    {102, REFUSED}, {0xFFFF, REFUSED},
};

/* A direct frame (0x01C/0x01D) with @p raw as its mode, then a preset with
 * the same raw third field started by 0x13/0x14: the same reading twice. */
static void check_modes(const mode_case_t *cases, size_t count, bool torque)
{
    for (size_t i = 0; i < count; i++) {
        const mode_case_t *c = &cases[i];
        char what[64];
        snprintf(what, sizeof what, "%s mode raw %u", torque ? "torque" : "velocity", (unsigned)c->raw);
        start_drive(1);
        deliver(motion_frame(1, torque ? 0x1Du : 0x1Cu, 2.5f, 150, (int32_t)c->raw));
        if (c->kind == REFUSED) {
            EXPECT_ONLY_FED();
        } else {
            const daran_move_t *move = EXPECT_MOVE();
            TEST_ASSERT_EQUAL_INT_MESSAGE(c->kind, move->kind, what);
            bool ramp = c->kind == DARAN_MOVE_VELOCITY_RAMP || c->kind == DARAN_MOVE_TORQUE_RAMP;
            TEST_ASSERT_EQUAL_FLOAT_MESSAGE(ramp ? 1.5f : 0.0f, move->rate, what);
        }
        if (!DARAN_ENABLE_MULTI_MOTOR) {
            continue;
        }
        deliver(motion_frame(1, 0x0Cu, 2.5f, 150, (int32_t)c->raw));
        deliver(system_frame(1, torque ? 0x14u : 0x13u, 0, 0));
        if (c->kind == REFUSED) {
            EXPECT_ONLY_FED();
        } else {
            const daran_move_t *move = EXPECT_MOVE();
            TEST_ASSERT_EQUAL_INT_MESSAGE(c->kind, move->kind, what);
        }
    }
}

static void test_c1_velocity_modes_read_raw_or_times_100_in_both_places(void)
{
    check_modes(velocity_modes, sizeof velocity_modes / sizeof velocity_modes[0], false);
}

static void test_c1_torque_modes_read_raw_or_times_100_and_2_as_6_in_both_places(void)
{
    check_modes(torque_modes, sizeof torque_modes / sizeof torque_modes[0], true);
}

static void test_c1_a_refused_mode_start_keeps_the_preset(void)
{
    SKIP_IF_NO_MULTI();
    deliver(motion_frame(1, 0x0Cu, 20.0f, 150, 300));
    deliver(system_frame(0, 0x13u, 0, 0));
    EXPECT_ONLY_FED();
    /* the preset is still there: a position start runs it */
    deliver(system_frame(1, 0x10u, 0, 0));
    const daran_move_t *move = EXPECT_MOVE();
    TEST_ASSERT_EQUAL_INT(DARAN_MOVE_FILTERED_POSITION, move->kind);
    TEST_ASSERT_EQUAL_FLOAT(20.0f, move->pos_deg);
}

/* ---- C2: the relative flag of starts 0x10..0x12 ---- */

static void test_c2_relative_flag_0_is_absolute_1_and_100_relative_others_ignored(void)
{
    SKIP_IF_NO_MULTI();
    static const struct {
        uint32_t flag;
        int relative; /* 1 relative, 0 absolute, -1 ignored */
    } flags[] = {{0, 0}, {1, 1}, {100, 1}, {2, -1}, {99, -1}, {101, -1}, {200, -1}, {0xFFFF, -1}};
    for (uint32_t sub = 0x10; sub <= 0x12u; sub++) {
        for (size_t i = 0; i < sizeof flags / sizeof flags[0]; i++) {
            start_drive(1);
            m->props[DARAN_PROP_POS_SETPOINT].f32 = 100.0f;
            m->props[DARAN_PROP_INPUT_POS].f32 = 100.0f;
            /* target 10, 20 s, 30 (r/min)/s (a timed move with room to spare) */
            deliver(motion_frame(1, 0x0Cu, 10.0f, 2000, 3000));
            /* bytes 6..7 carry garbage: ignored for these starts */
            deliver(system_frame(1, sub, flags[i].flag, 0xBEEF));
            char what[48];
            snprintf(what, sizeof what, "start 0x%02x flag %u", (unsigned)sub, (unsigned)flags[i].flag);
            if (flags[i].relative < 0) {
                EXPECT_ONLY_FED();
                /* ignored, the preset kept: an absolute start runs it */
                deliver(system_frame(1, sub, 0, 0));
            }
            const daran_move_t *move = EXPECT_MOVE();
            TEST_ASSERT_EQUAL_FLOAT_MESSAGE(flags[i].relative == 1 ? 110.0f : 10.0f, move->pos_deg, what);
        }
    }
}

/* ---- C3: raw / 100, correctly rounded ---- */

/* The distance of @p value from raw / 100, in units of 1/100: exact in double. */
static double error_of(float value, int32_t raw)
{
    return fabs((double)value * 100.0 - (double)raw);
}

static void expect_nearest(float value, int32_t raw)
{
    bool nearest = error_of(value, raw) <= error_of(nextafterf(value, INFINITY), raw) &&
                   error_of(value, raw) <= error_of(nextafterf(value, -INFINITY), raw);
    if (!nearest) {
        TEST_FAIL_MESSAGE_F("raw %d became %.9g, not the float nearest raw / 100", (int)raw, (double)value);
    }
}

static void test_c3_every_scaled_value_is_raw_over_100_correctly_rounded(void)
{
    /* p's two scaled fields take any value: all 65536 raws, two a frame */
    for (int32_t raw = -32768; raw < 0; raw++) {
        int32_t other = -1 - raw; /* 32767 .. 0 */
        deliver(motion_frame(1, 0x1Bu, 1.0f, raw, other));
        const daran_move_t *move = EXPECT_MOVE();
        expect_nearest(move->vel_rpm, raw);
        expect_nearest(move->torque_nm, other);
        if (raw % 100 == 0) {
            TEST_ASSERT_EQUAL_FLOAT((float)(raw / 100), move->vel_rpm);
        }
    }
}

static void test_c3_the_libraries_truncated_values_arrive_as_sent(void)
{
    /* set_speed(1, 20, 1.15): 114 (1.14 Nm); set_angle(2, 10, 0.29, 0.57, 2): 28, 56 */
    deliver(frame_hex(0x03C, "00 00 a0 41 72 00 01 00"));
    const daran_move_t *move = EXPECT_MOVE();
    TEST_ASSERT_EQUAL_HEX32(daran_bits_of(1.14f), daran_bits_of(move->torque_nm));
    start_drive(2);
    deliver(frame_hex(0x05B, "00 00 20 41 1c 00 38 00"));
    move = EXPECT_MOVE();
    TEST_ASSERT_EQUAL_HEX32(daran_bits_of(0.28f), daran_bits_of(move->vel_rpm));
    TEST_ASSERT_EQUAL_HEX32(daran_bits_of(0.56f), daran_bits_of(move->torque_nm));
}

/* ---- C6, C7, C25: type codes ---- */

typedef struct write_case {
    const char *what;
    uint32_t address;
    uint32_t type;
    uint32_t value;   /* bytes 4..7 */
    bool accepted;
    uint32_t written; /* the value's bits as the HAL gets them */
} write_case_t;

static const write_case_t write_cases[] = {
    {"u16 bool, garbage in bytes 6..7", 31202, 1, 0xABCD0001u, true, 1},
    {"u16 u32 row", 10001, 1, 0x00002580u, true, 9600},
    {"s16 positive to a u32 row", 10001, 2, 0xFFFF2580u, true, 9600},
    {"s32 to a u32 row", 10001, 4, 9600, true, 9600},
    {"f32 integral to a u32 row", 10001, 0, 0x46160000u, true, 9600},       /* 9600.0 */
    {"f32 integral to a bool", 31214, 0, 0x3F800000u, true, 1},              /* 1.0 */
    {"f32 fraction to a u32 row", 10001, 0, 0x46160200u, false, 0},          /* 9600.5 */
    {"f32 fraction to a bool", 31214, 0, 0x3F000000u, false, 0},             /* 0.5 */
    {"f32 negative to a u32 row", 21004, 0, 0xBF800000u, false, 0},          /* -1.0 */
    {"f32 beyond u32 to a u32 row", 21004, 0, 0x4F800000u, false, 0},        /* 2^32 */
    {"f32 NaN to a u32 row", 21004, 0, 0x7FC00000u, false, 0},
    {"f32 infinity to a u32 row", 21004, 0, 0x7F800000u, false, 0},
    {"s16 negative to a u32 row", 21004, 2, 0x0000FFFFu, false, 0},
    {"s32 negative to a u32 row", 21004, 4, 0xFFFFFFFFu, false, 0},
    {"u32 to a u32 row", 21004, 3, 0xFFFFFFFFu, true, 0xFFFFFFFFu},
    {"s16 -1 to an s32 row", 33108, 2, 0x1234FFFFu, true, 0xFFFFFFFFu},
    {"s32 -1 to an s32 row", 33108, 4, 0xFFFFFFFFu, true, 0xFFFFFFFFu},
    {"f32 -1 to an s32 row", 33108, 0, 0xBF800000u, true, 0xFFFFFFFFu},
    {"u16 65535 to an s32 row", 33108, 1, 0x0000FFFFu, false, 0},
    {"u32 beyond s32 to an s32 row", 34103, 3, 0x80000000u, false, 0},
    {"s32 INT32_MAX to an s32 row", 31206, 4, 0x7FFFFFFFu, true, 0x7FFFFFFFu},
    {"u32 INT32_MAX to an s32 row", 31206, 3, 0x7FFFFFFFu, true, 0x7FFFFFFFu},
    {"s32 INT32_MIN to an s32 row", 31206, 4, 0x80000000u, true, 0x80000000u},
    {"f32 -2^31 to an s32 row", 31206, 0, 0xCF000000u, true, 0x80000000u},
    {"f32 2^31 to an s32 row", 31206, 0, 0x4F000000u, false, 0},
    {"u32 to an s32 row", 34103, 3, 4096, true, 4096},
    {"f32 to an f32 row", 38004, 0, 0xC2B8F038u, true, 0xC2B8F038u},
    {"u32 to an f32 row, to the nearest float", 38004, 3, 16777217u, true, 0x4B800000u},
    {"s16 to an f32 row", 38004, 2, 0x0000FFFBu, true, 0xC0A00000u},         /* -5 */
    {"s32 to an f32 row", 38004, 4, 0xFFFFFF9Cu, true, 0xC2C80000u},         /* -100 */
    {"u16 to an f32 row", 38004, 1, 0xFFFF0064u, true, 0x42C80000u},         /* 100 */
    {"f32 NaN to an f32 row", 38004, 0, 0x7FC00000u, false, 0},
    {"f32 -NaN to an f32 row", 38004, 0, 0xFFC00001u, false, 0},
    {"f32 infinity to an f32 row", 38004, 0, 0x7F800000u, false, 0},
    {"f32 -infinity to an f32 row", 38004, 0, 0xFF800000u, false, 0},
    {"type code 5", 10001, 5, 9600, false, 0},
    {"type code 65535", 10001, 0xFFFF, 9600, false, 0},
    {"u32 2 to a bool", 31214, 3, 2, false, 0},
    {"u16 0x10000 does not fit: only the low half counts", 31214, 1, 0x00010000u, true, 0},
};

static void run_write_case(const void *arg)
{
    const write_case_t *c = arg;
    const can_row_t *row = row_at(c->address);
    TEST_ASSERT_NOT_NULL(row);
    deliver(WRITE_FRAME(1, c->address, c->type, c->value));
    if (!c->accepted) {
        EXPECT_ONLY_FED();
        return;
    }
    TEST_ASSERT_EQUAL_HEX32(c->written, EXPECT_SET(row->prop).u32);
}

static void test_c7_a_read_reply_carries_the_property_s_own_type_code_whatever_was_asked(void)
{
    static const uint32_t asked[] = {0, 1, 2, 3, 4, 5, 0xFFFF};
    static const uint32_t addresses[] = {1, 10001, 33108, 31214, 50005};
    for (size_t a = 0; a < sizeof addresses / sizeof addresses[0]; a++) {
        const can_row_t *row = row_at(addresses[a]);
        TEST_ASSERT_NOT_NULL(row);
        for (size_t t = 0; t < sizeof asked / sizeof asked[0]; t++) {
            deliver(property_frame(1, 0x1Eu, addresses[a], asked[t], 0xFFFFFFFFu));
            TEST_ASSERT_EQUAL_UINT(1, m->n_calls);
            TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
            daran_can_frame_t want = read_reply_of(m, 1, row);
            expect_frame(__LINE__, 0, &want);
        }
    }
}

static void test_every_address_of_the_list_is_read_with_its_type_and_value(void)
{
    size_t rows = 0;
    for (size_t i = 0; i < CAN_ROWS; i++) {
        const can_row_t *row = &can_rows[i];
        if (row->address == 0u) {
            continue;
        }
        /* a recognisable value in the property's own bits (but the node
         * id, which decides whether the next frame is for this drive) */
        if (row->prop != DARAN_PROP_CAN_NODE_ID) {
            m->props[row->prop].u32 = 0x5A000000u + (uint32_t)i;
        }
        deliver(READ_FRAME(1, row->address, type_code_of(row->type)));
        daran_can_frame_t want = read_reply_of(m, 1, row);
        expect_frame(__LINE__, 0, &want);
        TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
        rows++;
    }
    /* the vendor's 159 paths and the 5 extensions (2.10) */
    TEST_ASSERT_EQUAL_UINT(164, rows);
}

static void test_an_address_outside_the_list_is_never_answered(void)
{
    /* every address, up to eight frames a poll */
    const uint32_t batch = DARAN_CAN_RX_FRAMES < 8 ? DARAN_CAN_RX_FRAMES : 8u;
    for (uint32_t first = 1; first <= 0xFFFFu; first += batch) {
        mock_clear(m);
        bus.n_sent = 0;
        size_t expected = 0;
        for (uint32_t address = first; address < first + batch && address <= 0xFFFFu; address++) {
            daran_can_frame_t frame = READ_FRAME(1, address, 3);
            TEST_ASSERT_TRUE(daran_can_receive(&can, &frame));
            expected += row_at(address) != NULL;
        }
        (void)daran_can_poll(&can);
        TEST_ASSERT_EQUAL_UINT(expected, bus.n_sent);
        for (size_t i = 0; i < bus.n_sent; i++) {
            TEST_ASSERT_NOT_NULL(row_at(get_u16(bus.sent[i].data)));
        }
    }
}

static void test_c8_a_broadcast_read_is_answered_with_the_own_id(void)
{
    start_drive(5);
    deliver(READ_FRAME(0, 31001, 3));
    EXPECT_SENT(0, 0x0BE, "19 79 03 00 05 00 00 00");
    deliver(READ_FRAME(5, 31001, 3));
    EXPECT_SENT(0, 0x0BE, "19 79 03 00 05 00 00 00");
    /* and a broadcast fast read with the own id in the status frame */
    deliver(READ_FRAME(0, 0, 0));
    daran_can_frame_t want = status_of(m, 5);
    expect_frame(__LINE__, 0, &want);
}

/* ---- 2.7: the status frame ---- */

typedef struct status_case {
    const char *what;
    uint32_t node;
    float pos, vel, torque;
    uint32_t done, error, warnings;
    uint32_t id;
    const char *hex;
} status_case_t;

static const status_case_t status_cases[] = {
    {"the worked example of 6.6", 3, 90.0f, 12.34f, -0.5f, 1, 0, 0, 0x063, "00 00 b4 42 d2 04 ce ff"},
    {"the e-stop, saturated fields", 1, -92.46918f, 400.0f, -400.0f, 0, DARAN_FLAG_ESTOP, 0, 0x025, "38 f0 b8 c2 ff 7f 00 80"},
    {"327.67 and -327.68, a fault bit", 1, 0.0f, 327.67f, -327.68f, 1, 1, 0, 0x027, "00 00 00 00 ff 7f 00 80"},
    {"ties away from zero, a warning is no error", 1, 1.0f, 0.125f, -0.125f, 0, 0, DARAN_WARNING_NVM_CORRUPT, 0x021, "00 00 80 3f 0d 00 f3 ff"},
    {"-0 and small values at node 63", 63, -0.0f, 0.004f, -0.006f, 1, 0, 0, 0x7E3, "00 00 00 80 00 00 ff ff"},
    {"beyond the field, saturated", 2, 1e30f, 1e30f, -1e30f, 1, 0, 0, 0x043, "ca f2 49 71 ff 7f 00 80"},
    {"infinities saturated", 2, 0.0f, INFINITY, -INFINITY, 0, 0, 0, 0x041, "00 00 00 00 ff 7f 00 80"},
    {"just below the field's ends", 2, 0.0f, 327.675f, -327.675f, 0, 0, 0, 0x041, "00 00 00 00 ff 7f 01 80"},
};

static void run_status_case(const void *arg)
{
    const status_case_t *c = arg;
    start_drive(c->node);
    m->props[DARAN_PROP_POS_ESTIMATE].f32 = c->pos;
    m->props[DARAN_PROP_VEL_ESTIMATE].f32 = c->vel;
    m->props[DARAN_PROP_TORQUE_ESTIMATE].f32 = c->torque;
    m->props[DARAN_PROP_TRAJECTORY_DONE].u32 = c->done;
    m->props[DARAN_PROP_AXIS_ERROR].u32 = c->error;
    m->props[DARAN_PROP_CONFIG_WARNINGS].u32 = c->warnings;
    deliver(READ_FRAME(c->node, 0, 3));
    TEST_ASSERT_EQUAL_UINT(1, m->n_calls);
    TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
    EXPECT_SENT(0, c->id, c->hex);
    daran_can_frame_t want = status_of(m, c->node);
    expect_frame(__LINE__, 0, &want);
}

/* The status frame's velocity and torque counts (2.7) for a drive whose
 * estimates are value and -value, through a fast read. */
static void status_counts(float value, int32_t *vel, int32_t *torque)
{
    m->props[DARAN_PROP_VEL_ESTIMATE].f32 = value;
    m->props[DARAN_PROP_TORQUE_ESTIMATE].f32 = -value;
    mock_clear(m);
    bus.n_sent = 0;
    daran_can_frame_t fast_read = READ_FRAME(1, 0, 0);
    TEST_ASSERT_TRUE(daran_can_receive(&can, &fast_read));
    (void)daran_can_poll(&can);
    TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
    *vel = (int16_t)get_u16(bus.sent[0].data + 4);
    *torque = (int16_t)get_u16(bus.sent[0].data + 6);
}

/* Every float near a half count (k + 0.5) / 100 for k = 0..32767, its
 * neighbours, and their negatives: the status frame's velocity and torque
 * are value x 100 rounded to the nearest count, ties away from zero (2.7,
 * C3), as exact arithmetic says. */
static void test_the_status_frame_rounds_near_half_counts_to_the_nearest(void)
{
    size_t wrong = 0;
    float first_wrong = 0.0f;
    for (int32_t k = 0; k < 32767; k++) {
        float near_half = (float)(((double)k + 0.5) / 100.0);
        float value = nextafterf(nextafterf(nextafterf(near_half, -INFINITY), -INFINITY), -INFINITY);
        for (int step = 0; step < 7; step++, value = nextafterf(value, INFINITY)) {
            int32_t vel;
            int32_t torque;
            status_counts(value, &vel, &torque);
            if (vel != scaled_of(value) || torque != scaled_of(-value)) {
                if (wrong++ == 0u) {
                    first_wrong = value;
                }
            }
        }
    }
    if (wrong != 0u) {
        TEST_FAIL_MESSAGE_F("%u of %u values were not rounded to the nearest count, the first %.9g "
                            "(x 100 = %.12g; sent %d, nearest %d)",
                            (unsigned)wrong, 7u * 32767u, (double)first_wrong, (double)first_wrong * 100.0,
                            (int)scaled_of(first_wrong) + 1, (int)scaled_of(first_wrong));
    }
}

/* Every power of two a float has (and its neighbours at the field's ends),
 * both signs, in the status frame: value x 100 to the nearest count, or the
 * field's end when it does not fit (2.7). The exact rounding takes |value| =
 * m x 2^-shift apart; this walks every shift, the ones past the field
 * included. */
static void test_the_status_frame_saturates_at_every_scale(void)
{
    float values[2 * 277 + 8];
    size_t count = 0;
    for (int e = -149; e <= 127; e++) {
        values[count++] = ldexpf(1.0f, e);
        values[count++] = nextafterf(ldexpf(1.0f, e), INFINITY);
    }
    static const float ends[] = {327.67f, 327.674f, 327.675f, 327.68f, INFINITY, FLT_MAX, 8388607.5f,
                                 16777215.0f};
    for (size_t i = 0; i < sizeof ends / sizeof ends[0]; i++) {
        values[count++] = ends[i];
    }
    for (size_t i = 0; i < count; i++) {
        for (int sign = 1; sign >= -1; sign -= 2) {
            float value = (float)sign * values[i];
            int32_t vel;
            int32_t torque;
            status_counts(value, &vel, &torque);
            char what[48];
            (void)snprintf(what, sizeof what, "%a", (double)value);
            TEST_ASSERT_EQUAL_INT32_MESSAGE(scaled_of(value), vel, what);
            TEST_ASSERT_EQUAL_INT32_MESSAGE(scaled_of(-value), torque, what);
        }
    }
}

/* ---- C10, 2.8: the automatic status reply ---- */

static void test_c10_no_status_reply_without_enable_reply_state(void)
{
    deliver(frame_hex(0x039, "00 00 b4 42 00 00 e8 03"));
    (void)EXPECT_MOVE();
    if (DARAN_ENABLE_MULTI_MOTOR) {
        deliver(frame_hex(0x02C, "00 00 20 41 00 00 d0 07"));
        EXPECT_ONLY_FED();
    }
}

static void test_c10_each_preset_and_direct_motion_gets_one_status_frame_with_reply_state(void)
{
    static const hex_frame_t frames[] = {
        {0x039, "00 00 b4 42 00 00 e8 03"}, {0x03a, "00 00 16 c3 e8 03 f4 01"},
        {0x03b, "00 00 f0 41 f4 01 1e 00"}, {0x03c, "00 00 a0 41 f4 01 02 00"},
        {0x03d, "00 00 00 3f 00 00 01 00"}, {0x02c, "00 00 20 41 00 00 d0 07"},
        {0x019, "00 00 b4 42 00 00 e8 03"}, {0x00c, "00 00 20 41 00 00 d0 07"},
    };
    for (size_t i = 0; i < sizeof frames / sizeof frames[0]; i++) {
        bool preset = (frames[i].id & 0x1Fu) == 0x0Cu;
        if (preset && !DARAN_ENABLE_MULTI_MOTOR) {
            continue;
        }
        start_drive(1);
        m->props[DARAN_PROP_ENABLE_REPLY_STATE].u32 = 1;
        m->props[DARAN_PROP_TRAJECTORY_DONE].u32 = (uint32_t)(i & 1u);
        m->props[DARAN_PROP_POS_ESTIMATE].f32 = 1.5f * (float)i;
        deliver(frame_hex(frames[i].id, frames[i].hex));
        if (preset) {
            expect_fed_first(__LINE__);
            TEST_ASSERT_EQUAL_UINT(1, m->n_calls);
        } else {
            (void)expect_move(__LINE__, 1u);
        }
        TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
        daran_can_frame_t want = status_of(m, 1);
        expect_frame(__LINE__, 0, &want);
    }
}

static void test_c10_starts_writes_reads_and_system_commands_get_no_status_reply(void)
{
    m->props[DARAN_PROP_ENABLE_REPLY_STATE].u32 = 1;
    if (DARAN_ENABLE_MULTI_MOTOR) {
        deliver(frame_hex(0x02C, "00 00 20 41 00 00 d0 07"));
        TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
        deliver(frame_hex(0x028, "10 00 00 00 00 00 00 00"));
        (void)EXPECT_MOVE();
    }
    deliver(frame_hex(0x03F, "7c 94 00 00 00 00 70 42"));
    (void)EXPECT_SET(DARAN_PROP_SHAFT_VEL_LIMIT);
    deliver(frame_hex(0x028, "01 00 00 00 00 00 00 00"));
    EXPECT_ACTION(DARAN_ACTION_SAVE_CONFIG);
    deliver(READ_FRAME(1, 38012, 0));
    TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
    TEST_ASSERT_EQUAL_HEX32(0x03E, bus.sent[0].id);
}

/* ---- C27 with C10: a frame refused for its values: no effect, no reply ---- */

typedef struct refused_row {
    const char *what;
    uint32_t id;
    const char *hex;
} refused_row_t;

static const refused_row_t refused_rows[] = {
    {"t NaN position", 0x039, "00 00 c0 7f 00 00 e8 03"},
    {"t infinite position", 0x039, "00 00 80 ff 00 00 e8 03"},
    {"t negative bandwidth", 0x039, "00 00 b4 42 00 00 9c ff"},
    {"q velocity 0", 0x03A, "00 00 b4 42 00 00 f4 01"},
    {"q negative velocity", 0x03A, "00 00 b4 42 9c ff f4 01"},
    {"q negative acceleration", 0x03A, "00 00 b4 42 e8 03 ff ff"},
    {"q NaN position", 0x03A, "01 00 c0 ff e8 03 f4 01"},
    {"p infinite position", 0x03B, "00 00 80 7f f4 01 1e 00"},
    {"v NaN velocity", 0x03C, "00 00 c0 7f 96 00 01 00"},
    {"v mode 3", 0x03C, "00 00 a0 41 96 00 03 00"},
    {"v ramp negative", 0x03C, "00 00 a0 41 9c ff 02 00"},
    {"v ramp negative, mode 200", 0x03C, "00 00 a0 41 9c ff c8 00"},
    {"c mode 0", 0x03D, "00 00 c0 3f 00 00 00 00"},
    {"c ramp negative", 0x03D, "00 00 c0 3f 9c ff 06 00"},
    {"c infinite torque", 0x03D, "00 00 80 7f 00 00 01 00"},
    {"preset NaN target", 0x02C, "00 00 c0 7f 00 00 64 00"},
    {"write uart baud 9601", 0x03F, "11 27 03 00 81 25 00 00"},
    {"write requested_state 3", 0x03F, "33 75 03 00 03 00 00 00"},
    {"write can_node_id 64", 0x03F, "19 79 03 00 40 00 00 00"},
    {"write can_node_id 0", 0x03F, "19 79 03 00 00 00 00 00"},
    {"write can baud 100000", 0x03F, "09 52 03 00 a0 86 01 00"},
    {"write can protocol 2", 0x03F, "0a 52 03 00 02 00 00 00"},
    {"write a bool 2", 0x03F, "ee 79 03 00 02 00 00 00"},
    {"write pos_gain -1", 0x03F, "6c 7d 00 00 00 00 80 bf"},
    {"write vel_limit 0", 0x03F, "7c 94 00 00 00 00 00 00"},
    {"write traj_mode 3", 0x03F, "20 89 03 00 03 00 00 00"},
    {"write the read-only vbus_voltage", 0x03F, "01 00 00 00 00 00 40 41"},
    {"write the read-only pos_estimate", 0x03F, "77 94 00 00 00 00 40 41"},
    {"write the read-only fw_version", 0x03F, "06 00 03 00 01 00 00 00"},
    {"write 1 to the error register", 0x03F, "31 75 03 00 01 00 00 00"},
    {"write 1 to can.error", 0x03F, "21 4e 03 00 01 00 00 00"},
    {"write to an unknown address", 0x03F, "07 00 03 00 01 00 00 00"},
    {"write to 60000 (no port rows)", 0x03F, "60 ea 03 00 01 00 00 00"},
    {"read an unknown address", 0x03E, "07 00 03 00 00 00 00 00"},
    {"read 50006", 0x03E, "56 c3 03 00 00 00 00 00"},
    {"read 65535", 0x03E, "ff ff 03 00 00 00 00 00"},
    {"system sub-code 0x08", 0x028, "08 00 00 00 00 00 00 00"},
    {"system sub-code 0x16", 0x028, "16 00 00 00 00 00 00 00"},
    {"system sub-code 0x21", 0x028, "21 00 00 00 00 00 00 00"},
    {"system sub-code 0x10010", 0x028, "10 00 01 00 00 00 00 00"},
    {"system sub-code 0x01000006", 0x028, "06 00 00 01 00 00 00 00"},
    {"system sub-code 0xffffffff", 0x028, "ff ff ff ff 00 00 00 00"},
    {"the feed sub-code 0x20", 0x028, "20 00 00 00 00 00 00 00"},
    {"a start without a preset", 0x028, "10 00 00 00 00 00 00 00"},
    {"a broadcast start without a preset", 0x008, "11 00 00 00 01 00 00 00"},
    {"an impedance start without a preset", 0x028, "15 00 00 00 14 00 05 00"},
};

/* The drive's store before a refused frame, to show it unchanged after. */
static daran_value_t store_before[DARAN_PROP_COUNT];

static void run_refused_row(const void *arg)
{
    const refused_row_t *row = arg;
    m->props[DARAN_PROP_ENABLE_REPLY_STATE].u32 = 1;
    memcpy(store_before, m->props, sizeof store_before);
    deliver(frame_hex(row->id, row->hex));
    EXPECT_ONLY_FED();
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(store_before, m->props, sizeof m->props, "the store changed");
    /* a preset the frame refused was not stored either */
    if (DARAN_ENABLE_MULTI_MOTOR) {
        deliver(frame_hex(0x028, "10 00 00 00 00 00 00 00"));
        EXPECT_ONLY_FED();
    }
}

/* Starts refused for the preset's values (C23, C27): ignored, the preset
 * kept for a start that can run it. */
static void test_c27_a_start_refused_for_its_values_is_ignored_and_keeps_the_preset(void)
{
    SKIP_IF_NO_MULTI();
    static const struct {
        const char *preset;
        const char *start;
    } rows[] = {
        {"00 00 20 41 9c ff e8 03", "11 00 00 00 00 00 00 00"}, /* mq duration -1 s */
        {"00 00 20 41 f4 01 9c ff", "11 00 00 00 00 00 00 00"}, /* mq acceleration -1 */
        {"00 00 20 41 00 00 9c ff", "10 00 00 00 00 00 00 00"}, /* mt bandwidth -1 */
        {"00 00 20 41 f4 01 2c 01", "13 00 00 00 00 00 00 00"}, /* mv mode raw 300 */
        {"00 00 20 41 9c ff c8 00", "13 00 00 00 00 00 00 00"}, /* mv ramp -1 */
        {"00 00 20 41 9c ff 58 02", "14 00 00 00 00 00 00 00"}, /* mc ramp -1 */
        {"00 00 20 41 00 00 00 00", "14 00 00 00 00 00 00 00"}, /* mc mode raw 0 */
        {"00 00 20 41 f4 01 32 00", "15 00 00 00 ff ff 05 00"}, /* impedance kp -0.01 */
        {"00 00 20 41 f4 01 32 00", "15 00 00 00 14 00 fb ff"}, /* impedance kd -0.05 */
        {"00 00 20 41 01 00 e8 03", "11 00 00 00 00 00 00 00"}, /* mq 0.01 s for 80 deg: infeasible */
    };
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        start_drive(1);
        m->props[DARAN_PROP_POS_SETPOINT].f32 = 90.0f;
        m->props[DARAN_PROP_ENABLE_REPLY_STATE].u32 = 1;
        deliver(frame_hex(0x02C, rows[i].preset));
        TEST_ASSERT_EQUAL_UINT(1, bus.n_sent); /* the preset itself passed */
        memcpy(store_before, m->props, sizeof store_before);
        deliver(frame_hex(0x028, rows[i].start));
        EXPECT_ONLY_FED();
        TEST_ASSERT_EQUAL_MEMORY(store_before, m->props, sizeof m->props);
        deliver(frame_hex(0x028, "12 00 00 00 00 00 00 00"));
        const daran_move_t *move = EXPECT_MOVE();
        TEST_ASSERT_EQUAL_INT(DARAN_MOVE_PASSTHROUGH, move->kind);
        TEST_ASSERT_EQUAL_FLOAT(10.0f, move->pos_deg);
    }
}

/* ---- a timed start keeps its time (protocol.md 10.5, D42; C13) ---- */

/* The time a trapezoid (or S-curve) move with this cruise velocity and
 * acceleration takes over @p distance degrees. */
static float profile_time(const daran_move_t *move, float distance, bool s_curve)
{
    float v = move->vel_rpm * 6.0f, a = move->rate * 6.0f;
    return distance / v + (s_curve ? 2.0f : 1.0f) * v / a;
}

/* Drive 1 at 90 deg; a CAN preset of @p target in @p duration_raw / 100 s at
 * 10 (r/min)/s, started by a broadcast 0x11. */
static void timed_start(float target, int32_t duration_raw)
{
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 90.0f;
    m->props[DARAN_PROP_INPUT_POS].f32 = 90.0f;
    deliver(motion_frame(1, 0x0Cu, target, duration_raw, 1000));
    deliver(system_frame(0, 0x11u, 0, 0));
}

/* 10.5: @p move is the cruise-less move from @p from to @p target that
 * lands exactly after @p duration s: peak 2D/T, acceleration 4D/T^2 (8D/T^2
 * for an S-curve), faster than the preset's acceleration asked. */
static void check_move_in_time(const daran_move_t *move, float from, float target, float duration,
                               bool s_curve)
{
    float distance = fabsf(target - from);
    TEST_ASSERT_EQUAL_INT(DARAN_MOVE_TRAPEZOID, move->kind);
    TEST_ASSERT_EQUAL_UINT(DARAN_GIVEN_VEL | DARAN_GIVEN_RATE, move->given);
    TEST_ASSERT_EQUAL_FLOAT(target, move->pos_deg);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 2.0f * distance / duration / 6.0f, move->vel_rpm);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, (s_curve ? 8.0f : 4.0f) * distance / (duration * duration) / 6.0f,
                             move->rate);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, duration, profile_time(move, distance, s_curve));
}

static void expect_move_in_time(int line, float target, float duration, bool s_curve)
{
    check_move_in_time(expect_move(line, 0u), 90.0f, target, duration, s_curve);
}

static void test_c13_a_can_preset_9_ms_short_of_the_least_duration_keeps_its_time(void)
{
    SKIP_IF_NO_MULTI();
    /* the recorded set_angles: 80 deg at 10 (r/min)/s takes 2.3094 s, sent 2.30 */
    timed_start(10.0f, 230);
    expect_move_in_time(__LINE__, 10.0f, 2.30f, false);
}

static void test_the_same_start_of_an_ascii_preset_keeps_its_time_too(void)
{
    SKIP_IF_NO_MULTI();
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 90.0f;
    m->props[DARAN_PROP_INPUT_POS].f32 = 90.0f;
    mock_send_line(m, "ms 1 10 2.3 10");
    TEST_ASSERT_EQUAL_STRING("", m->out);
    deliver(system_frame(0, 0x11u, 0, 0)); /* a CAN start of the ASCII preset */
    expect_move_in_time(__LINE__, 10.0f, 2.3f, false);
    start_drive(1);
    m->props[DARAN_PROP_POS_SETPOINT].f32 = 90.0f;
    m->props[DARAN_PROP_INPUT_POS].f32 = 90.0f;
    mock_send_line(m, "ms 1 10 2.3 10");
    mock_clear(m);
    mock_send_line(m, "mq 1 0");
    TEST_ASSERT_EQUAL_STRING("", m->out);
    TEST_ASSERT_EQUAL_UINT(1, mock_count(m, MOCK_CALL_MOVE));
    TEST_ASSERT_EQUAL_INT(MOCK_CALL_MOVE, m->calls[0].kind);
    check_move_in_time(&m->calls[0].move, 90.0f, 10.0f, 2.3f, false);
}

static void test_a_can_start_far_short_of_its_acceleration_keeps_its_time(void)
{
    SKIP_IF_NO_MULTI();
    timed_start(10.0f, 100); /* 80 deg in 1 s where 10 (r/min)/s needs 2.31 s */
    expect_move_in_time(__LINE__, 10.0f, 1.0f, false);
}

static void test_a_can_start_beyond_the_velocity_limit_is_ignored_and_kept(void)
{
    SKIP_IF_NO_MULTI();
    /* 80 deg in 1 s peaks at 160 deg/s = 26.67 r/min */
    m->props[DARAN_PROP_SHAFT_VEL_LIMIT].f32 = 26.6f;
    timed_start(10.0f, 100);
    EXPECT_ONLY_FED();
    deliver(system_frame(1, 0x10u, 0, 0)); /* the preset is still there */
    TEST_ASSERT_EQUAL_FLOAT(10.0f, EXPECT_MOVE()->pos_deg);
    start_drive(1);
    m->props[DARAN_PROP_SHAFT_VEL_LIMIT].f32 = 26.7f;
    timed_start(10.0f, 100);
    expect_move_in_time(__LINE__, 10.0f, 1.0f, false);
}

static void test_c13_a_can_start_within_10_ms_of_the_least_runs_whatever_the_limit(void)
{
    SKIP_IF_NO_MULTI();
    /* as a duration just long enough would: its peak is the least-time one */
    m->props[DARAN_PROP_SHAFT_VEL_LIMIT].f32 = 5.0f;
    timed_start(10.0f, 230);
    expect_move_in_time(__LINE__, 10.0f, 2.30f, false);
    /* 10.6 ms short: the least time of 80.0826 deg is 2.3106 s; now the limit counts */
    start_drive(1);
    m->props[DARAN_PROP_SHAFT_VEL_LIMIT].f32 = 5.0f;
    timed_start(90.0f - 80.0826f, 230);
    EXPECT_ONLY_FED();
}

static void test_c13_an_s_curve_start_short_by_9_ms_keeps_its_time(void)
{
    SKIP_IF_NO_MULTI();
    if (!DARAN_ENABLE_S_CURVE) {
        TEST_IGNORE_MESSAGE("S-curves are compiled out");
    }
    m->props[DARAN_PROP_TRAJ_MODE].u32 = 2;
    timed_start(50.0f, 230); /* 40 deg: 2.3094 s as an S-curve */
    expect_move_in_time(__LINE__, 50.0f, 2.30f, true);
}

static void test_c13_duration_0_over_distance_0_is_accepted(void)
{
    SKIP_IF_NO_MULTI();
    timed_start(90.0f, 0);
    const daran_move_t *move = EXPECT_MOVE();
    TEST_ASSERT_EQUAL_INT(DARAN_MOVE_TRAPEZOID, move->kind);
    TEST_ASSERT_EQUAL_FLOAT(90.0f, move->pos_deg);
    deliver(system_frame(0, 0x11u, 0, 0));
    EXPECT_ONLY_FED(); /* consumed */
}

/* ---- C14: node ids ---- */

static void test_c14_a_new_node_id_applies_at_once_and_0_is_refused(void)
{
    deliver(WRITE_FRAME(1, 31001, 3, 0));
    EXPECT_ONLY_FED();
    deliver(WRITE_FRAME(0, 31001, 3, 0));
    EXPECT_ONLY_FED();
    deliver(WRITE_FRAME(1, 31001, 3, 5));
    TEST_ASSERT_EQUAL_UINT32(5, EXPECT_SET(DARAN_PROP_CAN_NODE_ID).u32);
    /* the next frame is filtered with the new id */
    deliver(READ_FRAME(1, 31001, 3));
    EXPECT_UNTOUCHED();
    deliver(READ_FRAME(5, 31001, 3));
    EXPECT_SENT(0, 0x0BE, "19 79 03 00 05 00 00 00");
}

/* ---- C15: can.config.protocol 0 ---- */

static void expect_silent_front_end(void)
{
    static const hex_frame_t frames[] = {
        {0x039, "00 00 b4 42 00 00 e8 03"}, {0x03e, "00 00 00 00 00 00 00 00"},
        {0x03e, "19 79 03 00 00 00 00 00"}, {0x03f, "0a 52 03 00 01 00 00 00"},
        {0x028, "06 00 00 00 00 00 00 00"}, {0x023, "00 00 00 00 00 00 00 00"},
        {0x02c, "00 00 20 41 00 00 d0 07"}, {0x008, "10 00 00 00 00 00 00 00"},
    };
    for (size_t i = 0; i < sizeof frames / sizeof frames[0]; i++) {
        deliver(frame_hex(frames[i].id, frames[i].hex));
        EXPECT_UNTOUCHED();
    }
    /* no heartbeat and no node guard either */
    for (uint32_t t = 100; t <= 1000u; t += 100u) {
        bus.now_ms = t;
        mock_clear(m);
        TEST_ASSERT_EQUAL_UINT(0, daran_can_poll(&can));
        EXPECT_UNTOUCHED();
    }
}

static void test_c15_protocol_0_at_init_leaves_the_front_end_silent(void)
{
    m->props[DARAN_PROP_CAN_PROTOCOL].u32 = 0;
    m->props[DARAN_PROP_CAN_HEARTBEAT_MS].u32 = 100;
    m->props[DARAN_PROP_CAN_TIMEOUT_MS].u32 = 50;
    m->props[DARAN_PROP_ENABLE_REPLY_STATE].u32 = 1;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_can_init(&can, &m->drive));
    expect_silent_front_end();
}

static void test_c15_a_protocol_written_over_can_applies_at_the_next_init(void)
{
    deliver(WRITE_FRAME(1, 21002, 3, 0));
    TEST_ASSERT_EQUAL_UINT32(0, EXPECT_SET(DARAN_PROP_CAN_PROTOCOL).u32);
    /* still speaking until the next boot */
    deliver(READ_FRAME(1, 21002, 3));
    EXPECT_SENT(0, 0x03E, "0a 52 03 00 00 00 00 00");
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_can_init(&can, &m->drive));
    m->props[DARAN_PROP_CAN_HEARTBEAT_MS].u32 = 100;
    expect_silent_front_end();
    m->props[DARAN_PROP_CAN_PROTOCOL].u32 = 1;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_can_init(&can, &m->drive));
    deliver(READ_FRAME(1, 21002, 3));
    EXPECT_SENT(0, 0x03E, "0a 52 03 00 01 00 00 00");
}

/* ---- C16: node guarding ---- */

static size_t guard_trips(void)
{
    return mock_count_action(m, DARAN_ACTION_NODE_GUARD);
}

/* Poll at @p now with nothing queued. */
static void tick(uint32_t now)
{
    bus.now_ms = now;
    mock_clear(m);
    bus.n_sent = 0;
    TEST_ASSERT_EQUAL_UINT(0, daran_can_poll(&can));
}

static void test_c16_the_guard_arms_at_the_first_frame_and_trips_once_after_the_timeout(void)
{
    m->props[DARAN_PROP_CAN_TIMEOUT_MS].u32 = 100;
    tick(1000); /* not armed: no frame yet */
    EXPECT_UNTOUCHED();
    bus.now_ms = 1000;
    deliver(READ_FRAME(1, 31001, 3));
    tick(1099);
    EXPECT_UNTOUCHED();
    tick(1100); /* the timeout itself: the limit is reached */
    TEST_ASSERT_EQUAL_UINT(1, m->n_calls);
    TEST_ASSERT_EQUAL_UINT(1, guard_trips());
    TEST_ASSERT_EQUAL_UINT(0, bus.n_sent);
    TEST_ASSERT_EQUAL_HEX32(DARAN_FLAG_WATCHDOG, m->props[DARAN_PROP_AXIS_ERROR].u32 & DARAN_FLAG_WATCHDOG);
    tick(1300); /* once */
    EXPECT_UNTOUCHED();
    tick(90000);
    EXPECT_UNTOUCHED();
    /* the next frame for the drive arms it again */
    bus.now_ms = 90000;
    deliver(frame_hex(0x028, "04 00 00 00 00 00 00 00"));
    EXPECT_ACTION(DARAN_ACTION_CLEAR_ERRORS);
    tick(90050);
    EXPECT_UNTOUCHED();
    tick(90100);
    TEST_ASSERT_EQUAL_UINT(1, guard_trips());
}

static void test_c16_every_frame_for_the_drive_holds_the_guard_off_and_others_do_not(void)
{
    m->props[DARAN_PROP_CAN_TIMEOUT_MS].u32 = 100;
    for (uint32_t t = 0; t <= 1000u; t += 90u) {
        bus.now_ms = t;
        /* a refused frame counts too (C18) */
        deliver(t % 180u == 0u ? WRITE_FRAME(0, 31001, 3, 0) : READ_FRAME(1, 7, 3));
        EXPECT_ONLY_FED();
    }
    for (uint32_t t = 1000; t <= 1080u; t += 40u) {
        bus.now_ms = t;
        deliver(READ_FRAME(2, 31001, 3)); /* another node's */
        EXPECT_UNTOUCHED();
        daran_can_frame_t bad = READ_FRAME(1, 31001, 3);
        bad.dlc = 7;
        TEST_ASSERT_FALSE(offer(&bad));
        deliver(frame_hex(0x02E, "00 00 00 00 00 00 00 00")); /* an unknown code */
        EXPECT_UNTOUCHED();
    }
    tick(1091);
    TEST_ASSERT_EQUAL_UINT(1, guard_trips());
}

static void test_c16_the_guard_is_off_at_timeout_0(void)
{
    deliver(READ_FRAME(1, 31001, 3));
    tick(100000);
    tick(4000000000u);
    EXPECT_UNTOUCHED();
}

static void test_c16_the_guard_measures_across_the_clock_wrap(void)
{
    m->props[DARAN_PROP_CAN_TIMEOUT_MS].u32 = 100;
    bus.now_ms = 0xFFFFFFF0u;
    deliver(READ_FRAME(1, 31001, 3));
    tick(0x50u); /* 96 ms later */
    EXPECT_UNTOUCHED();
    tick(0x55u); /* 101 ms later */
    TEST_ASSERT_EQUAL_UINT(1, guard_trips());
}

/* ---- C17: the heartbeat ---- */

static void test_c17_a_heartbeat_status_frame_goes_out_every_period_at_most_one_a_poll(void)
{
    m->props[DARAN_PROP_CAN_HEARTBEAT_MS].u32 = 100;
    m->props[DARAN_PROP_POS_ESTIMATE].f32 = -45.25f;
    m->props[DARAN_PROP_AXIS_ERROR].u32 = DARAN_FLAG_OVERTEMP;
    tick(50);
    TEST_ASSERT_EQUAL_UINT(0, bus.n_sent);
    tick(101);
    TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
    daran_can_frame_t want = status_of(m, 1);
    expect_frame(__LINE__, 0, &want);
    EXPECT_SENT(0, 0x027, "00 00 35 c2 00 00 00 00");
    TEST_ASSERT_EQUAL_UINT(0, m->n_calls);
    tick(101);
    TEST_ASSERT_EQUAL_UINT(0, bus.n_sent);
    tick(150);
    TEST_ASSERT_EQUAL_UINT(0, bus.n_sent);
    tick(460); /* three periods late: one frame */
    TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
    tick(461);
    TEST_ASSERT_EQUAL_UINT(0, bus.n_sent);
    tick(561);
    TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
    /* with the own id, changed at once */
    m->props[DARAN_PROP_CAN_NODE_ID].u32 = 9;
    tick(700);
    TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
    TEST_ASSERT_EQUAL_HEX32(9u << 5 | 0x07u, bus.sent[0].id);
}

static void test_c17_no_heartbeat_at_period_0(void)
{
    for (uint32_t t = 0; t < 100000u; t += 997u) {
        tick(t);
        TEST_ASSERT_EQUAL_UINT(0, bus.n_sent);
    }
}

/* ---- C18: what feeds the watchdogs ---- */

static void test_c18_every_well_formed_frame_for_the_drive_feeds_even_a_refused_one(void)
{
    static const hex_frame_t frames[] = {
        {0x028, "ff 00 00 00 00 00 00 00"}, /* unknown sub-code */
        {0x008, "20 00 00 00 00 00 00 00"}, /* the feed sub-code */
        {0x03a, "00 00 b4 42 00 00 00 00"}, /* q velocity 0 */
        {0x03e, "07 00 00 00 00 00 00 00"}, /* unknown address */
        {0x01f, "19 79 03 00 00 00 00 00"}, /* node id 0 */
        {0x01c, "00 00 a0 41 00 00 09 00"}, /* mode 9, broadcast */
        {0x028, "13 00 00 00 00 00 00 00"}, /* no preset */
    };
    for (size_t i = 0; i < sizeof frames / sizeof frames[0]; i++) {
        deliver(frame_hex(frames[i].id, frames[i].hex));
        EXPECT_ONLY_FED();
    }
}

/* ---- C21: frames of another shape ---- */

static void test_c21_remote_extended_fd_and_short_frames_are_dropped_by_the_ring(void)
{
    m->props[DARAN_PROP_CAN_TIMEOUT_MS].u32 = 10;
    const daran_can_frame_t good = frame_hex(0x028, "06 00 00 00 00 00 00 00");
    static const uint8_t flags[] = {DARAN_CAN_FRAME_REMOTE, DARAN_CAN_FRAME_EXTENDED, DARAN_CAN_FRAME_FD,
                                    DARAN_CAN_FRAME_REMOTE | DARAN_CAN_FRAME_EXTENDED, 0x80};
    for (size_t i = 0; i < sizeof flags / sizeof flags[0]; i++) {
        daran_can_frame_t frame = good;
        frame.flags = flags[i];
        TEST_ASSERT_FALSE(offer(&frame));
        EXPECT_UNTOUCHED();
    }
    for (uint8_t dlc = 0; dlc < 8u; dlc++) {
        daran_can_frame_t frame = good;
        frame.dlc = dlc;
        TEST_ASSERT_FALSE(offer(&frame));
        EXPECT_UNTOUCHED();
    }
    /* a 29-bit id whose low bits read as the e-stop at node 1 */
    daran_can_frame_t extended = good;
    extended.id = 0x10000028u;
    extended.flags = DARAN_CAN_FRAME_EXTENDED;
    TEST_ASSERT_FALSE(offer(&extended));
    extended.flags = 0; /* or not marked as one: not a standard id either */
    TEST_ASSERT_FALSE(offer(&extended));
    /* an FD frame of 8 bytes at the right id, and a long one */
    daran_can_frame_t fd = good;
    fd.flags = DARAN_CAN_FRAME_FD;
    fd.dlc = 15;
    TEST_ASSERT_FALSE(offer(&fd));
    fd.flags = 0;
    TEST_ASSERT_FALSE(offer(&fd));
    EXPECT_UNTOUCHED();
    TEST_ASSERT_EQUAL_UINT32(0, m->props[DARAN_PROP_AXIS_ERROR].u32);
    /* none of them armed the guard */
    tick(1000);
    EXPECT_UNTOUCHED();
}

/* ---- C22: unknown codes, duplicate ids ---- */

static bool known_code(uint32_t code)
{
    return code == 0x08u || code == 0x0Cu || (code >= 0x19u && code <= 0x1Fu);
}

static bool status_code(uint32_t code)
{
    return (code & 1u) != 0u && code < 0x18u;
}

static void test_c22_unknown_codes_at_the_own_node_or_0_have_no_effect_at_all(void)
{
    size_t unknown = 0;
    for (uint32_t code = 0; code < 32u; code++) {
        if (known_code(code) || status_code(code)) {
            continue;
        }
        for (uint32_t node = 0; node <= 1u; node++) {
            deliver(motion_frame(node, code, 90.0f, 1000, 1000));
            EXPECT_UNTOUCHED();
        }
        unknown++;
    }
    TEST_ASSERT_EQUAL_UINT(11, unknown); /* 0x00..0x16 even but 0x08 and 0x0C, and 0x18 */
}

static void test_c22_a_status_frame_with_the_own_id_sets_can_error_bit_0_and_nothing_else(void)
{
    for (uint32_t code = 1; code < 0x18u; code += 2u) {
        start_drive(7);
        m->props[DARAN_PROP_CAN_ERROR].u32 = 0x4;
        deliver(motion_frame(7, code, 1.0f, 0, 0));
        TEST_ASSERT_EQUAL_UINT(1, m->n_calls);
        TEST_ASSERT_EQUAL_INT(MOCK_CALL_SET, m->calls[0].kind);
        TEST_ASSERT_EQUAL_INT(DARAN_PROP_CAN_ERROR, m->calls[0].prop);
        TEST_ASSERT_EQUAL_HEX32(0x5, m->calls[0].value.u32);
        TEST_ASSERT_EQUAL_UINT(0, bus.n_sent);
        /* at node 0 or another node's: nothing */
        deliver(motion_frame(0, code, 1.0f, 0, 0));
        EXPECT_UNTOUCHED();
        deliver(motion_frame(8, code, 1.0f, 0, 0));
        EXPECT_UNTOUCHED();
    }
}

static void test_c22_after_a_duplicate_the_drive_keeps_running_and_sc_or_0_clears_it(void)
{
    deliver(frame_hex(0x027, "00 00 00 00 00 00 00 00"));
    TEST_ASSERT_EQUAL_HEX32(1, m->props[DARAN_PROP_CAN_ERROR].u32);
    /* a second one changes nothing more: the bit is set already, not set again */
    deliver(frame_hex(0x021, "00 00 00 00 00 00 00 00"));
    EXPECT_UNTOUCHED();
    TEST_ASSERT_EQUAL_HEX32(1, m->props[DARAN_PROP_CAN_ERROR].u32);
    deliver(frame_hex(0x039, "00 00 b4 42 00 00 e8 03"));
    (void)EXPECT_MOVE();
    deliver(READ_FRAME(1, 20001, 3));
    EXPECT_SENT(0, 0x03E, "21 4e 03 00 01 00 00 00");
    deliver(frame_hex(0x028, "04 00 00 00 00 00 00 00"));
    EXPECT_ACTION(DARAN_ACTION_CLEAR_ERRORS);
    TEST_ASSERT_EQUAL_HEX32(0, m->props[DARAN_PROP_CAN_ERROR].u32);
    deliver(frame_hex(0x023, "00 00 00 00 00 00 00 00"));
    deliver(WRITE_FRAME(1, 20001, 3, 0));
    TEST_ASSERT_EQUAL_HEX32(0, EXPECT_SET(DARAN_PROP_CAN_ERROR).u32);
}

/* ---- C19, C23: system sub-codes ---- */

static void test_c19_restore_and_firmware_sub_codes_go_to_the_port_hook_with_their_data(void)
{
    deliver(system_frame(1, 0x00u, 0x1234u, 0xABCDu));
    EXPECT_ONLY_FED();
    TEST_ASSERT_EQUAL_UINT(1, bus.n_hook);
    TEST_ASSERT_EQUAL_HEX32(0x00, bus.hook_subcode);
    TEST_ASSERT_EQUAL_HEX16(0x1234, bus.hook_data1);
    TEST_ASSERT_EQUAL_HEX16(0xABCD, bus.hook_data2);
    deliver(system_frame(0, 0x07u, 7u, 0xFFFFu));
    EXPECT_ONLY_FED();
    TEST_ASSERT_EQUAL_UINT(2, bus.n_hook);
    TEST_ASSERT_EQUAL_HEX32(0x07, bus.hook_subcode);
    TEST_ASSERT_EQUAL_HEX16(7, bus.hook_data1);
    TEST_ASSERT_EQUAL_HEX16(0xFFFF, bus.hook_data2);
    /* no other sub-code reaches it */
    static const uint32_t others[] = {0x01, 0x06, 0x08, 0x10, 0x15, 0x20, 0x100, 0x10007};
    for (size_t i = 0; i < sizeof others / sizeof others[0]; i++) {
        deliver(system_frame(1, others[i], 0, 0));
    }
    TEST_ASSERT_EQUAL_UINT(2, bus.n_hook);
}

static void test_c19_without_a_hook_restore_and_firmware_do_nothing(void)
{
    start_drive_on(1, false);
    deliver(system_frame(1, 0x00u, 1, 2));
    EXPECT_ONLY_FED();
    deliver(system_frame(1, 0x07u, 1, 2));
    EXPECT_ONLY_FED();
}

static void test_c23_each_system_sub_code_runs_its_action_at_the_own_node_or_0(void)
{
    static const daran_action_t actions[] = {DARAN_ACTION_SAVE_CONFIG, DARAN_ACTION_ERASE_CONFIG,
                                             DARAN_ACTION_REBOOT, DARAN_ACTION_CLEAR_ERRORS,
                                             DARAN_ACTION_SET_ZERO, DARAN_ACTION_ESTOP};
    for (uint32_t node = 0; node <= 1u; node++) {
        for (uint32_t sub = 1; sub <= 6u; sub++) {
            start_drive(1);
            /* sys_data1 and sys_data2 are ignored */
            deliver(system_frame(node, sub, 0x5555u, 0xAAAAu));
            EXPECT_ACTION(actions[sub - 1u]);
        }
    }
}

/* ---- C28: frames for another node ---- */

static void test_c28_every_code_at_another_node_has_no_effect(void)
{
    m->props[DARAN_PROP_ENABLE_REPLY_STATE].u32 = 1;
    static const uint32_t nodes[] = {2, 3, 31, 32, 63};
    for (size_t i = 0; i < sizeof nodes / sizeof nodes[0]; i++) {
        for (uint32_t code = 0; code < 32u; code++) {
            daran_can_frame_t frame = motion_frame(nodes[i], code, 90.0f, 1000, 1);
            if (code == 0x08u) {
                frame = system_frame(nodes[i], 0x06u, 0, 0);
            } else if (code == 0x1Eu || code == 0x1Fu) {
                frame = property_frame(nodes[i], code, 31214, 3, 0);
            }
            deliver(frame);
            EXPECT_UNTOUCHED();
        }
    }
}

/* ---- C29: the drive's state refuses a valid motion ---- */

static void test_c29_estop_fault_or_idle_no_motion_but_the_status_reply_still_goes_out(void)
{
    static const struct {
        uint32_t state;
        uint32_t error;
    } states[] = {{DARAN_STATE_IDLE, DARAN_FLAG_ESTOP},
                  {DARAN_STATE_CLOSED_LOOP, DARAN_FLAG_MOTOR_FAILED},
                  {DARAN_STATE_IDLE, 0}};
    static const hex_frame_t motions[] = {
        {0x039, "00 00 b4 42 00 00 e8 03"}, {0x03a, "00 00 16 c3 e8 03 f4 01"},
        {0x03b, "00 00 f0 41 f4 01 1e 00"}, {0x03c, "00 00 a0 41 f4 01 02 00"},
        {0x03d, "00 00 00 3f 00 00 01 00"}, {0x01d, "00 00 00 3f 00 00 01 00"},
    };
    for (size_t s = 0; s < sizeof states / sizeof states[0]; s++) {
        for (size_t i = 0; i < sizeof motions / sizeof motions[0]; i++) {
            start_drive(1);
            m->props[DARAN_PROP_CURRENT_STATE].u32 = states[s].state;
            m->props[DARAN_PROP_AXIS_ERROR].u32 = states[s].error;
            m->props[DARAN_PROP_ENABLE_REPLY_STATE].u32 = 1;
            deliver(frame_hex(motions[i].id, motions[i].hex));
            TEST_ASSERT_EQUAL_UINT(1, m->n_calls);
            expect_fed_first(__LINE__);
            TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
            daran_can_frame_t want = status_of(m, 1);
            expect_frame(__LINE__, 0, &want);
            TEST_ASSERT_EQUAL_HEX32(states[s].error != 0u ? 0x04u : 0u, bus.sent[0].id & 0x04u);
        }
        if (!DARAN_ENABLE_MULTI_MOTOR) {
            continue;
        }
        /* a start: no motion, no reply, the preset kept */
        start_drive(1);
        m->props[DARAN_PROP_ENABLE_REPLY_STATE].u32 = 1;
        deliver(frame_hex(0x02C, "00 00 20 41 00 00 d0 07"));
        m->props[DARAN_PROP_CURRENT_STATE].u32 = states[s].state;
        m->props[DARAN_PROP_AXIS_ERROR].u32 = states[s].error;
        deliver(frame_hex(0x028, "10 00 00 00 00 00 00 00"));
        EXPECT_ONLY_FED();
        deliver(frame_hex(0x028, "15 00 00 00 14 00 05 00"));
        EXPECT_ONLY_FED();
        m->props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
        m->props[DARAN_PROP_AXIS_ERROR].u32 = 0;
        deliver(frame_hex(0x028, "10 00 00 00 00 00 00 00"));
        TEST_ASSERT_EQUAL_FLOAT(10.0f, EXPECT_MOVE()->pos_deg);
    }
}

/* ---- C30: reads, writes and system commands in every state ---- */

static void test_c30_reads_writes_and_system_commands_work_during_an_estop(void)
{
    deliver(frame_hex(0x028, "06 00 00 00 00 00 00 00"));
    EXPECT_ACTION(DARAN_ACTION_ESTOP);
    TEST_ASSERT_EQUAL_UINT32(DARAN_STATE_IDLE, m->props[DARAN_PROP_CURRENT_STATE].u32);
    deliver(READ_FRAME(1, 30001, 3));
    EXPECT_SENT(0, 0x03E, "31 75 03 00 00 40 00 00");
    deliver(READ_FRAME(0, 0, 0));
    TEST_ASSERT_EQUAL_HEX32(0x027, bus.sent[0].id);
    deliver(frame_hex(0x03F, "6c 7d 00 00 00 00 c8 41"));
    TEST_ASSERT_EQUAL_FLOAT(25.0f, EXPECT_SET(DARAN_PROP_POS_GAIN).f32);
    deliver(frame_hex(0x028, "01 00 00 00 00 00 00 00"));
    EXPECT_ACTION(DARAN_ACTION_SAVE_CONFIG);
    /* closed loop while the flag holds: refused, ignored */
    deliver(WRITE_FRAME(1, 30003, 3, 8));
    EXPECT_ONLY_FED();
    TEST_ASSERT_EQUAL_UINT32(DARAN_STATE_IDLE, m->props[DARAN_PROP_CURRENT_STATE].u32);
    deliver(frame_hex(0x028, "04 00 00 00 00 00 00 00"));
    EXPECT_ACTION(DARAN_ACTION_CLEAR_ERRORS);
    deliver(WRITE_FRAME(1, 30003, 3, 8));
    TEST_ASSERT_EQUAL_UINT32(8, EXPECT_SET(DARAN_PROP_REQUESTED_STATE).u32);
    deliver(frame_hex(0x039, "00 00 b4 42 00 00 e8 03"));
    (void)EXPECT_MOVE();
}

/* ---- C26: read-only properties, error registers ---- */

static void test_c26_error_registers_take_0_only(void)
{
    static const uint32_t registers[] = {30001, 33001, 34001, 32001, 36001, 37001, 20001, 50003};
    for (size_t i = 0; i < sizeof registers / sizeof registers[0]; i++) {
        const can_row_t *row = row_at(registers[i]);
        TEST_ASSERT_NOT_NULL(row);
        m->props[row->prop].u32 = 0x40u;
        deliver(WRITE_FRAME(1, registers[i], 3, 0x40u));
        EXPECT_ONLY_FED();
        deliver(WRITE_FRAME(1, registers[i], 0, 0));
        TEST_ASSERT_EQUAL_HEX32(0, EXPECT_SET(row->prop).u32);
    }
}

static void test_c26_no_read_only_property_is_written(void)
{
    size_t read_only = 0;
    for (size_t i = 0; i < CAN_ROWS; i++) {
        const can_row_t *row = &can_rows[i];
        if (row->address == 0u || row->writable) {
            continue;
        }
        deliver(WRITE_FRAME(1, row->address, type_code_of(row->type), 0));
        EXPECT_ONLY_FED();
        read_only++;
    }
    TEST_ASSERT_EQUAL_UINT(36, read_only); /* the 37 read-only rows but serial_number */
}

/* ---- the ring ---- */

/* Queue a read of @p address without running it. */
static bool queue_read(uint32_t address)
{
    daran_can_frame_t frame = READ_FRAME(1, address, 3);
    return daran_can_receive(&can, &frame);
}

/* Run what is queued; the replies must answer @p addresses in order. */
static void expect_replies_in_order(const uint32_t *addresses, size_t count)
{
    mock_clear(m);
    bus.n_sent = 0;
    bus.forget_calls = true;
    TEST_ASSERT_EQUAL_UINT(count, daran_can_poll(&can));
    bus.forget_calls = false;
    TEST_ASSERT_EQUAL_UINT(count, bus.n_sent);
    for (size_t i = 0; i < count; i++) {
        TEST_ASSERT_EQUAL_HEX16(addresses[i], get_u16(bus.sent[i].data));
    }
}

static const uint32_t some_addresses[] = {1,     2,     5,     6,     10001, 10002, 20001, 21001,
                                          21002, 21003, 21004, 30001, 30002, 30003, 31001, 31214};

static void test_a_full_ring_drops_and_counts_and_keeps_what_it_holds_in_order(void)
{
    TEST_ASSERT_EQUAL_UINT(0, daran_can_poll(&can));
    for (size_t i = 0; i < DARAN_CAN_RX_FRAMES; i++) {
        TEST_ASSERT_TRUE(queue_read(some_addresses[i % 16u]));
    }
    TEST_ASSERT_EQUAL_UINT32(0, daran_can_dropped(&can));
    TEST_ASSERT_FALSE(queue_read(38007));
    TEST_ASSERT_FALSE(queue_read(38008));
    TEST_ASSERT_EQUAL_UINT32(2, daran_can_dropped(&can));
    uint32_t expected[DARAN_CAN_RX_FRAMES];
    for (size_t i = 0; i < DARAN_CAN_RX_FRAMES; i++) {
        expected[i] = some_addresses[i % 16u];
    }
    expect_replies_in_order(expected, DARAN_CAN_RX_FRAMES);
    /* room again; the count stays */
    TEST_ASSERT_TRUE(queue_read(38007));
    expect_replies_in_order((const uint32_t[]){38007}, 1);
    TEST_ASSERT_EQUAL_UINT32(2, daran_can_dropped(&can));
    TEST_ASSERT_EQUAL_UINT(0, daran_can_poll(&can));
}

static void test_frames_wrap_around_the_ring_in_order(void)
{
    /* runs of 1..ring-size frames, so every slot boundary is crossed */
    uint32_t expected[DARAN_CAN_RX_FRAMES];
    size_t next = 0;
    for (size_t round = 0; round < 4u * DARAN_CAN_RX_FRAMES; round++) {
        size_t count = 1u + round % DARAN_CAN_RX_FRAMES;
        for (size_t i = 0; i < count; i++) {
            expected[i] = some_addresses[next++ % 16u];
            TEST_ASSERT_TRUE(queue_read(expected[i]));
        }
        expect_replies_in_order(expected, count);
    }
    TEST_ASSERT_EQUAL_UINT32(0, daran_can_dropped(&can));
}

static void test_the_ring_indices_wrap_past_65536_frames(void)
{
    daran_can_frame_t other = READ_FRAME(2, 31001, 3);
    uint32_t rounds = 0;
    for (uint32_t n = 0; n < 65536u + 3u; n += DARAN_CAN_RX_FRAMES, rounds++) {
        for (size_t i = 0; i < DARAN_CAN_RX_FRAMES; i++) {
            TEST_ASSERT_TRUE(daran_can_receive(&can, &other));
        }
        TEST_ASSERT_FALSE(daran_can_receive(&can, &other));
        TEST_ASSERT_EQUAL_UINT(DARAN_CAN_RX_FRAMES, daran_can_poll(&can));
    }
    TEST_ASSERT_EQUAL_UINT32(rounds, daran_can_dropped(&can)); /* one a round */
    uint32_t expected[DARAN_CAN_RX_FRAMES];
    for (size_t i = 0; i < DARAN_CAN_RX_FRAMES; i++) {
        expected[i] = some_addresses[(i * 5u) % 16u];
        TEST_ASSERT_TRUE(queue_read(expected[i]));
    }
    expect_replies_in_order(expected, DARAN_CAN_RX_FRAMES);
}

static void test_unsent_counts_the_frames_the_port_refused(void)
{
    TEST_ASSERT_EQUAL_UINT32(0, daran_can_unsent(&can));
    bus.refuse = true;
    deliver(READ_FRAME(1, 1, 0));
    TEST_ASSERT_EQUAL_UINT32(1, daran_can_unsent(&can));
    deliver(READ_FRAME(1, 0, 0));
    TEST_ASSERT_EQUAL_UINT32(2, daran_can_unsent(&can));
    m->props[DARAN_PROP_ENABLE_REPLY_STATE].u32 = 1;
    deliver(frame_hex(0x039, "00 00 b4 42 00 00 e8 03"));
    (void)EXPECT_MOVE(); /* the move stands; its reply is lost */
    TEST_ASSERT_EQUAL_UINT32(3, daran_can_unsent(&can));
    m->props[DARAN_PROP_CAN_HEARTBEAT_MS].u32 = 10;
    tick(10);
    TEST_ASSERT_EQUAL_UINT32(4, daran_can_unsent(&can));
    TEST_ASSERT_EQUAL_UINT(4, bus.n_refused);
    /* frames nothing answers do not count */
    deliver(WRITE_FRAME(1, 32108, 0, daran_bits_of(2.0f)));
    TEST_ASSERT_EQUAL_UINT32(4, daran_can_unsent(&can));
    bus.refuse = false;
    deliver(READ_FRAME(1, 1, 0));
    TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
    TEST_ASSERT_EQUAL_UINT32(4, daran_can_unsent(&can));
    /* a new init starts the counts again */
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_can_init(&can, &m->drive));
    TEST_ASSERT_EQUAL_UINT32(0, daran_can_unsent(&can));
    TEST_ASSERT_EQUAL_UINT32(0, daran_can_dropped(&can));
}

/* ---- daran_can_init ---- */

static void test_can_init_refuses_missing_pointers_and_port_functions(void)
{
    daran_can_t other;
    daran_drive_t never_initialised;
    memset(&never_initialised, 0, sizeof never_initialised);
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_can_init(NULL, &m->drive));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_can_init(&other, NULL));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_can_init(&other, &never_initialised));
    m->hal.can_send = NULL;
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_can_init(&other, &m->drive));
    plug_into_bus(m, true);
    m->hal.now_ms = NULL;
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT, daran_can_init(&other, &m->drive));
    /* the hook is optional */
    plug_into_bus(m, false);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_can_init(&other, &m->drive));
    /* nothing of the refused calls reached the drive or the bus */
    TEST_ASSERT_EQUAL_UINT(0, m->n_calls);
    TEST_ASSERT_EQUAL_UINT(0, bus.n_sent);
}

static void test_can_init_reads_the_protocol_and_nothing_else_changes(void)
{
    mock_clear(m);
    bus.now_ms = 12345;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_can_init(&can, &m->drive));
    TEST_ASSERT_EQUAL_UINT(0, m->n_calls);
    TEST_ASSERT_TRUE(m->n_gets >= 1u);
    TEST_ASSERT_EQUAL_UINT(0, bus.n_sent);
    /* the heartbeat counts from the init */
    m->props[DARAN_PROP_CAN_HEARTBEAT_MS].u32 = 100;
    tick(12444);
    TEST_ASSERT_EQUAL_UINT(0, bus.n_sent);
    tick(12446);
    TEST_ASSERT_EQUAL_UINT(1, bus.n_sent);
}

/* ---- the vendor's python-can recording, frame by frame (6.6) ---- */

typedef struct pending_preset {
    bool held;
    float p1;
    int32_t raw2, raw3;
} pending_preset_t;

typedef struct replay_counts {
    size_t for_drive, moves, sets, actions, replies, refused, timed;
} replay_counts_t;

/* As the recording's responder kept its drives between calls: closed loop,
 * no flag, their own node ids; every drive replies to motions in pass 2. */
static void ready(mock_t *drive, uint32_t id, unsigned pass)
{
    daran_value_t *p = drive->props;
    p[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    p[DARAN_PROP_REQUESTED_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    p[DARAN_PROP_AXIS_ERROR].u32 = 0;
    p[DARAN_PROP_CAN_NODE_ID].u32 = id;
    p[DARAN_PROP_ENABLE_REPLY_STATE].u32 = pass == 2u ? 1u : 0u;
}

/* The recorded frames the contract refuses (6.6): set_id()'s node id 0 (C14). */
static bool refused_by_contract(const daran_can_frame_t *frame)
{
    return (frame->id & 0x1Fu) == 0x1Fu && get_u16(frame->data) == 31001u && get_u32(frame->data + 4) == 0u;
}

/* Room for the longest twin line (a write of the longest path). */
#define TWIN_LINE_MAX 160

static const char *const action_words[] = {"ss", "se", "sr", "sc", "sz", "st"};
static const char *const start_words[] = {"mt", "mq", "mp", "mv", "mc"};
static const char motion_letters[] = "tqpvc";

/* The `w` twin of a write frame, or false when it has none (type code > 4). */
static bool write_line(char *line, size_t size, uint32_t node, const daran_can_frame_t *frame,
                       const can_row_t *row)
{
    uint32_t type = get_u16(frame->data + 2), bits = get_u32(frame->data + 4);
    char value[48];
    switch (type) {
    case 0:
        text_f32(value, sizeof value, daran_float_of(bits));
        break;
    case 1:
        snprintf(value, sizeof value, "%u", (unsigned)(bits & 0xFFFFu));
        break;
    case 2:
        snprintf(value, sizeof value, "%d", (int)(int16_t)(bits & 0xFFFFu));
        break;
    case 3:
        snprintf(value, sizeof value, "%lu", (unsigned long)bits);
        break;
    case 4:
        snprintf(value, sizeof value, "%ld", (long)(int32_t)bits);
        break;
    default:
        return false;
    }
    if (row->axis) {
        snprintf(line, size, "w axis%u.%s %s", (unsigned)node, row->path, value);
    } else {
        snprintf(line, size, "w %s %s %u", row->path, value, (unsigned)node);
    }
    return true;
}

/* The `ms` line of the pending preset; @p mode_kind: 0 position starts
 * (p3 as is), 1 velocity, 2 torque (p3 a mode, C1). */
static void preset_line(char *line, size_t size, uint32_t id, const pending_preset_t *preset, int mode_kind)
{
    char p1[48], p2[16], p3[16];
    text_f32(p1, sizeof p1, preset->p1);
    text_scaled(p2, sizeof p2, preset->raw2);
    if (mode_kind == 0) {
        text_scaled(p3, sizeof p3, preset->raw3);
    } else {
        snprintf(p3, sizeof p3, "%d", (int)ascii_mode_of((uint16_t)preset->raw3, mode_kind == 2));
    }
    snprintf(line, size, "ms %u %s %s %s", (unsigned)id, p1, p2, p3);
}

/* The twin lines of a frame for the drive (0, 1 or 2); @p timed is set
 * for a start of the timed trapezoid. */
static size_t twin_lines(const daran_can_frame_t *frame, uint32_t id, const pending_preset_t *pending,
                         char lines[2][TWIN_LINE_MAX], bool *timed)
{
    uint32_t node = frame->id >> 5, code = frame->id & 0x1Fu;
    const uint8_t *d = frame->data;
    char f[48], a[16], b[16];
    text_f32(f, sizeof f, daran_float_of(get_u32(d)));
    text_scaled(a, sizeof a, (int16_t)get_u16(d + 4));
    text_scaled(b, sizeof b, (int16_t)get_u16(d + 6));
    *timed = false;
    if (code >= 0x19u && code <= 0x1Bu) {
        snprintf(lines[0], TWIN_LINE_MAX, "%c %u %s %s %s", motion_letters[code - 0x19u], (unsigned)node, f, a, b);
        return 1;
    }
    if (code == 0x1Cu || code == 0x1Du) {
        snprintf(lines[0], TWIN_LINE_MAX, "%c %u %s %s %d", motion_letters[code - 0x19u], (unsigned)node, f, a,
                 (int)ascii_mode_of(get_u16(d + 6), code == 0x1Du));
        return 1;
    }
    if (code == 0x1Fu) {
        const can_row_t *row = row_at(get_u16(d));
        return row != NULL && write_line(lines[0], TWIN_LINE_MAX, node, frame, row) ? 1u : 0u;
    }
    if (code != 0x08u) {
        return 0; /* a preset or a read: nothing an ASCII line would call */
    }
    uint32_t sub = get_u32(d);
    if (sub >= 1u && sub <= 6u) {
        snprintf(lines[0], TWIN_LINE_MAX, "%s %u", action_words[sub - 1u], (unsigned)node);
        return 1;
    }
    if (!DARAN_ENABLE_MULTI_MOTOR || !pending->held || sub < 0x10u || sub > 0x15u) {
        return 0;
    }
    if (sub == 0x15u) {
        char p1[48], p2[16], p3[16];
        text_f32(p1, sizeof p1, pending->p1);
        text_scaled(p2, sizeof p2, pending->raw2);
        text_scaled(p3, sizeof p3, pending->raw3);
        snprintf(lines[0], TWIN_LINE_MAX, "d %u %s %s %s %s %s", (unsigned)node, p1, p2, p3, a, b);
        return 1;
    }
    uint32_t flag = get_u16(d + 4);
    if (sub <= 0x12u) {
        if (flag != 0u && flag != 1u && flag != 100u) {
            return 0; /* C2: ignored */
        }
        preset_line(lines[0], TWIN_LINE_MAX, id, pending, 0);
        snprintf(lines[1], TWIN_LINE_MAX, "%s %u %u", start_words[sub - 0x10u], (unsigned)node, flag != 0u ? 1u : 0u);
        *timed = sub == 0x11u;
        return 2;
    }
    preset_line(lines[0], TWIN_LINE_MAX, id, pending, sub == 0x13u ? 1 : 2);
    snprintf(lines[1], TWIN_LINE_MAX, "%s %u", start_words[sub - 0x10u], (unsigned)node);
    return 2;
}

/* Run one recorded frame through drive @p id (m) and its twin lines through
 * the reference drive (@p twin): the same HAL calls, the same store, the
 * frames the contract says, and no refusal the contract does not make. */
static void replay_frame(const can_recorded_frame_t *rec, uint32_t id, mock_t *twin, pending_preset_t *pending,
                         replay_counts_t *counts)
{
    daran_can_frame_t frame;
    memset(&frame, 0, sizeof frame);
    frame.id = rec->id;
    frame.dlc = rec->dlc;
    memcpy(frame.data, rec->data, sizeof frame.data);
    uint32_t node = frame.id >> 5, code = frame.id & 0x1Fu;
    context = rec->call;
    ready(m, id, rec->pass);
    ready(twin, id, rec->pass);
    mock_clear(twin);

    bool taken = offer(&frame);
    bool for_drive = frame.dlc == 8u && (node == id || node == 0u) && known_code(code);
    TEST_ASSERT_EQUAL_MESSAGE(frame.dlc == 8u, taken, rec->call);
    if (!for_drive) {
        EXPECT_UNTOUCHED();
        return;
    }
    counts->for_drive++;
    expect_fed_first(__LINE__);

    char lines[2][TWIN_LINE_MAX];
    bool timed;
    size_t n_lines = twin_lines(&frame, id, pending, lines, &timed);
    for (size_t i = 0; i < n_lines; i++) {
        mock_send_line(twin, lines[i]);
        if (i + 1u < n_lines) {
            TEST_ASSERT_EQUAL_STRING_MESSAGE("", twin->out, lines[i]);
        }
    }
    bool twin_refused = n_lines > 0u && REPLY_IS_ERROR(twin);
    bool twin_moved = mock_count(twin, MOCK_CALL_MOVE) > 0u;
    bool reply_state = m->props[DARAN_PROP_ENABLE_REPLY_STATE].u32 != 0u;

    daran_can_frame_t want;
    bool want_frame = false;
    /* 10.5: a timed start keeps its time on both front ends, the recorded
     * one 9.4 ms short of its acceleration's least (C13) included */
    if (timed && twin_moved) {
        counts->timed++;
    }
    {
        expect_same_effects(__LINE__, twin, n_lines > 0u ? lines[n_lines - 1u] : "(no line)");
        if (twin_refused != refused_by_contract(&frame)) {
            can_fail(__LINE__, "%s: the line \"%s\" answered \"%s\"", twin_refused ? "refused" : "accepted",
                     lines[n_lines - 1u], mock_escape(twin->out, twin->out_len));
        }
        if (code == 0x08u && get_u32(frame.data) >= 0x10u && !twin_refused && twin_moved) {
            pending->held = false; /* a start consumed it */
        }
        counts->moves += mock_count(m, MOCK_CALL_MOVE);
        counts->sets += mock_count(m, MOCK_CALL_SET);
        counts->actions += m->n_calls - mock_count(m, MOCK_CALL_MOVE) - mock_count(m, MOCK_CALL_SET) -
                           mock_count_action(m, DARAN_ACTION_FEED_WATCHDOG);
        counts->refused += twin_refused;
    }
    if (code == 0x0Cu && DARAN_ENABLE_MULTI_MOTOR) {
        float p1 = daran_float_of(get_u32(frame.data));
        TEST_ASSERT_TRUE_MESSAGE(isfinite(p1), rec->call);
        pending->held = true;
        pending->p1 = p1;
        pending->raw2 = (int16_t)get_u16(frame.data + 4);
        pending->raw3 = (int16_t)get_u16(frame.data + 6);
        want_frame = reply_state;
    } else if (code >= 0x19u && code <= 0x1Du) {
        want_frame = reply_state && (!twin_refused || refused_for_state(twin));
    }
    if (want_frame) {
        want = status_of(m, id);
    } else if (code == 0x1Eu && get_u16(frame.data) == 0u) {
        want_frame = true;
        want = status_of(m, id);
    } else if (code == 0x1Eu && row_at(get_u16(frame.data)) != NULL) {
        want_frame = true;
        want = read_reply_of(m, id, row_at(get_u16(frame.data)));
    }
    if (bus.n_sent != (want_frame ? 1u : 0u)) {
        can_fail(__LINE__, "expected %u frames sent", want_frame ? 1u : 0u);
    }
    if (want_frame) {
        expect_frame(__LINE__, 0, &want);
        counts->replies++;
    }
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(twin->props, m->props, sizeof m->props, rec->call);
}

static void run_recording_through_drive(const void *arg)
{
    uint32_t id = *(const uint32_t *)arg;
    start_drive(id);
    mock_t *twin = new_twin(id);
    pending_preset_t pending = {false, 0.0f, 0, 0};
    replay_counts_t counts = {0, 0, 0, 0, 0, 0, 0};
    for (size_t i = 0; i < CAN_RECORDING_FRAMES; i++) {
        replay_frame(&can_recording[i], id, twin, &pending, &counts);
    }
    context = NULL;
    mock_message("drive %u: %u of the %u recorded frames for it: %u moves (%u timed starts), "
                 "%u writes, %u actions, %u replies, %u refused",
                 (unsigned)id, (unsigned)counts.for_drive, (unsigned)CAN_RECORDING_FRAMES, (unsigned)counts.moves,
                 (unsigned)counts.timed, (unsigned)counts.sets, (unsigned)counts.actions,
                 (unsigned)counts.replies, (unsigned)counts.refused);
    /* the replay did what the recording asks: every drive moved, was
     * written, acted and answered; the one refusal is set_id()'s id 0 */
    TEST_ASSERT_TRUE(counts.for_drive > 60u);
    TEST_ASSERT_TRUE(counts.moves >= (DARAN_ENABLE_MULTI_MOTOR ? 8u : 3u));
    TEST_ASSERT_TRUE(counts.sets >= 8u);
    TEST_ASSERT_TRUE(counts.actions >= 8u);
    TEST_ASSERT_TRUE(counts.replies >= 20u);
    TEST_ASSERT_EQUAL_UINT(1, counts.refused);
}

static void test_the_recording_has_176_frames_the_first_with_dlc_0(void)
{
    TEST_ASSERT_EQUAL_UINT(176, CAN_RECORDING_FRAMES);
    size_t short_frames = 0;
    for (size_t i = 0; i < CAN_RECORDING_FRAMES; i++) {
        short_frames += can_recording[i].dlc != 8u;
    }
    TEST_ASSERT_EQUAL_UINT(1, short_frames);
    TEST_ASSERT_EQUAL_UINT(0, can_recording[0].dlc);
    TEST_ASSERT_EQUAL_HEX16(0x009, can_recording[0].id);
}

/* ---- the suite ---- */

static mock_suite_t suite;

/* One case a table row; every row type begins with the row's name. */
static void add_rows(mock_row_fn fn, const void *rows, size_t count, size_t size, const char *prefix)
{
    for (size_t i = 0; i < count; i++) {
        const void *row = (const char *)rows + i * size;
        mock_suite_add(&suite, fn, row, "%s: %s", prefix, *(const char *const *)row);
    }
}
#define ADD_ROWS(fn, rows, prefix) add_rows((fn), (rows), sizeof(rows) / sizeof((rows)[0]), sizeof((rows)[0]), (prefix))

/* ---- C1 for an ASCII preset: a start reads its p3 as a mode field x 100 ---- */

/* p3 x 100 + 0.5, truncated, then raw or x 100 as a mode field reads: a
 * sign (-0 too), 10 and past it are no mode; 0.015 x 100 rounds to 1.5 in
 * float32, so it starts the ramp (mode 2), as the drive always read it. */
static void test_c1_a_velocity_start_reads_an_ascii_preset_s_p3_x_100_and_a_sign_as_no_mode(void)
{
    SKIP_IF_NO_MULTI();
    static const struct {
        const char *p3;
        daran_move_kind_t kind; /* REFUSED: ignored, the preset kept */
    } cases[] = {
        {"1", DARAN_MOVE_VELOCITY},       {"2", DARAN_MOVE_VELOCITY_RAMP},
        {"0.01", DARAN_MOVE_VELOCITY},    {"0.02", DARAN_MOVE_VELOCITY_RAMP},
        {"0.015", DARAN_MOVE_VELOCITY_RAMP}, {"0.014", DARAN_MOVE_VELOCITY},
        {"-0", REFUSED},                  {"0", REFUSED},
        {"-0.01", REFUSED},               {"-1", REFUSED},
        {"6", REFUSED},                   {"3", REFUSED},
        {"10", REFUSED},                  {"10.01", REFUSED},
        {"1e30", REFUSED},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char line[48];
        snprintf(line, sizeof line, "ms 1 2.5 1.5 %s", cases[i].p3);
        start_drive(1);
        mock_send_line(m, line);
        TEST_ASSERT_EQUAL_STRING_MESSAGE("", m->out, line);
        deliver(system_frame(1, 0x13u, 0, 0));
        if (cases[i].kind == REFUSED) {
            EXPECT_ONLY_FED();
            continue;
        }
        const daran_move_t *move = EXPECT_MOVE();
        TEST_ASSERT_EQUAL_INT_MESSAGE(cases[i].kind, move->kind, line);
        TEST_ASSERT_EQUAL_FLOAT_MESSAGE(2.5f, move->vel_rpm, line);
    }
}

int main(void)
{
    static const uint32_t drive_ids[] = {1, 2, 3};
    UNITY_BEGIN();
    RUN_TEST(test_get_id_broadcast_is_answered_by_drive_1_with_its_own_id);
    RUN_TEST(test_get_state_3_answers_the_status_frame_of_the_worked_example);
    RUN_TEST(test_preset_torque_then_a_torque_start_ramps_to_minus_1_2_nm_at_0_2_nm_per_s);
    RUN_TEST(test_set_speeds_presets_with_raw_100_run_each_drive_in_feed_forward_mode);
    RUN_TEST(test_impedance_control_runs_drive_1_and_any_drive_holding_a_preset);
    RUN_TEST(test_stm32_u16_bool_write_is_accepted_and_its_bytes_6_and_7_ignored);
    RUN_TEST(test_set_id_default_writing_id_0_is_ignored);
    RUN_TEST(test_send_command_default_with_dlc_0_is_dropped_by_the_ring);
    RUN_TEST(test_an_estop_with_dlc_7_is_dropped_by_the_ring);
    RUN_TEST(test_a_status_frame_with_the_own_id_sets_can_error_bit_0);
    RUN_TEST(test_with_reply_state_set_angle_is_answered_after_the_move_with_the_state_after_it);
    RUN_TEST(test_the_recording_has_176_frames_the_first_with_dlc_0);
    for (size_t i = 0; i < sizeof drive_ids / sizeof drive_ids[0]; i++) {
        mock_suite_add(&suite, run_recording_through_drive, &drive_ids[i],
                       "test_every_recorded_frame_runs_on_drive_%u_as_its_ascii_twin", (unsigned)drive_ids[i]);
    }
    ADD_ROWS(run_twin_row, twin_rows, "test_frame_and_line_make_the_same_calls");
    ADD_ROWS(run_read_twin_row, read_twin_rows, "test_a_read_frame_answers_what_r_answers");
    ADD_ROWS(run_write_case, write_cases, "test_c6_c25_write_type_codes");
    ADD_ROWS(run_refused_row, refused_rows, "test_a_refused_frame_only_feeds_and_gets_no_reply");
    ADD_ROWS(run_status_case, status_cases, "test_the_status_frame_layout");
    mock_suite_run(&suite);
    RUN_TEST(test_c1_velocity_modes_read_raw_or_times_100_in_both_places);
    RUN_TEST(test_c1_torque_modes_read_raw_or_times_100_and_2_as_6_in_both_places);
    RUN_TEST(test_c1_a_refused_mode_start_keeps_the_preset);
    RUN_TEST(test_c2_relative_flag_0_is_absolute_1_and_100_relative_others_ignored);
    RUN_TEST(test_c3_every_scaled_value_is_raw_over_100_correctly_rounded);
    RUN_TEST(test_c3_the_libraries_truncated_values_arrive_as_sent);
    RUN_TEST(test_c7_a_read_reply_carries_the_property_s_own_type_code_whatever_was_asked);
    RUN_TEST(test_every_address_of_the_list_is_read_with_its_type_and_value);
    RUN_TEST(test_an_address_outside_the_list_is_never_answered);
    RUN_TEST(test_c8_a_broadcast_read_is_answered_with_the_own_id);
    RUN_TEST(test_the_status_frame_rounds_near_half_counts_to_the_nearest);
    RUN_TEST(test_the_status_frame_saturates_at_every_scale);
    RUN_TEST(test_c10_no_status_reply_without_enable_reply_state);
    RUN_TEST(test_c10_each_preset_and_direct_motion_gets_one_status_frame_with_reply_state);
    RUN_TEST(test_c10_starts_writes_reads_and_system_commands_get_no_status_reply);
    RUN_TEST(test_c27_a_start_refused_for_its_values_is_ignored_and_keeps_the_preset);
    RUN_TEST(test_c13_a_can_preset_9_ms_short_of_the_least_duration_keeps_its_time);
    RUN_TEST(test_the_same_start_of_an_ascii_preset_keeps_its_time_too);
    RUN_TEST(test_a_can_start_far_short_of_its_acceleration_keeps_its_time);
    RUN_TEST(test_a_can_start_beyond_the_velocity_limit_is_ignored_and_kept);
    RUN_TEST(test_c13_a_can_start_within_10_ms_of_the_least_runs_whatever_the_limit);
    RUN_TEST(test_c13_an_s_curve_start_short_by_9_ms_keeps_its_time);
    RUN_TEST(test_c13_duration_0_over_distance_0_is_accepted);
    RUN_TEST(test_c14_a_new_node_id_applies_at_once_and_0_is_refused);
    RUN_TEST(test_c15_protocol_0_at_init_leaves_the_front_end_silent);
    RUN_TEST(test_c15_a_protocol_written_over_can_applies_at_the_next_init);
    RUN_TEST(test_c16_the_guard_arms_at_the_first_frame_and_trips_once_after_the_timeout);
    RUN_TEST(test_c16_every_frame_for_the_drive_holds_the_guard_off_and_others_do_not);
    RUN_TEST(test_c16_the_guard_is_off_at_timeout_0);
    RUN_TEST(test_c16_the_guard_measures_across_the_clock_wrap);
    RUN_TEST(test_c17_a_heartbeat_status_frame_goes_out_every_period_at_most_one_a_poll);
    RUN_TEST(test_c17_no_heartbeat_at_period_0);
    RUN_TEST(test_c18_every_well_formed_frame_for_the_drive_feeds_even_a_refused_one);
    RUN_TEST(test_c21_remote_extended_fd_and_short_frames_are_dropped_by_the_ring);
    RUN_TEST(test_c22_unknown_codes_at_the_own_node_or_0_have_no_effect_at_all);
    RUN_TEST(test_c22_a_status_frame_with_the_own_id_sets_can_error_bit_0_and_nothing_else);
    RUN_TEST(test_c22_after_a_duplicate_the_drive_keeps_running_and_sc_or_0_clears_it);
    RUN_TEST(test_c19_restore_and_firmware_sub_codes_go_to_the_port_hook_with_their_data);
    RUN_TEST(test_c19_without_a_hook_restore_and_firmware_do_nothing);
    RUN_TEST(test_c23_each_system_sub_code_runs_its_action_at_the_own_node_or_0);
    RUN_TEST(test_c28_every_code_at_another_node_has_no_effect);
    RUN_TEST(test_c29_estop_fault_or_idle_no_motion_but_the_status_reply_still_goes_out);
    RUN_TEST(test_c30_reads_writes_and_system_commands_work_during_an_estop);
    RUN_TEST(test_c26_error_registers_take_0_only);
    RUN_TEST(test_c26_no_read_only_property_is_written);
    RUN_TEST(test_a_full_ring_drops_and_counts_and_keeps_what_it_holds_in_order);
    RUN_TEST(test_frames_wrap_around_the_ring_in_order);
    RUN_TEST(test_the_ring_indices_wrap_past_65536_frames);
    RUN_TEST(test_unsent_counts_the_frames_the_port_refused);
    RUN_TEST(test_can_init_refuses_missing_pointers_and_port_functions);
    RUN_TEST(test_can_init_reads_the_protocol_and_nothing_else_changes);
    RUN_TEST(test_c1_a_velocity_start_reads_an_ascii_preset_s_p3_x_100_and_a_sign_as_no_mode);
    return UNITY_END();
}

#else /* !DARAN_ENABLE_CAN */

void setUp(void)
{
}

void tearDown(void)
{
}

static void test_without_can_the_front_end_is_compiled_out(void)
{
    TEST_IGNORE_MESSAGE("DARAN_ENABLE_CAN is 0 in this build");
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_without_can_the_front_end_is_compiled_out);
    return UNITY_END();
}

#endif /* DARAN_ENABLE_CAN */
