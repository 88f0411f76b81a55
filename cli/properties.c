/* A drive's property list: its own discovery (`h id properties`) when it
 * has it, else the vendor's table the tool was built with (cli.h). */
#include <string.h>

#include "cli.h"
#include "daran_properties.h"

static void copy_text(char *dst, size_t size, const char *src, size_t len)
{
    if (len >= size) {
        len = size - 1;
    }
    memcpy(dst, src, len);
    dst[len] = '\0';
}

typedef struct builtin_row {
    const char *path;
    bool axis;
    daran_client_type_t type;
    bool writable;
    const char *unit;
} builtin_row_t;

#define CLI_SCOPE_AXIS_ true
#define CLI_SCOPE_SYSTEM_ false
#define CLI_TYPE_F32_ DARAN_CLIENT_TYPE_F32
#define CLI_TYPE_U32_ DARAN_CLIENT_TYPE_U32
#define CLI_TYPE_S32_ DARAN_CLIENT_TYPE_S32
#define CLI_TYPE_U64_ DARAN_CLIENT_TYPE_U64
#define CLI_TYPE_BOOL_ DARAN_CLIENT_TYPE_BOOL
#define CLI_ACCESS_RW_ true
#define CLI_ACCESS_RO_ false
#define CLI_BUILTIN_ROW_(id, path, scope, type, access, range, unit, can) \
    {path, CLI_SCOPE_##scope##_, CLI_TYPE_##type##_, CLI_ACCESS_##access##_, unit},

static const builtin_row_t builtin_rows[] = {DARAN_PROPERTY_LIST(CLI_BUILTIN_ROW_)};

static bool has_prefix(const char *path, size_t len, const char *prefix)
{
    size_t plen = prefix != NULL ? strlen(prefix) : 0;
    return plen <= len && memcmp(path, prefix != NULL ? prefix : "", plen) == 0;
}

void cli_properties_builtin(const char *prefix, cli_property_list_t *out)
{
    out->count = 0;
    out->from_drive = false;
    for (size_t i = 0; i < sizeof builtin_rows / sizeof builtin_rows[0]; i++) {
        const builtin_row_t *row = &builtin_rows[i];
        char path[CLI_PATH_MAX];
        int n = snprintf(path, sizeof path, "%s%s", row->axis ? "axis0." : "", row->path);
        if (n < 0 || (size_t)n >= sizeof path || !has_prefix(path, (size_t)n, prefix) ||
            out->count == CLI_PROPERTIES_MAX) {
            continue;
        }
        cli_property_t *p = &out->items[out->count++];
        memset(p, 0, sizeof *p);
        memcpy(p->path, path, (size_t)n + 1);
        p->type = row->type;
        p->writable = row->writable;
        copy_text(p->unit, sizeof p->unit, row->unit, strlen(row->unit));
    }
}

typedef struct load_ctx {
    cli_property_list_t *list;
    size_t unreadable;
} load_ctx_t;

static void take_property_line(void *ctx, const daran_client_line_t *line)
{
    load_ctx_t *load = ctx;
    daran_client_property_t prop;
    if (daran_client_parse_property(line, &prop) != DARAN_OK ||
        load->list->count == CLI_PROPERTIES_MAX) {
        load->unreadable++;
        return;
    }
    cli_property_t *p = &load->list->items[load->list->count++];
    memset(p, 0, sizeof *p);
    copy_text(p->path, sizeof p->path, prop.path, prop.path_len);
    p->type = prop.type;
    p->writable = prop.writable;
    copy_text(p->unit, sizeof p->unit, prop.unit, prop.unit_len);
    copy_text(p->range, sizeof p->range, prop.range, prop.range_len);
}

cli_status_t cli_properties_load(cli_session_t *s, uint8_t id, const char *prefix,
                                 cli_property_list_t *out)
{
    out->count = 0;
    out->from_drive = true;
    load_ctx_t load = {.list = out, .unreadable = 0};
    daran_client_request_t request = {
        .command = DARAN_CLIENT_CMD_H_PROPERTIES, .id = id, .path = prefix};
    daran_result_t result;
    cli_status_t status = cli_transact(s, &request, take_property_line, &load, true, &result);
    if (status == CLI_DRIVE_ERROR) {
        /* A drive without discovery (the vendor's own) refuses the request. */
        cli_properties_builtin(prefix, out);
        return CLI_OK;
    }
    if (status != CLI_OK) {
        return cli_transact_failed(s, &request, status, result);
    }
    if (load.unreadable > 0) {
        return cli_fail(CLI_NO_REPLY, "drive %u: %zu discovery line(s) could not be read%s", id,
                        load.unreadable,
                        out->count == CLI_PROPERTIES_MAX ? " (more than the tool holds)" : "");
    }
    return CLI_OK;
}

const cli_property_t *cli_property_find(const cli_property_list_t *list, const char *path)
{
    /* `axis7.x` and `x` both name discovery's `axis0.x`. */
    const char *bare = path;
    if (strncmp(path, "axis", 4) == 0) {
        const char *p = path + 4;
        while (*p >= '0' && *p <= '9') {
            p++;
        }
        if (p > path + 4 && *p == '.') {
            bare = p + 1;
        }
    }
    for (size_t i = 0; i < list->count; i++) {
        const char *candidate = list->items[i].path;
        if (strcmp(candidate, path) == 0 ||
            (strncmp(candidate, "axis0.", 6) == 0 && strcmp(candidate + 6, bare) == 0) ||
            strcmp(candidate, bare) == 0) {
            return &list->items[i];
        }
    }
    return NULL;
}
