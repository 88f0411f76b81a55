/* A failure told as one line on stderr (cli.h, commands.h): a leaf, so the
 * commands that report and the table that lists them call nothing of each
 * other. */
#include <stdarg.h>

#include "commands.h"

cli_status_t cli_fail(cli_status_t status, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    fputs("daran: ", stderr);
    vfprintf(stderr, format, args);
    fputc('\n', stderr);
    va_end(args);
    return status;
}

cli_status_t cli_usage(const cli_command_t *command, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    fprintf(stderr, "daran: %s: ", command->name);
    vfprintf(stderr, format, args);
    fprintf(stderr, " (usage: daran %s %s)\n", command->name, command->synopsis);
    va_end(args);
    return CLI_USAGE;
}
