/* The simulated bus with the protocol core in front of every drive: lines go
 * through the byte path, replies come back in id order, a synchronised `mq`
 * lands every drive on time (trapezoid and S-curve), and the e-stop, stall,
 * overspeed and corrupt-store sequences work end to end. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "sim_unity.h"
#include "unity.h"

#include "sim_bus.h"

/* The bus under test and what its drives answered to the last line; setUp()
 * gives every test three fresh drives (ids 1, 2, 3) at 1 kHz and no replies. */
static daran_sim_bus_t bus;
static char out[4096];
static size_t out_len;
static uint32_t order[DARAN_SIM_MAX_DRIVES];
static uint32_t order_len;

void setUp(void)
{
    memset(&bus, 0, sizeof bus);
    memset(out, 0, sizeof out);
    out_len = 0u;
    memset(order, 0, sizeof order);
    order_len = 0u;
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_bus_init(&bus, 3u, 1000u));
}

void tearDown(void)
{
}

static void sink(void *ctx, uint32_t id, const char *bytes, size_t len)
{
    (void)ctx;
    if (order_len < DARAN_SIM_MAX_DRIVES) {
        order[order_len++] = id;
    }
    if (len < sizeof out - out_len) {
        memcpy(out + out_len, bytes, len);
        out_len += len;
    }
    out[out_len] = '\0';
}

/* Send one line; returns how many drives answered, replies in out. */
static uint32_t say(const char *line)
{
    out_len = 0u;
    out[0] = '\0';
    order_len = 0u;
    daran_sim_bus_send(&bus, line, strlen(line));
    daran_sim_bus_send(&bus, "\n", 1u);
    return daran_sim_bus_collect(&bus, sink, NULL);
}

static void run(double seconds)
{
    long n = lround(seconds * (double)bus.tick_hz);
    long k;
    for (k = 0; k < n; k++) {
        daran_sim_bus_tick(&bus);
    }
}

static daran_sim_model_t *model(uint32_t index)
{
    return &bus.node[index].sim.model;
}

static void test_bus_init_refuses_bad_sizes(void)
{
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_BAD_ARGUMENT, daran_sim_bus_init(&bus, 0u, 1000u));
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_BAD_ARGUMENT,
                            daran_sim_bus_init(&bus, DARAN_SIM_MAX_DRIVES + 1u, 1000u));
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_BAD_ARGUMENT, daran_sim_bus_init(&bus, 2u, 0u));
}

static void test_broadcast_read_is_answered_by_every_drive_in_id_order(void)
{
    TEST_ASSERT_EQUAL_INT64(3u, say("r axis0.config.can_node_id "));
    TEST_ASSERT_EQUAL_STRING("1\r\n2\r\n3\r\n", out);
    /* drive 1 becomes id 9: it now answers last */
    TEST_ASSERT_EQUAL_INT64(0u, say("w axis1.config.can_node_id 9"));
    TEST_ASSERT_EQUAL_INT64(3u, say("r axis0.config.can_node_id"));
    TEST_ASSERT_EQUAL_STRING("2\r\n3\r\n9\r\n", out);
    TEST_ASSERT_EQUAL_INT64(2u, order[0]);
    TEST_ASSERT_EQUAL_INT64(9u, order[2]);
    /* addressed lines: one drive answers */
    TEST_ASSERT_EQUAL_INT64(1u, say("f 9"));
    TEST_ASSERT_EQUAL_STRING("0 0\r\n", out);
    TEST_ASSERT_EQUAL_INT64(0u, say("f 1"));
}

/* ms 1 30 2 30 / ms 2 -60 2 30 / ms 3 90 2 30 / mq 0 0: A = 180 deg/s^2,
 * T = 2 s (the longest, 90 deg, needs 2 sqrt(90/180) = 1.41 s). Every drive
 * finishes at tick 2000, exactly on its target. */
static void test_mq_lands_three_drives_on_time_together(void)
{
    long done_at[3] = {-1, -1, -1};
    static const float target[3] = {30.0f, -60.0f, 90.0f};
    long k;
    int i;
    TEST_ASSERT_EQUAL_INT64(0u, say("ms 1 30 2 30"));
    TEST_ASSERT_EQUAL_INT64(0u, say("ms 2 -60 2 30"));
    TEST_ASSERT_EQUAL_INT64(0u, say("ms 3 90 2 30"));
    TEST_ASSERT_EQUAL_INT64(0u, say("mq 0 0"));
    for (i = 0; i < 3; i++) {
        TEST_ASSERT_FALSE(model((uint32_t)i)->trajectory_done);
        TEST_ASSERT_TRUE(model((uint32_t)i)->input_pos == target[i]);
    }
    for (k = 1; k <= 2500; k++) {
        daran_sim_bus_tick(&bus);
        for (i = 0; i < 3; i++) {
            if (done_at[i] < 0 && model((uint32_t)i)->trajectory_done) {
                done_at[i] = k;
            }
        }
    }
    NOTE("mq arrival ticks: %ld %ld %ld (duration 2000)", done_at[0], done_at[1],
         done_at[2]);
    for (i = 0; i < 3; i++) {
        TEST_ASSERT_EQUAL_INT64(2000, done_at[i]);
        TEST_ASSERT_TRUE(model((uint32_t)i)->pos_sp == target[i]);
        TEST_ASSERT_FLOAT_WITHIN(0.05f, target[i], daran_sim_model_pos_deg(model((uint32_t)i)));
    }
    /* relative: +10 on each, from the setpoints */
    TEST_ASSERT_EQUAL_INT64(0u, say("ms 0 10 1 60"));
    TEST_ASSERT_EQUAL_INT64(0u, say("mq 0 1"));
    run(1.001);
    for (i = 0; i < 3; i++) {
        TEST_ASSERT_TRUE(model((uint32_t)i)->pos_sp == target[i] + 10.0f);
    }
}

/* The vendor's minimum duration 2 sqrt(D/A) sent with 17 digits. */
static void test_mq_at_the_minimum_duration_runs_the_exact_triangle(void)
{
    long k;
    TEST_ASSERT_EQUAL_INT64(0u, say("ms 1 30 1.4142135623730951 10"));
    TEST_ASSERT_EQUAL_INT64(0u, say("mq 0 1"));
    TEST_ASSERT_EQUAL_STRING("", out);
    for (k = 0; k < 1500 && !model(0)->trajectory_done; k++) {
        daran_sim_bus_tick(&bus);
    }
    TEST_ASSERT_TRUE(k >= 1413 && k <= 1415);
    TEST_ASSERT_TRUE(model(0)->pos_sp == 30.0f);
}

static void test_estop_then_clear_then_closed_loop_lets_the_drive_move_again(void)
{
    TEST_ASSERT_EQUAL_INT64(0u, say("q 1 20"));
    run(0.2);
    TEST_ASSERT_EQUAL_INT64(0u, say("st 1"));
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_IDLE, model(0)->state);
    TEST_ASSERT_EQUAL_INT64(1u, say("e 1"));
    TEST_ASSERT_EQUAL_STRING("axis: 16384\r\nmotor: 0\r\nencoder: 0\r\ncontroller: 0\r\n"
                             "fet_thermistor: 0\r\nmotor_thermistor: 0\r\ncan: 0\r\n", out);
    TEST_ASSERT_EQUAL_INT64(1u, say("q 1 10"));
    TEST_ASSERT_EQUAL_STRING("error: estop active\r\n", out);
    TEST_ASSERT_EQUAL_INT64(1u, say("w axis1.requested_state 8"));
    TEST_ASSERT_EQUAL_STRING("error: estop active\r\n", out);
    TEST_ASSERT_EQUAL_INT64(0u, say("sc 1"));
    TEST_ASSERT_EQUAL_INT64(1u, say("q 1 10"));
    TEST_ASSERT_EQUAL_STRING("error: motor idle\r\n", out);
    TEST_ASSERT_EQUAL_INT64(0u, say("w axis1.requested_state 8"));
    TEST_ASSERT_EQUAL_INT64(1u, say("r axis1.current_state"));
    TEST_ASSERT_EQUAL_STRING("8\r\n", out);
    TEST_ASSERT_EQUAL_INT64(0u, say("q 1 10 60 120"));
    run(2.0);
    TEST_ASSERT_FLOAT_WITHIN(0.05f, 10.0f, daran_sim_model_pos_deg(model(0)));
}

static void test_long_line_is_fed_in_chunks_and_refused_once_per_drive(void)
{
    char line[300];
    memset(line, 'x', sizeof line - 1u);
    line[sizeof line - 1u] = '\0';
    TEST_ASSERT_EQUAL_INT64(3u, say(line));
    TEST_ASSERT_EQUAL_STRING(
        "error: line too long\r\nerror: line too long\r\nerror: line too long\r\n", out);
    /* the next line is fine */
    TEST_ASSERT_EQUAL_INT64(1u, say("f 2"));
    TEST_ASSERT_EQUAL_STRING("0 0\r\n", out);
}

static void test_power_cycle_drops_the_preset_and_unsaved_settings(void)
{
    TEST_ASSERT_EQUAL_INT64(0u, say("w axis2.controller.config.pos_gain 30"));
    TEST_ASSERT_EQUAL_INT64(0u, say("ms 2 10 1 10"));
    daran_sim_bus_power_cycle(&bus, 1u);
    TEST_ASSERT_EQUAL_INT64(1u, say("mq 2 0"));
    TEST_ASSERT_EQUAL_STRING("error: no preset\r\n", out);
    TEST_ASSERT_EQUAL_INT64(1u, say("r axis2.controller.config.pos_gain"));
    TEST_ASSERT_EQUAL_STRING("20\r\n", out);
}

/* traj_mode 2 on every drive (a broadcast write), then the same timed start:
 * the core picks each cruise from the S-curve formula T = D/(6v) + 2v/a and
 * the drives' S-curve planner lands them all on tick 2000. */
static void test_s_curve_mq_lands_three_drives_on_time_together(void)
{
    long done_at[3] = {-1, -1, -1};
    static const float target[3] = {30.0f, -60.0f, 90.0f};
    long k;
    int i;
    TEST_ASSERT_EQUAL_INT64(0u, say("w axis0.trap_traj.config.traj_mode 2"));
    TEST_ASSERT_EQUAL_INT64(0u, say("ms 1 30 2 60"));
    TEST_ASSERT_EQUAL_INT64(0u, say("ms 2 -60 2 60"));
    TEST_ASSERT_EQUAL_INT64(0u, say("ms 3 90 2 60"));
    TEST_ASSERT_EQUAL_INT64(0u, say("mq 0 0"));
    for (k = 1; k <= 2500; k++) {
        daran_sim_bus_tick(&bus);
        for (i = 0; i < 3; i++) {
            if (done_at[i] < 0 && model((uint32_t)i)->trajectory_done) {
                done_at[i] = k;
            }
        }
    }
    NOTE("S-curve mq arrival ticks: %ld %ld %ld (duration 2000)", done_at[0],
         done_at[1], done_at[2]);
    for (i = 0; i < 3; i++) {
        TEST_ASSERT_TRUE(model((uint32_t)i)->trap_scurve);
        TEST_ASSERT_EQUAL_INT64(2000, done_at[i]);
        TEST_ASSERT_TRUE(model((uint32_t)i)->pos_sp == target[i]);
    }
    TEST_ASSERT_EQUAL_INT64(1u, say("r axis2.controller.trajectory_done"));
    TEST_ASSERT_EQUAL_STRING("1\r\n", out);
}

/* Spec 10.1 over the line: q with acceleration 0 is done at once. */
static void test_q_with_zero_acceleration_is_done_at_once(void)
{
    TEST_ASSERT_EQUAL_INT64(0u, say("q 1 90 30 0"));
    TEST_ASSERT_EQUAL_INT64(1u, say("r axis1.controller.trajectory_done"));
    TEST_ASSERT_EQUAL_STRING("1\r\n", out);
    TEST_ASSERT_EQUAL_INT64(1u, say("r axis1.output_shaft.trap_traj_accel_limit"));
    TEST_ASSERT_EQUAL_STRING("0\r\n", out);
    run(1.0);
    TEST_ASSERT_FLOAT_WITHIN(0.05f, 90.0f, daran_sim_model_pos_deg(model(0)));
}

/* A stall: motor.error bit 16 and axis0.error bit 6; clearing axis0.error
 * alone leaves closed loop refused while motor.error holds; clearing that
 * too lets the drive back. */
static void test_stall_registers_are_cleared_one_by_one(void)
{
    daran_sim_model_fault(model(0), DARAN_SIM_FAULT_STALL);
    run(0.001);
    TEST_ASSERT_EQUAL_INT64(1u, say("r axis1.motor.error"));
    TEST_ASSERT_EQUAL_STRING("65536\r\n", out);
    TEST_ASSERT_EQUAL_INT64(1u, say("r axis1.error"));
    TEST_ASSERT_EQUAL_STRING("64\r\n", out);
    TEST_ASSERT_EQUAL_INT64(1u, say("q 1 10"));
    TEST_ASSERT_EQUAL_STRING("error: motor fault\r\n", out);
    TEST_ASSERT_EQUAL_INT64(1u, say("w axis1.motor.error 1"));
    TEST_ASSERT_EQUAL_STRING("error: value out of range\r\n", out);
    TEST_ASSERT_EQUAL_INT64(0u, say("w axis1.error 0"));
    TEST_ASSERT_EQUAL_INT64(1u, say("r axis1.error"));
    TEST_ASSERT_EQUAL_STRING("0\r\n", out);
    TEST_ASSERT_EQUAL_INT64(1u, say("w axis1.requested_state 8"));
    TEST_ASSERT_EQUAL_STRING("error: motor fault\r\n", out);
    TEST_ASSERT_EQUAL_INT64(0u, say("w axis1.motor.error 0"));
    TEST_ASSERT_EQUAL_INT64(1u, say("r axis1.current_state"));
    TEST_ASSERT_EQUAL_STRING("1\r\n", out);
    TEST_ASSERT_EQUAL_INT64(0u, say("w axis1.requested_state 8"));
    TEST_ASSERT_EQUAL_INT64(0u, say("q 1 10"));
}

/* Overspeed with the error enabled: controller.error bit 0 and axis0.error
 * bit 9, as `e` shows them; `sc` clears every register. */
static void test_overspeed_shows_in_the_e_reply_and_sc_clears_it(void)
{
    TEST_ASSERT_EQUAL_INT64(0u, say("w axis2.controller.config.enable_overspeed_error 1"));
    daran_sim_model_fault(model(1), DARAN_SIM_FAULT_OVERSPEED);
    run(0.001);
    TEST_ASSERT_EQUAL_INT64(1u, say("e 2"));
    TEST_ASSERT_EQUAL_STRING("axis: 512\r\nmotor: 0\r\nencoder: 0\r\ncontroller: 1\r\n"
                             "fet_thermistor: 0\r\nmotor_thermistor: 0\r\ncan: 0\r\n", out);
    TEST_ASSERT_EQUAL_INT64(0u, say("sc 2"));
    TEST_ASSERT_EQUAL_INT64(1u, say("r axis2.controller.error"));
    TEST_ASSERT_EQUAL_STRING("0\r\n", out);
}

/* A corrupt store is a warning in config_warnings, not an error: the drive
 * moves, `e` shows nothing, `sc` clears it. */
static void test_corrupt_store_is_a_warning_that_sc_clears(void)
{
    TEST_ASSERT_TRUE(daran_sim_drive_corrupt_nvm(&bus.node[0].sim));
    daran_sim_bus_power_cycle(&bus, 0u);
    TEST_ASSERT_EQUAL_INT64(1u, say("r axis1.config_warnings"));
    TEST_ASSERT_EQUAL_STRING("1\r\n", out);
    TEST_ASSERT_EQUAL_INT64(1u, say("r axis1.error"));
    TEST_ASSERT_EQUAL_STRING("0\r\n", out);
    TEST_ASSERT_EQUAL_INT64(0u, say("t 1 5"));
    TEST_ASSERT_EQUAL_INT64(0u, say("sc 1"));
    TEST_ASSERT_EQUAL_INT64(1u, say("r axis1.config_warnings"));
    TEST_ASSERT_EQUAL_STRING("0\r\n", out);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_bus_init_refuses_bad_sizes);
    RUN_TEST(test_broadcast_read_is_answered_by_every_drive_in_id_order);
    RUN_TEST(test_mq_lands_three_drives_on_time_together);
    RUN_TEST(test_mq_at_the_minimum_duration_runs_the_exact_triangle);
    RUN_TEST(test_estop_then_clear_then_closed_loop_lets_the_drive_move_again);
    RUN_TEST(test_long_line_is_fed_in_chunks_and_refused_once_per_drive);
    RUN_TEST(test_power_cycle_drops_the_preset_and_unsaved_settings);
    RUN_TEST(test_s_curve_mq_lands_three_drives_on_time_together);
    RUN_TEST(test_q_with_zero_acceleration_is_done_at_once);
    RUN_TEST(test_stall_registers_are_cleared_one_by_one);
    RUN_TEST(test_overspeed_shows_in_the_e_reply_and_sc_clears_it);
    RUN_TEST(test_corrupt_store_is_a_warning_that_sc_clears);
    return UNITY_END();
}
