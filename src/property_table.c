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
