/* `h id properties [prefix]`: every property the drive knows, one line each
 * in path order, from the same table that lookup and range checks use (so
 * it cannot drift from them), then `end` (protocol.md 11.1). */
#include "can.h"
#include "handlers.h"
#include "property.h"
#include "reply.h"
#include "text.h"

#if DARAN_ENABLE_DISCOVERY

static const char type_names[] = "f32\0u32\0s32\0u64\0bool";

/* " <range>" as `w` checks it (the same text); nothing for a read-only
 * property or when any value of the type goes. */
static void reply_range(daran_drive_t *drive, daran_property_t row)
{
    const char *text = daran_range_text(DARAN_PROPERTY_RANGE(row));
    if (DARAN_PROPERTY_ACCESS(row) == DARAN_ACCESS_RW && *text != '\0') {
        daran_reply_space(drive);
        daran_reply_cstr(drive, text);
    }
}

/* Does the line built so far (the path) start with the prefix? */
static bool reply_starts_with(const daran_drive_t *drive, const daran_field_t *prefix)
{
    if (drive->reply_len < prefix->len) {
        return false;
    }
    for (uint16_t i = 0; i < prefix->len; i++) {
        if (drive->reply[i] != prefix->text[i]) {
            return false;
        }
    }
    return true;
}

daran_result_t daran_discovery(daran_drive_t *drive, const daran_request_t *request,
                               bool on_can_only)
{
    static const char properties[] = DARAN_H_PROPERTIES_WORD;
    daran_field_t what = daran_field_at(request, 2);
    if (what.len != sizeof properties - 1u) {
        return DARAN_ERR_INVALID_VALUE;
    }
    for (uint16_t i = 0; i < what.len; i++) {
        if (what.text[i] != properties[i]) {
            return DARAN_ERR_INVALID_VALUE;
        }
    }
    daran_field_t prefix = {what.text, 0};
    if (request->fields->count == 4u) {
        prefix = daran_field_at(request, 3);
    }
    size_t cursor = 0;
    for (daran_prop_t prop = daran_discovery_next(&cursor); prop != DARAN_PROP_COUNT;
         prop = daran_discovery_next(&cursor)) {
        daran_property_t row = daran_property_row(prop);
#if DARAN_ENABLE_CAN_BRIDGE
        if (on_can_only && daran_can_address_of(prop) == 0u) {
            continue; /* a bridged `h N properties` lists what the bridge can reach (C35) */
        }
#else
        (void)on_can_only;
#endif
        daran_reply_begin(drive);
        daran_reply_path(drive, prop);
        if (!reply_starts_with(drive, &prefix)) {
            continue;
        }
        daran_reply_space(drive);
        daran_reply_cstr(drive, daran_nth_text(type_names, DARAN_PROPERTY_TYPE(row)));
        daran_reply_text(drive, DARAN_PROPERTY_ACCESS(row) == DARAN_ACCESS_RW ? " rw " : " ro ", 4);
        daran_reply_cstr(drive, daran_unit_text(row));
        reply_range(drive, row);
        daran_reply_end(drive);
    }
    daran_reply_begin(drive);
    daran_reply_text(drive, "end", 3);
    daran_reply_end(drive);
    return DARAN_OK;
}

#endif /* DARAN_ENABLE_DISCOVERY */
