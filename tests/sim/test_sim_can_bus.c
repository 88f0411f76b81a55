/* The simulated CAN bus alone (sim_can_bus.h): the time each frame takes
 * (its fields and its exact stuff bits), arbitration by identifier across
 * nodes and first-in-first-out within one, delivery to every node but the
 * sender when the last bit passes (an answer sent on arrival crossing in
 * the same run, after its node's send delay), and the faults: lost frames,
 * a mute, unplugged or bus-off node, the whole bus off, recovery. */
#include <stdint.h>
#include <string.h>

#include "sim_unity.h"
#include "unity.h"

#include "sim_can_bus.h"

#define NODES 4u
#define BIT_NS 1000u /* at 1 Mbit/s */

/* What each node received, in order, with the time the last bit passed. */
typedef struct heard {
    daran_can_frame_t frame[64];
    uint64_t end_ns[64];
    uint32_t count;
} heard_t;

static daran_sim_can_bus_t bus;
static heard_t heard[NODES];

static void listen(void *ctx, const daran_can_frame_t *frame, uint64_t end_ns)
{
    heard_t *h = ctx;
    if (h->count < 64u) {
        h->frame[h->count] = *frame;
        h->end_ns[h->count] = end_ns;
        h->count++;
    }
}

void setUp(void)
{
    uint32_t i;
    memset(heard, 0, sizeof heard);
    daran_sim_can_bus_init(&bus, 0u, 0u);
    for (i = 0; i < NODES; i++) {
        TEST_ASSERT_EQUAL_UINT32(i, daran_sim_can_bus_add_node(&bus, listen, &heard[i]));
    }
}

void tearDown(void)
{
}

static daran_can_frame_t frame8(uint32_t id, uint8_t fill)
{
    daran_can_frame_t f;
    memset(&f, 0, sizeof f);
    f.id = id;
    f.dlc = 8u;
    memset(f.data, fill, sizeof f.data);
    return f;
}

static daran_can_frame_t frame_of(uint32_t id, const uint8_t *data, uint8_t dlc, uint8_t flags)
{
    daran_can_frame_t f;
    memset(&f, 0, sizeof f);
    f.id = id;
    f.dlc = dlc;
    f.flags = flags;
    if (data != NULL) {
        memcpy(f.data, data, dlc);
    }
    return f;
}

static void send_ok(uint32_t node, daran_can_frame_t f)
{
    TEST_ASSERT_TRUE(daran_sim_can_bus_send(&bus, node, &f));
}

/* ---- frame timing ---- */

/* SOF, 11 id bits, RTR, IDE, r0 and the DLC are 19 zeros and the CRC of
 * zeros is 0: 34 zeros in a row take a stuff bit after every 5 (6 of them),
 * then the 10 fixed bits and the 3 of the intermission: 53. */
static void test_a_frame_of_zeros_takes_its_hand_counted_53_bits(void)
{
    daran_can_frame_t f = frame_of(0x000u, NULL, 0u, 0u);
    TEST_ASSERT_EQUAL_UINT32(53u, daran_sim_can_frame_bits(&f));
}

/* Frames of the protocol, their bits counted by a separate bit-listing
 * script (CRC-15 and stuffing written out, docs/simulator.md "Timing"):
 * 47 + 64 fixed bits plus each frame's own stuff bits. */
static void test_protocol_frames_take_their_stuffed_bit_counts(void)
{
    static const struct {
        uint32_t id;
        uint8_t data[8];
        uint32_t bits;
    } cases[] = {
        {0x01Eu, {0x19, 0x79, 0x03, 0, 0, 0, 0, 0}, 122u}, /* get_id(), broadcast */
        {0x03Eu, {0x19, 0x79, 0x03, 0, 1, 0, 0, 0}, 125u}, /* drive 1's answer */
        {0x05Eu, {0x19, 0x79, 0x03, 0, 2, 0, 0, 0}, 121u},
        {0x05Eu, {0x77, 0x94, 0, 0, 0, 0, 0, 0}, 123u},    /* read pos_estimate of 2 */
        {0x063u, {0, 0, 0, 0, 0, 0, 0, 0}, 126u},          /* a status frame at rest */
        {0x000u, {0, 0, 0, 0, 0, 0, 0, 0}, 127u},
        {0x7FFu, {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF}, 126u},
    };
    size_t k;
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        daran_can_frame_t f = frame_of(cases[k].id, cases[k].data, 8u, 0u);
        if (daran_sim_can_frame_bits(&f) != cases[k].bits) {
            FAIL_F("frame %03X: %u bits, expected %u", (unsigned)cases[k].id,
                   (unsigned)daran_sim_can_frame_bits(&f), (unsigned)cases[k].bits);
        }
    }
}

/* 0x555 and 0x55 bytes alternate nearly everywhere: no run of five but
 * one, so one stuff bit over the minimum 111. */
static void test_alternating_bits_need_almost_no_stuffing(void)
{
    daran_can_frame_t f = frame8(0x555u, 0x55u);
    TEST_ASSERT_EQUAL_UINT32(112u, daran_sim_can_frame_bits(&f));
}

/* Every standard 8-byte data frame: at least the 111 fixed bits (47 + 64),
 * at most the worst case of one stuff bit per 4 bits after the first of the
 * 98-bit stuffed region (24): 135. */
static void test_every_standard_8_byte_frame_takes_111_to_135_bits(void)
{
    uint32_t seed = 12345u;
    uint32_t lo = 1000u;
    uint32_t hi = 0u;
    uint32_t n;
    for (n = 0; n < 20000u; n++) {
        daran_can_frame_t f;
        uint32_t k;
        uint32_t bits;
        seed = seed * 1103515245u + 12345u;
        f = frame8((seed >> 8) & 0x7FFu, 0u);
        for (k = 0; k < 8u; k++) {
            /* half the bytes all ones or all zeros, to reach the heavily
             * stuffed end too */
            static const uint8_t runs[2] = {0x00u, 0xFFu};
            seed = seed * 1103515245u + 12345u;
            f.data[k] = (seed >> 16) % 2u == 0u ? runs[(seed >> 17) % 2u] : (uint8_t)(seed >> 24);
        }
        bits = daran_sim_can_frame_bits(&f);
        lo = bits < lo ? bits : lo;
        hi = bits > hi ? bits : hi;
    }
    NOTE("standard 8-byte frames: %u to %u bits", (unsigned)lo, (unsigned)hi);
    TEST_ASSERT_TRUE(lo >= 111u);
    TEST_ASSERT_TRUE(hi <= 135u);
    TEST_ASSERT_TRUE(hi > 125u); /* the stuffing really varies */
}

/* An extended frame has 20 more arbitration bits; a remote frame carries
 * no data bits whatever its DLC says. */
static void test_extended_and_remote_frames_have_their_own_field_lengths(void)
{
    uint8_t ff[8] = {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
    daran_can_frame_t ext = frame_of(0x1FFFFFFFu, ff, 8u, DARAN_CAN_FRAME_EXTENDED);
    daran_can_frame_t ext_empty = frame_of(0u, NULL, 0u, DARAN_CAN_FRAME_EXTENDED);
    daran_can_frame_t remote = frame_of(0x123u, NULL, 8u, DARAN_CAN_FRAME_REMOTE);
    TEST_ASSERT_EQUAL_UINT32(149u, daran_sim_can_frame_bits(&ext));
    TEST_ASSERT_EQUAL_UINT32(74u, daran_sim_can_frame_bits(&ext_empty));
    TEST_ASSERT_EQUAL_UINT32(48u, daran_sim_can_frame_bits(&remote));
}

/* ---- arbitration and delivery ---- */

static void test_frames_queued_together_go_out_lowest_id_first(void)
{
    daran_can_frame_t a = frame8(0x300u, 0x11u);
    daran_can_frame_t b = frame8(0x100u, 0x22u);
    daran_can_frame_t c = frame8(0x200u, 0x33u);
    uint64_t t;
    send_ok(0u, a);
    send_ok(1u, b);
    send_ok(2u, c);
    TEST_ASSERT_EQUAL_UINT32(3u, daran_sim_can_bus_run(&bus, 1000000u));
    TEST_ASSERT_EQUAL_UINT32(3u, heard[3].count);
    TEST_ASSERT_EQUAL_HEX32(0x100u, heard[3].frame[0].id);
    TEST_ASSERT_EQUAL_HEX32(0x200u, heard[3].frame[1].id);
    TEST_ASSERT_EQUAL_HEX32(0x300u, heard[3].frame[2].id);
    /* back to back: each ends its own bit count after the one before */
    t = (uint64_t)daran_sim_can_frame_bits(&b) * BIT_NS;
    TEST_ASSERT_EQUAL_UINT64(t, heard[3].end_ns[0]);
    t += (uint64_t)daran_sim_can_frame_bits(&c) * BIT_NS;
    TEST_ASSERT_EQUAL_UINT64(t, heard[3].end_ns[1]);
    t += (uint64_t)daran_sim_can_frame_bits(&a) * BIT_NS;
    TEST_ASSERT_EQUAL_UINT64(t, heard[3].end_ns[2]);
}

/* A node's frames keep their order (a preset before its start frame,
 * whatever their ids); the other nodes' heads still compete with them. */
static void test_one_nodes_frames_leave_in_the_order_it_sent_them(void)
{
    send_ok(0u, frame8(0x04Cu, 1u)); /* a preset for drive 2 ... */
    send_ok(0u, frame8(0x008u, 2u)); /* ... then the broadcast start */
    send_ok(1u, frame8(0x020u, 3u));
    (void)daran_sim_can_bus_run(&bus, 1000000u);
    TEST_ASSERT_EQUAL_UINT32(3u, heard[2].count);
    TEST_ASSERT_EQUAL_HEX32(0x020u, heard[2].frame[0].id); /* beats 0x04C */
    TEST_ASSERT_EQUAL_HEX32(0x04Cu, heard[2].frame[1].id);
    TEST_ASSERT_EQUAL_HEX32(0x008u, heard[2].frame[2].id);
}

static void test_a_standard_frame_beats_an_extended_one_and_data_beats_remote(void)
{
    send_ok(0u, frame_of(0x100u << 18, NULL, 0u, DARAN_CAN_FRAME_EXTENDED)); /* same first 11 bits */
    send_ok(1u, frame_of(0x100u, NULL, 0u, DARAN_CAN_FRAME_REMOTE));
    send_ok(2u, frame_of(0x100u, NULL, 0u, 0u));
    (void)daran_sim_can_bus_run(&bus, 1000000u);
    TEST_ASSERT_EQUAL_UINT32(3u, heard[3].count);
    TEST_ASSERT_EQUAL_UINT8(0u, heard[3].frame[0].flags);
    TEST_ASSERT_EQUAL_UINT8(DARAN_CAN_FRAME_REMOTE, heard[3].frame[1].flags);
    TEST_ASSERT_EQUAL_UINT8(DARAN_CAN_FRAME_EXTENDED, heard[3].frame[2].flags);
}

static void test_the_sender_never_receives_its_own_frame(void)
{
    send_ok(1u, frame8(0x123u, 0xA5u));
    (void)daran_sim_can_bus_run(&bus, 1000000u);
    TEST_ASSERT_EQUAL_UINT32(0u, heard[1].count);
    TEST_ASSERT_EQUAL_UINT32(1u, heard[0].count);
    TEST_ASSERT_EQUAL_UINT32(1u, heard[2].count);
    TEST_ASSERT_EQUAL_UINT32(1u, heard[3].count);
    TEST_ASSERT_EQUAL_HEX8(0xA5u, heard[0].frame[0].data[7]);
    TEST_ASSERT_EQUAL_UINT32(1u, bus.node[1].sent);
}

static void test_a_frame_arrives_when_its_last_bit_has_passed(void)
{
    daran_can_frame_t f = frame8(0x123u, 0u);
    uint64_t end = (uint64_t)daran_sim_can_frame_bits(&f) * BIT_NS;
    send_ok(0u, f);
    TEST_ASSERT_EQUAL_UINT32(0u, daran_sim_can_bus_run(&bus, end - 1u));
    TEST_ASSERT_EQUAL_UINT32(0u, heard[1].count);
    TEST_ASSERT_TRUE(bus.on_wire);
    TEST_ASSERT_EQUAL_UINT32(1u, daran_sim_can_bus_run(&bus, end));
    TEST_ASSERT_EQUAL_UINT32(1u, heard[1].count);
    TEST_ASSERT_EQUAL_UINT64(end, heard[1].end_ns[0]);
}

/* A frame queued on an idle bus starts when it is queued, not when the
 * wire went idle. */
static void test_a_frame_queued_later_starts_when_it_is_queued(void)
{
    daran_can_frame_t f = frame8(0x10u, 0u);
    (void)daran_sim_can_bus_run(&bus, 5000000u);
    send_ok(0u, f);
    (void)daran_sim_can_bus_run(&bus, 6000000u);
    TEST_ASSERT_EQUAL_UINT64(5000000u + (uint64_t)daran_sim_can_frame_bits(&f) * BIT_NS,
                             heard[1].end_ns[0]);
}

/* A node that answers from its receive callback: node 1 sends this frame
 * back when it hears one, as a drive answers a request. */
static daran_can_frame_t answer;

static void listen_and_answer(void *ctx, const daran_can_frame_t *frame, uint64_t end_ns)
{
    listen(ctx, frame, end_ns);
    send_ok(1u, answer);
}

/* The answer is queued at the request's end (the bus's clock reads it in
 * the callback), ready after node 1's send delay, and crosses in the same
 * run: the requester has it at request + delay + answer, not at the next
 * run. */
static void test_an_answer_sent_on_arrival_crosses_in_the_same_run(void)
{
    daran_can_frame_t request = frame8(0x05Eu, 0u);
    uint64_t request_end = (uint64_t)daran_sim_can_frame_bits(&request) * BIT_NS;
    answer = frame8(0x043u, 0x5Au);
    bus.node[1].deliver = listen_and_answer;
    daran_sim_can_bus_set_send_delay(&bus, 1u, 10000u);
    send_ok(0u, request);
    (void)daran_sim_can_bus_run(&bus, 10000000u);
    TEST_ASSERT_EQUAL_UINT32(1u, heard[0].count);
    TEST_ASSERT_EQUAL_HEX32(0x043u, heard[0].frame[0].id);
    TEST_ASSERT_EQUAL_UINT64(request_end + 10000u + daran_sim_can_frame_bits(&answer) * BIT_NS,
                             heard[0].end_ns[0]);
}

/* A frame not yet ready does not take part in the arbitration: the wire
 * goes to a higher id that is ready, and the delayed frame follows it. */
static void test_a_frame_competes_only_once_its_send_delay_has_passed(void)
{
    daran_sim_can_bus_set_send_delay(&bus, 0u, 50000u);
    send_ok(0u, frame8(0x001u, 0u));
    send_ok(1u, frame8(0x700u, 0u));
    (void)daran_sim_can_bus_run(&bus, 1000000u);
    TEST_ASSERT_EQUAL_HEX32(0x700u, heard[2].frame[0].id);
    TEST_ASSERT_EQUAL_HEX32(0x001u, heard[2].frame[1].id);
    daran_sim_can_bus_set_send_delay(&bus, 0u, 0u);
    daran_sim_can_bus_set_send_delay(&bus, NODES, 1u); /* no such node: nothing */
}

/* next_ns: the end of the frame on the wire, else of the one the idle wire
 * will carry next (after its delay), else none. */
static void test_the_next_frame_end_is_known_in_advance(void)
{
    daran_can_frame_t f = frame8(0x123u, 0u);
    uint64_t frame = (uint64_t)daran_sim_can_frame_bits(&f) * BIT_NS;
    TEST_ASSERT_EQUAL_UINT64(UINT64_MAX, daran_sim_can_bus_next_ns(&bus));
    daran_sim_can_bus_set_send_delay(&bus, 0u, 7000u);
    (void)daran_sim_can_bus_run(&bus, 1000u);
    send_ok(0u, f);
    TEST_ASSERT_EQUAL_UINT64(1000u + 7000u + frame, daran_sim_can_bus_next_ns(&bus));
    (void)daran_sim_can_bus_run(&bus, 9000u); /* on the wire */
    TEST_ASSERT_EQUAL_UINT64(1000u + 7000u + frame, daran_sim_can_bus_next_ns(&bus));
    (void)daran_sim_can_bus_run(&bus, daran_sim_can_bus_next_ns(&bus));
    TEST_ASSERT_EQUAL_UINT32(1u, heard[1].count);
    TEST_ASSERT_EQUAL_UINT64(UINT64_MAX, daran_sim_can_bus_next_ns(&bus));
    TEST_ASSERT_EQUAL_INT(DARAN_OK,
                          daran_sim_can_bus_fault(&bus, 0u, DARAN_SIM_CAN_FAULT_UNPLUG, 0u));
    send_ok(0u, f);
    TEST_ASSERT_EQUAL_UINT64(UINT64_MAX, daran_sim_can_bus_next_ns(&bus)); /* off the bus */
}

/* A frame on the wire cannot be overtaken by a lower id queued after it
 * started. */
static void test_a_frame_on_the_wire_is_not_preempted(void)
{
    send_ok(0u, frame8(0x700u, 0u));
    (void)daran_sim_can_bus_run(&bus, 50000u); /* mid-frame */
    send_ok(1u, frame8(0x001u, 0u));
    (void)daran_sim_can_bus_run(&bus, 1000000u);
    TEST_ASSERT_EQUAL_HEX32(0x700u, heard[2].frame[0].id);
    TEST_ASSERT_EQUAL_HEX32(0x001u, heard[2].frame[1].id);
}

static void test_a_full_queue_refuses_the_next_frame(void)
{
    uint32_t k;
    for (k = 0; k < DARAN_SIM_CAN_TX_FRAMES; k++) {
        send_ok(0u, frame8(0x100u + k, 0u));
    }
    TEST_ASSERT_EQUAL_UINT32(0u, daran_sim_can_bus_room(&bus, 0u));
    {
        daran_can_frame_t f = frame8(0x1u, 0u);
        TEST_ASSERT_FALSE(daran_sim_can_bus_send(&bus, 0u, &f));
        f.dlc = 9u;
        TEST_ASSERT_FALSE(daran_sim_can_bus_send(&bus, 1u, &f));
    }
    TEST_ASSERT_EQUAL_UINT32(1u, bus.node[0].refused);
    TEST_ASSERT_EQUAL_UINT32(1u, bus.node[1].refused);
}

/* ---- faults ---- */

static void test_a_nodes_lost_frames_take_their_time_and_reach_nobody(void)
{
    daran_can_frame_t f = frame8(0x100u, 0u);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_can_bus_fault(&bus, 0u, DARAN_SIM_CAN_FAULT_LOSE, 2u));
    send_ok(0u, f);
    send_ok(0u, f);
    send_ok(0u, f);
    send_ok(1u, frame8(0x200u, 0u)); /* another node's frame is not lost */
    TEST_ASSERT_EQUAL_UINT32(4u, daran_sim_can_bus_run(&bus, 10000000u));
    TEST_ASSERT_EQUAL_UINT32(2u, heard[2].count);
    TEST_ASSERT_EQUAL_HEX32(0x100u, heard[2].frame[0].id); /* the third */
    TEST_ASSERT_EQUAL_UINT64(3u * daran_sim_can_frame_bits(&f) * BIT_NS, heard[2].end_ns[0]);
    TEST_ASSERT_EQUAL_HEX32(0x200u, heard[2].frame[1].id);
    TEST_ASSERT_EQUAL_UINT32(1u, heard[0].count);
    TEST_ASSERT_EQUAL_HEX32(0x200u, heard[0].frame[0].id);
    TEST_ASSERT_EQUAL_UINT32(3u, bus.node[0].sent);
}

static void test_lost_frames_of_the_bus_are_whoever_sends_next(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_can_bus_fault(&bus, DARAN_SIM_CAN_ANY_NODE,
                                                           DARAN_SIM_CAN_FAULT_LOSE, 0u));
    send_ok(2u, frame8(0x300u, 0u));
    send_ok(1u, frame8(0x100u, 0u)); /* wins the arbitration: the one lost */
    (void)daran_sim_can_bus_run(&bus, 10000000u);
    TEST_ASSERT_EQUAL_UINT32(1u, heard[0].count);
    TEST_ASSERT_EQUAL_HEX32(0x300u, heard[0].frame[0].id);
}

static void test_a_mute_node_hears_everything_and_is_never_heard(void)
{
    send_ok(0u, frame8(0x100u, 0u)); /* queued before: never leaves either */
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_can_bus_fault(&bus, 0u, DARAN_SIM_CAN_FAULT_MUTE, 0u));
    send_ok(0u, frame8(0x101u, 0u)); /* its controller takes it */
    send_ok(1u, frame8(0x200u, 0u));
    (void)daran_sim_can_bus_run(&bus, 10000000u);
    TEST_ASSERT_EQUAL_UINT32(1u, heard[0].count);
    TEST_ASSERT_EQUAL_UINT32(1u, heard[2].count); /* 0x200 only */
    TEST_ASSERT_EQUAL_HEX32(0x200u, heard[2].frame[0].id);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_can_bus_fault(&bus, 0u, DARAN_SIM_CAN_FAULT_RECOVER, 0u));
    send_ok(0u, frame8(0x102u, 0u));
    (void)daran_sim_can_bus_run(&bus, 20000000u);
    TEST_ASSERT_EQUAL_UINT32(2u, heard[2].count);
    TEST_ASSERT_EQUAL_HEX32(0x102u, heard[2].frame[1].id);
}

static void test_an_unplugged_nodes_frames_wait_until_it_is_plugged_in(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK,
                          daran_sim_can_bus_fault(&bus, 3u, DARAN_SIM_CAN_FAULT_UNPLUG, 0u));
    send_ok(3u, frame8(0x100u, 0u));
    send_ok(0u, frame8(0x200u, 0u));
    (void)daran_sim_can_bus_run(&bus, 10000000u);
    TEST_ASSERT_EQUAL_UINT32(0u, heard[3].count); /* hears nothing */
    TEST_ASSERT_EQUAL_UINT32(1u, heard[1].count); /* 0x200 only */
    TEST_ASSERT_EQUAL_UINT32(1u, bus.node[3].queued);
    TEST_ASSERT_EQUAL_INT(DARAN_OK,
                          daran_sim_can_bus_fault(&bus, 3u, DARAN_SIM_CAN_FAULT_RECOVER, 0u));
    (void)daran_sim_can_bus_run(&bus, 20000000u);
    TEST_ASSERT_EQUAL_UINT32(2u, heard[1].count);
    TEST_ASSERT_EQUAL_HEX32(0x100u, heard[1].frame[1].id);
    TEST_ASSERT_EQUAL_UINT64(10000000u + daran_sim_can_frame_bits(&heard[1].frame[1]) * BIT_NS,
                             heard[1].end_ns[1]);
}

static void test_a_bus_off_node_cannot_send_and_hears_nothing_until_it_recovers(void)
{
    daran_can_frame_t f = frame8(0x100u, 0u);
    send_ok(2u, f);
    TEST_ASSERT_EQUAL_INT(DARAN_OK,
                          daran_sim_can_bus_fault(&bus, 2u, DARAN_SIM_CAN_FAULT_BUS_OFF, 0u));
    TEST_ASSERT_FALSE(daran_sim_can_bus_send(&bus, 2u, &f));
    TEST_ASSERT_EQUAL_UINT32(0u, daran_sim_can_bus_room(&bus, 2u));
    send_ok(0u, frame8(0x200u, 0u));
    (void)daran_sim_can_bus_run(&bus, 10000000u);
    TEST_ASSERT_EQUAL_UINT32(0u, heard[2].count);
    TEST_ASSERT_EQUAL_UINT32(1u, heard[1].count); /* its queued frame was dropped */
    TEST_ASSERT_EQUAL_INT(DARAN_OK,
                          daran_sim_can_bus_fault(&bus, 2u, DARAN_SIM_CAN_FAULT_RECOVER, 0u));
    send_ok(2u, f);
    (void)daran_sim_can_bus_run(&bus, 20000000u);
    TEST_ASSERT_EQUAL_UINT32(2u, heard[1].count);
}

static void test_the_whole_bus_off_destroys_the_frame_on_the_wire_and_refuses_all(void)
{
    daran_can_frame_t f = frame8(0x100u, 0u);
    send_ok(0u, f);
    (void)daran_sim_can_bus_run(&bus, 50000u);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_can_bus_fault(&bus, DARAN_SIM_CAN_ANY_NODE,
                                                           DARAN_SIM_CAN_FAULT_BUS_OFF, 0u));
    TEST_ASSERT_FALSE(daran_sim_can_bus_send(&bus, 1u, &f));
    (void)daran_sim_can_bus_run(&bus, 10000000u);
    TEST_ASSERT_EQUAL_UINT32(0u, heard[1].count + heard[2].count + heard[3].count);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_can_bus_fault(&bus, DARAN_SIM_CAN_ANY_NODE,
                                                           DARAN_SIM_CAN_FAULT_RECOVER, 0u));
    send_ok(1u, f);
    (void)daran_sim_can_bus_run(&bus, 20000000u);
    TEST_ASSERT_EQUAL_UINT32(1u, heard[0].count);
}

static void test_a_reset_clears_bus_off_and_the_queue_but_not_the_wiring(void)
{
    send_ok(0u, frame8(0x100u, 0u));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_can_bus_fault(&bus, 1u, DARAN_SIM_CAN_FAULT_BUS_OFF, 0u));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_can_bus_fault(&bus, 0u, DARAN_SIM_CAN_FAULT_UNPLUG, 0u));
    daran_sim_can_bus_reset_node(&bus, 0u);
    daran_sim_can_bus_reset_node(&bus, 1u);
    TEST_ASSERT_EQUAL_UINT32(0u, bus.node[0].queued);
    TEST_ASSERT_TRUE(bus.node[0].unplugged);
    TEST_ASSERT_FALSE(bus.node[1].bus_off);
}

static void test_faults_on_nodes_or_kinds_that_do_not_exist_are_refused(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                          daran_sim_can_bus_fault(&bus, NODES, DARAN_SIM_CAN_FAULT_MUTE, 0u));
    TEST_ASSERT_EQUAL_INT(DARAN_ERR_BAD_ARGUMENT,
                          daran_sim_can_bus_fault(&bus, 0u, DARAN_SIM_CAN_FAULT_COUNT, 0u));
    TEST_ASSERT_FALSE(bus.node[0].mute);
}

static void test_fault_names_map_to_their_faults(void)
{
    daran_sim_can_fault_t f = DARAN_SIM_CAN_FAULT_COUNT;
    TEST_ASSERT_TRUE(daran_sim_can_fault_from_name("can-lose", &f));
    TEST_ASSERT_EQUAL_INT(DARAN_SIM_CAN_FAULT_LOSE, f);
    TEST_ASSERT_TRUE(daran_sim_can_fault_from_name("can-bus-off", &f));
    TEST_ASSERT_EQUAL_INT(DARAN_SIM_CAN_FAULT_BUS_OFF, f);
    TEST_ASSERT_TRUE(daran_sim_can_fault_from_name("can-recover", &f));
    TEST_ASSERT_EQUAL_INT(DARAN_SIM_CAN_FAULT_RECOVER, f);
    TEST_ASSERT_FALSE(daran_sim_can_fault_from_name("stall", &f));
    TEST_ASSERT_EQUAL_INT(DARAN_SIM_CAN_FAULT_RECOVER, f);
}

static void test_the_bus_holds_at_most_its_nodes(void)
{
    uint32_t k;
    for (k = NODES; k < DARAN_SIM_CAN_MAX_NODES; k++) {
        TEST_ASSERT_EQUAL_UINT32(k, daran_sim_can_bus_add_node(&bus, NULL, NULL));
    }
    TEST_ASSERT_EQUAL_UINT32(DARAN_SIM_CAN_ANY_NODE, daran_sim_can_bus_add_node(&bus, NULL, NULL));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_frame_of_zeros_takes_its_hand_counted_53_bits);
    RUN_TEST(test_protocol_frames_take_their_stuffed_bit_counts);
    RUN_TEST(test_alternating_bits_need_almost_no_stuffing);
    RUN_TEST(test_every_standard_8_byte_frame_takes_111_to_135_bits);
    RUN_TEST(test_extended_and_remote_frames_have_their_own_field_lengths);
    RUN_TEST(test_frames_queued_together_go_out_lowest_id_first);
    RUN_TEST(test_one_nodes_frames_leave_in_the_order_it_sent_them);
    RUN_TEST(test_a_standard_frame_beats_an_extended_one_and_data_beats_remote);
    RUN_TEST(test_the_sender_never_receives_its_own_frame);
    RUN_TEST(test_a_frame_arrives_when_its_last_bit_has_passed);
    RUN_TEST(test_a_frame_queued_later_starts_when_it_is_queued);
    RUN_TEST(test_an_answer_sent_on_arrival_crosses_in_the_same_run);
    RUN_TEST(test_a_frame_competes_only_once_its_send_delay_has_passed);
    RUN_TEST(test_the_next_frame_end_is_known_in_advance);
    RUN_TEST(test_a_frame_on_the_wire_is_not_preempted);
    RUN_TEST(test_a_full_queue_refuses_the_next_frame);
    RUN_TEST(test_a_nodes_lost_frames_take_their_time_and_reach_nobody);
    RUN_TEST(test_lost_frames_of_the_bus_are_whoever_sends_next);
    RUN_TEST(test_a_mute_node_hears_everything_and_is_never_heard);
    RUN_TEST(test_an_unplugged_nodes_frames_wait_until_it_is_plugged_in);
    RUN_TEST(test_a_bus_off_node_cannot_send_and_hears_nothing_until_it_recovers);
    RUN_TEST(test_the_whole_bus_off_destroys_the_frame_on_the_wire_and_refuses_all);
    RUN_TEST(test_a_reset_clears_bus_off_and_the_queue_but_not_the_wiring);
    RUN_TEST(test_faults_on_nodes_or_kinds_that_do_not_exist_are_refused);
    RUN_TEST(test_fault_names_map_to_their_faults);
    RUN_TEST(test_the_bus_holds_at_most_its_nodes);
    return UNITY_END();
}
