/* The dump file and the rule of what is restored (dump_file.h). */
#include <errno.h>
#include <math.h>
#include <string.h>

#include "dump_file.h"

/* ------------------------------------------------------------ the rule */

#define WHY_SETPOINT "a setpoint; writing it moves the motor"
#define WHY_MODE "the mode the last motion command chose; writing it switches the controller"
#define WHY_POSITION "the shaft's position, not a setting; writing it shifts the position the drive reports"

/* Read-write rows that are the drive's state, not its configuration. A
 * restore that wrote them would move the motor, start or stop it, or move
 * its zero (protocol.md 6, 7, 10.2, 11.2). */
static const struct never_restored {
    const char *path; /* without axis0. */
    const char *why;
} never_restored[] = {
    {DUMP_NODE_ID_PATH, "the drive's id; a restore keeps the id the drive has"},
    {"output_shaft.input_pos", WHY_SETPOINT},
    {"output_shaft.input_vel", WHY_SETPOINT},
    {"output_shaft.input_torque", WHY_SETPOINT},
    {"output_shaft.pos_setpoint", WHY_SETPOINT},
    {"output_shaft.vel_setpoint", WHY_SETPOINT},
    {"output_shaft.torque_setpoint", WHY_SETPOINT},
    {"controller.input_pos", WHY_SETPOINT},
    {"controller.input_vel", WHY_SETPOINT},
    {"controller.input_torque", WHY_SETPOINT},
    {"controller.pos_setpoint", WHY_SETPOINT},
    {"controller.vel_setpoint", WHY_SETPOINT},
    {"controller.torque_setpoint", WHY_SETPOINT},
    {"requested_state", "the drive's state; writing it starts or stops closed-loop control"},
    {"controller.config.control_mode", WHY_MODE},
    {"controller.config.input_mode", WHY_MODE},
    {"config.extra_setting.zero_offset_counts", WHY_POSITION},
    {"config.extra_setting.stored_turns_counts", WHY_POSITION},
    {"telemetry.period",
     "writing it starts a telemetry stream; on a shared link only one drive may stream"},
};

#define WHY_ERROR_REGISTER "an error register; writing 0 clears it (daran clear)"

const char *dump_bare_path(const char *path)
{
    if (strncmp(path, "axis", 4) != 0) {
        return path;
    }
    const char *p = path + 4;
    while (*p >= '0' && *p <= '9') {
        p++;
    }
    return p > path + 4 && *p == '.' ? p + 1 : path;
}

const char *dump_not_restored_why(const char *path, const char *range)
{
    const char *bare = dump_bare_path(path);
    for (size_t i = 0; i < sizeof never_restored / sizeof never_restored[0]; i++) {
        if (strcmp(bare, never_restored[i].path) == 0) {
            return never_restored[i].why;
        }
    }
    size_t len = strlen(bare);
    bool error_name = strcmp(bare, "error") == 0 ||
                      (len > 6 && strcmp(bare + len - 6, ".error") == 0) ||
                      strcmp(bare, "config_warnings") == 0;
    if (error_name || strcmp(range, "0") == 0) {
        return WHY_ERROR_REGISTER;
    }
    return NULL;
}

/* ------------------------------------------------------------ the file */

static void copy_field(char *dst, size_t size, const cli_field_t *field)
{
    size_t len = field->len < size - 1 ? field->len : size - 1;
    memcpy(dst, field->text, len);
    dst[len] = '\0';
}

/* `w PATH VALUE [ID]`: fields already split. */
static cli_status_t read_write_line(const char *name, unsigned line, const cli_field_t *f,
                                    size_t count, uint8_t target, dump_entry_t *entry)
{
    if (count < 3 || count > 4) {
        return cli_fail(CLI_USAGE, "%s:%u: a `w` line is `w PATH VALUE [ID]`", name, line);
    }
    if (f[1].len >= CLI_PATH_MAX || f[2].len >= sizeof entry->value) {
        return cli_fail(CLI_USAGE, "%s:%u: path or value too long", name, line);
    }
    copy_field(entry->path, sizeof entry->path, &f[1]);
    copy_field(entry->value, sizeof entry->value, &f[2]);
    entry->line = line;
    entry->axis = dump_bare_path(entry->path) != entry->path;
    if (entry->axis) {
        char digits[8];
        cli_field_t id_field = {entry->path + 4,
                                (size_t)(dump_bare_path(entry->path) - entry->path) - 5};
        uint8_t id;
        copy_field(digits, sizeof digits, &id_field);
        if (id_field.len >= sizeof digits || !cli_parse_id(digits, true, &id)) {
            return cli_fail(CLI_USAGE, "%s:%u: %s: axis number not a motor id (0..63)", name,
                            line, entry->path);
        }
        if (count == 4) {
            return cli_fail(CLI_USAGE, "%s:%u: an `axisN.` path takes no id at the end", name,
                            line);
        }
    } else if (count == 4) {
        char id_text[8];
        uint8_t id;
        copy_field(id_text, sizeof id_text, &f[3]);
        if (f[3].len >= sizeof id_text || !cli_parse_id(id_text, true, &id)) {
            return cli_fail(CLI_USAGE, "%s:%u: \"%s\" is not a motor id (0..63)", name, line,
                            id_text);
        }
    }
    if (!cli_parse_value(entry->value, &entry->parsed) ||
        (entry->parsed.kind == DARAN_CLIENT_VALUE_F32 && !isfinite(entry->parsed.f32))) {
        return cli_fail(CLI_USAGE, "%s:%u: \"%s\" is not a value a drive takes", name, line,
                        entry->value);
    }
    const char *why = dump_not_restored_why(entry->path, "");
    if (why != NULL) {
        return cli_fail(CLI_USAGE, "%s:%u: %s is never restored (%s)", name, line, entry->path,
                        why);
    }
    if (entry->axis) {
        /* the path the drive gets, so that every message names what was sent
         * (path[] has room for an ID one digit longer than the file's N) */
        char prefix[12];
        int len = snprintf(prefix, sizeof prefix, "axis%u.", target);
        const char *bare = dump_bare_path(entry->path);
        if (len < 0 || (size_t)len + strlen(bare) >= sizeof entry->path) {
            return cli_fail(CLI_USAGE, "%s:%u: path too long", name, line);
        }
        memmove(entry->path + len, bare, strlen(bare) + 1u);
        memcpy(entry->path, prefix, (size_t)len);
    }
    return CLI_OK;
}

/* A header comment: the firmware version the file was dumped from. */
static void read_comment(const char *text, dump_file_t *out)
{
    size_t head = strlen(DUMP_FIRMWARE_HEAD);
    if (out->firmware[0] != '\0' || strncmp(text, DUMP_FIRMWARE_HEAD, head) != 0) {
        return;
    }
    const char *v = text + head;
    size_t len = strcspn(v, ", ");
    if (len > 0 && len < sizeof out->firmware) {
        memcpy(out->firmware, v, len);
        out->firmware[len] = '\0';
    }
}

cli_status_t dump_file_read(const char *name, uint8_t id, dump_file_t *out)
{
    out->count = 0;
    out->firmware[0] = '\0';
    FILE *in = fopen(name, "r");
    if (in == NULL) {
        return cli_fail(CLI_USAGE, "%s: %s", name, strerror(errno));
    }
    char text[DARAN_CLIENT_LINE_MAX + 2];
    unsigned line = 0;
    cli_status_t status = CLI_OK;
    while (status == CLI_OK && fgets(text, sizeof text, in) != NULL) {
        line++;
        size_t len = strlen(text);
        if (len == sizeof text - 1 && text[len - 1] != '\n') {
            status = cli_fail(CLI_USAGE, "%s:%u: line too long", name, line);
            break;
        }
        while (len > 0 && (text[len - 1] == '\n' || text[len - 1] == '\r')) {
            text[--len] = '\0';
        }
        for (size_t i = 0; i < len; i++) {
            text[i] = text[i] == '\t' ? ' ' : text[i];
        }
        const char *start = text + strspn(text, " ");
        if (start[0] == '\0') {
            continue;
        }
        if (start[0] == '#') {
            read_comment(start, out);
            continue;
        }
        cli_field_t f[5];
        size_t count = cli_split_fields(start, strlen(start), f, 5);
        if (f[0].len != 1 || (f[0].text[0] != 'w' && f[0].text[0] != 'W')) {
            status = cli_fail(CLI_USAGE, "%s:%u: only `w` lines and `#` comments belong in a dump",
                              name, line);
        } else if (out->count == CLI_PROPERTIES_MAX) {
            status = cli_fail(CLI_USAGE, "%s:%u: more than %u `w` lines", name, line,
                              CLI_PROPERTIES_MAX);
        } else {
            status = read_write_line(name, line, f, count, id, &out->entries[out->count]);
            if (status == CLI_OK) {
                out->count++;
            }
        }
    }
    if (status == CLI_OK && ferror(in)) {
        status = cli_fail(CLI_USAGE, "%s: %s", name, strerror(errno));
    }
    fclose(in);
    return status;
}
