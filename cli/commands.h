/* The tool's commands (docs/cli.md): one table of those the shell runs,
 * used by main() and by the shell, and the shell beside it. Each command
 * parses its own arguments (after its word). */
#ifndef DARAN_CLI_COMMANDS_H
#define DARAN_CLI_COMMANDS_H

#include "cli.h"

typedef struct cli_command {
    const char *name;
    const char *synopsis; /**< the arguments, as `daran --help` shows them */
    const char *summary;  /**< one line */
    const char *help;     /**< `daran COMMAND --help`: the details, may be NULL */
    cli_status_t (*run)(cli_session_t *s, int argc, char **argv);
} cli_command_t;

extern const cli_command_t cli_cmd_scan, cli_cmd_get, cli_cmd_set, cli_cmd_send, cli_cmd_errors,
    cli_cmd_clear, cli_cmd_dump, cli_cmd_restore, cli_cmd_watch, cli_cmd_shell;

/* ------------------------------------------------------------ commands.c */

/** The command named `name` among those the shell runs (all but the shell
 * itself); NULL when there is none. */
const cli_command_t *cli_command_find(const char *name);
/** Those commands, in the order --help lists them (the shell comes after
 * them); *count set. */
const cli_command_t *const *cli_commands(size_t *count);

/* ------------------------------------------------------------ cmd_shell.c */

/** cli_command_find(), or the shell when `name` is its. */
const cli_command_t *cli_command_or_shell(const char *name);

/* ------------------------------------------------------------ fail.c */

/** Report a usage error of `command` (its synopsis follows) and return CLI_USAGE. */
cli_status_t cli_usage(const cli_command_t *command, const char *format, ...)
    __attribute__((format(printf, 2, 3)));

#endif /* DARAN_CLI_COMMANDS_H */
