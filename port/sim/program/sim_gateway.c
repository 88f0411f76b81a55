/* daran-sim's --bridge: drive 1 as a CAN gateway (sim_gateway.h). */
#include "sim_gateway.h"

/* daran_sim_can_on_front_end()'s hook: the gateway's front end was just
 * initialised (attach, or a power cycle's boot). */
static void on_front_end(void *ctx, uint32_t index, daran_can_t *front)
{
    sim_gateway_t *gw = ctx;
    if (index == SIM_GATEWAY_INDEX && daran_can_bridge_init(&gw->bridge, front) != DARAN_OK) {
        gw->refused++;
    }
}

void sim_gateway_start(sim_gateway_t *gw, daran_sim_can_t *can)
{
    gw->on = true;
    gw->refused = 0u;
    daran_sim_can_on_front_end(can, on_front_end, gw);
}

bool sim_gateway_busy(const sim_gateway_t *gw)
{
    return gw->on && daran_can_bridge_busy(&gw->bridge);
}

void sim_gateway_after_run(const sim_gateway_t *gw, daran_sim_bus_t *bus)
{
    uint32_t i;
    if (!gw->on) {
        return;
    }
    (void)daran_poll(&bus->node[SIM_GATEWAY_INDEX].proto);
    for (i = 0; i < bus->count; i++) {
        if (i != SIM_GATEWAY_INDEX) {
            bus->node[i].out_len = 0u;
        }
    }
}

uint64_t sim_gateway_wait_limit(uint32_t tick_hz)
{
    /* a millisecond more for each read: its timeout is counted in whole
     * milliseconds of the bus clock */
    uint64_t ms = (uint64_t)DARAN_CAN_BRIDGE_READS * (DARAN_CAN_BRIDGE_TIMEOUT_MS + 1u);
    return (ms * tick_hz + 999u) / 1000u + 1u;
}
