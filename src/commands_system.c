/* System and watchdog commands: ss se sr sc sz st u. Each is one HAL action,
 * silent on success. */
#include "internal.h"

daran_result_t daran_cmd_action(daran_drive_t *drive, const daran_request_t *request)
{
    daran_action_t action = (daran_action_t)request->command->arg;
    daran_result_t result = drive->hal->action(drive->hal_ctx, action);
    if ((unsigned)result >= (unsigned)DARAN_RESULT_COUNT) {
        result = DARAN_ERR_MOTOR_FAULT;
    }
    if (result == DARAN_OK && action == DARAN_ACTION_REBOOT) {
        drive->has_preset = 0; /* a reboot forgets what RAM held (D16) */
    }
    return result;
}
