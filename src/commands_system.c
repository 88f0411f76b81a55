/* System and watchdog commands: ss se sr sc sz st u. Each is one HAL action,
 * silent on success. */
#include "handlers.h"
#include "hal.h"

DARAN_CAN_SHARED daran_result_t daran_run_action(daran_drive_t *drive, daran_action_t action)
{
    daran_result_t result = daran_act(drive, action);
    if (result == DARAN_OK && action == DARAN_ACTION_REBOOT) {
        drive->has_preset = DARAN_PRESET_NONE; /* a reboot forgets what RAM held (D16) */
    }
    return result;
}

daran_result_t daran_cmd_action(daran_drive_t *drive, const daran_request_t *request)
{
    return daran_run_action(drive, (daran_action_t)request->command->arg);
}
