/* The fault injections a test arms on a simulated drive; sim_drive.c's HAL
 * consumes the refusals and failing saves. */
#include "sim_faults.h"

#include <string.h>

static const struct {
    const char *name;
    daran_sim_fault_t fault;
} fault_names[] = {
    {"overtemp", DARAN_SIM_FAULT_OVERTEMP},
    {"undervoltage", DARAN_SIM_FAULT_UNDERVOLTAGE},
    {"stall", DARAN_SIM_FAULT_STALL},
    {"overspeed", DARAN_SIM_FAULT_OVERSPEED},
    {"nvm-corrupt", DARAN_SIM_FAULT_NVM_CORRUPT},
};
#define FAULT_COUNT (sizeof fault_names / sizeof fault_names[0])

daran_result_t daran_sim_drive_inject_fault(daran_sim_drive_t *d, daran_sim_fault_t fault)
{
    switch (fault) {
    case DARAN_SIM_FAULT_OVERTEMP:
    case DARAN_SIM_FAULT_UNDERVOLTAGE:
    case DARAN_SIM_FAULT_STALL:
    case DARAN_SIM_FAULT_OVERSPEED:
        daran_sim_model_fault(&d->model, fault);
        return DARAN_OK;
    case DARAN_SIM_FAULT_NVM_CORRUPT:
        return daran_sim_drive_corrupt_nvm(d) ? DARAN_OK : DARAN_ERR_MOTOR_FAULT;
    default:
        return DARAN_ERR_BAD_ARGUMENT;
    }
}

bool daran_sim_fault_from_name(const char *name, daran_sim_fault_t *fault)
{
    size_t k;
    for (k = 0; k < FAULT_COUNT; k++) {
        if (strcmp(name, fault_names[k].name) == 0) {
            *fault = fault_names[k].fault;
            return true;
        }
    }
    return false;
}

const char *daran_sim_fault_name(daran_sim_fault_t fault)
{
    size_t k;
    for (k = 0; k < FAULT_COUNT; k++) {
        if (fault_names[k].fault == fault) {
            return fault_names[k].name;
        }
    }
    return NULL;
}

daran_result_t daran_sim_drive_refuse_calls(daran_sim_drive_t *d, daran_sim_hal_call_t call,
                                            uint32_t count, daran_result_t result)
{
    /* the results from DARAN_ERR_BAD_ARGUMENT on report API misuse and are
     * never sent on the link: no HAL answers them */
    if ((unsigned)call >= (unsigned)DARAN_SIM_CALL_COUNT || result == DARAN_OK ||
        (unsigned)result >= (unsigned)DARAN_ERR_BAD_ARGUMENT) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    d->refuse[call].left = count;
    d->refuse[call].result = result;
    return DARAN_OK;
}

uint32_t daran_sim_drive_refusals_left(const daran_sim_drive_t *d, daran_sim_hal_call_t call)
{
    return (unsigned)call < (unsigned)DARAN_SIM_CALL_COUNT ? d->refuse[call].left : 0u;
}

void daran_sim_drive_fail_nvm_saves(daran_sim_drive_t *d, uint32_t count)
{
    d->failing_saves = count;
}

void daran_sim_drive_clear_injections(daran_sim_drive_t *d)
{
    uint32_t k;
    for (k = 0; k < (uint32_t)DARAN_SIM_CALL_COUNT; k++) {
        d->refuse[k].left = 0u;
    }
    d->failing_saves = 0u;
}
