/* The one door to the HAL (hal.c). Nothing else in the core calls
 * drive->hal; docs/design.md says which calls a line may make before it is
 * validated. */
#ifndef DARAN_HAL_DOOR_H
#define DARAN_HAL_DOOR_H

#include "daran_drive.h"

/* What the core answers for a HAL's result: protocol errors as they are,
 * anything else (the bridge's own three, DARAN_ERR_BAD_ARGUMENT, unknown
 * values) `motor fault`. */
static inline daran_result_t daran_from_hal(daran_result_t result)
{
    /* A HAL may return anything; what is not a drive's error is a fault (D26). */
    return (unsigned)result < (unsigned)DARAN_ERR_NO_REPLY ? result : DARAN_ERR_MOTOR_FAULT;
}

daran_result_t daran_get(daran_drive_t *drive, daran_prop_t prop, daran_value_t *out);
daran_result_t daran_set(daran_drive_t *drive, daran_prop_t prop, daran_value_t value);
daran_result_t daran_act(daran_drive_t *drive, daran_action_t action);

/* Hand a validated move to the HAL and feed the watchdog (D22). */
daran_result_t daran_start_move(daran_drive_t *drive, const daran_move_t *move);

#endif /* DARAN_HAL_DOOR_H */
