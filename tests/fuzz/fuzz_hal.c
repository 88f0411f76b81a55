/* The recording HAL and reply checks shared by the fuzz harnesses (see
 * fuzz_hal.h). Written for the harnesses, independent of tests/unit's mock
 * (which needs Unity), so the harnesses link only the core. */
#include "fuzz_hal.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* What the core promises about each property, from the single list. */
typedef struct prop_rule {
    daran_prop_type_t type;
    bool writable;
    daran_range_t range;
} prop_rule_t;

#define FUZZ_RULE_(id, path, scope, type, access, range, unit, can) \
    {DARAN_TYPE_##type, FUZZ_ACCESS_##access, DARAN_RANGE_##range},
#define FUZZ_ACCESS_RO false
#define FUZZ_ACCESS_RW true
static const prop_rule_t rules[DARAN_PROP_COUNT] = {
    DARAN_PROPERTY_LIST(FUZZ_RULE_)
#ifdef DARAN_PORT_PROPERTY_LIST
    /* a port's own rows (fuzz_port: examples/port-brake/brake_options.h) */
    DARAN_PORT_PROPERTY_LIST(FUZZ_RULE_)
#endif
};
#undef FUZZ_RULE_

#ifdef DARAN_OMIT_PROPERTIES
/* The rows the port's options header leaves out: their paths answer
 * `invalid property`, so the core must never get or set them. */
#define FUZZ_OMIT_(id) [DARAN_PROP_##id] = true,
static const bool omitted[DARAN_PROP_COUNT] = {DARAN_OMIT_PROPERTIES(FUZZ_OMIT_)};
#undef FUZZ_OMIT_
#define FUZZ_OMITTED(prop) omitted[prop]
#else
#define FUZZ_OMITTED(prop) false
#endif

/* The phrases of protocol.md section 8, written out here rather than taken
 * from the core so that a wrong phrase in the core is caught. */
static const char *const phrases[] = {
    "unknown command", "invalid command format", "invalid motor", "invalid value",
    "value out of range", "invalid mode", "invalid property", "read only property",
    "invalid checksum", "checksum mismatch", "line too long", "invalid character",
    "no preset", "trajectory infeasible", "estop active", "motor fault", "motor idle",
    "updating", "not idle", "no update", "bad image",
    "no reply", "bus error", "not bridged",
};

void fuzz_fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("FUZZ INVARIANT VIOLATED: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    fflush(stderr);
    abort();
}

const char *fuzz_escape(const char *s, size_t len)
{
    static char buf[4 * 600 + 8];
    size_t o = 0;
    for (size_t i = 0; i < len && o + 5 < sizeof buf; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c == '\n') {
            buf[o++] = '\\';
            buf[o++] = 'n';
        } else if (c == '\\') {
            buf[o++] = '\\';
            buf[o++] = '\\';
        } else if (c >= 0x20 && c < 0x7f) {
            buf[o++] = (char)c;
        } else {
            o += (size_t)snprintf(buf + o, sizeof buf - o, "\\x%02x", c);
        }
    }
    buf[o] = '\0';
    return buf;
}

uint64_t fuzz_hash(uint64_t h, const void *data, size_t len)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < len; i++) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
    return h;
}

void fuzz_hal_init(fuzz_hal_t *h, uint32_t id)
{
    memset(h, 0, sizeof *h);
    h->hash = 1469598103934665603ull;
    for (int p = 0; p < DARAN_PROP_COUNT; p++) {
        if (rules[p].type == DARAN_TYPE_F32) {
            h->props[p].f32 = 1.0f;
        }
    }
    h->props[DARAN_PROP_CAN_NODE_ID].u32 = id;
    h->props[DARAN_PROP_UART_BAUDRATE].u32 = 115200u;
    h->props[DARAN_PROP_CAN_BAUD_RATE].u32 = 1000000u;
    h->props[DARAN_PROP_REQUESTED_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    h->props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    h->props[DARAN_PROP_FW_VERSION].u32 = 100u;
    h->props[DARAN_PROP_HW_VERSION].u32 = 3u;
    h->props[DARAN_PROP_SERIAL_NUMBER].u64 = 18446744073709551615ull;
    h->props[DARAN_PROP_VBUS_VOLTAGE].f32 = 24.0f;
    h->props[DARAN_PROP_POS_SETPOINT].f32 = -12.5f;
    h->props[DARAN_PROP_TRAJ_MODE].u32 = 1u;
    h->props[DARAN_PROP_CONTROL_MODE].u32 = 3u;
    h->props[DARAN_PROP_INPUT_MODE].u32 = 3u;
    h->props[DARAN_PROP_MOTOR_DIRECTION].s32 = -1;
    h->props[DARAN_PROP_POLE_PAIRS].s32 = 7;
    h->props[DARAN_PROP_ENCODER_CPR].s32 = 16384;
    h->props[DARAN_PROP_ENCODER_POS_ABS].s32 = INT32_MIN;
    h->props[DARAN_PROP_ENCODER_TURN_ABS].s32 = -1;
    h->props[DARAN_PROP_POS_ESTIMATE].f32 = 1.0e-7f;
    h->props[DARAN_PROP_VEL_ESTIMATE].f32 = -3.0e12f;
}

void fuzz_hal_clear(fuzz_hal_t *h)
{
    h->n_get = h->n_get_other = h->n_set = h->n_move = h->n_action = h->n_port = 0;
    h->failed = h->failed_was_last = h->get_failed = false;
    h->last_call = 0;
    h->out_len = 0;
    h->n_replies = h->n_error_replies = 0;
    h->n_forward = 0;
}

void fuzz_hal_arm(fuzz_hal_t *h, uint32_t nth, int result)
{
    h->fail_nth = nth;
    h->mutating_seen = 0;
    h->fail_result = result;
}

void fuzz_hal_arm_get(fuzz_hal_t *h, uint32_t nth, int result)
{
    h->fail_get_nth = nth;
    h->gets_seen = 0;
    h->fail_result = result;
}

size_t fuzz_hal_mutations(const fuzz_hal_t *h)
{
    return h->n_set + h->n_move + h->n_action + h->n_port;
}

/* Count a mutating call; true when the injection makes it fail. */
static bool mutating_call(fuzz_hal_t *h)
{
    if (h->fail_nth == 0u) {
        return false;
    }
    h->mutating_seen++;
    return h->mutating_seen == h->fail_nth;
}

/* Remember whether the HAL refused, so the harness can tell a HAL error
 * (which the core must answer, D26) from a validation error. */
static daran_result_t outcome(fuzz_hal_t *h, daran_result_t result)
{
    h->failed_was_last = result != DARAN_OK;
    if (result != DARAN_OK) {
        h->failed = true;
        h->fail_answer = ((int)result > 0 && result < DARAN_ERR_NO_REPLY)
                             ? result
                             : DARAN_ERR_MOTOR_FAULT;
    }
    return result;
}

static void interrupt(fuzz_hal_t *h)
{
    if (h->on_call != NULL) {
        h->on_call(h->on_call_ctx);
    }
}

daran_result_t fuzz_hal_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    fuzz_hal_t *h = ctx;
    interrupt(h);
    FUZZ_CHECK((int)prop >= 0 && prop < DARAN_PROP_COUNT, "get of property %d", (int)prop);
    FUZZ_CHECK(!FUZZ_OMITTED(prop), "get of property %d, which the port left out", (int)prop);
    h->n_get++;
    if (prop != DARAN_PROP_CAN_NODE_ID) {
        h->n_get_other++;
    }
    if (h->fail_get_nth != 0u && ++h->gets_seen == h->fail_get_nth) {
        h->get_failed = true;
        h->get_failed_prop = prop;
        return (daran_result_t)h->fail_result;
    }
    *out = h->props[prop];
    return DARAN_OK;
}

/* An integer of a set range: the values the range documents in
 * daran_properties.h, written out here rather than taken from the core. */
static bool integer_in_set(daran_range_t range, int64_t x)
{
    switch (range) {
    case DARAN_RANGE_UART_BAUD:
        return x == 9600 || x == 19200 || x == 38400 || x == 57600 || x == 115200;
    case DARAN_RANGE_CAN_BAUD:
        return x == 125000 || x == 250000 || x == 500000 || x == 1000000;
    case DARAN_RANGE_AXIS_STATE:
        return x == DARAN_STATE_IDLE || x == DARAN_STATE_CLOSED_LOOP;
    case DARAN_RANGE_INPUT_MODE:
        return x == 1 || x == 2 || x == 3 || x == 5 || x == 6 || x == 9;
    case DARAN_RANGE_DIRECTION:
        return x == -1 || x == 1;
    case DARAN_RANGE_MOTOR_TYPE:
        return x == 0 || x == 2 || x == 3;
    default:
        return false;
    }
}

/* Every range of daran_range_t for an integer (u32, s32, bool) value x. A
 * new range makes -Wswitch name this function until it is written here. */
static bool integer_in_range(daran_range_t range, int64_t x)
{
    switch (range) {
    case DARAN_RANGE_NONE:
        return true;
    case DARAN_RANGE_NON_NEGATIVE:
        return x >= 0;
    case DARAN_RANGE_POSITIVE:
        return x > 0;
    case DARAN_RANGE_NON_POSITIVE:
        return x <= 0;
    case DARAN_RANGE_BOOL:
        return x == 0 || x == 1;
    case DARAN_RANGE_ZERO:
        return x == 0;
    case DARAN_RANGE_NODE_ID:
        return x >= 1 && x <= DARAN_MOTOR_ID_MAX;
    case DARAN_RANGE_CAN_PROTOCOL:
        return x == 0 || x == 1;
    case DARAN_RANGE_CONTROL_MODE:
        return x >= 1 && x <= 3;
    case DARAN_RANGE_TRAJ_MODE:
        return x == 1 || x == 2;
    case DARAN_RANGE_POLE_PAIRS:
        return x >= 1 && x <= 128;
    case DARAN_RANGE_TELEMETRY:
        return x >= 0 && x <= 511; /* every set fits the default DARAN_REPLY_MAX */
    case DARAN_RANGE_UART_BAUD:
    case DARAN_RANGE_CAN_BAUD:
    case DARAN_RANGE_AXIS_STATE:
    case DARAN_RANGE_INPUT_MODE:
    case DARAN_RANGE_DIRECTION:
    case DARAN_RANGE_MOTOR_TYPE:
        return integer_in_set(range, x);
    case DARAN_RANGE_COUNT:
        return false;
    }
    return false;
}

/* What the core promises of every value it writes (daran_properties.h,
 * mirrored from src/ascii/commands_property.c's rules): finite floats within the
 * float ranges (the integer-only ranges put no bound on a float); integers
 * of the type within the range; u64 unbounded (serial numbers are
 * read-only). */
static bool value_in_range(daran_prop_t prop, daran_value_t v)
{
    const prop_rule_t *r = &rules[prop];
    switch (r->type) {
    case DARAN_TYPE_F32:
        if (!isfinite(v.f32)) {
            return false;
        }
        switch (r->range) {
        case DARAN_RANGE_NON_NEGATIVE: return v.f32 >= 0.0f;
        case DARAN_RANGE_POSITIVE: return v.f32 > 0.0f;
        case DARAN_RANGE_NON_POSITIVE: return v.f32 <= 0.0f;
        default: return true;
        }
    case DARAN_TYPE_U64:
        return true;
    case DARAN_TYPE_S32:
        return integer_in_range(r->range, (int64_t)v.s32);
    case DARAN_TYPE_BOOL:
        return v.u32 <= 1u && integer_in_range(r->range, (int64_t)v.u32);
    case DARAN_TYPE_U32:
        return integer_in_range(r->range, (int64_t)v.u32);
    }
    return false;
}

/* Any bit of axis0.error blocks motion (the NVM warning lives in
 * axis0.config_warnings and blocks nothing). */
static bool blocking_flags(const fuzz_hal_t *h)
{
    return h->props[DARAN_PROP_AXIS_ERROR].u32 != 0u;
}

daran_result_t fuzz_hal_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    fuzz_hal_t *h = ctx;
    interrupt(h);
    FUZZ_CHECK((int)prop >= 0 && prop < DARAN_PROP_COUNT, "set of property %d", (int)prop);
    FUZZ_CHECK(!FUZZ_OMITTED(prop), "set of property %d, which the port left out", (int)prop);
    FUZZ_CHECK(rules[prop].writable, "set of read-only property %d", (int)prop);
    FUZZ_CHECK(value_in_range(prop, value), "set of property %d out of range (bits %08x)",
               (int)prop, (unsigned)value.u32);
    h->n_set++;
    h->last_call = 's';
    h->last_set_prop = prop;
    h->last_set_value = value;
    uint32_t tag = 1u + (uint32_t)prop;
    h->hash = fuzz_hash(h->hash, &tag, sizeof tag);
    h->hash = fuzz_hash(h->hash, &value.u64, rules[prop].type == DARAN_TYPE_U64 ? 8u : 4u);
    if (mutating_call(h)) {
        return outcome(h, (daran_result_t)h->fail_result);
    }
    if (prop == DARAN_PROP_TELEMETRY_PERIOD) {
        h->period_writes++;
    }
    if (prop == DARAN_PROP_REQUESTED_STATE) {
        if (value.u32 == DARAN_STATE_CLOSED_LOOP && blocking_flags(h)) {
            return outcome(h, DARAN_ERR_MOTOR_FAULT); /* as a drive would */
        }
        h->props[DARAN_PROP_CURRENT_STATE] = value;
    }
    h->props[prop] = value;
    return outcome(h, DARAN_OK);
}

static bool finite_move(const daran_move_t *m)
{
    return isfinite(m->pos_deg) && isfinite(m->vel_rpm) && isfinite(m->torque_nm) &&
           isfinite(m->rate) && isfinite(m->kp) && isfinite(m->kd);
}

daran_result_t fuzz_hal_move(void *ctx, const daran_move_t *move)
{
    fuzz_hal_t *h = ctx;
    interrupt(h);
    FUZZ_CHECK(move->kind >= DARAN_MOVE_FILTERED_POSITION && move->kind <= DARAN_MOVE_IMPEDANCE,
               "move of kind %d", (int)move->kind);
    FUZZ_CHECK(finite_move(move), "move with a value that is not finite");
    FUZZ_CHECK(h->props[DARAN_PROP_CURRENT_STATE].u32 == DARAN_STATE_CLOSED_LOOP &&
                   !blocking_flags(h),
               "move while idle or with a blocking flag");
    /* daran_hal.h's table: zero rates are meaningful (spec 10.1) except a
     * filter bandwidth, which the core never passes as 0 (it clears
     * DARAN_GIVEN_RATE: "keep the current one"); a rate of 0 is +0, as it
     * becomes a property that reads back. */
    switch (move->kind) {
    case DARAN_MOVE_FILTERED_POSITION:
        FUZZ_CHECK((move->given & DARAN_GIVEN_RATE) == 0u || move->rate > 0.0f,
                   "t with a bandwidth <= 0");
        break;
    case DARAN_MOVE_TRAPEZOID:
        FUZZ_CHECK((move->given & DARAN_GIVEN_VEL) == 0u || move->vel_rpm > 0.0f,
                   "q with a cruise velocity <= 0");
        FUZZ_CHECK((move->given & DARAN_GIVEN_RATE) == 0u ||
                       (move->rate >= 0.0f && !signbit(move->rate)),
                   "q with an acceleration < 0 or -0");
        FUZZ_CHECK((move->given & DARAN_GIVEN_RATE) == 0u || move->rate > 0.0f ||
                       ((move->given & DARAN_GIVEN_VEL) == 0u && move->vel_rpm == 0.0f),
                   "q step (acceleration 0) with a cruise velocity");
        break;
    case DARAN_MOVE_VELOCITY_RAMP:
    case DARAN_MOVE_TORQUE_RAMP:
        FUZZ_CHECK(move->rate >= 0.0f && !signbit(move->rate), "ramp with a rate < 0 or -0");
        break;
    case DARAN_MOVE_IMPEDANCE:
        FUZZ_CHECK(move->kp >= 0.0f && move->kd >= 0.0f, "d with a negative gain");
        break;
    default:
        break;
    }
    h->n_move++;
    h->last_call = 'm';
    uint32_t tag = 1000u + (uint32_t)move->kind;
    h->hash = fuzz_hash(h->hash, &tag, sizeof tag);
    float v[6] = {move->pos_deg, move->vel_rpm, move->torque_nm, move->rate, move->kp, move->kd};
    h->hash = fuzz_hash(h->hash, v, sizeof v);
    h->hash = fuzz_hash(h->hash, &move->given, 1);
    if (mutating_call(h)) {
        return outcome(h, (daran_result_t)h->fail_result);
    }
    h->props[DARAN_PROP_INPUT_POS].f32 = move->pos_deg;
    return outcome(h, DARAN_OK);
}

daran_result_t fuzz_hal_action(void *ctx, daran_action_t action)
{
    fuzz_hal_t *h = ctx;
    interrupt(h);
    FUZZ_CHECK(action >= DARAN_ACTION_SAVE_CONFIG && action <= DARAN_ACTION_FEED_WATCHDOG,
               "action %d", (int)action);
    h->n_action++;
    h->last_call = 'a';
    h->last_action = action;
    uint32_t tag = 2000u + (uint32_t)action;
    h->hash = fuzz_hash(h->hash, &tag, sizeof tag);
    if (mutating_call(h)) {
        return outcome(h, (daran_result_t)h->fail_result);
    }
    switch (action) {
    case DARAN_ACTION_ESTOP:
        h->props[DARAN_PROP_AXIS_ERROR].u32 |= DARAN_FLAG_ESTOP;
        h->props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_IDLE;
        break;
    case DARAN_ACTION_CLEAR_ERRORS: {
        /* `sc` clears every error register and the warnings (spec 10.4) */
        static const daran_prop_t registers[] = {
            DARAN_PROP_AXIS_ERROR,           DARAN_PROP_MOTOR_ERROR,
            DARAN_PROP_ENCODER_ERROR,        DARAN_PROP_CONTROLLER_ERROR,
            DARAN_PROP_FET_THERMISTOR_ERROR, DARAN_PROP_MOTOR_THERMISTOR_ERROR,
            DARAN_PROP_CAN_ERROR,            DARAN_PROP_CONFIG_WARNINGS};
        for (size_t i = 0; i < sizeof registers / sizeof registers[0]; i++) {
            h->props[registers[i]].u32 = 0u;
        }
        break;
    }
    case DARAN_ACTION_SET_ZERO:
        h->props[DARAN_PROP_POS_SETPOINT].f32 = 0.0f;
        break;
    default:
        break;
    }
    return outcome(h, DARAN_OK);
}

daran_result_t fuzz_hal_port_call(fuzz_hal_t *h, uint32_t tag, const void *data, size_t len)
{
    interrupt(h);
    h->n_port++;
    h->last_call = 'p';
    uint32_t t = 5000u + tag;
    h->hash = fuzz_hash(h->hash, &t, sizeof t);
    h->hash = fuzz_hash(h->hash, data, len);
    if (mutating_call(h)) {
        return outcome(h, (daran_result_t)h->fail_result);
    }
    return outcome(h, DARAN_OK);
}


void fuzz_check_reply_line(const char *line, size_t len)
{
    FUZZ_CHECK(len >= 2u && len <= DARAN_REPLY_MAX, "reply of %zu bytes: \"%s\"", len,
               fuzz_escape(line, len));
    size_t end = len - 1u;
    FUZZ_CHECK(line[end] == '\n', "reply without a final line end: \"%s\"",
               fuzz_escape(line, len));
#if DARAN_REPLY_CRLF
    FUZZ_CHECK(end >= 1u && line[end - 1u] == '\r', "reply without CR LF");
    end--;
#endif
    for (size_t i = 0; i < end; i++) {
        unsigned char c = (unsigned char)line[i];
        FUZZ_CHECK(c >= 0x20 && c <= 0x7e, "reply byte 0x%02x at %zu: \"%s\"", c, i,
                   fuzz_escape(line, len));
    }
    /* An optional " *N" tail, N = XOR of everything before the '*'. */
    size_t payload = end;
    const char *star = memchr(line, '*', end);
    if (star != NULL) {
        size_t s = (size_t)(star - line);
        FUZZ_CHECK(s >= 2u && line[s - 1u] == ' ' && line[s - 2u] != ' ',
                   "reply checksum tail malformed: \"%s\"", fuzz_escape(line, len));
        unsigned n = 0;
        size_t digits = 0;
        for (size_t i = s + 1u; i < end; i++) {
            FUZZ_CHECK(line[i] >= '0' && line[i] <= '9' && digits < 3u,
                       "reply checksum tail malformed: \"%s\"", fuzz_escape(line, len));
            n = n * 10u + (unsigned)(line[i] - '0');
            digits++;
        }
        FUZZ_CHECK(digits >= 1u && n <= 255u && (digits == 1u || line[s + 1u] != '0'),
                   "reply checksum tail malformed: \"%s\"", fuzz_escape(line, len));
        unsigned x = 0;
        for (size_t i = 0; i < s; i++) {
            x ^= (unsigned char)line[i];
        }
        FUZZ_CHECK(x == n, "reply checksum %u, XOR is %u: \"%s\"", n, x,
                   fuzz_escape(line, len));
        payload = s - 1u;
    }
    FUZZ_CHECK(payload >= 1u && line[0] != ' ' && line[payload - 1u] != ' ',
               "reply payload empty or padded: \"%s\"", fuzz_escape(line, len));
    /* `e`: "name: value", a register name the vendor's decoder knows and a
     * decimal u32 (spec 10.4) - the only replies with a ':' but errors. */
    static const char *const registers[] = {"axis", "motor", "encoder", "controller",
                                            "fet_thermistor", "motor_thermistor", "can"};
    const char *colon = memchr(line, ':', payload);
    bool is_error = payload >= 7u && memcmp(line, "error: ", 7) == 0;
    if (colon != NULL && !is_error) {
        size_t name_len = (size_t)(colon - line);
        bool known = false;
        for (size_t i = 0; i < sizeof registers / sizeof registers[0]; i++) {
            known = known || (strlen(registers[i]) == name_len &&
                              memcmp(registers[i], line, name_len) == 0);
        }
        FUZZ_CHECK(known && payload >= name_len + 3u && colon[1] == ' ',
                   "reply looks like a malformed error or register: \"%s\"",
                   fuzz_escape(line, len));
        const char *number = colon + 2;
        size_t count = payload - name_len - 2u;
        FUZZ_CHECK(count == 1u || number[0] != '0', "register value with a leading zero: \"%s\"",
                   fuzz_escape(line, len));
        uint64_t value = 0;
        for (size_t i = 0; i < count; i++) {
            FUZZ_CHECK(number[i] >= '0' && number[i] <= '9' && i < 10u,
                       "register value malformed: \"%s\"", fuzz_escape(line, len));
            value = value * 10u + (uint64_t)(number[i] - '0');
        }
        FUZZ_CHECK(value <= UINT32_MAX, "register value beyond u32: \"%s\"",
                   fuzz_escape(line, len));
        return;
    }
    if (is_error) {
        bool known = false;
        for (size_t i = 0; i < sizeof phrases / sizeof phrases[0]; i++) {
            if (strlen(phrases[i]) == payload - 7u &&
                memcmp(phrases[i], line + 7, payload - 7u) == 0) {
                known = true;
            }
        }
        FUZZ_CHECK(known, "unknown error phrase: \"%s\"", fuzz_escape(line, len));
    }
}

void fuzz_write(void *ctx, const char *line, size_t len)
{
    fuzz_hal_t *h = ctx;
    interrupt(h);
    fuzz_check_reply_line(line, len);
    h->n_replies++;
    if (len >= 7u && memcmp(line, "error: ", 7) == 0) {
        h->n_error_replies++;
    }
    uint32_t tag = 3000u;
    h->hash = fuzz_hash(h->hash, &tag, sizeof tag);
    h->hash = fuzz_hash(h->hash, line, len);
    if (len <= sizeof h->out - h->out_len) {
        memcpy(h->out + h->out_len, line, len);
        h->out_len += len;
    }
}

void fuzz_forward(void *ctx, uint8_t id, const char *line, size_t len)
{
    fuzz_hal_t *h = ctx;
    FUZZ_CHECK(id <= DARAN_MOTOR_ID_MAX, "forward to id %u", id);
    FUZZ_CHECK(len <= DARAN_LINE_MAX, "forwarded line of %zu bytes", len);
    h->n_forward++;
    h->forward_id = id;
    h->forward_len = len;
    memcpy(h->forward_line, line, len);
    uint32_t tag = 4000u + id;
    h->hash = fuzz_hash(h->hash, &tag, sizeof tag);
    h->hash = fuzz_hash(h->hash, line, len);
}

const daran_hal_t fuzz_hal_fns = {FUZZ_HAL_FUNCTIONS, .write = fuzz_write};
const daran_hal_t fuzz_hal_forwarding = {FUZZ_HAL_FUNCTIONS, .write = fuzz_write,
                                         .forward = fuzz_forward};

void fuzz_bind(daran_drive_t *drive, fuzz_hal_t *h, bool forward)
{
    if (daran_init(drive, forward ? &fuzz_hal_forwarding : &fuzz_hal_fns, h) != DARAN_OK) {
        fuzz_fail("daran_init refused a complete HAL");
    }
}
