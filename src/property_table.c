/* The property table: each property's attributes (from DARAN_PROPERTY_LIST)
 * and the lookup of a path.
 *
 * Paths are not stored whole. src/property_index.h (generated from the same
 * list by tools/gen_property_index.py) holds every dot-separated segment once,
 * 5 bits a character, and each path as a key of segment numbers, so lookup is two binary
 * searches: O(log segments) per segment, then O(log properties) for the key. */
#include "internal.h"
#include "property_index.h"

#define SCOPE_SYSTEM DARAN_SCOPE_SYSTEM
#define SCOPE_AXIS DARAN_SCOPE_AXIS
#define TYPE_F32 DARAN_TYPE_F32
#define TYPE_U32 DARAN_TYPE_U32
#define TYPE_U64 DARAN_TYPE_U64
#define TYPE_BOOL DARAN_TYPE_BOOL
#define ACCESS_RO DARAN_ACCESS_RO
#define ACCESS_RW DARAN_ACCESS_RW
#define RANGE_NONE DARAN_RANGE_NONE
#define RANGE_NON_NEGATIVE DARAN_RANGE_NON_NEGATIVE
#define RANGE_POSITIVE DARAN_RANGE_POSITIVE
#define RANGE_BOOL DARAN_RANGE_BOOL
#define RANGE_NODE_ID DARAN_RANGE_NODE_ID
#define RANGE_UART_BAUD DARAN_RANGE_UART_BAUD
#define RANGE_CAN_BAUD DARAN_RANGE_CAN_BAUD
#define RANGE_AXIS_STATE DARAN_RANGE_AXIS_STATE

const daran_property_t daran_properties[DARAN_PROP_COUNT] = {
#define DARAN_PROPERTY_ROW_(id, path, scope, type, access, range, unit) \
    [DARAN_PROP_##id] = DARAN_PROPERTY_ROW(ACCESS_##access, TYPE_##type, RANGE_##range),
    DARAN_PROPERTY_LIST(DARAN_PROPERTY_ROW_)
#undef DARAN_PROPERTY_ROW_
};

/* Character i of the packed segment text. */
static unsigned char segment_char(size_t i)
{
    size_t bit = i * 5u;
    unsigned pair = (unsigned)segment_text[bit >> 3] | (unsigned)segment_text[(bit >> 3) + 1u] << 8;
    return (unsigned char)DARAN_SEGMENT_ALPHABET[(pair >> (bit & 7u)) & 0x1Fu];
}

/* The segment number (1-based) of text[0..len), or 0 when there is none. */
static uint32_t find_segment(const char *text, size_t len)
{
    size_t low = 0;
    size_t high = DARAN_SEGMENT_COUNT;
    while (low < high) {
        size_t mid = low + (high - low) / 2u;
        size_t start = mid == 0u ? 0u : segment_end[mid - 1u];
        size_t seg_len = (size_t)segment_end[mid] - start;
        size_t common = seg_len < len ? seg_len : len;
        int order = 0;
        for (size_t i = 0; i < common && order == 0; i++) {
            unsigned char a = segment_char(start + i);
            unsigned char b = (unsigned char)text[i];
            order = a == b ? 0 : (a < b ? -1 : 1);
        }
        if (order == 0) {
            order = seg_len == len ? 0 : (seg_len < len ? -1 : 1);
        }
        if (order == 0) {
            return (uint32_t)(mid + 1u);
        }
        if (order < 0) {
            low = mid + 1u;
        } else {
            high = mid;
        }
    }
    return 0;
}

daran_result_t daran_find_property(daran_scope_t scope, const char *name, size_t len,
                                   daran_prop_t *prop)
{
    uint32_t key = scope == DARAN_SCOPE_AXIS ? 1u : 0u;
    uint32_t segments = 0;
    size_t start = 0;
    for (;;) {
        size_t end = start;
        while (end < len && name[end] != '.') {
            end++;
        }
        uint32_t number = find_segment(name + start, end - start);
        if (number == 0u || segments == DARAN_MAX_SEGMENTS) {
            return DARAN_ERR_INVALID_PROPERTY;
        }
        key = (key << DARAN_SEGMENT_BITS) | number;
        segments++;
        if (end == len) {
            break;
        }
        start = end + 1u;
    }
    key <<= DARAN_SEGMENT_BITS * (DARAN_MAX_SEGMENTS - segments);

    size_t low = 0;
    size_t high = DARAN_KEY_COUNT;
    while (low < high) {
        size_t mid = low + (high - low) / 2u;
        const uint8_t *stored = &property_key[mid * 3u];
        uint32_t probe = (uint32_t)stored[0] << 16 | (uint32_t)stored[1] << 8 | stored[2];
        if (probe == key) {
            *prop = (daran_prop_t)mid; /* keys are in the list's order */
            return DARAN_OK;
        }
        if (probe < key) {
            low = mid + 1u;
        } else {
            high = mid;
        }
    }
    return DARAN_ERR_INVALID_PROPERTY;
}
