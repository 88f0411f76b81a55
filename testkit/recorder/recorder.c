/* The recording HAL of daran_recorder.h: logs every call the core makes
 * into the HAL, passes it on to an inner HAL (or serves it from its own
 * store), captures the replies, and can make a chosen call fail.
 *
 * Compiled per core target: the store and the property names follow the
 * options header (DARAN_PROP_COUNT, the port's own rows). */
#include "daran_recorder.h"

#include <stdio.h>
#include <string.h>

/* ---- the property list, for names and types ---- */

typedef struct recorder_row {
    const char *path; /* as in the list: without "axisN." */
    uint8_t axis;     /* 1: an axisN. path */
    uint8_t type;     /* daran_prop_type_t */
} recorder_row_t;

#define RECORDER_SCOPE_AXIS 1u
#define RECORDER_SCOPE_SYSTEM 0u
#define RECORDER_ROW(id, path, scope, type, access, range, unit, can) \
    {path, RECORDER_SCOPE_##scope, DARAN_TYPE_##type},
static const recorder_row_t recorder_rows[DARAN_PROP_COUNT] = {
    DARAN_PROPERTY_LIST(RECORDER_ROW)
#ifdef DARAN_PORT_PROPERTY_LIST
    DARAN_PORT_PROPERTY_LIST(RECORDER_ROW)
#endif
};
#undef RECORDER_ROW

static bool prop_known(daran_prop_t prop)
{
    return (unsigned)prop < (unsigned)DARAN_PROP_COUNT;
}

/* ---- logging and fault injection ---- */

/* A call's record, filled in by the HAL function, then kept (finish()). */
static void begin_record(daran_call_t *record, daran_call_kind_t kind)
{
    memset(record, 0, sizeof *record);
    record->kind = kind;
}

/* Count the call, keep it in the log if it is logged and there is room,
 * and hand it to the observer. */
static void finish(daran_recorder_t *rec, const daran_call_t *record)
{
    bool logged = true;
    if (record->kind == DARAN_CALL_GET) {
        rec->n_gets++;
        logged = rec->log_gets;
    } else {
        rec->n_mutations++;
    }
    if (logged) {
        if (rec->n_calls < DARAN_RECORDER_CALLS_MAX) {
            rec->calls[rec->n_calls++] = *record;
        } else {
            rec->n_dropped++;
        }
    }
    if (rec->observer != NULL) {
        rec->observer(rec->observer_ctx, record);
    }
}

/* Does this call take the injected failure? prop is -1 for moves and
 * actions, which a property-bound injection does not count. */
static bool take_failure(daran_recorder_t *rec, daran_call_kind_t kind, int prop)
{
    if (rec->fail_countdown == 0u || (rec->fail_mask & (1u << kind)) == 0u) {
        return false;
    }
    if (rec->fail_prop >= 0 && rec->fail_prop != prop) {
        return false;
    }
    rec->fail_countdown--;
    return rec->fail_countdown == 0u;
}

/* ---- the store double (no inner HAL) ---- */

static void store_set(daran_recorder_t *rec, daran_prop_t prop, daran_value_t value)
{
    daran_value_t *p = rec->store;
    p[prop] = value;
    switch (prop) {
    case DARAN_PROP_REQUESTED_STATE: p[DARAN_PROP_CURRENT_STATE] = value; break;
    case DARAN_PROP_POS_SETPOINT: p[DARAN_PROP_INPUT_POS] = value; break;
    case DARAN_PROP_VEL_SETPOINT: p[DARAN_PROP_INPUT_VEL] = value; break;
    case DARAN_PROP_TORQUE_SETPOINT: p[DARAN_PROP_INPUT_TORQUE] = value; break;
    default: break;
    }
}

/* What docs/porting.md section 3 asks of move(): the targets in input_*,
 * each given rate, cruise or acceleration in its property. */
daran_result_t daran_recorder_apply_move(daran_value_t store[DARAN_PROP_COUNT],
                                         const daran_move_t *move)
{
    daran_value_t *p = store;
    switch (move->kind) {
    case DARAN_MOVE_FILTERED_POSITION:
        p[DARAN_PROP_INPUT_POS].f32 = move->pos_deg;
        if ((move->given & DARAN_GIVEN_RATE) != 0u) {
            p[DARAN_PROP_INPUT_FILTER_BANDWIDTH].f32 = move->rate;
        }
        break;
    case DARAN_MOVE_TRAPEZOID:
        p[DARAN_PROP_INPUT_POS].f32 = move->pos_deg;
        if ((move->given & DARAN_GIVEN_VEL) != 0u) {
            p[DARAN_PROP_TRAP_TRAJ_VEL_LIMIT].f32 = move->vel_rpm;
        }
        if ((move->given & DARAN_GIVEN_RATE) != 0u) {
            p[DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT].f32 = move->rate;
            p[DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT].f32 = move->rate;
        }
        break;
    case DARAN_MOVE_PASSTHROUGH:
    case DARAN_MOVE_IMPEDANCE:
        p[DARAN_PROP_INPUT_POS].f32 = move->pos_deg;
        p[DARAN_PROP_INPUT_VEL].f32 = move->vel_rpm;
        p[DARAN_PROP_INPUT_TORQUE].f32 = move->torque_nm;
        break;
    case DARAN_MOVE_VELOCITY:
        p[DARAN_PROP_INPUT_VEL].f32 = move->vel_rpm;
        p[DARAN_PROP_INPUT_TORQUE].f32 = move->torque_nm;
        break;
    case DARAN_MOVE_VELOCITY_RAMP:
        p[DARAN_PROP_INPUT_VEL].f32 = move->vel_rpm;
        p[DARAN_PROP_VEL_RAMP_RATE].f32 = move->rate;
        break;
    case DARAN_MOVE_TORQUE:
        p[DARAN_PROP_INPUT_TORQUE].f32 = move->torque_nm;
        break;
    case DARAN_MOVE_TORQUE_RAMP:
        p[DARAN_PROP_INPUT_TORQUE].f32 = move->torque_nm;
        p[DARAN_PROP_TORQUE_RAMP_RATE].f32 = move->rate;
        break;
    default:
        return DARAN_ERR_INVALID_MODE; /* a kind it does not know: refuse, change nothing */
    }
    return DARAN_OK;
}

static daran_result_t store_action(daran_recorder_t *rec, daran_action_t action)
{
    static const daran_prop_t registers[] = {
        DARAN_PROP_AXIS_ERROR,           DARAN_PROP_MOTOR_ERROR,
        DARAN_PROP_ENCODER_ERROR,        DARAN_PROP_CONTROLLER_ERROR,
        DARAN_PROP_FET_THERMISTOR_ERROR, DARAN_PROP_MOTOR_THERMISTOR_ERROR,
        DARAN_PROP_CAN_ERROR,            DARAN_PROP_CONFIG_WARNINGS,
    };
    daran_value_t *p = rec->store;
    switch (action) {
    case DARAN_ACTION_ESTOP:
    case DARAN_ACTION_NODE_GUARD:
        p[DARAN_PROP_AXIS_ERROR].u32 |= action == DARAN_ACTION_ESTOP ? DARAN_FLAG_ESTOP
                                                                     : DARAN_FLAG_WATCHDOG;
        p[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_IDLE;
        p[DARAN_PROP_REQUESTED_STATE].u32 = DARAN_STATE_IDLE;
        break;
    case DARAN_ACTION_CLEAR_ERRORS:
        for (size_t i = 0; i < sizeof registers / sizeof registers[0]; i++) {
            p[registers[i]].u32 = 0;
        }
        break;
    case DARAN_ACTION_SET_ZERO: {
        float shift = p[DARAN_PROP_POS_ESTIMATE].f32;
        p[DARAN_PROP_POS_ESTIMATE].f32 = 0.0f;
        p[DARAN_PROP_POS_SETPOINT].f32 -= shift;
        p[DARAN_PROP_INPUT_POS].f32 -= shift;
        break;
    }
    case DARAN_ACTION_SAVE_CONFIG:
    case DARAN_ACTION_ERASE_CONFIG:
    case DARAN_ACTION_REBOOT:
    case DARAN_ACTION_FEED_WATCHDOG:
        break;
    default:
        return DARAN_ERR_MOTOR_FAULT;
    }
    return DARAN_OK;
}

/* ---- the HAL ---- */

static daran_result_t recorder_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    daran_recorder_t *rec = ctx;
    daran_call_t record;
    begin_record(&record, DARAN_CALL_GET);
    record.prop = prop;
    if (take_failure(rec, DARAN_CALL_GET, (int)prop)) {
        record.result = rec->fail_result;
    } else if (rec->inner != NULL) {
        record.result = rec->inner->get(rec->inner_ctx, prop, out);
    } else if (prop_known(prop)) {
        *out = rec->store[prop];
        record.result = DARAN_OK;
    } else {
        record.result = DARAN_ERR_INVALID_PROPERTY;
    }
    if (record.result == DARAN_OK) {
        record.value = *out;
    }
    finish(rec, &record);
    return record.result;
}

static daran_result_t recorder_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    daran_recorder_t *rec = ctx;
    daran_call_t record;
    begin_record(&record, DARAN_CALL_SET);
    record.prop = prop;
    record.value = value;
    if (take_failure(rec, DARAN_CALL_SET, (int)prop)) {
        record.result = rec->fail_result;
    } else if (rec->inner != NULL) {
        record.result = rec->inner->set(rec->inner_ctx, prop, value);
    } else if (prop_known(prop)) {
        store_set(rec, prop, value);
        record.result = DARAN_OK;
    } else {
        record.result = DARAN_ERR_INVALID_PROPERTY;
    }
    finish(rec, &record);
    return record.result;
}

static daran_result_t recorder_move(void *ctx, const daran_move_t *move)
{
    daran_recorder_t *rec = ctx;
    daran_call_t record;
    begin_record(&record, DARAN_CALL_MOVE);
    record.move = *move;
    if (take_failure(rec, DARAN_CALL_MOVE, -1)) {
        record.result = rec->fail_result;
    } else if (rec->inner != NULL) {
        record.result = rec->inner->move(rec->inner_ctx, move);
    } else {
        record.result = daran_recorder_apply_move(rec->store, move);
    }
    finish(rec, &record);
    return record.result;
}

static daran_result_t recorder_action(void *ctx, daran_action_t action)
{
    daran_recorder_t *rec = ctx;
    daran_call_t record;
    begin_record(&record, DARAN_CALL_ACTION);
    record.action = action;
    if (take_failure(rec, DARAN_CALL_ACTION, -1)) {
        record.result = rec->fail_result;
    } else if (rec->inner != NULL) {
        record.result = rec->inner->action(rec->inner_ctx, action);
    } else {
        record.result = store_action(rec, action);
    }
    finish(rec, &record);
    return record.result;
}

/* The clock and the CAN functions are not HAL calls a line's check is about:
 * they pass to the inner port unrecorded (no inner one: a stopped clock and a
 * controller that takes nothing). */
static uint32_t recorder_now_ms(void *ctx)
{
    const daran_recorder_t *rec = ctx;
    return rec->inner != NULL && rec->inner->now_ms != NULL ? rec->inner->now_ms(rec->inner_ctx)
                                                            : 0u;
}

static bool recorder_can_send(void *ctx, const struct daran_can_frame *frame)
{
    const daran_recorder_t *rec = ctx;
    return rec->inner != NULL && rec->inner->can_send != NULL &&
           rec->inner->can_send(rec->inner_ctx, frame);
}

static void recorder_can_system(void *ctx, uint32_t subcode, uint16_t data1, uint16_t data2)
{
    const daran_recorder_t *rec = ctx;
    if (rec->inner != NULL && rec->inner->can_system != NULL) {
        rec->inner->can_system(rec->inner_ctx, subcode, data1, data2);
    }
}

const daran_hal_t daran_recorder_hal = {recorder_get,      recorder_set,       recorder_move,
                                        recorder_action,   daran_recorder_write, NULL,
                                        recorder_now_ms,   recorder_can_send,  recorder_can_system,
                                        NULL};

/* ---- the inner port's own commands ---- */

#if DARAN_ENABLE_PORT_COMMANDS
/* A relay's handler: the drive's context is the recorder, the port's
 * handler wants the port's own. */
static daran_result_t relay_command(daran_drive_t *drive, const daran_args_t *args, void *ctx)
{
    const daran_recorder_t *rec = ctx;
    size_t len = 0;
    const char *word = daran_args_word(args, &len);
    for (size_t i = 0; i < rec->port_command_count; i++) {
        const daran_port_command_t *c = &rec->port_commands[i];
        if (strlen(c->word) == len && memcmp(c->word, word, len) == 0) {
            return c->handler(drive, args, rec->inner_ctx);
        }
    }
    return DARAN_ERR_UNKNOWN_COMMAND; /* the drive found a relay: cannot happen */
}
#endif

daran_result_t daran_recorder_attach_commands(daran_recorder_t *rec, daran_drive_t *drive,
                                              const daran_port_command_t *commands, size_t count)
{
    if (rec == NULL || count > sizeof rec->relays / sizeof rec->relays[0] ||
        (commands == NULL && count != 0u)) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    for (size_t i = 0; i < count; i++) {
        rec->relays[i] = commands[i];
#if DARAN_ENABLE_PORT_COMMANDS
        /* a NULL handler stays NULL, so the drive refuses the table as it would the port's */
        if (commands[i].handler != NULL) {
            rec->relays[i].handler = relay_command;
        }
#endif
    }
    daran_result_t result = daran_set_port_commands(drive, rec->relays, count);
    if (result == DARAN_OK) {
        rec->port_commands = commands;
        rec->port_command_count = count;
    }
    return result;
}

/* ---- setting up ---- */

void daran_recorder_init_store(daran_recorder_t *rec, uint32_t node_id)
{
    daran_recorder_init(rec, NULL, NULL);
    rec->store[DARAN_PROP_CAN_NODE_ID].u32 = node_id;
}

void daran_recorder_init(daran_recorder_t *rec, const daran_hal_t *inner, void *inner_ctx)
{
    memset(rec, 0, sizeof *rec);
    rec->inner = inner;
    rec->inner_ctx = inner_ctx;
    rec->fail_prop = -1;
    rec->store[DARAN_PROP_CAN_NODE_ID].u32 = 1;
    rec->store[DARAN_PROP_REQUESTED_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    rec->store[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
}

void daran_recorder_clear(daran_recorder_t *rec)
{
    rec->n_calls = 0;
    rec->n_dropped = 0;
    rec->n_gets = 0;
    rec->n_mutations = 0;
    rec->out_len = 0;
    rec->out[0] = '\0';
    rec->out_dropped = 0;
    rec->n_replies = 0;
}

void daran_recorder_write(void *ctx, const char *line, size_t len)
{
    daran_recorder_t *rec = ctx;
    size_t room = DARAN_RECORDER_OUT_MAX - rec->out_len;
    size_t kept = len < room ? len : room;
    memcpy(rec->out + rec->out_len, line, kept);
    rec->out_len += kept;
    rec->out[rec->out_len] = '\0';
    rec->out_dropped += len - kept;
    rec->n_replies++;
}

void daran_recorder_fail(daran_recorder_t *rec, unsigned mask, unsigned nth,
                         daran_result_t result, int prop)
{
    rec->fail_mask = mask;
    rec->fail_countdown = nth;
    rec->fail_result = result;
    rec->fail_prop = prop;
}

/* ---- questions ---- */

size_t daran_recorder_mutations(const daran_recorder_t *rec)
{
    return rec->n_mutations;
}

bool daran_recorder_no_effect(const daran_recorder_t *rec)
{
    return rec->n_mutations == 0u;
}

size_t daran_recorder_count(const daran_recorder_t *rec, daran_call_kind_t kind, int action)
{
    size_t n = 0;
    for (size_t i = 0; i < rec->n_calls; i++) {
        const daran_call_t *call = &rec->calls[i];
        if (call->kind == kind &&
            (kind != DARAN_CALL_ACTION || action < 0 || (int)call->action == action)) {
            n++;
        }
    }
    return n;
}

size_t daran_recorder_count_prop(const daran_recorder_t *rec, daran_call_kind_t kind,
                                 daran_prop_t prop)
{
    size_t n = 0;
    for (size_t i = 0; i < rec->n_calls; i++) {
        if (rec->calls[i].kind == kind && rec->calls[i].prop == prop) {
            n++;
        }
    }
    return n;
}

const daran_call_t *daran_recorder_first(const daran_recorder_t *rec, daran_call_kind_t kind)
{
    for (size_t i = 0; i < rec->n_calls; i++) {
        if (rec->calls[i].kind == kind) {
            return &rec->calls[i];
        }
    }
    return NULL;
}

bool daran_recorder_reply_equals(const daran_recorder_t *rec, const char *expected)
{
    if (rec->out_dropped != 0u) {
        return false;
    }
    size_t at = 0;
    for (const char *e = expected; *e != '\0'; e++) {
        if (*e == '\n' && DARAN_REPLY_CRLF) {
            if (at >= rec->out_len || rec->out[at] != '\r') {
                return false;
            }
            at++;
        }
        if (at >= rec->out_len || rec->out[at] != *e) {
            return false;
        }
        at++;
    }
    return at == rec->out_len;
}

/* ---- names ---- */

/* Copy @p text to buf[at..size) without overrunning, NUL terminated when
 * there is room; returns the length the whole text would reach. */
static size_t put_text(char *buf, size_t size, size_t at, const char *text)
{
    size_t len = strlen(text);
    if (at < size) {
        size_t room = size - at - 1u;
        size_t n = len < room ? len : room;
        memcpy(buf + at, text, n);
        buf[at + n] = '\0';
    }
    return at + len;
}

size_t daran_recorder_prop_path(daran_prop_t prop, char *buf, size_t size)
{
    if (size > 0u) {
        buf[0] = '\0';
    }
    if (!prop_known(prop)) {
        return put_text(buf, size, 0, "?");
    }
    size_t at = recorder_rows[prop].axis ? put_text(buf, size, 0, "axis0.") : 0u;
    return put_text(buf, size, at, recorder_rows[prop].path);
}

const char *daran_recorder_move_name(daran_move_kind_t kind)
{
    static const char *const names[] = {
        [DARAN_MOVE_FILTERED_POSITION] = "FILTERED_POSITION",
        [DARAN_MOVE_TRAPEZOID] = "TRAPEZOID",
        [DARAN_MOVE_PASSTHROUGH] = "PASSTHROUGH",
        [DARAN_MOVE_VELOCITY] = "VELOCITY",
        [DARAN_MOVE_VELOCITY_RAMP] = "VELOCITY_RAMP",
        [DARAN_MOVE_TORQUE] = "TORQUE",
        [DARAN_MOVE_TORQUE_RAMP] = "TORQUE_RAMP",
        [DARAN_MOVE_IMPEDANCE] = "IMPEDANCE",
    };
    return (unsigned)kind < sizeof names / sizeof names[0] ? names[kind] : "?";
}

const char *daran_recorder_action_name(daran_action_t action)
{
    static const char *const names[] = {
        [DARAN_ACTION_SAVE_CONFIG] = "SAVE_CONFIG",
        [DARAN_ACTION_ERASE_CONFIG] = "ERASE_CONFIG",
        [DARAN_ACTION_REBOOT] = "REBOOT",
        [DARAN_ACTION_CLEAR_ERRORS] = "CLEAR_ERRORS",
        [DARAN_ACTION_SET_ZERO] = "SET_ZERO",
        [DARAN_ACTION_ESTOP] = "ESTOP",
        [DARAN_ACTION_FEED_WATCHDOG] = "FEED_WATCHDOG",
        [DARAN_ACTION_NODE_GUARD] = "NODE_GUARD",
    };
    return (unsigned)action < sizeof names / sizeof names[0] ? names[action] : "?";
}

/* ---- describing (the only stdio) ---- */

const char *daran_recorder_escape(const char *text, size_t len, char *buf, size_t size)
{
    static const char plain[] = "\n\r\t\"\\";
    static const char named[] = "nrt\"\\";
    size_t k = 0;
    if (size < 4u) { /* no room for anything but the NUL */
        if (size > 0u) {
            buf[0] = '\0';
        }
        return buf;
    }
    /* Each step keeps room for "..." and the NUL after what it wrote. */
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)text[i];
        const char *special = c != 0u ? strchr(plain, c) : NULL;
        size_t width = special != NULL ? 2u : (c < 0x20u || c >= 0x7Fu ? 4u : 1u);
        if (k + width + 4u > size) {
            memcpy(buf + k, "...", 3);
            k += 3u;
            break;
        }
        if (special != NULL) {
            buf[k++] = '\\';
            buf[k++] = named[special - plain];
        } else if (width == 4u) {
            k += (size_t)snprintf(buf + k, size - k, "\\x%02X", c);
        } else {
            buf[k++] = (char)c;
        }
    }
    buf[k] = '\0';
    return buf;
}

/* snprintf's result as a length, or 0 for an encoding error. */
static size_t printed(int n)
{
    return n > 0 ? (size_t)n : 0u;
}

static size_t describe_value(daran_prop_t prop, daran_value_t value, char *buf, size_t size)
{
    unsigned type = prop_known(prop) ? recorder_rows[prop].type : (unsigned)DARAN_TYPE_U32;
    switch (type) {
    case DARAN_TYPE_F32: return printed(snprintf(buf, size, "%.9g", (double)value.f32));
    case DARAN_TYPE_S32: return printed(snprintf(buf, size, "%ld", (long)value.s32));
    case DARAN_TYPE_U64: return printed(snprintf(buf, size, "%llu", (unsigned long long)value.u64));
    default: return printed(snprintf(buf, size, "%lu", (unsigned long)value.u32));
    }
}

/* The members a move of this kind uses (the table in daran_hal.h). */
static size_t describe_move(const daran_move_t *move, char *buf, size_t size)
{
    enum { POS = 1, VEL = 2, TORQUE = 4, RATE = 8, GAINS = 16, GIVEN = 32 };
    static const uint8_t members[] = {
        [DARAN_MOVE_FILTERED_POSITION] = POS | RATE | GIVEN,
        [DARAN_MOVE_TRAPEZOID] = POS | VEL | RATE | GIVEN,
        [DARAN_MOVE_PASSTHROUGH] = POS | VEL | TORQUE,
        [DARAN_MOVE_VELOCITY] = VEL | TORQUE,
        [DARAN_MOVE_VELOCITY_RAMP] = VEL | RATE,
        [DARAN_MOVE_TORQUE] = TORQUE,
        [DARAN_MOVE_TORQUE_RAMP] = TORQUE | RATE,
        [DARAN_MOVE_IMPEDANCE] = POS | VEL | TORQUE | GAINS,
    };
    unsigned used = (unsigned)move->kind < sizeof members ? members[move->kind]
                                                            : POS | VEL | TORQUE | RATE | GAINS | GIVEN;
    size_t len = printed(snprintf(buf, size, "move %s", daran_recorder_move_name(move->kind)));
    /* snprintf with size 0 only counts: past the end, keep counting */
#define MORE_(...) \
    (len += printed(snprintf(len < size ? buf + len : NULL, len < size ? size - len : 0u, __VA_ARGS__)))
    if (used & POS) MORE_(" pos %.9g", (double)move->pos_deg);
    if (used & VEL) MORE_(" vel %.9g", (double)move->vel_rpm);
    if (used & TORQUE) MORE_(" torque %.9g", (double)move->torque_nm);
    if (used & RATE) MORE_(" rate %.9g", (double)move->rate);
    if (used & GAINS) MORE_(" kp %.9g kd %.9g", (double)move->kp, (double)move->kd);
    if (used & GIVEN) {
        static const char *const given[] = {"none", "vel", "rate", "vel|rate"};
        MORE_(" given %s", given[move->given & (DARAN_GIVEN_VEL | DARAN_GIVEN_RATE)]);
    }
#undef MORE_
    return len;
}

size_t daran_call_describe(const daran_call_t *call, char *buf, size_t size)
{
    char path[96];
    char value[32];
    char body[224];
    switch (call->kind) {
    case DARAN_CALL_GET:
    case DARAN_CALL_SET:
        (void)daran_recorder_prop_path(call->prop, path, sizeof path);
        if (call->kind == DARAN_CALL_SET || call->result == DARAN_OK) {
            (void)describe_value(call->prop, call->value, value, sizeof value);
        } else {
            value[0] = '\0';
        }
        if (call->kind == DARAN_CALL_SET) {
            (void)snprintf(body, sizeof body, "set %s %s", path, value);
        } else if (call->result == DARAN_OK) {
            /* a get's value is what it returned: after the arrow */
            return printed(snprintf(buf, size, "get %s -> %s", path, value));
        } else {
            (void)snprintf(body, sizeof body, "get %s", path);
        }
        break;
    case DARAN_CALL_MOVE:
        (void)describe_move(&call->move, body, sizeof body);
        break;
    default:
        (void)snprintf(body, sizeof body, "action %s", daran_recorder_action_name(call->action));
        break;
    }
    return printed(snprintf(buf, size, "%s -> %s", body,
                            call->result == DARAN_OK ? "ok" : daran_result_phrase(call->result)));
}

size_t daran_recorder_describe(const daran_recorder_t *rec, char *buf, size_t size)
{
    if (size > 0u) {
        buf[0] = '\0';
    }
    if (rec->n_calls == 0u && rec->n_dropped == 0u) {
        return put_text(buf, size, 0, "none");
    }
    size_t len = 0;
    for (size_t i = 0; i < rec->n_calls; i++) {
        if (i > 0u) {
            len = put_text(buf, size, len, "\n");
        }
        len += daran_call_describe(&rec->calls[i], len < size ? buf + len : NULL,
                                   len < size ? size - len : 0u);
    }
    if (rec->n_dropped > 0u) {
        char more[48];
        (void)snprintf(more, sizeof more, "%s... and %lu more", rec->n_calls > 0u ? "\n" : "",
                       (unsigned long)rec->n_dropped);
        len = put_text(buf, size, len, more);
    }
    return len;
}
