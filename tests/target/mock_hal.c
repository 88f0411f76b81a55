/* The recording HAL of the on-target self-test. Log entries look like
 *   set UART_BAUDRATE 9600     move 0 10 0 0 25 0 0 g2     action 6
 * (move: kind pos vel torque rate kp kd, then the DARAN_GIVEN_ bits),
 * separated by "; ". Floats are written by the core's own shortest
 * formatter so that the log compares as text; s32 values with their sign.
 * A set is also stored, so a later line of the same case reads it back. */
#include "mock_hal.h"

#include <string.h>

#include "number.h"

#define PROP_NAME(id, path, scope, type, access, range, unit) #id,
static const char *const prop_names[DARAN_PROP_COUNT] = {DARAN_PROPERTY_LIST(PROP_NAME)};
#undef PROP_NAME

#define PROP_TYPE(id, path, scope, type, access, range, unit) DARAN_TYPE_##type,
static const unsigned char prop_type[DARAN_PROP_COUNT] = {DARAN_PROPERTY_LIST(PROP_TYPE)};
#undef PROP_TYPE

static void log_text(target_mock_t *m, const char *text, size_t len)
{
    if (len > TARGET_MOCK_LOG_MAX - 1u - m->log_len) {
        len = TARGET_MOCK_LOG_MAX - 1u - m->log_len;
    }
    memcpy(m->log + m->log_len, text, len);
    m->log_len += len;
    m->log[m->log_len] = '\0';
}

static void log_str(target_mock_t *m, const char *text)
{
    log_text(m, text, strlen(text));
}

static void log_f32(target_mock_t *m, float v)
{
    char buf[DARAN_F32_TEXT_MAX];
    log_str(m, " ");
    log_text(m, buf, daran_format_f32(v, buf));
}

static void log_u64(target_mock_t *m, uint64_t v)
{
    char buf[DARAN_U64_TEXT_MAX];
    log_str(m, " ");
    log_text(m, buf, daran_format_u64(v, buf));
}

static void log_begin(target_mock_t *m, const char *what)
{
    if (m->log_len > 0u) {
        log_str(m, "; ");
    }
    log_str(m, what);
}

static daran_result_t mock_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    const target_mock_t *m = ctx;
    *out = m->value[prop];
    return DARAN_OK;
}

static daran_result_t mock_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    target_mock_t *m = ctx;
    log_begin(m, "set ");
    log_str(m, prop_names[prop]);
    switch (prop_type[prop]) {
    case DARAN_TYPE_F32:
        log_f32(m, value.f32);
        break;
    case DARAN_TYPE_U64:
        log_u64(m, value.u64);
        break;
    case DARAN_TYPE_S32:
        if (value.s32 < 0) {
            log_str(m, " -");
            char buf[DARAN_U64_TEXT_MAX];
            log_text(m, buf, daran_format_u64((uint64_t)(-(int64_t)value.s32), buf));
        } else {
            log_u64(m, (uint64_t)value.s32);
        }
        break;
    default:
        log_u64(m, value.u32);
        break;
    }
    m->value[prop] = value;
    return DARAN_OK;
}

static daran_result_t mock_move(void *ctx, const daran_move_t *move)
{
    target_mock_t *m = ctx;
    log_begin(m, "move");
    log_u64(m, (uint64_t)move->kind);
    log_f32(m, move->pos_deg);
    log_f32(m, move->vel_rpm);
    log_f32(m, move->torque_nm);
    log_f32(m, move->rate);
    log_f32(m, move->kp);
    log_f32(m, move->kd);
    log_str(m, " g");
    log_text(m, &"0123"[move->given & 3u], 1u);
    return DARAN_OK;
}

static daran_result_t mock_action(void *ctx, daran_action_t action)
{
    target_mock_t *m = ctx;
    log_begin(m, "action");
    log_u64(m, (uint64_t)action);
    return DARAN_OK;
}

const daran_hal_t target_mock_hal = {mock_get, mock_set, mock_move, mock_action};

void target_mock_reset(target_mock_t *m)
{
    memset(m, 0, sizeof *m);
    m->value[DARAN_PROP_CAN_NODE_ID].u32 = 1u;
    m->value[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    m->value[DARAN_PROP_REQUESTED_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    m->value[DARAN_PROP_UART_BAUDRATE].u32 = 115200u;
    m->value[DARAN_PROP_VBUS_VOLTAGE].f32 = 24.0f;
    m->value[DARAN_PROP_IQ_MEASURED].f32 = 0.5f;
    m->value[DARAN_PROP_POS_ESTIMATE].f32 = 12.5f;
    m->value[DARAN_PROP_VEL_ESTIMATE].f32 = -3.0f;
    m->value[DARAN_PROP_POS_SETPOINT].f32 = 100.0f;
    m->value[DARAN_PROP_FW_VERSION].u32 = 100u;
    m->value[DARAN_PROP_HW_VERSION].u32 = 3u;
    m->value[DARAN_PROP_SERIAL_NUMBER].u64 = 2026000001u;
    m->value[DARAN_PROP_SHAFT_VEL_LIMIT].f32 = 300.0f;
    m->value[DARAN_PROP_TRAJ_MODE].u32 = 1u;
    m->value[DARAN_PROP_MOTOR_DIRECTION].s32 = 1;
    m->value[DARAN_PROP_ENCODER_POS_ABS].s32 = -16384;
    m->value[DARAN_PROP_ENCODER_TURN_ABS].s32 = INT32_MIN;
}
