/* The CAN front end: a frame for this drive -> the same requests an ASCII
 * line becomes (request.h) -> the HAL, and the frames the drive sends:
 * read replies, status frames, heartbeats (docs/can.md; the decisions C1..C30
 * of the contract are cited where they decide). A frame is decoded and
 * checked whole before any request runs, and a refused frame has no effect:
 * CAN has no error reply, so the refusal is silence. */
#include <stddef.h>
#include <string.h>

#include "can.h"
#include "can_codec.h"
#include "can_ring.h"
#include "compiler.h"
#include "property.h"
#include "request.h"

#if DARAN_ENABLE_CAN

/* ---- what the drive sends ---- */

/* The drive's own frames: one the port refuses is counted, not retried. */
static void send(daran_can_t *can, uint32_t id, const uint8_t *data)
{
    if (!daran_send_frame(can->drive, id, data)) {
        can->unsent++;
    }
}

/* A value the status frame reads; a row the port left out reads 0. */
static daran_value_t read_or_zero(daran_drive_t *drive, daran_prop_t prop)
{
    daran_value_t value;
    if (daran_get(drive, prop, &value) != DARAN_OK) {
        value.u32 = 0; /* f32 0 too: only those are read */
    }
    return value;
}

/* The status frame (2.7): position, velocity and torque, with T (the
 * trajectory is done) and E (axis0.error is not 0) in the id's code; the
 * i-th read goes to the i-th place. */
static void send_status(daran_can_t *can, uint32_t node)
{
    static const daran_prop_t reads[] = {DARAN_PROP_POS_ESTIMATE, DARAN_PROP_VEL_ESTIMATE,
                                         DARAN_PROP_TORQUE_ESTIMATE, DARAN_PROP_TRAJECTORY_DONE,
                                         DARAN_PROP_AXIS_ERROR};
    uint8_t data[8];
    uint32_t code = DARAN_CAN_STATUS;
    for (unsigned i = 0; i < sizeof reads / sizeof reads[0]; i++) {
        daran_value_t value = read_or_zero(can->drive, reads[i]);
        if (i == 0u) {
            daran_can_put_u32(data, value.u32);
        } else if (i < 3u) {
            (void)daran_can_put_scaled(data + 2u + 2u * i, value.f32, 1);
        } else if (value.u32 != 0u) {
            code |= 1u << (i - 2u); /* T bit 1, E bit 2 */
        }
    }
    send(can, DARAN_CAN_ID(node, code), data);
}

/* The automatic status reply of a motion or preset frame that passed its
 * value checks, when the drive is set to give one (2.8, C10). */
static void reply_state(daran_can_t *can, uint32_t node)
{
    if (read_or_zero(can->drive, DARAN_PROP_ENABLE_REPLY_STATE).u32 != 0u) {
        send_status(can, node);
    }
}

/* ---- the frames for this drive ---- */

/* A value the motion checks refused, as opposed to the drive's state: the
 * frame then gets no status reply (C10, C27). */
static bool value_refused(daran_result_t result)
{
    return result == DARAN_ERR_INVALID_VALUE || result == DARAN_ERR_OUT_OF_RANGE ||
           result == DARAN_ERR_INVALID_MODE;
}

/* 0x019..0x01D, t q p v c with every value given (2.1), and 0x00C, the
 * preset, its third field kept as raw / 100 for the start to read (C1; it
 * moves nothing, 2.4): three values by the code's layout, the first a
 * finite f32. A mode is the shape's to check, as a line's is. */
static void value_frame(daran_can_t *can, uint32_t node, uint32_t code, const uint8_t *data)
{
    bool preset = code == DARAN_CAN_PRESET;
    daran_can_layout_t layout =
        preset ? DARAN_CAN_LAYOUT_PRESET : (daran_can_layout_t)(code - DARAN_CAN_TRACK);
    float values[DARAN_PRESET_VALUES];
    daran_can_decode_values(layout, data, values);
    if (!daran_is_finite(values[0])) {
        return;
    }
    if (preset) {
#if DARAN_ENABLE_MULTI_MOTOR
        daran_store_preset(can->drive, values, DARAN_PRESET_FROM_CAN);
#else
        return;
#endif
    } else {
        daran_shape_t shape = (daran_shape_t)layout;
        daran_result_t result = daran_shape_check(shape, values, 3);
        if (result == DARAN_OK) {
            result = daran_run_motion(can->drive, shape, values, 3);
        }
        if (value_refused(result)) {
            return;
        }
    }
    reply_state(can, node);
}

#if DARAN_ENABLE_MULTI_MOTOR
/* Sub-codes 0x10..0x14: a start of the preset as @p shape (2.4), with the
 * start's flag (bytes 4..5). A start the drive refuses is ignored and keeps
 * the preset (C23, C29). */
static void start(daran_drive_t *drive, daran_shape_t shape, uint32_t flag, bool broadcast)
{
    float values[DARAN_PRESET_VALUES];
    memcpy(values, drive->preset, sizeof values);
    /* 0 absolute, 1 relative to the position setpoint (C2); v and c have
     * no flag, and a start of theirs reads none */
    uint32_t rel = daran_can_whole_of(flag);
    if (shape >= DARAN_SHAPE_VELOCITY) {
        /* The mode in p3: raw / 100 of a CAN preset, the mode itself of an
         * ASCII one; x 100, both read as a mode field does (C1). */
        uint32_t p3;
        memcpy(&p3, &values[2], sizeof p3);
        if (p3 > 0x41200000u) {
            return; /* past 10.0f as bits: a sign (-0 too), NaN, inf: no mode */
        }
        /* a mode the shape has not is the start's to refuse, as a line's */
        values[2] = (float)daran_can_whole_of((uint32_t)(values[2] * 100.0f + 0.5f));
    } else if (rel > 1u) {
        return;
    }
    (void)daran_start_preset(drive, shape, values, rel != 0u, broadcast);
}
#endif

/* 0x008 (2.3). None of them is answered. */
static void system_command(daran_can_t *can, const uint8_t *data, bool broadcast)
{
    daran_drive_t *drive = can->drive;
    uint32_t subcode = daran_can_get_u32(data);
    daran_action_t action;
    if (daran_can_action_of(subcode, &action)) {
        (void)daran_run_action(drive, action);
    } else if (subcode == DARAN_CAN_SUB_RESTORE || subcode == DARAN_CAN_SUB_FIRMWARE) {
        daran_pass_system(drive, subcode, daran_can_get_u16(data + 4), daran_can_get_u16(data + 6));
    }
#if DARAN_ENABLE_MULTI_MOTOR
    else if (subcode - DARAN_CAN_SUB_START_TRACK <= (uint32_t)DARAN_SHAPE_IMPEDANCE) {
        /* the starts follow the shapes' order, the impedance start last */
        daran_shape_t shape = (daran_shape_t)(subcode - DARAN_CAN_SUB_START_TRACK);
        if (shape == DARAN_SHAPE_IMPEDANCE) {
            float gains[3];
            daran_can_decode_values(DARAN_CAN_LAYOUT_GAINS, data, gains);
            (void)daran_start_impedance(drive, gains[1], gains[2], broadcast);
        } else {
            start(drive, shape, daran_can_get_u16(data + 4), broadcast);
        }
    }
#else
    (void)broadcast;
#endif
    /* 0x20 feeds the watchdogs, as every frame for the drive already has
     * (C18, C19); any other sub-code is ignored (C23). */
}

/* A write's value, decoded by the frame's type code and converted exactly
 * to the property's type (C6, C25): false when it does not fit. An integer
 * travels as its sign and magnitude, so every pair of types is one road. */
static bool write_value(daran_prop_type_t type, uint32_t code, const uint8_t *data,
                        daran_value_t *value)
{
    uint32_t magnitude = daran_can_get_u32(data);
    bool negative = false;
    if (code == DARAN_CAN_TYPE_F32) {
        float given = daran_can_get_f32(data);
        if (type == DARAN_TYPE_F32) {
            value->f32 = given;
            return daran_is_finite(given);
        }
        /* an integral float for an integer row, as ASCII takes `5.0` */
        negative = given < 0.0f;
        float size = negative ? -given : given;
        if (!(size < 4294967296.0f)) {
            return false; /* and NaN */
        }
        magnitude = (uint32_t)size;
        if ((float)magnitude != size) {
            return false;
        }
    } else if (code <= DARAN_CAN_TYPE_S32) {
        if (code < DARAN_CAN_TYPE_U32) { /* the 16-bit codes */
            magnitude = code == DARAN_CAN_TYPE_S16 ? (uint32_t)(int16_t)(uint16_t)magnitude
                                                   : magnitude & 0xFFFFu;
        }
        /* S16 and S32, the even codes: their sign bit */
        negative = (code & 1u) == 0u && (magnitude >> 31) != 0u;
        if (negative) {
            magnitude = 0u - magnitude;
        }
    } else {
        return false;
    }
    if (type == DARAN_TYPE_F32) {
        value->f32 = negative ? -(float)magnitude : (float)magnitude; /* the nearest float32 */
        return true;
    }
    value->u32 = negative ? 0u - magnitude : magnitude; /* two's complement, as s32 reads it */
    if (type == DARAN_TYPE_S32) {
        return magnitude <= 0x7FFFFFFFu + (uint32_t)negative;
    }
    return !negative || magnitude == 0u;
}

/* 0x01E, a read (2.6, 2.7): the property's value, or the status frame for
 * address 0; 0x01F, a write (2.6): checked as ASCII `w` checks it, never
 * answered. */
static void property_frame(daran_can_t *can, uint32_t node, uint32_t code, const uint8_t *data)
{
    uint16_t address = daran_can_get_u16(data);
    bool read = code == DARAN_CAN_READ;
    if (read && address == 0u) {
        send_status(can, node);
        return;
    }
    daran_prop_t prop;
    if (!daran_can_property_at(address, &prop)) {
        return; /* no such address here (C24) */
    }
    daran_value_t value;
    value.u64 = 0;
    if (read) {
        if (daran_get(can->drive, prop, &value) == DARAN_OK) { /* else the HAL could not read it */
            uint8_t reply[8];
            daran_can_put_property(reply, address, daran_can_type_of(prop), value.u32);
            send(can, DARAN_CAN_ID(node, DARAN_CAN_READ), reply);
        }
        return;
    }
    daran_property_t row = daran_property_row(prop);
    if (DARAN_PROPERTY_ACCESS(row) == DARAN_ACCESS_RW &&
        write_value(DARAN_PROPERTY_TYPE(row), daran_can_get_u16(data + 2), data + 4, &value) &&
        daran_check_property_value(prop, value) == DARAN_OK) { /* else C25, C26, C27 */
        (void)daran_commit_property(can->drive, prop, value);
    }
}

/* A command code of the protocol (2.1); every other one is ignored (C22). */
static bool known_code(uint32_t code)
{
    return code == DARAN_CAN_SYSTEM || code == DARAN_CAN_PRESET ||
           (code >= DARAN_CAN_TRACK && code <= DARAN_CAN_WRITE);
}

/* Another node claims this drive's id: can.error bit 0 (C22). The core
 * writes that bit itself; it is the one non-zero value it ever gives an
 * error register (docs/porting.md). */
static void duplicate_id(daran_drive_t *drive)
{
    daran_value_t errors;
    if (daran_get(drive, DARAN_PROP_CAN_ERROR, &errors) == DARAN_OK && (errors.u32 & 1u) == 0u) {
        errors.u32 |= 1u;
        (void)daran_set(drive, DARAN_PROP_CAN_ERROR, errors);
    }
}

static void run_frame(daran_can_t *can, const daran_can_slot_t *frame, uint32_t now)
{
    daran_drive_t *drive = can->drive;
    uint32_t node = DARAN_CAN_NODE_OF(frame->id);
    uint32_t code = DARAN_CAN_CODE_OF(frame->id);
    daran_value_t own;
    if (daran_get(drive, DARAN_PROP_CAN_NODE_ID, &own) != DARAN_OK) {
        return;
    }
    if ((code & DARAN_CAN_STATUS) != 0u && code < 0x18u) {
        if (node == own.u32) {
            duplicate_id(drive); /* a status frame: never a command (C9) */
        }
        return;
    }
    if (node != own.u32 && node != 0u) {
        if (can->listener != NULL) {
            can->listener->frame(can->listener_ctx, frame); /* a reply to a bridged query? */
        }
        return; /* C28 */
    }
    if (!known_code(code)) {
        return; /* C22 */
    }
    /* Every well-formed frame for the drive feeds the node guard and the
     * axis watchdog, whatever its content (C18). */
    can->last_frame_ms = now;
    can->guard_armed = 1;
    (void)daran_act(drive, DARAN_ACTION_FEED_WATCHDOG);

    if (code == DARAN_CAN_SYSTEM) {
        system_command(can, frame->data, node == 0u);
    } else if (code >= DARAN_CAN_READ) {
        property_frame(can, own.u32, code, frame->data);
    } else {
        value_frame(can, own.u32, code, frame->data);
    }
}

/* ---- the front end ---- */

daran_result_t daran_can_init_checked(daran_can_t *can, daran_drive_t *drive,
                                      uint32_t build_check)
{
    if (can == NULL || drive == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    /* first: a drive a mismatched build refused holds no port to look at */
    if (build_check != DARAN_BUILD_CHECK(daran_can_t)) {
        return DARAN_ERR_BUILD_MISMATCH;
    }
    if (drive->hal == NULL || drive->hal->can_send == NULL || drive->hal->now_ms == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    /* every member but the slots, which the producer fills before use */
    unsigned char *raw = (unsigned char *)can;
    for (size_t i = 0; i < offsetof(daran_can_t, slots); i++) {
        raw[i] = 0;
    }
    can->drive = drive;
    daran_value_t protocol;
    /* read once, as a drive reads it at boot (C15); a port without the row
     * speaks the protocol */
    daran_result_t result = daran_get(drive, DARAN_PROP_CAN_PROTOCOL, &protocol);
    can->enabled = result != DARAN_OK || protocol.u32 == 1u;
    can->heartbeat_ms = daran_now_ms(drive);
    can->kept_ms = can->heartbeat_ms - 1u; /* the first poll looks */
    return DARAN_OK;
}

/* The node guard (C16) and the heartbeat (2.9, C17), once per poll. */
static void keep_time(daran_can_t *can, uint32_t now)
{
    daran_drive_t *drive = can->drive;
    daran_value_t limit;
    if (can->guard_armed &&
        daran_get(drive, DARAN_PROP_CAN_TIMEOUT_MS, &limit) == DARAN_OK && limit.u32 != 0u &&
        now - can->last_frame_ms >= limit.u32) {
        can->guard_armed = 0; /* tripped: the next frame for the drive arms it again */
        (void)daran_act(drive, DARAN_ACTION_NODE_GUARD);
    }
    daran_value_t period;
    daran_value_t own;
    if (daran_get(drive, DARAN_PROP_CAN_HEARTBEAT_MS, &period) == DARAN_OK && period.u32 != 0u &&
        now - can->heartbeat_ms >= period.u32 &&
        daran_get(drive, DARAN_PROP_CAN_NODE_ID, &own) == DARAN_OK) {
        can->heartbeat_ms = now;
        send_status(can, own.u32);
    }
}

size_t daran_can_poll(daran_can_t *can)
{
    uint32_t now = daran_now_ms(can->drive);
    size_t queued = daran_can_queued(can);
    for (size_t i = 0; i < queued; i++) {
        if (can->enabled) {
            run_frame(can, daran_can_oldest(can), now);
        }
        daran_can_release(can);
    }
    /* Once a millisecond is enough: neither can fall due again before the
     * clock moves, and a poll of a fast control loop spares two HAL reads. */
    if (can->enabled && now != can->kept_ms) {
        can->kept_ms = now;
        keep_time(can, now);
        if (can->listener != NULL) {
            can->listener->tick(can->listener_ctx); /* a bridged query's timeout */
        }
    }
    return queued;
}

uint32_t daran_can_unsent(const daran_can_t *can)
{
    return can->unsent;
}

#endif /* DARAN_ENABLE_CAN */
