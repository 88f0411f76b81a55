/* The ACME X1's HAL (acme_hal.h). */
#include "acme_hal.h"
#include "acme_can.h"

#include <string.h>

/* State, targets, measurements and error registers live in the drive, not
 * in flash: a reboot starts in closed loop with no error. */
static bool is_saved_setting(daran_prop_t prop)
{
    switch (prop) {
    case DARAN_PROP_CURRENT_STATE:
    case DARAN_PROP_REQUESTED_STATE:
    case DARAN_PROP_AXIS_ERROR:
    case DARAN_PROP_MOTOR_ERROR:
    case DARAN_PROP_ENCODER_ERROR:
    case DARAN_PROP_CONTROLLER_ERROR:
    case DARAN_PROP_FET_THERMISTOR_ERROR:
    case DARAN_PROP_MOTOR_THERMISTOR_ERROR:
    case DARAN_PROP_CAN_ERROR:
    case DARAN_PROP_CONFIG_WARNINGS:
    case DARAN_PROP_INPUT_POS:
    case DARAN_PROP_INPUT_VEL:
    case DARAN_PROP_INPUT_TORQUE:
    case DARAN_PROP_POS_SETPOINT:
    case DARAN_PROP_VEL_SETPOINT:
    case DARAN_PROP_TORQUE_SETPOINT:
        return false;
    default:
        return true;
    }
}

static void load_defaults(acme_drive_t *drive)
{
    daran_value_t *s = drive->settings;
    memset(s, 0, sizeof drive->settings);
    s[DARAN_PROP_CAN_NODE_ID].u32 = 1;
    s[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    s[DARAN_PROP_REQUESTED_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    s[DARAN_PROP_VBUS_VOLTAGE].f32 = 48.0f;
    s[DARAN_PROP_UART_BAUDRATE].u32 = 115200;
    s[DARAN_PROP_CAN_BAUD_RATE].u32 = 1000000;
    s[DARAN_PROP_CAN_PROTOCOL].u32 = 1; /* the vendor's CAN protocol on (its factory default) */
    s[DARAN_PROP_FW_VERSION].u32 = ACME_FW_VERSION;
    s[DARAN_PROP_HW_VERSION].u32 = ACME_HW_VERSION;
    s[DARAN_PROP_SHAFT_VEL_LIMIT].f32 = 300.0f;
    s[DARAN_PROP_INPUT_FILTER_BANDWIDTH].f32 = 20.0f;
    s[DARAN_PROP_TORQUE_CONSTANT].f32 = 0.1f;
    s[DARAN_PROP_TRAJ_MODE].u32 = 1;
    s[DARAN_PROP_MOTOR_DIRECTION].s32 = 1;
    s[DARAN_PROP_POLE_PAIRS].s32 = 7;
    s[DARAN_PROP_ENCODER_CPR].s32 = 4096;
    s[DARAN_PROP_GEAR_RATIO].f32 = 1.0f;
    s[DARAN_PROP_CONTROL_MODE].u32 = 3;
    s[DARAN_PROP_INPUT_MODE].u32 = 3;
    s[DARAN_PROP_SERIAL_NUMBER_H].u32 = (uint32_t)(drive->serial_number >> 32);
    s[DARAN_PROP_SERIAL_NUMBER_L].u32 = (uint32_t)drive->serial_number;
}

void acme_drive_power_on(acme_drive_t *drive)
{
    load_defaults(drive);
    if (drive->flash_valid) {
        for (size_t i = 0; i < DARAN_PROP_COUNT; i++) {
            if (is_saved_setting((daran_prop_t)i)) {
                drive->settings[i] = drive->flash[i];
            }
        }
    }
    float pos = drive->plant.pos_deg;
    float temp = drive->plant.stage_temp_c;
    acme_plant_init(&drive->plant, drive->settings[DARAN_PROP_SHAFT_VEL_LIMIT].f32);
    drive->plant.pos_deg = pos;   /* the shaft does not move when the drive reboots */
    drive->plant.stage_temp_c = temp;
    drive->plant.fan_duty = drive->settings[DARAN_PROP_FAN_DUTY].f32;
    drive->settings[DARAN_PROP_POS_SETPOINT].f32 = pos;
    drive->settings[DARAN_PROP_INPUT_POS].f32 = pos;
    acme_can_filter_set(&drive->can_filter, drive->settings[DARAN_PROP_CAN_NODE_ID].u32);
}

void acme_drive_factory_reset(acme_drive_t *drive, uint64_t serial_number)
{
    memset(drive, 0, sizeof *drive);
    drive->serial_number = serial_number;
    acme_plant_init(&drive->plant, 300.0f);
    acme_drive_power_on(drive);
}

void acme_drive_run(acme_drive_t *drive, uint32_t ms)
{
    for (uint32_t i = 0; i < ms; i++) {
        if (drive->settings[DARAN_PROP_CURRENT_STATE].u32 != DARAN_STATE_CLOSED_LOOP) {
            drive->plant.mode = ACME_PLANT_HOLD;
        }
        acme_plant_step(&drive->plant, 0.001f);
        drive->time_ms++;
        drive->can_mailboxes_busy = 0;
    }
}

static daran_result_t get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    const acme_drive_t *drive = ctx;
    const acme_plant_t *plant = &drive->plant;
    switch (prop) {
    case DARAN_PROP_POS_ESTIMATE:
        out->f32 = plant->pos_deg;
        return DARAN_OK;
    case DARAN_PROP_VEL_ESTIMATE:
        out->f32 = plant->vel_rpm;
        return DARAN_OK;
    case DARAN_PROP_TRAJECTORY_DONE:
        out->u32 = acme_plant_arrived(plant) ? 1u : 0u;
        return DARAN_OK;
    case DARAN_PROP_FET_TEMPERATURE:
        out->f32 = plant->stage_temp_c;
        return DARAN_OK;
    case DARAN_PROP_SERIAL_NUMBER:
        out->u64 = drive->serial_number;
        return DARAN_OK;
    case DARAN_PROP_ENCODER_POS_ABS:
    case DARAN_PROP_ENCODER_TURN_ABS:
        /* left out of this build (acme_options.h): the core never asks */
        return DARAN_ERR_INVALID_PROPERTY;
    default:
        *out = drive->settings[prop];
        return DARAN_OK;
    }
}

static daran_result_t set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    acme_drive_t *drive = ctx;
    daran_value_t *s = drive->settings;
    switch (prop) {
    case DARAN_PROP_REQUESTED_STATE:
        /* the core refused closed loop while an error bit is set */
        s[DARAN_PROP_CURRENT_STATE] = value;
        break;
    case DARAN_PROP_SHAFT_VEL_LIMIT:
        drive->plant.vel_limit_rpm = value.f32;
        break;
    case DARAN_PROP_FAN_DUTY:
        drive->plant.fan_duty = value.f32;
        break;
    case DARAN_PROP_CAN_NODE_ID:
        acme_can_filter_set(&drive->can_filter, value.u32); /* frames for the new id from now on */
        break;
    case DARAN_PROP_POS_SETPOINT:
        s[DARAN_PROP_INPUT_POS] = value;
        drive->plant.target_deg = value.f32;
        drive->plant.mode = ACME_PLANT_POSITION;
        break;
    case DARAN_PROP_VEL_SETPOINT:
        s[DARAN_PROP_INPUT_VEL] = value;
        drive->plant.target_rpm = value.f32;
        drive->plant.mode = ACME_PLANT_VELOCITY;
        break;
    case DARAN_PROP_TORQUE_SETPOINT:
        s[DARAN_PROP_INPUT_TORQUE] = value;
        drive->plant.mode = ACME_PLANT_TORQUE;
        break;
    default:
        break;
    }
    s[prop] = value;
    return DARAN_OK;
}

static daran_result_t move(void *ctx, const daran_move_t *request)
{
    acme_drive_t *drive = ctx;
    daran_value_t *s = drive->settings;
    acme_plant_t *plant = &drive->plant;
    switch (request->kind) {
    case DARAN_MOVE_FILTERED_POSITION:
    case DARAN_MOVE_TRAPEZOID:
    case DARAN_MOVE_PASSTHROUGH:
    case DARAN_MOVE_IMPEDANCE:
        s[DARAN_PROP_INPUT_POS].f32 = request->pos_deg;
        s[DARAN_PROP_POS_SETPOINT].f32 = request->pos_deg;
        if (request->kind == DARAN_MOVE_FILTERED_POSITION && (request->given & DARAN_GIVEN_RATE)) {
            s[DARAN_PROP_INPUT_FILTER_BANDWIDTH].f32 = request->rate;
        }
        if (request->kind == DARAN_MOVE_TRAPEZOID) {
            if (request->given & DARAN_GIVEN_VEL) {
                s[DARAN_PROP_TRAP_TRAJ_VEL_LIMIT].f32 = request->vel_rpm;
            }
            if (request->given & DARAN_GIVEN_RATE) {
                s[DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT].f32 = request->rate;
                s[DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT].f32 = request->rate;
            }
        }
        if (request->kind == DARAN_MOVE_PASSTHROUGH || request->kind == DARAN_MOVE_IMPEDANCE) {
            s[DARAN_PROP_INPUT_VEL].f32 = request->vel_rpm;
            s[DARAN_PROP_INPUT_TORQUE].f32 = request->torque_nm;
        }
        plant->target_deg = request->pos_deg;
        plant->mode = ACME_PLANT_POSITION;
        return DARAN_OK;
    case DARAN_MOVE_VELOCITY:
    case DARAN_MOVE_VELOCITY_RAMP:
        s[DARAN_PROP_INPUT_VEL].f32 = request->vel_rpm;
        s[DARAN_PROP_VEL_SETPOINT].f32 = request->vel_rpm;
        if (request->kind == DARAN_MOVE_VELOCITY) {
            s[DARAN_PROP_INPUT_TORQUE].f32 = request->torque_nm;
        } else {
            s[DARAN_PROP_VEL_RAMP_RATE].f32 = request->rate;
        }
        plant->target_rpm = request->vel_rpm;
        plant->mode = ACME_PLANT_VELOCITY;
        return DARAN_OK;
    case DARAN_MOVE_TORQUE:
    case DARAN_MOVE_TORQUE_RAMP:
        s[DARAN_PROP_INPUT_TORQUE].f32 = request->torque_nm;
        s[DARAN_PROP_TORQUE_SETPOINT].f32 = request->torque_nm;
        if (request->kind == DARAN_MOVE_TORQUE_RAMP) {
            s[DARAN_PROP_TORQUE_RAMP_RATE].f32 = request->rate;
        }
        plant->mode = ACME_PLANT_TORQUE;
        return DARAN_OK;
    default:
        return DARAN_ERR_INVALID_MODE; /* a kind this drive does not know: change nothing */
    }
}

static daran_result_t action(void *ctx, daran_action_t which)
{
    acme_drive_t *drive = ctx;
    daran_value_t *s = drive->settings;
    switch (which) {
    case DARAN_ACTION_SAVE_CONFIG:
        memcpy(drive->flash, s, sizeof drive->flash);
        drive->flash_valid = true;
        return DARAN_OK;
    case DARAN_ACTION_ERASE_CONFIG:
        drive->flash_valid = false;
        return DARAN_OK;
    case DARAN_ACTION_REBOOT:
        acme_drive_power_on(drive);
        return DARAN_OK;
    case DARAN_ACTION_CLEAR_ERRORS:
        s[DARAN_PROP_AXIS_ERROR].u32 = 0;
        s[DARAN_PROP_MOTOR_ERROR].u32 = 0;
        s[DARAN_PROP_ENCODER_ERROR].u32 = 0;
        s[DARAN_PROP_CONTROLLER_ERROR].u32 = 0;
        s[DARAN_PROP_FET_THERMISTOR_ERROR].u32 = 0;
        s[DARAN_PROP_MOTOR_THERMISTOR_ERROR].u32 = 0;
        s[DARAN_PROP_CAN_ERROR].u32 = 0;
        s[DARAN_PROP_CONFIG_WARNINGS].u32 = 0;
        return DARAN_OK;
    case DARAN_ACTION_SET_ZERO: {
        float here = drive->plant.pos_deg;
        drive->plant.pos_deg = 0.0f;
        drive->plant.target_deg -= here;
        s[DARAN_PROP_INPUT_POS].f32 -= here;
        s[DARAN_PROP_POS_SETPOINT].f32 -= here;
        return DARAN_OK;
    }
    case DARAN_ACTION_NODE_GUARD:
    case DARAN_ACTION_ESTOP:
        s[DARAN_PROP_AXIS_ERROR].u32 |=
            which == DARAN_ACTION_ESTOP ? DARAN_FLAG_ESTOP : DARAN_FLAG_WATCHDOG;
        s[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_IDLE;
        s[DARAN_PROP_REQUESTED_STATE].u32 = DARAN_STATE_IDLE;
        drive->plant.mode = ACME_PLANT_HOLD;
        return DARAN_OK;
    case DARAN_ACTION_FEED_WATCHDOG:
        return DARAN_OK;
    default:
        return DARAN_ERR_MOTOR_FAULT;
    }
}

const daran_hal_t acme_hal = {.get = get,
                              .set = set,
                              .move = move,
                              .action = action,
                              .now_ms = acme_can_now_ms,
                              .can_send = acme_can_send};
