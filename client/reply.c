/* daran_client: reading reply lines. A line is first taken apart (line end,
 * checksum, kind), then the caller decodes its payload with the parser that
 * fits the request: values, an `e` register, a telemetry report, a
 * discovery or help line. Every parser works on views of the caller's
 * text; nothing is copied. */
#include "daran_client.h"

#include <math.h>

#include "checksum.h"
#include "number.h"
#include "text.h"

/* The drive's phrases, from the core's one list; the two API-misuse results
 * are never sent, so they never match a line. */
#define PHRASE_(name, phrase) phrase "\0"
static const char phrases[] = DARAN_RESULT_LIST(PHRASE_);
#undef PHRASE_

static bool same_text(const char *a, size_t a_len, const char *b)
{
    size_t i = 0;
    for (; i < a_len; i++) {
        if (b[i] == '\0' || a[i] != b[i]) {
            return false;
        }
    }
    return b[i] == '\0';
}

/* The result whose phrase is text[0..len), or DARAN_OK when none is. */
static daran_result_t result_of_phrase(const char *text, size_t len)
{
    const char *phrase = phrases;
    for (unsigned r = 0; r < (unsigned)DARAN_RESULT_COUNT; r++) {
        daran_result_t result = (daran_result_t)r;
        if (result != DARAN_OK && result != DARAN_ERR_BAD_ARGUMENT &&
            result != DARAN_ERR_BUILD_MISMATCH && same_text(text, len, phrase)) {
            return result;
        }
        phrase += daran_text_len(phrase) + 1u;
    }
    return DARAN_OK;
}

static bool is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r';
}

/* Cut a trailing ` *N` off text[0..*len): 1 when there was a well-formed
 * one and it matches, -1 when it is well-formed and wrong, 0 when there is
 * none (or a malformed one, which then stays in the payload). */
static int cut_checksum(const char *text, size_t *len)
{
    size_t end = *len;
    size_t digits = 0;
    uint32_t value = 0;
    while (digits < end && digits < 4u && text[end - 1u - digits] >= '0' &&
           text[end - 1u - digits] <= '9') {
        digits++;
    }
    if (digits == 0u || digits > 3u || end < digits + 2u) {
        return 0;
    }
    size_t star = end - digits - 1u;
    if (text[star] != '*' || text[star - 1u] != ' ') {
        return 0;
    }
    for (size_t i = star + 1u; i < end; i++) {
        value = value * 10u + (uint32_t)(text[i] - '0');
    }
    if (value > 255u) {
        return 0;
    }
    /* the sum covers the payload and the space before the '*' */
    *len = star - 1u;
    return daran_xor(text, star) == value ? 1 : -1;
}

daran_result_t daran_client_read_line(const char *text, size_t len, bool checksum_expected,
                                      daran_client_line_t *out)
{
    if (text == NULL || out == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    while (len > 0u && (text[len - 1u] == '\n' || text[len - 1u] == '\r')) {
        len--;
    }
    for (size_t i = 0; i < len; i++) {
        if ((text[i] < ' ' || text[i] > '~') && text[i] != '\t') {
            return DARAN_ERR_INVALID_VALUE;
        }
    }
    int checksum = cut_checksum(text, &len);
    if (checksum < 0) {
        return DARAN_ERR_CHECKSUM_MISMATCH;
    }
    bool telemetry = len > 0u && text[0] == '@';
    if (checksum == 0 && (checksum_expected || telemetry)) {
        return DARAN_ERR_INVALID_CHECKSUM;
    }
    daran_client_line_t line = {DARAN_CLIENT_LINE_TEXT, text, len, checksum > 0, DARAN_OK};
    static const char error_prefix[] = "error: ";
    const size_t prefix_len = sizeof error_prefix - 1u;
    if (telemetry) {
        line.kind = DARAN_CLIENT_LINE_TELEMETRY;
    } else if (same_text(text, len, "end")) {
        line.kind = DARAN_CLIENT_LINE_END;
    } else if (len >= prefix_len && same_text(text, prefix_len, error_prefix)) {
        line.kind = DARAN_CLIENT_LINE_ERROR;
        line.error = result_of_phrase(text + prefix_len, len - prefix_len);
        if (line.error == DARAN_OK) {
            return DARAN_ERR_INVALID_VALUE;
        }
    }
    *out = line;
    return DARAN_OK;
}

daran_result_t daran_client_parse_number(const char *text, size_t len, daran_client_number_t *out)
{
    if (text == NULL || out == NULL || len == 0u) {
        return DARAN_ERR_INVALID_VALUE;
    }
    daran_client_number_t n = {0.0f, 0u, text[0] == '-', false};
    size_t sign = n.negative ? 1u : 0u;
    const char *body = text + sign;
    size_t body_len = len - sign;
    /* the reply format's three non-finite words, which requests never carry
     * and so the core's parser does not take */
    if (same_text(body, body_len, "inf")) {
        n.f32 = n.negative ? -INFINITY : INFINITY;
    } else if (!n.negative && same_text(body, body_len, "nan")) {
        n.f32 = NAN;
    } else {
        if (daran_parse_f32(text, len, &n.f32) != DARAN_OK) {
            return DARAN_ERR_INVALID_VALUE;
        }
        bool digits_only = body_len > 0u;
        for (size_t i = 0; i < body_len; i++) {
            digits_only = digits_only && body[i] >= '0' && body[i] <= '9';
        }
        /* an integer too large for u64 still reads as its float */
        n.is_integer = digits_only && daran_parse_u64(body, body_len, &n.magnitude) == DARAN_OK;
    }
    *out = n;
    return DARAN_OK;
}

daran_result_t daran_client_number_u64(const daran_client_number_t *n, uint64_t *out)
{
    if (n == NULL || out == NULL || !n->is_integer) {
        return DARAN_ERR_INVALID_VALUE;
    }
    if (n->negative && n->magnitude != 0u) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    *out = n->magnitude;
    return DARAN_OK;
}

daran_result_t daran_client_number_u32(const daran_client_number_t *n, uint32_t *out)
{
    uint64_t value = 0;
    daran_result_t result = daran_client_number_u64(n, &value);
    if (result != DARAN_OK) {
        return result;
    }
    if (value > UINT32_MAX) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    *out = (uint32_t)value;
    return DARAN_OK;
}

daran_result_t daran_client_number_s32(const daran_client_number_t *n, int32_t *out)
{
    if (n == NULL || out == NULL || !n->is_integer) {
        return DARAN_ERR_INVALID_VALUE;
    }
    uint64_t limit = n->negative ? 2147483648u : 2147483647u;
    if (n->magnitude > limit) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    /* -2^31 has no positive twin: subtract from -1 instead of negating */
    *out = n->negative && n->magnitude != 0u ? (int32_t)(-1 - (int64_t)(n->magnitude - 1u))
                                              : (int32_t)n->magnitude;
    return DARAN_OK;
}

/* The next field of text[*pos..len), as a view; false when none is left. */
static bool next_field(const char *text, size_t len, size_t *pos, const char **field,
                       size_t *field_len)
{
    size_t i = *pos;
    while (i < len && is_blank(text[i])) {
        i++;
    }
    size_t start = i;
    while (i < len && !is_blank(text[i])) {
        i++;
    }
    *pos = i;
    *field = text + start;
    *field_len = i - start;
    return i > start;
}

/* Numbers of text[0..len) into out[0..max); *count set; INVALID_VALUE for
 * a field that is not a number or one past max. */
static daran_result_t parse_numbers(const char *text, size_t len, daran_client_number_t *out,
                                    size_t max, size_t *count)
{
    size_t pos = 0;
    size_t n = 0;
    const char *field;
    size_t field_len;
    while (next_field(text, len, &pos, &field, &field_len)) {
        if (n == max || daran_client_parse_number(field, field_len, &out[n]) != DARAN_OK) {
            return DARAN_ERR_INVALID_VALUE;
        }
        n++;
    }
    *count = n;
    return DARAN_OK;
}

daran_result_t daran_client_parse_values(const daran_client_line_t *line,
                                         daran_client_number_t *out, size_t max, size_t expected,
                                         size_t *count)
{
    if (line == NULL || out == NULL || count == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    size_t n = 0;
    if (line->kind != DARAN_CLIENT_LINE_TEXT ||
        parse_numbers(line->payload, line->len, out, max, &n) != DARAN_OK || n == 0u ||
        (expected != 0u && n != expected)) {
        return DARAN_ERR_INVALID_VALUE;
    }
    *count = n;
    return DARAN_OK;
}

static const char register_names[] =
    "axis\0motor\0encoder\0controller\0fet_thermistor\0motor_thermistor\0can";

const char *daran_client_error_register_name(size_t index)
{
    return index < DARAN_CLIENT_ERROR_REGISTERS ? daran_nth_text(register_names, (unsigned)index)
                                                : NULL;
}

daran_result_t daran_client_parse_error_line(const daran_client_line_t *line, size_t index,
                                             daran_client_errors_t *errors)
{
    const char *name = daran_client_error_register_name(index);
    if (line == NULL || errors == NULL || name == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    size_t name_len = daran_text_len(name);
    const char *text = line->payload;
    size_t len = line->len;
    if (line->kind != DARAN_CLIENT_LINE_TEXT || len < name_len + 3u ||
        !same_text(text, name_len, name) || text[name_len] != ':' || text[name_len + 1u] != ' ') {
        return DARAN_ERR_INVALID_VALUE;
    }
    daran_client_number_t value;
    uint32_t reg = 0;
    if (daran_client_parse_number(text + name_len + 2u, len - name_len - 2u, &value) != DARAN_OK ||
        value.negative || daran_client_number_u32(&value, &reg) != DARAN_OK) {
        return DARAN_ERR_INVALID_VALUE;
    }
    errors->reg[index] = reg;
    return DARAN_OK;
}

daran_result_t daran_client_parse_report(const daran_client_line_t *line,
                                         daran_client_report_t *out)
{
    if (line == NULL || out == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    if (line->kind != DARAN_CLIENT_LINE_TELEMETRY) {
        return DARAN_ERR_INVALID_VALUE;
    }
    size_t pos = 1; /* after the '@' */
    const char *field;
    size_t field_len;
    daran_client_number_t id;
    daran_client_number_t time;
    uint32_t id_value = 0;
    /* the id sits right after '@', no blank between */
    if (line->len < 2u || is_blank(line->payload[1]) ||
        !next_field(line->payload, line->len, &pos, &field, &field_len) ||
        daran_client_parse_number(field, field_len, &id) != DARAN_OK || id.negative ||
        daran_client_number_u32(&id, &id_value) != DARAN_OK || id_value > 255u ||
        !next_field(line->payload, line->len, &pos, &field, &field_len) ||
        daran_client_parse_number(field, field_len, &time) != DARAN_OK) {
        return DARAN_ERR_INVALID_VALUE;
    }
    daran_client_report_t report;
    report.id = (uint8_t)id_value;
    report.time_s = time.f32;
    if (parse_numbers(line->payload + pos, line->len - pos, report.values,
                      DARAN_CLIENT_REPORT_MAX, &report.count) != DARAN_OK) {
        return DARAN_ERR_INVALID_VALUE;
    }
    *out = report;
    return DARAN_OK;
}

static const char type_names[] = "f32\0u32\0s32\0u64\0bool";

daran_result_t daran_client_parse_property(const daran_client_line_t *line,
                                           daran_client_property_t *out)
{
    if (line == NULL || out == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    if (line->kind != DARAN_CLIENT_LINE_TEXT) {
        return DARAN_ERR_INVALID_VALUE;
    }
    const char *text = line->payload;
    size_t pos = 0;
    daran_client_property_t p;
    const char *type;
    size_t type_len;
    const char *access;
    size_t access_len;
    if (!next_field(text, line->len, &pos, &p.path, &p.path_len) ||
        !next_field(text, line->len, &pos, &type, &type_len) ||
        !next_field(text, line->len, &pos, &access, &access_len) ||
        !next_field(text, line->len, &pos, &p.unit, &p.unit_len)) {
        return DARAN_ERR_INVALID_VALUE;
    }
    if (!next_field(text, line->len, &pos, &p.range, &p.range_len)) {
        p.range_len = 0;
    }
    const char *extra;
    size_t extra_len;
    if (next_field(text, line->len, &pos, &extra, &extra_len)) {
        return DARAN_ERR_INVALID_VALUE;
    }
    unsigned t = 0;
    for (; t <= (unsigned)DARAN_CLIENT_TYPE_BOOL; t++) {
        if (same_text(type, type_len, daran_nth_text(type_names, t))) {
            break;
        }
    }
    if (t > (unsigned)DARAN_CLIENT_TYPE_BOOL) {
        return DARAN_ERR_INVALID_VALUE;
    }
    p.type = (daran_client_type_t)t;
    if (same_text(access, access_len, "rw")) {
        p.writable = true;
    } else if (same_text(access, access_len, "ro")) {
        p.writable = false;
    } else {
        return DARAN_ERR_INVALID_VALUE;
    }
    if (same_text(p.unit, p.unit_len, "-")) {
        p.unit_len = 0;
    }
    *out = p;
    return DARAN_OK;
}

daran_result_t daran_client_parse_help(const daran_client_line_t *line, daran_client_help_t *out)
{
    if (line == NULL || out == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    size_t pos = 0;
    daran_client_help_t help;
    if (line->kind != DARAN_CLIENT_LINE_TEXT ||
        !next_field(line->payload, line->len, &pos, &help.word, &help.word_len)) {
        return DARAN_ERR_INVALID_VALUE;
    }
    while (pos < line->len && is_blank(line->payload[pos])) {
        pos++;
    }
    help.arguments = line->payload + pos;
    help.arguments_len = line->len - pos;
    *out = help;
    return DARAN_OK;
}
