/* The property table (property_table.c): each property's attributes, its
 * path as text, the lookup of a path, and the ranges `w` checks. */
#ifndef DARAN_PROPERTY_H
#define DARAN_PROPERTY_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_drive.h"

typedef enum daran_scope { DARAN_SCOPE_SYSTEM, DARAN_SCOPE_AXIS } daran_scope_t;
typedef enum daran_access { DARAN_ACCESS_RO, DARAN_ACCESS_RW } daran_access_t;

/* One property's attributes in 16 bits: type (3), access (1), scope (1),
 * range (5), unit number (6; 0 = none). Made by tools/gen_property_index.py. */
typedef uint16_t daran_property_t;
#define DARAN_PROPERTY_TYPE(row) ((daran_prop_type_t)((row) & 7u))
#define DARAN_PROPERTY_ACCESS(row) ((daran_access_t)(((row) >> 3) & 1u))
#define DARAN_PROPERTY_SCOPE(row) ((daran_scope_t)(((row) >> 4) & 1u))
#define DARAN_PROPERTY_RANGE(row) ((daran_range_t)(((row) >> 5) & 31u))
#define DARAN_PROPERTY_UNIT(row) ((unsigned)((row) >> 10))

/* The word before an axis path's motor id (`axis1.…`, D8), and the name
 * `e` gives axis0.error's line: one spelling for both. */
#define DARAN_AXIS_WORD "axis"
#define DARAN_AXIS_WORD_LEN (sizeof DARAN_AXIS_WORD - 1u)

daran_property_t daran_property_row(daran_prop_t prop);

/* DARAN_OK with *prop set, or DARAN_ERR_INVALID_PROPERTY. */
daran_result_t daran_find_property(daran_scope_t scope, const char *name, size_t len,
                                   daran_prop_t *prop);

#if DARAN_ENABLE_DISCOVERY
/* Property @p prop's path (without `axisN.`) into out[0..DARAN_PATH_MAX);
 * returns its length, 0 for a row left out of this build. */
#define DARAN_PATH_MAX 64u
size_t daran_property_path(daran_prop_t prop, char *out);

/* Append property @p prop's path as a host writes it (`axis0.` for AXIS). */
void daran_reply_path(daran_drive_t *drive, daran_prop_t prop);

/* The unit text of a property, or "-" when it has none. */
const char *daran_unit_text(daran_property_t row);

/* Discovery: every property this build knows, in path order: start with
 * *cursor 0; DARAN_PROP_COUNT after the last. */
daran_prop_t daran_discovery_next(size_t *cursor);
#endif /* DARAN_ENABLE_DISCOVERY */

/* A range as the text discovery prints (">=0", "1..63", "{9600,...}",
 * "0|1", "" for none), and whether an integer, or a float's sign, is within
 * it: `w` checks with the very text discovery shows. */
const char *daran_range_text(daran_range_t range);
bool daran_range_holds(daran_range_t range, int64_t value);
/* Does a float satisfy a float row's range (a sign condition, or an
 * interval "lo..hi" when the build has one)? */
bool daran_range_holds_f32(daran_range_t range, float value);

#endif /* DARAN_PROPERTY_H */
