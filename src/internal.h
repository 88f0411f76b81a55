/* Declarations shared by the core's modules; not part of the public API. */
#ifndef DARAN_INTERNAL_H
#define DARAN_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_drive.h"
#include "number.h"

/* The most fields any command has (d: word, id and 5 values); one more slot
 * tells "too many" apart from "exactly enough". */
#define DARAN_FIELDS_MAX 8u

/* A field: a view into the line, never a copy. */
typedef struct daran_field {
    const char *text;
    uint16_t len;
} daran_field_t;

typedef struct daran_fields {
    daran_field_t at[DARAN_FIELDS_MAX];
    uint8_t count; /* fields found, saturating at DARAN_FIELDS_MAX */
} daran_fields_t;

/* One request on its way from the table to the HAL. */
struct daran_command;

typedef struct daran_request {
    const struct daran_command *command;
    const daran_fields_t *fields;
    uint8_t motor;      /* addressed id; 0 = every drive */
    daran_prop_t prop;  /* r/w only */
} daran_request_t;

typedef daran_result_t (*daran_handler_fn)(daran_drive_t *drive, const daran_request_t *request);

/* Command flags. */
#define DARAN_CMD_READ 0x01u /* answered for id 0 and never forwarded */
#define DARAN_CMD_PATH 0x02u /* the id comes from a property path (r, w) */

typedef struct daran_command {
    char word[3];
    uint8_t min_fields; /* command word included */
    uint8_t max_fields;
    uint8_t flags;
    uint8_t arg; /* handler-specific: the HAL action of a system command */
    daran_handler_fn handler;
#if DARAN_ENABLE_HELP
    const char *arguments;
#endif
} daran_command_t;

typedef enum daran_scope { DARAN_SCOPE_SYSTEM, DARAN_SCOPE_AXIS } daran_scope_t;
typedef enum daran_access { DARAN_ACCESS_RO, DARAN_ACCESS_RW } daran_access_t;

/* One row of the compiled property table, 4 bytes: the name lives in one
 * shared block of characters (no pointers, no NULs), the rest in bit fields.
 * The unit is documentation only and stays in DARAN_PROPERTY_LIST. */
typedef struct daran_property {
    unsigned name_offset : 16;
    unsigned name_len : 8;
    unsigned scope : 1;  /* daran_scope_t */
    unsigned access : 1; /* daran_access_t */
    unsigned type : 2;   /* daran_prop_type_t */
    unsigned range : 4;  /* daran_range_t */
} daran_property_t;

/* checksum.c */
uint8_t daran_xor(const char *text, size_t len);
/* Split off a "*N" field: *payload_len is the length before the '*' (len if
 * none). DARAN_OK with *has_checksum 0 when there is none; DARAN_OK with
 * *has_checksum 1 when it is well-formed and matches;
 * DARAN_ERR_CHECKSUM_MISMATCH (*has_checksum 1) or DARAN_ERR_INVALID_CHECKSUM
 * (*has_checksum 0) otherwise. */
daran_result_t daran_checksum_split(const char *line, size_t len, size_t *payload_len,
                                    uint8_t *has_checksum);

/* fields.c */
bool daran_is_blank(char c);
bool daran_byte_allowed(uint8_t byte);
void daran_split_fields(const char *text, size_t len, daran_fields_t *out);
bool daran_field_equals(const daran_field_t *field, const char *text, size_t len);

/* command_table.c */
const daran_command_t *daran_find_command(const daran_field_t *word);
extern const daran_command_t daran_commands[];
extern const uint8_t daran_command_count;

/* property_table.c */
extern const daran_property_t daran_properties[DARAN_PROP_COUNT];
/* The path of a property, without its "axisN." (not NUL-terminated). */
const char *daran_property_name(daran_prop_t prop);
/* DARAN_OK with *prop set, or DARAN_ERR_INVALID_PROPERTY. */
daran_result_t daran_find_property(daran_scope_t scope, const char *name, size_t len,
                                   daran_prop_t *prop);

/* reply.c: one line at a time in drive->reply */
void daran_reply_begin(daran_drive_t *drive);
void daran_reply_text(daran_drive_t *drive, const char *text, size_t len);
void daran_reply_cstr(daran_drive_t *drive, const char *text);
void daran_reply_f32(daran_drive_t *drive, float value);
void daran_reply_u64(daran_drive_t *drive, uint64_t value);
void daran_reply_space(daran_drive_t *drive);
void daran_reply_end(daran_drive_t *drive);
void daran_reply_error(daran_drive_t *drive, daran_result_t result);

/* framer.c */
void daran_framer_reset(daran_drive_t *drive);
/* Returns true when the byte completed a line (processed or rejected). */
bool daran_framer_feed(daran_drive_t *drive, uint8_t byte, bool damaged);

/* drive.c: a framed line whose length and characters are known good. */
daran_result_t daran_execute_line(daran_drive_t *drive, const char *line, size_t len);

/* values.c helpers shared by the handlers (commands_common.c) */
daran_result_t daran_field_f32(const daran_field_t *field, float *out);
daran_result_t daran_field_positive(const daran_field_t *field, float *out);
daran_result_t daran_field_non_negative(const daran_field_t *field, float *out);
/* Modes as a bit set: bit m set = mode m allowed (modes are below 32). */
#define DARAN_MODES_VELOCITY ((1u << 1) | (1u << 2))
#define DARAN_MODES_TORQUE ((1u << 1) | (1u << 2) | (1u << 6))
#define DARAN_MODES_START ((1u << 0) | (1u << 1))
/* An integer mode field: DARAN_ERR_INVALID_VALUE when malformed or not an
 * integer, DARAN_ERR_INVALID_MODE when an integer outside @p allowed. */
daran_result_t daran_field_mode(const daran_field_t *field, uint32_t allowed, uint32_t *out);
/* v/mv and c/mc: the move for (target, param, mode), with the ramp check of D11. */
daran_result_t daran_velocity_move(float vel, float param, uint32_t mode, daran_move_t *move);
daran_result_t daran_torque_move(float torque, float param, uint32_t mode, daran_move_t *move);
daran_result_t daran_field_motor(const daran_field_t *field, uint8_t *out);
daran_result_t daran_get(daran_drive_t *drive, daran_prop_t prop, daran_value_t *out);
/* The drive accepts motion: closed loop, no blocking flag. */
daran_result_t daran_check_motion_allowed(daran_drive_t *drive);
/* Hand a validated move to the HAL and feed the watchdog. */
daran_result_t daran_start_move(daran_drive_t *drive, const daran_move_t *move);
bool daran_is_finite(float value);

/* The handlers, one per command family. */
daran_result_t daran_cmd_t(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_q(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_p(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_v(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_c(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_d(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_ms(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_mt(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_mq(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_mp(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_mv(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_mc(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_r(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_w(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_action(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_h(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_f(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_g(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_i(daran_drive_t *drive, const daran_request_t *request);
daran_result_t daran_cmd_e(daran_drive_t *drive, const daran_request_t *request);

#endif /* DARAN_INTERNAL_H */
