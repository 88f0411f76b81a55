/* What dump and restore both ask of a drive (dump_drive.h). */
#include <string.h>

#include "dump_drive.h"
#include "dump_file.h"

cli_status_t dump_read_version(cli_session_t *s, uint8_t id, drive_version_t *v)
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

cli_status_t dump_read_value(cli_session_t *s, uint8_t id, const char *path, char *out,
                             size_t size, daran_result_t *refused, char *why, size_t why_size)
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
    why[0] = '\0';
    cli_status_t status = cli_transact(s, &request, cli_take_line, &value, true, &result);
    if (status == CLI_DRIVE_ERROR) {
        *refused = result;
        return status;
    }
    if (status != CLI_OK) {
        return cli_failure_text(s, &request, status, result, why, why_size);
    }
    if (value.len >= size) {
        (void)snprintf(why, why_size, "drive %u: %s reads as \"%.*s\", too long for a value", id,
                       path, (int)value.len, value.text);
        return CLI_NO_REPLY;
    }
    memcpy(out, value.text, value.len);
    out[value.len] = '\0';
    return CLI_OK;
}

void dump_write_line(char *buf, size_t size, uint8_t id, const char *path, const char *value)
{
    const char *bare = dump_bare_path(path);
    if (bare != path) {
        snprintf(buf, size, "w axis%u.%s %s", id, bare, value);
    } else {
        snprintf(buf, size, "w %s %s %u", path, value, id);
    }
}

void dump_json_value(FILE *out, const char *name, const char *text, size_t len)
{
    fprintf(out, ",\"%s\":", name);
    cli_json_number(out, text, len);
}
