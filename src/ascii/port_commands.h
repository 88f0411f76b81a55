/* The port's own commands as the drive's road finds them (port_commands.c). */
#ifndef DARAN_PORT_COMMANDS_H
#define DARAN_PORT_COMMANDS_H

#include "daran_drive.h"
#include "line.h"

struct daran_port_command;

/* port_commands.c: the port's command of that word, or NULL (always, in a
 * build without port commands: the dispatcher's branch for them goes). */
#if DARAN_ENABLE_PORT_COMMANDS
/* The command of that word among commands[0..count), or NULL. */
const struct daran_port_command *daran_port_command_in(const struct daran_port_command *commands,
                                                       size_t count, const daran_field_t *word);
static inline const struct daran_port_command *daran_find_port_command(const daran_drive_t *drive,
                                                                       const daran_field_t *word)
{
    return daran_port_command_in(drive->port_commands, drive->port_command_count, word);
}
#else
static inline const struct daran_port_command *daran_find_port_command(const daran_drive_t *drive,
                                                                       const daran_field_t *word)
{
    (void)drive;
    (void)word;
    return NULL;
}
#endif

#endif /* DARAN_PORT_COMMANDS_H */
