/* `r` and `w`: property access through the table. The dispatcher has
 * already found the property; here its value is formatted or parsed and
 * range-checked against the table row. */
#include "internal.h"

daran_result_t daran_cmd_r(daran_drive_t *drive, const daran_request_t *request)
{
    return daran_reply_properties(drive, &request->prop, 1);
}

/* The integers the set ranges allow, each list ending in 0 (no set holds 0). */
static const uint32_t allowed_sets[] = {
    9600u, 19200u, 38400u, 57600u, 115200u, 0u,   /* DARAN_RANGE_UART_BAUD, from 0 */
    125000u, 250000u, 500000u, 1000000u, 0u,      /* DARAN_RANGE_CAN_BAUD, from 6 */
    DARAN_STATE_IDLE, DARAN_STATE_CLOSED_LOOP, 0u, /* DARAN_RANGE_AXIS_STATE, from 11 */
};

static bool integer_in_range(daran_range_t range, uint64_t value)
{
    size_t i;
    switch (range) {
    case DARAN_RANGE_BOOL:
        return value <= 1u;
    case DARAN_RANGE_NODE_ID:
        return value >= 1u && value <= DARAN_MOTOR_ID_MAX;
    case DARAN_RANGE_UART_BAUD:
        i = 0;
        break;
    case DARAN_RANGE_CAN_BAUD:
        i = 6;
        break;
    case DARAN_RANGE_AXIS_STATE:
        i = 11;
        break;
    default:
        return true; /* the integer properties without a listed range take any value */
    }
    for (; allowed_sets[i] != 0u; i++) {
        if (value == allowed_sets[i]) {
            return true;
        }
    }
    return false;
}

/* Grammar and range of the written value, as the property's table row says. */
static daran_result_t parse_value(daran_property_t row, const daran_field_t *field,
                                  daran_value_t *value)
{
    daran_range_t range = DARAN_PROPERTY_RANGE(row);
    uint64_t integer;
    daran_result_t result;
    if (DARAN_PROPERTY_TYPE(row) == DARAN_TYPE_F32) {
        result = daran_field_f32(field, &value->f32);
        if (result == DARAN_OK && ((range == DARAN_RANGE_POSITIVE && !(value->f32 > 0.0f)) ||
                                   (range == DARAN_RANGE_NON_NEGATIVE && !(value->f32 >= 0.0f)))) {
            result = DARAN_ERR_OUT_OF_RANGE;
        }
        return result;
    }
    result = daran_parse_u64(field->text, field->len, &integer);
    if (result != DARAN_OK) {
        return result;
    }
    if (DARAN_PROPERTY_TYPE(row) == DARAN_TYPE_U64) {
        value->u64 = integer;
    } else {
        value->u32 = (uint32_t)integer;
    }
    if (DARAN_PROPERTY_TYPE(row) != DARAN_TYPE_U64 && integer > UINT32_MAX) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    return integer_in_range(range, integer) ? DARAN_OK : DARAN_ERR_OUT_OF_RANGE;
}

daran_result_t daran_cmd_w(daran_drive_t *drive, const daran_request_t *request)
{
    daran_property_t row = daran_properties[request->prop];
    if (DARAN_PROPERTY_ACCESS(row) != DARAN_ACCESS_RW) {
        return DARAN_ERR_READ_ONLY;
    }
    daran_value_t value;
    value.u64 = 0;
    daran_field_t field = daran_field_at(request->fields, 2);
    daran_result_t result = parse_value(row, &field, &value);
    if (result != DARAN_OK) {
        return result;
    }
    if (request->prop == DARAN_PROP_REQUESTED_STATE && value.u32 == DARAN_STATE_CLOSED_LOOP) {
        /* Closing the loop is refused while a flag still holds the drive (D21). */
        result = daran_check_motion_allowed(drive);
        if (result == DARAN_ERR_MOTOR_IDLE) {
            result = DARAN_OK;
        }
        if (result != DARAN_OK) {
            return result;
        }
    }
    return daran_from_hal(drive->hal->set(drive->hal_ctx, request->prop, value));
}
