/* The request layer: what both front ends ask of a drive once a line's
 * text (src/ascii/commands_*.c) or a frame's bytes (src/can/can.c) are decoded: run a
 * motion, store and start a preset, check and commit a property value, run
 * an action, read a property. Ranges, state rules and HAL calls are written
 * here once; the HAL door (hal.h) is this layer's bottom, and nothing above
 * it reaches the HAL but through it. */
#ifndef DARAN_REQUEST_H
#define DARAN_REQUEST_H

#include <stdbool.h>
#include <stdint.h>

#include "daran_drive.h"
#include "hal.h"

/* Whether @p value is finite: inf - inf and nan - nan are nan, which
 * compares unequal to 0. */
static inline bool daran_is_finite(float value)
{
    return value - value == 0.0f;
}

/* The drive accepts motion: closed loop, no blocking flag. */
daran_result_t daran_check_motion_allowed(daran_drive_t *drive);

/* The motion shapes of t q p v c d (commands_motion.c, beside the parsing
 * of their values, which checks each value as it is read: the hot path of
 * a line), shared by the starts. */
#define DARAN_MOTION_VALUES_MAX 5u /* the most values a motion command has after its id */
typedef enum daran_shape {
    DARAN_SHAPE_FILTERED,    /* t, mt */
    DARAN_SHAPE_TRAPEZOID,   /* q, mq */
    DARAN_SHAPE_PASSTHROUGH, /* p, mp */
    DARAN_SHAPE_VELOCITY,    /* v, mv */
    DARAN_SHAPE_TORQUE,      /* c, mc */
    DARAN_SHAPE_IMPEDANCE,   /* d */
    DARAN_SHAPE_COUNT
} daran_shape_t;
/* Check @p count values against a shape, in order: the first failing value
 * answers (D11). A line's values are checked as they are parsed; a preset's
 * with this, in the same order (D17). */
daran_result_t daran_shape_check(daran_shape_t shape, const float *values, uint8_t count);
/* Build the move of @p count checked values; the ramp rate, which depends on
 * the mode, is checked here, last. */
daran_result_t daran_shape_move(daran_shape_t shape, const float *values, uint8_t count,
                                daran_move_t *move);
/* The move of @p count values checked against the shape
 * (daran_shape_check()), after the drive's state, to the HAL. */
daran_result_t daran_run_motion(daran_drive_t *drive, daran_shape_t shape, const float *values,
                                uint8_t count);

/* Presets and their starts (request_preset.c). Where a preset came from
 * (drive->has_preset): a start of a CAN preset forgives a duration short by
 * less than one count of the CAN field (C13). */
#define DARAN_PRESET_NONE 0u
#define DARAN_PRESET_FROM_LINE 1u
#define DARAN_PRESET_FROM_CAN 2u
void daran_store_preset(daran_drive_t *drive, const float *values, uint8_t origin);
/* Start the preset as @p shape (t q p v c) with @p values in place of the
 * stored ones (the same, or a CAN start's reading of them), relative to the
 * position setpoint when @p rel; a broadcast start is not for a drive
 * without a preset (D18). The preset is consumed when the move starts. */
daran_result_t daran_start_preset(daran_drive_t *drive, daran_shape_t shape, const float *values,
                                  bool rel, bool broadcast);
/* The CAN impedance start (sub-code 0x15): the preset's pdes, vdes, tff with
 * @p kp and @p kd, as `d` would run them. */
daran_result_t daran_start_impedance(daran_drive_t *drive, float kp, float kd, bool broadcast);

/* Properties (request_property.c): does @p value (in @p prop's type) pass
 * the row's range; then write it, refusing `requested_state` 8 while a flag
 * holds the drive (D21). Access is the caller's to check first. A read is
 * the HAL door's daran_get(). */
daran_result_t daran_check_property_value(daran_prop_t prop, daran_value_t value);
daran_result_t daran_commit_property(daran_drive_t *drive, daran_prop_t prop, daran_value_t value);

/* A HAL action, and what the core forgets with it (request_action.c). */
daran_result_t daran_run_action(daran_drive_t *drive, daran_action_t action);

#endif /* DARAN_REQUEST_H */
