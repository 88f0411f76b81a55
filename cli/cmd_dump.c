/* PLACEHOLDER: replaced by its owner (issue 22). */
#include "commands.h"
static cli_status_t run_dump(cli_session_t *s, int argc, char **argv)
{
    (void)s;
    (void)argc;
    (void)argv;
    return cli_fail(CLI_USAGE, "dump: not built yet");
}
const cli_command_t cli_cmd_dump = {.name = "dump", .synopsis = "ID", .summary = "(not built yet)", .help = NULL, .run = run_dump};
static cli_status_t run_restore(cli_session_t *s, int argc, char **argv)
{
    (void)s;
    (void)argc;
    (void)argv;
    return cli_fail(CLI_USAGE, "restore: not built yet");
}
const cli_command_t cli_cmd_restore = {.name = "restore", .synopsis = "ID", .summary = "(not built yet)", .help = NULL, .run = run_restore};
