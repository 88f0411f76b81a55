/* Multi-motor commands: `ms` stores a preset in the instance; mt/mq/mp/mv/mc
 * start it as t/q/p/v/c, together on every drive of the bus. */
#include <math.h>

#include "internal.h"

#if DARAN_ENABLE_MULTI_MOTOR

/* Degrees per second in one r/min. */
#define DEG_PER_S_PER_RPM 6.0f
/* How far below feasible a timed move may be and still run as the exact
 * triangle (spec section 6): hosts send the minimum duration, which float32
 * rounding can push a hair too short. */
#define TIMED_MOVE_SLACK 1e-4f

daran_result_t daran_cmd_ms(daran_drive_t *drive, const daran_request_t *request)
{
    float values[3];
    for (uint8_t i = 0; i < 3u; i++) {
        daran_result_t result = daran_field_f32(&request->fields->at[2u + i], &values[i]);
        if (result != DARAN_OK) {
            return result;
        }
    }
    for (uint8_t i = 0; i < 3u; i++) {
        drive->preset[i] = values[i];
    }
    drive->has_preset = 1;
    return DARAN_OK;
}

/* The checks every start shares, in the order of spec section 8 (D18).
 * Returns DARAN_OK with *go false when a broadcast start finds no preset here:
 * that line is not for this drive. */
static daran_result_t begin_start(daran_drive_t *drive, const daran_request_t *request,
                                  bool has_rel, uint32_t *rel, bool *go)
{
    *go = false;
    *rel = 0;
    if (has_rel) {
        daran_result_t result = daran_field_mode(&request->fields->at[2], DARAN_MODES_START, rel);
        if (result != DARAN_OK) {
            return result;
        }
    }
    if (request->motor == 0u && !drive->has_preset) {
        return DARAN_OK;
    }
    daran_result_t result = daran_check_motion_allowed(drive);
    if (result != DARAN_OK) {
        return result;
    }
    if (!drive->has_preset) {
        return DARAN_ERR_NO_PRESET;
    }
    *go = true;
    return DARAN_OK;
}

static daran_result_t finish_start(daran_drive_t *drive, const daran_move_t *move)
{
    daran_result_t result = daran_start_move(drive, move);
    if (result == DARAN_OK) {
        drive->has_preset = 0; /* a start consumes its preset; a refused one keeps it */
    }
    return result;
}

static daran_result_t position_setpoint(daran_drive_t *drive, float *out)
{
    daran_value_t value;
    daran_result_t result = daran_get(drive, DARAN_PROP_POS_SETPOINT, &value);
    *out = value.f32;
    return result;
}

/* The target of a positional start: the preset's p1, absolute or relative
 * to the current position setpoint. */
static daran_result_t start_target(daran_drive_t *drive, uint32_t rel, float *base, float *target)
{
    daran_result_t result = position_setpoint(drive, base);
    if (result != DARAN_OK) {
        return result;
    }
    *target = rel != 0u ? *base + drive->preset[0] : drive->preset[0];
    return daran_is_finite(*target) ? DARAN_OK : DARAN_ERR_OUT_OF_RANGE;
}

daran_result_t daran_cmd_mt(daran_drive_t *drive, const daran_request_t *request)
{
    uint32_t rel;
    bool go;
    daran_result_t result = begin_start(drive, request, true, &rel, &go);
    if (result != DARAN_OK || !go) {
        return result;
    }
    daran_move_t move = {DARAN_MOVE_FILTERED_POSITION, DARAN_GIVEN_RATE, 0, 0, 0, 0, 0, 0};
    float base;
    result = start_target(drive, rel, &base, &move.pos_deg);
    if (result != DARAN_OK) {
        return result;
    }
    move.rate = drive->preset[2];
    if (!(move.rate > 0.0f)) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    return finish_start(drive, &move);
}

/* Cruise velocity (deg/s) that covers distance d (deg) in exactly t (s) at
 * accel a (deg/s^2): the smaller root of v^2 - a t v + a d = 0, written as
 * 2ad / (at + sqrt(...)) so no cancellation eats its digits. */
static daran_result_t timed_trapezoid(float d, float t, float a, daran_move_t *move)
{
    float at = a * t;
    float need = 4.0f * a * d;
    float discriminant = at * at - need;
    if (!daran_is_finite(discriminant)) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    if (discriminant >= 0.0f) {
        float v = d > 0.0f ? 2.0f * a * d / (at + sqrtf(discriminant)) : at / 2.0f;
        move->vel_rpm = v / DEG_PER_S_PER_RPM;
        move->rate = a / DEG_PER_S_PER_RPM;
        return DARAN_OK;
    }
    if (-discriminant <= TIMED_MOVE_SLACK * at * at) {
        /* The exact triangle: peak 2d/t, acceleration 4d/t^2. */
        move->vel_rpm = 2.0f * d / t / DEG_PER_S_PER_RPM;
        move->rate = 4.0f * d / (t * t) / DEG_PER_S_PER_RPM;
        return DARAN_OK;
    }
    return DARAN_ERR_TRAJECTORY_INFEASIBLE;
}

daran_result_t daran_cmd_mq(daran_drive_t *drive, const daran_request_t *request)
{
    uint32_t rel;
    bool go;
    daran_result_t result = begin_start(drive, request, true, &rel, &go);
    if (result != DARAN_OK || !go) {
        return result;
    }
    float duration = drive->preset[1];
    float acc = drive->preset[2];
    if (!(duration > 0.0f) || !(acc > 0.0f)) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    daran_move_t move = {DARAN_MOVE_TRAPEZOID, DARAN_GIVEN_VEL | DARAN_GIVEN_RATE, 0, 0, 0, 0, 0, 0};
    float base;
    result = start_target(drive, rel, &base, &move.pos_deg);
    if (result != DARAN_OK) {
        return result;
    }
    float distance = fabsf(move.pos_deg - base);
    result = timed_trapezoid(distance, duration, acc * DEG_PER_S_PER_RPM, &move);
    if (result != DARAN_OK) {
        return result;
    }
    return finish_start(drive, &move);
}

daran_result_t daran_cmd_mp(daran_drive_t *drive, const daran_request_t *request)
{
    uint32_t rel;
    bool go;
    daran_result_t result = begin_start(drive, request, true, &rel, &go);
    if (result != DARAN_OK || !go) {
        return result;
    }
    daran_move_t move = {DARAN_MOVE_PASSTHROUGH, 0, 0, 0, 0, 0, 0, 0};
    float base;
    result = start_target(drive, rel, &base, &move.pos_deg);
    if (result != DARAN_OK) {
        return result;
    }
    move.vel_rpm = drive->preset[1];
    move.torque_nm = drive->preset[2];
    return finish_start(drive, &move);
}

/* A preset's mode is a float; it must be exactly one of the allowed modes. */
static daran_result_t preset_mode(float value, uint32_t allowed, uint32_t *mode)
{
    for (uint32_t m = 0; m < 32u; m++) {
        if (((allowed >> m) & 1u) != 0u && value == (float)m) {
            *mode = m;
            return DARAN_OK;
        }
    }
    return DARAN_ERR_INVALID_MODE;
}

daran_result_t daran_cmd_mv(daran_drive_t *drive, const daran_request_t *request)
{
    uint32_t unused;
    bool go;
    daran_result_t result = begin_start(drive, request, false, &unused, &go);
    if (result != DARAN_OK || !go) {
        return result;
    }
    daran_move_t move = {DARAN_MOVE_VELOCITY, 0, 0, 0, 0, 0, 0, 0};
    uint32_t mode;
    result = preset_mode(drive->preset[2], DARAN_MODES_VELOCITY, &mode);
    if (result == DARAN_OK) {
        result = daran_velocity_move(drive->preset[0], drive->preset[1], mode, &move);
    }
    return result != DARAN_OK ? result : finish_start(drive, &move);
}

daran_result_t daran_cmd_mc(daran_drive_t *drive, const daran_request_t *request)
{
    uint32_t unused;
    bool go;
    daran_result_t result = begin_start(drive, request, false, &unused, &go);
    if (result != DARAN_OK || !go) {
        return result;
    }
    daran_move_t move = {DARAN_MOVE_TORQUE, 0, 0, 0, 0, 0, 0, 0};
    uint32_t mode;
    result = preset_mode(drive->preset[2], DARAN_MODES_TORQUE, &mode);
    if (result == DARAN_OK) {
        result = daran_torque_move(drive->preset[0], drive->preset[1], mode, &move);
    }
    return result != DARAN_OK ? result : finish_start(drive, &move);
}

#endif /* DARAN_ENABLE_MULTI_MOTOR */
