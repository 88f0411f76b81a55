/* One simulated drive behind the protocol core's HAL: the model, its
 * non-volatile memory and its identity (versions, serial number).
 *
 * Portable C99: no stdio, no heap. */
#ifndef DARAN_SIM_DRIVE_H
#define DARAN_SIM_DRIVE_H

#include <stdint.h>

#include "daran_hal.h"
#include "sim_model.h"
#include "sim_nvm.h"

#ifdef __cplusplus
extern "C" {
#endif

#define DARAN_SIM_FW_VERSION 100u /* 1.00 */
#define DARAN_SIM_HW_VERSION 3u
#define DARAN_SIM_SERIAL_BASE 2026000000u

typedef struct daran_sim_drive {
    daran_sim_model_t model;
    daran_sim_storage_t storage;   /* the NVM in use (RAM unless replaced) */
    daran_sim_ram_storage_t ram;
    uint32_t default_id;           /* can_node_id when no config is stored */
    uint64_t serial_number;
    daran_sim_nvm_status_t nvm_status; /* found at the last boot */
} daran_sim_drive_t;

/* The HAL the core calls; its context is a daran_sim_drive_t. */
extern const daran_hal_t daran_sim_hal;

/* Set up drive number @p index (0-based; default id index + 1) with empty RAM
 * storage, then power it on. */
void daran_sim_drive_init(daran_sim_drive_t *d, uint32_t index, uint32_t tick_hz);

/* Use @p st instead of the RAM storage (call daran_sim_drive_power_on()
 * after). */
void daran_sim_drive_set_storage(daran_sim_drive_t *d, const daran_sim_storage_t *st);

/* Power on (or reboot): load the stored config or the defaults, raise
 * DARAN_WARNING_NVM_CORRUPT in axis0.config_warnings when the store was
 * damaged (never an error: motion is not blocked), hold position in closed
 * loop. The shaft angle and temperatures are physical and are kept. */
void daran_sim_drive_power_on(daran_sim_drive_t *d);

/* The drive's current id (axis0.config.can_node_id). */
uint32_t daran_sim_drive_id(const daran_sim_drive_t *d);

/* The nvm-corrupt fault: damage the stored config (found at next boot). */
bool daran_sim_drive_corrupt_nvm(daran_sim_drive_t *d);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_SIM_DRIVE_H */
