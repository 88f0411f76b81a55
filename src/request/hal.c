/* The one door to the HAL: every get, set, move and action the core makes
 * goes through this file, and so does every HAL answer on its way back, so
 * the all-or-nothing rule (a line has no effect unless it is valid) can be
 * audited here: each call below is made by a handler only after its line
 * passed every check, except the reads listed in docs/design.md. */
#include "hal.h"

daran_result_t daran_get(daran_drive_t *drive, daran_prop_t prop, daran_value_t *out)
{
    out->u64 = 0;
    return daran_from_hal(drive->hal->get(drive->ctx, prop, out));
}

daran_result_t daran_set(daran_drive_t *drive, daran_prop_t prop, daran_value_t value)
{
    return daran_from_hal(drive->hal->set(drive->ctx, prop, value));
}

daran_result_t daran_act(daran_drive_t *drive, daran_action_t action)
{
    return daran_from_hal(drive->hal->action(drive->ctx, action));
}

daran_result_t daran_start_move(daran_drive_t *drive, const daran_move_t *move)
{
    daran_result_t result = daran_from_hal(drive->hal->move(drive->ctx, move));
    if (result == DARAN_OK) {
        /* The move is done; a feed that fails cannot undo it, and the drive's
         * own watchdog will say so if it matters (D22). */
        (void)drive->hal->action(drive->ctx, DARAN_ACTION_FEED_WATCHDOG);
    }
    return result;
}
