/* The command stage: a line's word -> its command row (command_table.c) or
 * the port's command (port_commands.c), and the request a handler gets. */
#ifndef DARAN_COMMAND_H
#define DARAN_COMMAND_H

#include <stdint.h>

#include "daran_drive.h"
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

/* 5 bytes a row; the row's handler is in a parallel table made from the
 * same list (command_table.c), so a row stays small. */
typedef struct daran_command {
    char word[2];   /* lower case; word[1] is 0 for one-letter words */
    uint8_t fields; /* min << 4 | max, command word included */
    uint8_t flags;
    uint8_t arg; /* handler-specific: the shape of a motion command, the HAL action of a system one */
} daran_command_t;

#define DARAN_MIN_FIELDS(command) ((command)->fields >> 4)
#define DARAN_MAX_FIELDS(command) ((command)->fields & 0x0Fu)

/* command_table.c: the core's command of that word, or NULL. */
const daran_command_t *daran_find_command(const daran_field_t *word);
/* DARAN_OK from the command's handler, or its error. */
daran_result_t daran_run_command(daran_drive_t *drive, const daran_request_t *request);

/* port_commands.c: the port's command of that word, or NULL (always, in a
 * build without port commands: the dispatcher's branch for them goes). */
#if DARAN_ENABLE_PORT_COMMANDS
const struct daran_port_command *daran_find_port_command(const daran_drive_t *drive,
                                                         const daran_field_t *word);
#else
static inline const struct daran_port_command *daran_find_port_command(const daran_drive_t *drive,
                                                                       const daran_field_t *word)
{
    (void)drive;
    (void)word;
    return NULL;
}
#endif

#endif /* DARAN_COMMAND_H */
