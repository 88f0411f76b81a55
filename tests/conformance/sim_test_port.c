/* The simulated drive (daran_sim.h) handed to the conformance suite: a HAL
 * over a physical model, with time (advance() runs its 1 kHz control
 * ticks) and non-volatile memory. Its reset is a new drive: id 1, empty
 * storage, closed loop. */
#include "daran_test_port.h"

#include "daran_sim.h"

#define SIM_TICK_HZ 1000u

static daran_sim_drive_t sim;

static bool factory_reset(void *ctx)
{
    daran_sim_drive_init(ctx, 0u, SIM_TICK_HZ);
    return true;
}

static void advance(void *ctx, uint32_t ms)
{
    for (uint32_t tick = 0; tick < ms * (SIM_TICK_HZ / 1000u); tick++) {
        daran_sim_drive_tick(ctx);
    }
}

const daran_test_port_t *daran_test_port(void)
{
    static const daran_test_port_t port = {
        .name = "port/sim (the simulated drive)",
        .hal = &daran_sim_hal,
        .ctx = &sim,
        .reset = factory_reset,
        .advance = advance,
    };
    return &port;
}
