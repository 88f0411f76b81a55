/* `r` and `w`: property access through the table. The dispatcher has
 * already found the property; here its value is formatted or parsed and
 * range-checked against the table row. */
#include "handlers.h"
#include "hal.h"
#include "number.h"
#include "property.h"
#include "telemetry.h"

#include "property_features.h"

daran_result_t daran_cmd_r(daran_drive_t *drive, const daran_request_t *request)
{
    return daran_reply_properties(drive, &request->prop, 1);
}

/* An integer field of a property of @p type: the value, or why not. A
 * u64 takes the whole unsigned range and no range rule (serial numbers are
 * read-only); s32 takes a sign. */
static daran_result_t parse_integer(daran_prop_type_t type, const daran_field_t *field,
                                    uint64_t *magnitude, bool *negative)
{
    const char *text = field->text;
    size_t len = field->len;
    *negative = false;
    if (type == DARAN_TYPE_S32 && len > 1u && text[0] == '-' && text[1] != '+' &&
        text[1] != '-') {
        *negative = true;
        text++;
        len--;
    }
    return daran_parse_u64(text, len, magnitude);
}

/* The written value's grammar, as the property's type says; its range is
 * daran_check_property_value()'s. */
daran_result_t daran_parse_property_value(daran_prop_t prop,
                                                              const daran_field_t *field,
                                                              daran_value_t *value)
{
    daran_prop_type_t type = DARAN_PROPERTY_TYPE(daran_property_row(prop));
    if (type == DARAN_TYPE_F32) {
        daran_result_t result = daran_field_f32(field, &value->f32);
        return result == DARAN_OK ? daran_check_property_value(prop, *value) : result;
    }
    uint64_t magnitude;
    bool negative;
    daran_result_t result = parse_integer(type, field, &magnitude, &negative);
    if (result != DARAN_OK) {
        return result;
    }
    if (type == DARAN_TYPE_U64) {
        value->u64 = magnitude;
        return DARAN_OK;
    }
    /* Past 2^31 nothing but a u32 can fit: check before the signed view. */
    if (magnitude > (type == DARAN_TYPE_S32 ? (negative ? 0x80000000u : 0x7FFFFFFFu) : UINT32_MAX)) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    if (type == DARAN_TYPE_S32) {
        value->s32 = (int32_t)(negative ? -(int64_t)magnitude : (int64_t)magnitude);
    } else {
        value->u32 = (uint32_t)magnitude; /* parse_integer takes a sign for s32 alone */
    }
    return daran_check_property_value(prop, *value);
}

daran_result_t daran_cmd_w(daran_drive_t *drive, const daran_request_t *request)
{
    if (DARAN_PROPERTY_ACCESS(daran_property_row(request->prop)) != DARAN_ACCESS_RW) {
        return DARAN_ERR_READ_ONLY;
    }
    daran_value_t value;
    value.u64 = 0;
    daran_field_t field = daran_field_at(request, 2);
    daran_result_t result = daran_parse_property_value(request->prop, &field, &value);
    return result == DARAN_OK ? daran_commit_property(drive, request->prop, value) : result;
}
