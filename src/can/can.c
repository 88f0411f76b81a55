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
        value.u64 = 0;
    }
    return value;
}

/* The status frame (2.7): position, velocity and torque, with T (the
 * trajectory is done) and E (axis0.error is not 0) in the id's code. */
static void send_status(daran_can_t *can, uint32_t node)
{
    static const daran_prop_t reads[] = {DARAN_PROP_POS_ESTIMATE, DARAN_PROP_VEL_ESTIMATE,
                                         DARAN_PROP_TORQUE_ESTIMATE, DARAN_PROP_TRAJECTORY_DONE,
                                         DARAN_PROP_AXIS_ERROR};
    daran_value_t values[sizeof reads / sizeof reads[0]];
    for (size_t i = 0; i < sizeof reads / sizeof reads[0]; i++) {
        values[i] = read_or_zero(can->drive, reads[i]);
    }
    uint8_t data[8];
    daran_can_put_u32(data, values[0].u32);
    (void)daran_can_put_scaled(data + 4, values[1].f32, 1);
    (void)daran_can_put_scaled(data + 6, values[2].f32, 1);
    uint32_t code = DARAN_CAN_STATUS | (values[3].u32 != 0u ? 2u : 0u) | (values[4].u32 != 0u ? 4u : 0u);
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

/* 0x019..0x01D: t q p v c with every value given (2.1). */
static void direct_motion(daran_can_t *can, uint32_t node, uint32_t code, const uint8_t *data)
{
    daran_shape_t shape = (daran_shape_t)(code - DARAN_CAN_TRACK);
    float values[3];
    daran_can_decode_values((daran_can_layout_t)shape, data, values);
    daran_result_t result = daran_is_finite(values[0]) ? daran_shape_check(shape, values, 3)
                                                       : DARAN_ERR_INVALID_VALUE;
    if (result == DARAN_OK) {
        result = daran_run_motion(can->drive, shape, values, 3);
    }
    if (!value_refused(result)) {
        reply_state(can, node);
    }
}

/* 0x00C: the preset, its third field kept as raw / 100 for the start to
 * read (C1); it moves nothing (2.4). */
static void preset(daran_can_t *can, uint32_t node, const uint8_t *data)
{
#if DARAN_ENABLE_MULTI_MOTOR
    float values[DARAN_PRESET_VALUES];
    daran_can_decode_values(DARAN_CAN_LAYOUT_PRESET, data, values);
    if (!daran_is_finite(values[0])) {
        return;
    }
    daran_store_preset(can->drive, values, DARAN_PRESET_FROM_CAN);
    reply_state(can, node);
#else
    (void)can;
    (void)node;
    (void)data;
#endif
}

/* Sub-codes 0x10..0x15: a start of the preset (2.4). A start the drive
 * refuses is ignored and keeps the preset (C23, C29). */
static void start(daran_can_t *can, uint32_t subcode, const uint8_t *data, bool broadcast)
{
#if DARAN_ENABLE_MULTI_MOTOR
    daran_drive_t *drive = can->drive;
    uint32_t first = daran_can_get_u16(data + 4);
    if (subcode == DARAN_CAN_SUB_START_IMPEDANCE) {
        float gains[3];
        daran_can_decode_values(DARAN_CAN_LAYOUT_GAINS, data, gains);
        (void)daran_start_impedance(drive, gains[1], gains[2], broadcast);
        return;
    }
    daran_shape_t shape = (daran_shape_t)(subcode - DARAN_CAN_SUB_START_TRACK);
    float values[DARAN_PRESET_VALUES];
    memcpy(values, drive->preset, sizeof values);
    bool rel = false;
    if (shape >= DARAN_SHAPE_VELOCITY) {
        /* The mode in p3: raw / 100 of a CAN preset, the mode itself of an
         * ASCII one; x 100, both are what mode_of() reads (C1). */
        float p3 = values[2];
        if (!(p3 >= 0.0f && p3 <= 10.0f)) {
            return;
        }
        values[2] = daran_can_mode_of((uint32_t)(p3 * 100.0f + 0.5f), shape == DARAN_SHAPE_TORQUE);
        if (values[2] == 0.0f) {
            return;
        }    } else if (first == 1u || first == 100u) {
        rel = true; /* relative to the position setpoint (C2) */
    } else if (first != 0u) {
        return;
    }
    (void)daran_start_preset(drive, shape, values, rel, broadcast);
#else
    (void)can;
    (void)subcode;
    (void)data;
    (void)broadcast;
#endif
}

/* 0x008 (2.3). None of them is answered. */
static void system_command(daran_can_t *can, const uint8_t *data, bool broadcast)
{
    uint32_t subcode = daran_can_get_u32(data);
    daran_action_t action;
    if (daran_can_action_of(subcode, &action)) {
        (void)daran_run_action(can->drive, action);
    } else if (subcode >= DARAN_CAN_SUB_START_TRACK && subcode <= DARAN_CAN_SUB_START_IMPEDANCE) {
        start(can, subcode, data, broadcast);
    } else if (subcode == DARAN_CAN_SUB_RESTORE || subcode == DARAN_CAN_SUB_FIRMWARE) {
        daran_pass_system(can->drive, subcode, daran_can_get_u16(data + 4),
                          daran_can_get_u16(data + 6));
    }
    /* 0x20 feeds the watchdogs, as every frame for the drive already has
     * (C18, C19); any other sub-code is ignored (C23). */
}

/* 0x01E (2.6, 2.7): a property's value, or the status frame for address 0. */
static void read_property(daran_can_t *can, uint32_t node, const uint8_t *data)
{
    uint16_t address = daran_can_get_u16(data);
    if (address == 0u) {
        send_status(can, node);
        return;
    }
    daran_prop_t prop;
    daran_value_t value;
    if (!daran_can_property_at(address, &prop) || daran_get(can->drive, prop, &value) != DARAN_OK) {
        return; /* no such address here (C24), or the HAL could not read it */
    }
    uint8_t reply[8];
    daran_can_put_property(reply, address, daran_can_type_of(prop), value.u32);
    send(can, DARAN_CAN_ID(node, DARAN_CAN_READ), reply);
}

/* A write's value, decoded by the frame's type code and converted exactly
 * to the property's type (C6, C25): false when it does not fit. */
static bool write_value(daran_prop_type_t type, uint32_t code, const uint8_t *data,
                        daran_value_t *value)
{
    uint32_t bits = daran_can_get_u32(data);
    bool negative = false;
    uint32_t magnitude = bits;
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
    } else if (code == DARAN_CAN_TYPE_U16) {
        magnitude = bits & 0xFFFFu;
    } else if (code == DARAN_CAN_TYPE_S16 || code == DARAN_CAN_TYPE_S32) {
        int32_t signed_value = code == DARAN_CAN_TYPE_S16 ? (int16_t)(uint16_t)bits : (int32_t)bits;
        negative = signed_value < 0;
        magnitude = negative ? 0u - (uint32_t)signed_value : (uint32_t)signed_value;
    } else if (code != DARAN_CAN_TYPE_U32) {
        return false;
    }
    if (type == DARAN_TYPE_F32) {
        value->f32 = negative ? -(float)magnitude : (float)magnitude; /* the nearest float32 */
        return true;
    }
    if (type == DARAN_TYPE_S32) {
        if (magnitude > (negative ? 0x80000000u : 0x7FFFFFFFu)) {
            return false;
        }
        value->u32 = negative ? 0u - magnitude : magnitude; /* two's complement, as s32 reads it */
        return true;
    }
    value->u32 = magnitude;
    return !negative || magnitude == 0u;
}

/* 0x01F (2.6): checked as ASCII `w` checks it; never answered. */
static void write_property(daran_can_t *can, const uint8_t *data)
{
    daran_prop_t prop;
    if (!daran_can_property_at(daran_can_get_u16(data), &prop)) {
        return; /* C24 */
    }
    daran_property_t row = daran_property_row(prop);
    daran_value_t value;
    value.u64 = 0;
    if (DARAN_PROPERTY_ACCESS(row) != DARAN_ACCESS_RW ||
        !write_value(DARAN_PROPERTY_TYPE(row), daran_can_get_u16(data + 2), data + 4, &value) ||
        daran_check_property_value(prop, value) != DARAN_OK) {
        return; /* C25, C26, C27 */
    }
    (void)daran_commit_property(can->drive, prop, value);
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
    can->guard_tripped = 0;
    (void)daran_act(drive, DARAN_ACTION_FEED_WATCHDOG);

    const uint8_t *data = frame->data;
    bool broadcast = node == 0u;
    switch (code) {
    case DARAN_CAN_SYSTEM:
        system_command(can, data, broadcast);
        break;
    case DARAN_CAN_PRESET:
        preset(can, own.u32, data);
        break;
    case DARAN_CAN_READ:
        read_property(can, own.u32, data);
        break;
    case DARAN_CAN_WRITE:
        write_property(can, data);
        break;
    default:
        direct_motion(can, own.u32, code, data);
        break;
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
    if (can->guard_armed && !can->guard_tripped &&
        daran_get(drive, DARAN_PROP_CAN_TIMEOUT_MS, &limit) == DARAN_OK && limit.u32 != 0u &&
        now - can->last_frame_ms >= limit.u32) {
        can->guard_tripped = 1;
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
