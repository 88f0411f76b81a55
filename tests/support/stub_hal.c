/* The remembering stub HAL of stub_hal.h. */
#include "stub_hal.h"

#include <string.h>

void daran_stub_init(daran_stub_t *stub, uint32_t id)
{
    memset(stub, 0, sizeof *stub);
    stub->values[DARAN_PROP_CAN_NODE_ID].u32 = id;
    stub->values[DARAN_PROP_CURRENT_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
    stub->values[DARAN_PROP_REQUESTED_STATE].u32 = DARAN_STATE_CLOSED_LOOP;
}

daran_result_t daran_stub_get(void *ctx, daran_prop_t prop, daran_value_t *out)
{
    *out = ((daran_stub_t *)ctx)->values[prop];
    return DARAN_OK;
}

daran_result_t daran_stub_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    daran_stub_t *stub = ctx;
    stub->values[prop] = value;
    stub->sets++;
    return DARAN_OK;
}

daran_result_t daran_stub_move(void *ctx, const daran_move_t *move)
{
    (void)move;
    ((daran_stub_t *)ctx)->moves++;
    return DARAN_OK;
}

daran_result_t daran_stub_action(void *ctx, daran_action_t action)
{
    (void)action;
    ((daran_stub_t *)ctx)->actions++;
    return DARAN_OK;
}

const daran_hal_t daran_stub_hal = {DARAN_STUB_HAL_FUNCTIONS, .write = daran_stub_drop_reply};

void daran_stub_drop_reply(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    (void)line;
    (void)len;
}
