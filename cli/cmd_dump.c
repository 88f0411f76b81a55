/* dump (docs/cli.md, "dump, restore"): a drive's configuration to a file
 * of protocol `w` lines (cmd_restore.c writes it back). */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "commands.h"
#include "daran_version.h"
#include "dump_drive.h"
#include "dump_file.h"

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
    cli_status_t status = dump_read_version(s, d->id, &d->version);
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
        char why[CLI_FAILURE_MAX];
        status = dump_read_value(s, d->id, p->path, d->value[i], sizeof d->value[i],
                                 &d->refused[i], why, sizeof why);
        if (status != CLI_OK && status != CLI_DRIVE_ERROR) {
            status = cli_fail(status, "%s", why);
        } else if (status == CLI_DRIVE_ERROR) {
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
        dump_write_line(line, sizeof line, d->id, p->path, d->value[i]);
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
    dump_json_value(out, "firmware", f[0].text, f[0].len);
    dump_json_value(out, "hardware", f[1].text, f[1].len);
    dump_json_value(out, "serial_number", f[2].text, f[2].len);
    cli_json_member(out, "date", d->date);
    if (d->node_id != NULL) {
        dump_json_value(out, "node_id", d->node_id, strlen(d->node_id));
    }
    cli_json_member(out, "source", d->list.from_drive ? "discovery" : "vendor table");
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
            cli_json_member(out, "error", daran_result_phrase(d->refused[i]));
        } else {
            char line[DARAN_CLIENT_LINE_MAX];
            dump_write_line(line, sizeof line, d->id, p->path, d->value[i]);
            dump_json_value(out, "value", d->value[i], strlen(d->value[i]));
            cli_json_member(out, "line", line);
            const char *why = dump_row_why(d, i);
            if (why != NULL) {
                cli_json_member(out, "not_restored", why);
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
