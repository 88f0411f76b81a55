/* shell (docs/cli.md, "shell"): an interactive session on one port. Each
 * line is one of the tool's commands, run on the session's port, or a
 * protocol line, sent as it is with its reply printed; telemetry reports
 * are shown apart (shell_term.c), Tab completes (shell_complete.c). */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "commands.h"
#include "shell.h"

/* The most words a command line of the tool takes in the shell. */
#define TOOL_ARGS_MAX 64

/* ------------------------------------------------------------ help */

static void print_help(const char *topic)
{
    const cli_command_t *command = topic[0] != '\0' ? cli_command_or_shell(topic) : NULL;
    if (command != NULL) {
        printf("%s %s\n%s\n", command->name, command->synopsis, command->summary);
        if (command->help != NULL) {
            printf("\n%s", command->help);
        }
        return;
    }
    if (topic[0] != '\0') {
        printf("no command \"%s\"; ", topic);
    }
    printf("a line is one of the tool's commands, as after `daran` (`help COMMAND` tells\n"
           "its arguments; --json and --timeout S may follow them):\n");
    size_t count;
    const cli_command_t *const *commands = cli_commands(&count);
    for (size_t i = 0; i < count; i++) {
        printf("  %-8s %s\n", commands[i]->name, commands[i]->summary);
    }
    printf("or a protocol line, sent as it is (`f 1`, `t 1 90`, `r axis1.output_shaft.vel_limit`),\n"
           "its reply printed; the protocol's words:\n ");
    const char *words[64];
    count = shell_command_words(words, sizeof words / sizeof words[0]);
    for (size_t i = 0; i < count; i++) {
        if (cli_command_find(words[i]) == NULL && strcmp(words[i], "help") != 0 &&
            strcmp(words[i], "quit") != 0 && strcmp(words[i], "exit") != 0) {
            printf(" %s", words[i]);
        }
    }
    printf("\nor: help [COMMAND], quit (or exit, or Ctrl-D).\n"
           "Tab completes command words and property paths. Telemetry reports show as\n"
           "`@ID t=TIME name=value...` on lines of their own.\n");
}

/* ------------------------------------------------------------ protocol lines */

static void print_reply_line(void *ctx, const daran_client_line_t *line)
{
    (void)ctx;
    printf("%.*s\n", (int)line->len, line->payload);
}

/* Send a protocol line as it is and print its reply: the lines as they
 * come, `error: <phrase>` for the drive's error; no reply or a damaged one
 * is told on stderr. */
static void run_protocol_line(shell_t *sh, const char *line)
{
    cli_session_t *s = sh->s;
    size_t len = strlen(line);
    bool known;
    daran_client_reply_shape_t shape = daran_client_line_shape(line, len, &known);
    if (!known) {
        shape = DARAN_CLIENT_REPLY_UNTIL_QUIET; /* a port's own command: lines, or none */
    }
    daran_client_outcome_t outcome;
    daran_result_t result = daran_client_transact_line(&s->link, line, len, shape,
                                                       s->options.timeout_ms, print_reply_line,
                                                       NULL, &outcome);
    if (result == DARAN_OK || s->port_failed) {
        return; /* a port failure ends the shell, reported there */
    }
    if (outcome.drive_error) {
        printf("error: %s\n", daran_result_phrase(result));
    } else if (result == DARAN_ERR_NO_REPLY) {
        if (known) {
            cli_fail(CLI_NO_REPLY, "\"%s\": no reply within %u ms", line,
                     (unsigned)s->options.timeout_ms);
        } /* else silence is an answer from a command the tool does not know */
    } else if (result == DARAN_ERR_LINE_TOO_LONG) {
        cli_fail(CLI_USAGE, "\"%s\": longer than a protocol line", line);
    } else {
        cli_fail(CLI_NO_REPLY, "\"%s\": the reply was damaged (%s)", line,
                 daran_result_phrase(result));
    }
}

/* ------------------------------------------------------------ the tool's commands */

/* In the child that runs a command: the per-line options out of args
 * (--json, --timeout S), into the session. false: reported (usage). */
static bool take_line_options(cli_session_t *s, const cli_command_t *command, int *argc,
                              char **args)
{
    int kept = 0;
    for (int i = 0; i < *argc; i++) {
        if (strcmp(args[i], "--json") == 0) {
            s->options.json = true;
        } else if (strcmp(args[i], "--timeout") == 0) {
            if (i + 1 == *argc || !cli_parse_seconds(args[i + 1], &s->options.timeout_ms) ||
                s->options.timeout_ms == 0) {
                cli_usage(command, "--timeout needs a time in seconds (0.001..3600)");
                return false;
            }
            s->options.timeout_given = true;
            i++;
        } else {
            args[kept++] = args[i];
        }
    }
    args[kept] = NULL;
    *argc = kept;
    return true;
}

/* Run the command in a child process on the same port: a command that
 * takes Ctrl-C for its end (watch) ends alone, and whatever it changes in
 * the session stays with it. Returns its exit status (-1: it did not end
 * by itself). */
static int run_child(shell_t *sh, const cli_command_t *command, int argc, const char **argv)
{
    fflush(stdout);
    fflush(stderr);
    pid_t child = fork();
    if (child < 0) {
        cli_fail(CLI_PORT_ERROR, "%s: cannot start it: %s", command->name, strerror(errno));
        return -1;
    }
    if (child == 0) {
        /* A script's next lines are the shell's, not the command's. */
        int null_fd = sh->editing ? -1 : open("/dev/null", O_RDONLY);
        if (null_fd >= 0) {
            dup2(null_fd, STDIN_FILENO);
            close(null_fd);
        }
        cli_catch_signals();
        char store[SHELL_LINE_MAX + TOOL_ARGS_MAX];
        char *args[TOOL_ARGS_MAX + 1];
        size_t used = 0;
        int count = 0;
        for (int i = 1; i < argc && count < TOOL_ARGS_MAX; i++) {
            size_t len = strlen(argv[i]) + 1;
            if (used + len > sizeof store) {
                break;
            }
            args[count++] = memcpy(store + used, argv[i], len);
            used += len;
        }
        int status = take_line_options(sh->s, command, &count, args)
                         ? (int)command->run(sh->s, count, args)
                         : (int)CLI_USAGE;
        fflush(stdout);
        fflush(stderr);
        _exit(status);
    }
    int wstatus = 0;
    bool passed_on = false;
    while (waitpid(child, &wstatus, 0) < 0) {
        if (errno != EINTR) {
            cli_fail(CLI_PORT_ERROR, "%s: lost it: %s", command->name, strerror(errno));
            return -1;
        }
        if (shell_terminated() && !passed_on) {
            kill(child, SIGTERM); /* the shell ends: so does the command, cleanly */
            passed_on = true;
        }
    }
    (void)shell_take_interrupt(); /* a Ctrl-C meanwhile was the command's */
    if (WIFSIGNALED(wstatus)) {
        cli_fail(CLI_PORT_ERROR, "%s: ended by signal %d", command->name, WTERMSIG(wstatus));
        return -1;
    }
    return WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1;
}

/* A line of the tool's command: split as a shell would (quotes kept
 * together), `--help` answered here, the rest run. Returns false when the
 * port failed under it. */
static bool run_tool_line(shell_t *sh, const cli_command_t *command, const char *line)
{
    Tokenizer *tokenizer = tok_init(NULL);
    if (tokenizer == NULL) {
        cli_fail(CLI_PORT_ERROR, "out of memory");
        return true;
    }
    int argc = 0;
    const char **argv = NULL;
    bool port_alive = true;
    if (tok_str(tokenizer, line, &argc, &argv) != 0) {
        cli_fail(CLI_USAGE, "%s: a quote is not closed", command->name);
    } else if (argc > TOOL_ARGS_MAX) {
        cli_usage(command, "more than %d words", TOOL_ARGS_MAX);
    } else {
        bool help = false;
        for (int i = 1; i < argc; i++) {
            help = help || strcmp(argv[i], "--help") == 0;
        }
        if (help) {
            print_help(command->name);
        } else {
            port_alive = run_child(sh, command, argc, argv) != (int)CLI_PORT_ERROR;
        }
    }
    tok_end(tokenizer);
    return port_alive;
}

/* ------------------------------------------------------------ the session */

typedef enum line_outcome {
    LINE_DONE,    /* the next line */
    LINE_QUIT,    /* quit, exit */
    LINE_PORT_LOST /* the port failed under a command */
} line_outcome_t;

static line_outcome_t run_line(shell_t *sh, char *line)
{
    size_t len = strlen(line);
    while (len > 0 && (line[len - 1] == ' ' || line[len - 1] == '\t')) {
        line[--len] = '\0';
    }
    while (*line == ' ' || *line == '\t') {
        line++;
    }
    if (line[0] == '\0') {
        return LINE_DONE;
    }
    if (sh->editing) {
        shell_history_add(sh, line);
    }
    if (strstr(line, "telemetry.fields") != NULL) {
        shell_forget_fields(sh); /* the reports' values may be others now */
    }
    char word[16];
    size_t word_len = strcspn(line, " \t");
    (void)snprintf(word, sizeof word, "%.*s", (int)(word_len < sizeof word ? word_len : 0), line);
    if (strcmp(word, "quit") == 0 || strcmp(word, "exit") == 0) {
        return LINE_QUIT;
    }
    if (strcmp(word, "help") == 0) {
        print_help(line + word_len + strspn(line + word_len, " \t"));
        return LINE_DONE;
    }
    if (strcmp(word, cli_cmd_shell.name) == 0) {
        cli_fail(CLI_USAGE, "shell: this is the shell already");
        return LINE_DONE;
    }
    const cli_command_t *command = cli_command_find(word);
    if (command != NULL) {
        return run_tool_line(sh, command, line) ? LINE_DONE : LINE_PORT_LOST;
    }
    run_protocol_line(sh, line);
    return LINE_DONE;
}

static cli_status_t run_shell(cli_session_t *s, int argc, char **argv)
{
    shell_t *sh = calloc(1, sizeof *sh);
    if (sh == NULL) {
        return cli_fail(CLI_PORT_ERROR, "out of memory");
    }
    if (argc > 1) {
        free(sh);
        return cli_usage(&cli_cmd_shell, "one id at most");
    }
    if (argc == 1 && !cli_parse_id(argv[0], false, &sh->default_id)) {
        free(sh);
        return cli_usage(&cli_cmd_shell, "\"%s\" is not a motor id (1..63)", argv[0]);
    }
    cli_status_t status = cli_session_connect(s);
    if (status != CLI_OK) {
        free(sh);
        return status;
    }
    sh->s = s;
    s->on_report = shell_print_report;
    s->report_ctx = sh;
    s->on_stray = shell_print_stray;
    s->stray_ctx = sh;
    shell_catch_signals();
    sh->editing = isatty(STDIN_FILENO) && isatty(STDOUT_FILENO);
    if (sh->editing && !shell_editing_open(sh)) {
        cli_fail(CLI_OK, "shell: no line editing on this terminal (libedit failed): plain lines");
        sh->editing = false;
    }
    if (sh->editing && sh->default_id != 0) {
        shell_properties_preload(sh, sh->default_id); /* for Tab, asked once */
    }
    if (sh->editing) {
        printf("daran shell on %s: `help` lists what to type, Tab completes, Ctrl-D ends.\n",
               s->port_path);
    }
    char line[SHELL_LINE_MAX];
    line_outcome_t outcome = LINE_DONE;
    while (outcome == LINE_DONE && !s->port_failed && shell_read_line(sh, line, sizeof line)) {
        outcome = run_line(sh, line);
    }
    fflush(stdout);
    status = CLI_OK;
    if (s->port_failed) {
        status = cli_port_status(s);
    } else if (outcome == LINE_PORT_LOST) {
        status = CLI_PORT_ERROR; /* the command told what failed */
    }
    shell_editing_close(sh);
    shell_properties_free(sh);
    s->on_report = NULL;
    s->on_stray = NULL;
    free(sh);
    return status;
}

const cli_command_t *cli_command_or_shell(const char *name)
{
    return strcmp(name, cli_cmd_shell.name) == 0 ? &cli_cmd_shell : cli_command_find(name);
}

const cli_command_t cli_cmd_shell = {
    .name = "shell",
    .synopsis = "[ID]",
    .summary = "an interactive session: commands and protocol lines, with history and Tab",
    .help = "Reads lines and runs each: one of the tool's commands (`get 1 vbus_voltage`,\n"
            "`errors 1`, with --json or --timeout S after it if wanted) on this port, or\n"
            "a protocol line sent as it is (`f 1`, `t 1 90`, `r vbus_voltage 1`),\n"
            "its reply printed as it comes and `error: <phrase>` for a refusal. Telemetry\n"
            "reports are shown on lines of their own as `@ID t=TIME name=value...`.\n"
            "Tab completes command words and property paths (after `r `, `w `, `get ID `,\n"
            "`set ID `) from the drive's discovery; ID names the drive for paths typed\n"
            "without `axisN.`. History is kept in $DARAN_HISTORY, else ~/.daran_history.\n"
            "`help`, `quit` (or Ctrl-D). Without a terminal, lines are read from standard\n"
            "input with no prompt. Exit status 0, or 4 when the port fails.\n",
    .run = run_shell,
};
