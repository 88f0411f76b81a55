/* daran_client: the command table (words, reply shapes, classes, the retry
 * rule) and the request builder. Every line is built field by field into
 * the caller's buffer with the core's shortest float printer; nothing is
 * written past `size`, and a line that does not fit leaves no line. */
#include "daran_client.h"

#include "checksum.h"
#include "daran_properties.h"
#include "number.h"
#include "text.h"

typedef struct command_row {
    char word[3];
    uint8_t min_values;
    uint8_t max_values;
    uint8_t may_retry;
    daran_client_reply_shape_t shape;
    daran_client_class_t cls;
} command_row_t;

/* The protocol's classes as the client's retry rule sees them: a start
 * moves, `r` reads. */
#define CLIENT_CLASS_MOTION DARAN_CLIENT_CLASS_MOTION
#define CLIENT_CLASS_START DARAN_CLIENT_CLASS_MOTION
#define CLIENT_CLASS_PRESET DARAN_CLIENT_CLASS_PRESET
#define CLIENT_CLASS_QUERY DARAN_CLIENT_CLASS_QUERY
#define CLIENT_CLASS_READ DARAN_CLIENT_CLASS_QUERY
#define CLIENT_CLASS_WRITE DARAN_CLIENT_CLASS_WRITE
#define CLIENT_CLASS_SYSTEM DARAN_CLIENT_CLASS_SYSTEM
#define CLIENT_CLASS_UPDATE DARAN_CLIENT_CLASS_UPDATE
#define CLIENT_RETRY_RETRY 1u
#define CLIENT_RETRY_ONCE 0u

#define ROW_(name, c0, c1, feature, cls, reply, retry, handler, arg, can, help, f1, f2, f3, f4, \
             f5, f6)                                                                             \
    {{c0, c1, 0},                                                                                \
     DARAN_PROTOCOL_MIN_VALUES(f1, f2, f3, f4, f5, f6),                                          \
     DARAN_PROTOCOL_MAX_VALUES(f1, f2, f3, f4, f5, f6),                                          \
     CLIENT_RETRY_##retry,                                                                       \
     DARAN_CLIENT_REPLY_##reply,                                                                 \
     CLIENT_CLASS_##cls},
static const command_row_t commands[DARAN_CLIENT_CMD_COUNT] = {DARAN_PROTOCOL_COMMANDS(ROW_)};
#undef ROW_

static const command_row_t *row_of(daran_client_command_t command)
{
    return (unsigned)command < (unsigned)DARAN_CLIENT_CMD_COUNT ? &commands[command] : NULL;
}

const char *daran_client_command_word(daran_client_command_t command)
{
    const command_row_t *row = row_of(command);
    return row != NULL ? row->word : NULL;
}

daran_client_reply_shape_t daran_client_reply_shape(daran_client_command_t command)
{
    const command_row_t *row = row_of(command);
    return row != NULL ? row->shape : DARAN_CLIENT_REPLY_SILENT;
}

daran_client_class_t daran_client_command_class(daran_client_command_t command)
{
    const command_row_t *row = row_of(command);
    return row != NULL ? row->cls : DARAN_CLIENT_CLASS_MOTION;
}

bool daran_client_may_retry(daran_client_command_t command)
{
    const command_row_t *row = row_of(command);
    return row != NULL && row->may_retry != 0u;
}

/* The field after position *at in text[0..len): its start and length, *at
 * moved past it; false when there is none. */
static bool next_field(const char *text, size_t len, size_t *at, const char **field,
                       size_t *field_len)
{
    size_t i = *at;
    while (i < len && (text[i] == ' ' || text[i] == '\t')) {
        i++;
    }
    size_t start = i;
    while (i < len && text[i] != ' ' && text[i] != '\t') {
        i++;
    }
    *at = i;
    *field = text + start;
    *field_len = i - start;
    return i > start;
}

static bool same_word(const char *field, size_t len, const char *word)
{
    size_t i = 0;
    while (i < len && word[i] != '\0' && word[i] == field[i]) {
        i++;
    }
    return i == len && word[i] == '\0';
}

daran_client_reply_shape_t daran_client_line_shape(const char *payload, size_t len, bool *known)
{
    bool unused;
    known = known != NULL ? known : &unused;
    *known = false;
    size_t at = 0;
    const char *word;
    size_t word_len;
    if (payload == NULL || !next_field(payload, len, &at, &word, &word_len)) {
        return DARAN_CLIENT_REPLY_SILENT;
    }
    for (unsigned c = 0; c < (unsigned)DARAN_CLIENT_CMD_COUNT; c++) {
        if (!same_word(word, word_len, commands[c].word)) {
            continue;
        }
        *known = true;
        const char *field;
        size_t field_len;
        if (c == (unsigned)DARAN_CLIENT_CMD_H && next_field(payload, len, &at, &field, &field_len) &&
            next_field(payload, len, &at, &field, &field_len) &&
            same_word(field, field_len, DARAN_H_PROPERTIES_WORD)) {
            return DARAN_CLIENT_REPLY_UNTIL_END;
        }
        return commands[c].shape;
    }
    return DARAN_CLIENT_REPLY_SILENT;
}

/* The SYSTEM rows' paths and their lengths, from the core's list: the scope
 * token picks whether a row contributes. The lengths are compared first, so
 * a path is looked at only against rows of its own length. */
typedef struct system_path {
    const char *text;
    uint8_t len;
} system_path_t;
#define SCOPE_PATH_SYSTEM(path) {path, (uint8_t)(sizeof path - 1u)},
#define SCOPE_PATH_AXIS(path)
#define SYSTEM_PATH_(id, path, scope, type, access, range, unit, can) SCOPE_PATH_##scope(path)
static const system_path_t system_paths[] = {DARAN_PROPERTY_LIST(SYSTEM_PATH_)};
#undef SYSTEM_PATH_

daran_client_scope_t daran_client_path_scope(const char *path, size_t len)
{
    if (path == NULL) {
        return DARAN_CLIENT_SCOPE_AXIS;
    }
    for (size_t row = 0; row < sizeof system_paths / sizeof system_paths[0]; row++) {
        const system_path_t *entry = &system_paths[row];
        if (entry->len != len) {
            continue;
        }
        size_t i = 0;
        while (i < len && entry->text[i] == path[i]) {
            i++;
        }
        if (i == len) {
            return DARAN_CLIENT_SCOPE_SYSTEM;
        }
    }
    return DARAN_CLIENT_SCOPE_AXIS;
}

/* A line under construction: appends stop at the first that does not fit. */
typedef struct writer {
    char *buf;
    size_t size;
    size_t len;
    bool overflow;
} writer_t;

static void put_text(writer_t *w, const char *text, size_t len)
{
    if (w->overflow || len > w->size - w->len) {
        w->overflow = true;
        return;
    }
    for (size_t i = 0; i < len; i++) {
        w->buf[w->len + i] = text[i];
    }
    w->len += len;
}

static void put_char(writer_t *w, char c)
{
    put_text(w, &c, 1u);
}

static void put_uint(writer_t *w, uint64_t value)
{
    char digits[DARAN_U64_TEXT_MAX];
    put_text(w, digits, daran_format_uint(value, digits, sizeof digits));
}

static void put_float(writer_t *w, float value)
{
    char digits[DARAN_F32_TEXT_MAX];
    put_text(w, digits, daran_format_float(value, digits, sizeof digits));
}

static bool is_finite(float value)
{
    /* NaN fails both comparisons; the infinities fail the bound */
    return value >= -3.40282347e38f && value <= 3.40282347e38f;
}

/* A path as given: not empty, no blank, no control byte, no '*'. */
static bool path_is_sane(const char *path, size_t len)
{
    if (len == 0u) {
        return false;
    }
    for (size_t i = 0; i < len; i++) {
        char c = path[i];
        if (c <= ' ' || c > '~' || c == '*') {
            return false;
        }
    }
    return true;
}

/* The length of an `axisN.` prefix of path (N one or more digits), 0 when
 * there is none. */
static size_t axis_prefix_len(const char *path, size_t len)
{
    static const char axis[] = "axis";
    size_t i = 0;
    for (; i < 4u; i++) {
        if (i == len || path[i] != axis[i]) {
            return 0;
        }
    }
    size_t digits_start = i;
    while (i < len && path[i] >= '0' && path[i] <= '9') {
        i++;
    }
    if (i == digits_start || i == len || path[i] != '.') {
        return 0;
    }
    return i + 1u;
}

static daran_result_t put_value(writer_t *w, const daran_client_value_t *value)
{
    switch (value->kind) {
    case DARAN_CLIENT_VALUE_F32:
        if (!is_finite(value->f32)) {
            return DARAN_ERR_INVALID_VALUE;
        }
        put_float(w, value->f32);
        return DARAN_OK;
    case DARAN_CLIENT_VALUE_UINT:
        put_uint(w, value->uint);
        return DARAN_OK;
    case DARAN_CLIENT_VALUE_INT:
        if (value->sint < 0) {
            put_char(w, '-');
            /* negate in unsigned arithmetic: INT64_MIN has no positive twin */
            put_uint(w, 0u - (uint64_t)value->sint);
        } else {
            put_uint(w, (uint64_t)value->sint);
        }
        return DARAN_OK;
    default:
        return DARAN_ERR_BAD_ARGUMENT;
    }
}

/* `r path [id]` / `w path value [id]`: the id goes into `axisN.` or last. */
static daran_result_t put_property(writer_t *w, const daran_client_request_t *request)
{
    const char *path = request->path;
    if (path == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    size_t len = daran_text_len(path);
    size_t prefix = axis_prefix_len(path, len);
    daran_client_scope_t scope = request->scope;
    if (prefix != 0u) {
        scope = DARAN_CLIENT_SCOPE_AXIS;
        path += prefix;
        len -= prefix;
    }
    if (!path_is_sane(path, len)) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    if (scope == DARAN_CLIENT_SCOPE_AUTO) {
        scope = daran_client_path_scope(path, len);
    }
    put_char(w, ' ');
    if (scope == DARAN_CLIENT_SCOPE_AXIS) {
        put_text(w, "axis", 4u);
        put_uint(w, request->id);
        put_char(w, '.');
    }
    put_text(w, path, len);
    if (request->command == DARAN_CLIENT_CMD_W) {
        put_char(w, ' ');
        daran_result_t result = put_value(w, &request->value);
        if (result != DARAN_OK) {
            return result;
        }
    }
    if (scope == DARAN_CLIENT_SCOPE_SYSTEM) {
        put_char(w, ' ');
        put_uint(w, request->id);
    }
    return DARAN_OK;
}

/* `h id properties [prefix]` */
static daran_result_t put_discovery(writer_t *w, const char *prefix)
{
    put_text(w, " properties", 11u);
    if (prefix != NULL) {
        size_t len = daran_text_len(prefix);
        if (!path_is_sane(prefix, len)) {
            return DARAN_ERR_BAD_ARGUMENT;
        }
        put_char(w, ' ');
        put_text(w, prefix, len);
    }
    return DARAN_OK;
}

static daran_result_t put_payload(writer_t *w, const daran_client_request_t *request)
{
    const command_row_t *row = row_of(request->command);
    if (row == NULL || request->id > DARAN_CLIENT_ID_MAX ||
        request->value_count < row->min_values || request->value_count > row->max_values) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    put_text(w, row->word, daran_text_len(row->word));
    if (request->command == DARAN_CLIENT_CMD_R || request->command == DARAN_CLIENT_CMD_W) {
        return put_property(w, request);
    }
    put_char(w, ' ');
    put_uint(w, request->id);
    for (size_t i = 0; i < request->value_count; i++) {
        if (!is_finite(request->values[i])) {
            return DARAN_ERR_INVALID_VALUE;
        }
        put_char(w, ' ');
        put_float(w, request->values[i]);
    }
    if (request->command == DARAN_CLIENT_CMD_H_PROPERTIES) {
        return put_discovery(w, request->path);
    }
    return DARAN_OK;
}

/* ` *N` (N the XOR of the payload and the space before '*') and `\n`. */
static void put_end(writer_t *w, bool with_checksum)
{
    if (with_checksum && !w->overflow) {
        uint8_t sum = (uint8_t)(daran_xor(w->buf, w->len) ^ (uint8_t)' ');
        put_text(w, " *", 2u);
        put_uint(w, sum);
    }
    put_char(w, '\n');
}

daran_result_t daran_client_build(const daran_client_request_t *request, bool with_checksum,
                                  char *buf, size_t size, size_t *len)
{
    if (len != NULL) {
        *len = 0;
    }
    if (request == NULL || buf == NULL || len == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    writer_t w = {buf, size, 0u, false};
    daran_result_t result = put_payload(&w, request);
    if (result != DARAN_OK) {
        return result;
    }
    put_end(&w, with_checksum);
    if (w.overflow) {
        return DARAN_ERR_LINE_TOO_LONG;
    }
    *len = w.len;
    return DARAN_OK;
}

daran_result_t daran_client_seal(char *buf, size_t size, size_t payload_len, bool with_checksum,
                                 size_t *len)
{
    if (buf == NULL || len == NULL || payload_len > size) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    writer_t w = {buf, size, payload_len, false};
    put_end(&w, with_checksum);
    if (w.overflow) {
        return DARAN_ERR_LINE_TOO_LONG;
    }
    *len = w.len;
    return DARAN_OK;
}
