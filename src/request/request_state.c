/* The request layer's drive state and actions (request.h): whether the
 * drive takes motion, and a HAL action with what the core forgets with it. */
#include "request.h"

#include "daran_update.h"

daran_result_t daran_check_motion_allowed(daran_drive_t *drive)
{
#if DARAN_ENABLE_UPDATE
    if (drive->update != NULL && drive->update->state != DARAN_UPDATE_IDLE) {
        return DARAN_ERR_UPDATE_OPEN;
    }
#endif
    daran_value_t value;
    daran_result_t result = daran_get(drive, DARAN_PROP_AXIS_ERROR, &value);
    if (result != DARAN_OK) {
        return result;
    }
    if ((value.u32 & DARAN_FLAG_ESTOP) != 0u) {
        return DARAN_ERR_ESTOP_ACTIVE;
    }
    if (value.u32 != 0u) {
        return DARAN_ERR_MOTOR_FAULT;
    }
    result = daran_get(drive, DARAN_PROP_CURRENT_STATE, &value);
    if (result != DARAN_OK) {
        return result;
    }
    return value.u32 == DARAN_STATE_CLOSED_LOOP ? DARAN_OK : DARAN_ERR_MOTOR_IDLE;
}

daran_result_t daran_run_action(daran_drive_t *drive, daran_action_t action)
{
    daran_result_t result = daran_act(drive, action);
    if (result == DARAN_OK && action == DARAN_ACTION_REBOOT) {
        drive->has_preset = DARAN_PRESET_NONE; /* a reboot forgets what RAM held (D16) */
    }
    return result;
}
