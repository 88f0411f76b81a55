/* Command-line arguments: ids, values and times, read with the client's
 * own number parser (the one the drive's replies go through). */
#include <string.h>

#include "cli.h"

static bool number_of(const char *text, daran_client_number_t *n)
{
    return text != NULL && text[0] != '\0' &&
           daran_client_parse_number(text, strlen(text), n) == DARAN_OK;
}

bool cli_parse_id(const char *text, bool allow_broadcast, uint8_t *id)
{
    daran_client_number_t n;
    uint32_t value;
    if (!number_of(text, &n) || n.negative || daran_client_number_u32(&n, &value) != DARAN_OK ||
        value > DARAN_CLIENT_ID_MAX || (value == 0 && !allow_broadcast)) {
        return false;
    }
    *id = (uint8_t)value;
    return true;
}

bool cli_parse_value(const char *text, daran_client_value_t *value)
{
    daran_client_number_t n;
    if (!number_of(text, &n)) {
        return false;
    }
    memset(value, 0, sizeof *value);
    if (!n.is_integer) {
        value->kind = DARAN_CLIENT_VALUE_F32;
        value->f32 = n.f32;
        return true;
    }
    if (!n.negative) {
        value->kind = DARAN_CLIENT_VALUE_UINT;
        value->uint = n.magnitude;
        return true;
    }
    if (n.magnitude > (uint64_t)INT64_MAX + 1u) {
        return false;
    }
    value->kind = DARAN_CLIENT_VALUE_INT;
    value->sint = n.magnitude == (uint64_t)INT64_MAX + 1u ? INT64_MIN : -(int64_t)n.magnitude;
    return true;
}

bool cli_parse_seconds(const char *text, uint32_t *ms)
{
    daran_client_number_t n;
    if (!number_of(text, &n) || n.negative || !(n.f32 >= 0.0f) || n.f32 > 3600.0f) {
        return false;
    }
    *ms = (uint32_t)(n.f32 * 1000.0f + 0.5f);
    return true;
}

size_t cli_split_fields(const char *text, size_t len, cli_field_t *out, size_t max)
{
    size_t count = 0;
    size_t i = 0;
    for (;;) {
        while (i < len && text[i] == ' ') {
            i++;
        }
        if (i == len) {
            return count;
        }
        size_t start = i;
        while (i < len && text[i] != ' ') {
            i++;
        }
        if (count < max) {
            out[count].text = text + start;
            out[count].len = i - start;
        }
        count++;
    }
}

void cli_take_line(void *ctx, const daran_client_line_t *line)
{
    cli_text_line_t *t = ctx;
    size_t len = line->len < sizeof t->text ? line->len : sizeof t->text;
    memcpy(t->text, line->payload, len);
    t->len = len;
}

bool cli_same_number(const char *a, const char *b)
{
    daran_client_number_t x;
    daran_client_number_t y;
    if (daran_client_parse_number(a, strlen(a), &x) != DARAN_OK ||
        daran_client_parse_number(b, strlen(b), &y) != DARAN_OK) {
        return strcmp(a, b) == 0;
    }
    if (x.is_integer && y.is_integer) {
        return x.magnitude == y.magnitude && (x.negative == y.negative || x.magnitude == 0);
    }
    return x.f32 == y.f32 || (x.f32 != x.f32 && y.f32 != y.f32);
}
