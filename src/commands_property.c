/* `r` and `w`: property access through the table. The dispatcher has
 * already found the property; here its value is formatted or parsed and
 * range-checked against the table row. */
#include "internal.h"

daran_result_t daran_cmd_r(daran_drive_t *drive, const daran_request_t *request)
{
    return daran_reply_properties(drive, &request->prop, 1);
}

static bool in_set(uint64_t value, const uint32_t *set, size_t count)
{
    for (size_t i = 0; i < count; i++) {
        if (value == set[i]) {
            return true;
        }
    }
    return false;
}

static const uint32_t uart_bauds[] = {9600u, 19200u, 38400u, 57600u, 115200u};
static const uint32_t can_bauds[] = {125000u, 250000u, 500000u, 1000000u};

static bool integer_in_range(daran_range_t range, uint64_t value)
{
    switch (range) {
    case DARAN_RANGE_BOOL:
        return value <= 1u;
    case DARAN_RANGE_NODE_ID:
        return value >= 1u && value <= DARAN_MOTOR_ID_MAX;
    case DARAN_RANGE_UART_BAUD:
        return in_set(value, uart_bauds, sizeof uart_bauds / sizeof uart_bauds[0]);
    case DARAN_RANGE_CAN_BAUD:
        return in_set(value, can_bauds, sizeof can_bauds / sizeof can_bauds[0]);
    case DARAN_RANGE_AXIS_STATE:
        return value == DARAN_STATE_IDLE || value == DARAN_STATE_CLOSED_LOOP;
    case DARAN_RANGE_POSITIVE:
        return value > 0u;
    case DARAN_RANGE_NONE:
    case DARAN_RANGE_NON_NEGATIVE:
    default:
        return true;
    }
}

static bool float_in_range(daran_range_t range, float value)
{
    switch (range) {
    case DARAN_RANGE_POSITIVE:
        return value > 0.0f;
    case DARAN_RANGE_NON_NEGATIVE:
        return value >= 0.0f;
    default:
        return true;
    }
}

static daran_result_t parse_value(daran_property_t row, const daran_field_t *field,
                                  daran_value_t *value)
{
    daran_range_t range = DARAN_PROPERTY_RANGE(row);
    if (DARAN_PROPERTY_TYPE(row) == DARAN_TYPE_F32) {
        daran_result_t result = daran_field_f32(field, &value->f32);
        if (result == DARAN_OK && !float_in_range(range, value->f32)) {
            result = DARAN_ERR_OUT_OF_RANGE;
        }
        return result;
    }
    uint64_t integer;
    daran_result_t result = daran_parse_u64(field->text, field->len, &integer);
    if (result != DARAN_OK) {
        return result;
    }
    if (DARAN_PROPERTY_TYPE(row) == DARAN_TYPE_U64) {
        value->u64 = integer;
    } else if (integer > UINT32_MAX) {
        return DARAN_ERR_OUT_OF_RANGE;
    } else {
        value->u32 = (uint32_t)integer;
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
