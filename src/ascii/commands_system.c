/* System and watchdog commands: ss se sr sc sz st u. Each is one HAL action,
 * silent on success. */
#include "handlers.h"

daran_result_t daran_cmd_action(daran_drive_t *drive, const daran_request_t *request)
{
    return daran_run_action(drive, (daran_action_t)request->command->arg);
}
