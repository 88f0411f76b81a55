/* The simulated drives' CAN front ends on the simulated bus (sim_can.h). */
#include "sim_can.h"

#include <string.h>

#if DARAN_ENABLE_CAN

/* The drive's side of its controller: its port description's CAN
 * transmit and clock, with the node as context. */
static bool node_can_send(void *ctx, const daran_can_frame_t *frame)
{
    const daran_sim_node_t *node = ctx;
    return daran_sim_can_bus_send(&node->can->wire, node->index, frame);
}

static uint32_t node_now_ms(void *ctx)
{
    const daran_sim_node_t *node = ctx;
    return (uint32_t)(node->can->wire.now_ns / 1000000u); /* wraps, as a millisecond timer */
}

/* The bus hands a frame to a drive's controller: into its receive ring,
 * and the drive runs it at once, as a firmware that polls its front end
 * from the receive interrupt's wake-up (or a main loop far faster than the
 * bus) does; its answer is queued now, on the bus's clock at the frame's
 * end, and ready after the drive's processing time. */
static void deliver_to_drive(void *ctx, const daran_can_frame_t *frame, uint64_t end_ns)
{
    const daran_sim_can_port_ctx_t *port = ctx;
    daran_can_t *front = &port->owner->front[port->index];
    (void)end_ns;
    if (daran_can_receive(front, frame)) {
        (void)daran_can_poll(front);
    }
}

static daran_result_t start_front_end(daran_sim_can_t *can, uint32_t index)
{
    daran_sim_can_bus_reset_node(&can->wire, index);
    return daran_can_init(&can->front[index], &can->line->node[index].proto);
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
        daran_sim_node_t *node = &line->node[i];
        node->can = can;
        node->port.now_ms = node_now_ms;
        node->port.can_send = node_can_send;
        can->port_ctx[i].owner = can;
        can->port_ctx[i].index = i;
        (void)daran_sim_can_bus_add_node(&can->wire, deliver_to_drive, &can->port_ctx[i]);
        daran_sim_can_bus_set_send_delay(&can->wire, i, DARAN_SIM_CAN_DRIVE_DELAY_NS);
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
    /* the frames of the tick ran as they arrived, on the state its start
     * left, as an ASCII line between two ticks does: the tick acts on them */
    (void)daran_sim_can_bus_run(&can->wire, daran_sim_can_tick_ns(line, line->ticks + 1u));
    daran_sim_bus_tick(line);
    for (i = 0; i < line->count; i++) {
        (void)daran_can_poll(&can->front[i]); /* the heartbeat, the node guard */
    }
}

#else
typedef int daran_sim_can_needs_daran_enable_can; /* ISO C: no empty file */
#endif /* DARAN_ENABLE_CAN */
