/* The build's properties as the suite sees them: the public lists
 * (DARAN_PROPERTY_LIST, the port's DARAN_PORT_PROPERTY_LIST, less
 * DARAN_OMIT_PROPERTIES), compiled against the adopter's options header;
 * rows left out with the CMake list DARAN_PROPERTY_OMIT are found by probing
 * (`r` answers invalid property without a HAL call). Also: ranges, values
 * and their texts, and the r/w lines. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "conformance.h"

conf_prop_t conf_props[DARAN_PROP_COUNT];

/* The range texts, from the same list the core reads them from. */
#define CONF_RANGE_TEXT_(name, text) [DARAN_RANGE_##name] = text,
static const char *const range_texts[DARAN_RANGE_COUNT] = {
    DARAN_RANGE_LIST(CONF_RANGE_TEXT_)
#ifdef DARAN_PORT_RANGE_LIST
    DARAN_PORT_RANGE_LIST(CONF_RANGE_TEXT_)
#endif
};
#undef CONF_RANGE_TEXT_

#define CONF_SCOPE_AXIS true
#define CONF_SCOPE_SYSTEM false
#define CONF_ACCESS_RW true
#define CONF_ACCESS_RO false

typedef struct conf_row {
    daran_prop_t id;
    const char *path;
    bool axis;
    daran_prop_type_t type;
    bool rw;
    daran_range_t range;
    const char *unit;
} conf_row_t;

#define CONF_ROW_(id, path, scope, type, access, range, unit, can) \
    {DARAN_PROP_##id, path, CONF_SCOPE_##scope, DARAN_TYPE_##type, CONF_ACCESS_##access, DARAN_RANGE_##range, unit},
static const conf_row_t rows[] = {
    DARAN_PROPERTY_LIST(CONF_ROW_)
#ifdef DARAN_PORT_PROPERTY_LIST
    DARAN_PORT_PROPERTY_LIST(CONF_ROW_)
#endif
};
#undef CONF_ROW_

void conf_model_init(void)
{
    memset(conf_props, 0, sizeof conf_props);
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        conf_prop_t *p = &conf_props[rows[i].id];
        p->path = rows[i].path;
        p->axis = rows[i].axis;
        p->type = rows[i].type;
        p->rw = rows[i].rw;
        p->range_text = range_texts[rows[i].range];
        p->unit = rows[i].unit;
        conf_parse_range(p->range_text, &p->range);
    }
#ifdef DARAN_OMIT_PROPERTIES
#define CONF_OMIT_(id) conf_props[DARAN_PROP_##id].header_omits = true;
    DARAN_OMIT_PROPERTIES(CONF_OMIT_)
#undef CONF_OMIT_
#endif
}

bool conf_in_build(daran_prop_t prop)
{
    return conf_props[prop].presence == PRESENT_IN_BUILD;
}

/* ---- ranges ---- */

/* A number at *p (strtod's grammar), moving *p past it. */
static bool read_number(const char **p, double *out)
{
    char *end;
    *out = strtod(*p, &end);
    if (end == *p) {
        return false;
    }
    *p = end;
    return true;
}

void conf_parse_range(const char *text, conf_range_t *range)
{
    memset(range, 0, sizeof *range);
    const char *p = text;
    if (*p == '\0') {
        range->kind = RANGE_ANY;
        return;
    }
    if (strcmp(p, ">=0") == 0) {
        range->kind = RANGE_NON_NEGATIVE;
        return;
    }
    if (strcmp(p, ">0") == 0) {
        range->kind = RANGE_POSITIVE;
        return;
    }
    if (strcmp(p, "<=0") == 0) {
        range->kind = RANGE_NON_POSITIVE;
        return;
    }
    range->kind = RANGE_UNKNOWN;
    const char *dots = strstr(p, "..");
    if (dots != NULL) {
        /* "a..b": read a from a copy, as strtod would take "1." of "1..5" */
        char first_text[48];
        size_t len = (size_t)(dots - p);
        if (len == 0u || len >= sizeof first_text) {
            return;
        }
        memcpy(first_text, p, len);
        first_text[len] = '\0';
        const char *q = first_text;
        const char *last_text = dots + 2;
        double lo;
        double hi;
        if (read_number(&q, &lo) && *q == '\0' && read_number(&last_text, &hi) &&
            *last_text == '\0' && lo <= hi) {
            range->kind = RANGE_INTERVAL;
            range->lo = lo;
            range->hi = hi;
        }
        return;
    }
    bool braces = *p == '{';
    if (braces) {
        p++;
    }
    double first;
    if (!read_number(&p, &first)) {
        return;
    }
    /* a set: "{a,b,...}", "a|b" or one value "a" */
    char separator = braces ? ',' : '|';
    range->set[range->set_count++] = first;
    while (*p == separator && range->set_count < CONF_SET_MAX) {
        p++;
        if (!read_number(&p, &range->set[range->set_count])) {
            return;
        }
        range->set_count++;
    }
    if ((braces && p[0] == '}' && p[1] == '\0') || (!braces && *p == '\0')) {
        range->kind = RANGE_SET;
    }
}

static bool range_holds(const conf_range_t *range, double v)
{
    switch (range->kind) {
    case RANGE_ANY: return true;
    case RANGE_NON_NEGATIVE: return v >= 0.0;
    case RANGE_POSITIVE: return v > 0.0;
    case RANGE_NON_POSITIVE: return v <= 0.0;
    case RANGE_INTERVAL: return v >= range->lo && v <= range->hi;
    case RANGE_SET:
        for (size_t i = 0; i < range->set_count; i++) {
            if (range->set[i] == v) {
                return true;
            }
        }
        return false;
    default: return true;
    }
}

/* Does the type itself carry v (integers: whole and within their width)? */
static bool type_holds(daran_prop_type_t type, double v)
{
    switch (type) {
    case DARAN_TYPE_F32: return fabs(v) <= 3.4028234663852886e38;
    case DARAN_TYPE_BOOL:
    case DARAN_TYPE_U32: return v == floor(v) && v >= 0.0 && v <= 4294967295.0;
    case DARAN_TYPE_S32: return v == floor(v) && v >= -2147483648.0 && v <= 2147483647.0;
    default: return v == floor(v) && v >= 0.0 && v < 18446744073709551616.0;
    }
}

/* ---- texts and values ---- */

static void number_text(daran_prop_type_t type, double v, char *buf, size_t size)
{
    if (type == DARAN_TYPE_F32) {
        (void)snprintf(buf, size, "%.9g", (double)(float)v);
    } else {
        (void)snprintf(buf, size, "%.0f", v);
    }
}

bool conf_value_of_text(daran_prop_type_t type, const char *text, daran_value_t *out)
{
    char *end;
    out->u64 = 0;
    switch (type) {
    case DARAN_TYPE_F32:
        out->f32 = strtof(text, &end);
        break;
    case DARAN_TYPE_S32: {
        long long v = strtoll(text, &end, 10);
        if (v < INT32_MIN || v > INT32_MAX) {
            return false;
        }
        out->s32 = (int32_t)v;
        break;
    }
    case DARAN_TYPE_U64:
        if (text[0] == '-') {
            return false;
        }
        out->u64 = strtoull(text, &end, 10);
        break;
    default: {
        if (text[0] == '-') {
            return false;
        }
        unsigned long long v = strtoull(text, &end, 10);
        if (v > UINT32_MAX) {
            return false;
        }
        out->u32 = (uint32_t)v;
        break;
    }
    }
    return end != text && *end == '\0';
}

void conf_format_value(daran_prop_type_t type, daran_value_t value, char *buf, size_t size)
{
    switch (type) {
    case DARAN_TYPE_F32: (void)snprintf(buf, size, "%.9g", (double)value.f32); break;
    case DARAN_TYPE_S32: (void)snprintf(buf, size, "%ld", (long)value.s32); break;
    case DARAN_TYPE_U64: (void)snprintf(buf, size, "%llu", (unsigned long long)value.u64); break;
    default: (void)snprintf(buf, size, "%lu", (unsigned long)value.u32); break;
    }
}

bool conf_same_value(daran_prop_type_t type, daran_value_t a, daran_value_t b)
{
    switch (type) {
    case DARAN_TYPE_F32: {
        float x = a.f32;
        float y = b.f32;
        if (x != x || y != y) {
            return x != x && y != y;
        }
        if (x == y) {
            return true;
        }
        double scale = fabs((double)x) > fabs((double)y) ? fabs((double)x) : fabs((double)y);
        return fabs((double)x - (double)y) <= 1e-5 * scale + 1e-9;
    }
    case DARAN_TYPE_S32: return a.s32 == b.s32;
    case DARAN_TYPE_U64: return a.u64 == b.u64;
    default: return a.u32 == b.u32;
    }
}

/* The reply number format (protocol.md section 4): integers in decimal,
 * floats as the shortest text, positional or d.ddde±XX, nan, inf, -inf. */
static bool float_text(const char *t, size_t len)
{
    size_t i = 0;
    if (len == 3u && (memcmp(t, "nan", 3) == 0 || memcmp(t, "inf", 3) == 0)) {
        return true;
    }
    if (len == 4u && memcmp(t, "-inf", 4) == 0) {
        return true;
    }
    if (i < len && t[i] == '-') {
        i++;
    }
    size_t digits = 0;
    while (i < len && t[i] >= '0' && t[i] <= '9') {
        i++;
        digits++;
    }
    if (digits == 0u) {
        return false;
    }
    if (i < len && t[i] == '.') {
        i++;
        size_t fraction = 0;
        while (i < len && t[i] >= '0' && t[i] <= '9') {
            i++;
            fraction++;
        }
        if (fraction == 0u) {
            return false;
        }
    }
    if (i < len && t[i] == 'e') {
        i++;
        if (i >= len || (t[i] != '+' && t[i] != '-')) {
            return false;
        }
        i++;
        size_t exponent = 0;
        while (i < len && t[i] >= '0' && t[i] <= '9') {
            i++;
            exponent++;
        }
        if (exponent < 2u) {
            return false;
        }
    }
    return i == len;
}

static bool integer_text(const char *t, size_t len, bool sign)
{
    size_t i = sign && len > 1u && t[0] == '-' ? 1u : 0u;
    if (i == len) {
        return false;
    }
    if (len - i > 1u && t[i] == '0') {
        return false; /* no leading zeros */
    }
    for (; i < len; i++) {
        if (t[i] < '0' || t[i] > '9') {
            return false;
        }
    }
    return true;
}

bool conf_parse_reply_value(daran_prop_type_t type, const char *text, size_t len,
                            daran_value_t *out)
{
    char token[64];
    if (len == 0u || len >= sizeof token) {
        return false;
    }
    memcpy(token, text, len);
    token[len] = '\0';
    switch (type) {
    case DARAN_TYPE_F32:
        if (!float_text(token, len)) {
            return false;
        }
        out->u64 = 0;
        out->f32 = strtof(token, NULL);
        return true;
    case DARAN_TYPE_BOOL:
        if (len != 1u || (token[0] != '0' && token[0] != '1')) {
            return false;
        }
        out->u64 = 0;
        out->u32 = (uint32_t)(token[0] - '0');
        return true;
    case DARAN_TYPE_S32:
        return integer_text(token, len, true) && conf_value_of_text(type, token, out);
    default:
        return integer_text(token, len, false) && len <= 20u && conf_value_of_text(type, token, out) &&
               (type != DARAN_TYPE_U64 || len < 20u || strcmp(token, "18446744073709551615") <= 0);
    }
}

/* ---- lines ---- */

void conf_wire_path(daran_prop_t prop, unsigned id, char *buf, size_t size)
{
    const conf_prop_t *p = &conf_props[prop];
    if (p->axis) {
        (void)snprintf(buf, size, "axis%u.%s", id, p->path);
    } else {
        (void)snprintf(buf, size, "%s", p->path);
    }
}

void conf_read_line(daran_prop_t prop, unsigned id, char *buf, size_t size)
{
    const conf_prop_t *p = &conf_props[prop];
    if (p->axis) {
        (void)snprintf(buf, size, "r axis%u.%s", id, p->path);
    } else {
        (void)snprintf(buf, size, "r %s %u", p->path, id);
    }
}

void conf_write_line(daran_prop_t prop, unsigned id, const char *value, char *buf, size_t size)
{
    const conf_prop_t *p = &conf_props[prop];
    if (p->axis) {
        (void)snprintf(buf, size, "w axis%u.%s %s", id, p->path, value);
    } else {
        (void)snprintf(buf, size, "w %s %s %u", p->path, value, id);
    }
}

bool conf_read_value(daran_prop_t prop, unsigned id, daran_value_t *out, bool quiet)
{
    char line[160];
    conf_read_line(prop, id, line, sizeof line);
    conf_send(line);
    const char *reply = conf_reply();
    size_t len = conf_reply_len();
    size_t end = DARAN_REPLY_CRLF ? 2u : 1u;
    bool ok = conf_reply_lines() == 1u && len > end &&
              conf_parse_reply_value(conf_props[prop].type, reply, len - end, out);
    if (!ok && !quiet) {
        char path[128];
        conf_wire_path(prop, id, path, sizeof path);
        conf_fail("`%s` to answer one value of its type", line);
    }
    return ok;
}

/* ---- values for writes ---- */

/* Keep the texts of candidate values the range and type take, no text twice. */
typedef struct value_list {
    char (*texts)[40];
    size_t count, max;
    daran_prop_type_t type;
} value_list_t;

static void add_value(value_list_t *list, double v, const conf_range_t *range, bool must_hold)
{
    if (list->count == list->max || !type_holds(list->type, v)) {
        return;
    }
    if (must_hold && !range_holds(range, v)) {
        return;
    }
    if (!must_hold && range_holds(range, v)) {
        return;
    }
    char text[40];
    number_text(list->type, v, text, sizeof text);
    for (size_t i = 0; i < list->count; i++) {
        if (strcmp(list->texts[i], text) == 0) {
            return;
        }
    }
    memcpy(list->texts[list->count++], text, sizeof text);
}

static double current_number(daran_prop_type_t type, const daran_value_t *v)
{
    switch (type) {
    case DARAN_TYPE_F32: return (double)v->f32;
    case DARAN_TYPE_S32: return (double)v->s32;
    case DARAN_TYPE_U64: return (double)v->u64;
    default: return (double)v->u32;
    }
}

size_t conf_valid_values(daran_prop_t prop, const daran_value_t *current, char values[][40],
                         size_t max)
{
    const conf_prop_t *p = &conf_props[prop];
    const conf_range_t *range = &p->range;
    bool is_float = p->type == DARAN_TYPE_F32;
    double candidates[CONF_SET_MAX + 8];
    size_t n = 0;
    switch (range->kind) {
    case RANGE_ANY:
        candidates[n++] = is_float ? 1.25 : (p->type == DARAN_TYPE_S32 ? -7.0 : 7.0);
        candidates[n++] = is_float ? -2.5 : 3.0;
        candidates[n++] = 0.0;
        break;
    case RANGE_NON_NEGATIVE:
        candidates[n++] = is_float ? 1.25 : 3.0;
        candidates[n++] = 0.0;
        candidates[n++] = is_float ? 2.5 : 5.0;
        break;
    case RANGE_POSITIVE:
        candidates[n++] = is_float ? 1.25 : 3.0;
        candidates[n++] = is_float ? 2.5 : 1.0;
        break;
    case RANGE_NON_POSITIVE:
        candidates[n++] = is_float ? -1.25 : -3.0;
        candidates[n++] = 0.0;
        candidates[n++] = is_float ? -2.5 : -5.0;
        break;
    case RANGE_INTERVAL: {
        double mid = (range->lo + range->hi) / 2.0;
        candidates[n++] = is_float ? mid : floor(mid);
        candidates[n++] = range->lo;
        candidates[n++] = range->hi;
        break;
    }
    case RANGE_SET:
        for (size_t i = 0; i < range->set_count; i++) {
            candidates[n++] = range->set[i];
        }
        break;
    default:
        return 0;
    }
    if (prop == DARAN_PROP_TELEMETRY_FIELDS && DARAN_REPLY_MAX < 160) {
        /* wide field sets may not fit the reply: the core refuses them (D40) */
        n = 0;
        candidates[n++] = 1.0;
        candidates[n++] = 0.0;
    }
    value_list_t list = {values, 0, max, p->type};
    /* first a value that differs from the current one, so a read-back proves the write */
    double now = current != NULL ? current_number(p->type, current) : NAN;
    for (size_t i = 0; i < n; i++) {
        if (candidates[i] != now) {
            add_value(&list, candidates[i], range, true);
            break;
        }
    }
    for (size_t i = 0; i < n; i++) {
        add_value(&list, candidates[i], range, true);
    }
    return list.count;
}

size_t conf_invalid_values(daran_prop_t prop, char values[][40], size_t max)
{
    const conf_prop_t *p = &conf_props[prop];
    const conf_range_t *range = &p->range;
    value_list_t list = {values, 0, max, p->type};
    /* beyond what the type can carry: the core refuses it as out of range */
    switch (p->type) {
    case DARAN_TYPE_F32:
        if (list.count < max) {
            memcpy(values[list.count++], "3.5e38", 7);
        }
        break;
    case DARAN_TYPE_S32:
        if (list.count + 1u < max) {
            memcpy(values[list.count++], "2147483648", 11);
            memcpy(values[list.count++], "-2147483649", 12);
        }
        break;
    case DARAN_TYPE_U64:
        break;
    default:
        if (list.count + 1u < max) {
            memcpy(values[list.count++], "4294967296", 11);
            memcpy(values[list.count++], "-1", 3);
        }
        break;
    }
    switch (range->kind) {
    case RANGE_NON_NEGATIVE:
        add_value(&list, -1.25, range, false);
        add_value(&list, -1.0, range, false);
        if (p->type == DARAN_TYPE_F32) {
            add_value(&list, -1e-30, range, false);
        }
        break;
    case RANGE_POSITIVE:
        add_value(&list, 0.0, range, false);
        add_value(&list, -1.0, range, false);
        if (p->type == DARAN_TYPE_F32 && list.count < max) {
            memcpy(values[list.count++], "-0", 3); /* -0 is not > 0 (D27) */
        }
        break;
    case RANGE_NON_POSITIVE:
        add_value(&list, 1.25, range, false);
        add_value(&list, 1.0, range, false);
        break;
    case RANGE_INTERVAL: {
        double step = p->type == DARAN_TYPE_F32 ? (range->hi - range->lo) / 4.0 + 1.0 : 1.0;
        add_value(&list, range->hi + step, range, false);
        add_value(&list, range->lo - step, range, false);
        break;
    }
    case RANGE_SET: {
        double top = range->set[0];
        double bottom = range->set[0];
        for (size_t i = 1; i < range->set_count; i++) {
            top = range->set[i] > top ? range->set[i] : top;
            bottom = range->set[i] < bottom ? range->set[i] : bottom;
        }
        add_value(&list, top + 1.0, range, false);
        add_value(&list, bottom - 1.0, range, false);
        /* a value between the members, when there is a gap */
        for (double v = bottom + 1.0; v < top; v += 1.0) {
            if (!range_holds(range, v)) {
                add_value(&list, v, range, false);
                break;
            }
        }
        break;
    }
    default:
        break;
    }
    return list.count;
}
