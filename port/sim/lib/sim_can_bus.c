/* The simulated CAN bus: transmit queues, arbitration, frame timing with
 * exact bit stuffing, delivery and the bus faults (sim_can_bus.h). */
#include "sim_can_bus.h"

#include <string.h>

#define CRC15_POLY 0x4599u
#define STUFF_RUN 5u
/* CRC delimiter, ACK slot, ACK delimiter and the 7 bits of end of frame:
 * fixed form, never stuffed. */
#define UNSTUFFED_TAIL_BITS 10u

static const struct {
    const char *name;
    daran_sim_can_fault_t fault;
} can_fault_names[] = {
    {"can-lose", DARAN_SIM_CAN_FAULT_LOSE},       {"can-mute", DARAN_SIM_CAN_FAULT_MUTE},
    {"can-unplug", DARAN_SIM_CAN_FAULT_UNPLUG},   {"can-bus-off", DARAN_SIM_CAN_FAULT_BUS_OFF},
    {"can-recover", DARAN_SIM_CAN_FAULT_RECOVER},
};

/* ---- the bits of a frame ---- */

/* The stuffed region of a frame (start of frame through CRC), walked bit by
 * bit: the CRC-15 over the bits before it, and the stuff bits. */
typedef struct bit_walk {
    uint32_t crc;
    uint32_t bits;  /* bits of the region, stuff bits not included */
    uint32_t stuff; /* stuff bits inserted */
    uint32_t run;   /* identical bits in a row on the wire (stuff bits count) */
    uint32_t last;  /* the last bit on the wire */
} bit_walk_t;

static void put_bit(bit_walk_t *w, uint32_t bit, bool in_crc)
{
    if (!in_crc) {
        uint32_t feedback = bit ^ ((w->crc >> 14) & 1u);
        w->crc = (w->crc << 1) & 0x7FFFu;
        if (feedback != 0u) {
            w->crc ^= CRC15_POLY;
        }
    }
    w->bits++;
    if (w->bits > 1u && bit == w->last) {
        w->run++;
    } else {
        w->run = 1u;
    }
    w->last = bit;
    if (w->run == STUFF_RUN) {
        /* the complement goes in, and starts the next run */
        w->stuff++;
        w->last = bit ^ 1u;
        w->run = 1u;
    }
}

static void put_field(bit_walk_t *w, uint32_t value, uint32_t width)
{
    while (width > 0u) {
        width--;
        put_bit(w, (value >> width) & 1u, false);
    }
}

uint32_t daran_sim_can_frame_bits(const daran_can_frame_t *frame)
{
    bit_walk_t w;
    bool remote = (frame->flags & DARAN_CAN_FRAME_REMOTE) != 0u;
    uint32_t dlc = frame->dlc > 8u ? 8u : frame->dlc;
    uint32_t data_bytes = remote ? 0u : dlc;
    uint32_t k;
    memset(&w, 0, sizeof w);
    put_bit(&w, 0u, false); /* start of frame */
    if ((frame->flags & DARAN_CAN_FRAME_EXTENDED) != 0u) {
        put_field(&w, (frame->id >> 18) & 0x7FFu, 11u);
        put_field(&w, 1u, 1u); /* SRR */
        put_field(&w, 1u, 1u); /* IDE: extended */
        put_field(&w, frame->id & 0x3FFFFu, 18u);
        put_field(&w, remote ? 1u : 0u, 1u); /* RTR */
        put_field(&w, 0u, 2u);               /* r1, r0 */
    } else {
        put_field(&w, frame->id & 0x7FFu, 11u);
        put_field(&w, remote ? 1u : 0u, 1u); /* RTR */
        put_field(&w, 0u, 2u);               /* IDE: standard, r0 */
    }
    put_field(&w, frame->dlc & 0xFu, 4u);
    for (k = 0; k < data_bytes; k++) {
        put_field(&w, frame->data[k], 8u);
    }
    {
        uint32_t crc = w.crc;
        for (k = 15u; k > 0u; k--) {
            put_bit(&w, (crc >> (k - 1u)) & 1u, true);
        }
    }
    return w.bits + w.stuff + UNSTUFFED_TAIL_BITS + DARAN_SIM_CAN_INTERMISSION_BITS;
}

/* ---- nodes and queues ---- */

void daran_sim_can_bus_init(daran_sim_can_bus_t *bus, uint32_t bit_rate, uint64_t now_ns)
{
    memset(bus, 0, sizeof *bus);
    bus->bit_rate = bit_rate != 0u ? bit_rate : DARAN_SIM_CAN_BIT_RATE;
    bus->now_ns = now_ns;
    bus->free_ns = now_ns;
}

uint32_t daran_sim_can_bus_add_node(daran_sim_can_bus_t *bus, daran_sim_can_deliver_fn deliver,
                                    void *ctx)
{
    daran_sim_can_node_t *n;
    if (bus->count >= DARAN_SIM_CAN_MAX_NODES) {
        return DARAN_SIM_CAN_ANY_NODE;
    }
    n = &bus->node[bus->count];
    memset(n, 0, sizeof *n);
    n->deliver = deliver;
    n->ctx = ctx;
    return bus->count++;
}

uint32_t daran_sim_can_bus_room(const daran_sim_can_bus_t *bus, uint32_t node)
{
    const daran_sim_can_node_t *n;
    if (node >= bus->count || bus->bus_off) {
        return 0u;
    }
    n = &bus->node[node];
    return n->bus_off ? 0u : DARAN_SIM_CAN_TX_FRAMES - n->queued;
}

void daran_sim_can_bus_set_send_delay(daran_sim_can_bus_t *bus, uint32_t node, uint64_t delay_ns)
{
    if (node < bus->count) {
        bus->node[node].send_delay_ns = delay_ns;
    }
}

bool daran_sim_can_bus_send(daran_sim_can_bus_t *bus, uint32_t node,
                            const daran_can_frame_t *frame)
{
    daran_sim_can_node_t *n;
    uint32_t slot;
    if (node >= bus->count) {
        return false;
    }
    n = &bus->node[node];
    if (frame->dlc > 8u || daran_sim_can_bus_room(bus, node) == 0u) {
        n->refused++;
        return false;
    }
    if (n->mute) {
        return true; /* taken, and never seen on the wire */
    }
    slot = (n->head + n->queued) % DARAN_SIM_CAN_TX_FRAMES;
    n->queue[slot] = *frame;
    n->ready_ns[slot] = bus->now_ns + n->send_delay_ns;
    n->queued++;
    return true;
}

static void drop_queue(daran_sim_can_node_t *n)
{
    n->head = 0u;
    n->queued = 0u;
}

void daran_sim_can_bus_reset_node(daran_sim_can_bus_t *bus, uint32_t node)
{
    if (node < bus->count) {
        drop_queue(&bus->node[node]);
        bus->node[node].bus_off = false;
    }
}

/* ---- arbitration and the wire ---- */

/* The arbitration field as the wire sends it, as one number compared from
 * its first bit: the 11 base identifier bits, then SRR/RTR, IDE, the 18
 * extension bits and the extended frame's RTR. A lower number wins. */
static uint64_t arbitration_key(const daran_can_frame_t *f)
{
    uint64_t remote = (f->flags & DARAN_CAN_FRAME_REMOTE) != 0u ? 1u : 0u;
    if ((f->flags & DARAN_CAN_FRAME_EXTENDED) != 0u) {
        uint64_t base = (f->id >> 18) & 0x7FFu;
        return base << 21 | 1u << 20 /* SRR */ | 1u << 19 /* IDE */ |
               (uint64_t)(f->id & 0x3FFFFu) << 1 | remote;
    }
    return (uint64_t)(f->id & 0x7FFu) << 21 | remote << 20; /* IDE 0 and the rest */
}

static bool on_bus(const daran_sim_can_node_t *n)
{
    return !n->unplugged && !n->bus_off;
}

/* Whether node @p n has a frame for the wire: queued, and the node on the bus. */
static bool offers(const daran_sim_can_node_t *n)
{
    return n->queued > 0u && on_bus(n);
}

/* When the idle wire can next start a frame: from free_ns, or as soon as
 * the first oldest frame of a node becomes ready; UINT64_MAX when no node
 * offers one. */
static uint64_t next_start(const daran_sim_can_bus_t *bus)
{
    uint64_t start = UINT64_MAX;
    uint32_t i;
    for (i = 0; i < bus->count; i++) {
        const daran_sim_can_node_t *n = &bus->node[i];
        if (offers(n) && n->ready_ns[n->head] < start) {
            start = n->ready_ns[n->head];
        }
    }
    if (start != UINT64_MAX && start < bus->free_ns) {
        start = bus->free_ns;
    }
    return start;
}

/* The node whose oldest frame, ready by @p start_ns, wins the arbitration;
 * count when none. */
static uint32_t winner(const daran_sim_can_bus_t *bus, uint64_t start_ns)
{
    uint32_t best = bus->count;
    uint64_t best_key = 0u;
    uint32_t i;
    for (i = 0; i < bus->count; i++) {
        const daran_sim_can_node_t *n = &bus->node[i];
        uint64_t key;
        if (!offers(n) || n->ready_ns[n->head] > start_ns) {
            continue;
        }
        key = arbitration_key(&n->queue[n->head]);
        if (best == bus->count || key < best_key) {
            best = i;
            best_key = key;
        }
    }
    return best;
}

static uint64_t frame_ns(const daran_sim_can_bus_t *bus, const daran_can_frame_t *frame)
{
    return ((uint64_t)daran_sim_can_frame_bits(frame) * 1000000000u + bus->bit_rate - 1u) /
           bus->bit_rate;
}

/* The frame on the wire has ended: every other node on the bus gets it,
 * at its end (what they send meanwhile is queued then). */
static void deliver(daran_sim_can_bus_t *bus)
{
    uint32_t i;
    bus->on_wire = false;
    bus->now_ns = bus->wire_end_ns;
    if (bus->wire_lost || bus->bus_off) {
        return;
    }
    for (i = 0; i < bus->count; i++) {
        daran_sim_can_node_t *n = &bus->node[i];
        if (i != bus->wire_node && on_bus(n) && n->deliver != NULL) {
            n->received++;
            n->deliver(n->ctx, &bus->wire, bus->wire_end_ns);
        }
    }
}

/* The winner's oldest frame goes on the wire at @p start_ns. */
static void transmit(daran_sim_can_bus_t *bus, uint32_t node, uint64_t start_ns)
{
    daran_sim_can_node_t *n = &bus->node[node];
    bus->wire = n->queue[n->head];
    n->head = (n->head + 1u) % DARAN_SIM_CAN_TX_FRAMES;
    n->queued--;
    n->sent++;
    bus->wire_node = node;
    bus->wire_end_ns = start_ns + frame_ns(bus, &bus->wire);
    bus->free_ns = bus->wire_end_ns;
    bus->on_wire = true;
    bus->wire_lost = false;
    if (bus->lose_any > 0u) {
        bus->lose_any--;
        bus->wire_lost = true;
    } else if (n->lose > 0u) {
        n->lose--;
        bus->wire_lost = true;
    }
}

uint32_t daran_sim_can_bus_run(daran_sim_can_bus_t *bus, uint64_t until_ns)
{
    uint32_t done = 0u;
    if (until_ns < bus->now_ns) {
        return 0u;
    }
    /* frames queued since the last run compete from then on: an idle wire
     * does not send them in the past */
    if (bus->free_ns < bus->now_ns) {
        bus->free_ns = bus->now_ns;
    }
    for (;;) {
        uint64_t start;
        if (bus->on_wire) {
            if (bus->wire_end_ns > until_ns) {
                break;
            }
            deliver(bus);
            done++;
            continue;
        }
        start = next_start(bus);
        if (bus->bus_off || start >= until_ns) {
            break;
        }
        transmit(bus, winner(bus, start), start);
    }
    bus->now_ns = until_ns;
    return done;
}

uint64_t daran_sim_can_bus_next_ns(const daran_sim_can_bus_t *bus)
{
    uint64_t start;
    uint32_t node;
    if (bus->on_wire) {
        return bus->wire_end_ns;
    }
    start = next_start(bus);
    if (bus->bus_off || start == UINT64_MAX) {
        return UINT64_MAX;
    }
    if (start < bus->now_ns) {
        start = bus->now_ns; /* queued since the last run: not in the past */
    }
    node = winner(bus, start);
    return start + frame_ns(bus, &bus->node[node].queue[bus->node[node].head]);
}

/* ---- faults ---- */

static void node_fault(daran_sim_can_node_t *n, daran_sim_can_fault_t fault, uint32_t count)
{
    switch (fault) {
    case DARAN_SIM_CAN_FAULT_LOSE:
        n->lose += count;
        break;
    case DARAN_SIM_CAN_FAULT_MUTE:
        n->mute = true;
        drop_queue(n); /* what it had queued never leaves either */
        break;
    case DARAN_SIM_CAN_FAULT_UNPLUG:
        n->unplugged = true;
        break;
    case DARAN_SIM_CAN_FAULT_BUS_OFF:
        n->bus_off = true;
        drop_queue(n);
        break;
    default: /* RECOVER */
        n->lose = 0u;
        n->mute = false;
        n->unplugged = false;
        n->bus_off = false;
        break;
    }
}

daran_result_t daran_sim_can_bus_fault(daran_sim_can_bus_t *bus, uint32_t node,
                                       daran_sim_can_fault_t fault, uint32_t count)
{
    uint32_t i;
    if ((unsigned)fault >= (unsigned)DARAN_SIM_CAN_FAULT_COUNT ||
        (node != DARAN_SIM_CAN_ANY_NODE && node >= bus->count)) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    if (count == 0u) {
        count = 1u;
    }
    if (node != DARAN_SIM_CAN_ANY_NODE) {
        node_fault(&bus->node[node], fault, count);
        return DARAN_OK;
    }
    switch (fault) {
    case DARAN_SIM_CAN_FAULT_LOSE:
        bus->lose_any += count;
        break;
    case DARAN_SIM_CAN_FAULT_BUS_OFF:
        bus->bus_off = true;
        bus->on_wire = false; /* the frame being sent is destroyed */
        for (i = 0; i < bus->count; i++) {
            drop_queue(&bus->node[i]);
        }
        break;
    case DARAN_SIM_CAN_FAULT_RECOVER:
        bus->lose_any = 0u;
        bus->bus_off = false;
        for (i = 0; i < bus->count; i++) {
            node_fault(&bus->node[i], fault, count);
        }
        break;
    default: /* MUTE, UNPLUG */
        for (i = 0; i < bus->count; i++) {
            node_fault(&bus->node[i], fault, count);
        }
        break;
    }
    return DARAN_OK;
}

bool daran_sim_can_fault_from_name(const char *name, daran_sim_can_fault_t *fault)
{
    size_t k;
    for (k = 0; k < sizeof can_fault_names / sizeof can_fault_names[0]; k++) {
        if (strcmp(name, can_fault_names[k].name) == 0) {
            *fault = can_fault_names[k].fault;
            return true;
        }
    }
    return false;
}
