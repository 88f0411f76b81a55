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

/* A function of the request layer that the CAN front end (or the bridge)
 * calls too is external when that is built, and file-local otherwise: an
 * ASCII-only build then inlines it into its one caller. */
#if DARAN_ENABLE_CAN
#define DARAN_CAN_SHARED
#else
#define DARAN_CAN_SHARED static
#endif
#if DARAN_ENABLE_CAN_BRIDGE
#define DARAN_BRIDGE_SHARED
#else
#define DARAN_BRIDGE_SHARED static
#endif

/* The requests both front ends make once their values are decoded (the
 * ASCII handlers below parse text into them, can.c decodes frames into
 * them), so ranges, state rules and HAL calls are written once. */

/* Where a preset came from (drive->has_preset): a start of a CAN preset
 * forgives a duration short by less than one count of the CAN field (C13). */
#define DARAN_PRESET_NONE 0u
#define DARAN_PRESET_FROM_LINE 1u
#define DARAN_PRESET_FROM_CAN 2u

#if DARAN_ENABLE_CAN
/* commands_motion.c: the move of @p count values checked against the shape
 * (daran_shape_check()), after the drive's state, to the HAL. */
daran_result_t daran_run_motion(daran_drive_t *drive, daran_shape_t shape, const float *values,
                                uint8_t count);

/* commands_multi.c: presets and their starts. */
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

/* commands_property.c: does @p value (in @p prop's type) pass the row's
 * range; then write it, refusing `requested_state` 8 while a flag holds the
 * drive (D21). Access is the caller's to check first. */
daran_result_t daran_check_property_value(daran_prop_t prop, daran_value_t value);
daran_result_t daran_commit_property(daran_drive_t *drive, daran_prop_t prop, daran_value_t value);
#endif /* DARAN_ENABLE_CAN */

#if DARAN_ENABLE_CAN_BRIDGE
/* The values of a line, parsed and checked as its handler does, without
 * running it: what the bridge sends for a line for another drive. */
daran_result_t daran_parse_motion(const daran_request_t *request, float *values, uint8_t *count);
daran_result_t daran_parse_preset(const daran_request_t *request, float *values);
daran_result_t daran_parse_start(const daran_request_t *request, bool *rel);
daran_result_t daran_parse_property_value(daran_prop_t prop, const daran_field_t *field,
                                          daran_value_t *value);
#endif /* DARAN_ENABLE_CAN_BRIDGE */

#if DARAN_ENABLE_CAN
/* commands_system.c: a HAL action, and what the core forgets with it. */
daran_result_t daran_run_action(daran_drive_t *drive, daran_action_t action);
#endif

/* commands_query.c: read @p count (<= DARAN_APPEND_MAX) properties, then
 * append them to the line being built, each formatted by its type and after
 * a space unless the line is still empty; nothing is appended when a read
 * fails. */
#define DARAN_APPEND_MAX 9u
daran_result_t daran_append_properties(daran_drive_t *drive, const daran_prop_t *props,
                                       size_t count);
#define DARAN_ERROR_REGISTERS 7u
#if DARAN_ENABLE_CAN_BRIDGE
/* Append @p count values, each printed as a property of types[i]
 * (daran_prop_type_t) prints: what daran_append_properties() does after
 * its reads, and what the bridge prints of a remote drive's values. */
void daran_append_values(daran_drive_t *drive, const daran_value_t *values,
                         const uint8_t *types, size_t count);
/* `e`'s seven lines, of the registers' values in `e`'s order. */
void daran_reply_error_registers(daran_drive_t *drive, const uint32_t *values);
#endif
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
daran_result_t daran_cmd_query(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_errors(daran_drive_t *drive, const daran_request_t *request);
/* `h` and discovery as the bridge answers them for another id (C35): the
 * core's commands without the port's, the properties with a CAN address. */
daran_result_t daran_help(daran_drive_t *drive, const daran_request_t *request, bool bridged);
daran_result_t daran_discovery(daran_drive_t *drive, const daran_request_t *request,
                               bool on_can_only);

#endif /* DARAN_HANDLERS_H */
