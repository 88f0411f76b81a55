/* The property table: each property's attributes and the lookup of a path.
 *
 * Both come from DARAN_PROPERTY_LIST through tools/gen_property_index.py,
 * run by the build (property_index.h is in the build folder). A path is
 * found by a perfect hash: one pass over its bytes names the only property
 * it can be, and one comparison of that property's words decides. The
 * cost depends on the path's length only, never on how many rows the table
 * has. */
#include <string.h>

#include "compiler.h"
#include "number.h"
#include "property.h"
#include "reply.h"
#include "text.h"

#define DARAN_ATTR(type, access, scope, range, unit) \
    (uint16_t)((type) | (access) << 3 | (scope) << 4 | (range) << 5 | (unit) << 10)
#include "property_index.h"
#include "property_features.h"

/* The packed tables' entries (see the generated header for the layout). */
static unsigned word_end(unsigned n)
{
    return word_end_low[n] | (((unsigned)word_end_high[n >> 2] >> ((n & 3u) * 2u)) & 3u) << 8;
}

static unsigned word_start(unsigned number)
{
    return number > 1u ? word_end(number - 2u) : 0u;
}

static unsigned path_start(unsigned prop)
{
    return path_start_low[prop] | (unsigned)(path_info[prop] >> 6) << 8;
}

daran_property_t daran_property_row(daran_prop_t prop)
{
    return property_attr[prop];
}

/* Every range as the text discovery prints, which is also what `w` checks
 * (daran_range_holds reads it): one source for both, NUL-separated in
 * daran_range_t order because both come from DARAN_RANGE_LIST. */
#define DARAN_RANGE_TEXT_(name, text) text "\0"
#ifndef DARAN_PORT_RANGE_LIST
#define DARAN_PORT_RANGE_LIST(X)
#endif
static const char range_text[] = DARAN_RANGE_LIST(DARAN_RANGE_TEXT_)
    DARAN_PORT_RANGE_LIST(DARAN_RANGE_TEXT_);
#undef DARAN_RANGE_TEXT_

const char *daran_range_text(daran_range_t range)
{
    return daran_nth_text(range_text, (unsigned)range);
}

/* A decimal integer at *p, optionally negative; moves *p past it. */
static int64_t read_integer(const char **p)
{
    const char *t = *p;
    bool negative = *t == '-';
    int64_t v = 0;
    t += negative ? 1 : 0;
    while (*t >= '0' && *t <= '9') {
        v = v * 10 + (*t++ - '0');
    }
    *p = t;
    return negative ? -v : v;
}

bool daran_range_holds(daran_range_t range, int64_t value)
{
    const char *t = daran_range_text(range);
    switch (*t) {
    case '\0':
        return true;
    case '>':
        return t[1] == '=' ? value >= 0 : value > 0;
    case '<':
        return value <= 0;
    default:
        break;
    }
    /* "a..b", or a list "a|b", "{a,b,...}", "a" */
    t += *t == '{' ? 1 : 0;
    for (;;) {
        int64_t low = read_integer(&t);
        if (t[0] == '.' && t[1] == '.') {
            t += 2;
            return value >= low && value <= read_integer(&t);
        }
        if (value == low) {
            return true;
        }
        if (*t != ',' && *t != '|') {
            return false;
        }
        t++;
    }
}

#if DARAN_F32_INTERVALS
bool daran_range_holds_f32(daran_range_t range, float value)
{
    const char *t = daran_range_text(range);
    if (*t == '-' || (*t >= '0' && *t <= '9') || *t == '.') {
        /* "lo..hi": the ends as the floats they parse to, both included */
        size_t dots = 0;
        while (t[dots] != '\0' && !(t[dots] == '.' && t[dots + 1u] == '.')) {
            dots++;
        }
        float low;
        float high;
        const char *high_text = t + dots + 2u;
        size_t high_len = daran_text_len(high_text);
        return t[dots] != '\0' && daran_parse_f32(t, dots, &low) == DARAN_OK &&
               daran_parse_f32(high_text, high_len, &high) == DARAN_OK && value >= low &&
               value <= high;
    }
    /* the sign conditions: -0 counts as 0 (D27) */
    return daran_range_holds(range, value > 0.0f ? 1 : (value < 0.0f ? -1 : 0));
}
#endif

/* The separator before segment k (k >= 1) of a path whose separator bits
 * are @p dots. */
static char separator(unsigned dots, unsigned k)
{
    return ((dots >> (k - 1u)) & 1u) != 0u ? '.' : '_';
}

#if DARAN_ENABLE_DISCOVERY
/* What only discovery (`h id properties`) reads: the rows in path order,
 * each path as text, the units. */
daran_prop_t daran_discovery_next(size_t *cursor)
{
#if DARAN_DISCOVERY_IN_ID_ORDER
    /* id order is path order; rows left out of the build have no path */
    while (*cursor < DARAN_PROP_COUNT) {
        size_t id = (*cursor)++;
        if (path_start((unsigned)id) != path_start((unsigned)id + 1u)) {
            return (daran_prop_t)id;
        }
    }
    return DARAN_PROP_COUNT;
#else
    return *cursor < DARAN_DISCOVERY_COUNT ? (daran_prop_t)discovery_order[(*cursor)++]
                                           : DARAN_PROP_COUNT;
#endif
}

size_t daran_property_path(daran_prop_t prop, char *out)
{
    unsigned first = path_start(prop);
    unsigned end = path_start(prop + 1u);
    size_t len = 0;
    for (unsigned k = first; k < end; k++) {
        if (k > first) {
            out[len++] = separator(path_info[prop], k - first);
        }
        unsigned n = path_words[k];
        const char *text = word_text + word_start(n);
        const char *text_end = word_text + word_end(n - 1u);
        while (text != text_end) {
            out[len++] = *text++;
        }
    }
    return len;
}

void daran_reply_path(daran_drive_t *drive, daran_prop_t prop)
{
    char path[DARAN_PATH_MAX];
    if (DARAN_PROPERTY_SCOPE(property_attr[prop]) == DARAN_SCOPE_AXIS) {
        static const char axis0[] = DARAN_AXIS_WORD "0.";
        daran_reply_text(drive, axis0, sizeof axis0 - 1u);
    }
    daran_reply_text(drive, path, daran_property_path(prop, path));
}

static const char unit_text[] = "-\0" DARAN_UNIT_TEXT;

const char *daran_unit_text(daran_property_t row)
{
    return daran_nth_text(unit_text, DARAN_PROPERTY_UNIT(row));
}
#endif /* DARAN_ENABLE_DISCOVERY */

/* Is a[0..len) b[0..len)? Four bytes a step: a segment is 2 to 30 bytes. */
static bool same_text(const char *a, const char *b, size_t len)
{
    for (; len >= 4u; len -= 4u, a += 4, b += 4) {
        uint32_t x;
        uint32_t y;
        memcpy(&x, a, sizeof x);
        memcpy(&y, b, sizeof y);
        if (x != y) {
            return false;
        }
    }
    for (; len > 0u; len--) {
        if (*a++ != *b++) {
            return false;
        }
    }
    return true;
}

/* Does name[0..len) spell property @p prop's path? Compared segment by
 * segment against the stored text, the path never built. */
static bool path_is(daran_prop_t prop, const char *name, size_t len)
{
    unsigned first = path_start(prop);
    unsigned end = path_start(prop + 1u);
    const char *at = name;
    const char *name_end = name + len;
    if (first == end) {
        return false; /* a row left out of this build has no path at all */
    }
    for (unsigned k = first; k < end; k++) {
        if (k > first) {
            if (at == name_end || *at++ != separator(path_info[prop], k - first)) {
                return false;
            }
        }
        unsigned n = path_words[k];
        const char *text = word_text + word_start(n);
        size_t text_len = word_end(n - 1u) - word_start(n);
        if (text_len > (size_t)(name_end - at)) {
            return false;
        }
        if (!same_text(at, text, text_len)) {
            return false;
        }
        at += text_len;
    }
    return at == name_end;
}

daran_result_t daran_find_property(daran_scope_t scope, const char *name, size_t len,
                                   daran_prop_t *prop)
{
    /* FNV-1a four bytes a step, each four as a little-endian word (one load
     * where the target is little-endian), then the rest a byte at a time:
     * fnv() in tools/gen_property_index.py takes the same steps. */
    uint32_t h = DARAN_HASH_SEED + (uint32_t)scope;
    const uint8_t *byte = (const uint8_t *)name;
    const uint8_t *words_end = byte + (len - len % 4u);
    for (; byte != words_end; byte += 4) {
        uint32_t word = (uint32_t)byte[0] | (uint32_t)byte[1] << 8 | (uint32_t)byte[2] << 16 |
                        (uint32_t)byte[3] << 24;
        h = (h ^ word) * DARAN_HASH_PRIME;
    }
    for (; byte != (const uint8_t *)name + len; byte++) {
        h = (h ^ *byte) * DARAN_HASH_PRIME;
    }
    uint32_t displacement = hash_displacement[h >> (32u - DARAN_HASH_BUCKET_BITS)];
    uint32_t x = (h + displacement * ((h >> 16) | 1u)) & 0xFFFFu;
    unsigned candidate = hash_slot[(x * DARAN_HASH_SLOTS) >> 16];
    if (candidate == DARAN_HASH_EMPTY ||
        DARAN_PROPERTY_SCOPE(property_attr[candidate]) != scope ||
        !path_is((daran_prop_t)candidate, name, len)) {
        return DARAN_ERR_INVALID_PROPERTY;
    }
    *prop = (daran_prop_t)candidate;
    return DARAN_OK;
}
