/* The property table: each property's attributes and the lookup of a path.
 *
 * Both come from DARAN_PROPERTY_LIST through tools/gen_property_index.py,
 * run by the build (property_index.h is in the build folder). A path is
 * found by a perfect hash: one pass over its bytes names the only property
 * it can be, and one comparison of that property's words decides. The
 * cost depends on the path's length only, never on how many rows the table
 * has. */
#include "internal.h"

#define DARAN_ATTR(type, access, scope, range, unit) \
    (uint16_t)((type) | (access) << 3 | (scope) << 4 | (range) << 5 | (unit) << 10)
#include "property_index.h"

daran_property_t daran_property_row(daran_prop_t prop)
{
    return property_attr[prop];
}

const int32_t daran_range_sets[] = {
    9600, 19200, 38400, 57600, 115200, /* 0: UART_BAUD */
    125000, 250000, 500000, 1000000,   /* 5: CAN_BAUD */
    (int32_t)DARAN_STATE_IDLE, (int32_t)DARAN_STATE_CLOSED_LOOP, /* 9: AXIS_STATE */
    1, 2, 3, 5, 6, 9,                  /* 11: INPUT_MODE */
    -1, 1,                             /* 17: DIRECTION */
    0, 2, 3,                           /* 19: MOTOR_TYPE */
};

#define ANY_INT {DARAN_RULE_INTERVAL, 0, 0, INT32_MIN, INT32_MAX}
#define INTERVAL(low, high) {DARAN_RULE_INTERVAL, 0, 0, low, high}
#define SET(first, count) {DARAN_RULE_SET, count, 0, first, 0}
const daran_range_rule_t daran_range_rules[DARAN_RANGE_COUNT] = {
    [DARAN_RANGE_NONE] = ANY_INT,
    [DARAN_RANGE_NON_NEGATIVE] = {DARAN_RULE_INTERVAL, 0, 1, 0, INT32_MAX},
    [DARAN_RANGE_POSITIVE] = {DARAN_RULE_INTERVAL, 0, 2, 1, INT32_MAX},
    [DARAN_RANGE_NON_POSITIVE] = {DARAN_RULE_INTERVAL, 0, -1, INT32_MIN, 0},
    [DARAN_RANGE_BOOL] = INTERVAL(0, 1),
    [DARAN_RANGE_ZERO] = INTERVAL(0, 0),
    [DARAN_RANGE_NODE_ID] = INTERVAL(1, DARAN_MOTOR_ID_MAX),
    [DARAN_RANGE_UART_BAUD] = SET(0, 5),
    [DARAN_RANGE_CAN_BAUD] = SET(5, 4),
    [DARAN_RANGE_CAN_PROTOCOL] = INTERVAL(0, 1),
    [DARAN_RANGE_AXIS_STATE] = SET(9, 2),
    [DARAN_RANGE_CONTROL_MODE] = INTERVAL(1, 3),
    [DARAN_RANGE_INPUT_MODE] = SET(11, 6),
    [DARAN_RANGE_TRAJ_MODE] = INTERVAL(1, 2),
    [DARAN_RANGE_DIRECTION] = SET(17, 2),
    [DARAN_RANGE_MOTOR_TYPE] = SET(19, 3),
    [DARAN_RANGE_POLE_PAIRS] = INTERVAL(1, 128),
    [DARAN_RANGE_TELEMETRY] = INTERVAL(0, 511),
};

daran_prop_t daran_discovery_next(size_t *cursor)
{
#if DARAN_DISCOVERY_IN_ID_ORDER
    /* id order is path order; rows left out of the build have no path */
    while (*cursor < DARAN_PROP_COUNT) {
        size_t id = (*cursor)++;
        if (path_start[id] != path_start[id + 1u]) {
            return (daran_prop_t)id;
        }
    }
    return DARAN_PROP_COUNT;
#else
    return *cursor < DARAN_DISCOVERY_COUNT ? (daran_prop_t)discovery_order[(*cursor)++]
                                           : DARAN_PROP_COUNT;
#endif
}

void daran_reply_path(daran_drive_t *drive, daran_prop_t prop)
{
    if (DARAN_PROPERTY_SCOPE(property_attr[prop]) == DARAN_SCOPE_AXIS) {
        daran_reply_text(drive, "axis0.", 6);
    }
    unsigned dots = path_dots[prop];
    for (size_t k = path_start[prop]; k < path_start[prop + 1u]; k++) {
        if (k > path_start[prop]) {
            daran_reply_text(drive, (dots & 1u) != 0u ? "." : "_", 1);
            dots >>= 1;
        }
        unsigned n = path_words[k];
        size_t start = n > 1u ? word_end[n - 2u] : 0u;
        daran_reply_text(drive, word_text + start, word_end[n - 1u] - start);
    }
}

static const char unit_text[] = "-\0" DARAN_UNIT_TEXT;

const char *daran_unit_text(daran_property_t row)
{
    const char *unit = unit_text;
    for (unsigned n = DARAN_PROPERTY_UNIT(row); n > 0u; n--) {
        while (*unit != '\0') {
            unit++;
        }
        unit++;
    }
    return unit;
}

/* Does name[0..len) spell property @p prop's path? Word by word, each
 * followed by the separator its bit says. */
static bool path_is(daran_prop_t prop, const char *name, size_t len)
{
    const uint8_t *word = path_words + path_start[prop];
    const uint8_t *end = path_words + path_start[prop + 1u];
    unsigned dots = path_dots[prop];
    size_t at = 0;
    if (word == end) {
        return false; /* left out of this build */
    }
    for (;;) {
        unsigned n = *word++;
        size_t start = n > 1u ? word_end[n - 2u] : 0u;
        size_t word_len = (size_t)word_end[n - 1u] - start;
        if (len - at < word_len) {
            return false;
        }
        for (size_t i = 0; i < word_len; i++) {
            if (name[at + i] != word_text[start + i]) {
                return false;
            }
        }
        at += word_len;
        if (word == end) {
            return at == len;
        }
        if (at == len || name[at] != ((dots & 1u) != 0u ? '.' : '_')) {
            return false;
        }
        dots >>= 1;
        at++;
    }
}

daran_result_t daran_find_property(daran_scope_t scope, const char *name, size_t len,
                                   daran_prop_t *prop)
{
    uint32_t h = DARAN_HASH_SEED + (uint32_t)scope;
    for (size_t i = 0; i < len; i++) {
        h = (h ^ (uint8_t)name[i]) * 16777619u;
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
