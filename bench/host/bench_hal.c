/* The benchmarks' trivial HAL (see bench_hal.h). It keeps just enough state
 * for the streams to run as on a drive: the id, the axis state and flags
 * that e-stop and clear-errors change, and the position a relative start
 * builds on. */
#include "bench_hal.h"

#include <string.h>

void bench_hal_reset(bench_hal_state_t *state, FILE *trace)
{
    memset(state, 0, sizeof *state);
    state->trace = trace;
    state->values[DARAN_PROP_CAN_NODE_ID].u32 = 1;
    state->values[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    state->values[DARAN_PROP_REQUESTED_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    state->values[DARAN_PROP_VBUS_VOLTAGE].f32 = 24.125f;
    state->values[DARAN_PROP_IQ_MEASURED].f32 = 0.75f;
    state->values[DARAN_PROP_FW_VERSION].u32 = 10203;
    state->values[DARAN_PROP_HW_VERSION].u32 = 3;
    state->values[DARAN_PROP_SERIAL_NUMBER].u64 = 123456789012345ull;
    state->values[DARAN_PROP_UART_BAUDRATE].u32 = 115200;
    state->values[DARAN_PROP_CAN_BAUD_RATE].u32 = 1000000;
    state->values[DARAN_PROP_POS_GAIN].f32 = 20.0f;
    state->values[DARAN_PROP_VEL_GAIN].f32 = 0.16f;
    state->values[DARAN_PROP_WATCHDOG_TIMEOUT].f32 = 0.5f;
    state->values[DARAN_PROP_FET_TEMPERATURE].f32 = 41.5f;
    state->values[DARAN_PROP_MOTOR_TEMPERATURE].f32 = 38.25f;
    state->values[DARAN_PROP_TRAJ_MODE].u32 = 1; /* trapezoids until a stream asks for S-curves */
}

static daran_result_t bench_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    const bench_hal_state_t *state = ctx;
    *out = state->values[prop];
    return DARAN_OK;
}

static daran_result_t bench_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    bench_hal_state_t *state = ctx;
    state->values[prop] = value;
    if (prop == DARAN_PROP_REQUESTED_STATE) {
        state->values[DARAN_PROP_CURRENT_STATE] = value;
    }
    if (state->trace != NULL) {
        fprintf(state->trace, "%lu set %d %.9g %llu\n", state->line, (int)prop,
                (double)value.f32, (unsigned long long)value.u64);
    }
    return DARAN_OK;
}

static daran_result_t bench_move(void *ctx, const daran_move_t *move)
{
    bench_hal_state_t *state = ctx;
    daran_value_t *v = state->values;
    switch (move->kind) {
    case DARAN_MOVE_FILTERED_POSITION:
    case DARAN_MOVE_TRAPEZOID:
    case DARAN_MOVE_PASSTHROUGH:
    case DARAN_MOVE_IMPEDANCE:
        v[DARAN_PROP_INPUT_POS].f32 = move->pos_deg;
        v[DARAN_PROP_POS_SETPOINT].f32 = move->pos_deg;
        v[DARAN_PROP_POS_ESTIMATE].f32 = move->pos_deg;
        break;
    default:
        v[DARAN_PROP_INPUT_VEL].f32 = move->vel_rpm;
        v[DARAN_PROP_VEL_ESTIMATE].f32 = move->vel_rpm;
        break;
    }
    if (state->trace != NULL) {
        fprintf(state->trace, "%lu move %d %u %.9g %.9g %.9g %.9g %.9g %.9g\n", state->line,
                (int)move->kind, (unsigned)move->given, (double)move->pos_deg,
                (double)move->vel_rpm, (double)move->torque_nm, (double)move->rate,
                (double)move->kp, (double)move->kd);
    }
    return DARAN_OK;
}

static daran_result_t bench_action(void *ctx, daran_action_t action)
{
    bench_hal_state_t *state = ctx;
    daran_value_t *v = state->values;
    switch (action) {
    case DARAN_ACTION_ESTOP:
        v[DARAN_PROP_AXIS_ERROR].u32 |= DARAN_FLAG_ESTOP;
        v[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_IDLE;
        break;
    case DARAN_ACTION_CLEAR_ERRORS:
        v[DARAN_PROP_AXIS_ERROR].u32 = 0;
        break;
    case DARAN_ACTION_SET_ZERO:
        v[DARAN_PROP_POS_SETPOINT].f32 = 0.0f;
        v[DARAN_PROP_POS_ESTIMATE].f32 = 0.0f;
        v[DARAN_PROP_INPUT_POS].f32 = 0.0f;
        break;
    default:
        break;
    }
    if (state->trace != NULL) {
        fprintf(state->trace, "%lu action %d\n", state->line, (int)action);
    }
    return DARAN_OK;
}

void bench_write(void *ctx, const char *text, size_t len)
{
    bench_hal_state_t *state = ctx;
    state->reply_bytes += len;
    if (state->trace != NULL) {
        /* the line without its end ("\n", or "\r\n" with DARAN_REPLY_CRLF) */
        size_t shown = len > 0 && text[len - 1] == '\n' ? len - 1 : len;
        if (shown > 0 && text[shown - 1] == '\r') {
            shown--;
        }
        fprintf(state->trace, "%lu reply %.*s\n", state->line, (int)shown, text);
    }
}

const daran_hal_t bench_hal = {.get = bench_get,
                               .set = bench_set,
                               .move = bench_move,
                               .action = bench_action,
                               .write = bench_write};
