/* Harness 7: the CAN front end (daran_can_receive / daran_can_poll) with the
 * recording HAL of fuzz_hal.c, on the invariants of docs/security.md as the
 * CAN contract (can.md sections 2-4, docs/can.md) states them for frames.
 *
 * Input: 4 setup bytes, then records of 12 bytes, one frame each.
 *   setup[0]  the drive's node id, 1 + setup[0] % 63
 *   setup[1]  bits 0-1: closed loop / idle / idle with the e-stop flag /
 *             closed loop with a motor fault flag; bit 2: enable_reply_state;
 *             bit 3: S-curve timing (traj_mode 2); bit 4: no system hook;
 *             bit 5: the port refuses every third transmission; bit 6:
 *             can.config.protocol 0 at daran_can_init(); bit 7: odd
 *             estimates (NaN, infinities, beyond the s16 fields)
 *   setup[2]  can.config.heartbeat_ms (0: off)
 *   setup[3]  can.config.timeout_ms (0: off)
 *   record    id bits 0-7; id bits 8-10 and flags (bit 3 remote, bit 4
 *             extended with bits 3-7 as id bits 24-28, bit 5 FD, bits 6-7
 *             unknown flag bits); DLC (bit 7 set: bits 0-3 are the DLC,
 *             else 8) and bit 6: queue only, poll with the next record; the
 *             milliseconds the clock advances before it; 8 data bytes.
 *
 * Asserted (fuzz_fail() aborts):
 *  - the HAL's own checks (fuzz_hal.c): only writable properties written,
 *    every value in its range (can.error aside: it may take 0, or its value
 *    with bit 0 set by a duplicate id, C22), every move finite and valid,
 *    no move while idle or with a flag;
 *  - a frame that is not an 8-byte standard data frame is refused by
 *    daran_can_receive(); a well-formed one only when the ring is full, and
 *    then daran_can_dropped() counts it;
 *  - a frame run alone by a poll: not for the drive (another node, unknown
 *    code, bad shape) -> no HAL call and no frame of its own; a status frame
 *    with the own id -> at most the can.error write; a frame for the drive
 *    -> the watchdog feed first (C18), then at most one move, write or
 *    action of the kind its code allows, and the frames its code allows
 *    (one read reply for a known address, one status frame for a fast read,
 *    at most one for a motion or preset with enable_reply_state, none else);
 *  - every frame sent: DLC 8, standard, the own node; a read reply echoes the
 *    requested address with the property's own type code and value; a
 *    status frame's T and E bits, position and scaled fields are the
 *    drive's (C9, 2.7); at most one heartbeat per poll, none at period 0;
 *  - the node guard (DARAN_ACTION_NODE_GUARD) trips only when armed by a
 *    frame for the drive, after timeout_ms without one, once (C16);
 *  - can.config.protocol 0: no HAL call and no frame at all (C15);
 *  - daran_can_unsent() counts exactly the transmissions the port refused. */
#include <math.h>
#include <string.h>

#include "fuzz_hal.h"

#define RECORD_SIZE 12u
#define SETUP_SIZE 4u
#define SENT_MAX 64u

/* The CAN column of the property list: address -> property and type. */
typedef struct can_address {
    uint16_t address;
    daran_prop_t prop;
    daran_prop_type_t type;
} can_address_t;

#define FUZZ_CAN_ROW_(id, path, scope, type, access, range, unit, can) \
    {can, DARAN_PROP_##id, DARAN_TYPE_##type},
static const can_address_t addresses[] = {DARAN_PROPERTY_LIST(FUZZ_CAN_ROW_)};
#undef FUZZ_CAN_ROW_

static const can_address_t *address_row(uint32_t address)
{
    for (size_t i = 0; i < sizeof addresses / sizeof addresses[0]; i++) {
        if (address != 0u && addresses[i].address == address) {
            return &addresses[i];
        }
    }
    return NULL;
}

typedef struct state {
    daran_drive_t drive;
    daran_can_t can;
    fuzz_hal_t hal;
    bool enabled;        /* can.config.protocol was 1 at init */
    bool refuse_every_3; /* the port refuses every third transmission */
    uint32_t now;
    uint32_t transmissions;
    uint32_t refused;
    uint32_t dropped;
    size_t queued;
    size_t records_in_poll; /* records offered since the last poll */
    /* the guard as the contract describes it (C16) */
    bool armed;
    bool tripped;
    uint32_t last_for_drive;
    size_t guard_trips;
    /* since the last poll began */
    size_t can_error_sets;
    char first_call;     /* 'f'eed, 's'et, 'm'ove, 'a'ction, 'e' can.error, 0 none */
    size_t feeds;
    size_t sent_status;
    size_t sent_replies;
    uint16_t reply_address;
} state_t;

static state_t st;

/* ---- the HAL: fuzz_hal's, with the two calls the CAN front end adds ---- */

static void note_call(char kind)
{
    if (st.first_call == 0) {
        st.first_call = kind;
    }
}

static daran_result_t can_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    return fuzz_hal_get(ctx, prop, out);
}

static daran_result_t can_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    fuzz_hal_t *h = ctx;
    if (prop != DARAN_PROP_CAN_ERROR) {
        note_call('s');
        return fuzz_hal_set(ctx, prop, value);
    }
    /* an error register takes 0; can.error also bit 0 on a duplicate id (C22) */
    uint32_t old = h->props[DARAN_PROP_CAN_ERROR].u32;
    FUZZ_CHECK(value.u32 == 0u || value.u32 == (old | 1u), "can.error 0x%08x written over 0x%08x",
               (unsigned)value.u32, (unsigned)old);
    note_call(value.u32 == 0u ? 's' : 'e');
    if (value.u32 != 0u) {
        st.can_error_sets++;
    }
    h->n_set++;
    h->last_set_prop = prop;
    h->props[DARAN_PROP_CAN_ERROR] = value;
    return DARAN_OK;
}

static daran_result_t can_move(void *ctx, const daran_move_t *move)
{
    note_call('m');
    return fuzz_hal_move(ctx, move);
}

static daran_result_t can_action(void *ctx, daran_action_t action)
{
    fuzz_hal_t *h = ctx;
    if (action == DARAN_ACTION_FEED_WATCHDOG) {
        /* only a frame for the drive feeds (checked per frame), and every
         * one arms the guard again (C16, C18) */
        st.feeds++;
        st.armed = true;
        st.tripped = false;
        st.last_for_drive = st.now;
    }
    if (action != DARAN_ACTION_NODE_GUARD) {
        note_call(action == DARAN_ACTION_FEED_WATCHDOG ? 'f' : 'a');
        return fuzz_hal_action(ctx, action);
    }
    uint32_t limit = h->props[DARAN_PROP_CAN_TIMEOUT_MS].u32;
    FUZZ_CHECK(st.armed && !st.tripped && limit != 0u && st.now - st.last_for_drive >= limit,
               "node guard tripped: armed %d, tripped before %d, timeout %u, %u ms since the last frame",
               st.armed, st.tripped, (unsigned)limit, (unsigned)(st.now - st.last_for_drive));
    st.tripped = true;
    st.guard_trips++;
    /* go idle with the watchdog flag, as the port would */
    h->props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_IDLE;
    h->props[DARAN_PROP_AXIS_ERROR].u32 |= DARAN_FLAG_WATCHDOG;
    return DARAN_OK;
}


/* ---- the port ---- */

/* value x 100 as an s16 field may carry it: within one count, or saturated. */
static bool scaled_fits(float value, int16_t raw)
{
    if (isnan(value)) {
        return true;
    }
    double x = (double)value * 100.0;
    if (x >= 32767.0) {
        return raw >= 32766;
    }
    if (x <= -32768.0) {
        return raw <= -32767;
    }
    return fabs(x - (double)raw) <= 1.0;
}

static uint32_t le32(const uint8_t *b)
{
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

static bool port_send(void *ctx, const daran_can_frame_t *frame)
{
    fuzz_hal_t *h = ctx;
    FUZZ_CHECK(st.enabled, "a frame sent with can.config.protocol 0");
    uint32_t own = h->props[DARAN_PROP_CAN_NODE_ID].u32;
    FUZZ_CHECK(frame->dlc == 8u && frame->flags == 0u && frame->id <= 0x7FFu && frame->id >> 5 == own,
               "frame 0x%x dlc %u flags %u sent by node %u", (unsigned)frame->id, frame->dlc, frame->flags,
               (unsigned)own);
    uint32_t code = frame->id & 0x1Fu;
    const uint8_t *d = frame->data;
    if (code == 0x1Eu) {
        uint16_t address = (uint16_t)(d[0] | d[1] << 8);
        const can_address_t *row = address_row(address);
        FUZZ_CHECK(row != NULL, "read reply for address %u, which the list does not have", address);
        uint32_t type = (uint32_t)(d[2] | d[3] << 8);
        uint32_t want = row->type == DARAN_TYPE_F32 ? 0u : row->type == DARAN_TYPE_S32 ? 4u : 3u;
        FUZZ_CHECK(type == want, "read reply of %u with type code %u, not %u (C7)", address, (unsigned)type,
                   (unsigned)want);
        FUZZ_CHECK(le32(d + 4) == h->props[row->prop].u32, "read reply of %u with another value", address);
        st.sent_replies++;
        st.reply_address = address;
    } else {
        FUZZ_CHECK((code & 0x19u) == 0x01u, "frame of code 0x%02x sent", (unsigned)code);
        bool t = (code & 2u) != 0u, e = (code & 4u) != 0u;
        FUZZ_CHECK(t == (h->props[DARAN_PROP_TRAJECTORY_DONE].u32 != 0u) &&
                       e == (h->props[DARAN_PROP_AXIS_ERROR].u32 != 0u),
                   "status frame T %d E %d for trajectory_done %u, error 0x%x", t, e,
                   (unsigned)h->props[DARAN_PROP_TRAJECTORY_DONE].u32, (unsigned)h->props[DARAN_PROP_AXIS_ERROR].u32);
        FUZZ_CHECK(le32(d) == h->props[DARAN_PROP_POS_ESTIMATE].u32, "status frame with another position");
        FUZZ_CHECK(scaled_fits(h->props[DARAN_PROP_VEL_ESTIMATE].f32, (int16_t)(d[4] | d[5] << 8)) &&
                       scaled_fits(h->props[DARAN_PROP_TORQUE_ESTIMATE].f32, (int16_t)(d[6] | d[7] << 8)),
                   "status frame with velocity or torque not the drive's x 100");
        st.sent_status++;
    }
    st.transmissions++;
    if (st.refuse_every_3 && st.transmissions % 3u == 0u) {
        st.refused++;
        return false;
    }
    return true;
}

static uint32_t port_now(void *ctx)
{
    (void)ctx;
    return st.now;
}

static void port_hook(void *ctx, uint32_t subcode, uint16_t data1, uint16_t data2)
{
    (void)ctx;
    (void)data1;
    (void)data2;
    FUZZ_CHECK(subcode == 0x00u || subcode == 0x07u, "system hook called with sub-code 0x%x", (unsigned)subcode);
}

static const daran_hal_t port_with_hook = {.get = can_get,
                                           .set = can_set,
                                           .move = can_move,
                                           .action = can_action,
                                           .write = fuzz_write,
                                           .now_ms = port_now,
                                           .can_send = port_send,
                                           .can_system = port_hook};
static const daran_hal_t port_without_hook = {.get = can_get,
                                              .set = can_set,
                                              .move = can_move,
                                              .action = can_action,
                                              .write = fuzz_write,
                                              .now_ms = port_now,
                                              .can_send = port_send};

/* ---- the harness's own reading of a frame ---- */

static bool known_code(uint32_t code)
{
    return code == 0x08u || code == 0x0Cu || (code >= 0x19u && code <= 0x1Fu);
}

static bool well_formed(const daran_can_frame_t *frame)
{
    return frame->dlc == 8u && frame->flags == 0u && frame->id <= 0x7FFu;
}

static bool for_drive(const daran_can_frame_t *frame, uint32_t own)
{
    uint32_t node = frame->id >> 5, code = frame->id & 0x1Fu;
    return well_formed(frame) && (node == own || node == 0u) && known_code(code);
}

static void reset_poll_counts(void)
{
    fuzz_hal_clear(&st.hal);
    st.can_error_sets = 0;
    st.first_call = 0;
    st.feeds = 0;
    st.sent_status = 0;
    st.sent_replies = 0;
}

/* A poll that ran @p frame alone (or nothing, when it was refused). */
static void check_one(const daran_can_frame_t *frame, bool taken, uint32_t own, uint32_t reply_state)
{
    fuzz_hal_t *h = &st.hal;
    uint32_t node = frame->id >> 5, code = frame->id & 0x1Fu;
    size_t mutations = h->n_set + h->n_move + h->n_action;
    bool heartbeat_on = h->props[DARAN_PROP_CAN_HEARTBEAT_MS].u32 != 0u;
    size_t status_allowed = heartbeat_on ? 1u : 0u; /* one heartbeat a poll */
    if (!st.enabled) {
        FUZZ_CHECK(mutations == 0u && st.transmissions == 0u && st.guard_trips == 0u,
                   "protocol 0: %zu HAL calls, %u frames sent", mutations, (unsigned)st.transmissions);
        return;
    }
    if (!taken || !for_drive(frame, own)) {
        bool duplicate = taken && well_formed(frame) && (code & 1u) != 0u && code < 0x18u && node == own;
        FUZZ_CHECK(h->n_move == 0u && h->n_action == 0u && st.feeds == 0u &&
                       h->n_set == (duplicate ? st.can_error_sets : 0u) && st.can_error_sets <= 1u &&
                       st.sent_replies == 0u && st.sent_status <= status_allowed,
                   "frame 0x%x dlc %u flags %u for node %u (own %u), not for the drive: %zu set, %zu move, "
                   "%zu action, %zu replies, %zu status frames",
                   (unsigned)frame->id, frame->dlc, frame->flags, (unsigned)node, (unsigned)own, h->n_set,
                   h->n_move, h->n_action, st.sent_replies, st.sent_status);
        return;
    }
    FUZZ_CHECK(st.first_call == 'f', "frame 0x%x for the drive did not feed the watchdog first (C18)",
               (unsigned)frame->id);
    size_t others = mutations - st.feeds;
    FUZZ_CHECK(others <= 1u && st.can_error_sets == 0u, "frame 0x%x made %zu calls besides the feeds",
               (unsigned)frame->id, others);
    uint32_t address = (uint32_t)(frame->data[0] | frame->data[1] << 8);
    switch (code) {
    case 0x0Cu: case 0x19u: case 0x1Au: case 0x1Bu: case 0x1Cu: case 0x1Du:
        /* a motion moves or not; a preset makes no call; either may get a
         * status reply when the drive is set to give one (2.8) */
        FUZZ_CHECK(h->n_set == 0u && h->n_action == st.feeds && (code != 0x0Cu || others == 0u),
                   "frame 0x%x wrote, acted, or moved as a preset", (unsigned)frame->id);
        status_allowed += reply_state != 0u ? 1u : 0u;
        FUZZ_CHECK(st.sent_replies == 0u && st.sent_status <= status_allowed, "frame 0x%x: %zu frames sent",
                   (unsigned)frame->id, st.sent_replies + st.sent_status);
        break;
    case 0x1Eu:
        FUZZ_CHECK(others == 0u, "a read made a HAL call");
        if (address == 0u) {
            FUZZ_CHECK(st.sent_replies == 0u && st.sent_status >= 1u && st.sent_status <= status_allowed + 1u,
                       "fast read answered by %zu status frames", st.sent_status);
        } else {
            FUZZ_CHECK(st.sent_replies == (address_row(address) != NULL ? 1u : 0u) &&
                           (st.sent_replies == 0u || st.reply_address == address) &&
                           st.sent_status <= status_allowed,
                       "read of %u answered by %zu replies", (unsigned)address, st.sent_replies);
        }
        break;
    case 0x1Fu:
        FUZZ_CHECK(h->n_move == 0u && h->n_action == st.feeds, "a write moved or acted");
        FUZZ_CHECK(h->n_set == 0u || (address_row(address) != NULL &&
                                      h->last_set_prop == address_row(address)->prop),
                   "a write of %u set another property", (unsigned)address);
        FUZZ_CHECK(st.sent_replies == 0u && st.sent_status <= status_allowed, "a write was answered");
        break;
    default: /* 0x008: an action, a start's move, or nothing; never answered */
        FUZZ_CHECK(h->n_set == 0u, "a system command wrote a property");
        FUZZ_CHECK(st.sent_replies == 0u && st.sent_status <= status_allowed, "a system command was answered");
        break;
    }
}

static void poll_and_check(const daran_can_frame_t *alone, bool taken, uint32_t own, uint32_t reply_state)
{
    size_t ran = daran_can_poll(&st.can);
    FUZZ_CHECK(ran == st.queued, "poll ran %zu of %zu queued frames", ran, st.queued);
    st.queued = 0;
    st.records_in_poll = 0;
    uint32_t limit = st.hal.props[DARAN_PROP_CAN_TIMEOUT_MS].u32;
    FUZZ_CHECK(!st.enabled || !st.armed || st.tripped || limit == 0u || st.now - st.last_for_drive < limit,
               "the node guard did not trip %u ms after the last frame (timeout %u)",
               (unsigned)(st.now - st.last_for_drive), (unsigned)limit);
    if (alone != NULL) {
        check_one(alone, taken, own, reply_state);
    } else if (!st.enabled) {
        FUZZ_CHECK(st.hal.n_set + st.hal.n_move + st.hal.n_action == 0u && st.transmissions == 0u,
                   "protocol 0: a batch made HAL calls or sent frames");
    }
    FUZZ_CHECK(daran_can_unsent(&st.can) == st.refused, "unsent %u, the port refused %u",
               (unsigned)daran_can_unsent(&st.can), (unsigned)st.refused);
    FUZZ_CHECK(daran_can_dropped(&st.can) == st.dropped, "dropped %u, the ring refused %u",
               (unsigned)daran_can_dropped(&st.can), (unsigned)st.dropped);
}

static daran_can_frame_t decode(const uint8_t *r)
{
    daran_can_frame_t frame;
    frame.id = (uint32_t)r[0] | (uint32_t)(r[1] & 0x07u) << 8;
    frame.flags = 0;
    if ((r[1] & 0x08u) != 0u) {
        frame.flags |= DARAN_CAN_FRAME_REMOTE;
    }
    if ((r[1] & 0x10u) != 0u) {
        frame.flags |= DARAN_CAN_FRAME_EXTENDED;
        frame.id |= (uint32_t)(r[1] >> 3) << 24;
    }
    if ((r[1] & 0x20u) != 0u) {
        frame.flags |= DARAN_CAN_FRAME_FD;
    }
    frame.flags |= (uint8_t)(r[1] & 0xC0u);
    frame.dlc = (r[2] & 0x80u) != 0u ? (uint8_t)(r[2] & 0x0Fu) : 8u;
    memcpy(frame.data, r + 4, 8);
    return frame;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < SETUP_SIZE) {
        return 0;
    }
    memset(&st, 0, sizeof st);
    fuzz_hal_t *h = &st.hal;
    uint32_t own = 1u + data[0] % 63u;
    fuzz_hal_init(h, own);
    switch (data[1] & 3u) {
    case 1:
        h->props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_IDLE;
        break;
    case 2:
        h->props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_IDLE;
        h->props[DARAN_PROP_AXIS_ERROR].u32 = DARAN_FLAG_ESTOP;
        break;
    case 3:
        h->props[DARAN_PROP_AXIS_ERROR].u32 = DARAN_FLAG_MOTOR_FAILED;
        break;
    default:
        break;
    }
    h->props[DARAN_PROP_ENABLE_REPLY_STATE].u32 = (data[1] >> 2) & 1u;
    h->props[DARAN_PROP_TRAJ_MODE].u32 = (data[1] & 0x08u) != 0u ? 2u : 1u;
    h->props[DARAN_PROP_TRAJECTORY_DONE].u32 = 1u;
    h->props[DARAN_PROP_CAN_PROTOCOL].u32 = (data[1] & 0x40u) != 0u ? 0u : 1u;
    h->props[DARAN_PROP_CAN_HEARTBEAT_MS].u32 = data[2];
    h->props[DARAN_PROP_CAN_TIMEOUT_MS].u32 = data[3];
    if ((data[1] & 0x80u) != 0u) {
        static const float odd[] = {NAN, INFINITY, -INFINITY, 327.675f, -327.685f, 1e9f, -1e-9f, 0.005f};
        h->props[DARAN_PROP_POS_ESTIMATE].f32 = odd[data[0] & 7u];
        h->props[DARAN_PROP_VEL_ESTIMATE].f32 = odd[(data[0] >> 3) & 7u];
        h->props[DARAN_PROP_TORQUE_ESTIMATE].f32 = odd[(data[2] + data[3]) & 7u];
    } else {
        h->props[DARAN_PROP_TORQUE_ESTIMATE].f32 = -0.5f;
    }
    st.enabled = h->props[DARAN_PROP_CAN_PROTOCOL].u32 == 1u;
    st.refuse_every_3 = (data[1] & 0x20u) != 0u;
    st.now = 1000u * data[0];
    const daran_hal_t *port = (data[1] & 0x10u) != 0u ? &port_without_hook : &port_with_hook;
    if (daran_init(&st.drive, port, h) != DARAN_OK) {
        fuzz_fail("daran_init refused a complete HAL");
    }
    if (daran_can_init(&st.can, &st.drive) != DARAN_OK) {
        fuzz_fail("daran_can_init refused a complete port");
    }

    reset_poll_counts();
    size_t records = (size_t)(size - SETUP_SIZE) / RECORD_SIZE;
    for (size_t i = 0; i < records; i++) {
        const uint8_t *r = data + SETUP_SIZE + i * RECORD_SIZE;
        daran_can_frame_t frame = decode(r);
        bool batch = (r[2] & 0x40u) != 0u && i + 1u < records;
        if (st.records_in_poll == 0u) {
            /* the clock moves between polls, never during one */
            st.now += r[3];
            reset_poll_counts();
        }
        uint32_t own_now = h->props[DARAN_PROP_CAN_NODE_ID].u32;
        uint32_t reply_state = h->props[DARAN_PROP_ENABLE_REPLY_STATE].u32;
        bool taken = daran_can_receive(&st.can, &frame);
        if (!well_formed(&frame)) {
            FUZZ_CHECK(!taken, "frame 0x%x dlc %u flags %u taken by the ring", (unsigned)frame.id, frame.dlc,
                       frame.flags);
        } else if (!taken) {
            FUZZ_CHECK(st.queued == DARAN_CAN_RX_FRAMES, "well-formed frame refused with %zu queued", st.queued);
            st.dropped++;
        } else {
            st.queued++;
        }
        st.records_in_poll++;
        if (batch) {
            continue;
        }
        bool alone = st.records_in_poll == 1u;
        poll_and_check(alone ? &frame : NULL, taken, own_now, reply_state);
    }
    /* time passes with nothing on the bus: the guard and the heartbeat */
    for (int i = 0; i < 4; i++) {
        st.now += 64u;
        reset_poll_counts();
        poll_and_check(NULL, false, h->props[DARAN_PROP_CAN_NODE_ID].u32, 0u);
        FUZZ_CHECK(st.sent_replies == 0u && st.sent_status <= 1u && st.hal.n_move == 0u && st.feeds == 0u,
                   "an empty poll sent %zu replies, %zu status frames, moved or fed",
                   st.sent_replies, st.sent_status);
        FUZZ_CHECK(st.sent_status == 0u || h->props[DARAN_PROP_CAN_HEARTBEAT_MS].u32 != 0u,
                   "a heartbeat at period 0");
    }
    return 0;
}
