/* The simulated multi-drop line between a host and N drives. */
#include "sim_bus.h"

#include "daran_port.h"

#include <string.h>

static void node_write(void *ctx, const char *line, size_t len)
{
    daran_sim_node_t *n = ctx;
    if (len > DARAN_SIM_OUT_MAX - n->out_len) {
        n->out_lost += (uint32_t)len;
        return;
    }
    memcpy(&n->out[n->out_len], line, len);
    n->out_len += len;
}

static void node_start(daran_sim_bus_t *bus, uint32_t index)
{
    daran_sim_node_t *n = &bus->node[index];
    n->out_len = 0u;
    if (daran_init(&n->proto, &n->port, n) != DARAN_OK) {
        n->out_lost++; /* cannot happen: every pointer is set */
    }
    if (bus->setup != NULL) {
        bus->setup(bus->setup_ctx, index, &n->proto);
    }
}

daran_result_t daran_sim_bus_init(daran_sim_bus_t *bus, uint32_t count, uint32_t tick_hz)
{
    uint32_t i;
    if (count < 1u || count > DARAN_SIM_MAX_DRIVES || tick_hz == 0u) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    bus->count = count;
    bus->tick_hz = tick_hz;
    bus->ticks = 0u;
    bus->setup = NULL;
    bus->setup_ctx = NULL;
    for (i = 0; i < count; i++) {
        daran_sim_node_t *n = &bus->node[i];
        daran_sim_drive_init(&n->sim, i, tick_hz);
        n->out_lost = 0u;
        n->port = (daran_hal_t){DARAN_SIM_HAL_FUNCTIONS, .write = node_write};
        n->can = NULL;
        n->index = i;
        node_start(bus, i);
    }
    return DARAN_OK;
}

void daran_sim_bus_set_setup(daran_sim_bus_t *bus, daran_sim_setup_fn setup, void *ctx)
{
    uint32_t i;
    bus->setup = setup;
    bus->setup_ctx = ctx;
    for (i = 0; setup != NULL && i < bus->count; i++) {
        setup(ctx, i, &bus->node[i].proto);
    }
}

void daran_sim_bus_set_storage(daran_sim_bus_t *bus, uint32_t index,
                               const daran_sim_storage_t *st)
{
    if (index < bus->count) {
        daran_sim_drive_set_storage(&bus->node[index].sim, st);
        daran_sim_drive_power_on(&bus->node[index].sim);
    }
}

static void feed(daran_sim_node_t *n, const char *bytes, size_t len)
{
    /* A byte written into a full ring is lost and damages its line, so feed
     * at most half a ring between polls, as a UART interrupt would between
     * two passes of a main loop that keeps up; every poll empties the ring. */
    while (len > 0u) {
        size_t chunk = len < DARAN_RX_RING_SIZE / 2u ? len : DARAN_RX_RING_SIZE / 2u;
        (void)daran_rx_write(&n->proto, bytes, chunk);
        (void)daran_poll(&n->proto);
        bytes += chunk;
        len -= chunk;
    }
}

void daran_sim_bus_send(daran_sim_bus_t *bus, const char *bytes, size_t len)
{
    uint32_t i;
    for (i = 0; i < bus->count; i++) {
        feed(&bus->node[i], bytes, len);
    }
}

void daran_sim_bus_send_to(daran_sim_bus_t *bus, uint32_t index, const char *bytes, size_t len)
{
    if (index < bus->count) {
        feed(&bus->node[index], bytes, len);
    }
}

uint32_t daran_sim_bus_collect(daran_sim_bus_t *bus, daran_sim_sink_fn sink, void *ctx)
{
    uint8_t done[DARAN_SIM_MAX_DRIVES];
    uint32_t answered = 0u;
    uint32_t k;
    memset(done, 0, sizeof done);
    for (k = 0; k < bus->count; k++) {
        uint32_t best = bus->count;
        uint32_t i;
        for (i = 0; i < bus->count; i++) {
            if (!done[i] && (best == bus->count || daran_sim_drive_id(&bus->node[i].sim) <
                                                       daran_sim_drive_id(&bus->node[best].sim))) {
                best = i;
            }
        }
        done[best] = 1u;
        if (bus->node[best].out_len > 0u) {
            answered++;
            if (sink != NULL) {
                sink(ctx, daran_sim_drive_id(&bus->node[best].sim), bus->node[best].out,
                     bus->node[best].out_len);
            }
            bus->node[best].out_len = 0u;
        }
    }
    return answered;
}

void daran_sim_bus_tick(daran_sim_bus_t *bus)
{
    uint32_t i;
    for (i = 0; i < bus->count; i++) {
        daran_sim_drive_tick(&bus->node[i].sim);
    }
    bus->ticks++;
    /* after the tick, as a drive's main loop would: reports go out with the
     * replies, in time order */
    for (i = 0; i < bus->count; i++) {
        (void)daran_telemetry_tick(&bus->node[i].proto, (uint32_t)bus->ticks, bus->tick_hz);
    }
}

void daran_sim_bus_power_cycle(daran_sim_bus_t *bus, uint32_t index)
{
    if (index < bus->count) {
        daran_sim_node_t *n = &bus->node[index];
        daran_sim_drive_power_on(&n->sim);
        node_start(bus, index);
    }
}
