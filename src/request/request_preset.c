/* The request layer's presets and their starts (request.h): a preset
 * stored from a line or a frame, a start that moves every drive of the bus
 * at once, the timed `mq` that picks its own cruise velocity. */
#include <math.h>

#include "request.h"

#if DARAN_ENABLE_MULTI_MOTOR

/* Degrees per second in one r/min. */
#define DEG_PER_S_PER_RPM 6.0f
/* How far below feasible a timed move may be and still run as the exact
 * triangle (spec section 6): hosts send the minimum duration, which float32
 * rounding can push a hair too short. */
#define TIMED_MOVE_SLACK 1e-4f
/* One count of a CAN preset's duration field, in seconds (s16 x 100). */
#define CAN_DURATION_STEP 0.01f

void daran_store_preset(daran_drive_t *drive, const float *values, uint8_t origin)
{
    for (uint8_t i = 0; i < DARAN_PRESET_VALUES; i++) {
        drive->preset[i] = values[i];
    }
    drive->has_preset = origin;
}

/* Whether a cruise-less move peaking at @p peak (deg/s) stays within the
 * drive's velocity limit (output_shaft.vel_limit); a port without that
 * property has no limit to keep. */
static daran_result_t within_vel_limit(daran_drive_t *drive, float peak)
{
    daran_value_t limit;
    daran_result_t result = daran_get(drive, DARAN_PROP_SHAFT_VEL_LIMIT, &limit);
    if (result == DARAN_ERR_INVALID_PROPERTY) {
        return DARAN_OK;
    }
    if (result == DARAN_OK && peak > limit.f32 * DEG_PER_S_PER_RPM) {
        result = DARAN_ERR_TRAJECTORY_INFEASIBLE;
    }
    return result;
}

/* Cruise velocity that covers distance d (deg) in exactly t (s) at accel a
 * (deg/s^2), the move going to the HAL as an ordinary trapezoid in r/min and
 * (r/min)/s. A trapezoid's ramps cover v^2/a together, an S-curve's (each
 * ramp 2v/a long) 2v^2/a, so t = d/v + ramps/v: v is the smaller root of
 * s v^2 - a t v + a d = 0 with s = 1 or 2, written as 2ad / (at + sqrt(...))
 * so no cancellation eats its digits. When a cannot cover d in t the drive
 * keeps the time (spec 10.5, D42): the cruise-less move that lands at t. A
 * zero duration or acceleration can only be kept by a drive that need not
 * move (spec 10.1, D41). @p move comes with the target alone (nothing given,
 * no cruise, no rate). */
static daran_result_t timed_move(daran_drive_t *drive, float d, float t, float a, bool s_curve,
                                 float slack, daran_move_t *move)
{
    if (d == 0.0f) {
        return DARAN_OK; /* nothing to plan: the drive keeps its settings and any running move */
    }
    if (t == 0.0f || a == 0.0f) {
        return DARAN_ERR_TRAJECTORY_INFEASIBLE;
    }
    move->given = DARAN_GIVEN_VEL | DARAN_GIVEN_RATE;
    float ramps = s_curve ? 8.0f : 4.0f;
    float at = a * t;
    float discriminant = at * at - ramps * a * d;
    if (!daran_is_finite(discriminant)) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    float v;
    float rate;
    if (discriminant >= 0.0f) {
        v = 2.0f * a * d / (at + sqrtf(discriminant));
        rate = a;
    } else {
        /* The triangle that lands exactly on time: peak 2d/t, acceleration
         * 4d/t^2 (trapezoid) or 8d/t^2 (S-curve). A host's least duration
         * (float32 can push it a hair short, D31; a CAN preset's truncated
         * to 0.01 s, C13) runs whatever the limit, as a duration just long
         * enough would; a shorter one only within the velocity limit. */
        v = 2.0f * d / t;
        rate = ramps * d / (t * t);
        bool least = -discriminant <= TIMED_MOVE_SLACK * at * at;
#if DARAN_ENABLE_CAN
        least = least || sqrtf(ramps * d / a) - t < slack;
#else
        (void)slack;
#endif
        if (!least) {
            daran_result_t result = within_vel_limit(drive, v);
            if (result != DARAN_OK) {
                return result;
            }
        }
    }
    move->vel_rpm = v / DEG_PER_S_PER_RPM;
    move->rate = rate / DEG_PER_S_PER_RPM;
    if (!(move->vel_rpm > 0.0f) || !(move->rate > 0.0f)) {
        /* a plan that underflows (a subnormal distance; a triangle whose
         * duration squared overflows): the drive steps there, nothing
         * given, as for no distance at all */
        move->given = 0;
        move->vel_rpm = 0.0f;
        move->rate = 0.0f;
    }
    return DARAN_OK;
}

#if DARAN_ENABLE_S_CURVE
/* S-curve planning when the drive says so; a port that left traj_mode out
 * of its table has trapezoids only. */
static daran_result_t uses_s_curve(daran_drive_t *drive, bool *s_curve)
{
    daran_value_t mode;
    daran_result_t result = daran_get(drive, DARAN_PROP_TRAJ_MODE, &mode);
    *s_curve = result == DARAN_OK && mode.u32 == 2u;
    return result == DARAN_ERR_INVALID_PROPERTY ? DARAN_OK : result;
}
#else
/* A build without S-curves plans trapezoids and never asks traj_mode. */
static daran_result_t uses_s_curve(daran_drive_t *drive, bool *s_curve)
{
    (void)drive;
    *s_curve = false;
    return DARAN_OK;
}
#endif

/* The move a start makes of the preset. Positional starts aim at p1,
 * absolute or relative to the current position setpoint; `mq` reads p2 as a
 * duration and p3 as the acceleration, both >= 0, and picks its own cruise
 * velocity for the distance from where the drive is heading (D41): the
 * running move's end (`input_pos`) while `trajectory_done` reads 0, else the
 * position setpoint (also on a port without those properties). Its move is
 * built from p1 alone: p2 and p3 are not q's cruise and acceleration. */
static daran_result_t preset_move(daran_drive_t *drive, daran_shape_t shape, const float *values,
                                  bool rel, daran_move_t *move)
{
    bool timed = shape == DARAN_SHAPE_TRAPEZOID;
    if (timed && (!(values[1] >= 0.0f) || !(values[2] >= 0.0f))) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    uint8_t count = timed ? 1u : 3u;
    daran_result_t result = daran_shape_check(shape, values, count);
    if (result == DARAN_OK) {
        result = daran_shape_move(shape, values, count, move);
    }
    if (result != DARAN_OK || shape == DARAN_SHAPE_VELOCITY || shape == DARAN_SHAPE_TORQUE) {
        return result;
    }
    daran_value_t setpoint;
    result = daran_get(drive, DARAN_PROP_POS_SETPOINT, &setpoint);
    if (result != DARAN_OK) {
        return result;
    }
    if (rel) {
        move->pos_deg += setpoint.f32;
    }
    if (!daran_is_finite(move->pos_deg)) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    if (!timed) {
        return DARAN_OK;
    }
    bool s_curve;
    result = uses_s_curve(drive, &s_curve);
    if (result != DARAN_OK) {
        return result;
    }
    daran_value_t value;
    result = daran_get(drive, DARAN_PROP_TRAJECTORY_DONE, &value);
    if (result == DARAN_OK && value.u32 == 0u) {
        result = daran_get(drive, DARAN_PROP_INPUT_POS, &value);
        if (result == DARAN_OK) {
            setpoint.f32 = value.f32; /* a move runs: measure from its end */
        }
    }
    if (result != DARAN_OK && result != DARAN_ERR_INVALID_PROPERTY) {
        return result;
    }
    float slack = drive->has_preset == DARAN_PRESET_FROM_CAN ? CAN_DURATION_STEP : 0.0f;
    return timed_move(drive, fabsf(move->pos_deg - setpoint.f32), values[1],
                      values[2] * DEG_PER_S_PER_RPM, s_curve, slack, move);
}

daran_result_t daran_start_preset(daran_drive_t *drive, daran_shape_t shape, const float *values,
                                  bool rel, bool broadcast)
{
    /* A broadcast start is not for a drive that holds no preset (D18). */
    if (broadcast && drive->has_preset == DARAN_PRESET_NONE) {
        return DARAN_OK;
    }
    daran_result_t result = daran_check_motion_allowed(drive);
    if (result != DARAN_OK) {
        return result;
    }
    if (drive->has_preset == DARAN_PRESET_NONE) {
        return DARAN_ERR_NO_PRESET;
    }
    daran_move_t move;
    result = preset_move(drive, shape, values, rel, &move);
    if (result == DARAN_OK) {
        result = daran_start_move(drive, &move);
    }
    if (result == DARAN_OK) {
        drive->has_preset = DARAN_PRESET_NONE; /* a start consumes its preset; a refused one keeps it (D16) */
    }
    return result;
}

#if DARAN_ENABLE_CAN
daran_result_t daran_start_impedance(daran_drive_t *drive, float kp, float kd, bool broadcast)
{
    if (drive->has_preset == DARAN_PRESET_NONE) {
        return broadcast ? DARAN_OK : DARAN_ERR_NO_PRESET;
    }
    const float values[DARAN_MOTION_VALUES_MAX] = {drive->preset[0], drive->preset[1],
                                                   drive->preset[2], kp, kd};
    daran_result_t result = daran_shape_check(DARAN_SHAPE_IMPEDANCE, values, 5);
    if (result == DARAN_OK) {
        result = daran_run_motion(drive, DARAN_SHAPE_IMPEDANCE, values, 5);
    }
    if (result == DARAN_OK) {
        drive->has_preset = DARAN_PRESET_NONE;
    }
    return result;
}
#endif

#endif /* DARAN_ENABLE_MULTI_MOTOR */
