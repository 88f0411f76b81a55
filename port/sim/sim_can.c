/* The simulated drives' CAN front ends on the simulated bus (sim_can.h). */
#include "sim_can.h"

#include <string.h>

#if DARAN_ENABLE_CAN

static bool port_send(void *ctx, const daran_can_frame_t *frame)
{
    const daran_sim_can_port_ctx_t *port = ctx;
    return daran_sim_can_bus_send(&port->owner->wire, port->index, frame);
}

static uint32_t port_now_ms(void *ctx)
{
    const daran_sim_can_port_ctx_t *port = ctx;
    return (uint32_t)(port->owner->wire.now_ns / 1000000u); /* wraps, as a millisecond timer */
}

const daran_can_port_t daran_sim_can_port = {port_send, port_now_ms, NULL};

/* The bus hands a frame to a drive's controller: into its receive ring. */
static void deliver_to_drive(void *ctx, const daran_can_frame_t *frame, uint64_t end_ns)
{
    const daran_sim_can_port_ctx_t *port = ctx;
    (void)end_ns;
    (void)daran_can_receive(&port->owner->front[port->index], frame);
}

static daran_result_t start_front_end(daran_sim_can_t *can, uint32_t index)
{
    daran_sim_can_bus_reset_node(&can->wire, index);
    return daran_can_init(&can->front[index], &can->line->node[index].proto, &daran_sim_can_port,
                          &can->port_ctx[index]);
}

/* A power cycle started a new protocol instance: the port's own setup, then
 * the front end, as the firmware's boot would attach them. */
static void on_new_instance(void *ctx, uint32_t index, daran_drive_t *proto)
{
    daran_sim_can_t *can = ctx;
    if (can->chained_setup != NULL) {
        can->chained_setup(can->chained_ctx, index, proto);
    }
    (void)start_front_end(can, index); /* cannot fail: it succeeded at attach */
    if (can->front_end_started != NULL) {
        can->front_end_started(can->front_end_ctx, index, &can->front[index]);
    }
}

void daran_sim_can_on_front_end(daran_sim_can_t *can, daran_sim_front_end_fn fn, void *ctx)
{
    uint32_t i;
    can->front_end_started = fn;
    can->front_end_ctx = ctx;
    for (i = 0; fn != NULL && i < can->line->count; i++) {
        fn(ctx, i, &can->front[i]);
    }
}

uint64_t daran_sim_can_tick_ns(const daran_sim_bus_t *line, uint64_t ticks)
{
    uint64_t hz = line->tick_hz;
    return ticks / hz * 1000000000u + ticks % hz * 1000000000u / hz;
}

daran_result_t daran_sim_can_attach(daran_sim_can_t *can, daran_sim_bus_t *line)
{
    uint32_t i;
    memset(can, 0, sizeof *can);
    can->line = line;
    daran_sim_can_bus_init(&can->wire, DARAN_SIM_CAN_BIT_RATE,
                           daran_sim_can_tick_ns(line, line->ticks));
    for (i = 0; i < line->count; i++) {
        can->port_ctx[i].owner = can;
        can->port_ctx[i].index = i;
        (void)daran_sim_can_bus_add_node(&can->wire, deliver_to_drive, &can->port_ctx[i]);
        if (start_front_end(can, i) != DARAN_OK) {
            return DARAN_ERR_BAD_ARGUMENT;
        }
    }
    can->chained_setup = line->setup;
    can->chained_ctx = line->setup_ctx;
    line->setup = on_new_instance;
    line->setup_ctx = can;
    return DARAN_OK;
}

void daran_sim_can_tick(daran_sim_can_t *can)
{
    daran_sim_bus_t *line = can->line;
    uint32_t i;
    daran_sim_bus_tick(line);
    /* what crossed the bus during the tick runs at its end, as an ASCII line
     * does: its effect starts with the next tick */
    (void)daran_sim_can_bus_run(&can->wire, daran_sim_can_tick_ns(line, line->ticks));
    for (i = 0; i < line->count; i++) {
        (void)daran_can_poll(&can->front[i]);
    }
}

#else
typedef int daran_sim_can_needs_daran_enable_can; /* ISO C: no empty file */
#endif /* DARAN_ENABLE_CAN */
