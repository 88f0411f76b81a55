/* A minimal, complete port of daran-ascii: the HAL a real drive would start
 * from. It keeps every property in RAM and hands each validated move to the
 * control loop through a one-slot mailbox; the control loop itself (current
 * control, encoder) is the drive's own and not shown. docs/porting.md walks
 * through it. */
#ifndef MINIMAL_HAL_H
#define MINIMAL_HAL_H

#include <stdbool.h>
#include <stdint.h>

#include "daran_ascii.h"

typedef struct minimal_drive {
    daran_value_t props[DARAN_PROP_COUNT]; /* the live values of every property */
    /* Mailbox from the protocol (main loop) to the control loop (interrupt). */
    daran_move_t pending_move;
    volatile uint8_t move_ready;
    uint32_t saved_config_writes;          /* stands in for the flash driver */
} minimal_drive_t;

/* Power-up defaults: id 1, closed loop, no flags. */
void minimal_drive_init(minimal_drive_t *drive);

/* The control loop's side: take the newest move, if any. */
bool minimal_drive_take_move(minimal_drive_t *drive, daran_move_t *move);

extern const daran_hal_t minimal_hal;

#endif /* MINIMAL_HAL_H */
