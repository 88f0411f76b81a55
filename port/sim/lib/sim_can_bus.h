/* A simulated CAN bus: its nodes (simulated drives, host adapters), each
 * with a transmit queue, arbitration by identifier, the time every frame
 * takes on the wire at the bus's bit rate, delivery to every node but the
 * sender, and the bus faults a test injects (a lost frame, a mute or
 * unplugged node, bus-off).
 *
 * Timing. A frame occupies the wire for its exact bit count: the fields of
 * CAN 2.0 (44 + 8 x DLC bits for a standard data frame, 64 + 8 x DLC for an
 * extended one, no data bits for a remote frame), plus the stuff bits its
 * actual contents need (counted exactly: the CRC-15 is computed and the
 * stuffed region, start of frame through CRC, is walked), plus the 3-bit
 * intermission. At 1 Mbit/s a standard 8-byte data frame takes 111 to 135
 * microseconds (daran_sim_can_frame_bits()).
 *
 * Arbitration. Whenever the wire is idle, every node whose oldest frame
 * is ready presents it (a node's queue is first in, first out, as an
 * adapter's or a controller's FIFO mode keeps its frames in order) and the
 * one with the lowest identifier wins, as the dominant bits decide on a real
 * bus: a standard identifier beats an extended one with the same first
 * 11 bits, a data frame beats a remote frame with the same identifier. Two
 * nodes sending the very same identifier (which would garble each other on
 * a real bus) go in node order.
 *
 * Time is the caller's: daran_sim_can_bus_run() moves the bus to a time
 * (the end of a control tick, or any time between), putting on the wire
 * whatever the queues hold and delivering every frame whose last bit has
 * passed, at that time: the bus's clock (now_ns) reads the frame's end
 * while the receivers' callbacks run, so what they send in answer is queued
 * then, and goes out in the same run when its time comes. A frame queued
 * with daran_sim_can_bus_send() is ready to compete from the bus's current
 * time plus its node's send delay (a drive's own processing time,
 * daran_sim_can_bus_set_send_delay(); 0 for a new node). A frame reaches
 * every other node that is on the bus, never its sender (no loopback); no
 * acknowledgement errors are modelled.
 *
 * Portable C99: no stdio, no heap; the caller owns the bus object. Nothing
 * here is thread-safe. */
#ifndef DARAN_SIM_CAN_BUS_H
#define DARAN_SIM_CAN_BUS_H

#include <stdbool.h>
#include <stdint.h>

#include "daran_can.h"
#include "sim_bus.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Nodes on one bus: a node per simulated drive and a few host adapters. */
#define DARAN_SIM_CAN_MAX_NODES (DARAN_SIM_MAX_DRIVES + 4u)
/* Frames a node's transmit queue holds; a send to a full queue fails. */
#define DARAN_SIM_CAN_TX_FRAMES 32u
/* The bit rate of daran-sim's bus (the vendor's default, can.md 1.1). */
#define DARAN_SIM_CAN_BIT_RATE 1000000u
/* The bit count of the intermission that follows every frame. */
#define DARAN_SIM_CAN_INTERMISSION_BITS 3u
/* A node number meaning "the bus itself" (the faults of every node). */
#define DARAN_SIM_CAN_ANY_NODE 0xFFFFFFFFu

/* Receives a frame that has crossed the bus, at @p end_ns (the time its last
 * bit passed, on the bus's clock). */
typedef void (*daran_sim_can_deliver_fn)(void *ctx, const daran_can_frame_t *frame,
                                         uint64_t end_ns);

/* The bus faults (daran-sim's `!fault ID can-...`). */
typedef enum daran_sim_can_fault {
    DARAN_SIM_CAN_FAULT_LOSE,    /* the next N frames the node sends are lost: they take
                                    their time on the wire and nobody receives them */
    DARAN_SIM_CAN_FAULT_MUTE,    /* the node receives, but what it sends (or had queued)
                                    never reaches the wire; its sends still succeed */
    DARAN_SIM_CAN_FAULT_UNPLUG,  /* the node is off the bus: it receives nothing, and
                                    sends wait in its queue until it is plugged in again
                                    (a full queue refuses them) */
    DARAN_SIM_CAN_FAULT_BUS_OFF, /* the node's controller is bus-off: every send fails,
                                    its queue is emptied, it receives nothing */
    DARAN_SIM_CAN_FAULT_RECOVER, /* every fault above is cleared (losses still pending
                                    included); queued frames go out again */
    DARAN_SIM_CAN_FAULT_COUNT    /* how many there are; not a fault */
} daran_sim_can_fault_t;

/* The fault names of `!fault ID KIND`, as daran-sim lists them. */
#define DARAN_SIM_CAN_FAULT_NAMES "can-lose [N], can-mute, can-unplug, can-bus-off, can-recover"

typedef struct daran_sim_can_node {
    daran_sim_can_deliver_fn deliver; /* NULL: the node receives nothing */
    void *ctx;
    daran_can_frame_t queue[DARAN_SIM_CAN_TX_FRAMES]; /* waiting to go on the wire */
    uint64_t ready_ns[DARAN_SIM_CAN_TX_FRAMES];         /* when each may compete */
    uint32_t head;                                      /* the oldest, queue[head] */
    uint32_t queued;
    uint64_t send_delay_ns; /* from a send to its frame being ready */
    uint32_t lose;       /* frames still to lose of those it sends */
    bool mute;
    bool unplugged;
    bool bus_off;
    uint32_t sent;       /* frames that went on the wire (lost ones included) */
    uint32_t received;   /* frames delivered to it */
    uint32_t refused;    /* sends that failed (bus-off, full queue) */
} daran_sim_can_node_t;

typedef struct daran_sim_can_bus {
    uint32_t bit_rate;    /* bits per second */
    uint64_t now_ns;      /* the bus has run to this time */
    uint64_t free_ns;     /* the wire is idle from this time */
    bool on_wire;         /* a frame is being transmitted */
    bool wire_lost;       /* ... and nobody will receive it */
    uint32_t wire_node;   /* its sender */
    uint64_t wire_end_ns; /* when its last bit passes */
    daran_can_frame_t wire;
    uint32_t lose_any;    /* the next frames sent by anyone are lost */
    bool bus_off;         /* the whole bus is down */
    uint32_t count;       /* nodes */
    daran_sim_can_node_t node[DARAN_SIM_CAN_MAX_NODES];
} daran_sim_can_bus_t;

/* An empty bus at @p bit_rate bits per second (0: DARAN_SIM_CAN_BIT_RATE)
 * whose clock reads @p now_ns. O(size of the bus); cannot fail. */
void daran_sim_can_bus_init(daran_sim_can_bus_t *bus, uint32_t bit_rate, uint64_t now_ns);

/* Connect a node that receives through @p deliver (may be NULL); returns
 * its number (0, 1, ... in order of connection), or DARAN_SIM_CAN_ANY_NODE
 * when DARAN_SIM_CAN_MAX_NODES are connected. */
uint32_t daran_sim_can_bus_add_node(daran_sim_can_bus_t *bus, daran_sim_can_deliver_fn deliver,
                                    void *ctx);

/* Frames node @p node sends from now on are ready @p delay_ns after the
 * send (a drive's processing time between a frame's arrival and its
 * answer's transmission); nothing for a node that does not exist. */
void daran_sim_can_bus_set_send_delay(daran_sim_can_bus_t *bus, uint32_t node, uint64_t delay_ns);

/* Node @p node hands its controller @p frame, at the bus's current time.
 * True when the controller took it (a mute node's frame is taken and
 * vanishes); false when the node or the bus is bus-off or its queue is full
 * (counted in node[].refused). Frames of any shape are carried (remote,
 * extended, DLC 0..8); a DLC above 8 is refused. O(1). */
bool daran_sim_can_bus_send(daran_sim_can_bus_t *bus, uint32_t node,
                            const daran_can_frame_t *frame);

/* How many more frames node @p node can queue now (0 when bus-off). */
uint32_t daran_sim_can_bus_room(const daran_sim_can_bus_t *bus, uint32_t node);

/* Run the bus up to @p until_ns (an earlier time changes nothing): frames
 * go on the wire in arbitration order as they become ready (a frame ready
 * exactly at @p until_ns waits for the next run, so every frame ready then
 * competes), and each one whose last bit passes by then is delivered to
 * every other node on the bus, in node order, with the bus's clock at its
 * end.
 * Returns how many frames were delivered or lost. O(frames x nodes). */
uint32_t daran_sim_can_bus_run(daran_sim_can_bus_t *bus, uint64_t until_ns);

/* When the next frame's last bit passes, as the queues stand now (a frame
 * queued meanwhile may win the wire first): the end of the frame on the
 * wire, else of the frame the idle wire will carry next; UINT64_MAX when
 * nothing is on the wire or ready to go on it (queues empty, or their
 * nodes off the bus). A real-time loop sleeps until then. O(nodes). */
uint64_t daran_sim_can_bus_next_ns(const daran_sim_can_bus_t *bus);

/* Inject @p fault on node @p node, or with DARAN_SIM_CAN_ANY_NODE on the
 * bus as a whole: LOSE loses the next @p count frames anyone sends (0
 * counts as 1), MUTE and UNPLUG apply to every node, BUS_OFF takes the
 * whole bus down (every send fails, nothing is delivered), RECOVER clears
 * every fault of the bus and of every node. For a node, LOSE adds @p count
 * (0 counts as 1) to its frames to lose. DARAN_ERR_BAD_ARGUMENT for a node
 * or fault that does not exist (nothing changes). */
DARAN_NODISCARD daran_result_t daran_sim_can_bus_fault(daran_sim_can_bus_t *bus, uint32_t node,
                                                       daran_sim_can_fault_t fault,
                                                       uint32_t count);

/* Reset node @p node's controller, as a power cycle does: its queue is
 * emptied and bus-off cleared (mute and unplugged are wiring: they stay, as
 * do frames still to lose). */
void daran_sim_can_bus_reset_node(daran_sim_can_bus_t *bus, uint32_t node);

/* The bits @p frame occupies on the wire: its fields, the stuff bits its
 * contents need and the intermission. A DLC above 8 counts as 8 data bytes
 * (as a controller sends them). */
uint32_t daran_sim_can_frame_bits(const daran_can_frame_t *frame);

/* The fault named @p name (DARAN_SIM_CAN_FAULT_NAMES without the count):
 * true with it in *fault; false (nothing written) otherwise. */
bool daran_sim_can_fault_from_name(const char *name, daran_sim_can_fault_t *fault);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_SIM_CAN_BUS_H */
