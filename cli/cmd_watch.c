/* PLACEHOLDER: replaced by its owner (issue 22). */
#include "commands.h"
static cli_status_t run_watch(cli_session_t *s, int argc, char **argv)
{
    (void)s;
    (void)argc;
    (void)argv;
    return cli_fail(CLI_USAGE, "watch: not built yet");
}
const cli_command_t cli_cmd_watch = {.name = "watch", .synopsis = "ID", .summary = "(not built yet)", .help = NULL, .run = run_watch};
