/* daran: the command line (docs/cli.md). The options every command shares
 * may stand anywhere before `--`; the rest is the command and its own
 * arguments. */
#include <stdlib.h>
#include <string.h>

#include "commands.h"
#include "daran_version.h"
#include "serial.h"

static const char usage_head[] =
    "Usage: daran [OPTIONS] COMMAND [ARGUMENTS...]\n"
    "Talk to Daran servo drives (or anything speaking their ASCII protocol) on a\n"
    "serial port.\n"
    "\n"
    "Options:\n"
    "  --port PATH    the serial port (default: $DARAN_PORT, else the one\n"
    "                 /dev/ttyACM* or /dev/ttyUSB* there is)\n"
    "  --baud N       line speed (default 115200)\n"
    "  --checksum     send every line with ` *N` and require it on every reply\n"
    "  --timeout S    seconds a request waits for its reply (default 0.2)\n"
    "  --json         print one JSON document instead of text\n"
    "  --help         this text; `daran COMMAND --help` for one command\n"
    "  --version      the tool's version\n"
    "\n"
    "Commands:\n";

static const char usage_tail[] =
    "\n"
    "Exit status: 0 done, 1 a drive answered an error (or refused a value),\n"
    "2 usage, 3 no reply (or a damaged one), 4 port error, 5 a CAN gateway could\n"
    "not send the request on its bus. docs/cli.md has more.\n";

static void print_command_line(FILE *out, const cli_command_t *command)
{
    char head[256];
    (void)snprintf(head, sizeof head, "%s %s", command->name, command->synopsis);
    if (strlen(head) > 40) { /* a long synopsis whole on its line, the summary below */
        fprintf(out, "  %s\n  %-40s %s\n", head, "", command->summary);
    } else {
        fprintf(out, "  %-40s %s\n", head, command->summary);
    }
}

static void print_usage(FILE *out)
{
    fputs(usage_head, out);
    size_t count;
    const cli_command_t *const *tools = cli_commands(&count);
    for (size_t i = 0; i < count; i++) {
        print_command_line(out, tools[i]);
    }
    print_command_line(out, &cli_cmd_shell);
    fputs(usage_tail, out);
}

static void print_command_help(const cli_command_t *command)
{
    printf("Usage: daran [OPTIONS] %s %s\n%s\n", command->name, command->synopsis,
           command->summary);
    if (command->help != NULL) {
        printf("\n%s", command->help);
    }
}

/* Take the shared options out of argv (in place); argv keeps the rest. */
static cli_status_t take_options(int *argc, char **argv, cli_options_t *options, bool *help,
                                 bool *version)
{
    int kept = 1;
    bool options_end = false;
    for (int i = 1; i < *argc; i++) {
        const char *arg = argv[i];
        const char *value = i + 1 < *argc ? argv[i + 1] : NULL;
        if (options_end || arg[0] != '-' || arg[1] != '-') {
            argv[kept++] = argv[i];
            continue;
        }
        if (strcmp(arg, "--") == 0) {
            options_end = true;
        } else if (strcmp(arg, "--help") == 0) {
            *help = true;
        } else if (strcmp(arg, "--version") == 0) {
            *version = true;
        } else if (strcmp(arg, "--checksum") == 0) {
            options->checksum = true;
        } else if (strcmp(arg, "--json") == 0) {
            options->json = true;
        } else if (strcmp(arg, "--port") == 0 || strcmp(arg, "--baud") == 0 ||
                   strcmp(arg, "--timeout") == 0) {
            if (value == NULL) {
                return cli_fail(CLI_USAGE, "%s needs a value (daran --help)", arg);
            }
            i++;
            if (arg[2] == 'p') {
                options->port = value;
            } else if (arg[2] == 'b') {
                char *end;
                unsigned long baud = strtoul(value, &end, 10);
                if (*end != '\0' || !cli_serial_baud_supported((uint32_t)baud) ||
                    baud > UINT32_MAX) {
                    return cli_fail(CLI_USAGE, "--baud %s: not a speed the port can take", value);
                }
                options->baud = (uint32_t)baud;
            } else if (!cli_parse_seconds(value, &options->timeout_ms) ||
                       options->timeout_ms == 0) {
                return cli_fail(CLI_USAGE, "--timeout %s: not a time in seconds (0.001..3600)",
                                value);
            } else {
                options->timeout_given = true;
            }
        } else {
            argv[kept++] = argv[i]; /* the command's own option */
        }
    }
    *argc = kept;
    argv[kept] = NULL;
    return CLI_OK;
}

int main(int argc, char **argv)
{
    cli_options_t options = {
        .port = NULL, .baud = CLI_DEFAULT_BAUD, .timeout_ms = CLI_DEFAULT_TIMEOUT_MS};
    bool help = false;
    bool version = false;
    cli_status_t status = take_options(&argc, argv, &options, &help, &version);
    if (status != CLI_OK) {
        return (int)status;
    }
    if (version) {
        printf("daran %d.%d.%d\n", DARAN_VERSION_MAJOR, DARAN_VERSION_MINOR, DARAN_VERSION_PATCH);
        return CLI_OK;
    }
    if (argc < 2) {
        print_usage(help ? stdout : stderr);
        return help ? CLI_OK : CLI_USAGE;
    }
    const cli_command_t *command = cli_command_or_shell(argv[1]);
    if (command == NULL) {
        if (strcmp(argv[1], "help") == 0) {
            command = argc > 2 ? cli_command_or_shell(argv[2]) : NULL;
            if (command == NULL) {
                print_usage(stdout);
            } else {
                print_command_help(command);
            }
            return CLI_OK;
        }
        fprintf(stderr, "daran: no command \"%s\" (daran --help lists them)\n", argv[1]);
        return CLI_USAGE;
    }
    if (help) {
        print_command_help(command);
        return CLI_OK;
    }
    cli_session_t *session = malloc(sizeof *session);
    if (session == NULL) {
        return (int)cli_fail(CLI_PORT_ERROR, "out of memory");
    }
    cli_session_init(session, &options);
    status = command->run(session, argc - 2, argv + 2);
    fflush(stdout);
    cli_session_close(session);
    free(session);
    return (int)status;
}
