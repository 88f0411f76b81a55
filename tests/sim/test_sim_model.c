/* Physics of the simulated drive, checked against numbers worked out by
 * hand: step response, trapezoid and triangle, ramps, impedance law, input
 * filter, limits, set-zero, states and faults. The model is driven directly
 * (no protocol core) at 1 kHz. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "sim_model.h"

static daran_sim_model_t model;

static void run(daran_sim_model_t *m, double seconds)
{
    long n = lround(seconds * (double)m->tick_hz);
    long k;
    for (k = 0; k < n; k++) {
        daran_sim_model_tick(m);
    }
}

static void start(daran_move_kind_t kind, float pos, float vel, float torque, float rate,
                  uint8_t given)
{
    daran_move_t mv = {kind, given, pos, vel, torque, rate, 0.0f, 0.0f};
    assert_int_equal(daran_sim_model_move(&model, &mv), DARAN_OK);
}

static void set_f32(daran_prop_t prop, float v)
{
    daran_value_t value;
    value.u64 = 0u;
    value.f32 = v;
    assert_int_equal(daran_sim_model_set(&model, prop, value), DARAN_OK);
}

static void set_u32(daran_prop_t prop, uint32_t v)
{
    daran_value_t value;
    value.u64 = 0u;
    value.u32 = v;
    assert_int_equal(daran_sim_model_set(&model, prop, value), DARAN_OK);
}

static float pos(void)
{
    return daran_sim_model_pos_deg(&model);
}

static int setup(void **state)
{
    (void)state;
    daran_sim_model_init(&model, 1000u);
    return 0;
}

static void test_power_up_is_closed_loop_at_rest(void **state)
{
    (void)state;
    assert_int_equal(model.state, DARAN_STATE_CLOSED_LOOP);
    assert_int_equal(model.error, 0u);
    run(&model, 0.5);
    assert_true(pos() == 0.0f);
    assert_true(model.vbus_v == 24.0f);
}

/* Spec: a 10 deg step settles within 2 % (0.2 deg) in under 0.3 s with under
 * 5 % (0.5 deg) overshoot at zero load inertia. */
static void test_ten_degree_step_settles_in_under_0_3_s_without_overshoot(void **state)
{
    float peak = 0.0f;
    long last_outside = 0;
    long k;
    (void)state;
    start(DARAN_MOVE_PASSTHROUGH, 10.0f, 0.0f, 0.0f, 0.0f, 0u);
    for (k = 1; k <= 1000; k++) {
        daran_sim_model_tick(&model);
        if (pos() > peak) {
            peak = pos();
        }
        if (fabsf(pos() - 10.0f) > 0.2f) {
            last_outside = k;
        }
    }
    print_message("10 deg step: settled (2%%) after %ld ms, peak %.4f deg\n", last_outside,
                  (double)peak);
    assert_true(last_outside < 300);
    assert_true(peak < 10.5f);
    assert_true(fabsf(pos() - 10.0f) < 0.01f);
}

/* q 1 180 30 60: V = 30 r/min = 180 deg/s, A = 60 (r/min)/s = 360 deg/s^2.
 * ta = V/A = 0.5 s covering 45 deg; cruise 90 deg takes 0.5 s; T = 1.5 s.
 *   t = 0.25: 0.5*360*0.25^2 = 11.25      t = 0.75: 45 + 180*0.25 = 90
 *   t = 1.25: 180 - 0.5*360*0.25^2 = 168.75 */
static void test_q_setpoint_follows_the_analytic_trapezoid_and_ends_on_target(void **state)
{
    (void)state;
    start(DARAN_MOVE_TRAPEZOID, 180.0f, 30.0f, 0.0f, 60.0f, DARAN_GIVEN_VEL | DARAN_GIVEN_RATE);
    assert_false(model.trajectory_done);
    run(&model, 0.25);
    assert_float_equal(model.pos_sp, 11.25f, 0.5f);
    assert_float_equal(model.vel_sp, 15.0f, 0.1f); /* 90 deg/s */
    run(&model, 0.5);
    assert_float_equal(model.pos_sp, 90.0f, 0.5f);
    assert_float_equal(model.vel_sp, 30.0f, 0.01f);
    run(&model, 0.5);
    assert_float_equal(model.pos_sp, 168.75f, 0.5f);
    assert_float_equal(pos(), 168.75f, 1.0f);
    run(&model, 0.249);
    assert_false(model.trajectory_done);
    run(&model, 0.001);
    assert_true(model.trajectory_done);
    assert_true(model.pos_sp == 180.0f);
    run(&model, 0.5);
    assert_float_equal(pos(), 180.0f, 0.05f);
}

/* q 1 45 30 60: 45 deg < V^2/A = 90 deg, so a triangle: ta = sqrt(45/360) =
 * 0.35355 s, peak 127.28 deg/s (21.21 r/min), T = 0.70711 s.
 *   t = 0.2: 0.5*360*0.04 = 7.2
 *   t = 0.5: 45 - 0.5*360*(0.70711-0.5)^2 = 45 - 7.7213 = 37.279 */
static void test_q_too_short_for_its_cruise_velocity_runs_a_triangle(void **state)
{
    (void)state;
    start(DARAN_MOVE_TRAPEZOID, 45.0f, 30.0f, 0.0f, 60.0f, DARAN_GIVEN_VEL | DARAN_GIVEN_RATE);
    run(&model, 0.2);
    assert_float_equal(model.pos_sp, 7.2f, 0.5f);
    run(&model, 0.15);
    assert_float_equal(model.vel_sp, 21.0f, 0.3f);
    run(&model, 0.15);
    assert_float_equal(model.pos_sp, 37.279f, 0.5f);
    run(&model, 0.206);
    assert_false(model.trajectory_done);
    run(&model, 0.002);
    assert_true(model.trajectory_done);
    assert_true(model.pos_sp == 45.0f);
}

/* D20: without vel/acc, q uses the drive's settings, output_shaft.
 * trap_traj_vel_limit (600 r/min) and trap_traj_accel_limit = decel_limit
 * (60 (r/min)/s): 90 deg is a triangle of 2*sqrt(90/360) = 1 s. */
static void test_q_without_vel_and_acc_uses_the_drive_settings(void **state)
{
    (void)state;
    start(DARAN_MOVE_TRAPEZOID, 90.0f, 0.0f, 0.0f, 0.0f, 0u);
    run(&model, 0.999);
    assert_false(model.trajectory_done);
    run(&model, 0.001);
    assert_true(model.trajectory_done);
    /* a given acc becomes the new setting: 240 (r/min)/s halves the time */
    start(DARAN_MOVE_TRAPEZOID, 0.0f, 0.0f, 0.0f, 240.0f, DARAN_GIVEN_RATE);
    run(&model, 0.5);
    assert_true(model.trajectory_done);
    assert_true(model.pos_sp == 0.0f);
}

/* v 1 60 120 2: ramp at 120 (r/min)/s: 30 r/min after 0.25 s, 60 at 0.5 s. */
static void test_v_ramp_has_the_commanded_slope(void **state)
{
    (void)state;
    start(DARAN_MOVE_VELOCITY_RAMP, 0.0f, 60.0f, 0.0f, 120.0f, 0u);
    assert_true(model.cfg[DARAN_PROP_VEL_RAMP_RATE].f32 == 120.0f);
    run(&model, 0.25);
    assert_float_equal(model.vel_sp, 30.0f, 0.01f);
    assert_float_equal(model.vel_rpm, 30.0f, 1.5f);
    run(&model, 0.25);
    assert_float_equal(model.vel_sp, 60.0f, 0.01f);
    run(&model, 0.5);
    assert_float_equal(model.vel_rpm, 60.0f, 0.5f);
    /* v mode 1 sets the velocity at once */
    start(DARAN_MOVE_VELOCITY, 0.0f, -20.0f, 0.0f, 0.0f, 0u);
    run(&model, 0.001);
    assert_true(model.vel_sp == -20.0f);
}

/* c 1 0.5 1 6 on a heavy load (1 Nm/(r/s^2)): ramp at 1 Nm/s, 0.25 Nm after
 * 0.25 s, 0.5 at 0.5 s, then held. */
static void test_c_ramp_has_the_commanded_slope(void **state)
{
    (void)state;
    set_f32(DARAN_PROP_LOAD_INERTIA, 1.0f);
    start(DARAN_MOVE_TORQUE_RAMP, 0.0f, 0.0f, 0.5f, 1.0f, 0u);
    run(&model, 0.25);
    assert_float_equal(model.torque_cmd, 0.25f, 0.002f);
    run(&model, 0.25);
    assert_float_equal(model.torque_cmd, 0.5f, 0.002f);
    run(&model, 0.25);
    assert_float_equal(model.torque_cmd, 0.5f, 1e-6f);
    /* c mode 1: at once */
    start(DARAN_MOVE_TORQUE, 0.0f, 0.0f, -0.3f, 0.0f, 0u);
    run(&model, 0.001);
    assert_float_equal(model.torque_cmd, -0.3f, 1e-6f);
}

/* d 1 10 5 0.1 0.01 0.002 from rest at 0: 0.01*10 + 0.1 + 0.002*5 = 0.21 Nm;
 * then every tick torque = kp(pdes-pos) + tff + kd(vdes-vel). */
static void test_d_torque_is_the_impedance_law_every_tick(void **state)
{
    daran_move_t mv = {DARAN_MOVE_IMPEDANCE, 0u, 10.0f, 5.0f, 0.1f, 0.0f, 0.01f, 0.002f};
    int k;
    (void)state;
    assert_int_equal(daran_sim_model_move(&model, &mv), DARAN_OK);
    daran_sim_model_tick(&model);
    assert_float_equal(model.torque_cmd, 0.21f, 1e-6f);
    for (k = 0; k < 300; k++) {
        float p = pos();
        float v = model.vel_rpm;
        float expect = 0.01f * (10.0f - p) + 0.1f + 0.002f * (5.0f - v);
        daran_sim_model_tick(&model);
        assert_float_equal(model.torque_cmd, expect, 1e-5f);
    }
    assert_true(model.input_pos == 10.0f && model.input_vel == 5.0f && model.input_torque == 0.1f);
}

/* A host streams `t` at 100 Hz along 30 sin(pi t); with bandwidth 100 the
 * setpoint moves smoothly (never more than the path's 94 deg/s allows, plus
 * margin) and the shaft stays within 3 deg of the stream. */
static void test_t_stream_is_followed_smoothly(void **state)
{
    float prev_sp = 0.0f;
    float worst_err = 0.0f;
    float worst_step = 0.0f;
    int k;
    (void)state;
    for (k = 0; k < 3000; k++) {
        float t = (float)k / 1000.0f;
        if (k % 10 == 0) {
            start(DARAN_MOVE_FILTERED_POSITION, 30.0f * sinf(3.14159265f * t), 0.0f, 0.0f,
                  100.0f, DARAN_GIVEN_RATE);
        }
        daran_sim_model_tick(&model);
        if (k > 0 && fabsf(model.pos_sp - prev_sp) > worst_step) {
            worst_step = fabsf(model.pos_sp - prev_sp);
        }
        prev_sp = model.pos_sp;
        if (k >= 1000 && fabsf(pos() - 30.0f * sinf(3.14159265f * t)) > worst_err) {
            worst_err = fabsf(pos() - 30.0f * sinf(3.14159265f * t));
        }
    }
    print_message("t stream: worst tracking error %.3f deg, largest setpoint step %.4f deg\n",
                  (double)worst_err, (double)worst_step);
    assert_true(model.cfg[DARAN_PROP_INPUT_FILTER_BANDWIDTH].f32 == 100.0f);
    assert_true(worst_err < 3.0f);
    assert_true(worst_step < 0.15f);
}

/* A single `t` step: critically damped, so the setpoint never passes the
 * target. */
static void test_t_step_does_not_overshoot(void **state)
{
    float peak = 0.0f;
    int k;
    (void)state;
    start(DARAN_MOVE_FILTERED_POSITION, 20.0f, 0.0f, 0.0f, 25.0f, DARAN_GIVEN_RATE);
    for (k = 0; k < 1000; k++) {
        daran_sim_model_tick(&model);
        if (model.pos_sp > peak) {
            peak = model.pos_sp;
        }
    }
    assert_true(peak <= 20.0f);
    assert_float_equal(model.pos_sp, 20.0f, 0.001f);
}

static void test_torque_is_clamped_by_the_lowest_limit(void **state)
{
    int k;
    (void)state;
    set_f32(DARAN_PROP_SHAFT_TORQUE_LIM, 0.05f);
    start(DARAN_MOVE_PASSTHROUGH, 90.0f, 0.0f, 0.0f, 0.0f, 0u);
    daran_sim_model_tick(&model);
    assert_float_equal(model.torque_cmd, 0.05f, 1e-6f);
    /* current_lim 0.3 A x torque_constant 0.1 Nm/A = 0.03 Nm is lower */
    set_f32(DARAN_PROP_CURRENT_LIM, 0.3f);
    for (k = 0; k < 100; k++) {
        daran_sim_model_tick(&model);
        assert_true(fabsf(model.torque_cmd) <= 0.03f + 1e-6f);
    }
    set_f32(DARAN_PROP_CURRENT_LIM, 25.0f);
    set_f32(DARAN_PROP_MOTOR_TORQUE_LIM, 0.02f);
    daran_sim_model_tick(&model);
    assert_true(fabsf(model.torque_cmd) <= 0.02f + 1e-6f);
}

/* output_shaft.vel_limit 60 r/min, then controller vel_limit 0.5 turn/s =
 * 30 r/min: the lower applies. */
static void test_velocity_is_clamped_by_the_lowest_limit(void **state)
{
    float top = 0.0f;
    int k;
    (void)state;
    set_f32(DARAN_PROP_SHAFT_VEL_LIMIT, 60.0f);
    start(DARAN_MOVE_PASSTHROUGH, 720.0f, 0.0f, 0.0f, 0.0f, 0u);
    for (k = 0; k < 1000; k++) {
        daran_sim_model_tick(&model);
        top = model.vel_rpm > top ? model.vel_rpm : top;
    }
    assert_true(top < 61.0f && top > 59.0f);
    set_f32(DARAN_PROP_CONTROLLER_VEL_LIMIT, 0.5f);
    start(DARAN_MOVE_VELOCITY, 0.0f, 100.0f, 0.0f, 0.0f, 0u);
    run(&model, 0.5);
    assert_float_equal(model.vel_rpm, 30.0f, 0.5f);
    assert_true(model.vel_sp == 30.0f);
}

static void test_software_limits_hold_in_every_mode(void **state)
{
    (void)state;
    set_f32(DARAN_PROP_CIRCULAR_SETPOINT_MIN, -10.0f);
    set_f32(DARAN_PROP_CIRCULAR_SETPOINT_MAX, 20.0f);
    set_u32(DARAN_PROP_ENABLE_CIRCULAR_SETPOINT_LIMIT, 1u);
    start(DARAN_MOVE_TRAPEZOID, 90.0f, 60.0f, 0.0f, 600.0f, DARAN_GIVEN_VEL | DARAN_GIVEN_RATE);
    run(&model, 1.0);
    assert_true(model.trajectory_done);
    assert_true(model.pos_sp == 20.0f);
    assert_float_equal(pos(), 20.0f, 0.05f);
    start(DARAN_MOVE_PASSTHROUGH, -50.0f, 0.0f, 0.0f, 0.0f, 0u);
    run(&model, 1.0);
    assert_true(model.pos_sp == -10.0f);
    assert_float_equal(pos(), -10.0f, 0.05f);
    start(DARAN_MOVE_FILTERED_POSITION, 100.0f, 0.0f, 0.0f, 0.0f, 0u);
    run(&model, 2.0);
    assert_true(model.pos_sp <= 20.0f);
    /* velocity control runs into the limit and holds there */
    start(DARAN_MOVE_VELOCITY, 0.0f, -30.0f, 0.0f, 0.0f, 0u);
    run(&model, 3.0);
    assert_float_equal(pos(), -10.0f, 2.0f);
    assert_float_equal(model.vel_rpm, 0.0f, 0.1f);
    /* off: free again */
    set_u32(DARAN_PROP_ENABLE_CIRCULAR_SETPOINT_LIMIT, 0u);
    start(DARAN_MOVE_PASSTHROUGH, -50.0f, 0.0f, 0.0f, 0.0f, 0u);
    run(&model, 1.0);
    assert_float_equal(pos(), -50.0f, 0.05f);
}

static void test_set_zero_moves_nothing(void **state)
{
    float worst = 0.0f;
    int k;
    (void)state;
    start(DARAN_MOVE_PASSTHROUGH, 30.0f, 0.0f, 0.0f, 0.0f, 0u);
    run(&model, 1.0);
    daran_sim_model_set_zero(&model);
    assert_true(pos() == 0.0f);
    assert_float_equal(model.pos_sp, 0.0f, 0.01f);
    assert_float_equal(model.input_pos, 0.0f, 0.01f);
    for (k = 0; k < 500; k++) {
        daran_sim_model_tick(&model);
        worst = fabsf(pos()) > worst ? fabsf(pos()) : worst;
    }
    assert_true(worst < 0.01f);
    start(DARAN_MOVE_PASSTHROUGH, 5.0f, 0.0f, 0.0f, 0.0f, 0u);
    run(&model, 1.0);
    assert_float_equal(pos(), 5.0f, 0.01f);
    assert_float_equal(model.raw_pos_deg, 35.0f, 0.02f);
}

static void test_estop_then_clear_then_closed_loop_moves_again(void **state)
{
    daran_move_t mv = {DARAN_MOVE_PASSTHROUGH, 0u, 10.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    daran_value_t v;
    (void)state;
    daran_sim_model_trip(&model, DARAN_FLAG_ESTOP);
    assert_int_equal(model.state, DARAN_STATE_IDLE);
    assert_int_equal(daran_sim_model_move(&model, &mv), DARAN_ERR_ESTOP_ACTIVE);
    assert_int_equal(daran_sim_model_closed_loop(&model), DARAN_ERR_ESTOP_ACTIVE);
    run(&model, 0.1);
    assert_true(model.torque_cmd == 0.0f);
    daran_sim_model_clear_errors(&model);
    assert_int_equal(model.state, DARAN_STATE_IDLE);
    assert_int_equal(daran_sim_model_move(&model, &mv), DARAN_ERR_MOTOR_IDLE);
    v.u64 = 0u;
    v.u32 = DARAN_STATE_CLOSED_LOOP;
    assert_int_equal(daran_sim_model_set(&model, DARAN_PROP_REQUESTED_STATE, v), DARAN_OK);
    assert_int_equal(daran_sim_model_move(&model, &mv), DARAN_OK);
    run(&model, 1.0);
    assert_float_equal(pos(), 10.0f, 0.01f);
}

static void test_watchdog_trips_when_not_fed_in_time(void **state)
{
    (void)state;
    set_f32(DARAN_PROP_WATCHDOG_TIMEOUT, 0.2f);
    set_u32(DARAN_PROP_ENABLE_WATCHDOG, 1u);
    run(&model, 0.15);
    daran_sim_model_feed_watchdog(&model);
    run(&model, 0.15);
    assert_int_equal(model.state, DARAN_STATE_CLOSED_LOOP);
    run(&model, 0.06);
    assert_int_equal(model.state, DARAN_STATE_IDLE);
    assert_int_equal(model.error, DARAN_FLAG_WATCHDOG);
    assert_int_equal(daran_sim_model_closed_loop(&model), DARAN_ERR_MOTOR_FAULT);
}

static void test_overtemp_fault_trips_enabled_thermistors_at_the_next_tick(void **state)
{
    (void)state;
    set_u32(DARAN_PROP_MOTOR_THERMISTOR_ENABLED, 0u);
    daran_sim_model_fault(&model, DARAN_SIM_FAULT_OVERTEMP);
    assert_float_equal(model.fet_temp_c, 105.0f, 1e-3f);
    assert_float_equal(model.motor_temp_c, 125.0f, 1e-3f);
    daran_sim_model_tick(&model);
    assert_int_equal(model.state, DARAN_STATE_IDLE);
    assert_int_equal(model.error, DARAN_FLAG_OVERTEMP);
    assert_int_equal(model.fet_thermistor_error, DARAN_THERMISTOR_ERROR_OVERTEMP);
    assert_int_equal(model.motor_thermistor_error, 0u);
    /* FET cools with tau 5 s: 80 e^(-t/5) < 75 after 0.32 s */
    daran_sim_model_clear_errors(&model);
    run(&model, 0.1);
    assert_int_equal(model.error, DARAN_FLAG_OVERTEMP);
    run(&model, 0.4);
    daran_sim_model_clear_errors(&model);
    run(&model, 0.01);
    assert_int_equal(model.error, 0u);
    assert_int_equal(daran_sim_model_closed_loop(&model), DARAN_OK);
}

/* 2 Nm stall torque = 20 A. Motor: steady 25 + 0.3*400 = 145 degC, tau 30 s:
 * passes 120 after 30 ln(120/25) = 47.06 s when nothing derates. */
static void test_sustained_current_heats_the_motor_until_it_trips(void **state)
{
    double t = 0.0;
    (void)state;
    set_f32(DARAN_PROP_LOAD_INERTIA, 1.0e6f); /* shaft blocked */
    set_f32(DARAN_PROP_MOTOR_TEMP_LIMIT_LOWER, 120.0f); /* no derating */
    set_u32(DARAN_PROP_ENABLE_CURRENT_MODE_VEL_LIMIT, 0u);
    start(DARAN_MOVE_TORQUE, 0.0f, 0.0f, 2.0f, 0.0f, 0u);
    run(&model, 1.0);
    assert_float_equal(model.torque_nm / 0.1f, 20.0f, 0.01f);
    while (model.state == DARAN_STATE_CLOSED_LOOP && t < 100.0) {
        run(&model, 0.01);
        t += 0.01;
    }
    print_message("motor over-temperature trip after %.2f s at 20 A\n", t + 1.0);
    assert_true(t + 1.0 > 46.5 && t + 1.0 < 47.5);
    assert_int_equal(model.error, DARAN_FLAG_OVERTEMP);
    assert_int_equal(model.motor_thermistor_error, DARAN_THERMISTOR_ERROR_OVERTEMP);
    assert_int_equal(model.motor_error, 0u);
}

/* With derating (torque limit falling to 0 from 90 to 120 degC) the same
 * demand settles below the trip point. */
static void test_derating_keeps_the_motor_below_its_trip_temperature(void **state)
{
    (void)state;
    set_f32(DARAN_PROP_LOAD_INERTIA, 1.0e6f);
    set_u32(DARAN_PROP_ENABLE_CURRENT_MODE_VEL_LIMIT, 0u);
    start(DARAN_MOVE_TORQUE, 0.0f, 0.0f, 2.0f, 0.0f, 0u);
    run(&model, 300.0);
    assert_int_equal(model.state, DARAN_STATE_CLOSED_LOOP);
    assert_true(model.motor_temp_c > 90.0f && model.motor_temp_c < 120.0f);
    assert_true(daran_sim_model_torque_limit(&model) < 2.0f);
}

/* 0.5 Nm on a blocked shaft: Iq = 5 A, copper loss 25 * 0.3
 * = 7.5 W, ibus = 7.5 / 24 = 0.3125 A, vbus = 24 - 0.02 * 0.3125. */
static void test_electrical_quantities_follow_the_torque(void **state)
{
    daran_value_t v;
    (void)state;
    set_f32(DARAN_PROP_LOAD_INERTIA, 1.0e6f);
    start(DARAN_MOVE_TORQUE, 0.0f, 0.0f, 0.5f, 0.0f, 0u);
    run(&model, 0.1);
    assert_int_equal(daran_sim_model_get(&model, DARAN_PROP_IQ_MEASURED, &v), DARAN_OK);
    assert_float_equal(v.f32, 5.0f, 1e-3f);
    assert_float_equal(model.ibus_a, 0.3125f, 1e-3f);
    assert_float_equal(model.vbus_v, 23.99375f, 1e-3f);
}

static void test_undervoltage_sag_trips_and_recovers(void **state)
{
    (void)state;
    daran_sim_model_fault(&model, DARAN_SIM_FAULT_UNDERVOLTAGE);
    run(&model, 0.002);
    assert_int_equal(model.state, DARAN_STATE_IDLE);
    assert_int_equal(model.error, DARAN_FLAG_UNDERVOLTAGE);
    assert_true(model.vbus_v == 6.0f); /* 2 V below the 8 V trip level */
    run(&model, 0.2);
    assert_true(model.vbus_v == 24.0f);
    daran_sim_model_clear_errors(&model);
    run(&model, 0.01);
    assert_int_equal(model.error, 0u);
    assert_int_equal(daran_sim_model_closed_loop(&model), DARAN_OK);
}

static void test_writing_setpoints_sets_the_matching_input(void **state)
{
    (void)state;
    set_f32(DARAN_PROP_POS_SETPOINT, 15.0f);
    assert_true(model.input_pos == 15.0f);
    run(&model, 1.0);
    assert_true(model.pos_sp == 15.0f);
    assert_float_equal(pos(), 15.0f, 0.01f);
    set_f32(DARAN_PROP_VEL_SETPOINT, 12.0f);
    assert_true(model.input_vel == 12.0f);
    run(&model, 0.5);
    assert_float_equal(model.vel_rpm, 12.0f, 0.1f);
    set_f32(DARAN_PROP_TORQUE_SETPOINT, 0.0f);
    assert_true(model.input_torque == 0.0f);
    assert_int_equal(model.mode, DARAN_SIM_MODE_TORQUE);
}

static void test_runs_at_8_khz_too(void **state)
{
    (void)state;
    daran_sim_model_init(&model, 8000u);
    start(DARAN_MOVE_TRAPEZOID, 180.0f, 30.0f, 0.0f, 60.0f, DARAN_GIVEN_VEL | DARAN_GIVEN_RATE);
    run(&model, 1.499875);
    assert_false(model.trajectory_done);
    run(&model, 0.000125);
    assert_true(model.trajectory_done);
    run(&model, 0.5);
    assert_float_equal(pos(), 180.0f, 0.05f);
}

/* ---- turn 2: trajectory limits as properties, zero rates, S-curve ---- */

/* The acceleration limit shapes the rising phase, the deceleration limit the
 * falling one. q 1 180 30 with accel 60 and decel 120 (r/min)/s:
 * V = 180 deg/s, a1 = 360, a2 = 720 deg/s^2; rising 0.5 s (45 deg),
 * falling 0.25 s (22.5 deg), cruise 112.5 deg in 0.625 s: T = 1.375 s.
 *   t = 0.25: 0.5*360*0.25^2 = 11.25
 *   t = 1.25: 180 - 0.5*720*0.125^2 = 174.375 */
static void test_trapezoid_rises_at_the_accel_limit_and_falls_at_the_decel_limit(void **state)
{
    (void)state;
    set_f32(DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT, 60.0f);
    set_f32(DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT, 120.0f);
    start(DARAN_MOVE_TRAPEZOID, 180.0f, 30.0f, 0.0f, 0.0f, DARAN_GIVEN_VEL);
    assert_true(model.cfg[DARAN_PROP_TRAP_TRAJ_VEL_LIMIT].f32 == 30.0f);
    run(&model, 0.25);
    assert_float_equal(model.pos_sp, 11.25f, 1e-3f);
    assert_float_equal(model.acc_sp, 360.0f, 1e-3f);
    run(&model, 1.0);
    assert_float_equal(model.pos_sp, 174.375f, 1e-3f);
    assert_float_equal(model.acc_sp, -720.0f, 1e-3f);
    run(&model, 0.124);
    assert_false(model.trajectory_done);
    run(&model, 0.001);
    assert_true(model.trajectory_done);
    assert_true(model.pos_sp == 180.0f);
    /* a move's rate sets both limits */
    start(DARAN_MOVE_TRAPEZOID, 0.0f, 0.0f, 0.0f, 240.0f, DARAN_GIVEN_RATE);
    assert_true(model.cfg[DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT].f32 == 240.0f);
    assert_true(model.cfg[DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT].f32 == 240.0f);
}

/* Spec 10.1: q with acceleration 0 steps the setpoint to the target at
 * once; only the controller's velocity and torque limits bound the shaft.
 * The same when the stored accel (or decel) limit is written 0. */
static void test_q_with_zero_acceleration_steps_the_setpoint_to_the_target(void **state)
{
    float top = 0.0f;
    int k;
    (void)state;
    set_f32(DARAN_PROP_SHAFT_VEL_LIMIT, 120.0f);
    start(DARAN_MOVE_TRAPEZOID, 90.0f, 0.0f, 0.0f, 0.0f, DARAN_GIVEN_RATE);
    assert_true(model.trajectory_done);
    daran_sim_model_tick(&model);
    assert_true(model.pos_sp == 90.0f);
    assert_true(model.vel_sp == 0.0f);
    for (k = 0; k < 1000; k++) {
        daran_sim_model_tick(&model);
        top = fabsf(model.vel_rpm) > top ? fabsf(model.vel_rpm) : top;
    }
    print_message("q with acc 0: top speed %.2f r/min under a 120 r/min limit\n", (double)top);
    assert_true(top > 110.0f && top < 125.0f);
    assert_float_equal(pos(), 90.0f, 0.05f);
    /* stored limits of 0 mean the same */
    set_f32(DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT, 60.0f);
    set_f32(DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT, 0.0f);
    start(DARAN_MOVE_TRAPEZOID, 0.0f, 0.0f, 0.0f, 0.0f, 0u);
    assert_true(model.trajectory_done);
    daran_sim_model_tick(&model);
    assert_true(model.pos_sp == 0.0f);
}

/* Spec 10.1: v ... 0 2 holds the velocity setpoint where it is, for as long
 * as nothing else is commanded; vel_ramp_rate becomes 0. */
static void test_velocity_ramp_at_rate_zero_holds_the_velocity(void **state)
{
    int k;
    (void)state;
    start(DARAN_MOVE_VELOCITY, 0.0f, 30.0f, 0.0f, 0.0f, 0u);
    run(&model, 0.5);
    start(DARAN_MOVE_VELOCITY_RAMP, 0.0f, 100.0f, 0.0f, 0.0f, 0u);
    assert_true(model.cfg[DARAN_PROP_VEL_RAMP_RATE].f32 == 0.0f);
    assert_true(model.input_vel == 100.0f);
    for (k = 0; k < 1000; k++) {
        daran_sim_model_tick(&model);
        assert_true(model.vel_sp == 30.0f);
    }
    assert_float_equal(model.vel_rpm, 30.0f, 0.1f);
    /* a rate written later starts the ramp from there */
    set_f32(DARAN_PROP_VEL_RAMP_RATE, 140.0f);
    run(&model, 0.25);
    assert_float_equal(model.vel_sp, 65.0f, 0.01f);
}

/* c ... 0 6 holds the torque command; torque_ramp_rate becomes 0. */
static void test_torque_ramp_at_rate_zero_holds_the_torque(void **state)
{
    int k;
    (void)state;
    set_f32(DARAN_PROP_LOAD_INERTIA, 1.0e6f); /* shaft blocked */
    start(DARAN_MOVE_TORQUE, 0.0f, 0.0f, 0.2f, 0.0f, 0u);
    run(&model, 0.5);
    start(DARAN_MOVE_TORQUE_RAMP, 0.0f, 0.0f, 1.0f, 0.0f, 0u);
    assert_true(model.cfg[DARAN_PROP_TORQUE_RAMP_RATE].f32 == 0.0f);
    for (k = 0; k < 1000; k++) {
        daran_sim_model_tick(&model);
        assert_float_equal(model.torque_cmd, 0.2f, 1e-6f);
    }
}

/* A filter bandwidth written 0 freezes the filtered setpoint where it is. */
static void test_filter_bandwidth_zero_holds_the_setpoint(void **state)
{
    float held;
    (void)state;
    start(DARAN_MOVE_FILTERED_POSITION, 40.0f, 0.0f, 0.0f, 10.0f, DARAN_GIVEN_RATE);
    run(&model, 0.1);
    set_f32(DARAN_PROP_INPUT_FILTER_BANDWIDTH, 0.0f);
    daran_sim_model_tick(&model);
    held = model.pos_sp;
    assert_true(held > 1.0f && held < 39.0f);
    run(&model, 1.0);
    assert_true(model.pos_sp == held);
    assert_true(model.vel_sp == 0.0f);
    assert_float_equal(pos(), held, 0.05f);
}

/* Cruise velocity (r/min) that makes a move of d deg at a (r/min)/s last
 * exactly t s: the vendor's planning formulas (protocol.md 6, 10.3). */
static double cruise_for(double d, double t, double a, int traj_mode)
{
    if (traj_mode == 2) { /* t = d/(6v) + 2v/a */
        return a * (t - sqrt(t * t - 4.0 * d / (3.0 * a))) / 4.0;
    }
    { /* in deg: t = d/V + V/A, A = 6a */
        double acc = 6.0 * a;
        return (acc * t - sqrt(acc * acc * t * t - 4.0 * acc * d)) / 2.0 / 6.0;
    }
}

/* Three drives, distances 30, -60 and 90 deg, T = 2 s: with traj_mode 1 at
 * 30 (r/min)/s the cruise of the 90 deg one is (360 - sqrt(360^2 - 4*180*90))
 * / 2 = 52.72 deg/s = 8.787 r/min; with traj_mode 2 at 60 (r/min)/s it is
 * 60 (2 - sqrt(4 - 4*90/180)) / 4 = 15 (2 - sqrt 2) = 8.787 r/min too
 * (90/(6*8.787) + 2*8.787/60 = 1.7071 + 0.2929 = 2). Every drive ends on
 * tick 2000, not one tick early, exactly on its target. */
static void test_timed_moves_of_three_distances_end_on_the_planned_tick(void **state)
{
    static daran_sim_model_t drives[3];
    static const float dist[3] = {30.0f, -60.0f, 90.0f};
    int mode;
    (void)state;
    for (mode = 1; mode <= 2; mode++) {
        double a = mode == 1 ? 30.0 : 60.0;
        int i;
        long k;
        for (i = 0; i < 3; i++) {
            daran_move_t mv = {DARAN_MOVE_TRAPEZOID, DARAN_GIVEN_VEL | DARAN_GIVEN_RATE,
                               dist[i], 0.0f, 0.0f, (float)a, 0.0f, 0.0f};
            mv.vel_rpm = (float)cruise_for(fabs((double)dist[i]), 2.0, a, mode);
            daran_sim_model_init(&drives[i], 1000u);
            drives[i].cfg[DARAN_PROP_TRAJ_MODE].u32 = (uint32_t)mode;
            assert_int_equal(daran_sim_model_move(&drives[i], &mv), DARAN_OK);
            assert_true(drives[i].trap_tc > 0.0f); /* they all cruise */
        }
        assert_float_equal(drives[2].trap_vmax / 6.0f, 8.787f, 1e-3f);
        for (k = 1; k <= 2000; k++) {
            for (i = 0; i < 3; i++) {
                daran_sim_model_tick(&drives[i]);
                assert_int_equal(drives[i].trajectory_done, k == 2000);
            }
        }
        for (i = 0; i < 3; i++) {
            assert_true(drives[i].pos_sp == dist[i]);
        }
    }
}

/* S-curve too short to reach its cruise: the S-curve triangle. 10 deg at
 * 60 (r/min)/s (A = 360 deg/s^2) with a cruise of 100 r/min: peak
 * v = sqrt(a D / 12) = sqrt(50) = 7.071 r/min (42.43 deg/s), T = 4v/a =
 * 0.4714 s: done on tick 472. */
static void test_short_s_curve_is_the_s_curve_triangle(void **state)
{
    float peak = 0.0f;
    long k;
    (void)state;
    set_u32(DARAN_PROP_TRAJ_MODE, 2u);
    start(DARAN_MOVE_TRAPEZOID, 10.0f, 100.0f, 0.0f, 60.0f, DARAN_GIVEN_VEL | DARAN_GIVEN_RATE);
    assert_float_equal(model.trap_vmax, 42.4264f, 1e-3f);
    assert_float_equal(model.trap_total, 0.471405f, 1e-5f);
    for (k = 1; k <= 472; k++) {
        daran_sim_model_tick(&model);
        peak = model.vel_sp > peak ? model.vel_sp : peak;
        assert_int_equal(model.trajectory_done, k == 472);
    }
    assert_float_equal(peak, 7.071f, 0.01f);
    assert_true(model.pos_sp == 10.0f);
}

/* S-curve q 1 270 30 60: V = 180 deg/s, A = 360 deg/s^2; each phase lasts
 * 2V/A = 1 s and covers V^2/A = 90 deg with jerk A^2/V = 720 deg/s^3; the
 * cruise 90 deg takes 0.5 s: T = 2.5 s.
 *   t = 0.5: pos = J t^3/6 = 15 deg, vel = V/2 = 15 r/min, acc = A = 360
 *   t = 1.0: pos = 90, vel = 30 r/min, acc = 0
 * Position, velocity and acceleration change by at most one tick's worth
 * of their derivative: nothing jumps, at the start, the phase changes or the
 * end. */
static void test_s_curve_is_continuous_in_position_velocity_and_acceleration(void **state)
{
    const float jerk = 720.0f;
    float prev_pos = 0.0f;
    float prev_vel = 0.0f;
    float prev_acc = 0.0f;
    float worst_jump = 0.0f;
    long k;
    (void)state;
    set_u32(DARAN_PROP_TRAJ_MODE, 2u);
    start(DARAN_MOVE_TRAPEZOID, 270.0f, 30.0f, 0.0f, 60.0f, DARAN_GIVEN_VEL | DARAN_GIVEN_RATE);
    assert_float_equal(model.trap_total, 2.5f, 1e-6f);
    for (k = 1; k <= 2600; k++) {
        float vel_deg_s;
        daran_sim_model_tick(&model);
        vel_deg_s = model.vel_sp * 6.0f;
        assert_true(fabsf(model.pos_sp - prev_pos) <= 180.0f * 0.001f + 1e-3f);
        assert_true(fabsf(vel_deg_s - prev_vel) <= 360.0f * 0.001f + 1e-3f);
        assert_true(fabsf(model.acc_sp - prev_acc) <= jerk * 0.001f + 1e-3f);
        if (fabsf(model.acc_sp - prev_acc) > worst_jump) {
            worst_jump = fabsf(model.acc_sp - prev_acc);
        }
        /* the velocity's slope is the acceleration */
        assert_float_equal((vel_deg_s - prev_vel) / 0.001f, 0.5f * (model.acc_sp + prev_acc),
                           1.0f);
        prev_pos = model.pos_sp;
        prev_vel = vel_deg_s;
        prev_acc = model.acc_sp;
        if (k == 500) {
            assert_float_equal(model.pos_sp, 15.0f, 1e-3f);
            assert_float_equal(model.vel_sp, 15.0f, 1e-4f);
            assert_float_equal(model.acc_sp, 360.0f, 1e-2f);
        } else if (k == 1000) {
            assert_float_equal(model.pos_sp, 90.0f, 1e-3f);
            assert_float_equal(model.vel_sp, 30.0f, 1e-4f);
            assert_float_equal(model.acc_sp, 0.0f, 1e-2f);
        }
        assert_int_equal(model.trajectory_done, k >= 2500);
    }
    print_message("S-curve: largest change of acceleration in one tick %.4f deg/s^2 (jerk x dt "
                  "= 0.72)\n", (double)worst_jump);
    assert_true(model.pos_sp == 270.0f);
    assert_float_equal(pos(), 270.0f, 0.05f);
}

/* S-curve with accel 60 and decel 120 (r/min)/s, 270 deg at 30 r/min:
 * V = 180 deg/s; rising 2V/A1 = 1 s over 90 deg, falling 2V/A2 = 0.5 s over
 * 45 deg (jerk A2^2/V = 2880 deg/s^3), cruise 135 deg in 0.75 s: T = 2.25 s.
 * At t = 2.0 (0.25 s before the end, mid-fall) the remaining distance is
 * J*0.25^3/6 = V^2/(6 A2) = 7.5 deg: 262.5 deg, acceleration -A2 = -720. */
static void test_s_curve_with_unequal_rates_ends_on_time_and_stays_continuous(void **state)
{
    float prev_acc = 0.0f;
    long k;
    (void)state;
    set_u32(DARAN_PROP_TRAJ_MODE, 2u);
    set_f32(DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT, 120.0f);
    start(DARAN_MOVE_TRAPEZOID, 270.0f, 30.0f, 0.0f, 0.0f, DARAN_GIVEN_VEL);
    for (k = 1; k <= 2300; k++) {
        daran_sim_model_tick(&model);
        assert_true(fabsf(model.acc_sp - prev_acc) <= 2880.0f * 0.001f + 1e-3f);
        prev_acc = model.acc_sp;
        if (k == 2000) {
            assert_float_equal(model.pos_sp, 262.5f, 1e-3f);
            assert_float_equal(model.acc_sp, -720.0f, 1e-2f);
        }
        assert_int_equal(model.trajectory_done, k >= 2250);
    }
    assert_true(model.pos_sp == 270.0f);
}

/* ---- turn 2: faults and error registers ---- */

/* Stall limiter: 15 A (1.5 Nm) into a blocked shaft, limit 10 A for 0.5 s:
 * the current reaches 10 A within 2 ms (current loop 1000 rad/s), so the
 * trip comes between 0.50 and 0.51 s. */
static void test_stall_limiter_trips_after_its_time_at_its_current(void **state)
{
    (void)state;
    set_f32(DARAN_PROP_LOAD_INERTIA, 1.0e6f);
    set_u32(DARAN_PROP_ENABLE_CURRENT_MODE_VEL_LIMIT, 0u);
    set_f32(DARAN_PROP_STALL_CURRENT_LIMIT, 10.0f);
    set_f32(DARAN_PROP_STALL_TIME_LIMIT, 0.5f);
    start(DARAN_MOVE_TORQUE, 0.0f, 0.0f, 1.5f, 0.0f, 0u);
    run(&model, 2.0); /* the limiter is off by default */
    assert_int_equal(model.state, DARAN_STATE_CLOSED_LOOP);
    set_u32(DARAN_PROP_ENABLE_STALL_LIMIT, 1u);
    run(&model, 0.5);
    assert_int_equal(model.state, DARAN_STATE_CLOSED_LOOP);
    run(&model, 0.01);
    assert_int_equal(model.state, DARAN_STATE_IDLE);
    assert_int_equal(model.motor_error, DARAN_MOTOR_ERROR_STALL);
    assert_int_equal(model.error, DARAN_FLAG_MOTOR_FAILED);
    assert_int_equal(daran_sim_model_closed_loop(&model), DARAN_ERR_MOTOR_FAULT);
}

static void test_stall_fault_trips_the_limiter_at_the_next_tick(void **state)
{
    daran_move_t mv = {DARAN_MOVE_PASSTHROUGH, 0u, 10.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    (void)state;
    daran_sim_model_fault(&model, DARAN_SIM_FAULT_STALL);
    assert_int_equal(model.state, DARAN_STATE_CLOSED_LOOP);
    daran_sim_model_tick(&model);
    assert_int_equal(model.state, DARAN_STATE_IDLE);
    assert_int_equal(model.motor_error, DARAN_MOTOR_ERROR_STALL);
    assert_int_equal(model.error, DARAN_FLAG_MOTOR_FAILED);
    assert_int_equal(daran_sim_model_move(&model, &mv), DARAN_ERR_MOTOR_FAULT);
    run(&model, 1.0); /* it does not come back by itself */
    daran_sim_model_clear_errors(&model);
    assert_int_equal(daran_sim_model_closed_loop(&model), DARAN_OK);
    run(&model, 0.1);
    assert_int_equal(model.error, 0u);
}

/* The overspeed fault throws the shaft to 1.5 x 600 x 1.2 = 1080 r/min.
 * With enable_overspeed_error 0 (default) nothing trips and the controller
 * brakes the shaft back; with 1 the next tick trips. */
static void test_overspeed_trips_the_controller_only_when_enabled(void **state)
{
    (void)state;
    daran_sim_model_fault(&model, DARAN_SIM_FAULT_OVERSPEED);
    assert_float_equal(model.vel_rpm, 1080.0f, 1e-3f);
    run(&model, 1.0);
    assert_int_equal(model.state, DARAN_STATE_CLOSED_LOOP);
    assert_int_equal(model.controller_error, 0u);
    assert_float_equal(model.vel_rpm, 0.0f, 1.0f);
    run(&model, 1.0);
    assert_float_equal(pos(), 0.0f, 0.05f); /* back where it was held */
    set_u32(DARAN_PROP_ENABLE_OVERSPEED_ERROR, 1u);
    daran_sim_model_fault(&model, DARAN_SIM_FAULT_OVERSPEED);
    daran_sim_model_tick(&model);
    assert_int_equal(model.state, DARAN_STATE_IDLE);
    assert_int_equal(model.controller_error, DARAN_CONTROLLER_ERROR_OVERSPEED);
    assert_int_equal(model.error, DARAN_FLAG_CONTROLLER_FAILED);
}

/* A real over-speed: spinning at 300 r/min when vel_limit drops to 100
 * (x 1.2 = 120): the next tick trips. */
static void test_overspeed_error_trips_beyond_vel_limit_times_tolerance(void **state)
{
    (void)state;
    set_u32(DARAN_PROP_ENABLE_OVERSPEED_ERROR, 1u);
    start(DARAN_MOVE_VELOCITY, 0.0f, 300.0f, 0.0f, 0.0f, 0u);
    run(&model, 1.0);
    assert_int_equal(model.state, DARAN_STATE_CLOSED_LOOP);
    set_f32(DARAN_PROP_SHAFT_VEL_LIMIT, 100.0f);
    daran_sim_model_tick(&model);
    assert_int_equal(model.state, DARAN_STATE_IDLE);
    assert_int_equal(model.controller_error, DARAN_CONTROLLER_ERROR_OVERSPEED);
}

/* Writing 0 to one register clears that register only; the drive stays
 * idle, and a sub-register still set keeps closed loop refused. */
static void test_writing_zero_clears_one_register_and_the_drive_stays_idle(void **state)
{
    daran_value_t v;
    (void)state;
    daran_sim_model_fault(&model, DARAN_SIM_FAULT_STALL);
    daran_sim_model_fault(&model, DARAN_SIM_FAULT_OVERTEMP);
    daran_sim_model_tick(&model);
    assert_int_equal(model.error, DARAN_FLAG_MOTOR_FAILED | DARAN_FLAG_OVERTEMP);
    run(&model, 10.0); /* cool down below the limits */
    v.u64 = 1u;
    assert_int_equal(daran_sim_model_set(&model, DARAN_PROP_MOTOR_ERROR, v), DARAN_ERR_OUT_OF_RANGE);
    set_u32(DARAN_PROP_AXIS_ERROR, 0u);
    assert_int_equal(model.error, 0u);
    assert_int_equal(model.motor_error, DARAN_MOTOR_ERROR_STALL);
    assert_int_equal(model.state, DARAN_STATE_IDLE);
    assert_int_equal(daran_sim_model_closed_loop(&model), DARAN_ERR_MOTOR_FAULT);
    set_u32(DARAN_PROP_MOTOR_ERROR, 0u);
    set_u32(DARAN_PROP_FET_THERMISTOR_ERROR, 0u);
    assert_int_equal(daran_sim_model_closed_loop(&model), DARAN_ERR_MOTOR_FAULT);
    set_u32(DARAN_PROP_MOTOR_THERMISTOR_ERROR, 0u);
    assert_int_equal(model.state, DARAN_STATE_IDLE);
    assert_int_equal(daran_sim_model_closed_loop(&model), DARAN_OK);
}

static void test_clear_errors_clears_every_register_and_the_warnings(void **state)
{
    (void)state;
    daran_sim_model_trip(&model, DARAN_FLAG_ESTOP | DARAN_FLAG_WATCHDOG);
    model.motor_error = DARAN_MOTOR_ERROR_STALL;
    model.controller_error = DARAN_CONTROLLER_ERROR_OVERSPEED;
    model.encoder_error = 0x4u;
    model.fet_thermistor_error = 1u;
    model.motor_thermistor_error = 1u;
    model.can_error = 0x8u;
    model.config_warnings = DARAN_WARNING_NVM_CORRUPT;
    daran_sim_model_clear_errors(&model);
    assert_int_equal(model.error | model.motor_error | model.controller_error |
                         model.encoder_error | model.fet_thermistor_error |
                         model.motor_thermistor_error | model.can_error | model.config_warnings,
                     0u);
    assert_int_equal(model.state, DARAN_STATE_IDLE);
}

/* The trip level is config.dc_bus_undervoltage_trip_level; the fault sags
 * 2 V below it, so a level of 0 never trips. */
static void test_undervoltage_trip_level_is_the_property(void **state)
{
    (void)state;
    set_f32(DARAN_PROP_DC_BUS_UNDERVOLTAGE_TRIP_LEVEL, 25.0f);
    daran_sim_model_tick(&model);
    assert_int_equal(model.error, DARAN_FLAG_UNDERVOLTAGE);
    daran_sim_model_clear_errors(&model);
    set_f32(DARAN_PROP_DC_BUS_UNDERVOLTAGE_TRIP_LEVEL, 0.0f);
    assert_int_equal(daran_sim_model_closed_loop(&model), DARAN_OK);
    daran_sim_model_fault(&model, DARAN_SIM_FAULT_UNDERVOLTAGE);
    run(&model, 0.05);
    assert_true(model.vbus_v == 0.0f);
    assert_int_equal(model.state, DARAN_STATE_CLOSED_LOOP);
    run(&model, 0.1);
    assert_true(model.vbus_v > 23.9f);
}

static void test_startup_closed_loop_control_zero_boots_idle_without_a_flag(void **state)
{
    (void)state;
    set_u32(DARAN_PROP_STARTUP_CLOSED_LOOP_CONTROL, 0u);
    daran_sim_model_boot(&model);
    assert_int_equal(model.state, DARAN_STATE_IDLE);
    assert_int_equal(model.error, 0u);
    assert_int_equal(daran_sim_model_closed_loop(&model), DARAN_OK);
}

/* enable_damp_idle: in idle the shorted windings brake the shaft with
 * kt^2/R = 0.0333 Nm/(rad/s); from 300 r/min it stops far sooner than on
 * friction alone. */
static void test_damp_idle_brakes_a_coasting_shaft(void **state)
{
    float free_vel;
    (void)state;
    start(DARAN_MOVE_VELOCITY, 0.0f, 300.0f, 0.0f, 0.0f, 0u);
    run(&model, 1.0);
    daran_sim_model_trip(&model, 0u);
    run(&model, 0.1);
    free_vel = model.vel_rpm;
    assert_true(free_vel > 200.0f);
    assert_int_equal(daran_sim_model_closed_loop(&model), DARAN_OK);
    start(DARAN_MOVE_VELOCITY, 0.0f, 300.0f, 0.0f, 0.0f, 0u);
    run(&model, 1.0);
    set_u32(DARAN_PROP_ENABLE_DAMP_IDLE, 1u);
    daran_sim_model_trip(&model, 0u);
    run(&model, 0.1);
    assert_true(model.vel_rpm < 1.0f);
}

/* ---- turn 2: modes ---- */

static void expect_modes(uint32_t control, uint32_t input)
{
    daran_value_t v;
    assert_int_equal(daran_sim_model_get(&model, DARAN_PROP_CONTROL_MODE, &v), DARAN_OK);
    assert_int_equal(v.u32, control);
    assert_int_equal(daran_sim_model_get(&model, DARAN_PROP_INPUT_MODE, &v), DARAN_OK);
    assert_int_equal(v.u32, input);
}

static void test_control_and_input_modes_read_back_the_last_command(void **state)
{
    daran_move_t d = {DARAN_MOVE_IMPEDANCE, 0u, 0.0f, 0.0f, 0.0f, 0.0f, 0.01f, 0.001f};
    (void)state;
    expect_modes(3u, 1u); /* holding position after power-up */
    start(DARAN_MOVE_FILTERED_POSITION, 5.0f, 0.0f, 0.0f, 0.0f, 0u);
    expect_modes(3u, 3u);
    start(DARAN_MOVE_TRAPEZOID, 5.0f, 0.0f, 0.0f, 0.0f, 0u);
    expect_modes(3u, 5u);
    start(DARAN_MOVE_PASSTHROUGH, 5.0f, 0.0f, 0.0f, 0.0f, 0u);
    expect_modes(3u, 1u);
    start(DARAN_MOVE_VELOCITY, 0.0f, 5.0f, 0.0f, 0.0f, 0u);
    expect_modes(2u, 1u);
    start(DARAN_MOVE_VELOCITY_RAMP, 0.0f, 5.0f, 0.0f, 10.0f, 0u);
    expect_modes(2u, 2u);
    start(DARAN_MOVE_TORQUE, 0.0f, 0.0f, 0.1f, 0.0f, 0u);
    expect_modes(1u, 1u);
    start(DARAN_MOVE_TORQUE_RAMP, 0.0f, 0.0f, 0.1f, 1.0f, 0u);
    expect_modes(1u, 6u);
    assert_int_equal(daran_sim_model_move(&model, &d), DARAN_OK);
    expect_modes(3u, 9u);
    set_f32(DARAN_PROP_VEL_SETPOINT, 1.0f);
    expect_modes(2u, 1u);
    set_f32(DARAN_PROP_TORQUE_SETPOINT, 0.0f);
    expect_modes(1u, 1u);
    set_f32(DARAN_PROP_POS_SETPOINT, 0.0f);
    expect_modes(3u, 1u);
}

/* ODrive style: writing input_mode/control_mode switches the controller
 * from the current inputs; input_mode 5 then input_pos plans a trapezoid
 * with the stored limits (600 r/min, 60 (r/min)/s: 90 deg is a 1 s
 * triangle). */
static void test_writing_the_modes_switches_the_controller_from_the_inputs(void **state)
{
    (void)state;
    set_u32(DARAN_PROP_INPUT_MODE, 5u);
    expect_modes(3u, 5u);
    assert_true(model.trajectory_done); /* already at input_pos */
    set_f32(DARAN_PROP_INPUT_POS, 90.0f);
    assert_false(model.trajectory_done);
    run(&model, 0.999);
    assert_false(model.trajectory_done);
    run(&model, 0.001);
    assert_true(model.trajectory_done);
    assert_true(model.pos_sp == 90.0f);
    /* velocity control from input_vel */
    set_f32(DARAN_PROP_INPUT_VEL, 20.0f);
    set_u32(DARAN_PROP_CONTROL_MODE, 2u);
    expect_modes(2u, 1u);
    run(&model, 0.5);
    assert_float_equal(model.vel_rpm, 20.0f, 0.2f);
    /* ramp from there to input_vel at vel_ramp_rate (60 (r/min)/s) */
    set_f32(DARAN_PROP_INPUT_VEL, 50.0f);
    set_u32(DARAN_PROP_INPUT_MODE, 2u);
    expect_modes(2u, 2u);
    run(&model, 0.25);
    assert_float_equal(model.vel_sp, 35.0f, 0.5f);
    /* torque control from input_torque */
    set_f32(DARAN_PROP_INPUT_TORQUE, 0.05f);
    set_u32(DARAN_PROP_CONTROL_MODE, 1u);
    expect_modes(1u, 1u);
    daran_sim_model_tick(&model);
    assert_float_equal(model.torque_cmd, 0.05f, 1e-6f);
    set_u32(DARAN_PROP_INPUT_MODE, 6u);
    expect_modes(1u, 6u);
    /* back to position control: passthrough toward input_pos (90), with
     * input_vel and input_torque as its feed-forwards */
    set_f32(DARAN_PROP_INPUT_VEL, 0.0f);
    set_f32(DARAN_PROP_INPUT_TORQUE, 0.0f);
    set_u32(DARAN_PROP_CONTROL_MODE, 3u);
    expect_modes(3u, 1u);
    set_u32(DARAN_PROP_INPUT_MODE, 3u);
    expect_modes(3u, 3u);
    set_u32(DARAN_PROP_INPUT_MODE, 9u);
    expect_modes(3u, 9u);
    set_u32(DARAN_PROP_INPUT_MODE, 1u);
    expect_modes(3u, 1u);
    run(&model, 3.0);
    assert_float_equal(pos(), 90.0f, 0.05f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_power_up_is_closed_loop_at_rest, setup),
        cmocka_unit_test_setup(test_ten_degree_step_settles_in_under_0_3_s_without_overshoot, setup),
        cmocka_unit_test_setup(test_q_setpoint_follows_the_analytic_trapezoid_and_ends_on_target, setup),
        cmocka_unit_test_setup(test_q_too_short_for_its_cruise_velocity_runs_a_triangle, setup),
        cmocka_unit_test_setup(test_q_without_vel_and_acc_uses_the_drive_settings, setup),
        cmocka_unit_test_setup(test_v_ramp_has_the_commanded_slope, setup),
        cmocka_unit_test_setup(test_c_ramp_has_the_commanded_slope, setup),
        cmocka_unit_test_setup(test_d_torque_is_the_impedance_law_every_tick, setup),
        cmocka_unit_test_setup(test_t_stream_is_followed_smoothly, setup),
        cmocka_unit_test_setup(test_t_step_does_not_overshoot, setup),
        cmocka_unit_test_setup(test_torque_is_clamped_by_the_lowest_limit, setup),
        cmocka_unit_test_setup(test_velocity_is_clamped_by_the_lowest_limit, setup),
        cmocka_unit_test_setup(test_software_limits_hold_in_every_mode, setup),
        cmocka_unit_test_setup(test_set_zero_moves_nothing, setup),
        cmocka_unit_test_setup(test_estop_then_clear_then_closed_loop_moves_again, setup),
        cmocka_unit_test_setup(test_watchdog_trips_when_not_fed_in_time, setup),
        cmocka_unit_test_setup(test_overtemp_fault_trips_enabled_thermistors_at_the_next_tick, setup),
        cmocka_unit_test_setup(test_sustained_current_heats_the_motor_until_it_trips, setup),
        cmocka_unit_test_setup(test_derating_keeps_the_motor_below_its_trip_temperature, setup),
        cmocka_unit_test_setup(test_electrical_quantities_follow_the_torque, setup),
        cmocka_unit_test_setup(test_undervoltage_sag_trips_and_recovers, setup),
        cmocka_unit_test_setup(test_writing_setpoints_sets_the_matching_input, setup),
        cmocka_unit_test_setup(test_runs_at_8_khz_too, setup),
        cmocka_unit_test_setup(test_trapezoid_rises_at_the_accel_limit_and_falls_at_the_decel_limit, setup),
        cmocka_unit_test_setup(test_q_with_zero_acceleration_steps_the_setpoint_to_the_target, setup),
        cmocka_unit_test_setup(test_velocity_ramp_at_rate_zero_holds_the_velocity, setup),
        cmocka_unit_test_setup(test_torque_ramp_at_rate_zero_holds_the_torque, setup),
        cmocka_unit_test_setup(test_filter_bandwidth_zero_holds_the_setpoint, setup),
        cmocka_unit_test_setup(test_timed_moves_of_three_distances_end_on_the_planned_tick, setup),
        cmocka_unit_test_setup(test_short_s_curve_is_the_s_curve_triangle, setup),
        cmocka_unit_test_setup(test_s_curve_is_continuous_in_position_velocity_and_acceleration, setup),
        cmocka_unit_test_setup(test_s_curve_with_unequal_rates_ends_on_time_and_stays_continuous, setup),
        cmocka_unit_test_setup(test_stall_limiter_trips_after_its_time_at_its_current, setup),
        cmocka_unit_test_setup(test_stall_fault_trips_the_limiter_at_the_next_tick, setup),
        cmocka_unit_test_setup(test_overspeed_trips_the_controller_only_when_enabled, setup),
        cmocka_unit_test_setup(test_overspeed_error_trips_beyond_vel_limit_times_tolerance, setup),
        cmocka_unit_test_setup(test_writing_zero_clears_one_register_and_the_drive_stays_idle, setup),
        cmocka_unit_test_setup(test_clear_errors_clears_every_register_and_the_warnings, setup),
        cmocka_unit_test_setup(test_undervoltage_trip_level_is_the_property, setup),
        cmocka_unit_test_setup(test_startup_closed_loop_control_zero_boots_idle_without_a_flag, setup),
        cmocka_unit_test_setup(test_damp_idle_brakes_a_coasting_shaft, setup),
        cmocka_unit_test_setup(test_control_and_input_modes_read_back_the_last_command, setup),
        cmocka_unit_test_setup(test_writing_the_modes_switches_the_controller_from_the_inputs, setup),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
