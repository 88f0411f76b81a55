/* The ASCII front end's handlers and what they share: values from fields
 * (commands_common.c), the parsers the bridge uses too, properties as reply
 * text (commands_query.c). Each handler turns a line's text into a request
 * of the request layer (request.h). */
#ifndef DARAN_HANDLERS_H
#define DARAN_HANDLERS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "command.h"
#include "daran_drive.h"
#include "line.h"
#include "request.h"

/* commands_common.c */
daran_result_t daran_field_f32(const daran_field_t *field, float *out);
/* An integer mode field: DARAN_ERR_INVALID_VALUE when malformed or not an
 * integer, DARAN_ERR_INVALID_MODE when an integer whose bit is not set in
 * @p allowed (bit m = mode m). */
daran_result_t daran_field_mode(const daran_field_t *field, uint32_t allowed, uint32_t *out);
daran_result_t daran_field_motor(const daran_field_t *field, uint8_t *out);

/* The values of a line, parsed and checked as its handler does, without
 * running it: what the bridge sends for a line for another drive. */
daran_result_t daran_parse_motion(const daran_request_t *request, float *values, uint8_t *count);
daran_result_t daran_parse_preset(const daran_request_t *request, float *values);
daran_result_t daran_parse_start(const daran_request_t *request, bool *rel);
daran_result_t daran_parse_property_value(daran_prop_t prop, const daran_field_t *field,
                                          daran_value_t *value);


/* commands_query.c: read @p count (<= DARAN_APPEND_MAX) properties, then
 * append them to the line being built, each formatted by its type and after
 * a space unless the line is still empty; nothing is appended when a read
 * fails. */
#define DARAN_APPEND_MAX 9u
daran_result_t daran_append_properties(daran_drive_t *drive, const daran_prop_t *props,
                                       size_t count);
#define DARAN_ERROR_REGISTERS 7u
/* Append @p count values, each printed as a property of types[i]
 * (daran_prop_type_t) prints: what daran_append_properties() does after
 * its reads, and what the bridge prints of a remote drive's values. */
void daran_append_values(daran_drive_t *drive, const daran_value_t *values,
                         const uint8_t *types, size_t count);
/* `e`'s seven lines, of the registers' values in `e`'s order. */
void daran_reply_error_registers(daran_drive_t *drive, const uint32_t *values);
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
/* update.c (the update module's room): every `u?` step but `u` */
daran_result_t daran_cmd_update(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_help(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_query(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_errors(daran_drive_t *drive, const daran_request_t *request);
/* `h` and discovery as the bridge answers them for another id (C35): the
 * core's commands without the port's, the properties with a CAN address. */
daran_result_t daran_help(daran_drive_t *drive, const daran_request_t *request, bool bridged);
daran_result_t daran_discovery(daran_drive_t *drive, const daran_request_t *request,
                               bool on_can_only);

#endif /* DARAN_HANDLERS_H */
