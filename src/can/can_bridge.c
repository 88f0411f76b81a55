/* The bridge: a line for another drive, validated here like a line for this
 * one, goes out as the frames of the contract's section 5.2; a query's
 * replies come back through daran_can_poll() and are printed exactly as the
 * remote drive would print them. One bridged query at a time: while it
 * waits, daran_poll() reads no further line (C32). Frames go out when the
 * line is taken: a transmit the port refuses is `error: bus error` at once
 * (docs/can.md, "The bridge", says why there is no retry). */
#include "can.h"
#include "can_codec.h"
#include "compiler.h"
#include "handlers.h"
#include "property.h"
#include "reply.h"

#if DARAN_ENABLE_CAN_BRIDGE

/* What a finished query prints. */
enum answer {
    ANSWER_VALUES,    /* r f g i: the values on one line */
    ANSWER_ERRORS,    /* e: seven lines */
    ANSWER_TRAPEZOID  /* q with omitted values: nothing; the move goes out */
};

/* reads[i].reserved of the low half of the serial number, whose high half
 * is read next: the two print as one value, high * 2^32 + low (C7). */
#define READ_SERIAL_LOW 1u
/* Every query's reads fit (the serial number takes two). */
DARAN_STATIC_ASSERT(DARAN_QUERY_END_E - DARAN_QUERY_END_I <= DARAN_CAN_BRIDGE_READS &&
                        DARAN_QUERY_END_I - DARAN_QUERY_END_G + 1 <= DARAN_CAN_BRIDGE_READS,
                    a_query_fits_the_bridge_reads);

static void offer(void *bridge, const daran_can_slot_t *frame);
static void tick(void *bridge);
static const daran_can_listener_t bridge_listener = {offer, tick};

/* The drive's side: the bridge is its sink for lines to other ids (its
 * first member, so a sink is the bridge). */
static bool takes(const daran_line_sink_t *sink);
static daran_result_t bridge_line(daran_line_sink_t *sink, const daran_request_t *request,
                                  bool broadcast);
static bool waiting(daran_line_sink_t *sink);
static const daran_line_sink_ops_t bridge_sink = {takes, bridge_line, waiting};

daran_result_t daran_can_bridge_init_checked(daran_can_bridge_t *bridge, daran_can_t *can,
                                             uint32_t build_check)
{
    /* first: a caller of another build may pass a front end it could not
     * initialise, whose drive is still NULL */
    if (build_check != DARAN_BUILD_CHECK(daran_can_bridge_t)) {
        return DARAN_ERR_BUILD_MISMATCH;
    }
    if (bridge == NULL || can == NULL || can->drive == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    /* nothing pending; every other member is written before it is read */
    bridge->count = 0;
    bridge->can = can;
    bridge->sink.ops = &bridge_sink;
    can->listener = &bridge_listener;
    can->listener_ctx = bridge;
    can->drive->sink = &bridge->sink;
    return DARAN_OK;
}

bool daran_can_bridge_busy(const daran_can_bridge_t *bridge)
{
    return bridge->count != 0u;
}

static bool takes(const daran_line_sink_t *sink)
{
    return ((const daran_can_bridge_t *)sink)->can->enabled != 0u;
}

/* A bridged line's frame: one the port refuses is the line's bus error (C33). */
static daran_result_t send_or_fail(daran_can_bridge_t *bridge, uint32_t node, uint32_t code,
                                   const uint8_t *data)
{
    return daran_send_frame(bridge->can->drive, DARAN_CAN_ID(node, code), data)
               ? DARAN_OK
               : DARAN_ERR_BUS_ERROR;
}

/* ---- queries: reads one at a time ---- */

static daran_result_t ask_next(daran_can_bridge_t *bridge)
{
    uint8_t data[8];
    /* the row's type (5.2) */
    daran_can_put_property(data, bridge->reads[bridge->next].address,
                           bridge->reads[bridge->next].type, 0);
    bridge->asked_ms = daran_now_ms(bridge->can->drive);
    return send_or_fail(bridge, bridge->node, DARAN_CAN_READ, data);
}

/* Start a query of @p count properties (their CAN addresses in this
 * build's table, C31): `not bridged` when one has none. The serial number
 * has no address of its own: its two halves are read. */
static daran_result_t ask(daran_can_bridge_t *bridge, uint32_t node, enum answer kind,
                          const daran_prop_t *props, uint8_t count)
{
    uint8_t reads = 0;
    for (uint8_t i = 0; i < count; i++) {
        daran_prop_t prop = props[i];
        uint8_t halves = 1;
        if (prop == DARAN_PROP_SERIAL_NUMBER) {
            prop = DARAN_PROP_SERIAL_NUMBER_L;
            halves = 2;
        }
        while (halves-- != 0u) {
            uint16_t address = daran_can_address_of(prop);
            if (address == 0u) {
                return DARAN_ERR_NOT_BRIDGED;
            }
            daran_can_bridge_read_t *read = &bridge->reads[reads++];
            read->address = address;
            read->type = (uint8_t)daran_can_type_of(prop);
            read->reserved = halves; /* READ_SERIAL_LOW for the low half */
            prop = DARAN_PROP_SERIAL_NUMBER_H;
        }
    }
    bridge->node = (uint8_t)node;
    bridge->kind = (uint8_t)kind;
    bridge->next = 0;
    bridge->wants_checksum = bridge->can->drive->reply_wants_checksum;
    daran_result_t result = ask_next(bridge);
    if (result == DARAN_OK) {
        bridge->count = reads; /* waiting now */
    }
    return result;
}

/* A reply's value as the type it came with (its own type code, C7). */
static daran_prop_type_t reply_value(const daran_can_bridge_read_t *read, daran_value_t *value)
{
    value->u64 = 0;
    switch (read->type) {
    case DARAN_CAN_TYPE_F32:
        value->u32 = read->bits;
        return DARAN_TYPE_F32;
    case DARAN_CAN_TYPE_S16:
        value->s32 = (int16_t)(uint16_t)read->bits;
        return DARAN_TYPE_S32;
    case DARAN_CAN_TYPE_S32:
        value->u32 = read->bits;
        return DARAN_TYPE_S32;
    case DARAN_CAN_TYPE_U16:
        value->u32 = read->bits & 0xFFFFu;
        return DARAN_TYPE_U32;
    default:
        value->u32 = read->bits;
        return DARAN_TYPE_U32;
    }
}

/* The line the remote drive would have printed, or its error. */
static daran_result_t answer(daran_can_bridge_t *bridge)
{
    daran_drive_t *drive = bridge->can->drive;
    const daran_can_bridge_read_t *reads = bridge->reads;
    daran_value_t values[DARAN_CAN_BRIDGE_READS];
    uint8_t types[DARAN_CAN_BRIDGE_READS];
    uint8_t printed = bridge->count;
    for (uint8_t i = 0; i < printed; i++) {
        types[i] = (uint8_t)reply_value(&reads[i], &values[i]);
    }
    /* the serial number, last of its list wherever it is asked, prints as
     * one value: high * 2^32 + low */
    if (printed >= 2u && reads[printed - 2u].reserved == READ_SERIAL_LOW) {
        printed--;
        values[printed - 1u].u64 = (uint64_t)reads[printed].bits << 32 | reads[printed - 1u].bits;
        types[printed - 1u] = DARAN_TYPE_U64;
    }
    switch ((enum answer)bridge->kind) {
    case ANSWER_ERRORS: {
        uint32_t registers[DARAN_ERROR_REGISTERS];
        for (uint8_t i = 0; i < DARAN_ERROR_REGISTERS; i++) {
            registers[i] = values[i].u32;
        }
        daran_reply_error_registers(drive, registers);
        return DARAN_OK;
    }
    case ANSWER_TRAPEZOID: {
        /* the omitted cruise velocity and acceleration, as the remote keeps
         * them (C37): the reads are the velocity (when the line gave only a
         * position) and the acceleration, in that order */
        uint8_t data[8];
        daran_can_put_f32(data, bridge->values[0]);
        float vel = bridge->given == 2u ? bridge->values[1] : values[0].f32;
        /* a limit the frame cannot carry is refused like a value of the
         * line's (C3), not sent as another setting */
        if (!daran_can_put_scaled(data + 4, vel, 0) ||
            !daran_can_put_scaled(data + 6, values[bridge->count - 1u].f32, 0)) {
            return DARAN_ERR_OUT_OF_RANGE;
        }
        return send_or_fail(bridge, bridge->node, DARAN_CAN_TRAPEZOID, data);
    }
    default:
        break;
    }
    daran_reply_begin(drive);
    daran_append_values(drive, values, types, printed);
    daran_reply_end(drive);
    return DARAN_OK;
}

/* The query ends: its answer, or @p result's error line. */
static void finish(daran_can_bridge_t *bridge, daran_result_t result)
{
    daran_drive_t *drive = bridge->can->drive;
    drive->reply_wants_checksum = bridge->wants_checksum;
    if (result == DARAN_OK) {
        result = answer(bridge);
    }
    if (result != DARAN_OK) {
        daran_reply_error(drive, result);
    }
    bridge->count = 0;
}

static void offer(void *context, const daran_can_slot_t *frame)
{
    daran_can_bridge_t *bridge = context;
    if (bridge->count == 0u) {
        return;
    }
    daran_can_bridge_read_t *read = &bridge->reads[bridge->next];
    uint32_t type = daran_can_get_u16(frame->data + 2);
    if (frame->id != DARAN_CAN_ID(bridge->node, DARAN_CAN_READ) ||
        daran_can_get_u16(frame->data) != read->address || type > DARAN_CAN_TYPE_S32) {
        return; /* not the reply awaited: discarded (C32, C38) */
    }
    read->type = (uint8_t)type;
    read->bits = daran_can_get_u32(frame->data + 4);
    bridge->next++;
    if (bridge->next < bridge->count) {
        daran_result_t result = ask_next(bridge);
        if (result != DARAN_OK) {
            finish(bridge, result);
        }
        return;
    }
    finish(bridge, DARAN_OK);
}

/* Advance a pending query (its timeout): true while it still waits. */
static bool pending(daran_can_bridge_t *bridge)
{
    if (bridge->count == 0u) {
        return false;
    }
    daran_can_t *can = bridge->can;
    if (daran_now_ms(can->drive) - bridge->asked_ms >= DARAN_CAN_BRIDGE_TIMEOUT_MS) {
        finish(bridge, DARAN_ERR_NO_REPLY); /* nothing of a partial answer (C32) */
        return false;
    }
    return true;
}

/* ---- a line: its values parsed into the bridge, then its frames ---- */

/* Step 6 of the checks for the line's values, as its handler makes them
 * (C31), kept in the bridge: the parse is the core's deepest call chain,
 * and no frame buffer is on the stack beneath it. bridge->given counts the
 * values a motion line gave; a start keeps its relative flag there, `w` its
 * value's bits in reads[0]. */
static daran_result_t parse_line(daran_can_bridge_t *bridge, const daran_request_t *request,
                                 uint32_t node)
{
    const daran_command_t *command = request->command;
    daran_result_t result = DARAN_OK;
    switch (DARAN_CMD_CAN_FORM(command)) {
    case DARAN_CAN_FORM_WRITE: {
        if (DARAN_PROPERTY_ACCESS(daran_property_row(request->prop)) != DARAN_ACCESS_RW) {
            return DARAN_ERR_READ_ONLY;
        }
        if (daran_can_address_of(request->prop) == 0u) {
            return DARAN_ERR_NOT_BRIDGED;
        }
        daran_value_t value;
        value.u64 = 0;
        daran_field_t field = daran_field_at(request, 2);
        result = daran_parse_property_value(request->prop, &field, &value);
        bridge->reads[0].bits = value.u32;
        return result;
    }
#if DARAN_ENABLE_MULTI_MOTOR
    case DARAN_CAN_FORM_PRESET:
        return daran_parse_preset(request, bridge->values);
    case DARAN_CAN_FORM_START: {
        bool rel = false; /* parse_start sets it only for a good flag */
        result = daran_parse_start(request, &rel);
        bridge->given = rel ? 1u : 0u;
        return result;
    }
#endif
    case DARAN_CAN_FORM_MOTION:
    case DARAN_CAN_FORM_IMPEDANCE:
        if (command->arg == DARAN_SHAPE_TRAPEZOID && node == 0u && request->fields->count < 5u) {
            return DARAN_ERR_NOT_BRIDGED; /* every drive's own limits cannot be read (C35) */
        }
        return daran_parse_motion(request, bridge->values, &bridge->given);
    case DARAN_CAN_FORM_NONE:
        return DARAN_ERR_NOT_BRIDGED; /* nothing is sent for a row without a CAN form */
    default:
        return DARAN_OK; /* nothing after the id, or a property checked already */
    }
}

/* t q p v c d with the values parse_line() kept. */
static daran_result_t send_motion(daran_can_bridge_t *bridge, daran_shape_t shape, uint32_t node)
{
    static const daran_prop_t limits[] = {DARAN_PROP_TRAP_TRAJ_VEL_LIMIT,
                                          DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT};
    float *values = bridge->values;
    uint8_t count = bridge->given;
    /* omitted optional values: 0, and mode 1 for v and c (5.2) */
    for (uint8_t i = count; i < 3u; i++) {
        values[i] = i == 2u && shape >= DARAN_SHAPE_VELOCITY ? 1.0f : 0.0f;
    }
    uint8_t data[8];
    if (shape == DARAN_SHAPE_TRAPEZOID && count < 3u) {
        /* the remote's own limits first, then the move (C37) */
        if (count == 2u && !daran_can_put_scaled(data + 4, values[1], 0)) {
            return DARAN_ERR_OUT_OF_RANGE;
        }
        return ask(bridge, node, ANSWER_TRAPEZOID, limits + (count - 1u), (uint8_t)(3u - count));
    }
    if (shape == DARAN_SHAPE_IMPEDANCE) {
        /* a preset, then its start at the same node (C12) */
        uint8_t start[8] = {DARAN_CAN_SUB_START_IMPEDANCE, 0, 0, 0, 0, 0, 0, 0};
        if (!daran_can_encode_values(DARAN_CAN_LAYOUT_PRESET, values, data) ||
            !daran_can_encode_values(DARAN_CAN_LAYOUT_GAINS, values + 2, start)) {
            return DARAN_ERR_OUT_OF_RANGE;
        }
        daran_result_t result = send_or_fail(bridge, node, DARAN_CAN_PRESET, data);
        return result == DARAN_OK ? send_or_fail(bridge, node, DARAN_CAN_SYSTEM, start) : result;
    }
    return daran_can_encode_values((daran_can_layout_t)shape, values, data)
               ? send_or_fail(bridge, node, DARAN_CAN_TRACK + (uint32_t)shape, data)
               : DARAN_ERR_OUT_OF_RANGE;
}

/* The frames of a line whose values parse_line() kept (5.2). */
static DARAN_NOINLINE daran_result_t send_line(daran_can_bridge_t *bridge,
                                               const daran_request_t *request, uint32_t node)
{
    const daran_command_t *command = request->command;
    daran_prop_t prop = request->prop;
    uint8_t data[8] = {0};
    switch (DARAN_CMD_CAN_FORM(command)) {
    case DARAN_CAN_FORM_READ:
        return ask(bridge, node, ANSWER_VALUES, &request->prop, 1);
    case DARAN_CAN_FORM_READ_LIST: {
        uint8_t count;
        const daran_prop_t *props = daran_query_of(command, &count);
        return ask(bridge, node, command->arg == DARAN_QUERY_LIST_E ? ANSWER_ERRORS : ANSWER_VALUES,
                   props, count);
    }
    case DARAN_CAN_FORM_WRITE:
        if (node == 0u && prop == DARAN_PROP_CAN_NODE_ID) {
            return DARAN_OK; /* "the drive on this link" only, never every drive's id (C34) */
        }
        daran_can_put_property(data, daran_can_address_of(prop), daran_can_type_of(prop),
                               bridge->reads[0].bits);
        return send_or_fail(bridge, node, DARAN_CAN_WRITE, data);
    case DARAN_CAN_FORM_PRESET:
        /* a mode in p3 goes x 100, as the vendor's libraries send it (C40) */
        return daran_can_encode_values(DARAN_CAN_LAYOUT_PRESET, bridge->values, data)
                   ? send_or_fail(bridge, node, DARAN_CAN_PRESET, data)
                   : DARAN_ERR_OUT_OF_RANGE;
    case DARAN_CAN_FORM_START:
        data[0] = (uint8_t)(DARAN_CAN_SUB_START_TRACK + command->arg);
        data[4] = bridge->given; /* the relative flag (C2) */
        return send_or_fail(bridge, node, DARAN_CAN_SYSTEM, data);
    case DARAN_CAN_FORM_ACTION:
        data[0] = (uint8_t)daran_can_subcode_of((daran_action_t)command->arg); /* C36 */
        return send_or_fail(bridge, node, DARAN_CAN_SYSTEM, data);
    case DARAN_CAN_FORM_LOCAL:
#if DARAN_ENABLE_HELP
        return daran_help(bridge->can->drive, request, true); /* no traffic (C35) */
#else
        return DARAN_ERR_NOT_BRIDGED;
#endif
    case DARAN_CAN_FORM_MOTION:
    case DARAN_CAN_FORM_IMPEDANCE:
        return send_motion(bridge, (daran_shape_t)command->arg, node);
    default:
        return DARAN_ERR_NOT_BRIDGED;
    }
}

static void tick(void *bridge)
{
    (void)pending(bridge);
}

static bool waiting(daran_line_sink_t *sink)
{
    return pending((daran_can_bridge_t *)sink);
}

/* Send @p request (checked by the dispatcher up to its values) as frames to
 * its drive, or to node 0 when @p broadcast. DARAN_OK when it went out (a
 * query then answers later), else the error the line answers, with nothing
 * sent. A broadcast line that must not go out (a node id write, C34)
 * returns DARAN_OK without sending. */
static daran_result_t bridge_line(daran_line_sink_t *sink, const daran_request_t *request,
                                  bool broadcast)
{
    daran_can_bridge_t *bridge = (daran_can_bridge_t *)sink;
    if (bridge->count != 0u) {
        return DARAN_ERR_BUS_ERROR; /* one bridged request at a time (C32) */
    }
    uint32_t node = broadcast ? 0u : request->motor;
    daran_result_t result = parse_line(bridge, request, node);
    return result == DARAN_OK ? send_line(bridge, request, node) : result;
}

#endif /* DARAN_ENABLE_CAN_BRIDGE */
