/* Harness 8: ASCII lines and CAN frames mixed through a gateway's bridge
 * (docs/can.md, "The bridge"). Drive 1 is the gateway; drives 2 and 3 sit on
 * the same in-memory bus; every drive has the recording HAL of fuzz_hal.c,
 * so its range, finiteness and state checks hold on all three.
 *
 * Input: 1 setup byte, then records.
 *   setup     bit 0: drive 2 unplugged (hears nothing, sends nothing);
 *             bit 1: drive 3 unplugged; bit 2: the gateway's sends refused
 *             (bus-off); bit 3: every third send on the bus refused; bit 4:
 *             the gateway's can.config.protocol 0 at init; bit 5: drive 2
 *             answers reads with enable_reply_state 1 (status frames that
 *             a waiting query must ignore)
 *   record    op % 4 == 0: ASCII: (next byte % 48) bytes into the gateway's
 *                          ring, as an interrupt hands them over
 *             op % 4 == 1: a frame from a node outside the harness: 2 id
 *                          bytes (11 bits) and 8 data bytes, to every drive
 *             op % 4 == 2: the clock moves (next byte) milliseconds
 *             op % 4 == 3: nothing; each record ends with a poll of all
 *
 * Asserted (fuzz_fail() aborts), besides the sanitizers and fuzz_hal.c's own
 * checks on every drive:
 *  - every line the gateway writes is a well-formed reply (invariant 4);
 *  - every frame the gateway sends is a standard data frame with DLC 8, of
 *    a code the contract knows: its own node's replies and status frames, or
 *    a bridged line's frames to another node (never its own);
 *  - a drive that is not the gateway never writes an ASCII line;
 *  - a query never waits past its timeout: once the clock has moved
 *    DARAN_CAN_BRIDGE_TIMEOUT_MS since the read it waits for went out and
 *    the gateway was polled, it is answered;
 *  - at the end (a line end, the clock moved, polls), nothing waits and the
 *    gateway still runs a line of its own: exactly one set of a sentinel
 *    property, so no byte, line or query is stuck. */
#include <stdio.h>
#include <string.h>

#include "daran_can.h"
#include "fuzz_hal.h"

#if DARAN_ENABLE_CAN_BRIDGE

#define DRIVES 3u

typedef struct node {
    fuzz_hal_t hal; /* first: the node is the context of fuzz_hal's functions */
    daran_drive_t drive;
    daran_can_t can;
    bool unplugged;
} node_t;

static node_t nodes[DRIVES];
static daran_can_bridge_t bridge;
static uint32_t now;
static bool gateway_bus_off;
static bool refuse_every_third;
static uint32_t sends;

static uint32_t clock_ms(void *ctx)
{
    (void)ctx;
    return now;
}

/* A code the contract knows (2.1), or a status code (C9). */
static bool known_code(uint32_t code)
{
    return code == 0x08u || code == 0x0Cu || (code >= 0x19u && code <= 0x1Fu) ||
           ((code & 1u) != 0u && code < 0x18u);
}

static void deliver(const node_t *from, const daran_can_frame_t *frame)
{
    for (size_t i = 0; i < DRIVES; i++) {
        if (&nodes[i] != from && !nodes[i].unplugged) {
            (void)daran_can_receive(&nodes[i].can, frame);
        }
    }
}

static bool bus_send(void *ctx, const daran_can_frame_t *frame)
{
    node_t *from = ctx;
    FUZZ_CHECK(frame->dlc == 8u && frame->flags == 0u && frame->id <= 0x7FFu,
               "a frame of another shape sent: id 0x%x dlc %u", (unsigned)frame->id, frame->dlc);
    FUZZ_CHECK(known_code(frame->id & 0x1Fu), "a frame of an unknown code sent: 0x%03x",
               (unsigned)frame->id);
    if (from == &nodes[0]) {
        uint32_t node = frame->id >> 5;
        uint32_t code = frame->id & 0x1Fu;
        bool own = node == nodes[0].hal.props[DARAN_PROP_CAN_NODE_ID].u32;
        bool status = (code & 1u) != 0u && code < 0x18u;
        /* its own node: a read reply or a status frame; another: a bridged
         * line's frames, never a status frame */
        FUZZ_CHECK(own ? (status || code == 0x1Eu) : !status,
                   "the gateway sent 0x%03x (own node %d)", (unsigned)frame->id, own);
    }
    sends++;
    if (from->unplugged || (from == &nodes[0] && gateway_bus_off) ||
        (refuse_every_third && sends % 3u == 0u)) {
        return false;
    }
    deliver(from, frame);
    return true;
}

static void remote_write(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    fuzz_fail("a drive that is not the gateway wrote an ASCII line: %.*s", (int)len, line);
}

/* fuzz_hal's set, which also lets can.error take bit 0: the one non-zero
 * value the core writes to an error register (a duplicate id, C22). */
static daran_result_t bridge_set(void *ctx, daran_prop_t prop, daran_value_t value)
{
    fuzz_hal_t *h = ctx;
    if (prop == DARAN_PROP_CAN_ERROR && value.u32 != 0u) {
        FUZZ_CHECK(value.u32 == (h->props[DARAN_PROP_CAN_ERROR].u32 | 1u),
                   "can.error 0x%08x written", (unsigned)value.u32);
        h->props[DARAN_PROP_CAN_ERROR] = value;
        return DARAN_OK;
    }
    return fuzz_hal_set(ctx, prop, value);
}

static const daran_hal_t gateway_hal = {.get = fuzz_hal_get,
                                        .set = bridge_set,
                                        .move = fuzz_hal_move,
                                        .action = fuzz_hal_action,
                                        .write = fuzz_write,
                                        .now_ms = clock_ms,
                                        .can_send = bus_send};
static const daran_hal_t remote_hal = {.get = fuzz_hal_get,
                                       .set = bridge_set,
                                       .move = fuzz_hal_move,
                                       .action = fuzz_hal_action,
                                       .write = remote_write,
                                       .now_ms = clock_ms,
                                       .can_send = bus_send};

static void poll_all(void)
{
    (void)daran_poll(&nodes[0].drive);
    for (size_t i = 0; i < DRIVES; i++) {
        (void)daran_can_poll(&nodes[i].can);
    }
    (void)daran_poll(&nodes[0].drive);
}

static void setup(uint8_t flags)
{
    memset(nodes, 0, sizeof nodes);
    now = 1000;
    sends = 0;
    gateway_bus_off = (flags & 4u) != 0u;
    refuse_every_third = (flags & 8u) != 0u;
    for (size_t i = 0; i < DRIVES; i++) {
        node_t *n = &nodes[i];
        fuzz_hal_init(&n->hal, (uint32_t)(i + 1u));
        n->hal.props[DARAN_PROP_CAN_PROTOCOL].u32 = 1;
        FUZZ_CHECK(daran_init(&n->drive, i == 0u ? &gateway_hal : &remote_hal, n) == DARAN_OK,
                   "daran_init refused a complete HAL");
    }
    nodes[0].hal.props[DARAN_PROP_CAN_PROTOCOL].u32 = (flags & 16u) != 0u ? 0u : 1u;
    nodes[1].hal.props[DARAN_PROP_ENABLE_REPLY_STATE].u32 = (flags & 32u) != 0u ? 1u : 0u;
    nodes[1].unplugged = (flags & 1u) != 0u;
    nodes[2].unplugged = (flags & 2u) != 0u;
    for (size_t i = 0; i < DRIVES; i++) {
        FUZZ_CHECK(daran_can_init(&nodes[i].can, &nodes[i].drive) == DARAN_OK,
                   "daran_can_init refused");
    }
    FUZZ_CHECK(daran_can_bridge_init(&bridge, &nodes[0].can) == DARAN_OK,
               "daran_can_bridge_init refused");
}

/* A waiting query is answered once the read it waits for is overdue and
 * the gateway polled (each read has its own DARAN_CAN_BRIDGE_TIMEOUT_MS). */
static void check_no_overdue_query(void)
{
    FUZZ_CHECK(!daran_can_bridge_busy(&bridge) ||
                   now - bridge.asked_ms < DARAN_CAN_BRIDGE_TIMEOUT_MS,
               "a query waits past its timeout (asked at %u, now %u)", (unsigned)bridge.asked_ms,
               (unsigned)now);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1u) {
        return 0;
    }
    setup(data[0]);
    size_t at = 1;
    while (at < size) {
        uint8_t op = data[at++];
        switch (op % 4u) {
        case 0: {
            size_t n = at < size ? data[at++] % 48u : 0u;
            n = n < size - at ? n : size - at;
            (void)daran_rx_write(&nodes[0].drive, data + at, n);
            at += n;
            break;
        }
        case 1: {
            if (size - at < 10u) {
                at = size;
                break;
            }
            daran_can_frame_t frame = {(uint32_t)(data[at] | (data[at + 1] & 7u) << 8), 8, 0, {0}};
            memcpy(frame.data, data + at + 2, 8);
            at += 10;
            deliver(NULL, &frame);
            break;
        }
        case 2:
            now += at < size ? data[at++] : 0u;
            break;
        default:
            break;
        }
        poll_all();
        check_no_overdue_query();
    }
    /* The end: time for every held line and query to end (the ring holds
     * at most DARAN_RX_RING_SIZE / 2 lines, each waiting at most one timeout
     * per read), a line end, and then a line of the gateway's own must still
     * run, exactly once. */
    for (int pass = 0; pass < 2; pass++) {
        for (size_t round = 0; round < DARAN_RX_RING_SIZE * DARAN_CAN_BRIDGE_READS; round++) {
            if (!daran_can_bridge_busy(&bridge) &&
                daran_rx_free(&nodes[0].drive) == DARAN_RX_RING_SIZE) {
                break;
            }
            now += DARAN_CAN_BRIDGE_TIMEOUT_MS;
            poll_all();
            check_no_overdue_query();
        }
        if (pass == 0) {
            (void)daran_rx_byte(&nodes[0].drive, '\n');
        }
    }
    FUZZ_CHECK(!daran_can_bridge_busy(&bridge), "a query still waits at the end");
    /* addressed to the gateway's id as it is now (a line may have changed it) */
    char sentinel[64];
    uint32_t id = nodes[0].hal.props[DARAN_PROP_CAN_NODE_ID].u32;
    int n = snprintf(sentinel, sizeof sentinel, "w axis%u.output_shaft.circular_setpoint_max 1234.5\n",
                     (unsigned)id);
    fuzz_hal_clear(&nodes[0].hal);
    FUZZ_CHECK(daran_rx_write(&nodes[0].drive, sentinel, (size_t)n) == (size_t)n,
               "the gateway's ring is full at the end");
    poll_all();
    FUZZ_CHECK(nodes[0].hal.n_set == 1u &&
                   nodes[0].hal.last_set_prop == DARAN_PROP_CIRCULAR_SETPOINT_MAX &&
                   nodes[0].hal.last_set_value.f32 == 1234.5f,
               "the gateway's own line did not run once at the end (%zu sets)",
               nodes[0].hal.n_set);
    return 0;
}

#else /* a core without the bridge: nothing to fuzz */

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    (void)data;
    (void)size;
    return 0;
}

#endif
