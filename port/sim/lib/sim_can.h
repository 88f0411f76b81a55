/* The drives of a simulated line (daran_sim_bus_t) on a simulated CAN bus
 * (daran_sim_can_bus_t): each drive's protocol instance gets its CAN front
 * end (daran_can_t, daran_can.h) as a firmware port would attach it. The
 * front end's port queues its frames on the drive's node of the bus and
 * reads the bus's clock; the bus delivers every frame into the receive ring
 * of each other drive (daran_can_receive(), as a receive interrupt does).
 *
 * Drive i (0-based, as in line->node[i]) is node i of the bus; host
 * adapters join after them with daran_sim_can_bus_add_node(&can->wire, ...)
 * and send with daran_sim_can_bus_send(). A drive runs each frame when its
 * last bit has passed (daran_can_receive() and daran_can_poll() at once),
 * so its answer is queued at that time and ready
 * DARAN_SIM_CAN_DRIVE_DELAY_NS later, whatever the tick rate. One control
 * tick (daran_sim_can_tick()) is the bus running through the tick (frames
 * run as they arrive, on the state the tick's start left, as ASCII lines
 * between two ticks do), then the line's tick (models, telemetry), which
 * acts on them, then each front end's daran_can_poll() at the tick's end
 * (the heartbeat, the node guard). The bus may also be run to a time
 * inside a tick (daran_sim_can_bus_run()), as a real-time loop does.
 *
 * The front ends need a core built with DARAN_ENABLE_CAN (the default).
 * Portable C99: no stdio, no heap; the caller owns the object. */
#ifndef DARAN_SIM_CAN_H
#define DARAN_SIM_CAN_H

#include <stdint.h>

#include "daran_can.h"
#include "sim_bus.h"
#include "sim_can_bus.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct daran_sim_can daran_sim_can_t;

/* Told that drive @p index's front end @p front has just been initialised
 * (daran_sim_can_on_front_end()), e.g. to make it a bridge with
 * daran_can_bridge_init(): daran_can_init() forgets one. */
typedef void (*daran_sim_front_end_fn)(void *ctx, uint32_t index, daran_can_t *front);

/* The bus's context for delivering to one drive. */
typedef struct daran_sim_can_port_ctx {
    daran_sim_can_t *owner;
    uint32_t index;
} daran_sim_can_port_ctx_t;

struct daran_sim_can {
    daran_sim_can_bus_t wire;
    daran_sim_bus_t *line;
    daran_can_t front[DARAN_SIM_MAX_DRIVES];
    daran_sim_can_port_ctx_t port_ctx[DARAN_SIM_MAX_DRIVES];
    daran_sim_setup_fn chained_setup; /* the line's setup function before attaching */
    void *chained_ctx;
    daran_sim_front_end_fn front_end_started; /* NULL: none */
    void *front_end_ctx;
};

/* A drive's processing time, from a frame's last bit to its answer being
 * ready for the wire: a main loop pass of the firmware that takes the frame
 * from the receive ring and runs it (a read takes under 400 instructions on
 * a Cortex-M4, docs/performance.md: a few microseconds). */
#define DARAN_SIM_CAN_DRIVE_DELAY_NS 10000u

/* Put every drive of @p line on a new bus at DARAN_SIM_CAN_BIT_RATE (each
 * node's port description gets the bus's clock and a transmit that queues
 * on its node; no system hook) whose
 * clock starts at the line's simulated time: drive i becomes node i and its
 * protocol instance gets its front end (daran_can_init(), which reads
 * can.config.protocol). The line's setup function (daran_sim_bus_set_setup(),
 * set before this call) is kept and runs first on each new protocol instance
 * a power cycle starts; then that drive's front end is initialised again and
 * its controller reset (daran_sim_can_bus_reset_node()). Set no other setup
 * function afterwards. DARAN_ERR_BAD_ARGUMENT when a front end refuses its
 * port (a core without CAN cannot be attached). O(drives). */
DARAN_NODISCARD daran_result_t daran_sim_can_attach(daran_sim_can_t *can, daran_sim_bus_t *line);

/* Call @p fn (with @p ctx) on every drive's front end now, and on each
 * one a power cycle initialises again; NULL stops that. */
void daran_sim_can_on_front_end(daran_sim_can_t *can, daran_sim_front_end_fn fn, void *ctx);

/* One control tick of the line with its CAN bus: the bus runs to the end
 * of the tick, then daran_sim_bus_tick(), then every front end polls. Call
 * it instead of daran_sim_bus_tick(). */
void daran_sim_can_tick(daran_sim_can_t *can);

/* The simulated time of @p ticks control ticks of @p line, in nanoseconds. */
uint64_t daran_sim_can_tick_ns(const daran_sim_bus_t *line, uint64_t ticks);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_SIM_CAN_H */
