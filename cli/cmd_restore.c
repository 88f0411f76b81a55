/* restore (docs/cli.md, "dump, restore"): a dump written back into a
 * drive, all or nothing. A line the drive refuses, one a gateway could not
 * send, or one whose read-back goes unanswered (it may have taken effect),
 * stops the restore and the drive's previous values are written back;
 * "back" is said only of values read again as they were. */
#include <signal.h>
#include <string.h>

#include "commands.h"
#include "dump_drive.h"
#include "dump_file.h"

typedef struct restore {
    uint8_t id;
    const char *name;
    dump_file_t file; /* its paths as sent to drive id */
    char before[CLI_PROPERTIES_MAX][DUMP_VALUE_MAX]; /* what the drive had */
    size_t written;      /* entries written (in file order) */
    size_t compared;     /* entries read again once all were written */
    size_t differences;  /* written values the drive kept otherwise */
    const dump_entry_t *failed; /* the line that stopped the restore; NULL: none */
    const char *failure;        /* the drive's refusal, or "no reply" / "bus error" /
                                   "damaged reply" */
    size_t written_back; /* lines written back after it, each read back as it was */
    bool rolled_back;    /* every changed line written back, then all read again as they were */
} restore_t;

static daran_client_scope_t scope_of(const dump_entry_t *e)
{
    return e->axis ? DARAN_CLIENT_SCOPE_AXIS : DARAN_CLIENT_SCOPE_SYSTEM;
}

/* Write back what the drive had in lines [0, count), in file order (the
 * order a restore of a dump of those values would take), each with its
 * read-back; then read them all again, since a later write-back can change
 * an earlier one (two views of one value). CLI_OK: every one reads as it
 * was. Otherwise why[] tells how far it got and what stopped it. Stops at
 * the first failure: a drive that does not answer would fail the rest. */
static cli_status_t restore_roll_back(cli_session_t *s, restore_t *r, size_t count, char *why,
                                      size_t size)
{
    r->written_back = 0;
    for (size_t i = 0; i < count; i++) {
        const dump_entry_t *e = &r->file.entries[i];
        daran_client_value_t value;
        cli_read_back_t back;
        int head = snprintf(why, size, "%zu of %zu lines written back, each read back as it "
                            "was; then ", i, count);
        size_t at = head > 0 && (size_t)head < size ? (size_t)head : 0;
        if (!cli_parse_value(r->before[i], &value)) {
            (void)snprintf(why + at, size - at, "line %u's %s had %s, which cannot be written "
                           "back", e->line, e->path, r->before[i]);
            return CLI_DRIVE_ERROR;
        }
        cli_status_t status =
            cli_write_read_back_scoped(s, r->id, e->path, scope_of(e), &value, &back);
        if (status == CLI_DRIVE_ERROR) {
            (void)snprintf(why + at, size - at, "drive %u refused %s %s (line %u): %s", r->id,
                           e->path, r->before[i], e->line, daran_result_phrase(back.refused));
            return status;
        }
        if (status != CLI_OK) {
            (void)snprintf(why + at, size - at, "%s", back.failure);
            return status;
        }
        if (!cli_same_number(back.kept, r->before[i])) {
            (void)snprintf(why + at, size - at, "drive %u keeps %s for %s (line %u), which had %s",
                           r->id, back.kept, e->path, e->line, r->before[i]);
            return CLI_DRIVE_ERROR;
        }
        r->written_back++;
    }
    for (size_t i = 0; i < count; i++) {
        const dump_entry_t *e = &r->file.entries[i];
        char now[DUMP_VALUE_MAX];
        char failure[CLI_FAILURE_MAX];
        daran_result_t refused;
        int head = snprintf(why, size, "all %zu lines written back, each read back as it was; "
                            "then, reading them again, ", count);
        size_t at = head > 0 && (size_t)head < size ? (size_t)head : 0;
        cli_status_t status =
            dump_read_value(s, r->id, e->path, now, sizeof now, &refused, failure, sizeof failure);
        if (status == CLI_DRIVE_ERROR) {
            (void)snprintf(why + at, size - at, "drive %u refused to read %s (line %u): %s",
                           r->id, e->path, e->line, daran_result_phrase(refused));
            return status;
        }
        if (status != CLI_OK) {
            (void)snprintf(why + at, size - at, "%s", failure);
            return status;
        }
        if (!cli_same_number(now, r->before[i])) {
            (void)snprintf(why + at, size - at, "%s (line %u) reads %s; it had %s", e->path,
                           e->line, now, r->before[i]);
            return CLI_DRIVE_ERROR;
        }
    }
    why[0] = '\0';
    return CLI_OK;
}

static void print_difference(const cli_session_t *s, const restore_t *r, const dump_entry_t *e,
                             const char *kept)
{
    if (s->options.json) {
        fprintf(stdout, "%s{\"line\":%u", r->differences > 0 ? "," : "", e->line);
        cli_json_member(stdout, "path", e->path);
        dump_json_value(stdout, "file", e->value, strlen(e->value));
        dump_json_value(stdout, "kept", kept, strlen(kept));
        putchar('}');
    } else {
        printf("%s:%u: %s: drive %u keeps %s (the file has %s)\n", r->name, e->line, e->path,
               r->id, kept, e->value);
    }
}

/* What stopped the restore at entry e, as the message and JSON say it. */
static void describe_failure(restore_t *r, const dump_entry_t *e, cli_status_t status,
                             const cli_read_back_t *back, char *what, size_t size)
{
    r->failed = e;
    if (status != CLI_DRIVE_ERROR) {
        (void)snprintf(what, size, "%s", back->failure);
        r->failure = back->result == DARAN_ERR_NO_REPLY || back->result == DARAN_ERR_BUS_ERROR
                         ? daran_result_phrase(back->result)
                         : "damaged reply";
        return;
    }
    char line[DARAN_CLIENT_LINE_MAX];
    dump_write_line(line, sizeof line, r->id, e->path, e->value);
    (void)snprintf(what, size, "drive %u refused `%s`: %s%s%s%s", r->id, line,
                   daran_result_phrase(back->refused), back->kept[0] != '\0' ? " (it keeps " : "",
                   back->kept, back->kept[0] != '\0' ? ")" : "");
    r->failure = daran_result_phrase(back->refused);
}

/* Write every line; at the first one that fails, write back what may have
 * changed: the lines before it, and that one too unless it had no effect
 * (refused, or never sent: a gateway's bus error). */
static cli_status_t restore_write(cli_session_t *s, restore_t *r)
{
    cli_read_back_t back;
    for (size_t i = 0; i < r->file.count; i++) {
        const dump_entry_t *e = &r->file.entries[i];
        cli_status_t status =
            cli_write_read_back_scoped(s, r->id, e->path, scope_of(e), &e->parsed, &back);
        if (status == CLI_OK) {
            r->written++; /* what it kept is compared once all are written */
            continue;
        }
        if (s->port_failed) {
            return cli_fail(status, "%s; drive %u may be half-restored: %zu of %zu lines written",
                            back.failure, r->id, r->written, r->file.count);
        }
        size_t changed = back.may_have_taken_effect ? i + 1 : i;
        char what[CLI_FAILURE_MAX];
        describe_failure(r, e, status, &back, what, sizeof what);
        char why[2 * CLI_FAILURE_MAX];
        cli_status_t undone = restore_roll_back(s, r, changed, why, sizeof why);
        r->rolled_back = undone == CLI_OK;
        if (!r->rolled_back) {
            return cli_fail(undone > status ? undone : status, "%s:%u: %s; drive %u may be "
                            "half-restored: %s", r->name, e->line, what, r->id, why);
        }
        return cli_fail(status, "%s:%u: %s; drive %u's previous values are back%s (%zu line%s "
                        "written back, then all read again as they were)", r->name, e->line,
                        what, r->id, back.may_have_taken_effect ? ", that line's too" : "",
                        changed, changed == 1 ? "" : "s");
    }
    return CLI_OK;
}

/* What the drive kept of each line once all are written: a later line can
 * change an earlier one (two views of one value, a gear ratio). */
static cli_status_t restore_compare(cli_session_t *s, restore_t *r)
{
    for (size_t i = 0; i < r->file.count; i++) {
        const dump_entry_t *e = &r->file.entries[i];
        char kept[DUMP_VALUE_MAX];
        char why[CLI_FAILURE_MAX];
        daran_result_t refused;
        cli_status_t status =
            dump_read_value(s, r->id, e->path, kept, sizeof kept, &refused, why, sizeof why);
        if (status == CLI_DRIVE_ERROR) {
            return cli_fail(status, "%s:%u: drive %u wrote %s but cannot read it back: %s",
                            r->name, e->line, r->id, e->path, daran_result_phrase(refused));
        }
        if (status != CLI_OK) {
            return cli_fail(status, "%s:%u: %s; all %zu lines were written and read back, but "
                            "reading them again stopped there: what drive %u keeps from line %u "
                            "on is unchecked", r->name, e->line, why, r->file.count, r->id,
                            e->line);
        }
        r->compared++;
        if (!cli_same_number(kept, e->value)) {
            print_difference(s, r, e, kept);
            r->differences++;
        }
    }
    return CLI_OK;
}

static cli_status_t restore_check_firmware(cli_session_t *s, const restore_t *r, bool force)
{
    drive_version_t version;
    cli_status_t status = dump_read_version(s, r->id, &version);
    if (status != CLI_OK || force) {
        return status;
    }
    char firmware[DUMP_VALUE_MAX];
    size_t len = version.field[0].len < sizeof firmware ? version.field[0].len : sizeof firmware - 1;
    memcpy(firmware, version.field[0].text, len);
    firmware[len] = '\0';
    if (!cli_same_number(firmware, r->file.firmware)) {
        return cli_fail(CLI_DRIVE_ERROR, "%s was dumped from firmware %s; drive %u runs firmware "
                        "%s (--force restores it anyway)", r->name, r->file.firmware, r->id,
                        firmware);
    }
    return CLI_OK;
}

/* What each line's property holds now, so a refusal can be undone. */
static cli_status_t restore_read_before(cli_session_t *s, restore_t *r)
{
    for (size_t i = 0; i < r->file.count; i++) {
        const dump_entry_t *e = &r->file.entries[i];
        char why[CLI_FAILURE_MAX];
        daran_result_t refused;
        cli_status_t status = dump_read_value(s, r->id, e->path, r->before[i],
                                              sizeof r->before[i], &refused, why, sizeof why);
        if (status == CLI_DRIVE_ERROR) {
            return cli_fail(status, "%s:%u: drive %u cannot read %s: %s; nothing was written",
                            r->name, e->line, r->id, e->path, daran_result_phrase(refused));
        }
        if (status != CLI_OK) {
            return cli_fail(status, "%s:%u: %s; nothing was written", r->name, e->line, why);
        }
    }
    return CLI_OK;
}

static cli_status_t restore_save(cli_session_t *s, uint8_t id)
{
    daran_client_request_t request = {.command = DARAN_CLIENT_CMD_SS, .id = id};
    return cli_transact(s, &request, NULL, NULL, false, NULL);
}

/* The arguments: ID FILE [--save] [--force]. */
static cli_status_t restore_parse_args(int argc, char **argv, restore_t *r, bool *save,
                                       bool *force)
{
    int positional = 0;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--save") == 0) {
            *save = true;
        } else if (strcmp(argv[i], "--force") == 0) {
            *force = true;
        } else if (strncmp(argv[i], "--", 2) == 0) {
            return cli_usage(&cli_cmd_restore, "no option %s", argv[i]);
        } else if (positional == 0) {
            if (!cli_parse_id(argv[i], false, &r->id)) {
                return cli_usage(&cli_cmd_restore, "\"%s\" is not a motor id (1..63)", argv[i]);
            }
            positional++;
        } else if (positional == 1) {
            r->name = argv[i];
            positional++;
        } else {
            return cli_usage(&cli_cmd_restore, "one drive and one file (\"%s\" too many)",
                             argv[i]);
        }
    }
    if (positional != 2) {
        return cli_usage(&cli_cmd_restore, "a drive id and a file are needed");
    }
    return CLI_OK;
}

/* Everything before the first write: the file, the drive's firmware and
 * what it holds now. */
static cli_status_t restore_prepare(cli_session_t *s, restore_t *r, bool force)
{
    cli_status_t status = dump_file_read(r->name, r->id, &r->file);
    if (status != CLI_OK) {
        return status;
    }
    if (r->file.count == 0) {
        return cli_fail(CLI_USAGE, "%s: no `w` line to restore", r->name);
    }
    if (r->file.firmware[0] == '\0' && !force) {
        return cli_fail(CLI_USAGE, "%s names no firmware (no `" DUMP_FIRMWARE_HEAD "…` line); "
                        "--force restores it anyway", r->name);
    }
    status = cli_session_connect(s);
    if (status == CLI_OK) {
        status = restore_check_firmware(s, r, force);
    }
    if (status == CLI_OK) {
        status = restore_read_before(s, r);
    }
    return status;
}

static void restore_print_outcome(const cli_session_t *s, const restore_t *r, bool saved_to_nvm)
{
    if (s->options.json) {
        printf("],\"lines\":%zu,\"written\":%zu,\"complete\":%s,\"compared\":%zu,"
               "\"saved\":%s", r->file.count, r->written,
               r->written == r->file.count ? "true" : "false", r->compared,
               saved_to_nvm ? "true" : "false");
        if (r->failed != NULL) {
            printf(",\"failed\":{\"line\":%u", r->failed->line);
            cli_json_member(stdout, "path", r->failed->path);
            dump_json_value(stdout, "value", r->failed->value, strlen(r->failed->value));
            cli_json_member(stdout, "error", r->failure);
            printf("},\"written_back\":%zu,\"rolled_back\":%s", r->written_back,
                   r->rolled_back ? "true" : "false");
        }
        puts("}");
    } else if (r->compared == r->file.count) {
        printf("drive %u: %zu properties restored from %s, %s", r->id, r->written, r->name,
               r->differences == 0 ? "each kept as written" : "");
        if (r->differences > 0) {
            printf("%zu kept otherwise (above)", r->differences);
        }
        printf("%s\n", saved_to_nvm ? "; saved (ss)" : "");
    }
    fflush(stdout);
}

/* Write, compare and (--save) save, with Ctrl-C held back: cut short, a
 * restore would leave the drive half-configured. */
static cli_status_t restore_apply(cli_session_t *s, restore_t *r, bool save)
{
    sigset_t block;
    sigset_t saved;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    sigaddset(&block, SIGHUP);
    sigprocmask(SIG_BLOCK, &block, &saved);
    r->written = 0;
    r->compared = 0;
    r->differences = 0;
    r->failed = NULL;
    r->written_back = 0;
    r->rolled_back = false;
    if (s->options.json) {
        printf("{\"id\":%u", r->id);
        cli_json_member(stdout, "file", r->name);
        fputs(",\"differences\":[", stdout);
    }
    cli_status_t status = restore_write(s, r);
    if (status == CLI_OK) {
        status = restore_compare(s, r);
    }
    bool saved_to_nvm = false;
    if (status == CLI_OK && save) {
        status = restore_save(s, r->id);
        saved_to_nvm = status == CLI_OK;
    }
    restore_print_outcome(s, r, saved_to_nvm);
    sigprocmask(SIG_SETMASK, &saved, NULL);
    return status;
}

static cli_status_t run_restore(cli_session_t *s, int argc, char **argv)
{
    static restore_t r; /* 60 KiB: kept off the stack */
    bool save = false;
    bool force = false;
    cli_status_t status = restore_parse_args(argc, argv, &r, &save, &force);
    if (status == CLI_OK) {
        status = restore_prepare(s, &r, force);
    }
    return status == CLI_OK ? restore_apply(s, &r, save) : status;
}

const cli_command_t cli_cmd_restore = {
    .name = "restore",
    .synopsis = "ID FILE [--save] [--force]",
    .summary = "write a dump back into a drive, all or nothing",
    .help = "Reads FILE (a dump: `w` lines and `#` comments), refuses it when its firmware\n"
            "is not the drive's (unless --force), reads every value the drive has, then\n"
            "writes each line to drive ID (its id or axisN replaced by ID) and reads it back,\n"
            "printing each value the drive kept otherwise. At the first line the drive\n"
            "refuses (exit status 1), that a CAN gateway could not send (exit status 5),\n"
            "or whose read-back gets no answer (exit status 3, or 5 when the gateway could\n"
            "not send the read-back: that line may have taken effect), it writes back the\n"
            "values it had changed, that line's too when it may have, reads them all again\n"
            "and stops; it says \"back\" only when every one reads as it was.\n"
            "A line that would change the node id, a setpoint, the drive's state, an error\n"
            "register, the shaft's zero or telemetry.period is a format error (exit 2):\n"
            "a restore never writes them. --save: `ss ID` after a complete restore.\n",
    .run = run_restore,
};
