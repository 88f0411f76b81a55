/* dump and restore (docs/cli.md, "dump, restore"): a drive's configuration
 * to a file of protocol `w` lines, and back into a drive, all or nothing. */
#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "commands.h"
#include "daran_version.h"
#include "dump_file.h"

/* ------------------------------------------------------------ shared */

/* The drive's `i` line: firmware, hardware, serial number. */
typedef struct drive_version {
    cli_text_line_t line;
    cli_field_t field[3];
} drive_version_t;

static cli_status_t read_version(cli_session_t *s, uint8_t id, drive_version_t *v)
{
    daran_client_request_t request = {.command = DARAN_CLIENT_CMD_I, .id = id};
    v->line.len = 0;
    cli_status_t status = cli_transact(s, &request, cli_take_line, &v->line, false, NULL);
    if (status == CLI_OK && cli_split_fields(v->line.text, v->line.len, v->field, 3) != 3) {
        status = cli_fail(CLI_NO_REPLY, "drive %u: `i %u` answered \"%.*s\", not firmware, "
                          "hardware and serial number", id, id, (int)v->line.len, v->line.text);
    }
    return status;
}

/* `r` of one property into out. CLI_DRIVE_ERROR: the drive refused it
 * (*refused says why, nothing reported); other failures are reported. */
static cli_status_t read_value(cli_session_t *s, uint8_t id, const char *path, char *out,
                               size_t size, daran_result_t *refused)
{
    bool axis = dump_bare_path(path) != path;
    daran_client_request_t request = {
        .command = DARAN_CLIENT_CMD_R,
        .id = id,
        .path = path,
        .scope = axis ? DARAN_CLIENT_SCOPE_AXIS : DARAN_CLIENT_SCOPE_SYSTEM};
    cli_text_line_t value = {.len = 0};
    daran_result_t result;
    *refused = DARAN_OK;
    out[0] = '\0';
    cli_status_t status = cli_transact(s, &request, cli_take_line, &value, true, &result);
    if (status == CLI_DRIVE_ERROR) {
        *refused = result;
        return status;
    }
    if (status != CLI_OK) {
        return cli_transact_failed(s, &request, status, result);
    }
    if (value.len >= size) {
        return cli_fail(CLI_NO_REPLY, "drive %u: %s reads as \"%.*s\", too long for a value", id,
                        path, (int)value.len, value.text);
    }
    memcpy(out, value.text, value.len);
    out[value.len] = '\0';
    return CLI_OK;
}

/* The `w` line that gives drive `id` this value: the id in `axisN.` or last. */
static void format_write(char *buf, size_t size, uint8_t id, const char *path, const char *value)
{
    const char *bare = dump_bare_path(path);
    if (bare != path) {
        snprintf(buf, size, "w axis%u.%s %s", id, bare, value);
    } else {
        snprintf(buf, size, "w %s %s %u", path, value, id);
    }
}

static void json_text(FILE *out, const char *key, const char *text)
{
    fprintf(out, ",\"%s\":", key);
    cli_json_string(out, text, strlen(text));
}

static void json_value(FILE *out, const char *key, const char *text, size_t len)
{
    fprintf(out, ",\"%s\":", key);
    cli_json_number(out, text, len);
}

/* ------------------------------------------------------------ dump */

/* Where the dump goes: stdout, or a temporary file beside --out that is
 * renamed over it once whole (a reader never sees half a dump). */
typedef struct dump_output {
    FILE *file;
    const char *name; /* NULL: stdout */
    char temp[4096];
} dump_output_t;

static cli_status_t output_open(dump_output_t *o, const char *name)
{
    o->name = name;
    o->file = stdout;
    if (name == NULL) {
        return CLI_OK;
    }
    if ((size_t)snprintf(o->temp, sizeof o->temp, "%s.XXXXXX", name) >= sizeof o->temp) {
        return cli_fail(CLI_USAGE, "%s: path too long", name);
    }
    int fd = mkstemp(o->temp);
    if (fd < 0) {
        return cli_fail(CLI_USAGE, "%s: cannot create: %s", name, strerror(errno));
    }
    mode_t mask = umask(0); /* mkstemp's 0600 made what open() would make */
    umask(mask);
    if (fchmod(fd, 0666 & ~mask) != 0 || (o->file = fdopen(fd, "w")) == NULL) {
        int err = errno;
        close(fd);
        unlink(o->temp);
        return cli_fail(CLI_USAGE, "%s: cannot create: %s", name, strerror(err));
    }
    return CLI_OK;
}

static void output_discard(dump_output_t *o)
{
    if (o->name != NULL) {
        fclose(o->file);
        unlink(o->temp);
    }
}

static cli_status_t output_commit(dump_output_t *o)
{
    if (o->name == NULL) {
        return fflush(stdout) == 0 ? CLI_OK : cli_fail(CLI_USAGE, "stdout: %s", strerror(errno));
    }
    bool ok = fflush(o->file) == 0 && !ferror(o->file) && fsync(fileno(o->file)) == 0;
    int err = errno;
    ok = fclose(o->file) == 0 && ok;
    err = ok ? 0 : err;
    if (ok && rename(o->temp, o->name) != 0) {
        ok = false;
        err = errno;
    }
    if (!ok) {
        unlink(o->temp);
        return cli_fail(CLI_USAGE, "%s: cannot write: %s", o->name, strerror(err));
    }
    return CLI_OK;
}

/* A drive's configuration as read. */
typedef struct dump {
    uint8_t id;
    drive_version_t version;
    char date[32];
    cli_property_list_t list;
    char value[CLI_PROPERTIES_MAX][DUMP_VALUE_MAX];
    daran_result_t refused[CLI_PROPERTIES_MAX]; /* DARAN_OK: value[] holds it */
    const char *node_id;                        /* value[] of the node id; NULL: not read */
    size_t unread;                              /* refused reads that count as failures */
} dump_t;

static cli_status_t dump_read(cli_session_t *s, dump_t *d)
{
    cli_status_t status = read_version(s, d->id, &d->version);
    if (status == CLI_OK) {
        status = cli_properties_load(s, d->id, NULL, &d->list);
    }
    d->node_id = NULL;
    d->unread = 0;
    for (size_t i = 0; status == CLI_OK && i < d->list.count; i++) {
        const cli_property_t *p = &d->list.items[i];
        if (!p->writable) {
            continue;
        }
        status = read_value(s, d->id, p->path, d->value[i], sizeof d->value[i], &d->refused[i]);
        if (status == CLI_DRIVE_ERROR) {
            /* The built-in table is the vendor's: a drive may lack some rows. */
            bool absent = !d->list.from_drive && d->refused[i] == DARAN_ERR_INVALID_PROPERTY;
            d->unread += absent ? 0u : 1u;
            status = CLI_OK;
        } else if (status == CLI_OK && strcmp(dump_bare_path(p->path), DUMP_NODE_ID_PATH) == 0) {
            d->node_id = d->value[i];
        }
    }
    time_t now = time(NULL);
    struct tm utc;
    if (gmtime_r(&now, &utc) == NULL ||
        strftime(d->date, sizeof d->date, "%Y-%m-%dT%H:%M:%SZ", &utc) == 0) {
        snprintf(d->date, sizeof d->date, "unknown");
    }
    return status;
}

/* Why property i is written as a comment; NULL: it is a `w` line. */
static const char *dump_row_why(const dump_t *d, size_t i)
{
    const cli_property_t *p = &d->list.items[i];
    if (d->refused[i] != DARAN_OK) {
        return daran_result_phrase(d->refused[i]);
    }
    daran_client_value_t value;
    if (!cli_parse_value(d->value[i], &value) ||
        (value.kind == DARAN_CLIENT_VALUE_F32 && value.f32 != value.f32)) {
        return "not a value a drive takes";
    }
    return dump_not_restored_why(p->path, p->range);
}

static void dump_text(FILE *out, const dump_t *d)
{
    const cli_field_t *f = d->version.field;
    size_t restored = 0;
    for (size_t i = 0; i < d->list.count; i++) {
        restored += d->list.items[i].writable && dump_row_why(d, i) == NULL ? 1u : 0u;
    }
    fprintf(out, "# daran %s: dump of drive %u\n", DARAN_VERSION_TEXT, d->id);
    fprintf(out, DUMP_FIRMWARE_HEAD "%.*s, hardware %.*s, serial number %.*s\n", (int)f[0].len,
            f[0].text, (int)f[1].len, f[1].text, (int)f[2].len, f[2].text);
    fprintf(out, "# date %s\n", d->date);
    fprintf(out, "# node id %s (not restored)\n", d->node_id != NULL ? d->node_id : "unknown");
    fprintf(out, "# %zu properties to restore, from %s; restore with: daran restore ID FILE\n",
            restored, d->list.from_drive ? "the drive's discovery" : "the tool's vendor table");
    for (size_t i = 0; i < d->list.count; i++) {
        const cli_property_t *p = &d->list.items[i];
        if (!p->writable || strcmp(dump_bare_path(p->path), DUMP_NODE_ID_PATH) == 0) {
            continue;
        }
        char line[DARAN_CLIENT_LINE_MAX];
        if (d->refused[i] != DARAN_OK) {
            fprintf(out, "# not read: %s (%s)\n", p->path, daran_result_phrase(d->refused[i]));
            continue;
        }
        format_write(line, sizeof line, d->id, p->path, d->value[i]);
        const char *why = dump_row_why(d, i);
        if (why == NULL) {
            fprintf(out, "%s\n", line);
        } else {
            fprintf(out, "# %s  (not restored: %s)\n", line, why);
        }
    }
}

static void dump_json(FILE *out, const dump_t *d)
{
    const cli_field_t *f = d->version.field;
    fputs("{\"tool\":", out);
    cli_json_string(out, "daran " DARAN_VERSION_TEXT, strlen("daran " DARAN_VERSION_TEXT));
    fprintf(out, ",\"id\":%u", d->id);
    json_value(out, "firmware", f[0].text, f[0].len);
    json_value(out, "hardware", f[1].text, f[1].len);
    json_value(out, "serial_number", f[2].text, f[2].len);
    json_text(out, "date", d->date);
    if (d->node_id != NULL) {
        json_value(out, "node_id", d->node_id, strlen(d->node_id));
    }
    json_text(out, "source", d->list.from_drive ? "discovery" : "vendor table");
    fputs(",\"properties\":[", out);
    size_t n = 0;
    for (size_t i = 0; i < d->list.count; i++) {
        const cli_property_t *p = &d->list.items[i];
        if (!p->writable || strcmp(dump_bare_path(p->path), DUMP_NODE_ID_PATH) == 0) {
            continue;
        }
        fprintf(out, "%s{\"path\":", n++ > 0 ? "," : "");
        cli_json_string(out, p->path, strlen(p->path));
        if (d->refused[i] != DARAN_OK) {
            json_text(out, "error", daran_result_phrase(d->refused[i]));
        } else {
            char line[DARAN_CLIENT_LINE_MAX];
            format_write(line, sizeof line, d->id, p->path, d->value[i]);
            json_value(out, "value", d->value[i], strlen(d->value[i]));
            json_text(out, "line", line);
            const char *why = dump_row_why(d, i);
            if (why != NULL) {
                json_text(out, "not_restored", why);
            }
        }
        fputc('}', out);
    }
    fputs("]}\n", out);
}

static cli_status_t run_dump(cli_session_t *s, int argc, char **argv)
{
    static dump_t d; /* 60 KiB: kept off the stack */
    const char *out_name = NULL;
    bool have_id = false;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--out") == 0) {
            if (i + 1 == argc) {
                return cli_usage(&cli_cmd_dump, "--out needs a file name");
            }
            out_name = argv[++i];
        } else if (strncmp(argv[i], "--", 2) == 0) {
            return cli_usage(&cli_cmd_dump, "no option %s", argv[i]);
        } else if (have_id) {
            return cli_usage(&cli_cmd_dump, "one drive at a time (\"%s\" too many)", argv[i]);
        } else if (!cli_parse_id(argv[i], false, &d.id)) {
            return cli_usage(&cli_cmd_dump, "\"%s\" is not a motor id (1..63)", argv[i]);
        } else {
            have_id = true;
        }
    }
    if (!have_id) {
        return cli_usage(&cli_cmd_dump, "which drive?");
    }
    dump_output_t output;
    cli_status_t status = output_open(&output, out_name);
    if (status == CLI_OK) {
        status = cli_session_connect(s);
    }
    if (status == CLI_OK) {
        status = dump_read(s, &d);
    }
    if (status != CLI_OK) {
        if (out_name != NULL && output.file != stdout) {
            output_discard(&output);
        }
        return status;
    }
    if (s->options.json) {
        dump_json(output.file, &d);
    } else {
        dump_text(output.file, &d);
    }
    status = output_commit(&output);
    if (status == CLI_OK && d.unread > 0) {
        status = cli_fail(CLI_DRIVE_ERROR, "drive %u refused to read %zu propert%s (`# not read` "
                          "in the dump)", d.id, d.unread, d.unread == 1 ? "y" : "ies");
    }
    return status;
}

const cli_command_t cli_cmd_dump = {
    .name = "dump",
    .synopsis = "ID [--out FILE]",
    .summary = "save a drive's configuration as protocol `w` lines",
    .help = "Reads every read-write property of drive ID (the drive's discovery, else the\n"
            "vendor's table built into the tool) and prints one `w` line each, as the\n"
            "protocol writes it for that drive, after `#` header comments: the tool, the\n"
            "drive, its firmware, hardware and serial number, the date (UTC) and its node\n"
            "id. The node id, setpoints, the drive's state and modes, error registers, the\n"
            "shaft's zero and turn count and telemetry.period are not configuration: they\n"
            "are written as comments saying why, and never restored. --out FILE writes the\n"
            "file (whole or not at all) instead of stdout; --json writes a JSON document.\n",
    .run = run_dump,
};

/* ------------------------------------------------------------ restore */

typedef struct restore {
    uint8_t id;
    const char *name;
    dump_file_t file;
    char before[CLI_PROPERTIES_MAX][DUMP_VALUE_MAX]; /* what the drive had */
    size_t written;     /* entries written (in file order) */
    size_t differences; /* written values the drive kept otherwise */
    const dump_entry_t *failed; /* the line that stopped the restore; NULL: none */
    const char *failure;        /* what the drive said, or that it did not answer */
    bool rolled_back;           /* the previous values are back */
} restore_t;

/* Write back what the drive had, in file order (the order a restore of a
 * dump of those values would take). Stops at a drive that does not answer. */
static cli_status_t restore_roll_back(cli_session_t *s, restore_t *r, size_t count)
{
    for (size_t i = 0; i < count; i++) {
        const dump_entry_t *e = &r->file.entries[i];
        daran_client_value_t value;
        char kept[DARAN_CLIENT_LINE_MAX];
        daran_result_t refused;
        if (!cli_parse_value(r->before[i], &value)) {
            return cli_fail(CLI_DRIVE_ERROR, "%s:%u: %s had %s, which cannot be written back",
                            r->name, e->line, e->path, r->before[i]);
        }
        cli_status_t status = cli_write_read_back_scoped(s, r->id, e->path,
            e->axis ? DARAN_CLIENT_SCOPE_AXIS : DARAN_CLIENT_SCOPE_SYSTEM, &value, kept, sizeof kept,
                                                  &refused);
        if (status == CLI_DRIVE_ERROR) {
            return cli_fail(status, "%s:%u: writing back %s %s: drive %u refused it: %s", r->name,
                            e->line, e->path, r->before[i], r->id, daran_result_phrase(refused));
        }
        if (status != CLI_OK) {
            return status;
        }
        if (!cli_same_number(kept, r->before[i])) {
            return cli_fail(CLI_DRIVE_ERROR, "%s:%u: writing back %s %s: drive %u keeps %s",
                            r->name, e->line, e->path, r->before[i], r->id, kept);
        }
    }
    return CLI_OK;
}

static void print_difference(const cli_session_t *s, const restore_t *r, const dump_entry_t *e,
                             const char *kept)
{
    if (s->options.json) {
        fprintf(stdout, "%s{\"line\":%u", r->differences > 0 ? "," : "", e->line);
        json_text(stdout, "path", e->path);
        json_value(stdout, "file", e->value, strlen(e->value));
        json_value(stdout, "kept", kept, strlen(kept));
        putchar('}');
    } else {
        printf("%s:%u: %s: drive %u keeps %s (the file has %s)\n", r->name, e->line, e->path,
               r->id, kept, e->value);
    }
}

/* Write every line; at the first one the drive refuses (or a drive that
 * stops answering), write back what had changed. */
static cli_status_t restore_write(cli_session_t *s, restore_t *r)
{
    for (size_t i = 0; i < r->file.count; i++) {
        const dump_entry_t *e = &r->file.entries[i];
        char kept[DARAN_CLIENT_LINE_MAX];
        daran_result_t refused;
        cli_status_t status = cli_write_read_back_scoped(s, r->id, e->path,
            e->axis ? DARAN_CLIENT_SCOPE_AXIS : DARAN_CLIENT_SCOPE_SYSTEM, &e->parsed, kept,
                                                  sizeof kept, &refused);
        if (status == CLI_OK) {
            r->written++; /* what it kept is compared once all are written */
            continue;
        }
        if (status == CLI_PORT_ERROR) {
            return cli_fail(status, "drive %u may be half-restored: %zu of %zu lines written",
                            r->id, r->written, r->file.count);
        }
        /* A refused line had no effect; a line that got no answer may have. */
        size_t changed = status == CLI_DRIVE_ERROR ? i : i + 1;
        cli_status_t back = restore_roll_back(s, r, changed);
        r->failed = e;
        r->failure = status == CLI_DRIVE_ERROR ? daran_result_phrase(refused) : "no reply";
        r->rolled_back = back == CLI_OK;
        char line[DARAN_CLIENT_LINE_MAX];
        format_write(line, sizeof line, r->id, e->path, e->value);
        if (back != CLI_OK) {
            return cli_fail(back > status ? back : status,
                            "%s:%u: `%s` failed and drive %u could not be given back its "
                            "previous values: it may be half-restored",
                            r->name, e->line, line, r->id);
        }
        if (status == CLI_DRIVE_ERROR) {
            return cli_fail(status, "%s:%u: drive %u refused `%s`: %s%s%s%s; its previous values "
                            "are back (%zu line%s written back)", r->name, e->line, r->id, line,
                            daran_result_phrase(refused), kept[0] != '\0' ? " (it keeps " : "",
                            kept, kept[0] != '\0' ? ")" : "", changed, changed == 1 ? "" : "s");
        }
        return cli_fail(status, "%s:%u: `%s` went unanswered; drive %u's previous values are "
                        "back", r->name, e->line, line, r->id);
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
        daran_result_t refused;
        cli_status_t status = read_value(s, r->id, e->path, kept, sizeof kept, &refused);
        if (status == CLI_DRIVE_ERROR) {
            return cli_fail(status, "%s:%u: drive %u wrote %s but cannot read it back: %s",
                            r->name, e->line, r->id, e->path, daran_result_phrase(refused));
        }
        if (status != CLI_OK) {
            return status;
        }
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
    cli_status_t status = read_version(s, r->id, &version);
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
        daran_result_t refused;
        cli_status_t status = read_value(s, r->id, e->path, r->before[i], sizeof r->before[i],
                                         &refused);
        if (status == CLI_DRIVE_ERROR) {
            return cli_fail(status, "%s:%u: drive %u cannot read %s: %s; nothing was written",
                            r->name, e->line, r->id, e->path, daran_result_phrase(refused));
        }
        if (status != CLI_OK) {
            return status;
        }
    }
    return CLI_OK;
}

static cli_status_t restore_save(cli_session_t *s, uint8_t id)
{
    daran_client_request_t request = {.command = DARAN_CLIENT_CMD_SS, .id = id};
    return cli_transact(s, &request, NULL, NULL, false, NULL);
}

static cli_status_t run_restore(cli_session_t *s, int argc, char **argv)
{
    static restore_t r; /* 60 KiB: kept off the stack */
    bool save = false;
    bool force = false;
    int positional = 0;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--save") == 0) {
            save = true;
        } else if (strcmp(argv[i], "--force") == 0) {
            force = true;
        } else if (strncmp(argv[i], "--", 2) == 0) {
            return cli_usage(&cli_cmd_restore, "no option %s", argv[i]);
        } else if (positional == 0) {
            if (!cli_parse_id(argv[i], false, &r.id)) {
                return cli_usage(&cli_cmd_restore, "\"%s\" is not a motor id (1..63)", argv[i]);
            }
            positional++;
        } else if (positional == 1) {
            r.name = argv[i];
            positional++;
        } else {
            return cli_usage(&cli_cmd_restore, "one drive and one file (\"%s\" too many)",
                             argv[i]);
        }
    }
    if (positional != 2) {
        return cli_usage(&cli_cmd_restore, "a drive id and a file are needed");
    }
    cli_status_t status = dump_file_read(r.name, &r.file);
    if (status != CLI_OK) {
        return status;
    }
    if (r.file.count == 0) {
        return cli_fail(CLI_USAGE, "%s: no `w` line to restore", r.name);
    }
    if (r.file.firmware[0] == '\0' && !force) {
        return cli_fail(CLI_USAGE, "%s names no firmware (no `" DUMP_FIRMWARE_HEAD "…` line); "
                        "--force restores it anyway", r.name);
    }
    status = cli_session_connect(s);
    if (status == CLI_OK) {
        status = restore_check_firmware(s, &r, force);
    }
    if (status == CLI_OK) {
        status = restore_read_before(s, &r);
    }
    if (status != CLI_OK) {
        return status;
    }
    /* From the first write to the last write-back, a Ctrl-C waits: cut
     * short, it would leave the drive half-configured. */
    sigset_t block;
    sigset_t saved;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    sigaddset(&block, SIGHUP);
    sigprocmask(SIG_BLOCK, &block, &saved);
    r.written = 0;
    r.differences = 0;
    r.failed = NULL;
    r.rolled_back = false;
    if (s->options.json) {
        printf("{\"id\":%u", r.id);
        json_text(stdout, "file", r.name);
        fputs(",\"differences\":[", stdout);
    }
    status = restore_write(s, &r);
    if (status == CLI_OK) {
        status = restore_compare(s, &r);
    }
    bool saved_to_nvm = false;
    if (status == CLI_OK && save) {
        status = restore_save(s, r.id);
        saved_to_nvm = status == CLI_OK;
    }
    if (s->options.json) {
        printf("],\"lines\":%zu,\"written\":%zu,\"complete\":%s,\"saved\":%s", r.file.count,
               r.written, r.written == r.file.count ? "true" : "false",
               saved_to_nvm ? "true" : "false");
        if (r.failed != NULL) {
            printf(",\"failed\":{\"line\":%u", r.failed->line);
            json_text(stdout, "path", r.failed->path);
            json_value(stdout, "value", r.failed->value, strlen(r.failed->value));
            json_text(stdout, "error", r.failure);
            printf("},\"rolled_back\":%s", r.rolled_back ? "true" : "false");
        }
        puts("}");
    } else if (r.written == r.file.count) {
        printf("drive %u: %zu properties restored from %s, %s", r.id, r.written, r.name,
               r.differences == 0 ? "each kept as written" : "");
        if (r.differences > 0) {
            printf("%zu kept otherwise (above)", r.differences);
        }
        printf("%s\n", saved_to_nvm ? "; saved (ss)" : "");
    }
    fflush(stdout);
    sigprocmask(SIG_SETMASK, &saved, NULL);
    return status;
}

const cli_command_t cli_cmd_restore = {
    .name = "restore",
    .synopsis = "ID FILE [--save] [--force]",
    .summary = "write a dump back into a drive, all or nothing",
    .help = "Reads FILE (a dump: `w` lines and `#` comments), refuses it when its firmware\n"
            "is not the drive's (unless --force), reads every value the drive has, then\n"
            "writes each line to drive ID (its id or axisN replaced by ID) and reads it back,\n"
            "printing each value the drive kept otherwise. At the first line the drive\n"
            "refuses it writes back the values it had changed and stops (exit status 1).\n"
            "A line that would change the node id, a setpoint, the drive's state, an error\n"
            "register, the shaft's zero or telemetry.period is a format error (exit 2):\n"
            "a restore never writes them. --save: `ss ID` after a complete restore.\n",
    .run = run_restore,
};
