/* The HAL of the simulated drive: maps the core's get/set/move/action calls
 * onto the model and the non-volatile memory, after the test's layers: an
 * injected refusal, then the extension. (The functions that arm those are in
 * sim_faults.c and sim_extension.c; this file needs none of them, so a
 * firmware plant links model, NVM and drive alone.) */
#include "sim_drive.h"

#include <stddef.h>

/* Takes one pending refusal of kind @p call: true, with its result in *r. */
static bool refused(daran_sim_drive_t *d, daran_sim_hal_call_t call, daran_result_t *r)
{
    daran_sim_refusal_t *refusal = &d->refuse[call];
    if (refusal->left == 0u) {
        return false;
    }
    refusal->left--;
    *r = refusal->result;
    return true;
}

static daran_result_t drive_get(const daran_sim_drive_t *d, daran_prop_t prop, daran_value_t *out)
{
    switch (prop) {
    case DARAN_PROP_FW_VERSION:
        out->u64 = 0u;
        out->u32 = DARAN_SIM_FW_VERSION;
        return DARAN_OK;
    case DARAN_PROP_HW_VERSION:
        out->u64 = 0u;
        out->u32 = DARAN_SIM_HW_VERSION;
        return DARAN_OK;
    case DARAN_PROP_SERIAL_NUMBER:
        out->u64 = d->serial_number;
        return DARAN_OK;
    case DARAN_PROP_SERIAL_NUMBER_L:
        out->u64 = 0u;
        out->u32 = (uint32_t)(d->serial_number & 0xFFFFFFFFu);
        return DARAN_OK;
    case DARAN_PROP_SERIAL_NUMBER_H:
        out->u64 = 0u;
        out->u32 = (uint32_t)(d->serial_number >> 32);
        return DARAN_OK;
    default:
        return daran_sim_model_get(&d->model, prop, out);
    }
}

daran_result_t daran_sim_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    daran_sim_drive_t *d = ctx;
    daran_result_t r;
    if (refused(d, DARAN_SIM_CALL_GET, &r)) {
        return r;
    }
    if (d->ext != NULL && d->ext->get != NULL) {
        r = d->ext->get(d->ext_ctx, prop, out);
        if (r != DARAN_SIM_NOT_MINE) {
            return r;
        }
    }
    return drive_get(d, prop, out);
}

daran_result_t daran_sim_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    daran_sim_drive_t *d = ctx;
    daran_result_t r;
    if (refused(d, DARAN_SIM_CALL_SET, &r)) {
        return r;
    }
    if (d->ext != NULL && d->ext->set != NULL) {
        r = d->ext->set(d->ext_ctx, prop, value);
        if (r != DARAN_SIM_NOT_MINE) {
            return r;
        }
    }
    return daran_sim_model_set(&d->model, prop, value);
}

daran_result_t daran_sim_move(void *ctx, const daran_move_t *move)
{
    daran_sim_drive_t *d = ctx;
    daran_result_t r;
    if (refused(d, DARAN_SIM_CALL_MOVE, &r)) {
        return r;
    }
    return daran_sim_model_move(&d->model, move);
}

daran_result_t daran_sim_action(void *ctx, daran_action_t action)
{
    daran_sim_drive_t *d = ctx;
    daran_result_t r;
    if (refused(d, DARAN_SIM_CALL_ACTION, &r)) {
        return r;
    }
    switch (action) {
    case DARAN_ACTION_SAVE_CONFIG:
        if (d->failing_saves > 0u) {
            /* the flash refused the write: nothing stored changes */
            d->failing_saves--;
            return DARAN_ERR_MOTOR_FAULT;
        }
        return daran_sim_nvm_save(&d->storage, &d->model) ? DARAN_OK : DARAN_ERR_MOTOR_FAULT;
    case DARAN_ACTION_ERASE_CONFIG:
        return daran_sim_nvm_erase(&d->storage) ? DARAN_OK : DARAN_ERR_MOTOR_FAULT;
    case DARAN_ACTION_REBOOT:
        daran_sim_drive_power_on(d);
        return DARAN_OK;
    case DARAN_ACTION_CLEAR_ERRORS:
        daran_sim_model_clear_errors(&d->model);
        return DARAN_OK;
    case DARAN_ACTION_SET_ZERO:
        daran_sim_model_set_zero(&d->model);
        return DARAN_OK;
    case DARAN_ACTION_ESTOP:
        daran_sim_model_trip(&d->model, DARAN_FLAG_ESTOP);
        return DARAN_OK;
    case DARAN_ACTION_FEED_WATCHDOG:
        daran_sim_model_feed_watchdog(&d->model);
        return DARAN_OK;
    case DARAN_ACTION_NODE_GUARD:
        daran_sim_model_trip(&d->model, DARAN_FLAG_WATCHDOG);
        return DARAN_OK;
    default:
        return DARAN_ERR_MOTOR_FAULT;
    }
}

const daran_hal_t daran_sim_hal = {DARAN_SIM_HAL_FUNCTIONS};

void daran_sim_drive_init(daran_sim_drive_t *d, uint32_t index, uint32_t tick_hz)
{
    uint32_t k;
    d->ext = NULL;
    d->ext_ctx = NULL;
    for (k = 0; k < (uint32_t)DARAN_SIM_CALL_COUNT; k++) {
        d->refuse[k].left = 0u;
        d->refuse[k].result = DARAN_OK;
    }
    d->failing_saves = 0u;
    daran_sim_model_init(&d->model, tick_hz);
    daran_sim_ram_storage_init(&d->ram, &d->storage);
    d->default_id = index + 1u;
    d->serial_number = (uint64_t)DARAN_SIM_SERIAL_BASE + index + 1u;
    daran_sim_drive_power_on(d);
}

void daran_sim_drive_set_storage(daran_sim_drive_t *d, const daran_sim_storage_t *st)
{
    d->storage = *st;
}

void daran_sim_drive_power_on(daran_sim_drive_t *d)
{
    d->nvm_status = daran_sim_nvm_load(&d->storage, &d->model);
    if (d->nvm_status != DARAN_SIM_NVM_LOADED) {
        d->model.cfg[DARAN_PROP_CAN_NODE_ID].u32 = d->default_id;
    }
    daran_sim_model_boot(&d->model);
    if (d->nvm_status == DARAN_SIM_NVM_DAMAGED) {
        /* a warning: the drive runs on defaults and moves */
        d->model.config_warnings |= DARAN_WARNING_NVM_CORRUPT;
    }
}

void daran_sim_drive_tick(daran_sim_drive_t *d)
{
    daran_sim_model_tick(&d->model);
    if (d->ext != NULL && d->ext->tick != NULL) {
        d->ext->tick(d->ext_ctx, &d->model);
    }
}

uint32_t daran_sim_drive_id(const daran_sim_drive_t *d)
{
    return d->model.cfg[DARAN_PROP_CAN_NODE_ID].u32;
}

bool daran_sim_drive_corrupt_nvm(daran_sim_drive_t *d)
{
    return daran_sim_nvm_corrupt(&d->storage);
}
