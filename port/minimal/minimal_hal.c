/* A minimal, complete HAL: see minimal_hal.h and docs/porting.md. */
#include "minimal_hal.h"

#include <string.h>

/* What `ss` keeps: the settings, not the state, the setpoints or the error
 * registers (a reboot starts in closed loop with no flag). */
static bool saved_setting(daran_prop_t prop)
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

/* Power-up: the defaults, then the saved settings over them. */
static void boot(minimal_drive_t *drive)
{
    memset(drive->props, 0, sizeof drive->props);
    drive->props[DARAN_PROP_CAN_NODE_ID].u32 = 1;
    drive->props[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    drive->props[DARAN_PROP_REQUESTED_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    drive->props[DARAN_PROP_VBUS_VOLTAGE].f32 = 24.0f;
    drive->props[DARAN_PROP_UART_BAUDRATE].u32 = 115200;
    drive->props[DARAN_PROP_CAN_BAUD_RATE].u32 = 1000000;
    drive->props[DARAN_PROP_CAN_PROTOCOL].u32 = 1; /* the vendor protocol on CAN (C15) */
    drive->props[DARAN_PROP_INPUT_FILTER_BANDWIDTH].f32 = 20.0f;
    drive->props[DARAN_PROP_TORQUE_CONSTANT].f32 = 0.1f;
    drive->props[DARAN_PROP_FW_VERSION].u32 = 100;
    drive->props[DARAN_PROP_HW_VERSION].u32 = 1;
    if (drive->has_saved) {
        for (size_t i = 0; i < DARAN_PROP_COUNT; i++) {
            if (saved_setting((daran_prop_t)i)) {
                drive->props[i] = drive->saved[i];
            }
        }
    }
}

void minimal_drive_init(minimal_drive_t *drive)
{
    memset(drive, 0, sizeof *drive);
    for (size_t i = 0; i < MINIMAL_MOVE_WORDS; i++) {
        atomic_init(&drive->move_words[i], 0u);
    }
    atomic_init(&drive->move_seq, 0u);
    boot(drive);
}

bool minimal_drive_take_move(minimal_drive_t *drive, daran_move_t *move)
{
    uint32_t words[MINIMAL_MOVE_WORDS];
    uint32_t seq = atomic_load_explicit(&drive->move_seq, memory_order_acquire);
    if ((seq & 1u) != 0u || seq == drive->taken_seq) {
        return false; /* being written (it preempted the writer), or nothing new */
    }
    /* A word the writer stored after making the sequence odd (each word's
     * store is a release) makes the sequence read below differ: acquire
     * loads keep that read after the words. */
    for (size_t i = 0; i < MINIMAL_MOVE_WORDS; i++) {
        words[i] = atomic_load_explicit(&drive->move_words[i], memory_order_acquire);
    }
    if (atomic_load_explicit(&drive->move_seq, memory_order_relaxed) != seq) {
        return false; /* a newer move came meanwhile: take that one next time */
    }
    drive->taken_seq = seq;
    memcpy(move, words, sizeof *move);
    return true;
}

/* The main loop's side: publish a move, replacing one not yet taken (the
 * control loop only ever wants the latest target). */
static void post_move(minimal_drive_t *drive, const daran_move_t *request)
{
    uint32_t words[MINIMAL_MOVE_WORDS] = {0};
    memcpy(words, request, sizeof *request);
    uint32_t seq = atomic_load_explicit(&drive->move_seq, memory_order_relaxed);
    atomic_store_explicit(&drive->move_seq, seq + 1u, memory_order_relaxed);
    /* each word's release store keeps the odd number before it (no
     * standalone fence: ThreadSanitizer checks orders on the atomics) */
    for (size_t i = 0; i < MINIMAL_MOVE_WORDS; i++) {
        atomic_store_explicit(&drive->move_words[i], words[i], memory_order_release);
    }
    atomic_store_explicit(&drive->move_seq, seq + 2u, memory_order_release);
}

daran_result_t minimal_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    minimal_drive_t *drive = ctx;
    *out = drive->props[prop];
    return DARAN_OK;
}

daran_result_t minimal_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    minimal_drive_t *drive = ctx;
    drive->props[prop] = value;
    if (prop == DARAN_PROP_REQUESTED_STATE) {
        /* The core refused closed loop while a flag is set; here it just happens. */
        drive->props[DARAN_PROP_CURRENT_STATE] = value;
    }
    return DARAN_OK;
}

daran_result_t minimal_move(void *ctx, const daran_move_t *request)
{
    minimal_drive_t *drive = ctx;
    daran_value_t *p = drive->props;
    /* The protocol promises that `r` reads a command's targets back at once. */
    switch (request->kind) {
    case DARAN_MOVE_FILTERED_POSITION:
        p[DARAN_PROP_INPUT_POS].f32 = request->pos_deg;
        if (request->given & DARAN_GIVEN_RATE) {
            p[DARAN_PROP_INPUT_FILTER_BANDWIDTH].f32 = request->rate;
        }
        break;
    case DARAN_MOVE_TRAPEZOID:
        /* a given cruise and acceleration become the trapezoid settings (D20) */
        p[DARAN_PROP_INPUT_POS].f32 = request->pos_deg;
        if (request->given & DARAN_GIVEN_VEL) {
            p[DARAN_PROP_TRAP_TRAJ_VEL_LIMIT].f32 = request->vel_rpm;
        }
        if (request->given & DARAN_GIVEN_RATE) {
            p[DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT].f32 = request->rate;
            p[DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT].f32 = request->rate;
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
    post_move(drive, request); /* to the control loop */
    return DARAN_OK;
}

daran_result_t minimal_action(void *ctx, daran_action_t which)
{
    minimal_drive_t *drive = ctx;
    daran_value_t *p = drive->props;
    switch (which) {
    case DARAN_ACTION_SAVE_CONFIG:
        memcpy(drive->saved, drive->props, sizeof drive->saved);
        drive->has_saved = true;
        drive->saved_config_writes++;
        return DARAN_OK;
    case DARAN_ACTION_ERASE_CONFIG:
        drive->has_saved = false;
        return DARAN_OK;
    case DARAN_ACTION_REBOOT:
        boot(drive);
        return DARAN_OK;
    case DARAN_ACTION_ESTOP:
        p[DARAN_PROP_AXIS_ERROR].u32 |= DARAN_FLAG_ESTOP;
        p[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_IDLE;
        return DARAN_OK;
    case DARAN_ACTION_NODE_GUARD:
        p[DARAN_PROP_AXIS_ERROR].u32 |= DARAN_FLAG_WATCHDOG;
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
    case DARAN_ACTION_FEED_WATCHDOG:
        return DARAN_OK;
    default:
        return DARAN_ERR_MOTOR_FAULT;
    }
}

const daran_hal_t minimal_hal = {MINIMAL_HAL_FUNCTIONS};
