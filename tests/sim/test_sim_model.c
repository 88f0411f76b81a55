/* Physics of the simulated drive, checked against numbers worked out by
 * hand: step response, trapezoid and triangle, ramps, impedance law, input
 * filter, limits, set-zero, states and faults. The model is driven directly
 * (no protocol core) at 1 kHz. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "sim_unity.h"
#include "unity.h"

#include "sim_model.h"

/* The drive under test: setUp() gives every test a fresh one at 1 kHz. */
static daran_sim_model_t model;

void setUp(void)
{
    daran_sim_model_init(&model, 1000u);
}

void tearDown(void)
{
}

static void run(daran_sim_model_t *m, double seconds)
{
    long n = lround(seconds * (double)m->tick_hz);
    long k;
    for (k = 0; k < n; k++) {
        daran_sim_model_tick(m);
    }
}

/* The UPPER-CASE helpers are macros so that a failure points at the test's
 * line. */
static void start_at(int line, daran_move_kind_t kind, float pos, float vel, float torque,
                     float rate, uint8_t given)
{
    daran_move_t mv = {kind, given, pos, vel, torque, rate, 0.0f, 0.0f};
    UNITY_TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_move(&model, &mv), line,
                                  "the model refused the move");
}
/* Start a move on the model; it must be accepted. */
#define START(...) start_at(__LINE__, __VA_ARGS__)

static void set_at(int line, daran_prop_t prop, daran_value_t value)
{
    UNITY_TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_set(&model, prop, value), line,
                                  "the model refused the value");
}

static daran_value_t f32_value(float v)
{
    daran_value_t value;
    value.u64 = 0u;
    value.f32 = v;
    return value;
}

static daran_value_t u32_value(uint32_t v)
{
    daran_value_t value;
    value.u64 = 0u;
    value.u32 = v;
    return value;
}
/* Write a property of the model; it must be accepted. */
#define SET_F32(prop, v) set_at(__LINE__, (prop), f32_value(v))
#define SET_U32(prop, v) set_at(__LINE__, (prop), u32_value(v))

static float pos(void)
{
    return daran_sim_model_pos_deg(&model);
}

static void test_power_up_is_closed_loop_at_rest(void)
{
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_CLOSED_LOOP, model.state);
    TEST_ASSERT_EQUAL_INT64(0u, model.error);
    run(&model, 0.5);
    TEST_ASSERT_TRUE(pos() == 0.0f);
    TEST_ASSERT_TRUE(model.vbus_v == 24.0f);
}

/* Spec: a 10 deg step settles within 2 % (0.2 deg) in under 0.3 s with under
 * 5 % (0.5 deg) overshoot at zero load inertia. */
static void test_ten_degree_step_settles_in_under_0_3_s_without_overshoot(void)
{
    float peak = 0.0f;
    long last_outside = 0;
    long k;
    START(DARAN_MOVE_PASSTHROUGH, 10.0f, 0.0f, 0.0f, 0.0f, 0u);
    for (k = 1; k <= 1000; k++) {
        daran_sim_model_tick(&model);
        if (pos() > peak) {
            peak = pos();
        }
        if (fabsf(pos() - 10.0f) > 0.2f) {
            last_outside = k;
        }
    }
    NOTE("10 deg step: settled (2%%) after %ld ms, peak %.4f deg", last_outside,
         (double)peak);
    TEST_ASSERT_TRUE(last_outside < 300);
    TEST_ASSERT_TRUE(peak < 10.5f);
    TEST_ASSERT_TRUE(fabsf(pos() - 10.0f) < 0.01f);
}

/* q 1 180 30 60: V = 30 r/min = 180 deg/s, A = 60 (r/min)/s = 360 deg/s^2.
 * ta = V/A = 0.5 s covering 45 deg; cruise 90 deg takes 0.5 s; T = 1.5 s.
 *   t = 0.25: 0.5*360*0.25^2 = 11.25      t = 0.75: 45 + 180*0.25 = 90
 *   t = 1.25: 180 - 0.5*360*0.25^2 = 168.75 */
static void test_q_setpoint_follows_the_analytic_trapezoid_and_ends_on_target(void)
{
    START(DARAN_MOVE_TRAPEZOID, 180.0f, 30.0f, 0.0f, 60.0f, DARAN_GIVEN_VEL | DARAN_GIVEN_RATE);
    TEST_ASSERT_FALSE(model.trajectory_done);
    run(&model, 0.25);
    TEST_ASSERT_FLOAT_WITHIN(0.5f, 11.25f, model.pos_sp);
    TEST_ASSERT_FLOAT_WITHIN(0.1f, 15.0f, model.vel_sp); /* 90 deg/s */
    run(&model, 0.5);
    TEST_ASSERT_FLOAT_WITHIN(0.5f, 90.0f, model.pos_sp);
    TEST_ASSERT_FLOAT_WITHIN(0.01f, 30.0f, model.vel_sp);
    run(&model, 0.5);
    TEST_ASSERT_FLOAT_WITHIN(0.5f, 168.75f, model.pos_sp);
    TEST_ASSERT_FLOAT_WITHIN(1.0f, 168.75f, pos());
    run(&model, 0.249);
    TEST_ASSERT_FALSE(model.trajectory_done);
    run(&model, 0.001);
    TEST_ASSERT_TRUE(model.trajectory_done);
    TEST_ASSERT_TRUE(model.pos_sp == 180.0f);
    run(&model, 0.5);
    TEST_ASSERT_FLOAT_WITHIN(0.05f, 180.0f, pos());
}

/* q 1 45 30 60: 45 deg < V^2/A = 90 deg, so a triangle: ta = sqrt(45/360) =
 * 0.35355 s, peak 127.28 deg/s (21.21 r/min), T = 0.70711 s.
 *   t = 0.2: 0.5*360*0.04 = 7.2
 *   t = 0.5: 45 - 0.5*360*(0.70711-0.5)^2 = 45 - 7.7213 = 37.279 */
static void test_q_too_short_for_its_cruise_velocity_runs_a_triangle(void)
{
    START(DARAN_MOVE_TRAPEZOID, 45.0f, 30.0f, 0.0f, 60.0f, DARAN_GIVEN_VEL | DARAN_GIVEN_RATE);
    run(&model, 0.2);
    TEST_ASSERT_FLOAT_WITHIN(0.5f, 7.2f, model.pos_sp);
    run(&model, 0.15);
    TEST_ASSERT_FLOAT_WITHIN(0.3f, 21.0f, model.vel_sp);
    run(&model, 0.15);
    TEST_ASSERT_FLOAT_WITHIN(0.5f, 37.279f, model.pos_sp);
    run(&model, 0.206);
    TEST_ASSERT_FALSE(model.trajectory_done);
    run(&model, 0.002);
    TEST_ASSERT_TRUE(model.trajectory_done);
    TEST_ASSERT_TRUE(model.pos_sp == 45.0f);
}

/* D20: without vel/acc, q uses the drive's settings, output_shaft.
 * trap_traj_vel_limit (600 r/min) and trap_traj_accel_limit = decel_limit
 * (60 (r/min)/s): 90 deg is a triangle of 2*sqrt(90/360) = 1 s. */
static void test_q_without_vel_and_acc_uses_the_drive_settings(void)
{
    START(DARAN_MOVE_TRAPEZOID, 90.0f, 0.0f, 0.0f, 0.0f, 0u);
    run(&model, 0.999);
    TEST_ASSERT_FALSE(model.trajectory_done);
    run(&model, 0.001);
    TEST_ASSERT_TRUE(model.trajectory_done);
    /* a given acc becomes the new setting: 240 (r/min)/s halves the time */
    START(DARAN_MOVE_TRAPEZOID, 0.0f, 0.0f, 0.0f, 240.0f, DARAN_GIVEN_RATE);
    run(&model, 0.5);
    TEST_ASSERT_TRUE(model.trajectory_done);
    TEST_ASSERT_TRUE(model.pos_sp == 0.0f);
}

/* v 1 60 120 2: ramp at 120 (r/min)/s: 30 r/min after 0.25 s, 60 at 0.5 s. */
static void test_v_ramp_has_the_commanded_slope(void)
{
    START(DARAN_MOVE_VELOCITY_RAMP, 0.0f, 60.0f, 0.0f, 120.0f, 0u);
    TEST_ASSERT_TRUE(model.cfg[DARAN_PROP_VEL_RAMP_RATE].f32 == 120.0f);
    run(&model, 0.25);
    TEST_ASSERT_FLOAT_WITHIN(0.01f, 30.0f, model.vel_sp);
    TEST_ASSERT_FLOAT_WITHIN(1.5f, 30.0f, model.vel_rpm);
    run(&model, 0.25);
    TEST_ASSERT_FLOAT_WITHIN(0.01f, 60.0f, model.vel_sp);
    run(&model, 0.5);
    TEST_ASSERT_FLOAT_WITHIN(0.5f, 60.0f, model.vel_rpm);
    /* v mode 1 sets the velocity at once */
    START(DARAN_MOVE_VELOCITY, 0.0f, -20.0f, 0.0f, 0.0f, 0u);
    run(&model, 0.001);
    TEST_ASSERT_TRUE(model.vel_sp == -20.0f);
}

/* c 1 0.5 1 6 on a heavy load (1 Nm/(r/s^2)): ramp at 1 Nm/s, 0.25 Nm after
 * 0.25 s, 0.5 at 0.5 s, then held. */
static void test_c_ramp_has_the_commanded_slope(void)
{
    SET_F32(DARAN_PROP_LOAD_INERTIA, 1.0f);
    START(DARAN_MOVE_TORQUE_RAMP, 0.0f, 0.0f, 0.5f, 1.0f, 0u);
    run(&model, 0.25);
    TEST_ASSERT_FLOAT_WITHIN(0.002f, 0.25f, model.torque_cmd);
    run(&model, 0.25);
    TEST_ASSERT_FLOAT_WITHIN(0.002f, 0.5f, model.torque_cmd);
    run(&model, 0.25);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.5f, model.torque_cmd);
    /* c mode 1: at once */
    START(DARAN_MOVE_TORQUE, 0.0f, 0.0f, -0.3f, 0.0f, 0u);
    run(&model, 0.001);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, -0.3f, model.torque_cmd);
}

/* d 1 10 5 0.1 0.01 0.002 from rest at 0: 0.01*10 + 0.1 + 0.002*5 = 0.21 Nm;
 * then every tick torque = kp(pdes-pos) + tff + kd(vdes-vel). */
static void test_d_torque_is_the_impedance_law_every_tick(void)
{
    daran_move_t mv = {DARAN_MOVE_IMPEDANCE, 0u, 10.0f, 5.0f, 0.1f, 0.0f, 0.01f, 0.002f};
    int k;
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_move(&model, &mv));
    daran_sim_model_tick(&model);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.21f, model.torque_cmd);
    for (k = 0; k < 300; k++) {
        float p = pos();
        float v = model.vel_rpm;
        float expect = 0.01f * (10.0f - p) + 0.1f + 0.002f * (5.0f - v);
        daran_sim_model_tick(&model);
        TEST_ASSERT_FLOAT_WITHIN(1e-5f, expect, model.torque_cmd);
    }
    TEST_ASSERT_TRUE(model.input_pos == 10.0f && model.input_vel == 5.0f &&
                     model.input_torque == 0.1f);
}

/* A host streams `t` at 100 Hz along 30 sin(pi t); with bandwidth 100 the
 * setpoint moves smoothly (never more than the path's 94 deg/s allows, plus
 * margin) and the shaft stays within 3 deg of the stream. */
static void test_t_stream_is_followed_smoothly(void)
{
    float prev_sp = 0.0f;
    float worst_err = 0.0f;
    float worst_step = 0.0f;
    int k;
    for (k = 0; k < 3000; k++) {
        float t = (float)k / 1000.0f;
        if (k % 10 == 0) {
            START(DARAN_MOVE_FILTERED_POSITION, 30.0f * sinf(3.14159265f * t), 0.0f, 0.0f,
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
    NOTE("t stream: worst tracking error %.3f deg, largest setpoint step %.4f deg",
         (double)worst_err, (double)worst_step);
    TEST_ASSERT_TRUE(model.cfg[DARAN_PROP_INPUT_FILTER_BANDWIDTH].f32 == 100.0f);
    TEST_ASSERT_TRUE(worst_err < 3.0f);
    TEST_ASSERT_TRUE(worst_step < 0.15f);
}

/* A single `t` step: critically damped, so the setpoint never passes the
 * target. */
static void test_t_step_does_not_overshoot(void)
{
    float peak = 0.0f;
    int k;
    START(DARAN_MOVE_FILTERED_POSITION, 20.0f, 0.0f, 0.0f, 25.0f, DARAN_GIVEN_RATE);
    for (k = 0; k < 1000; k++) {
        daran_sim_model_tick(&model);
        if (model.pos_sp > peak) {
            peak = model.pos_sp;
        }
    }
    TEST_ASSERT_TRUE(peak <= 20.0f);
    TEST_ASSERT_FLOAT_WITHIN(0.001f, 20.0f, model.pos_sp);
}

static void test_torque_is_clamped_by_the_lowest_limit(void)
{
    int k;
    SET_F32(DARAN_PROP_SHAFT_TORQUE_LIM, 0.05f);
    START(DARAN_MOVE_PASSTHROUGH, 90.0f, 0.0f, 0.0f, 0.0f, 0u);
    daran_sim_model_tick(&model);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.05f, model.torque_cmd);
    /* current_lim 0.3 A x torque_constant 0.1 Nm/A = 0.03 Nm is lower */
    SET_F32(DARAN_PROP_CURRENT_LIM, 0.3f);
    for (k = 0; k < 100; k++) {
        daran_sim_model_tick(&model);
        TEST_ASSERT_TRUE(fabsf(model.torque_cmd) <= 0.03f + 1e-6f);
    }
    SET_F32(DARAN_PROP_CURRENT_LIM, 25.0f);
    SET_F32(DARAN_PROP_MOTOR_TORQUE_LIM, 0.02f);
    daran_sim_model_tick(&model);
    TEST_ASSERT_TRUE(fabsf(model.torque_cmd) <= 0.02f + 1e-6f);
}

/* output_shaft.vel_limit 60 r/min, then controller vel_limit 0.5 turn/s =
 * 30 r/min: the lower applies. */
static void test_velocity_is_clamped_by_the_lowest_limit(void)
{
    float top = 0.0f;
    int k;
    SET_F32(DARAN_PROP_SHAFT_VEL_LIMIT, 60.0f);
    START(DARAN_MOVE_PASSTHROUGH, 720.0f, 0.0f, 0.0f, 0.0f, 0u);
    for (k = 0; k < 1000; k++) {
        daran_sim_model_tick(&model);
        top = model.vel_rpm > top ? model.vel_rpm : top;
    }
    TEST_ASSERT_TRUE(top < 61.0f && top > 59.0f);
    SET_F32(DARAN_PROP_CONTROLLER_VEL_LIMIT, 0.5f);
    START(DARAN_MOVE_VELOCITY, 0.0f, 100.0f, 0.0f, 0.0f, 0u);
    run(&model, 0.5);
    TEST_ASSERT_FLOAT_WITHIN(0.5f, 30.0f, model.vel_rpm);
    TEST_ASSERT_TRUE(model.vel_sp == 30.0f);
}

static void test_software_limits_hold_in_every_mode(void)
{
    SET_F32(DARAN_PROP_CIRCULAR_SETPOINT_MIN, -10.0f);
    SET_F32(DARAN_PROP_CIRCULAR_SETPOINT_MAX, 20.0f);
    SET_U32(DARAN_PROP_ENABLE_CIRCULAR_SETPOINT_LIMIT, 1u);
    START(DARAN_MOVE_TRAPEZOID, 90.0f, 60.0f, 0.0f, 600.0f, DARAN_GIVEN_VEL | DARAN_GIVEN_RATE);
    run(&model, 1.0);
    TEST_ASSERT_TRUE(model.trajectory_done);
    TEST_ASSERT_TRUE(model.pos_sp == 20.0f);
    TEST_ASSERT_FLOAT_WITHIN(0.05f, 20.0f, pos());
    START(DARAN_MOVE_PASSTHROUGH, -50.0f, 0.0f, 0.0f, 0.0f, 0u);
    run(&model, 1.0);
    TEST_ASSERT_TRUE(model.pos_sp == -10.0f);
    TEST_ASSERT_FLOAT_WITHIN(0.05f, -10.0f, pos());
    START(DARAN_MOVE_FILTERED_POSITION, 100.0f, 0.0f, 0.0f, 0.0f, 0u);
    run(&model, 2.0);
    TEST_ASSERT_TRUE(model.pos_sp <= 20.0f);
    /* velocity control runs into the limit and holds there */
    START(DARAN_MOVE_VELOCITY, 0.0f, -30.0f, 0.0f, 0.0f, 0u);
    run(&model, 3.0);
    TEST_ASSERT_FLOAT_WITHIN(2.0f, -10.0f, pos());
    TEST_ASSERT_FLOAT_WITHIN(0.1f, 0.0f, model.vel_rpm);
    /* off: free again */
    SET_U32(DARAN_PROP_ENABLE_CIRCULAR_SETPOINT_LIMIT, 0u);
    START(DARAN_MOVE_PASSTHROUGH, -50.0f, 0.0f, 0.0f, 0.0f, 0u);
    run(&model, 1.0);
    TEST_ASSERT_FLOAT_WITHIN(0.05f, -50.0f, pos());
}

static void test_set_zero_moves_nothing(void)
{
    float worst = 0.0f;
    int k;
    START(DARAN_MOVE_PASSTHROUGH, 30.0f, 0.0f, 0.0f, 0.0f, 0u);
    run(&model, 1.0);
    daran_sim_model_set_zero(&model);
    TEST_ASSERT_TRUE(pos() == 0.0f);
    TEST_ASSERT_FLOAT_WITHIN(0.01f, 0.0f, model.pos_sp);
    TEST_ASSERT_FLOAT_WITHIN(0.01f, 0.0f, model.input_pos);
    for (k = 0; k < 500; k++) {
        daran_sim_model_tick(&model);
        worst = fabsf(pos()) > worst ? fabsf(pos()) : worst;
    }
    TEST_ASSERT_TRUE(worst < 0.01f);
    START(DARAN_MOVE_PASSTHROUGH, 5.0f, 0.0f, 0.0f, 0.0f, 0u);
    run(&model, 1.0);
    TEST_ASSERT_FLOAT_WITHIN(0.01f, 5.0f, pos());
    TEST_ASSERT_FLOAT_WITHIN(0.02f, 35.0f, model.raw_pos_deg);
}

static void test_estop_then_clear_then_closed_loop_moves_again(void)
{
    daran_move_t mv = {DARAN_MOVE_PASSTHROUGH, 0u, 10.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    daran_value_t v;
    daran_sim_model_trip(&model, DARAN_FLAG_ESTOP);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_IDLE, model.state);
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_ESTOP_ACTIVE, daran_sim_model_move(&model, &mv));
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_ESTOP_ACTIVE, daran_sim_model_closed_loop(&model));
    run(&model, 0.1);
    TEST_ASSERT_TRUE(model.torque_cmd == 0.0f);
    daran_sim_model_clear_errors(&model);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_IDLE, model.state);
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_MOTOR_IDLE, daran_sim_model_move(&model, &mv));
    v.u64 = 0u;
    v.u32 = DARAN_STATE_CLOSED_LOOP;
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_set(&model, DARAN_PROP_REQUESTED_STATE, v));
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_move(&model, &mv));
    run(&model, 1.0);
    TEST_ASSERT_FLOAT_WITHIN(0.01f, 10.0f, pos());
}

static void test_watchdog_trips_when_not_fed_in_time(void)
{
    SET_F32(DARAN_PROP_WATCHDOG_TIMEOUT, 0.2f);
    SET_U32(DARAN_PROP_ENABLE_WATCHDOG, 1u);
    run(&model, 0.15);
    daran_sim_model_feed_watchdog(&model);
    run(&model, 0.15);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_CLOSED_LOOP, model.state);
    run(&model, 0.06);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_IDLE, model.state);
    TEST_ASSERT_EQUAL_INT64(DARAN_FLAG_WATCHDOG, model.error);
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_MOTOR_FAULT, daran_sim_model_closed_loop(&model));
}

static void test_overtemp_fault_trips_enabled_thermistors_at_the_next_tick(void)
{
    SET_U32(DARAN_PROP_MOTOR_THERMISTOR_ENABLED, 0u);
    daran_sim_model_fault(&model, DARAN_SIM_FAULT_OVERTEMP);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 105.0f, model.fet_temp_c);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 125.0f, model.motor_temp_c);
    daran_sim_model_tick(&model);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_IDLE, model.state);
    TEST_ASSERT_EQUAL_INT64(DARAN_FLAG_OVERTEMP, model.error);
    TEST_ASSERT_EQUAL_INT64(DARAN_THERMISTOR_ERROR_OVERTEMP, model.fet_thermistor_error);
    TEST_ASSERT_EQUAL_INT64(0u, model.motor_thermistor_error);
    /* FET cools with tau 5 s: 80 e^(-t/5) < 75 after 0.32 s */
    daran_sim_model_clear_errors(&model);
    run(&model, 0.1);
    TEST_ASSERT_EQUAL_INT64(DARAN_FLAG_OVERTEMP, model.error);
    run(&model, 0.4);
    daran_sim_model_clear_errors(&model);
    run(&model, 0.01);
    TEST_ASSERT_EQUAL_INT64(0u, model.error);
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_closed_loop(&model));
}

/* 2 Nm stall torque = 20 A. Motor: steady 25 + 0.3*400 = 145 degC, tau 30 s:
 * passes 120 after 30 ln(120/25) = 47.06 s when nothing derates. */
static void test_sustained_current_heats_the_motor_until_it_trips(void)
{
    double t = 0.0;
    SET_F32(DARAN_PROP_LOAD_INERTIA, 1.0e6f); /* shaft blocked */
    SET_F32(DARAN_PROP_MOTOR_TEMP_LIMIT_LOWER, 120.0f); /* no derating */
    SET_U32(DARAN_PROP_ENABLE_CURRENT_MODE_VEL_LIMIT, 0u);
    START(DARAN_MOVE_TORQUE, 0.0f, 0.0f, 2.0f, 0.0f, 0u);
    run(&model, 1.0);
    TEST_ASSERT_FLOAT_WITHIN(0.01f, 20.0f, model.torque_nm / 0.1f);
    while (model.state == DARAN_STATE_CLOSED_LOOP && t < 100.0) {
        run(&model, 0.01);
        t += 0.01;
    }
    NOTE("motor over-temperature trip after %.2f s at 20 A", t + 1.0);
    TEST_ASSERT_TRUE(t + 1.0 > 46.5 && t + 1.0 < 47.5);
    TEST_ASSERT_EQUAL_INT64(DARAN_FLAG_OVERTEMP, model.error);
    TEST_ASSERT_EQUAL_INT64(DARAN_THERMISTOR_ERROR_OVERTEMP, model.motor_thermistor_error);
    TEST_ASSERT_EQUAL_INT64(0u, model.motor_error);
}

/* With derating (torque limit falling to 0 from 90 to 120 degC) the same
 * demand settles below the trip point. */
static void test_derating_keeps_the_motor_below_its_trip_temperature(void)
{
    SET_F32(DARAN_PROP_LOAD_INERTIA, 1.0e6f);
    SET_U32(DARAN_PROP_ENABLE_CURRENT_MODE_VEL_LIMIT, 0u);
    START(DARAN_MOVE_TORQUE, 0.0f, 0.0f, 2.0f, 0.0f, 0u);
    run(&model, 300.0);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_CLOSED_LOOP, model.state);
    TEST_ASSERT_TRUE(model.motor_temp_c > 90.0f && model.motor_temp_c < 120.0f);
    TEST_ASSERT_TRUE(daran_sim_model_torque_limit(&model) < 2.0f);
}

/* 0.5 Nm on a blocked shaft: Iq = 5 A, copper loss 25 * 0.3
 * = 7.5 W, ibus = 7.5 / 24 = 0.3125 A, vbus = 24 - 0.02 * 0.3125. */
static void test_electrical_quantities_follow_the_torque(void)
{
    daran_value_t v;
    SET_F32(DARAN_PROP_LOAD_INERTIA, 1.0e6f);
    START(DARAN_MOVE_TORQUE, 0.0f, 0.0f, 0.5f, 0.0f, 0u);
    run(&model, 0.1);
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_get(&model, DARAN_PROP_IQ_MEASURED, &v));
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 5.0f, v.f32);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 0.3125f, model.ibus_a);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 23.99375f, model.vbus_v);
}

static void test_undervoltage_sag_trips_and_recovers(void)
{
    daran_sim_model_fault(&model, DARAN_SIM_FAULT_UNDERVOLTAGE);
    run(&model, 0.002);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_IDLE, model.state);
    TEST_ASSERT_EQUAL_INT64(DARAN_FLAG_UNDERVOLTAGE, model.error);
    TEST_ASSERT_TRUE(model.vbus_v == 6.0f); /* 2 V below the 8 V trip level */
    run(&model, 0.2);
    TEST_ASSERT_TRUE(model.vbus_v == 24.0f);
    daran_sim_model_clear_errors(&model);
    run(&model, 0.01);
    TEST_ASSERT_EQUAL_INT64(0u, model.error);
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_closed_loop(&model));
}

static void test_writing_setpoints_sets_the_matching_input(void)
{
    SET_F32(DARAN_PROP_POS_SETPOINT, 15.0f);
    TEST_ASSERT_TRUE(model.input_pos == 15.0f);
    run(&model, 1.0);
    TEST_ASSERT_TRUE(model.pos_sp == 15.0f);
    TEST_ASSERT_FLOAT_WITHIN(0.01f, 15.0f, pos());
    SET_F32(DARAN_PROP_VEL_SETPOINT, 12.0f);
    TEST_ASSERT_TRUE(model.input_vel == 12.0f);
    run(&model, 0.5);
    TEST_ASSERT_FLOAT_WITHIN(0.1f, 12.0f, model.vel_rpm);
    SET_F32(DARAN_PROP_TORQUE_SETPOINT, 0.0f);
    TEST_ASSERT_TRUE(model.input_torque == 0.0f);
    TEST_ASSERT_EQUAL_INT64(DARAN_SIM_MODE_TORQUE, model.mode);
}

static void test_q_ends_on_its_planned_tick_at_8_khz_too(void)
{
    daran_sim_model_init(&model, 8000u);
    START(DARAN_MOVE_TRAPEZOID, 180.0f, 30.0f, 0.0f, 60.0f, DARAN_GIVEN_VEL | DARAN_GIVEN_RATE);
    run(&model, 1.499875);
    TEST_ASSERT_FALSE(model.trajectory_done);
    run(&model, 0.000125);
    TEST_ASSERT_TRUE(model.trajectory_done);
    run(&model, 0.5);
    TEST_ASSERT_FLOAT_WITHIN(0.05f, 180.0f, pos());
}

/* ---- turn 2: trajectory limits as properties, zero rates, S-curve ---- */

/* The acceleration limit shapes the rising phase, the deceleration limit the
 * falling one. q 1 180 30 with accel 60 and decel 120 (r/min)/s:
 * V = 180 deg/s, a1 = 360, a2 = 720 deg/s^2; rising 0.5 s (45 deg),
 * falling 0.25 s (22.5 deg), cruise 112.5 deg in 0.625 s: T = 1.375 s.
 *   t = 0.25: 0.5*360*0.25^2 = 11.25
 *   t = 1.25: 180 - 0.5*720*0.125^2 = 174.375 */
static void test_trapezoid_rises_at_the_accel_limit_and_falls_at_the_decel_limit(void)
{
    SET_F32(DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT, 60.0f);
    SET_F32(DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT, 120.0f);
    START(DARAN_MOVE_TRAPEZOID, 180.0f, 30.0f, 0.0f, 0.0f, DARAN_GIVEN_VEL);
    TEST_ASSERT_TRUE(model.cfg[DARAN_PROP_TRAP_TRAJ_VEL_LIMIT].f32 == 30.0f);
    run(&model, 0.25);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 11.25f, model.pos_sp);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 360.0f, model.acc_sp);
    run(&model, 1.0);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 174.375f, model.pos_sp);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, -720.0f, model.acc_sp);
    run(&model, 0.124);
    TEST_ASSERT_FALSE(model.trajectory_done);
    run(&model, 0.001);
    TEST_ASSERT_TRUE(model.trajectory_done);
    TEST_ASSERT_TRUE(model.pos_sp == 180.0f);
    /* a move's rate sets both limits */
    START(DARAN_MOVE_TRAPEZOID, 0.0f, 0.0f, 0.0f, 240.0f, DARAN_GIVEN_RATE);
    TEST_ASSERT_TRUE(model.cfg[DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT].f32 == 240.0f);
    TEST_ASSERT_TRUE(model.cfg[DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT].f32 == 240.0f);
}

/* Spec 10.1: q with acceleration 0 steps the setpoint to the target at
 * once; only the controller's velocity and torque limits bound the shaft.
 * The same when the stored accel (or decel) limit is written 0. */
static void test_q_with_zero_acceleration_steps_the_setpoint_to_the_target(void)
{
    float top = 0.0f;
    int k;
    SET_F32(DARAN_PROP_SHAFT_VEL_LIMIT, 120.0f);
    START(DARAN_MOVE_TRAPEZOID, 90.0f, 0.0f, 0.0f, 0.0f, DARAN_GIVEN_RATE);
    TEST_ASSERT_TRUE(model.trajectory_done);
    daran_sim_model_tick(&model);
    TEST_ASSERT_TRUE(model.pos_sp == 90.0f);
    TEST_ASSERT_TRUE(model.vel_sp == 0.0f);
    for (k = 0; k < 1000; k++) {
        daran_sim_model_tick(&model);
        top = fabsf(model.vel_rpm) > top ? fabsf(model.vel_rpm) : top;
    }
    NOTE("q with acc 0: top speed %.2f r/min under a 120 r/min limit", (double)top);
    TEST_ASSERT_TRUE(top > 110.0f && top < 125.0f);
    TEST_ASSERT_FLOAT_WITHIN(0.05f, 90.0f, pos());
    /* stored limits of 0 mean the same */
    SET_F32(DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT, 60.0f);
    SET_F32(DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT, 0.0f);
    START(DARAN_MOVE_TRAPEZOID, 0.0f, 0.0f, 0.0f, 0.0f, 0u);
    TEST_ASSERT_TRUE(model.trajectory_done);
    daran_sim_model_tick(&model);
    TEST_ASSERT_TRUE(model.pos_sp == 0.0f);
}

/* Spec 10.1: v ... 0 2 holds the velocity setpoint where it is, for as long
 * as nothing else is commanded; vel_ramp_rate becomes 0. */
static void test_velocity_ramp_at_rate_zero_holds_the_velocity(void)
{
    int k;
    START(DARAN_MOVE_VELOCITY, 0.0f, 30.0f, 0.0f, 0.0f, 0u);
    run(&model, 0.5);
    START(DARAN_MOVE_VELOCITY_RAMP, 0.0f, 100.0f, 0.0f, 0.0f, 0u);
    TEST_ASSERT_TRUE(model.cfg[DARAN_PROP_VEL_RAMP_RATE].f32 == 0.0f);
    TEST_ASSERT_TRUE(model.input_vel == 100.0f);
    for (k = 0; k < 1000; k++) {
        daran_sim_model_tick(&model);
        TEST_ASSERT_TRUE(model.vel_sp == 30.0f);
    }
    TEST_ASSERT_FLOAT_WITHIN(0.1f, 30.0f, model.vel_rpm);
    /* a rate written later starts the ramp from there */
    SET_F32(DARAN_PROP_VEL_RAMP_RATE, 140.0f);
    run(&model, 0.25);
    TEST_ASSERT_FLOAT_WITHIN(0.01f, 65.0f, model.vel_sp);
}

/* c ... 0 6 holds the torque command; torque_ramp_rate becomes 0. */
static void test_torque_ramp_at_rate_zero_holds_the_torque(void)
{
    int k;
    SET_F32(DARAN_PROP_LOAD_INERTIA, 1.0e6f); /* shaft blocked */
    START(DARAN_MOVE_TORQUE, 0.0f, 0.0f, 0.2f, 0.0f, 0u);
    run(&model, 0.5);
    START(DARAN_MOVE_TORQUE_RAMP, 0.0f, 0.0f, 1.0f, 0.0f, 0u);
    TEST_ASSERT_TRUE(model.cfg[DARAN_PROP_TORQUE_RAMP_RATE].f32 == 0.0f);
    for (k = 0; k < 1000; k++) {
        daran_sim_model_tick(&model);
        TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.2f, model.torque_cmd);
    }
}

/* A filter bandwidth written 0 freezes the filtered setpoint where it is. */
static void test_filter_bandwidth_zero_holds_the_setpoint(void)
{
    float held;
    START(DARAN_MOVE_FILTERED_POSITION, 40.0f, 0.0f, 0.0f, 10.0f, DARAN_GIVEN_RATE);
    run(&model, 0.1);
    SET_F32(DARAN_PROP_INPUT_FILTER_BANDWIDTH, 0.0f);
    daran_sim_model_tick(&model);
    held = model.pos_sp;
    TEST_ASSERT_TRUE(held > 1.0f && held < 39.0f);
    run(&model, 1.0);
    TEST_ASSERT_TRUE(model.pos_sp == held);
    TEST_ASSERT_TRUE(model.vel_sp == 0.0f);
    TEST_ASSERT_FLOAT_WITHIN(0.05f, held, pos());
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
static void test_timed_moves_of_three_distances_end_on_the_planned_tick(void)
{
    static daran_sim_model_t drives[3];
    static const float dist[3] = {30.0f, -60.0f, 90.0f};
    int mode;
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
            TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_move(&drives[i], &mv));
            TEST_ASSERT_TRUE(drives[i].trap_tc > 0.0f); /* they all cruise */
        }
        TEST_ASSERT_FLOAT_WITHIN(1e-3f, 8.787f, drives[2].trap_vmax / 6.0f);
        for (k = 1; k <= 2000; k++) {
            for (i = 0; i < 3; i++) {
                daran_sim_model_tick(&drives[i]);
                TEST_ASSERT_EQUAL_INT64(k == 2000, drives[i].trajectory_done);
            }
        }
        for (i = 0; i < 3; i++) {
            TEST_ASSERT_TRUE(drives[i].pos_sp == dist[i]);
        }
    }
}

/* D41: a TRAPEZOID with nothing given (what the core sends for `q id pos`
 * and for an `mq` whose distance from the running move's end is 0, as the
 * vendor library's repeated set_angles() makes) to the running plan's own
 * target leaves the plan alone: the setpoint follows, tick by tick, the
 * same path as a drive that was never told twice, and the move ends on its
 * planned tick (2000, T = 2 s) exactly on the target. Trapezoid and S-curve.
 * Another target, a given rate, or the same target after the plan ended
 * plans anew. */
static void test_same_target_with_nothing_given_keeps_the_running_plan(void)
{
    static daran_sim_model_t reference;
    int mode;
    for (mode = 1; mode <= 2; mode++) {
        double a = mode == 1 ? 30.0 : 60.0;
        daran_move_t timed = {DARAN_MOVE_TRAPEZOID, DARAN_GIVEN_VEL | DARAN_GIVEN_RATE,
                              90.0f, 0.0f, 0.0f, (float)a, 0.0f, 0.0f};
        long k;
        timed.vel_rpm = (float)cruise_for(90.0, 2.0, a, mode);
        daran_sim_model_init(&reference, 1000u);
        daran_sim_model_init(&model, 1000u);
        reference.cfg[DARAN_PROP_TRAJ_MODE].u32 = (uint32_t)mode;
        model.cfg[DARAN_PROP_TRAJ_MODE].u32 = (uint32_t)mode;
        TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_move(&reference, &timed));
        TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_move(&model, &timed));
        for (k = 1; k <= 2000; k++) {
            if (k == 300 || k == 1999) { /* in the ramp, and on the last tick but one */
                START(DARAN_MOVE_TRAPEZOID, 90.0f, 0.0f, 0.0f, 0.0f, 0u);
                TEST_ASSERT_FALSE(model.trajectory_done);
                TEST_ASSERT_TRUE(model.mode == DARAN_SIM_MODE_TRAPEZOID);
            }
            daran_sim_model_tick(&reference);
            daran_sim_model_tick(&model);
            TEST_ASSERT_TRUE(model.pos_sp == reference.pos_sp);
            TEST_ASSERT_TRUE(model.vel_sp == reference.vel_sp);
            TEST_ASSERT_EQUAL_INT64(k == 2000, model.trajectory_done);
        }
        TEST_ASSERT_TRUE(model.pos_sp == 90.0f);
        /* done: the same target again is a plan of length 0, done at once */
        START(DARAN_MOVE_TRAPEZOID, 90.0f, 0.0f, 0.0f, 0.0f, 0u);
        TEST_ASSERT_TRUE(model.trajectory_done);
        TEST_ASSERT_TRUE(model.pos_sp == 90.0f);
        /* another target while a plan runs: a new plan from the setpoint */
        START(DARAN_MOVE_TRAPEZOID, 0.0f, 0.0f, 0.0f, 0.0f, 0u);
        run(&model, 0.5);
        START(DARAN_MOVE_TRAPEZOID, 45.0f, 0.0f, 0.0f, 0.0f, 0u);
        TEST_ASSERT_TRUE(model.trap_target == 45.0f);
        TEST_ASSERT_TRUE(model.trap_start == model.pos_sp);
        TEST_ASSERT_EQUAL_UINT32(0u, model.trap_ticks);
        /* something given: a new plan even to the same target */
        run(&model, 0.1);
        START(DARAN_MOVE_TRAPEZOID, 45.0f, 0.0f, 0.0f, (float)a, DARAN_GIVEN_RATE);
        TEST_ASSERT_EQUAL_UINT32(0u, model.trap_ticks);
    }
}

/* S-curve too short to reach its cruise: the S-curve triangle. 10 deg at
 * 60 (r/min)/s (A = 360 deg/s^2) with a cruise of 100 r/min: peak
 * v = sqrt(a D / 12) = sqrt(50) = 7.071 r/min (42.43 deg/s), T = 4v/a =
 * 0.4714 s: done on tick 472. */
static void test_short_s_curve_is_the_s_curve_triangle(void)
{
    float peak = 0.0f;
    long k;
    SET_U32(DARAN_PROP_TRAJ_MODE, 2u);
    START(DARAN_MOVE_TRAPEZOID, 10.0f, 100.0f, 0.0f, 60.0f, DARAN_GIVEN_VEL | DARAN_GIVEN_RATE);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 42.4264f, model.trap_vmax);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.471405f, model.trap_total);
    for (k = 1; k <= 472; k++) {
        daran_sim_model_tick(&model);
        peak = model.vel_sp > peak ? model.vel_sp : peak;
        TEST_ASSERT_EQUAL_INT64(k == 472, model.trajectory_done);
    }
    TEST_ASSERT_FLOAT_WITHIN(0.01f, 7.071f, peak);
    TEST_ASSERT_TRUE(model.pos_sp == 10.0f);
}

/* S-curve q 1 270 30 60: V = 180 deg/s, A = 360 deg/s^2; each phase lasts
 * 2V/A = 1 s and covers V^2/A = 90 deg with jerk A^2/V = 720 deg/s^3; the
 * cruise 90 deg takes 0.5 s: T = 2.5 s.
 *   t = 0.5: pos = J t^3/6 = 15 deg, vel = V/2 = 15 r/min, acc = A = 360
 *   t = 1.0: pos = 90, vel = 30 r/min, acc = 0
 * Position, velocity and acceleration change by at most one tick's worth
 * of their derivative: nothing jumps, at the start, the phase changes or the
 * end. */
static void test_s_curve_is_continuous_in_position_velocity_and_acceleration(void)
{
    const float jerk = 720.0f;
    float prev_pos = 0.0f;
    float prev_vel = 0.0f;
    float prev_acc = 0.0f;
    float worst_jump = 0.0f;
    long k;
    SET_U32(DARAN_PROP_TRAJ_MODE, 2u);
    START(DARAN_MOVE_TRAPEZOID, 270.0f, 30.0f, 0.0f, 60.0f, DARAN_GIVEN_VEL | DARAN_GIVEN_RATE);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 2.5f, model.trap_total);
    for (k = 1; k <= 2600; k++) {
        float vel_deg_s;
        daran_sim_model_tick(&model);
        vel_deg_s = model.vel_sp * 6.0f;
        TEST_ASSERT_TRUE(fabsf(model.pos_sp - prev_pos) <= 180.0f * 0.001f + 1e-3f);
        TEST_ASSERT_TRUE(fabsf(vel_deg_s - prev_vel) <= 360.0f * 0.001f + 1e-3f);
        TEST_ASSERT_TRUE(fabsf(model.acc_sp - prev_acc) <= jerk * 0.001f + 1e-3f);
        if (fabsf(model.acc_sp - prev_acc) > worst_jump) {
            worst_jump = fabsf(model.acc_sp - prev_acc);
        }
        /* the velocity's slope is the acceleration */
        TEST_ASSERT_FLOAT_WITHIN(1.0f, 0.5f * (model.acc_sp + prev_acc),
                                 (vel_deg_s - prev_vel) / 0.001f);
        prev_pos = model.pos_sp;
        prev_vel = vel_deg_s;
        prev_acc = model.acc_sp;
        if (k == 500) {
            TEST_ASSERT_FLOAT_WITHIN(1e-3f, 15.0f, model.pos_sp);
            TEST_ASSERT_FLOAT_WITHIN(1e-4f, 15.0f, model.vel_sp);
            TEST_ASSERT_FLOAT_WITHIN(1e-2f, 360.0f, model.acc_sp);
        } else if (k == 1000) {
            TEST_ASSERT_FLOAT_WITHIN(1e-3f, 90.0f, model.pos_sp);
            TEST_ASSERT_FLOAT_WITHIN(1e-4f, 30.0f, model.vel_sp);
            TEST_ASSERT_FLOAT_WITHIN(1e-2f, 0.0f, model.acc_sp);
        }
        TEST_ASSERT_EQUAL_INT64(k >= 2500, model.trajectory_done);
    }
    NOTE("S-curve: largest change of acceleration in one tick %.4f deg/s^2 (jerk x dt "
         "= 0.72)", (double)worst_jump);
    TEST_ASSERT_TRUE(model.pos_sp == 270.0f);
    TEST_ASSERT_FLOAT_WITHIN(0.05f, 270.0f, pos());
}

/* S-curve with accel 60 and decel 120 (r/min)/s, 270 deg at 30 r/min:
 * V = 180 deg/s; rising 2V/A1 = 1 s over 90 deg, falling 2V/A2 = 0.5 s over
 * 45 deg (jerk A2^2/V = 2880 deg/s^3), cruise 135 deg in 0.75 s: T = 2.25 s.
 * At t = 2.0 (0.25 s before the end, mid-fall) the remaining distance is
 * J*0.25^3/6 = V^2/(6 A2) = 7.5 deg: 262.5 deg, acceleration -A2 = -720. */
static void test_s_curve_with_unequal_rates_ends_on_time_and_stays_continuous(void)
{
    float prev_acc = 0.0f;
    long k;
    SET_U32(DARAN_PROP_TRAJ_MODE, 2u);
    SET_F32(DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT, 120.0f);
    START(DARAN_MOVE_TRAPEZOID, 270.0f, 30.0f, 0.0f, 0.0f, DARAN_GIVEN_VEL);
    for (k = 1; k <= 2300; k++) {
        daran_sim_model_tick(&model);
        TEST_ASSERT_TRUE(fabsf(model.acc_sp - prev_acc) <= 2880.0f * 0.001f + 1e-3f);
        prev_acc = model.acc_sp;
        if (k == 2000) {
            TEST_ASSERT_FLOAT_WITHIN(1e-3f, 262.5f, model.pos_sp);
            TEST_ASSERT_FLOAT_WITHIN(1e-2f, -720.0f, model.acc_sp);
        }
        TEST_ASSERT_EQUAL_INT64(k >= 2250, model.trajectory_done);
    }
    TEST_ASSERT_TRUE(model.pos_sp == 270.0f);
}

/* ---- turn 2: faults and error registers ---- */

/* Stall limiter: 15 A (1.5 Nm) into a blocked shaft, limit 10 A for 0.5 s:
 * the current reaches 10 A within 2 ms (current loop 1000 rad/s), so the
 * trip comes between 0.50 and 0.51 s. */
static void test_stall_limiter_trips_after_its_time_at_its_current(void)
{
    SET_F32(DARAN_PROP_LOAD_INERTIA, 1.0e6f);
    SET_U32(DARAN_PROP_ENABLE_CURRENT_MODE_VEL_LIMIT, 0u);
    SET_F32(DARAN_PROP_STALL_CURRENT_LIMIT, 10.0f);
    SET_F32(DARAN_PROP_STALL_TIME_LIMIT, 0.5f);
    START(DARAN_MOVE_TORQUE, 0.0f, 0.0f, 1.5f, 0.0f, 0u);
    run(&model, 2.0); /* the limiter is off by default */
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_CLOSED_LOOP, model.state);
    SET_U32(DARAN_PROP_ENABLE_STALL_LIMIT, 1u);
    run(&model, 0.5);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_CLOSED_LOOP, model.state);
    run(&model, 0.01);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_IDLE, model.state);
    TEST_ASSERT_EQUAL_INT64(DARAN_MOTOR_ERROR_STALL, model.motor_error);
    TEST_ASSERT_EQUAL_INT64(DARAN_FLAG_MOTOR_FAILED, model.error);
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_MOTOR_FAULT, daran_sim_model_closed_loop(&model));
}

static void test_stall_fault_trips_the_limiter_at_the_next_tick(void)
{
    daran_move_t mv = {DARAN_MOVE_PASSTHROUGH, 0u, 10.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    daran_sim_model_fault(&model, DARAN_SIM_FAULT_STALL);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_CLOSED_LOOP, model.state);
    daran_sim_model_tick(&model);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_IDLE, model.state);
    TEST_ASSERT_EQUAL_INT64(DARAN_MOTOR_ERROR_STALL, model.motor_error);
    TEST_ASSERT_EQUAL_INT64(DARAN_FLAG_MOTOR_FAILED, model.error);
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_MOTOR_FAULT, daran_sim_model_move(&model, &mv));
    run(&model, 1.0); /* it does not come back by itself */
    daran_sim_model_clear_errors(&model);
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_closed_loop(&model));
    run(&model, 0.1);
    TEST_ASSERT_EQUAL_INT64(0u, model.error);
}

/* The overspeed fault throws the shaft to 1.5 x 600 x 1.2 = 1080 r/min.
 * With enable_overspeed_error 0 (default) nothing trips and the controller
 * brakes the shaft back; with 1 the next tick trips. */
static void test_overspeed_trips_the_controller_only_when_enabled(void)
{
    daran_sim_model_fault(&model, DARAN_SIM_FAULT_OVERSPEED);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 1080.0f, model.vel_rpm);
    run(&model, 1.0);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_CLOSED_LOOP, model.state);
    TEST_ASSERT_EQUAL_INT64(0u, model.controller_error);
    TEST_ASSERT_FLOAT_WITHIN(1.0f, 0.0f, model.vel_rpm);
    run(&model, 1.0);
    TEST_ASSERT_FLOAT_WITHIN(0.05f, 0.0f, pos()); /* back where it was held */
    SET_U32(DARAN_PROP_ENABLE_OVERSPEED_ERROR, 1u);
    daran_sim_model_fault(&model, DARAN_SIM_FAULT_OVERSPEED);
    daran_sim_model_tick(&model);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_IDLE, model.state);
    TEST_ASSERT_EQUAL_INT64(DARAN_CONTROLLER_ERROR_OVERSPEED, model.controller_error);
    TEST_ASSERT_EQUAL_INT64(DARAN_FLAG_CONTROLLER_FAILED, model.error);
}

/* A real over-speed: spinning at 300 r/min when vel_limit drops to 100
 * (x 1.2 = 120): the next tick trips. */
static void test_overspeed_error_trips_beyond_vel_limit_times_tolerance(void)
{
    SET_U32(DARAN_PROP_ENABLE_OVERSPEED_ERROR, 1u);
    START(DARAN_MOVE_VELOCITY, 0.0f, 300.0f, 0.0f, 0.0f, 0u);
    run(&model, 1.0);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_CLOSED_LOOP, model.state);
    SET_F32(DARAN_PROP_SHAFT_VEL_LIMIT, 100.0f);
    daran_sim_model_tick(&model);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_IDLE, model.state);
    TEST_ASSERT_EQUAL_INT64(DARAN_CONTROLLER_ERROR_OVERSPEED, model.controller_error);
}

/* Writing 0 to one register clears that register only; the drive stays
 * idle, and a sub-register still set keeps closed loop refused. */
static void test_writing_zero_clears_one_register_and_the_drive_stays_idle(void)
{
    daran_value_t v;
    daran_sim_model_fault(&model, DARAN_SIM_FAULT_STALL);
    daran_sim_model_fault(&model, DARAN_SIM_FAULT_OVERTEMP);
    daran_sim_model_tick(&model);
    TEST_ASSERT_EQUAL_INT64(DARAN_FLAG_MOTOR_FAILED | DARAN_FLAG_OVERTEMP, model.error);
    run(&model, 10.0); /* cool down below the limits */
    v.u64 = 1u;
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_OUT_OF_RANGE,
                            daran_sim_model_set(&model, DARAN_PROP_MOTOR_ERROR, v));
    SET_U32(DARAN_PROP_AXIS_ERROR, 0u);
    TEST_ASSERT_EQUAL_INT64(0u, model.error);
    TEST_ASSERT_EQUAL_INT64(DARAN_MOTOR_ERROR_STALL, model.motor_error);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_IDLE, model.state);
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_MOTOR_FAULT, daran_sim_model_closed_loop(&model));
    SET_U32(DARAN_PROP_MOTOR_ERROR, 0u);
    SET_U32(DARAN_PROP_FET_THERMISTOR_ERROR, 0u);
    TEST_ASSERT_EQUAL_INT64(DARAN_ERR_MOTOR_FAULT, daran_sim_model_closed_loop(&model));
    SET_U32(DARAN_PROP_MOTOR_THERMISTOR_ERROR, 0u);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_IDLE, model.state);
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_closed_loop(&model));
}

static void test_clear_errors_clears_every_register_and_the_warnings(void)
{
    daran_sim_model_trip(&model, DARAN_FLAG_ESTOP | DARAN_FLAG_WATCHDOG);
    model.motor_error = DARAN_MOTOR_ERROR_STALL;
    model.controller_error = DARAN_CONTROLLER_ERROR_OVERSPEED;
    model.encoder_error = 0x4u;
    model.fet_thermistor_error = 1u;
    model.motor_thermistor_error = 1u;
    model.can_error = 0x8u;
    model.config_warnings = DARAN_WARNING_NVM_CORRUPT;
    daran_sim_model_clear_errors(&model);
    TEST_ASSERT_EQUAL_INT64(0u, model.error | model.motor_error | model.controller_error |
                            model.encoder_error | model.fet_thermistor_error |
                            model.motor_thermistor_error | model.can_error | model.config_warnings);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_IDLE, model.state);
}

/* The trip level is config.dc_bus_undervoltage_trip_level; the fault sags
 * 2 V below it, so a level of 0 never trips. */
static void test_undervoltage_trip_level_is_the_property(void)
{
    SET_F32(DARAN_PROP_DC_BUS_UNDERVOLTAGE_TRIP_LEVEL, 25.0f);
    daran_sim_model_tick(&model);
    TEST_ASSERT_EQUAL_INT64(DARAN_FLAG_UNDERVOLTAGE, model.error);
    daran_sim_model_clear_errors(&model);
    SET_F32(DARAN_PROP_DC_BUS_UNDERVOLTAGE_TRIP_LEVEL, 0.0f);
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_closed_loop(&model));
    daran_sim_model_fault(&model, DARAN_SIM_FAULT_UNDERVOLTAGE);
    run(&model, 0.05);
    TEST_ASSERT_TRUE(model.vbus_v == 0.0f);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_CLOSED_LOOP, model.state);
    run(&model, 0.1);
    TEST_ASSERT_TRUE(model.vbus_v > 23.9f);
}

static void test_startup_closed_loop_control_zero_boots_idle_without_a_flag(void)
{
    SET_U32(DARAN_PROP_STARTUP_CLOSED_LOOP_CONTROL, 0u);
    daran_sim_model_boot(&model);
    TEST_ASSERT_EQUAL_INT64(DARAN_STATE_IDLE, model.state);
    TEST_ASSERT_EQUAL_INT64(0u, model.error);
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_closed_loop(&model));
}

/* enable_damp_idle: in idle the shorted windings brake the shaft with
 * kt^2/R = 0.0333 Nm/(rad/s); from 300 r/min it stops far sooner than on
 * friction alone. */
static void test_damp_idle_brakes_a_coasting_shaft(void)
{
    float free_vel;
    START(DARAN_MOVE_VELOCITY, 0.0f, 300.0f, 0.0f, 0.0f, 0u);
    run(&model, 1.0);
    daran_sim_model_trip(&model, 0u);
    run(&model, 0.1);
    free_vel = model.vel_rpm;
    TEST_ASSERT_TRUE(free_vel > 200.0f);
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_closed_loop(&model));
    START(DARAN_MOVE_VELOCITY, 0.0f, 300.0f, 0.0f, 0.0f, 0u);
    run(&model, 1.0);
    SET_U32(DARAN_PROP_ENABLE_DAMP_IDLE, 1u);
    daran_sim_model_trip(&model, 0u);
    run(&model, 0.1);
    TEST_ASSERT_TRUE(model.vel_rpm < 1.0f);
}

/* ---- turn 2: modes ---- */

static void expect_modes_at(int line, uint32_t control, uint32_t input)
{
    daran_value_t v;
    UNITY_TEST_ASSERT_EQUAL_INT64(DARAN_OK,
                                  daran_sim_model_get(&model, DARAN_PROP_CONTROL_MODE, &v), line,
                                  "control_mode unreadable");
    UNITY_TEST_ASSERT_EQUAL_INT64(control, v.u32, line, "control_mode");
    UNITY_TEST_ASSERT_EQUAL_INT64(DARAN_OK,
                                  daran_sim_model_get(&model, DARAN_PROP_INPUT_MODE, &v), line,
                                  "input_mode unreadable");
    UNITY_TEST_ASSERT_EQUAL_INT64(input, v.u32, line, "input_mode");
}
/* The model's control_mode and input_mode read back these. */
#define EXPECT_MODES(control, input) expect_modes_at(__LINE__, (control), (input))

static void test_control_and_input_modes_read_back_the_last_command(void)
{
    daran_move_t d = {DARAN_MOVE_IMPEDANCE, 0u, 0.0f, 0.0f, 0.0f, 0.0f, 0.01f, 0.001f};
    EXPECT_MODES(3u, 1u); /* holding position after power-up */
    START(DARAN_MOVE_FILTERED_POSITION, 5.0f, 0.0f, 0.0f, 0.0f, 0u);
    EXPECT_MODES(3u, 3u);
    START(DARAN_MOVE_TRAPEZOID, 5.0f, 0.0f, 0.0f, 0.0f, 0u);
    EXPECT_MODES(3u, 5u);
    START(DARAN_MOVE_PASSTHROUGH, 5.0f, 0.0f, 0.0f, 0.0f, 0u);
    EXPECT_MODES(3u, 1u);
    START(DARAN_MOVE_VELOCITY, 0.0f, 5.0f, 0.0f, 0.0f, 0u);
    EXPECT_MODES(2u, 1u);
    START(DARAN_MOVE_VELOCITY_RAMP, 0.0f, 5.0f, 0.0f, 10.0f, 0u);
    EXPECT_MODES(2u, 2u);
    START(DARAN_MOVE_TORQUE, 0.0f, 0.0f, 0.1f, 0.0f, 0u);
    EXPECT_MODES(1u, 1u);
    START(DARAN_MOVE_TORQUE_RAMP, 0.0f, 0.0f, 0.1f, 1.0f, 0u);
    EXPECT_MODES(1u, 6u);
    TEST_ASSERT_EQUAL_INT64(DARAN_OK, daran_sim_model_move(&model, &d));
    EXPECT_MODES(3u, 9u);
    SET_F32(DARAN_PROP_VEL_SETPOINT, 1.0f);
    EXPECT_MODES(2u, 1u);
    SET_F32(DARAN_PROP_TORQUE_SETPOINT, 0.0f);
    EXPECT_MODES(1u, 1u);
    SET_F32(DARAN_PROP_POS_SETPOINT, 0.0f);
    EXPECT_MODES(3u, 1u);
}

/* ODrive style: writing input_mode/control_mode switches the controller
 * from the current inputs; input_mode 5 then input_pos plans a trapezoid
 * with the stored limits (600 r/min, 60 (r/min)/s: 90 deg is a 1 s
 * triangle). */
static void test_writing_the_modes_switches_the_controller_from_the_inputs(void)
{
    SET_U32(DARAN_PROP_INPUT_MODE, 5u);
    EXPECT_MODES(3u, 5u);
    TEST_ASSERT_TRUE(model.trajectory_done); /* already at input_pos */
    SET_F32(DARAN_PROP_INPUT_POS, 90.0f);
    TEST_ASSERT_FALSE(model.trajectory_done);
    run(&model, 0.999);
    TEST_ASSERT_FALSE(model.trajectory_done);
    run(&model, 0.001);
    TEST_ASSERT_TRUE(model.trajectory_done);
    TEST_ASSERT_TRUE(model.pos_sp == 90.0f);
    /* velocity control from input_vel */
    SET_F32(DARAN_PROP_INPUT_VEL, 20.0f);
    SET_U32(DARAN_PROP_CONTROL_MODE, 2u);
    EXPECT_MODES(2u, 1u);
    run(&model, 0.5);
    TEST_ASSERT_FLOAT_WITHIN(0.2f, 20.0f, model.vel_rpm);
    /* ramp from there to input_vel at vel_ramp_rate (60 (r/min)/s) */
    SET_F32(DARAN_PROP_INPUT_VEL, 50.0f);
    SET_U32(DARAN_PROP_INPUT_MODE, 2u);
    EXPECT_MODES(2u, 2u);
    run(&model, 0.25);
    TEST_ASSERT_FLOAT_WITHIN(0.5f, 35.0f, model.vel_sp);
    /* torque control from input_torque */
    SET_F32(DARAN_PROP_INPUT_TORQUE, 0.05f);
    SET_U32(DARAN_PROP_CONTROL_MODE, 1u);
    EXPECT_MODES(1u, 1u);
    daran_sim_model_tick(&model);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.05f, model.torque_cmd);
    SET_U32(DARAN_PROP_INPUT_MODE, 6u);
    EXPECT_MODES(1u, 6u);
    /* back to position control: passthrough toward input_pos (90), with
     * input_vel and input_torque as its feed-forwards */
    SET_F32(DARAN_PROP_INPUT_VEL, 0.0f);
    SET_F32(DARAN_PROP_INPUT_TORQUE, 0.0f);
    SET_U32(DARAN_PROP_CONTROL_MODE, 3u);
    EXPECT_MODES(3u, 1u);
    SET_U32(DARAN_PROP_INPUT_MODE, 3u);
    EXPECT_MODES(3u, 3u);
    SET_U32(DARAN_PROP_INPUT_MODE, 9u);
    EXPECT_MODES(3u, 9u);
    SET_U32(DARAN_PROP_INPUT_MODE, 1u);
    EXPECT_MODES(3u, 1u);
    run(&model, 3.0);
    TEST_ASSERT_FLOAT_WITHIN(0.05f, 90.0f, pos());
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_power_up_is_closed_loop_at_rest);
    RUN_TEST(test_ten_degree_step_settles_in_under_0_3_s_without_overshoot);
    RUN_TEST(test_q_setpoint_follows_the_analytic_trapezoid_and_ends_on_target);
    RUN_TEST(test_q_too_short_for_its_cruise_velocity_runs_a_triangle);
    RUN_TEST(test_q_without_vel_and_acc_uses_the_drive_settings);
    RUN_TEST(test_v_ramp_has_the_commanded_slope);
    RUN_TEST(test_c_ramp_has_the_commanded_slope);
    RUN_TEST(test_d_torque_is_the_impedance_law_every_tick);
    RUN_TEST(test_t_stream_is_followed_smoothly);
    RUN_TEST(test_t_step_does_not_overshoot);
    RUN_TEST(test_torque_is_clamped_by_the_lowest_limit);
    RUN_TEST(test_velocity_is_clamped_by_the_lowest_limit);
    RUN_TEST(test_software_limits_hold_in_every_mode);
    RUN_TEST(test_set_zero_moves_nothing);
    RUN_TEST(test_estop_then_clear_then_closed_loop_moves_again);
    RUN_TEST(test_watchdog_trips_when_not_fed_in_time);
    RUN_TEST(test_overtemp_fault_trips_enabled_thermistors_at_the_next_tick);
    RUN_TEST(test_sustained_current_heats_the_motor_until_it_trips);
    RUN_TEST(test_derating_keeps_the_motor_below_its_trip_temperature);
    RUN_TEST(test_electrical_quantities_follow_the_torque);
    RUN_TEST(test_undervoltage_sag_trips_and_recovers);
    RUN_TEST(test_writing_setpoints_sets_the_matching_input);
    RUN_TEST(test_q_ends_on_its_planned_tick_at_8_khz_too);
    RUN_TEST(test_trapezoid_rises_at_the_accel_limit_and_falls_at_the_decel_limit);
    RUN_TEST(test_q_with_zero_acceleration_steps_the_setpoint_to_the_target);
    RUN_TEST(test_velocity_ramp_at_rate_zero_holds_the_velocity);
    RUN_TEST(test_torque_ramp_at_rate_zero_holds_the_torque);
    RUN_TEST(test_filter_bandwidth_zero_holds_the_setpoint);
    RUN_TEST(test_timed_moves_of_three_distances_end_on_the_planned_tick);
    RUN_TEST(test_same_target_with_nothing_given_keeps_the_running_plan);
    RUN_TEST(test_short_s_curve_is_the_s_curve_triangle);
    RUN_TEST(test_s_curve_is_continuous_in_position_velocity_and_acceleration);
    RUN_TEST(test_s_curve_with_unequal_rates_ends_on_time_and_stays_continuous);
    RUN_TEST(test_stall_limiter_trips_after_its_time_at_its_current);
    RUN_TEST(test_stall_fault_trips_the_limiter_at_the_next_tick);
    RUN_TEST(test_overspeed_trips_the_controller_only_when_enabled);
    RUN_TEST(test_overspeed_error_trips_beyond_vel_limit_times_tolerance);
    RUN_TEST(test_writing_zero_clears_one_register_and_the_drive_stays_idle);
    RUN_TEST(test_clear_errors_clears_every_register_and_the_warnings);
    RUN_TEST(test_undervoltage_trip_level_is_the_property);
    RUN_TEST(test_startup_closed_loop_control_zero_boots_idle_without_a_flag);
    RUN_TEST(test_damp_idle_brakes_a_coasting_shaft);
    RUN_TEST(test_control_and_input_modes_read_back_the_last_command);
    RUN_TEST(test_writing_the_modes_switches_the_controller_from_the_inputs);
    return UNITY_END();
}
