/* The property table: each property's attributes and the lookup of a path.
 *
 * Both come from DARAN_PROPERTY_LIST through tools/gen_property_index.py,
 * run by the build (property_index.h is in the build folder). A path is
 * found by a perfect hash: one pass over its bytes names the only property
 * it can be, and one comparison of that property's segments decides. The
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

/* Is text[0..len) exactly segment n (1-based)? */
static bool segment_is(unsigned n, const char *text, size_t len)
{
    size_t start = n > 1u ? segment_end[n - 2u] : 0u;
    if ((size_t)segment_end[n - 1u] - start != len) {
        return false;
    }
    const char *stored = segment_text + start;
    for (size_t i = 0; i < len; i++) {
        if (stored[i] != text[i]) {
            return false;
        }
    }
    return true;
}

/* Does name[0..len) spell property @p prop's path? */
static bool path_is(daran_prop_t prop, const char *name, size_t len)
{
    const uint8_t *segments = property_segments[prop];
    size_t start = 0;
    for (unsigned k = 0; k < 3u && segments[k] != 0u; k++) {
        if (k > 0u) {
            if (start >= len || name[start] != '.') {
                return false;
            }
            start++;
        }
        size_t end = start;
        while (end < len && name[end] != '.') {
            end++;
        }
        if (!segment_is(segments[k], name + start, end - start)) {
            return false;
        }
        start = end;
    }
    return segments[0] != 0u && start == len;
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
