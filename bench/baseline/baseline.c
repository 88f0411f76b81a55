/* YARDSTICK ONLY - never linked into the daran-ascii library (see baseline.h).
 *
 * The protocol parsed the ODrive way: sscanf splits the line, strtof reads
 * the numbers, strcmp walks the tables, snprintf("%f") formats the replies.
 * Validation order and HAL calls follow shared/spec/protocol.md section 8 and
 * docs/protocol.md, section 10 included (zero rates, S-curve mq timing, the
 * vendor's whole property table with s32 and the new ranges, the error
 * registers and the seven-line `e`, CR LF line ends), so the comparison
 * measures the parsing style, not a smaller job. */
#include "baseline.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "daran_config.h"

#define LINE_MAX_BYTES 128
#define MOTOR_ID_MAX 63
#define FIELDS_MAX 8
#define TOKEN_BYTES (LINE_MAX_BYTES + 1)

/* ---- tables, searched with strcmp --------------------------------------- */

enum { SCOPE_SYSTEM_ = 0, SCOPE_AXIS_ = 1 };
enum { ACC_RO, ACC_RW };
enum { T_F32, T_U32, T_S32, T_U64, T_BOOL };
enum {
    R_NONE, R_NON_NEGATIVE, R_POSITIVE, R_NON_POSITIVE, R_BOOL, R_ZERO, R_NODE_ID, R_UART_BAUD,
    R_CAN_BAUD, R_CAN_PROTOCOL, R_AXIS_STATE, R_CONTROL_MODE, R_INPUT_MODE, R_TRAJ_MODE,
    R_DIRECTION, R_MOTOR_TYPE, R_POLE_PAIRS, R_TELEMETRY
};

typedef struct bl_property {
    const char *name;
    daran_prop_t prop;
    unsigned char scope, type, access, range;
} bl_property_t;

#define BL_SYSTEM SCOPE_SYSTEM_
#define BL_AXIS SCOPE_AXIS_
#define BL_F32 T_F32
#define BL_U32 T_U32
#define BL_S32 T_S32
#define BL_U64 T_U64
#define BL_BOOL T_BOOL
#define BL_RO ACC_RO
#define BL_RW ACC_RW
#define BL_R_NONE R_NONE
#define BL_R_NON_NEGATIVE R_NON_NEGATIVE
#define BL_R_POSITIVE R_POSITIVE
#define BL_R_NON_POSITIVE R_NON_POSITIVE
#define BL_R_BOOL R_BOOL
#define BL_R_ZERO R_ZERO
#define BL_R_NODE_ID R_NODE_ID
#define BL_R_UART_BAUD R_UART_BAUD
#define BL_R_CAN_BAUD R_CAN_BAUD
#define BL_R_CAN_PROTOCOL R_CAN_PROTOCOL
#define BL_R_AXIS_STATE R_AXIS_STATE
#define BL_R_CONTROL_MODE R_CONTROL_MODE
#define BL_R_INPUT_MODE R_INPUT_MODE
#define BL_R_TRAJ_MODE R_TRAJ_MODE
#define BL_R_DIRECTION R_DIRECTION
#define BL_R_MOTOR_TYPE R_MOTOR_TYPE
#define BL_R_POLE_PAIRS R_POLE_PAIRS
#define BL_R_TELEMETRY R_TELEMETRY

/* Same names as the library (the X-macro list is the protocol's property
 * list: the vendor's whole table), but a plain array of C strings scanned
 * front to back, as ODrive-style endpoint tables are. */
static const bl_property_t properties[] = {
#define BL_ROW(id, path, scope, type, access, range, unit, can) \
    {path, DARAN_PROP_##id, BL_##scope, BL_##type, BL_##access, BL_R_##range},
    DARAN_PROPERTY_LIST(BL_ROW)
#undef BL_ROW
};
#define PROPERTY_COUNT (sizeof properties / sizeof properties[0])

typedef struct bl_command bl_command_t;
typedef daran_result_t (*bl_handler_fn)(baseline_t *b, const bl_command_t *cmd,
                                        char tok[][TOKEN_BYTES], int count, unsigned motor);

struct bl_command {
    const char *word;
    int min_fields;
    int max_fields;
    int is_read;
    int is_path;
    int arg;
    bl_handler_fn handler;
    const char *help;
};

static const char *const phrases[] = {
    "ok", "unknown command", "invalid command format", "invalid motor", "invalid value",
    "value out of range", "invalid mode", "invalid property", "read only property",
    "invalid checksum", "checksum mismatch", "line too long", "invalid character", "no preset",
    "trajectory infeasible", "estop active", "motor fault", "motor idle",
};

/* ---- replies ------------------------------------------------------------- */

static unsigned xor_bytes(const char *text, size_t len)
{
    unsigned x = 0;
    for (size_t i = 0; i < len; i++) {
        x ^= (unsigned char)text[i];
    }
    return x;
}

static void send_reply(baseline_t *b, int with_checksum)
{
    size_t n = strlen(b->reply);
    if (with_checksum) {
        unsigned x = xor_bytes(b->reply, n) ^ ' ';
        n += (size_t)snprintf(b->reply + n, sizeof b->reply - n, " *%u", x);
    }
#if DARAN_REPLY_CRLF
    if (n + 2 < sizeof b->reply) {
        b->reply[n++] = '\r';
    }
#endif
    if (n + 1 < sizeof b->reply) {
        b->reply[n++] = '\n';
    }
    b->write(b->write_ctx, b->reply, n);
}

static void reply(baseline_t *b, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    vsnprintf(b->reply, sizeof b->reply, format, args);
    va_end(args);
    send_reply(b, b->reply_checksum);
}

static daran_result_t reply_error(baseline_t *b, daran_result_t result, int with_checksum)
{
    unsigned index = (unsigned)result < sizeof phrases / sizeof phrases[0] ? (unsigned)result : 16u;
    snprintf(b->reply, sizeof b->reply, "error: %s", phrases[index]);
    send_reply(b, with_checksum);
    return result;
}

/* ---- numbers ------------------------------------------------------------- */

/* strtof accepts nan, inf and hex; the protocol does not. */
static int decimal_chars(const char *text)
{
    if (*text == '\0') {
        return 0;
    }
    for (const char *p = text; *p != '\0'; p++) {
        char c = *p;
        if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E')) {
            return 0;
        }
    }
    return 1;
}

static daran_result_t parse_f32(const char *text, float *out)
{
    char *end;
    if (!decimal_chars(text)) {
        return DARAN_ERR_INVALID_VALUE;
    }
    errno = 0;
    float value = strtof(text, &end);
    if (end == text || *end != '\0') {
        return DARAN_ERR_INVALID_VALUE;
    }
    if (errno == ERANGE && isinf(value)) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    *out = value;
    return DARAN_OK;
}

/* An exact integer written as a decimal number ("5", "5.0", "5e0"). */
static daran_result_t parse_integer(const char *text, double *out)
{
    char *end;
    if (!decimal_chars(text)) {
        return DARAN_ERR_INVALID_VALUE;
    }
    double value = strtod(text, &end);
    if (end == text || *end != '\0' || value != floor(value)) {
        return DARAN_ERR_INVALID_VALUE;
    }
    *out = value;
    return DARAN_OK;
}

static daran_result_t parse_motor(const char *text, unsigned *out)
{
    double value;
    if (parse_integer(text, &value) != DARAN_OK || value < 0.0 || value > MOTOR_ID_MAX) {
        return DARAN_ERR_INVALID_MOTOR;
    }
    *out = (unsigned)value;
    return DARAN_OK;
}

static daran_result_t parse_mode(const char *text, uint32_t allowed, uint32_t *out)
{
    double value;
    if (parse_integer(text, &value) != DARAN_OK) {
        return DARAN_ERR_INVALID_VALUE;
    }
    if (value < 0.0 || value >= 32.0 || ((allowed >> (unsigned)value) & 1u) == 0u) {
        return DARAN_ERR_INVALID_MODE;
    }
    *out = (uint32_t)value;
    return DARAN_OK;
}

static daran_result_t parse_positive(const char *text, float *out)
{
    daran_result_t result = parse_f32(text, out);
    return result == DARAN_OK && !(*out > 0.0f) ? DARAN_ERR_OUT_OF_RANGE : result;
}

static daran_result_t parse_non_negative(const char *text, float *out)
{
    daran_result_t result = parse_f32(text, out);
    return result == DARAN_OK && !(*out >= 0.0f) ? DARAN_ERR_OUT_OF_RANGE : result;
}

/* ---- drive state ---------------------------------------------------------- */

static daran_result_t get(baseline_t *b, daran_prop_t prop, daran_value_t *out)
{
    out->u64 = 0;
    daran_result_t result = b->hal->get(b->hal_ctx, prop, out);
    return (unsigned)result < DARAN_RESULT_COUNT ? result : DARAN_ERR_MOTOR_FAULT;
}

static daran_result_t motion_allowed(baseline_t *b)
{
    daran_value_t value;
    daran_result_t result = get(b, DARAN_PROP_AXIS_ERROR, &value);
    if (result != DARAN_OK) {
        return result;
    }
    if (value.u32 & DARAN_FLAG_ESTOP) {
        return DARAN_ERR_ESTOP_ACTIVE;
    }
    if (value.u32 != 0u) {
        return DARAN_ERR_MOTOR_FAULT; /* any other bit of axis0.error blocks motion */
    }
    result = get(b, DARAN_PROP_CURRENT_STATE, &value);
    if (result != DARAN_OK) {
        return result;
    }
    return value.u32 == DARAN_STATE_CLOSED_LOOP ? DARAN_OK : DARAN_ERR_MOTOR_IDLE;
}

static daran_result_t start_move(baseline_t *b, daran_result_t parsed, const daran_move_t *move)
{
    if (parsed != DARAN_OK) {
        return parsed;
    }
    daran_result_t result = motion_allowed(b);
    if (result != DARAN_OK) {
        return result;
    }
    result = b->hal->move(b->hal_ctx, move);
    if ((unsigned)result >= DARAN_RESULT_COUNT) {
        result = DARAN_ERR_MOTOR_FAULT;
    }
    if (result == DARAN_OK) {
        (void)b->hal->action(b->hal_ctx, DARAN_ACTION_FEED_WATCHDOG);
    }
    return result;
}

/* ---- single-motor motion ---------------------------------------------------- */

#define MODES_VELOCITY ((1u << 1) | (1u << 2))
#define MODES_TORQUE ((1u << 1) | (1u << 2) | (1u << 6))
#define MODES_START ((1u << 0) | (1u << 1))

static daran_result_t cmd_t(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                            int count, unsigned motor)
{
    daran_move_t move;
    float ignored;
    (void)cmd;
    (void)motor;
    memset(&move, 0, sizeof move);
    move.kind = DARAN_MOVE_FILTERED_POSITION;
    daran_result_t result = parse_f32(tok[2], &move.pos_deg);
    if (result == DARAN_OK && count > 3) {
        result = parse_f32(tok[3], &ignored);
    }
    if (result == DARAN_OK && count > 4) {
        result = parse_non_negative(tok[4], &move.rate);
        if (move.rate == 0.0f) {
            move.rate = 0.0f; /* bandwidth 0 (or -0): keep the current one */
        } else {
            move.given = DARAN_GIVEN_RATE;
        }
    }
    return start_move(b, result, &move);
}

static daran_result_t cmd_q(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                            int count, unsigned motor)
{
    daran_move_t move;
    (void)cmd;
    (void)motor;
    memset(&move, 0, sizeof move);
    move.kind = DARAN_MOVE_TRAPEZOID;
    daran_result_t result = parse_f32(tok[2], &move.pos_deg);
    if (result == DARAN_OK && count > 3) {
        result = parse_positive(tok[3], &move.vel_rpm);
        move.given |= DARAN_GIVEN_VEL;
    }
    if (result == DARAN_OK && count > 4) {
        result = parse_non_negative(tok[4], &move.rate);
        move.given |= DARAN_GIVEN_RATE;
        if (move.rate == 0.0f) {
            /* acceleration 0: a step to the target, no cruise */
            move.rate = 0.0f;
            move.vel_rpm = 0.0f;
            move.given &= (uint8_t)~DARAN_GIVEN_VEL;
        }
    }
    return start_move(b, result, &move);
}

static daran_result_t cmd_p(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                            int count, unsigned motor)
{
    daran_move_t move;
    (void)cmd;
    (void)motor;
    memset(&move, 0, sizeof move);
    move.kind = DARAN_MOVE_PASSTHROUGH;
    daran_result_t result = parse_f32(tok[2], &move.pos_deg);
    if (result == DARAN_OK && count > 3) {
        result = parse_f32(tok[3], &move.vel_rpm);
    }
    if (result == DARAN_OK && count > 4) {
        result = parse_f32(tok[4], &move.torque_nm);
    }
    return start_move(b, result, &move);
}

static daran_result_t velocity_move(float vel, float param, uint32_t mode, daran_move_t *move)
{
    move->vel_rpm = vel;
    if (mode == 2u) {
        move->kind = DARAN_MOVE_VELOCITY_RAMP;
        move->rate = param == 0.0f ? 0.0f : param; /* 0 holds the setpoint */
        return param >= 0.0f ? DARAN_OK : DARAN_ERR_OUT_OF_RANGE;
    }
    move->kind = DARAN_MOVE_VELOCITY;
    move->torque_nm = param;
    return DARAN_OK;
}

static daran_result_t torque_move(float torque, float param, uint32_t mode, daran_move_t *move)
{
    move->torque_nm = torque;
    if (mode == 1u) {
        move->kind = DARAN_MOVE_TORQUE;
        return DARAN_OK;
    }
    move->kind = DARAN_MOVE_TORQUE_RAMP;
    move->rate = param == 0.0f ? 0.0f : param; /* 0 holds the setpoint */
    return param >= 0.0f ? DARAN_OK : DARAN_ERR_OUT_OF_RANGE;
}

static daran_result_t cmd_v(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                            int count, unsigned motor)
{
    daran_move_t move;
    float vel, param = 0.0f;
    uint32_t mode = 1;
    (void)cmd;
    (void)motor;
    memset(&move, 0, sizeof move);
    daran_result_t result = parse_f32(tok[2], &vel);
    if (result == DARAN_OK && count > 3) {
        result = parse_f32(tok[3], &param);
    }
    if (result == DARAN_OK && count > 4) {
        result = parse_mode(tok[4], MODES_VELOCITY, &mode);
    }
    if (result == DARAN_OK) {
        result = velocity_move(vel, param, mode, &move);
    }
    return start_move(b, result, &move);
}

static daran_result_t cmd_c(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                            int count, unsigned motor)
{
    daran_move_t move;
    float torque, param = 0.0f;
    uint32_t mode = 1;
    (void)cmd;
    (void)motor;
    memset(&move, 0, sizeof move);
    daran_result_t result = parse_f32(tok[2], &torque);
    if (result == DARAN_OK && count > 3) {
        result = parse_f32(tok[3], &param);
    }
    if (result == DARAN_OK && count > 4) {
        result = parse_mode(tok[4], MODES_TORQUE, &mode);
    }
    if (result == DARAN_OK) {
        result = torque_move(torque, param, mode, &move);
    }
    return start_move(b, result, &move);
}

static daran_result_t cmd_d(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                            int count, unsigned motor)
{
    daran_move_t move;
    (void)cmd;
    (void)count;
    (void)motor;
    memset(&move, 0, sizeof move);
    move.kind = DARAN_MOVE_IMPEDANCE;
    daran_result_t result = parse_f32(tok[2], &move.pos_deg);
    if (result == DARAN_OK) {
        result = parse_f32(tok[3], &move.vel_rpm);
    }
    if (result == DARAN_OK) {
        result = parse_f32(tok[4], &move.torque_nm);
    }
    if (result == DARAN_OK) {
        result = parse_non_negative(tok[5], &move.kp);
    }
    if (result == DARAN_OK) {
        result = parse_non_negative(tok[6], &move.kd);
    }
    return start_move(b, result, &move);
}

/* ---- multi-motor ------------------------------------------------------------ */

static daran_result_t cmd_ms(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                             int count, unsigned motor)
{
    float values[3];
    (void)cmd;
    (void)count;
    (void)motor;
    for (int i = 0; i < 3; i++) {
        daran_result_t result = parse_f32(tok[2 + i], &values[i]);
        if (result != DARAN_OK) {
            return result;
        }
    }
    memcpy(b->preset, values, sizeof values);
    b->has_preset = 1;
    return DARAN_OK;
}

/* Returns DARAN_OK with *go 0 for a broadcast start that finds no preset. */
static daran_result_t begin_start(baseline_t *b, char tok[][TOKEN_BYTES], int has_rel,
                                  unsigned motor, uint32_t *rel, int *go)
{
    *go = 0;
    *rel = 0;
    if (has_rel) {
        daran_result_t result = parse_mode(tok[2], MODES_START, rel);
        if (result != DARAN_OK) {
            return result;
        }
    }
    if (motor == 0 && !b->has_preset) {
        return DARAN_OK;
    }
    daran_result_t result = motion_allowed(b);
    if (result != DARAN_OK) {
        return result;
    }
    if (!b->has_preset) {
        return DARAN_ERR_NO_PRESET;
    }
    *go = 1;
    return DARAN_OK;
}

static daran_result_t finish_start(baseline_t *b, const daran_move_t *move)
{
    daran_result_t result = start_move(b, DARAN_OK, move);
    if (result == DARAN_OK) {
        b->has_preset = 0;
    }
    return result;
}

static daran_result_t start_target(baseline_t *b, uint32_t rel, float *base, float *target)
{
    daran_value_t value;
    daran_result_t result = get(b, DARAN_PROP_POS_SETPOINT, &value);
    if (result != DARAN_OK) {
        return result;
    }
    *base = value.f32;
    *target = rel ? *base + b->preset[0] : b->preset[0];
    return isfinite(*target) ? DARAN_OK : DARAN_ERR_OUT_OF_RANGE;
}

static daran_result_t cmd_mt(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                             int count, unsigned motor)
{
    uint32_t rel;
    int go;
    float base;
    daran_move_t move;
    (void)cmd;
    (void)count;
    daran_result_t result = begin_start(b, tok, 1, motor, &rel, &go);
    if (result != DARAN_OK || !go) {
        return result;
    }
    memset(&move, 0, sizeof move);
    move.kind = DARAN_MOVE_FILTERED_POSITION;
    if (!(b->preset[2] >= 0.0f)) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    if (b->preset[2] != 0.0f) { /* bandwidth 0: keep the current one */
        move.given = DARAN_GIVEN_RATE;
        move.rate = b->preset[2];
    }
    result = start_target(b, rel, &base, &move.pos_deg);
    if (result != DARAN_OK) {
        return result;
    }
    return finish_start(b, &move);
}

static daran_result_t cmd_mq(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                             int count, unsigned motor)
{
    uint32_t rel;
    int go;
    float base;
    daran_move_t move;
    (void)cmd;
    (void)count;
    daran_result_t result = begin_start(b, tok, 1, motor, &rel, &go);
    if (result != DARAN_OK || !go) {
        return result;
    }
    float t = b->preset[1];
    float acc = b->preset[2];
    if (!(t >= 0.0f) || !(acc >= 0.0f)) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    memset(&move, 0, sizeof move);
    move.kind = DARAN_MOVE_TRAPEZOID;
    move.given = DARAN_GIVEN_VEL | DARAN_GIVEN_RATE;
    result = start_target(b, rel, &base, &move.pos_deg);
    if (result != DARAN_OK) {
        return result;
    }
    /* traj_mode 2: an S-curve, each ramp 2v/a long */
    daran_value_t mode;
    result = get(b, DARAN_PROP_TRAJ_MODE, &mode);
    if (result != DARAN_OK && result != DARAN_ERR_INVALID_PROPERTY) {
        return result;
    }
    float ramps = result == DARAN_OK && mode.u32 == 2u ? 8.0f : 4.0f;
    /* Same plan as the spec: cruise v with (ramps/4) v^2 - a t v + a d = 0 (deg, s). */
    float d = fabsf(move.pos_deg - base);
    float a = acc * 6.0f;
    if (d == 0.0f) {
        move.given = 0; /* nothing to plan: the drive keeps its settings */
        return finish_start(b, &move);
    }
    if (t == 0.0f || a == 0.0f) {
        return DARAN_ERR_TRAJECTORY_INFEASIBLE;
    }
    float at = a * t;
    float disc = at * at - ramps * a * d;
    if (!isfinite(disc)) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    if (disc >= 0.0f) {
        float v = 2.0f * a * d / (at + sqrtf(disc));
        move.vel_rpm = v / 6.0f;
        move.rate = a / 6.0f;
    } else {
        /* protocol.md 10.5: the time is kept, within the velocity limit
         * unless the duration is the least one pushed a hair short */
        move.vel_rpm = 2.0f * d / t / 6.0f;
        move.rate = ramps * d / (t * t) / 6.0f;
        if (-disc > 1e-4f * at * at) {
            daran_value_t limit;
            result = get(b, DARAN_PROP_SHAFT_VEL_LIMIT, &limit);
            if (result == DARAN_OK && 2.0f * d / t > limit.f32 * 6.0f) {
                result = DARAN_ERR_TRAJECTORY_INFEASIBLE;
            }
            if (result != DARAN_OK && result != DARAN_ERR_INVALID_PROPERTY) {
                return result;
            }
        }
    }
    return finish_start(b, &move);
}

static daran_result_t cmd_mp(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                             int count, unsigned motor)
{
    uint32_t rel;
    int go;
    float base;
    daran_move_t move;
    (void)cmd;
    (void)count;
    daran_result_t result = begin_start(b, tok, 1, motor, &rel, &go);
    if (result != DARAN_OK || !go) {
        return result;
    }
    memset(&move, 0, sizeof move);
    move.kind = DARAN_MOVE_PASSTHROUGH;
    result = start_target(b, rel, &base, &move.pos_deg);
    if (result != DARAN_OK) {
        return result;
    }
    move.vel_rpm = b->preset[1];
    move.torque_nm = b->preset[2];
    return finish_start(b, &move);
}

static daran_result_t preset_mode(float value, uint32_t allowed, uint32_t *mode)
{
    for (uint32_t m = 0; m < 32u; m++) {
        if (((allowed >> m) & 1u) && value == (float)m) {
            *mode = m;
            return DARAN_OK;
        }
    }
    return DARAN_ERR_INVALID_MODE;
}

static daran_result_t cmd_mv(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                             int count, unsigned motor)
{
    uint32_t unused, mode;
    int go;
    daran_move_t move;
    (void)cmd;
    (void)count;
    daran_result_t result = begin_start(b, tok, 0, motor, &unused, &go);
    if (result != DARAN_OK || !go) {
        return result;
    }
    memset(&move, 0, sizeof move);
    result = preset_mode(b->preset[2], MODES_VELOCITY, &mode);
    if (result == DARAN_OK) {
        result = velocity_move(b->preset[0], b->preset[1], mode, &move);
    }
    return result != DARAN_OK ? result : finish_start(b, &move);
}

static daran_result_t cmd_mc(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                             int count, unsigned motor)
{
    uint32_t unused, mode;
    int go;
    daran_move_t move;
    (void)cmd;
    (void)count;
    daran_result_t result = begin_start(b, tok, 0, motor, &unused, &go);
    if (result != DARAN_OK || !go) {
        return result;
    }
    memset(&move, 0, sizeof move);
    result = preset_mode(b->preset[2], MODES_TORQUE, &mode);
    if (result == DARAN_OK) {
        result = torque_move(b->preset[0], b->preset[1], mode, &move);
    }
    return result != DARAN_OK ? result : finish_start(b, &move);
}

/* ---- properties ---------------------------------------------------------- */

/* Kept out of line so the benchmark can count it on its own. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
daran_prop_t baseline_find_property(int scope, const char *name)
{
    for (size_t i = 0; i < PROPERTY_COUNT; i++) {
        if (properties[i].scope == scope && strcmp(properties[i].name, name) == 0) {
            return properties[i].prop;
        }
    }
    return DARAN_PROP_COUNT;
}

static const bl_property_t *property_row(daran_prop_t prop)
{
    for (size_t i = 0; i < PROPERTY_COUNT; i++) {
        if (properties[i].prop == prop) {
            return &properties[i];
        }
    }
    return NULL;
}

static void format_value(char *out, size_t size, int type, daran_value_t value)
{
    switch (type) {
    case T_F32:
        snprintf(out, size, "%f", (double)value.f32);
        break;
    case T_U64:
        snprintf(out, size, "%llu", (unsigned long long)value.u64);
        break;
    case T_S32:
        snprintf(out, size, "%ld", (long)value.s32);
        break;
    default:
        snprintf(out, size, "%lu", (unsigned long)value.u32);
        break;
    }
}

static daran_result_t cmd_r(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                            int count, unsigned motor)
{
    (void)cmd;
    (void)count;
    (void)motor;
    daran_prop_t prop = (daran_prop_t)b->prop; /* found by the dispatcher */
    (void)tok;
    daran_value_t value;
    daran_result_t result = get(b, prop, &value);
    if (result != DARAN_OK) {
        return result;
    }
    char text[48];
    format_value(text, sizeof text, property_row(prop)->type, value);
    reply(b, "%s", text);
    return DARAN_OK;
}

static int integer_in_range(int range, double value)
{
    switch (range) {
    case R_NON_NEGATIVE:
        return value >= 0.0;
    case R_POSITIVE:
        return value > 0.0;
    case R_NON_POSITIVE:
        return value <= 0.0;
    case R_BOOL:
        return value == 0.0 || value == 1.0;
    case R_ZERO:
        return value == 0.0;
    case R_NODE_ID:
        return value >= 1.0 && value <= MOTOR_ID_MAX;
    case R_UART_BAUD:
        return value == 9600.0 || value == 19200.0 || value == 38400.0 || value == 57600.0 ||
               value == 115200.0;
    case R_CAN_BAUD:
        return value == 125000.0 || value == 250000.0 || value == 500000.0 || value == 1000000.0;
    case R_CAN_PROTOCOL:
        return value == 0.0 || value == 1.0;
    case R_AXIS_STATE:
        return value == DARAN_STATE_IDLE || value == DARAN_STATE_CLOSED_LOOP;
    case R_CONTROL_MODE:
        return value >= 1.0 && value <= 3.0;
    case R_INPUT_MODE:
        return value == 1.0 || value == 2.0 || value == 3.0 || value == 5.0 || value == 6.0 ||
               value == 9.0;
    case R_TRAJ_MODE:
        return value == 1.0 || value == 2.0;
    case R_DIRECTION:
        return value == -1.0 || value == 1.0;
    case R_MOTOR_TYPE:
        return value == 0.0 || value == 2.0 || value == 3.0;
    case R_POLE_PAIRS:
        return value >= 1.0 && value <= 128.0;
    case R_TELEMETRY:
        return value >= 0.0 && value <= 511.0; /* every set fits the default reply */
    default:
        return 1;
    }
}

static daran_result_t cmd_w(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                            int count, unsigned motor)
{
    (void)cmd;
    (void)count;
    (void)motor;
    daran_prop_t prop = (daran_prop_t)b->prop;
    const bl_property_t *row = property_row(prop);
    daran_value_t value;
    daran_result_t result;
    if (row->access != ACC_RW) {
        return DARAN_ERR_READ_ONLY;
    }
    value.u64 = 0;
    if (row->type == T_F32) {
        result = parse_f32(tok[2], &value.f32);
        if (result == DARAN_OK && ((row->range == R_POSITIVE && !(value.f32 > 0.0f)) ||
                                   (row->range == R_NON_NEGATIVE && !(value.f32 >= 0.0f)) ||
                                   (row->range == R_NON_POSITIVE && !(value.f32 <= 0.0f)))) {
            result = DARAN_ERR_OUT_OF_RANGE;
        }
    } else {
        double integer;
        result = parse_integer(tok[2], &integer);
        if (result == DARAN_OK) {
            if (row->type == T_S32) {
                if (integer < -2147483648.0 || integer > 2147483647.0 ||
                    !integer_in_range(row->range, integer)) {
                    result = DARAN_ERR_OUT_OF_RANGE;
                } else {
                    value.s32 = (int32_t)integer;
                }
            } else if (integer < 0.0 || (row->type != T_U64 && integer > 4294967295.0) ||
                       (row->type != T_U64 && !integer_in_range(row->range, integer))) {
                result = DARAN_ERR_OUT_OF_RANGE;
            } else if (row->type == T_U64) {
                value.u64 = (uint64_t)integer;
            } else {
                value.u32 = (uint32_t)integer;
            }
        }
    }
    if (result != DARAN_OK) {
        return result;
    }
    if (prop == DARAN_PROP_REQUESTED_STATE && value.u32 == DARAN_STATE_CLOSED_LOOP) {
        result = motion_allowed(b);
        if (result != DARAN_OK && result != DARAN_ERR_MOTOR_IDLE) {
            return result;
        }
    }
    result = b->hal->set(b->hal_ctx, prop, value);
    return (unsigned)result < DARAN_RESULT_COUNT ? result : DARAN_ERR_MOTOR_FAULT;
}

/* ---- queries and actions ------------------------------------------------------- */

static daran_result_t reply_two(baseline_t *b, daran_prop_t first, daran_prop_t second)
{
    daran_value_t one, two;
    daran_result_t result = get(b, first, &one);
    if (result == DARAN_OK) {
        result = get(b, second, &two);
    }
    if (result == DARAN_OK) {
        reply(b, "%f %f", (double)one.f32, (double)two.f32);
    }
    return result;
}

static daran_result_t cmd_f(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                            int count, unsigned motor)
{
    (void)cmd;
    (void)tok;
    (void)count;
    (void)motor;
    return reply_two(b, DARAN_PROP_POS_ESTIMATE, DARAN_PROP_VEL_ESTIMATE);
}

static daran_result_t cmd_g(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                            int count, unsigned motor)
{
    (void)cmd;
    (void)tok;
    (void)count;
    (void)motor;
    return reply_two(b, DARAN_PROP_VBUS_VOLTAGE, DARAN_PROP_IQ_MEASURED);
}

static daran_result_t cmd_i(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                            int count, unsigned motor)
{
    daran_value_t fw, hw, serial;
    (void)cmd;
    (void)tok;
    (void)count;
    (void)motor;
    daran_result_t result = get(b, DARAN_PROP_FW_VERSION, &fw);
    if (result == DARAN_OK) {
        result = get(b, DARAN_PROP_HW_VERSION, &hw);
    }
    if (result == DARAN_OK) {
        result = get(b, DARAN_PROP_SERIAL_NUMBER, &serial);
    }
    if (result == DARAN_OK) {
        reply(b, "%lu %lu %llu", (unsigned long)fw.u32, (unsigned long)hw.u32,
              (unsigned long long)serial.u64);
    }
    return result;
}

static daran_result_t cmd_e(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                            int count, unsigned motor)
{
    /* The error registers, one line each, as the vendor's decoder reads them. */
    static const struct {
        const char *name;
        daran_prop_t prop;
    } registers[] = {
        {"axis", DARAN_PROP_AXIS_ERROR},
        {"motor", DARAN_PROP_MOTOR_ERROR},
        {"encoder", DARAN_PROP_ENCODER_ERROR},
        {"controller", DARAN_PROP_CONTROLLER_ERROR},
        {"fet_thermistor", DARAN_PROP_FET_THERMISTOR_ERROR},
        {"motor_thermistor", DARAN_PROP_MOTOR_THERMISTOR_ERROR},
        {"can", DARAN_PROP_CAN_ERROR},
    };
    enum { REGISTERS = sizeof registers / sizeof registers[0] };
    unsigned long values[REGISTERS];
    (void)cmd;
    (void)tok;
    (void)count;
    (void)motor;
    for (size_t i = 0; i < REGISTERS; i++) {
        daran_value_t value;
        daran_result_t result = get(b, registers[i].prop, &value);
        if (result == DARAN_ERR_INVALID_PROPERTY) {
            value.u32 = 0; /* a register the port does not have reads as 0 */
        } else if (result != DARAN_OK) {
            return result;
        }
        values[i] = (unsigned long)value.u32;
    }
    for (size_t i = 0; i < REGISTERS; i++) {
        reply(b, "%s: %lu", registers[i].name, values[i]);
    }
    return DARAN_OK;
}

static daran_result_t cmd_h(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                            int count, unsigned motor);

static daran_result_t cmd_action(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                                 int count, unsigned motor)
{
    (void)tok;
    (void)count;
    (void)motor;
    daran_result_t result = b->hal->action(b->hal_ctx, (daran_action_t)cmd->arg);
    if ((unsigned)result >= DARAN_RESULT_COUNT) {
        result = DARAN_ERR_MOTOR_FAULT;
    }
    if (result == DARAN_OK && cmd->arg == DARAN_ACTION_REBOOT) {
        b->has_preset = 0;
    }
    return result;
}

static const bl_command_t commands[] = {
    {"t", 3, 5, 0, 0, 0, cmd_t, "id pos [vel] [bw]"},
    {"q", 3, 5, 0, 0, 0, cmd_q, "id pos [vel] [acc]"},
    {"p", 3, 5, 0, 0, 0, cmd_p, "id pos [vel_ff] [torque_ff]"},
    {"v", 3, 5, 0, 0, 0, cmd_v, "id vel [param] [mode]"},
    {"c", 3, 5, 0, 0, 0, cmd_c, "id torque [param] [mode]"},
    {"d", 7, 7, 0, 0, 0, cmd_d, "id pdes vdes tff kp kd"},
    {"ms", 5, 5, 0, 0, 0, cmd_ms, "id p1 p2 p3"},
    {"mt", 3, 3, 0, 0, 0, cmd_mt, "id rel"},
    {"mq", 3, 3, 0, 0, 0, cmd_mq, "id rel"},
    {"mp", 3, 3, 0, 0, 0, cmd_mp, "id rel"},
    {"mv", 2, 2, 0, 0, 0, cmd_mv, "id"},
    {"mc", 2, 2, 0, 0, 0, cmd_mc, "id"},
    {"r", 2, 3, 1, 1, 0, cmd_r, "path [id]"},
    {"w", 3, 4, 0, 1, 0, cmd_w, "path value [id]"},
    {"ss", 2, 2, 0, 0, DARAN_ACTION_SAVE_CONFIG, cmd_action, "id"},
    {"se", 2, 2, 0, 0, DARAN_ACTION_ERASE_CONFIG, cmd_action, "id"},
    {"sr", 2, 2, 0, 0, DARAN_ACTION_REBOOT, cmd_action, "id"},
    {"sc", 2, 2, 0, 0, DARAN_ACTION_CLEAR_ERRORS, cmd_action, "id"},
    {"sz", 2, 2, 0, 0, DARAN_ACTION_SET_ZERO, cmd_action, "id"},
    {"st", 2, 2, 0, 0, DARAN_ACTION_ESTOP, cmd_action, "id"},
    {"h", 2, 2, 1, 0, 0, cmd_h, "id"},
    {"f", 2, 2, 1, 0, 0, cmd_f, "id"},
    {"g", 2, 2, 1, 0, 0, cmd_g, "id"},
    {"i", 2, 2, 1, 0, 0, cmd_i, "id"},
    {"e", 2, 2, 1, 0, 0, cmd_e, "id"},
    {"u", 2, 2, 0, 0, DARAN_ACTION_FEED_WATCHDOG, cmd_action, "id"},
};
#define COMMAND_COUNT (sizeof commands / sizeof commands[0])

static daran_result_t cmd_h(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                            int count, unsigned motor)
{
    (void)cmd;
    (void)tok;
    (void)count;
    (void)motor;
    for (size_t i = 0; i < COMMAND_COUNT; i++) {
        reply(b, "%s %s", commands[i].word, commands[i].help);
    }
    return DARAN_OK;
}

/* ---- the line ------------------------------------------------------------- */

void baseline_init(baseline_t *b, const daran_hal_t *hal, void *hal_ctx, baseline_write_fn write,
                   void *write_ctx)
{
    memset(b, 0, sizeof *b);
    b->hal = hal;
    b->hal_ctx = hal_ctx;
    b->write = write;
    b->write_ctx = write_ctx;
}

/* r/w: the id from "axisN." or the trailing field, then the field count,
 * then the property (spec section 8, D9). */
static daran_result_t address_path(baseline_t *b, const bl_command_t *cmd, char tok[][TOKEN_BYTES],
                                   int count, unsigned *motor, int *count_ok, int *scope,
                                   char **name)
{
    char *path = tok[1];
    char *dot = strchr(path, '.');
    (void)b;
    if (strncmp(path, "axis", 4) == 0 && dot != NULL && dot - path >= 4) {
        char number[TOKEN_BYTES];
        size_t n = (size_t)(dot - path) - 4u;
        memcpy(number, path + 4, n);
        number[n] = '\0';
        *scope = SCOPE_AXIS_;
        *name = dot + 1;
        *count_ok = count == cmd->min_fields;
        return parse_motor(number, motor);
    }
    *scope = SCOPE_SYSTEM_;
    *name = path;
    *count_ok = 1;
    if (count == cmd->min_fields) {
        *motor = 0;
        return DARAN_OK;
    }
    if (count == cmd->max_fields) {
        return parse_motor(tok[cmd->max_fields - 1], motor);
    }
    return DARAN_ERR_INVALID_FORMAT;
}

static daran_result_t dispatch(baseline_t *b, char *payload)
{
    static char tok[FIELDS_MAX][TOKEN_BYTES];
    int count = sscanf(payload, "%128s %128s %128s %128s %128s %128s %128s %128s", tok[0], tok[1],
                       tok[2], tok[3], tok[4], tok[5], tok[6], tok[7]);
    if (count <= 0) {
        return DARAN_ERR_UNKNOWN_COMMAND;
    }
    if (count == FIELDS_MAX) {
        /* sscanf stops at eight; a ninth field still makes the count wrong. */
        char extra[TOKEN_BYTES];
        if (sscanf(payload, "%*s %*s %*s %*s %*s %*s %*s %*s %128s", extra) == 1) {
            count = FIELDS_MAX + 1;
        }
    }
    for (char *p = tok[0]; *p != '\0'; p++) {
        *p = (char)tolower((unsigned char)*p);
    }
    const bl_command_t *cmd = NULL;
    for (size_t i = 0; i < COMMAND_COUNT; i++) {
        if (strcmp(commands[i].word, tok[0]) == 0) {
            cmd = &commands[i];
            break;
        }
    }
    if (cmd == NULL) {
        return DARAN_ERR_UNKNOWN_COMMAND;
    }

    unsigned motor = 0;
    int count_ok;
    int scope = SCOPE_SYSTEM_;
    char *name = NULL;
    daran_result_t result;
    if (cmd->is_path) {
        if (count < 2) {
            return DARAN_ERR_INVALID_FORMAT;
        }
        result = address_path(b, cmd, tok, count, &motor, &count_ok, &scope, &name);
    } else if (count < 2) {
        return DARAN_ERR_INVALID_FORMAT;
    } else {
        result = parse_motor(tok[1], &motor);
        count_ok = count >= cmd->min_fields && count <= cmd->max_fields;
    }
    if (result != DARAN_OK) {
        return result;
    }
    daran_value_t id;
    result = get(b, DARAN_PROP_CAN_NODE_ID, &id);
    if (result != DARAN_OK) {
        return result;
    }
    if (motor != 0 && motor != id.u32) {
        return DARAN_OK; /* another drive's line: no reply, no effect */
    }
    if (!count_ok) {
        return DARAN_ERR_INVALID_FORMAT;
    }
    if (cmd->is_path) {
        daran_prop_t prop = baseline_find_property(scope, name);
        if (prop == DARAN_PROP_COUNT) {
            return DARAN_ERR_INVALID_PROPERTY;
        }
        b->prop = (int)prop;
    }
    return cmd->handler(b, cmd, tok, count, motor);
}

daran_result_t baseline_process_line(baseline_t *b, const char *line)
{
    char buf[LINE_MAX_BYTES + 1];
    size_t len = strlen(line);
    b->reply_checksum = 0;
    if (len > LINE_MAX_BYTES) {
        return reply_error(b, DARAN_ERR_LINE_TOO_LONG, 0);
    }
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)line[i];
        if (!(c >= 0x20 && c <= 0x7e) && c != '\t' && c != '\r') {
            return reply_error(b, DARAN_ERR_INVALID_CHARACTER, 0);
        }
    }
    if (strspn(line, " \t\r") == len) {
        return DARAN_OK;
    }
    memcpy(buf, line, len + 1);

    char *star = strchr(buf, '*');
    if (star != NULL) {
        unsigned value = 0;
        int used = 0;
        if (!isdigit((unsigned char)star[1]) || sscanf(star + 1, "%u%n", &value, &used) != 1 ||
            used > 3 || value > 255 || star[1 + used + strspn(star + 1 + used, " \t\r")] != '\0') {
            return reply_error(b, DARAN_ERR_INVALID_CHECKSUM, 0);
        }
        b->reply_checksum = 1;
        if (value != xor_bytes(buf, (size_t)(star - buf))) {
            return reply_error(b, DARAN_ERR_CHECKSUM_MISMATCH, 1);
        }
        *star = '\0';
    }
    daran_result_t result = dispatch(b, buf);
    if (result != DARAN_OK) {
        reply_error(b, result, b->reply_checksum);
    }
    return result;
}
