/* The property table, built from DARAN_PROPERTY_LIST, and its lookup.
 * Rows are sorted by (scope, path), so a path is found by binary search:
 * O(log n) comparisons, never a scan of the whole table.
 *
 * The names are packed into one struct of char arrays without terminators,
 * and each row keeps a 16-bit offset into it: 4 bytes a row instead of a
 * pointer, a length and a padded struct. */
#include <stddef.h>

#include "internal.h"

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

typedef struct property_names {
#define DARAN_NAME_FIELD_(id, path, scope, type, access, range, unit) char id[sizeof(path) - 1u];
    DARAN_PROPERTY_LIST(DARAN_NAME_FIELD_)
#undef DARAN_NAME_FIELD_
} property_names_t;

static const property_names_t names = {
#define DARAN_NAME_INIT_(id, path, scope, type, access, range, unit) path,
    DARAN_PROPERTY_LIST(DARAN_NAME_INIT_)
#undef DARAN_NAME_INIT_
};

const daran_property_t daran_properties[DARAN_PROP_COUNT] = {
#define DARAN_PROPERTY_ROW_(id, path, scope, type, access, range, unit)                    \
    [DARAN_PROP_##id] = {offsetof(property_names_t, id), sizeof(path) - 1u, SCOPE_##scope, \
                         ACCESS_##access, TYPE_##type, RANGE_##range},
    DARAN_PROPERTY_LIST(DARAN_PROPERTY_ROW_)
#undef DARAN_PROPERTY_ROW_
};

/* The SYSTEM rows come first; this counts them at compile time. */
#define IS_SYSTEM_SYSTEM 1
#define IS_SYSTEM_AXIS 0
enum {
#define DARAN_COUNT_SYSTEM_(id, path, scope, type, access, range, unit) +IS_SYSTEM_##scope
    SYSTEM_ROWS = 0 DARAN_PROPERTY_LIST(DARAN_COUNT_SYSTEM_)
#undef DARAN_COUNT_SYSTEM_
};

const char *daran_property_name(daran_prop_t prop)
{
    return (const char *)&names + daran_properties[prop].name_offset;
}

static int compare_path(daran_prop_t prop, const char *name, size_t len)
{
    const char *path = daran_property_name(prop);
    size_t path_len = daran_properties[prop].name_len;
    size_t common = path_len < len ? path_len : len;
    for (size_t i = 0; i < common; i++) {
        unsigned char a = (unsigned char)path[i];
        unsigned char b = (unsigned char)name[i];
        if (a != b) {
            return a < b ? -1 : 1;
        }
    }
    if (path_len == len) {
        return 0;
    }
    return path_len < len ? -1 : 1;
}

daran_result_t daran_find_property(daran_scope_t scope, const char *name, size_t len,
                                   daran_prop_t *prop)
{
    size_t low = scope == DARAN_SCOPE_SYSTEM ? 0u : (size_t)SYSTEM_ROWS;
    size_t high = scope == DARAN_SCOPE_SYSTEM ? (size_t)SYSTEM_ROWS : (size_t)DARAN_PROP_COUNT;
    while (low < high) {
        size_t mid = low + (high - low) / 2u;
        int order = compare_path((daran_prop_t)mid, name, len);
        if (order == 0) {
            *prop = (daran_prop_t)mid;
            return DARAN_OK;
        }
        if (order < 0) {
            low = mid + 1u;
        } else {
            high = mid;
        }
    }
    return DARAN_ERR_INVALID_PROPERTY;
}
