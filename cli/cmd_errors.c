/* PLACEHOLDER: replaced by its owner (issue 22). */
#include "commands.h"
static cli_status_t run_errors(cli_session_t *s, int argc, char **argv)
{
    (void)s;
    (void)argc;
    (void)argv;
    return cli_fail(CLI_USAGE, "errors: not built yet");
}
const cli_command_t cli_cmd_errors = {.name = "errors", .synopsis = "ID", .summary = "(not built yet)", .help = NULL, .run = run_errors};
static cli_status_t run_clear(cli_session_t *s, int argc, char **argv)
{
    (void)s;
    (void)argc;
    (void)argv;
    return cli_fail(CLI_USAGE, "clear: not built yet");
}
const cli_command_t cli_cmd_clear = {.name = "clear", .synopsis = "ID", .summary = "(not built yet)", .help = NULL, .run = run_clear};
