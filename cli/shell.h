/* daran shell (docs/cli.md, "shell"): what its parts share. cmd_shell.c
 * reads lines and runs them, shell_term.c is the terminal side (input that
 * keeps the port serviced, libedit, history, reports printed apart),
 * shell_complete.c completes command words and property paths. */
#ifndef DARAN_CLI_SHELL_H
#define DARAN_CLI_SHELL_H

#include <histedit.h>

#include "cli.h"

/* The longest input line the shell takes (a protocol line is far shorter;
 * a `set` of several properties may be longer). */
#define SHELL_LINE_MAX 1024u

/* What the shell knows of a drive's telemetry fields (the bits of
 * axisN.telemetry.fields, which name a report's values). */
typedef enum shell_fields_state {
    SHELL_FIELDS_UNKNOWN,  /* not asked yet: ask when the next report comes */
    SHELL_FIELDS_WANTED,   /* a report came: ask when the link is free */
    SHELL_FIELDS_KNOWN,    /* fields_mask holds them */
    SHELL_FIELDS_UNREADABLE /* the drive did not tell: values shown unnamed */
} shell_fields_state_t;

typedef struct shell {
    cli_session_t *s;
    uint8_t default_id;   /* `shell ID`; 0: none given */
    bool editing;         /* libedit on a terminal (else plain lines, no prompt) */
    bool at_prompt;       /* inside el_gets: a report must redraw the prompt */
    EditLine *el;
    History *history;
    char history_path[512]; /* empty: no history file */
    /* property lists for completion, loaded once per id on first use;
     * [0] is the built-in table (no drive named) */
    cli_property_list_t *properties[DARAN_CLIENT_ID_MAX + 1];
    shell_fields_state_t fields_state[DARAN_CLIENT_ID_MAX + 1];
    uint32_t fields_mask[DARAN_CLIENT_ID_MAX + 1];
} shell_t;

/* ------------------------------------------------------------ shell_term.c */

/* Catch SIGINT (ends the line being typed or waited for), SIGTERM and
 * SIGHUP (end the shell), without SA_RESTART so a wait ends at once. */
void shell_catch_signals(void);
/* A SIGINT came since the last call (and is forgotten now). */
bool shell_take_interrupt(void);
/* SIGTERM or SIGHUP came: the shell ends. */
bool shell_terminated(void);

/* Set up libedit on the terminal: prompt, history (loaded from the file),
 * Tab bound to completion, input through shell_getc. false: it could not. */
bool shell_editing_open(shell_t *sh);
/* Save the history and end libedit. */
void shell_editing_close(shell_t *sh);
/* Remember a line in the history (editing only). */
void shell_history_add(shell_t *sh, const char *line);

/* The next input line into line[0..size) (no line end): true; false at the
 * end of input (or a SIGTERM/SIGHUP, or the port failing). A SIGINT gives
 * an empty line. A line too long is reported and skipped. */
bool shell_read_line(shell_t *sh, char *line, size_t size);

/* The session's report handler: `@ID t=TIME name=value…` on a line of its
 * own (above the prompt when one is shown). */
void shell_print_report(void *ctx, const daran_client_report_t *report);
/* Lines outside any request (a late error): `(unasked) LINE`. */
void shell_print_stray(void *ctx, const daran_client_line_t *line);
/* Ask the drives whose reports came for their telemetry fields (when the
 * link is free: between lines, while waiting for a key). */
void shell_resolve_fields(shell_t *sh);
/* Forget what is known of the telemetry fields (a line may have changed them). */
void shell_forget_fields(shell_t *sh);

/* ------------------------------------------------------------ shell_complete.c */

/* libedit's completion function (bound to Tab): `EditLine *` and the key. */
unsigned char shell_complete(EditLine *el, int key);
/* The words a line can start with, for completion and `help`: the tool's
 * commands except `shell`, the shell's own words, the protocol's words.
 * Fills out[0..max) and returns how many there are. */
size_t shell_command_words(const char **out, size_t max);
/* Load drive id's property list now (before the first prompt). */
void shell_properties_preload(shell_t *sh, uint8_t id);
/* Free the cached property lists. */
void shell_properties_free(shell_t *sh);

#endif /* DARAN_CLI_SHELL_H */
