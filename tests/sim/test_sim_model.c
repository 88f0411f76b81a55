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

/* D20: without vel/acc, q uses the drive's settings, starting at vel_limit
 * (600 r/min) and 60 (r/min)/s: 90 deg is a triangle of 2*sqrt(90/360) = 1 s. */
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
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
