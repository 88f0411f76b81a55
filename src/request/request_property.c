/* The request layer's property writes (request.h): a value checked against
 * its row's range, then committed through the HAL door. */
#include "property.h"
#include "request.h"
#include "telemetry.h"

#include "property_features.h"

daran_result_t daran_check_property_value(daran_prop_t prop, daran_value_t value)
{
    daran_property_t row = daran_property_row(prop);
    daran_range_t range = DARAN_PROPERTY_RANGE(row);
    switch (DARAN_PROPERTY_TYPE(row)) {
    case DARAN_TYPE_F32: {
#if DARAN_F32_INTERVALS
        bool holds = daran_range_holds_f32(range, value.f32);
#else
        /* this build's float ranges are sign conditions: test the sign, -0
         * counting as 0 (D27) */
        int64_t sign = value.f32 > 0.0f ? 1 : (value.f32 < 0.0f ? -1 : 0);
        bool holds = daran_range_holds(range, sign);
#endif
        return holds && daran_is_finite(value.f32) ? DARAN_OK : DARAN_ERR_OUT_OF_RANGE;
    }
    case DARAN_TYPE_U64:
        return DARAN_OK; /* the whole unsigned range, no range rule */
    case DARAN_TYPE_S32:
        return daran_range_holds(range, value.s32) ? DARAN_OK : DARAN_ERR_OUT_OF_RANGE;
    default:
        if (!daran_range_holds(range, (int64_t)value.u32)) {
            return DARAN_ERR_OUT_OF_RANGE;
        }
#if DARAN_ENABLE_TELEMETRY
        if (range == DARAN_RANGE_TELEMETRY && !daran_telemetry_fits(value.u32)) {
            return DARAN_ERR_OUT_OF_RANGE; /* its report might not fit DARAN_REPLY_MAX */
        }
#endif
        return DARAN_OK;
    }
}

daran_result_t daran_commit_property(daran_drive_t *drive, daran_prop_t prop,
                                                      daran_value_t value)
{
    if (prop == DARAN_PROP_REQUESTED_STATE && value.u32 == DARAN_STATE_CLOSED_LOOP) {
        /* Closing the loop is refused while a flag still holds the drive (D21). */
        daran_result_t result = daran_check_motion_allowed(drive);
        if (result != DARAN_OK && result != DARAN_ERR_MOTOR_IDLE) {
            return result;
        }
    }
    daran_result_t result = daran_set(drive, prop, value);
    if (DARAN_ENABLE_TELEMETRY && result == DARAN_OK && prop == DARAN_PROP_TELEMETRY_PERIOD) {
        /* a new period starts now, not after the report the old one still owes */
        drive->telemetry_due = 1;
    }
    return result;
}
