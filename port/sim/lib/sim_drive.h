/* One simulated drive behind the protocol core's HAL: the model, its
 * non-volatile memory and its identity (versions, serial number), with what
 * a test layers over it: an extension serving the port's own properties
 * (sim_extension.h) and injected HAL refusals and NVM failures
 * (sim_faults.h).
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

/* What an extension's get or set returns for a property it does not serve:
 * the drive then asks the model. Never a reply (it is no protocol result). */
#define DARAN_SIM_NOT_MINE DARAN_RESULT_COUNT

/* A layer over the model, given by the test (daran_sim_drive_extend()):
 * its get and set are asked first for every property the core passes the
 * HAL, vendor rows included, and answer DARAN_SIM_NOT_MINE to fall through
 * to the model; any other result is the HAL's answer (DARAN_OK, or the
 * error the drive replies with, having changed nothing). Each function may
 * be NULL (serves nothing). ctx is the pointer given with the extension.
 * tick, when set, runs after every control tick of the model
 * (daran_sim_drive_tick()). The same rules as daran_hal_t apply: get has no
 * side effects, set gets only values the core has range-checked. */
typedef struct daran_sim_extension {
    daran_result_t (*get)(void *ctx, daran_prop_t prop, daran_value_t *out);
    daran_result_t (*set)(void *ctx, daran_prop_t prop, daran_value_t value);
    void (*tick)(void *ctx, const daran_sim_model_t *model);
} daran_sim_extension_t;

/* The four kinds of HAL call, for injected refusals
 * (daran_sim_drive_refuse_calls()). */
typedef enum daran_sim_hal_call {
    DARAN_SIM_CALL_GET,    /* daran_hal_t.get: reads, and the core's checks of id, state, errors */
    DARAN_SIM_CALL_SET,    /* daran_hal_t.set: `w` */
    DARAN_SIM_CALL_MOVE,   /* daran_hal_t.move: motion commands */
    DARAN_SIM_CALL_ACTION, /* daran_hal_t.action: `ss`, `se`, `sr`, `sc`, `sz`, `st`, watchdog feeds */
    DARAN_SIM_CALL_COUNT   /* how many kinds there are; not a kind */
} daran_sim_hal_call_t;

/* An injected refusal: the next `left` calls of one kind answer `result`. */
typedef struct daran_sim_refusal {
    uint32_t left;
    daran_result_t result;
} daran_sim_refusal_t;

typedef struct daran_sim_drive {
    daran_sim_model_t model;
    daran_sim_storage_t storage;   /* the NVM in use (RAM unless replaced) */
    daran_sim_ram_storage_t ram;
    uint32_t default_id;           /* can_node_id when no config is stored */
    uint64_t serial_number;
    daran_sim_nvm_status_t nvm_status; /* found at the last boot */
    const daran_sim_extension_t *ext;  /* NULL: the model serves everything */
    void *ext_ctx;
    daran_sim_refusal_t refuse[DARAN_SIM_CALL_COUNT];
    uint32_t failing_saves;        /* `ss` lines still to fail with motor fault */
} daran_sim_drive_t;

/* The HAL's four functions; their context is a daran_sim_drive_t (or a
 * struct that begins with one). Each call first takes an injected refusal
 * of its kind if one is pending, then asks the extension (get, set), then
 * the model. A program's port description adds its reply writer:
 * `static const daran_hal_t hal = {DARAN_SIM_HAL_FUNCTIONS, .write = write_reply};`. */
daran_result_t daran_sim_get(void *ctx, daran_prop_t prop, daran_value_t *out);
daran_result_t daran_sim_set(void *ctx, daran_prop_t prop, daran_value_t value);
daran_result_t daran_sim_move(void *ctx, const daran_move_t *move);
daran_result_t daran_sim_action(void *ctx, daran_action_t action);
#define DARAN_SIM_HAL_FUNCTIONS \
    .get = daran_sim_get, .set = daran_sim_set, .move = daran_sim_move, .action = daran_sim_action

/* The four alone, for a HAL that wraps this one (the test kit's recorder,
 * which writes the replies itself). */
extern const daran_hal_t daran_sim_hal;

/* Set up drive number @p index (0-based; default id index + 1) with empty RAM
 * storage, no extension and nothing injected, then power it on. O(size of
 * the drive); cannot fail (a tick rate of 0 counts as 1). */
void daran_sim_drive_init(daran_sim_drive_t *d, uint32_t index, uint32_t tick_hz);

/* Use @p st instead of the RAM storage (call daran_sim_drive_power_on()
 * after). */
void daran_sim_drive_set_storage(daran_sim_drive_t *d, const daran_sim_storage_t *st);

/* Power on (or reboot): load the stored config or the defaults, raise
 * DARAN_WARNING_NVM_CORRUPT in axis0.config_warnings when the store was
 * damaged (never an error: motion is not blocked), hold position in closed
 * loop. The shaft angle and temperatures are physical and are kept, as are
 * the extension and pending injections (they belong to the test bench). */
void daran_sim_drive_power_on(daran_sim_drive_t *d);

/* One control tick: the model's, then the extension's tick if it has one.
 * (The telemetry of a protocol instance is the caller's:
 * daran_telemetry_tick(), as daran_sim_bus_tick() does.) */
void daran_sim_drive_tick(daran_sim_drive_t *d);

/* The drive's current id (axis0.config.can_node_id). */
uint32_t daran_sim_drive_id(const daran_sim_drive_t *d);

/* The nvm-corrupt fault: damage the stored config (found at next boot).
 * False when the storage failed. */
bool daran_sim_drive_corrupt_nvm(daran_sim_drive_t *d);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_SIM_DRIVE_H */
