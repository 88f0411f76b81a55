/* The command handlers and what they share: values from fields and the
 * drive's state (commands_common.c), the shapes of the motion commands
 * (commands_motion.c), properties as reply text (commands_query.c). */
#ifndef DARAN_HANDLERS_H
#define DARAN_HANDLERS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "command.h"
#include "daran_drive.h"
#include "line.h"

/* commands_common.c */
daran_result_t daran_field_f32(const daran_field_t *field, float *out);
/* An integer mode field: DARAN_ERR_INVALID_VALUE when malformed or not an
 * integer, DARAN_ERR_INVALID_MODE when an integer whose bit is not set in
 * @p allowed (bit m = mode m). */
daran_result_t daran_field_mode(const daran_field_t *field, uint32_t allowed, uint32_t *out);
daran_result_t daran_field_motor(const daran_field_t *field, uint8_t *out);
/* The drive accepts motion: closed loop, no blocking flag. */
daran_result_t daran_check_motion_allowed(daran_drive_t *drive);
bool daran_is_finite(float value);

/* commands_motion.c: the value layouts of t q p v c d, shared by the starts. */
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

/* commands_query.c: read @p count (<= DARAN_APPEND_MAX) properties, then
 * append them to the line being built, each formatted by its type and after
 * a space unless the line is still empty; nothing is appended when a read
 * fails. */
#define DARAN_APPEND_MAX 9u
daran_result_t daran_append_properties(daran_drive_t *drive, const daran_prop_t *props,
                                       size_t count);
/* The same as a whole reply line (`r`, `f`, `g`, `i`). */
daran_result_t daran_reply_properties(daran_drive_t *drive, const daran_prop_t *props,
                                      size_t count);

/* The handlers, one per command family; command->arg selects the shape or
 * action. Each lives in the commands_*.c file of its family. */
daran_result_t daran_cmd_motion(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_ms(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_start(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_r(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_w(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_action(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_help(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_feedback(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_power(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_identity(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_errors(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_discovery(daran_drive_t *drive, const daran_request_t *request);

#endif /* DARAN_HANDLERS_H */
