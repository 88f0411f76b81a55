/* The command stage: a line's word -> its command row (command_table.c) or
 * the port's command (port_commands.c), and the request a handler gets. */
#ifndef DARAN_COMMAND_H
#define DARAN_COMMAND_H

#include <stdint.h>

#include "daran_drive.h"
#include "daran_protocol.h"
#include "line.h"

struct daran_command;
struct daran_port_command;

/* One request on its way from the table to the HAL (also what a port
 * command's handler gets, as daran_args_t). */
typedef struct daran_request {
    const struct daran_command *command; /* NULL for a port command */
    const char *line;
    const daran_fields_t *fields;
    uint8_t motor;     /* addressed id; 0 = every drive */
    daran_prop_t prop; /* r/w only */
} daran_request_t;

/* Field i of a request's line. */
static inline daran_field_t daran_field_at(const daran_request_t *request, unsigned i)
{
    return daran_field_of(request->line, request->fields, i);
}

/* Command flags. */
#define DARAN_CMD_READ 0x01u /* answered for id 0 and never forwarded */
#define DARAN_CMD_PATH 0x02u /* the id comes from a property path (r, w) */
/* Bits 2..5: the row's CAN form (daran_protocol.h's CAN column), which the
 * bridge sends for a line addressed to a drive behind it. */
#define DARAN_CMD_CAN_SHIFT 2u
typedef enum daran_can_form {
    DARAN_CAN_FORM_NONE, /* no CAN form: `not bridged` for another drive */
    DARAN_CAN_FORM_MOTION,
    DARAN_CAN_FORM_IMPEDANCE,
    DARAN_CAN_FORM_PRESET,
    DARAN_CAN_FORM_START,
    DARAN_CAN_FORM_READ,
    DARAN_CAN_FORM_WRITE,
    DARAN_CAN_FORM_ACTION,
    DARAN_CAN_FORM_READ_LIST,
    DARAN_CAN_FORM_LOCAL
} daran_can_form_t;
#define DARAN_CMD_CAN_FORM(command) ((daran_can_form_t)((command)->flags >> DARAN_CMD_CAN_SHIFT))

/* The properties query rows answer (daran_protocol.h's DARAN_QUERY_*), one
 * list after another (commands_query.c). A query row's arg is where its
 * list starts << 3 | its length. */
extern const daran_prop_t daran_query_props[];
#define DARAN_QUERY_ONE_(name) +1
enum daran_query_ends {
    DARAN_QUERY_END_F = 0 DARAN_QUERY_F(DARAN_QUERY_ONE_),
    DARAN_QUERY_END_G = DARAN_QUERY_END_F DARAN_QUERY_G(DARAN_QUERY_ONE_),
    DARAN_QUERY_END_I = DARAN_QUERY_END_G DARAN_QUERY_I(DARAN_QUERY_ONE_),
    DARAN_QUERY_END_E = DARAN_QUERY_END_I DARAN_QUERY_E(DARAN_QUERY_ONE_)
};
#undef DARAN_QUERY_ONE_
#define DARAN_QUERY_ARG_(start, end) ((start) << 3 | ((end) - (start)))
#define DARAN_QUERY_LIST_F DARAN_QUERY_ARG_(0, DARAN_QUERY_END_F)
#define DARAN_QUERY_LIST_G DARAN_QUERY_ARG_(DARAN_QUERY_END_F, DARAN_QUERY_END_G)
#define DARAN_QUERY_LIST_I DARAN_QUERY_ARG_(DARAN_QUERY_END_G, DARAN_QUERY_END_I)
#define DARAN_QUERY_LIST_E DARAN_QUERY_ARG_(DARAN_QUERY_END_I, DARAN_QUERY_END_E)
#define DARAN_QUERY_LIST_NONE 0


/* 4 bytes a row; the row's handler is in a parallel table made from the
 * same list (command_table.c), so a row stays small. */
typedef struct daran_command {
    char word[2];   /* lower case; word[1] is 0 for one-letter words */
    uint8_t fields; /* min << 4 | max, command word included */
    uint8_t flags;
    uint8_t arg; /* handler-specific: the shape of a motion command, the HAL action of a system one */
} daran_command_t;

/* The step an UPDATE row names (daran_protocol.h's ARG column). */
typedef enum daran_update_op {
    DARAN_UPDATE_OP_BEGIN,
    DARAN_UPDATE_OP_WRITE,
    DARAN_UPDATE_OP_VERIFY,
    DARAN_UPDATE_OP_COMMIT,
    DARAN_UPDATE_OP_CONFIRM,
    DARAN_UPDATE_OP_ABORT,
    DARAN_UPDATE_OP_STATUS
} daran_update_op_t;

/* A query row's properties and their count. */
static inline const daran_prop_t *daran_query_of(const daran_command_t *command, uint8_t *count)
{
    *count = command->arg & 7u;
    return daran_query_props + (command->arg >> 3);
}

#define DARAN_MIN_FIELDS(command) ((command)->fields >> 4)
#define DARAN_MAX_FIELDS(command) ((command)->fields & 0x0Fu)

/* command_table.c: the core's command of that word, or NULL. */
const daran_command_t *daran_find_command(const daran_field_t *word);
/* DARAN_OK from the command's handler, or its error. */
daran_result_t daran_run_command(daran_drive_t *drive, const daran_request_t *request);


#endif /* DARAN_COMMAND_H */
