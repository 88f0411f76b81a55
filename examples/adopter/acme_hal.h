/* The ACME X1's HAL: daran-ascii's four functions over the drive's
 * settings, its flash and its plant (acme_plant.h). Written against the
 * options header acme_options.h: the fan's duty cycle is a property of its
 * own, the absolute encoder's two rows are left out. */
#ifndef ACME_HAL_H
#define ACME_HAL_H

#include <stdbool.h>
#include <stdint.h>

#include "daran_ascii.h"

#include "acme_can.h"
#include "acme_plant.h"

#define ACME_FW_VERSION 210u /* 2.10 */
#define ACME_HW_VERSION 1u

typedef struct acme_drive {
    daran_value_t settings[DARAN_PROP_COUNT]; /* live values the plant does not own */
    daran_value_t flash[DARAN_PROP_COUNT];    /* what `ss` wrote */
    bool flash_valid;
    uint64_t serial_number;
    acme_plant_t plant;
    uint32_t time_ms;              /* the drive's clock: acme_drive_run() moves it */
    acme_can_filter_t can_filter;  /* set for axis0.config.can_node_id */
    uint32_t can_mailboxes_busy;   /* frames the bus has not taken yet */
    uint32_t can_frames_sent;
} acme_drive_t;

/* A new drive from the factory: flash erased, defaults, node id 1, closed
 * loop, shaft at 0. */
void acme_drive_factory_reset(acme_drive_t *drive, uint64_t serial_number);

/* Power on (or `sr`): defaults, then the settings saved in flash; closed
 * loop, holding the shaft where it is. */
void acme_drive_power_on(acme_drive_t *drive);

/* The control loop: advance the plant and the clock by @p ms milliseconds;
 * the CAN bus takes the frames waiting in the mailboxes. */
void acme_drive_run(acme_drive_t *drive, uint32_t ms);

/* The X1's port description without a reply writer (the program adds its
 * UART's: acme_port.c): the HAL, the CAN transmit and clock (acme_can.h);
 * the context is the acme_drive_t. */
extern const daran_hal_t acme_hal;

#endif /* ACME_HAL_H */
