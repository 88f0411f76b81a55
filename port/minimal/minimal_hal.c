/* A minimal, complete HAL: see minimal_hal.h and docs/porting.md. */
#include "minimal_hal.h"

#include <string.h>

void minimal_drive_init(minimal_drive_t *drive)
{
    memset(drive, 0, sizeof *drive);
    drive->props[DARAN_PROP_CAN_NODE_ID].u32 = 1;
    drive->props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    drive->props[DARAN_PROP_REQUESTED_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    drive->props[DARAN_PROP_VBUS_VOLTAGE].f32 = 24.0f;
    drive->props[DARAN_PROP_UART_BAUDRATE].u32 = 115200;
    drive->props[DARAN_PROP_CAN_BAUD_RATE].u32 = 1000000;
    drive->props[DARAN_PROP_INPUT_FILTER_BANDWIDTH].f32 = 20.0f;
    drive->props[DARAN_PROP_TORQUE_CONSTANT].f32 = 0.1f;
    drive->props[DARAN_PROP_FW_VERSION].u32 = 100;
    drive->props[DARAN_PROP_HW_VERSION].u32 = 1;
}

bool minimal_drive_take_move(minimal_drive_t *drive, daran_move_t *move)
{
    if (!drive->move_ready) {
        return false;
    }
    *move = drive->pending_move;
    drive->move_ready = 0;
    return true;
}

static daran_result_t get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    minimal_drive_t *drive = ctx;
    *out = drive->props[prop];
    return DARAN_OK;
}

static daran_result_t set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    minimal_drive_t *drive = ctx;
    drive->props[prop] = value;
    if (prop == DARAN_PROP_REQUESTED_STATE) {
        /* The core refused closed loop while a flag is set; here it just happens. */
        drive->props[DARAN_PROP_CURRENT_STATE] = value;
    }
    return DARAN_OK;
}

static daran_result_t move(void *ctx, const daran_move_t *request)
{
    minimal_drive_t *drive = ctx;
    daran_value_t *p = drive->props;
    /* The protocol promises that `r` reads a command's targets back at once. */
    switch (request->kind) {
    case DARAN_MOVE_FILTERED_POSITION:
    case DARAN_MOVE_TRAPEZOID:
        p[DARAN_PROP_INPUT_POS].f32 = request->pos_deg;
        if (request->kind == DARAN_MOVE_FILTERED_POSITION && (request->given & DARAN_GIVEN_RATE)) {
            p[DARAN_PROP_INPUT_FILTER_BANDWIDTH].f32 = request->rate;
        }
        break;
    case DARAN_MOVE_PASSTHROUGH:
    case DARAN_MOVE_IMPEDANCE:
        p[DARAN_PROP_INPUT_POS].f32 = request->pos_deg;
        p[DARAN_PROP_INPUT_VEL].f32 = request->vel_rpm;
        p[DARAN_PROP_INPUT_TORQUE].f32 = request->torque_nm;
        break;
    case DARAN_MOVE_VELOCITY:
        p[DARAN_PROP_INPUT_VEL].f32 = request->vel_rpm;
        p[DARAN_PROP_INPUT_TORQUE].f32 = request->torque_nm;
        break;
    case DARAN_MOVE_VELOCITY_RAMP:
        p[DARAN_PROP_INPUT_VEL].f32 = request->vel_rpm;
        p[DARAN_PROP_VEL_RAMP_RATE].f32 = request->rate;
        break;
    case DARAN_MOVE_TORQUE:
        p[DARAN_PROP_INPUT_TORQUE].f32 = request->torque_nm;
        break;
    case DARAN_MOVE_TORQUE_RAMP:
        p[DARAN_PROP_INPUT_TORQUE].f32 = request->torque_nm;
        p[DARAN_PROP_TORQUE_RAMP_RATE].f32 = request->rate;
        break;
    default:
        return DARAN_ERR_INVALID_MODE; /* a kind this drive does not know: refuse, change nothing */
    }
    /* Hand the move to the control loop. A newer move replaces one not yet
     * taken: the control loop only ever wants the latest target. */
    drive->move_ready = 0;
    drive->pending_move = *request;
    drive->move_ready = 1;
    return DARAN_OK;
}

static daran_result_t action(void *ctx, daran_action_t which)
{
    minimal_drive_t *drive = ctx;
    daran_value_t *p = drive->props;
    switch (which) {
    case DARAN_ACTION_SAVE_CONFIG:
        drive->saved_config_writes++;
        return DARAN_OK;
    case DARAN_ACTION_ESTOP:
        p[DARAN_PROP_AXIS_ERROR].u32 |= DARAN_FLAG_ESTOP;
        p[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_IDLE;
        return DARAN_OK;
    case DARAN_ACTION_CLEAR_ERRORS:
        p[DARAN_PROP_AXIS_ERROR].u32 = 0;
        return DARAN_OK;
    case DARAN_ACTION_SET_ZERO:
        p[DARAN_PROP_INPUT_POS].f32 -= p[DARAN_PROP_POS_ESTIMATE].f32;
        p[DARAN_PROP_POS_SETPOINT].f32 -= p[DARAN_PROP_POS_ESTIMATE].f32;
        p[DARAN_PROP_POS_ESTIMATE].f32 = 0.0f;
        return DARAN_OK;
    case DARAN_ACTION_ERASE_CONFIG:
    case DARAN_ACTION_REBOOT:
    case DARAN_ACTION_FEED_WATCHDOG:
        return DARAN_OK;
    default:
        return DARAN_ERR_MOTOR_FAULT;
    }
}

const daran_hal_t minimal_hal = {get, set, move, action};
