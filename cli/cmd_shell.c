/* PLACEHOLDER: replaced by its owner (issue 22). */
#include "commands.h"
static cli_status_t run_shell(cli_session_t *s, int argc, char **argv)
{
    (void)s;
    (void)argc;
    (void)argv;
    return cli_fail(CLI_USAGE, "shell: not built yet");
}
const cli_command_t cli_cmd_shell = {.name = "shell", .synopsis = "ID", .summary = "(not built yet)", .help = NULL, .run = run_shell};
