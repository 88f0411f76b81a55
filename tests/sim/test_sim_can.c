/* Simulated drives with their CAN front ends on the simulated bus
 * (sim_can.h), driven by a host node as an adapter would: reads answered
 * by the right drive with its own id, broadcast reads by each drive in
 * arbitration order, a trajectory frame moving a shaft, the automatic
 * status reply, the heartbeat never mistaken for a duplicate id (no
 * loopback), the node guard, bus-off counted as unsent frames, a power
 * cycle that re-attaches the front end after the port's own setup, and
 * answers in bus time whatever the control tick. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "sim_unity.h"
#include "unity.h"

#include "daran_can.h"
#include "sim_can.h"

#define TICK_HZ 1000u

static daran_sim_bus_t line;
static daran_sim_can_t can;
static uint32_t host;

static daran_can_frame_t heard[64];
static uint64_t heard_ns[64];
static uint32_t heard_count;

/* Requests the host sends as each frame reaches it (a client that asks
 * again as soon as it has its answer), and the frame it sends. */
static uint32_t chained_requests;
static daran_can_frame_t chained_request;

static void host_listen(void *ctx, const daran_can_frame_t *frame, uint64_t end_ns)
{
    (void)ctx;
    if (heard_count < 64u) {
        heard[heard_count] = *frame;
        heard_ns[heard_count] = end_ns;
        heard_count++;
    }
    if (chained_requests > 0u) {
        chained_requests--;
        TEST_ASSERT_TRUE(daran_sim_can_bus_send(&can.wire, host, &chained_request));
    }
}

static void attach(uint32_t drives, uint32_t tick_hz)
{
    memset(&line, 0, sizeof line);
    heard_count = 0u;
    chained_requests = 0u;
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_bus_init(&line, drives, tick_hz));
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_can_attach(&can, &line));
    host = daran_sim_can_bus_add_node(&can.wire, host_listen, NULL);
    TEST_ASSERT_EQUAL_UINT32(drives, host);
}

void setUp(void)
{
    attach(2u, TICK_HZ);
}

void tearDown(void)
{
}

/* The bus time of @p frame at 1 Mbit/s. */
static uint64_t frame_ns(const daran_can_frame_t *frame)
{
    return daran_sim_can_frame_bits(frame) * 1000u;
}

static daran_can_frame_t frame_of(uint32_t id, const uint8_t data[8])
{
    daran_can_frame_t f;
    memset(&f, 0, sizeof f);
    f.id = id;
    f.dlc = 8u;
    memcpy(f.data, data, 8u);
    return f;
}

static void host_send(uint32_t id, const uint8_t data[8])
{
    daran_can_frame_t f = frame_of(id, data);
    TEST_ASSERT_TRUE(daran_sim_can_bus_send(&can.wire, host, &f));
}

static void ticks(uint32_t n)
{
    while (n-- > 0u) {
        daran_sim_can_tick(&can);
    }
}

/* An ASCII line to every drive (replies dropped): to set up a drive. */
static void line_say(const char *text)
{
    daran_sim_bus_send(&line, text, strlen(text));
    daran_sim_bus_send(&line, "\n", 1u);
    (void)daran_sim_bus_collect(&line, NULL, NULL);
}

static float f32_at(const uint8_t *bytes)
{
    uint32_t u = (uint32_t)bytes[0] | (uint32_t)bytes[1] << 8 | (uint32_t)bytes[2] << 16 |
                 (uint32_t)bytes[3] << 24;
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

static const uint8_t read_node_id[8] = {0x19, 0x79, 0x03, 0, 0, 0, 0, 0}; /* address 31001 */

static void test_a_read_is_answered_by_its_drive_alone_with_its_own_id(void)
{
    host_send(2u << 5 | 0x1Eu, read_node_id);
    ticks(2u);
    TEST_ASSERT_EQUAL_UINT32(1u, heard_count);
    TEST_ASSERT_EQUAL_HEX32(0x05Eu, heard[0].id);
    TEST_ASSERT_EQUAL_HEX8(2u, heard[0].data[4]);
    TEST_ASSERT_EQUAL_HEX8(0x03u, heard[0].data[2]); /* its own type code: u32 */
}

/* The recorded get_id() broadcast: each drive answers with its id; both
 * answers were queued when the request ended, so the lower id goes first
 * and the second follows back to back. */
static void test_a_broadcast_read_is_answered_by_each_drive_lowest_id_first(void)
{
    daran_can_frame_t request = frame_of(0x01Eu, read_node_id);
    host_send(0x01Eu, read_node_id);
    ticks(2u);
    TEST_ASSERT_EQUAL_UINT32(2u, heard_count);
    TEST_ASSERT_EQUAL_HEX32(0x03Eu, heard[0].id);
    TEST_ASSERT_EQUAL_HEX32(0x05Eu, heard[1].id);
    TEST_ASSERT_EQUAL_UINT64(frame_ns(&request) + DARAN_SIM_CAN_DRIVE_DELAY_NS + frame_ns(&heard[0]),
                             heard_ns[0]);
    TEST_ASSERT_EQUAL_UINT64(heard_ns[0] + daran_sim_can_frame_bits(&heard[1]) * 1000u,
                             heard_ns[1]);
}

/* 0x059 (trajectory tracking, `t 2 90 0 10`) moves drive 2 only. */
static void test_a_trajectory_frame_moves_its_drive_only(void)
{
    static const uint8_t t_90[8] = {0x00, 0x00, 0xB4, 0x42, 0x00, 0x00, 0xE8, 0x03};
    host_send(0x059u, t_90);
    ticks(3000u);
    TEST_ASSERT_FLOAT_WITHIN(0.5f, 90.0f, daran_sim_model_pos_deg(&line.node[1].sim.model));
    TEST_ASSERT_FLOAT_WITHIN(0.01f, 0.0f, daran_sim_model_pos_deg(&line.node[0].sim.model));
    TEST_ASSERT_EQUAL_UINT32(0u, heard_count); /* no reply without enable_reply_state */
}

static void test_a_motion_frame_gets_the_status_reply_when_the_drive_is_set_to(void)
{
    /* 0x05A, `q 2 45 10 5`: a trapezoid, under way once the frame ran */
    static const uint8_t q_45[8] = {0x00, 0x00, 0x34, 0x42, 0xE8, 0x03, 0xF4, 0x01};
    line_say("w axis2.config.extra_setting.enable_reply_state 1");
    host_send(0x05Au, q_45);
    ticks(2u);
    TEST_ASSERT_EQUAL_UINT32(1u, heard_count);
    /* a status frame of node 2: code 0 0 E T 1, T = 0 while it moves */
    TEST_ASSERT_EQUAL_HEX32(2u << 5 | 0x01u, heard[0].id);
}

/* A fast read after a finished move: T set, the position in the frame. */
static void test_a_fast_read_reports_the_position_and_trajectory_done(void)
{
    static const uint8_t fast[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    line_say("q 1 30");
    ticks(5000u);
    host_send(0x03Eu, fast);
    ticks(2u);
    TEST_ASSERT_EQUAL_UINT32(1u, heard_count);
    TEST_ASSERT_EQUAL_HEX32(1u << 5 | 0x03u, heard[0].id);
    TEST_ASSERT_FLOAT_WITHIN(0.01f, 30.0f, f32_at(heard[0].data));
}

/* Both drives send heartbeats; neither receives its own, so neither takes
 * the other's frames or its own echo for a duplicate id (can.error stays 0,
 * C22). */
static void test_heartbeats_reach_the_others_and_never_their_sender(void)
{
    line_say("w can.config.heartbeat_ms 10 1");
    line_say("w can.config.heartbeat_ms 10 2");
    ticks(100u);
    TEST_ASSERT_TRUE(heard_count >= 18u);
    TEST_ASSERT_EQUAL_UINT32(0u, line.node[0].sim.model.can_error);
    TEST_ASSERT_EQUAL_UINT32(0u, line.node[1].sim.model.can_error);
    TEST_ASSERT_TRUE(can.wire.node[0].received >= 9u); /* drive 2's heartbeats */
}

/* Another node sending status frames with drive 1's id: drive 1 notes a
 * duplicate id in can.error bit 0 (C22), drive 2 does not. */
static void test_a_status_frame_with_a_drives_id_marks_a_duplicate_id(void)
{
    static const uint8_t status[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    host_send(1u << 5 | 0x01u, status);
    ticks(2u);
    TEST_ASSERT_EQUAL_UINT32(DARAN_SIM_CAN_ERROR_DUPLICATE_ID, line.node[0].sim.model.can_error);
    TEST_ASSERT_EQUAL_UINT32(0u, line.node[1].sim.model.can_error);
}

/* The node guard: armed by a frame, it stops the drive when frames stop. */
static void test_the_node_guard_stops_a_drive_whose_frames_stopped(void)
{
    line_say("w can.config.timeout_ms 50 2");
    host_send(2u << 5 | 0x1Eu, read_node_id);
    ticks(40u);
    TEST_ASSERT_EQUAL_UINT32(8u, line.node[1].sim.model.state);
    ticks(20u);
    TEST_ASSERT_EQUAL_UINT32(1u, line.node[1].sim.model.state); /* idle */
    TEST_ASSERT_EQUAL_UINT32(8u, line.node[0].sim.model.state);
}

/* A bus-off drive cannot send: its heartbeats are counted as unsent. */
static void test_a_bus_off_drive_counts_its_frames_as_unsent(void)
{
    line_say("w can.config.heartbeat_ms 10 1");
    TEST_ASSERT_EQUAL_INT(DARAN_OK,
                          daran_sim_can_bus_fault(&can.wire, 0u, DARAN_SIM_CAN_FAULT_BUS_OFF, 0u));
    ticks(100u);
    TEST_ASSERT_EQUAL_UINT32(0u, heard_count);
    TEST_ASSERT_TRUE(daran_can_unsent(&can.front[0]) >= 9u);
}

/* A lost reply: the request ran (the write took), the answer never came. */
static void test_a_lost_reply_leaves_the_host_without_an_answer(void)
{
    TEST_ASSERT_EQUAL_INT(DARAN_OK,
                          daran_sim_can_bus_fault(&can.wire, 1u, DARAN_SIM_CAN_FAULT_LOSE, 1u));
    host_send(2u << 5 | 0x1Eu, read_node_id);
    ticks(3u);
    TEST_ASSERT_EQUAL_UINT32(0u, heard_count);
    host_send(2u << 5 | 0x1Eu, read_node_id);
    ticks(3u);
    TEST_ASSERT_EQUAL_UINT32(1u, heard_count);
}

static uint32_t setups;

static void count_setup(void *ctx, uint32_t index, daran_drive_t *proto)
{
    (void)ctx;
    (void)index;
    (void)proto;
    setups++;
}

/* A power cycle: the port's own setup first, then a fresh front end that
 * reads can.config.protocol again (0, saved, leaves it silent). */
static void test_a_power_cycle_restarts_the_front_end_after_the_ports_setup(void)
{
    memset(&line, 0, sizeof line);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_bus_init(&line, 2u, TICK_HZ));
    setups = 0u;
    daran_sim_bus_set_setup(&line, count_setup, NULL);
    TEST_ASSERT_EQUAL_INT(DARAN_OK, daran_sim_can_attach(&can, &line));
    host = daran_sim_can_bus_add_node(&can.wire, host_listen, NULL);
    heard_count = 0u;
    TEST_ASSERT_EQUAL_UINT32(2u, setups);
    line_say("w can.config.protocol 0 2");
    line_say("ss 2");
    daran_sim_bus_power_cycle(&line, 1u);
    TEST_ASSERT_EQUAL_UINT32(3u, setups);
    host_send(0x01Eu, read_node_id);
    ticks(3u);
    TEST_ASSERT_EQUAL_UINT32(1u, heard_count); /* drive 1 only */
    TEST_ASSERT_EQUAL_HEX32(0x03Eu, heard[0].id);
}

static daran_can_t *started[4];
static uint32_t started_count;

static void note_front_end(void *ctx, uint32_t index, daran_can_t *front)
{
    (void)ctx;
    if (started_count < 4u) {
        started[started_count++] = front;
    }
    TEST_ASSERT_EQUAL_PTR(&can.front[index], front);
}

/* The hook a bridge needs: told of every front end now, and of a front end
 * started again by a power cycle (daran_can_init() forgets a bridge). */
static void test_the_front_end_hook_hears_of_every_front_end_and_each_restart(void)
{
    started_count = 0u;
    daran_sim_can_on_front_end(&can, note_front_end, NULL);
    TEST_ASSERT_EQUAL_UINT32(2u, started_count);
    daran_sim_bus_power_cycle(&line, 1u);
    TEST_ASSERT_EQUAL_UINT32(3u, started_count);
    TEST_ASSERT_EQUAL_PTR(&can.front[1], started[2]);
    daran_sim_can_on_front_end(&can, NULL, NULL);
    daran_sim_bus_power_cycle(&line, 0u);
    TEST_ASSERT_EQUAL_UINT32(3u, started_count);
}

/* A link to one drive (a gateway's USB port): the other drive hears
 * nothing of it. */
static void test_a_line_sent_to_one_drive_reaches_it_alone(void)
{
    static const char line_text[] = "w axis0.config.extra_setting.enable_reply_state 1\n";
    daran_sim_bus_send_to(&line, 0u, line_text, sizeof line_text - 1u);
    daran_sim_bus_send_to(&line, 5u, line_text, sizeof line_text - 1u); /* no such drive */
    TEST_ASSERT_EQUAL_UINT32(1u, line.node[0].sim.model.cfg[DARAN_PROP_ENABLE_REPLY_STATE].u32);
    TEST_ASSERT_EQUAL_UINT32(0u, line.node[1].sim.model.cfg[DARAN_PROP_ENABLE_REPLY_STATE].u32);
}

/* A drive answers a frame in bus time, whatever the control tick: a host
 * that sends its next read as soon as it has the answer to the last gets
 * each of 20 answers its request's frame time, the drive's processing and
 * the answer's frame time after the last, all within the first tick at
 * 100 Hz (10 ms) and at 1 Hz, and no frame waits in the drive's ring for
 * the tick (none dropped). */
static void test_a_drive_answers_in_bus_time_at_any_tick_rate(void)
{
    static const uint32_t rates[] = {100u, 1u};
    size_t r;
    for (r = 0; r < sizeof rates / sizeof rates[0]; r++) {
        uint64_t asked_ns = 0u;
        uint32_t k;
        attach(1u, rates[r]);
        chained_request = frame_of(1u << 5 | 0x1Eu, read_node_id);
        chained_requests = 19u;
        host_send(chained_request.id, read_node_id);
        ticks(1u);
        TEST_ASSERT_EQUAL_UINT32(20u, heard_count);
        TEST_ASSERT_EQUAL_UINT32(0u, daran_can_dropped(&can.front[0]));
        for (k = 0; k < 20u; k++) {
            TEST_ASSERT_EQUAL_UINT64(asked_ns + frame_ns(&chained_request) +
                                         DARAN_SIM_CAN_DRIVE_DELAY_NS + frame_ns(&heard[k]),
                                     heard_ns[k]);
            asked_ns = heard_ns[k];
        }
    }
}

static void test_the_bus_clock_is_the_lines_simulated_time(void)
{
    attach(1u, 8000u);
    ticks(8000u);
    TEST_ASSERT_EQUAL_UINT64(1000000000u, can.wire.now_ns);
    TEST_ASSERT_EQUAL_UINT64(8000u, line.ticks);
    TEST_ASSERT_EQUAL_UINT64(375000u, daran_sim_can_tick_ns(&line, 3u));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_read_is_answered_by_its_drive_alone_with_its_own_id);
    RUN_TEST(test_a_broadcast_read_is_answered_by_each_drive_lowest_id_first);
    RUN_TEST(test_a_trajectory_frame_moves_its_drive_only);
    RUN_TEST(test_a_motion_frame_gets_the_status_reply_when_the_drive_is_set_to);
    RUN_TEST(test_a_fast_read_reports_the_position_and_trajectory_done);
    RUN_TEST(test_heartbeats_reach_the_others_and_never_their_sender);
    RUN_TEST(test_a_status_frame_with_a_drives_id_marks_a_duplicate_id);
    RUN_TEST(test_the_node_guard_stops_a_drive_whose_frames_stopped);
    RUN_TEST(test_a_bus_off_drive_counts_its_frames_as_unsent);
    RUN_TEST(test_a_lost_reply_leaves_the_host_without_an_answer);
    RUN_TEST(test_a_power_cycle_restarts_the_front_end_after_the_ports_setup);
    RUN_TEST(test_the_front_end_hook_hears_of_every_front_end_and_each_restart);
    RUN_TEST(test_a_line_sent_to_one_drive_reaches_it_alone);
    RUN_TEST(test_a_drive_answers_in_bus_time_at_any_tick_rate);
    RUN_TEST(test_the_bus_clock_is_the_lines_simulated_time);
    return UNITY_END();
}
