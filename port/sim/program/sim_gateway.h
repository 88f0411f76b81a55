/* daran-sim's --bridge: drive 1 (index 0 of the line) is a CAN gateway
 * (daran_can_bridge_t, docs/can.md "The bridge"). The ASCII link reaches it
 * alone; its lines for other ids travel through its bridge to the drives on
 * the simulated CAN bus, and their answers come back through its CAN front
 * end as each reply frame arrives (sim_can.h). The other drives have no ASCII link: what
 * they write (telemetry set over CAN) goes nowhere, as a real drive's
 * unplugged UART.
 *
 * Host program only (daran-sim's, not the library's). */
#ifndef SIM_GATEWAY_H
#define SIM_GATEWAY_H

#include <stdbool.h>
#include <stdint.h>

#include "daran_can.h"
#include "sim_bus.h"
#include "sim_can.h"

/* The drive the ASCII link reaches with --bridge. */
#define SIM_GATEWAY_INDEX 0u

typedef struct sim_gateway {
    daran_can_bridge_t bridge;
    bool on;          /* --bridge */
    uint32_t refused; /* front ends daran_can_bridge_init() refused (none: it checks pointers) */
} sim_gateway_t;

/* Make drive 1 of @p can's line the gateway, now and after each power
 * cycle: daran_can_init() forgets a bridge, so it is made again whenever
 * the front end is initialised (daran_sim_can_on_front_end()). */
void sim_gateway_start(sim_gateway_t *gw, daran_sim_can_t *can);

/* Whether a bridged query waits for its replies (false without --bridge):
 * the link's next line waits meanwhile. */
bool sim_gateway_busy(const sim_gateway_t *gw);

/* After the bus ran (a control tick, or a part of one), as the gateway's
 * main loop goes on: daran_poll() takes what its ring holds, and what the
 * drives without a link wrote is dropped before it is collected. Nothing
 * without --bridge. */
void sim_gateway_after_run(const sim_gateway_t *gw, daran_sim_bus_t *bus);

/* The most control ticks at @p tick_hz that one bridged line can wait: a
 * timeout (and a millisecond) for each of its reads, and a tick to spare. */
uint64_t sim_gateway_wait_limit(uint32_t tick_hz);

#endif /* SIM_GATEWAY_H */
