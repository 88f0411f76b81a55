/* The tool's commands that run on a session (commands.h). The shell runs
 * these; it is not one of them, so this table and the shell call nothing
 * of each other's back (main.c knows the shell beside the table). */
#include <string.h>

#include "commands.h"

static const cli_command_t *const tools[] = {
    &cli_cmd_scan,  &cli_cmd_get,  &cli_cmd_set,     &cli_cmd_send,  &cli_cmd_errors,
    &cli_cmd_clear, &cli_cmd_dump, &cli_cmd_restore, &cli_cmd_watch,
};

const cli_command_t *const *cli_commands(size_t *count)
{
    *count = sizeof tools / sizeof tools[0];
    return tools;
}

const cli_command_t *cli_command_find(const char *name)
{
    for (size_t i = 0; i < sizeof tools / sizeof tools[0]; i++) {
        if (strcmp(tools[i]->name, name) == 0) {
            return tools[i];
        }
    }
    return NULL;
}
