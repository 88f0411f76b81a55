/* Multi-motor commands: `ms` stores a preset in the instance; mt/mq/mp/mv/mc
 * start it as t/q/p/v/c on every drive of the bus at once. */
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
        daran_field_t field = daran_field_at(request->fields, 2u + i);
        daran_result_t result = daran_field_f32(&field, &values[i]);
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

/* Cruise velocity (deg/s) that covers distance d (deg) in exactly t (s) at
 * accel a (deg/s^2): the smaller root of v^2 - a t v + a d = 0, written as
 * 2ad / (at + sqrt(...)) so no cancellation eats its digits. The move goes
 * to the HAL as an ordinary trapezoid in r/min and (r/min)/s. */
static daran_result_t timed_trapezoid(float d, float t, float a, daran_move_t *move)
{
    float at = a * t;
    float discriminant = at * at - 4.0f * a * d;
    if (!daran_is_finite(discriminant)) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    if (discriminant >= 0.0f) {
        /* d == 0 completes at once whatever the cruise velocity (D19). */
        float v = d > 0.0f ? 2.0f * a * d / (at + sqrtf(discriminant)) : at / 2.0f;
        move->vel_rpm = v / DEG_PER_S_PER_RPM;
        move->rate = a / DEG_PER_S_PER_RPM;
        return DARAN_OK;
    }
    if (-discriminant <= TIMED_MOVE_SLACK * at * at) {
        /* The triangle that lands exactly on time: peak 2d/t, acceleration 4d/t^2. */
        move->vel_rpm = 2.0f * d / t / DEG_PER_S_PER_RPM;
        move->rate = 4.0f * d / (t * t) / DEG_PER_S_PER_RPM;
        return DARAN_OK;
    }
    return DARAN_ERR_TRAJECTORY_INFEASIBLE;
}

/* The move a start makes of the preset. Positional starts aim at p1,
 * absolute or relative to the current position setpoint; `mq` reads p2 as a
 * duration and picks its own cruise velocity. */
static daran_result_t preset_move(daran_drive_t *drive, daran_shape_t shape, uint32_t rel,
                                  daran_move_t *move)
{
    /* q's shape also holds mq's duration to > 0, like the cruise velocity. */
    const float *values = drive->preset;
    daran_result_t result = daran_shape_check(shape, values, 3);
    if (result == DARAN_OK) {
        result = daran_shape_move(shape, values, 3, move);
    }
    if (result != DARAN_OK || shape == DARAN_SHAPE_V || shape == DARAN_SHAPE_C) {
        return result;
    }
    daran_value_t setpoint;
    result = daran_get(drive, DARAN_PROP_POS_SETPOINT, &setpoint);
    if (result != DARAN_OK) {
        return result;
    }
    if (rel != 0u) {
        move->pos_deg += setpoint.f32;
    }
    if (!daran_is_finite(move->pos_deg)) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    if (shape != DARAN_SHAPE_Q) {
        return DARAN_OK;
    }
    return timed_trapezoid(fabsf(move->pos_deg - setpoint.f32), values[1],
                           values[2] * DEG_PER_S_PER_RPM, move);
}

daran_result_t daran_cmd_start(daran_drive_t *drive, const daran_request_t *request)
{
    daran_shape_t shape = (daran_shape_t)request->command->arg;
    uint32_t rel = 0;
    if (request->fields->count == 3u) { /* mt, mq, mp: 0 absolute, 1 relative */
        daran_field_t field = daran_field_at(request->fields, 2);
        daran_result_t result = daran_field_mode(&field, (1u << 0) | (1u << 1), &rel);
        if (result != DARAN_OK) {
            return result;
        }
    }
    /* A broadcast start is not for a drive that holds no preset (D18). */
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
    daran_move_t move;
    result = preset_move(drive, shape, rel, &move);
    if (result == DARAN_OK) {
        result = daran_start_move(drive, &move);
    }
    if (result == DARAN_OK) {
        drive->has_preset = 0; /* a start consumes its preset; a refused one keeps it (D16) */
    }
    return result;
}

#endif /* DARAN_ENABLE_MULTI_MOTOR */
