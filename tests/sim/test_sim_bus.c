/* The simulated bus with the protocol core in front of every drive: lines go
 * through the byte path, replies come back in id order, a synchronised `mq`
 * lands every drive on time (trapezoid and S-curve), and the e-stop, stall,
 * overspeed and corrupt-store sequences work end to end. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "sim_bus.h"

static daran_sim_bus_t bus;
static char out[4096];
static size_t out_len;
static uint32_t order[DARAN_SIM_MAX_DRIVES];
static uint32_t order_len;

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

static int setup3(void **state)
{
    (void)state;
    assert_int_equal(daran_sim_bus_init(&bus, 3u, 1000u), DARAN_OK);
    return 0;
}

static void test_bus_init_refuses_bad_sizes(void **state)
{
    (void)state;
    assert_int_equal(daran_sim_bus_init(&bus, 0u, 1000u), DARAN_ERR_BAD_ARGUMENT);
    assert_int_equal(daran_sim_bus_init(&bus, DARAN_SIM_MAX_DRIVES + 1u, 1000u),
                     DARAN_ERR_BAD_ARGUMENT);
    assert_int_equal(daran_sim_bus_init(&bus, 2u, 0u), DARAN_ERR_BAD_ARGUMENT);
}

static void test_broadcast_read_is_answered_by_every_drive_in_id_order(void **state)
{
    (void)state;
    assert_int_equal(say("r axis0.config.can_node_id "), 3u);
    assert_string_equal(out, "1\r\n2\r\n3\r\n");
    /* drive 1 becomes id 9: it now answers last */
    assert_int_equal(say("w axis1.config.can_node_id 9"), 0u);
    assert_int_equal(say("r axis0.config.can_node_id"), 3u);
    assert_string_equal(out, "2\r\n3\r\n9\r\n");
    assert_int_equal(order[0], 2u);
    assert_int_equal(order[2], 9u);
    /* addressed lines: one drive answers */
    assert_int_equal(say("f 9"), 1u);
    assert_string_equal(out, "0 0\r\n");
    assert_int_equal(say("f 1"), 0u);
}

/* ms 1 30 2 30 / ms 2 -60 2 30 / ms 3 90 2 30 / mq 0 0: A = 180 deg/s^2,
 * T = 2 s (the longest, 90 deg, needs 2 sqrt(90/180) = 1.41 s). Every drive
 * finishes at tick 2000, exactly on its target. */
static void test_mq_lands_three_drives_on_time_together(void **state)
{
    long done_at[3] = {-1, -1, -1};
    static const float target[3] = {30.0f, -60.0f, 90.0f};
    long k;
    int i;
    (void)state;
    assert_int_equal(say("ms 1 30 2 30"), 0u);
    assert_int_equal(say("ms 2 -60 2 30"), 0u);
    assert_int_equal(say("ms 3 90 2 30"), 0u);
    assert_int_equal(say("mq 0 0"), 0u);
    for (i = 0; i < 3; i++) {
        assert_false(model((uint32_t)i)->trajectory_done);
        assert_true(model((uint32_t)i)->input_pos == target[i]);
    }
    for (k = 1; k <= 2500; k++) {
        daran_sim_bus_tick(&bus);
        for (i = 0; i < 3; i++) {
            if (done_at[i] < 0 && model((uint32_t)i)->trajectory_done) {
                done_at[i] = k;
            }
        }
    }
    print_message("mq arrival ticks: %ld %ld %ld (duration 2000)\n", done_at[0], done_at[1],
                  done_at[2]);
    for (i = 0; i < 3; i++) {
        assert_int_equal(done_at[i], 2000);
        assert_true(model((uint32_t)i)->pos_sp == target[i]);
        assert_float_equal(daran_sim_model_pos_deg(model((uint32_t)i)), target[i], 0.05f);
    }
    /* relative: +10 on each, from the setpoints */
    assert_int_equal(say("ms 0 10 1 60"), 0u);
    assert_int_equal(say("mq 0 1"), 0u);
    run(1.001);
    for (i = 0; i < 3; i++) {
        assert_true(model((uint32_t)i)->pos_sp == target[i] + 10.0f);
    }
}

/* The vendor's minimum duration 2 sqrt(D/A) sent with 17 digits. */
static void test_mq_at_the_minimum_duration_runs_the_exact_triangle(void **state)
{
    long k;
    (void)state;
    assert_int_equal(say("ms 1 30 1.4142135623730951 10"), 0u);
    assert_int_equal(say("mq 0 1"), 0u);
    assert_string_equal(out, "");
    for (k = 0; k < 1500 && !model(0)->trajectory_done; k++) {
        daran_sim_bus_tick(&bus);
    }
    assert_true(k >= 1413 && k <= 1415);
    assert_true(model(0)->pos_sp == 30.0f);
}

static void test_estop_recovery_sequence(void **state)
{
    (void)state;
    assert_int_equal(say("q 1 20"), 0u);
    run(0.2);
    assert_int_equal(say("st 1"), 0u);
    assert_int_equal(model(0)->state, DARAN_STATE_IDLE);
    assert_int_equal(say("e 1"), 1u);
    assert_string_equal(out, "axis: 16384\r\nmotor: 0\r\nencoder: 0\r\ncontroller: 0\r\n"
                             "fet_thermistor: 0\r\nmotor_thermistor: 0\r\ncan: 0\r\n");
    assert_int_equal(say("q 1 10"), 1u);
    assert_string_equal(out, "error: estop active\r\n");
    assert_int_equal(say("w axis1.requested_state 8"), 1u);
    assert_string_equal(out, "error: estop active\r\n");
    assert_int_equal(say("sc 1"), 0u);
    assert_int_equal(say("q 1 10"), 1u);
    assert_string_equal(out, "error: motor idle\r\n");
    assert_int_equal(say("w axis1.requested_state 8"), 0u);
    assert_int_equal(say("r axis1.current_state"), 1u);
    assert_string_equal(out, "8\r\n");
    assert_int_equal(say("q 1 10 60 120"), 0u);
    run(2.0);
    assert_float_equal(daran_sim_model_pos_deg(model(0)), 10.0f, 0.05f);
}

static void test_long_line_is_fed_in_chunks_and_refused_once_per_drive(void **state)
{
    char line[300];
    (void)state;
    memset(line, 'x', sizeof line - 1u);
    line[sizeof line - 1u] = '\0';
    assert_int_equal(say(line), 3u);
    assert_string_equal(out, "error: line too long\r\nerror: line too long\r\nerror: line too long\r\n");
    /* the next line is fine */
    assert_int_equal(say("f 2"), 1u);
    assert_string_equal(out, "0 0\r\n");
}

static void test_power_cycle_drops_the_preset_and_unsaved_settings(void **state)
{
    (void)state;
    assert_int_equal(say("w axis2.controller.config.pos_gain 30"), 0u);
    assert_int_equal(say("ms 2 10 1 10"), 0u);
    daran_sim_bus_power_cycle(&bus, 1u);
    assert_int_equal(say("mq 2 0"), 1u);
    assert_string_equal(out, "error: no preset\r\n");
    assert_int_equal(say("r axis2.controller.config.pos_gain"), 1u);
    assert_string_equal(out, "20\r\n");
}

/* traj_mode 2 on every drive (a broadcast write), then the same timed start:
 * the core picks each cruise from the S-curve formula T = D/(6v) + 2v/a and
 * the drives' S-curve planner lands them all on tick 2000. */
static void test_s_curve_mq_lands_three_drives_on_time_together(void **state)
{
    long done_at[3] = {-1, -1, -1};
    static const float target[3] = {30.0f, -60.0f, 90.0f};
    long k;
    int i;
    (void)state;
    assert_int_equal(say("w axis0.trap_traj.config.traj_mode 2"), 0u);
    assert_int_equal(say("ms 1 30 2 60"), 0u);
    assert_int_equal(say("ms 2 -60 2 60"), 0u);
    assert_int_equal(say("ms 3 90 2 60"), 0u);
    assert_int_equal(say("mq 0 0"), 0u);
    for (k = 1; k <= 2500; k++) {
        daran_sim_bus_tick(&bus);
        for (i = 0; i < 3; i++) {
            if (done_at[i] < 0 && model((uint32_t)i)->trajectory_done) {
                done_at[i] = k;
            }
        }
    }
    print_message("S-curve mq arrival ticks: %ld %ld %ld (duration 2000)\n", done_at[0],
                  done_at[1], done_at[2]);
    for (i = 0; i < 3; i++) {
        assert_true(model((uint32_t)i)->trap_scurve);
        assert_int_equal(done_at[i], 2000);
        assert_true(model((uint32_t)i)->pos_sp == target[i]);
    }
    assert_int_equal(say("r axis2.controller.trajectory_done"), 1u);
    assert_string_equal(out, "1\r\n");
}

/* Spec 10.1 over the line: q with acceleration 0 is done at once. */
static void test_q_with_zero_acceleration_is_done_at_once(void **state)
{
    (void)state;
    assert_int_equal(say("q 1 90 30 0"), 0u);
    assert_int_equal(say("r axis1.controller.trajectory_done"), 1u);
    assert_string_equal(out, "1\r\n");
    assert_int_equal(say("r axis1.output_shaft.trap_traj_accel_limit"), 1u);
    assert_string_equal(out, "0\r\n");
    run(1.0);
    assert_float_equal(daran_sim_model_pos_deg(model(0)), 90.0f, 0.05f);
}

/* A stall: motor.error bit 16 and axis0.error bit 6; clearing axis0.error
 * alone leaves closed loop refused while motor.error holds; clearing that
 * too lets the drive back. */
static void test_stall_registers_are_cleared_one_by_one(void **state)
{
    (void)state;
    daran_sim_model_fault(model(0), DARAN_SIM_FAULT_STALL);
    run(0.001);
    assert_int_equal(say("r axis1.motor.error"), 1u);
    assert_string_equal(out, "65536\r\n");
    assert_int_equal(say("r axis1.error"), 1u);
    assert_string_equal(out, "64\r\n");
    assert_int_equal(say("q 1 10"), 1u);
    assert_string_equal(out, "error: motor fault\r\n");
    assert_int_equal(say("w axis1.motor.error 1"), 1u);
    assert_string_equal(out, "error: value out of range\r\n");
    assert_int_equal(say("w axis1.error 0"), 0u);
    assert_int_equal(say("r axis1.error"), 1u);
    assert_string_equal(out, "0\r\n");
    assert_int_equal(say("w axis1.requested_state 8"), 1u);
    assert_string_equal(out, "error: motor fault\r\n");
    assert_int_equal(say("w axis1.motor.error 0"), 0u);
    assert_int_equal(say("r axis1.current_state"), 1u);
    assert_string_equal(out, "1\r\n");
    assert_int_equal(say("w axis1.requested_state 8"), 0u);
    assert_int_equal(say("q 1 10"), 0u);
}

/* Overspeed with the error enabled: controller.error bit 0 and axis0.error
 * bit 9, as `e` shows them; `sc` clears every register. */
static void test_overspeed_shows_in_the_e_reply_and_sc_clears_it(void **state)
{
    (void)state;
    assert_int_equal(say("w axis2.controller.config.enable_overspeed_error 1"), 0u);
    daran_sim_model_fault(model(1), DARAN_SIM_FAULT_OVERSPEED);
    run(0.001);
    assert_int_equal(say("e 2"), 1u);
    assert_string_equal(out, "axis: 512\r\nmotor: 0\r\nencoder: 0\r\ncontroller: 1\r\n"
                             "fet_thermistor: 0\r\nmotor_thermistor: 0\r\ncan: 0\r\n");
    assert_int_equal(say("sc 2"), 0u);
    assert_int_equal(say("r axis2.controller.error"), 1u);
    assert_string_equal(out, "0\r\n");
}

/* A corrupt store is a warning in config_warnings, not an error: the drive
 * moves, `e` shows nothing, `sc` clears it. */
static void test_corrupt_store_is_a_warning_that_sc_clears(void **state)
{
    (void)state;
    assert_true(daran_sim_drive_corrupt_nvm(&bus.node[0].sim));
    daran_sim_bus_power_cycle(&bus, 0u);
    assert_int_equal(say("r axis1.config_warnings"), 1u);
    assert_string_equal(out, "1\r\n");
    assert_int_equal(say("r axis1.error"), 1u);
    assert_string_equal(out, "0\r\n");
    assert_int_equal(say("t 1 5"), 0u);
    assert_int_equal(say("sc 1"), 0u);
    assert_int_equal(say("r axis1.config_warnings"), 1u);
    assert_string_equal(out, "0\r\n");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bus_init_refuses_bad_sizes),
        cmocka_unit_test_setup(test_broadcast_read_is_answered_by_every_drive_in_id_order, setup3),
        cmocka_unit_test_setup(test_mq_lands_three_drives_on_time_together, setup3),
        cmocka_unit_test_setup(test_mq_at_the_minimum_duration_runs_the_exact_triangle, setup3),
        cmocka_unit_test_setup(test_estop_recovery_sequence, setup3),
        cmocka_unit_test_setup(test_long_line_is_fed_in_chunks_and_refused_once_per_drive, setup3),
        cmocka_unit_test_setup(test_power_cycle_drops_the_preset_and_unsaved_settings, setup3),
        cmocka_unit_test_setup(test_s_curve_mq_lands_three_drives_on_time_together, setup3),
        cmocka_unit_test_setup(test_q_with_zero_acceleration_is_done_at_once, setup3),
        cmocka_unit_test_setup(test_stall_registers_are_cleared_one_by_one, setup3),
        cmocka_unit_test_setup(test_overspeed_shows_in_the_e_reply_and_sc_clears_it, setup3),
        cmocka_unit_test_setup(test_corrupt_store_is_a_warning_that_sc_clears, setup3),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
