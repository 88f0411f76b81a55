/* Queries f g i e (and `r`'s reply): each answers with values read from the
 * HAL. `h` lives with the command table, whose text it prints. */
#include "internal.h"

daran_result_t daran_reply_properties(daran_drive_t *drive, const daran_prop_t *props,
                                      size_t count)
{
    daran_value_t values[3];
    for (size_t i = 0; i < count; i++) {
        daran_result_t result = daran_get(drive, props[i], &values[i]);
        if (result != DARAN_OK) {
            return result;
        }
    }
    daran_reply_begin(drive);
    for (size_t i = 0; i < count; i++) {
        if (i > 0u) {
            daran_reply_space(drive);
        }
        switch (DARAN_PROPERTY_TYPE(daran_properties[props[i]])) {
        case DARAN_TYPE_F32:
            daran_reply_f32(drive, values[i].f32);
            break;
        case DARAN_TYPE_U64:
            daran_reply_u64(drive, values[i].u64);
            break;
        default:
            daran_reply_u64(drive, values[i].u32);
            break;
        }
    }
    daran_reply_end(drive);
    return DARAN_OK;
}

daran_result_t daran_cmd_f(daran_drive_t *drive, const daran_request_t *request)
{
    static const daran_prop_t props[] = {DARAN_PROP_POS_ESTIMATE, DARAN_PROP_VEL_ESTIMATE};
    (void)request;
    return daran_reply_properties(drive, props, 2);
}

daran_result_t daran_cmd_g(daran_drive_t *drive, const daran_request_t *request)
{
    static const daran_prop_t props[] = {DARAN_PROP_VBUS_VOLTAGE, DARAN_PROP_IQ_MEASURED};
    (void)request;
    return daran_reply_properties(drive, props, 2);
}

daran_result_t daran_cmd_i(daran_drive_t *drive, const daran_request_t *request)
{
    static const daran_prop_t props[] = {DARAN_PROP_FW_VERSION, DARAN_PROP_HW_VERSION,
                                         DARAN_PROP_SERIAL_NUMBER};
    (void)request;
    return daran_reply_properties(drive, props, 3);
}

static const char *const flag_names[] = {
    "estop", "watchdog", "motor_overtemp", "fet_overtemp", "undervoltage", "nvm_corrupt",
};

daran_result_t daran_cmd_e(daran_drive_t *drive, const daran_request_t *request)
{
    daran_value_t flags;
    (void)request;
    daran_result_t result = daran_get(drive, DARAN_PROP_AXIS_ERROR, &flags);
    if (result != DARAN_OK) {
        return result;
    }
    daran_reply_begin(drive);
    daran_reply_u64(drive, flags.u32);
    for (uint32_t bit = 0; bit < sizeof flag_names / sizeof flag_names[0]; bit++) {
        if (((flags.u32 >> bit) & 1u) != 0u) {
            daran_reply_space(drive);
            daran_reply_cstr(drive, flag_names[bit]);
        }
    }
    daran_reply_end(drive);
    return DARAN_OK;
}
