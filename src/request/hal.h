/* The one door to the port (hal.c and the inline calls below). Nothing else
 * in the core calls drive->hal; docs/design.md says which calls a line may
 * make before it is validated. */
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

/* Inline: the reply writer and the forward hook sit on every line's road. */
static inline void daran_write_line(daran_drive_t *drive, const char *line, size_t len)
{
    drive->hal->write(drive->ctx, line, len);
}

/* False when the port has no forward hook. */
static inline bool daran_forward_line(daran_drive_t *drive, uint8_t motor, const char *line,
                                      size_t len)
{
    if (drive->hal->forward == NULL) {
        return false;
    }
    drive->hal->forward(drive->ctx, motor, line, len);
    return true;
}

#if DARAN_ENABLE_CAN
static inline uint32_t daran_now_ms(const daran_drive_t *drive)
{
    return drive->hal->now_ms(drive->ctx);
}

/* One 8-byte standard frame to the port: true when it took it. */
bool daran_send_frame(daran_drive_t *drive, uint32_t id, const uint8_t *data);

/* The CAN system sub-codes the library leaves to the port (C19). */
void daran_pass_system(daran_drive_t *drive, uint32_t subcode, uint16_t data1, uint16_t data2);
#endif

#endif /* DARAN_HAL_DOOR_H */
