/* Every property of the protocol's table on the simulated drive
 * (protocol.md 10.2): each reads, each read-write one takes a new value and
 * gives it back; the rotor-side views agree with the output shaft through
 * config.extra_setting.gear_ratio (output = rotor / ratio) whichever side is
 * written; the encoder's absolute readings; measured motor values; the
 * serial number's halves. Driven through the drive's HAL, no protocol core. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "sim_drive.h"

static daran_sim_drive_t drive;
static daran_sim_model_t *const m = &drive.model;

static const daran_prop_type_t prop_type[DARAN_PROP_COUNT] = {
#define TYPE_(id, path, scope, type, access, range, unit) DARAN_TYPE_##type,
    DARAN_PROPERTY_LIST(TYPE_)
#undef TYPE_
};

static const daran_range_t prop_range[DARAN_PROP_COUNT] = {
#define RANGE_(id, path, scope, type, access, range, unit) DARAN_RANGE_##range,
    DARAN_PROPERTY_LIST(RANGE_)
#undef RANGE_
};

#define RW_1 1
#define RO_1 0
static const int prop_rw[DARAN_PROP_COUNT] = {
#define RW_(id, path, scope, type, access, range, unit) access##_1,
    DARAN_PROPERTY_LIST(RW_)
#undef RW_
};

static const char *const prop_path[DARAN_PROP_COUNT] = {
#define PATH_(id, path, scope, type, access, range, unit) path,
    DARAN_PROPERTY_LIST(PATH_)
#undef PATH_
};

static int setup(void **state)
{
    (void)state;
    daran_sim_drive_init(&drive, 0u, 1000u);
    return 0;
}

static daran_value_t get(daran_prop_t prop)
{
    daran_value_t v;
    v.u64 = 0u;
    assert_int_equal(daran_sim_hal.get(&drive, prop, &v), DARAN_OK);
    return v;
}

static float getf(daran_prop_t prop)
{
    return get(prop).f32;
}

static void setf(daran_prop_t prop, float x)
{
    daran_value_t v;
    v.u64 = 0u;
    v.f32 = x;
    assert_int_equal(daran_sim_hal.set(&drive, prop, v), DARAN_OK);
}

static void setu(daran_prop_t prop, uint32_t x)
{
    daran_value_t v;
    v.u64 = 0u;
    v.u32 = x;
    assert_int_equal(daran_sim_hal.set(&drive, prop, v), DARAN_OK);
}

static void run(double seconds)
{
    long n = lround(seconds * (double)m->tick_hz);
    long k;
    for (k = 0; k < n; k++) {
        daran_sim_model_tick(m);
    }
}

/* Equal to float rounding (the views convert on the way in and out). */
static void assert_close(float got, float want)
{
    float tol = 1e-5f * (fabsf(want) > 1.0f ? fabsf(want) : 1.0f);
    if (!(fabsf(got - want) <= tol)) {
        fail_msg("got %.9g, want %.9g", (double)got, (double)want);
    }
}

/* A value the property's range accepts, different from @p now. */
static daran_value_t new_value(daran_prop_t prop, daran_value_t now)
{
    daran_value_t v;
    v.u64 = 0u;
    switch (prop_range[prop]) {
    case DARAN_RANGE_BOOL: v.u32 = 1u - now.u32; return v;
    case DARAN_RANGE_ZERO: v.u32 = 0u; return v;
    case DARAN_RANGE_NODE_ID: v.u32 = 5u; return v;
    case DARAN_RANGE_UART_BAUD: v.u32 = 9600u; return v;
    case DARAN_RANGE_CAN_BAUD: v.u32 = 500000u; return v;
    case DARAN_RANGE_CAN_PROTOCOL: v.u32 = 0u; return v;
    case DARAN_RANGE_AXIS_STATE: v.u32 = DARAN_STATE_IDLE; return v;
    case DARAN_RANGE_CONTROL_MODE: v.u32 = 2u; return v;
    case DARAN_RANGE_INPUT_MODE: v.u32 = 2u; return v;
    case DARAN_RANGE_TRAJ_MODE: v.u32 = 2u; return v;
    case DARAN_RANGE_DIRECTION: v.s32 = -1; return v;
    case DARAN_RANGE_MOTOR_TYPE: v.u32 = 2u; return v;
    case DARAN_RANGE_POLE_PAIRS: v.s32 = 14; return v;
    default:
        break;
    }
    switch (prop_type[prop]) {
    case DARAN_TYPE_F32: v.f32 = now.f32 == 0.0f ? 0.5f : now.f32 * 1.25f; break;
    case DARAN_TYPE_S32: v.s32 = now.s32 == 0 ? 7 : now.s32 / 2; break;
    default: v.u32 = now.u32 + 1u; break;
    }
    return v;
}

static void test_every_property_reads_and_every_writable_one_takes_a_new_value(void **state)
{
    int p;
    int rw = 0;
    (void)state;
    for (p = 0; p < (int)DARAN_PROP_COUNT; p++) {
        daran_prop_t prop = (daran_prop_t)p;
        daran_value_t now = get(prop);
        daran_value_t want;
        daran_value_t back;
        if (prop_type[p] == DARAN_TYPE_F32 && !isfinite(now.f32)) {
            fail_msg("%s reads %g", prop_path[p], (double)now.f32);
        }
        if (!prop_rw[p]) {
            assert_int_equal(daran_sim_hal.set(&drive, prop, now), DARAN_ERR_READ_ONLY);
            continue;
        }
        rw++;
        want = new_value(prop, now);
        if (daran_sim_hal.set(&drive, prop, want) != DARAN_OK) {
            fail_msg("w %s refused", prop_path[p]);
        }
        back = get(prop);
        if (prop_type[p] == DARAN_TYPE_F32) {
            assert_close(back.f32, want.f32);
        } else if (back.u32 != want.u32) {
            fail_msg("%s: wrote %u, read %u", prop_path[p], want.u32, back.u32);
        }
        if (prop == DARAN_PROP_REQUESTED_STATE) {
            setu(prop, DARAN_STATE_CLOSED_LOOP);
            assert_int_equal(get(DARAN_PROP_CURRENT_STATE).u32, DARAN_STATE_CLOSED_LOOP);
        }
    }
    print_message("%d properties read, %d of them written and read back\n", p, rw);
    /* the drive still runs */
    run(0.5);
    assert_true(isfinite(getf(DARAN_PROP_POS_ESTIMATE)));
}

static void test_error_registers_take_only_zero(void **state)
{
    static const daran_prop_t regs[] = {
        DARAN_PROP_AXIS_ERROR,        DARAN_PROP_MOTOR_ERROR,          DARAN_PROP_CONTROLLER_ERROR,
        DARAN_PROP_ENCODER_ERROR,     DARAN_PROP_FET_THERMISTOR_ERROR, DARAN_PROP_MOTOR_THERMISTOR_ERROR,
        DARAN_PROP_CAN_ERROR,         DARAN_PROP_CONFIG_WARNINGS,
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof regs / sizeof regs[0]; i++) {
        daran_value_t v;
        v.u64 = 0u;
        v.u32 = 1u;
        assert_int_equal(daran_sim_hal.set(&drive, regs[i], v), DARAN_ERR_OUT_OF_RANGE);
        setu(regs[i], 0u);
    }
}

/* Gear ratio g: rotor = output x g. Position 36 deg = 0.1 g turn; 60 r/min =
 * g turn/s; 1 Nm at the shaft = 1/g Nm at the rotor; inertia / g^2; 16384
 * steps per output turn = g/16384 rotor turns per step. */
static void check_views(float g)
{
    setf(DARAN_PROP_GEAR_RATIO, g);
    /* configuration: write the shaft side, read the rotor side */
    setf(DARAN_PROP_TORQUE_CONSTANT, 0.2f);
    assert_close(getf(DARAN_PROP_MOTOR_TORQUE_CONSTANT), 0.2f / g);
    setf(DARAN_PROP_STEPS_PER_TURN, 16384.0f);
    assert_close(getf(DARAN_PROP_TURNS_PER_STEP), g / 16384.0f);
    setf(DARAN_PROP_VEL_RAMP_RATE, 120.0f);
    assert_close(getf(DARAN_PROP_CONTROLLER_VEL_RAMP_RATE), 2.0f * g);
    setf(DARAN_PROP_TORQUE_RAMP_RATE, 3.0f);
    assert_close(getf(DARAN_PROP_CONTROLLER_TORQUE_RAMP_RATE), 3.0f / g);
    setf(DARAN_PROP_LOAD_INERTIA, 0.5f);
    assert_close(getf(DARAN_PROP_CONTROLLER_INERTIA), 0.5f / (g * g));
    setf(DARAN_PROP_TRAP_TRAJ_VEL_LIMIT, 300.0f);
    setf(DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT, 30.0f);
    setf(DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT, 90.0f);
    assert_close(getf(DARAN_PROP_TRAP_VEL_LIMIT), 5.0f * g);
    assert_close(getf(DARAN_PROP_TRAP_ACCEL_LIMIT), 0.5f * g);
    assert_close(getf(DARAN_PROP_TRAP_DECEL_LIMIT), 1.5f * g);
    setf(DARAN_PROP_CIRCULAR_SETPOINT_MIN, -90.0f);
    setf(DARAN_PROP_CIRCULAR_SETPOINT_MAX, 180.0f);
    assert_close(getf(DARAN_PROP_EXTRA_CIRCULAR_SETPOINT_MIN), -0.25f * g);
    assert_close(getf(DARAN_PROP_EXTRA_CIRCULAR_SETPOINT_MAX), 0.5f * g);
    /* and the other way round */
    setf(DARAN_PROP_MOTOR_TORQUE_CONSTANT, 0.05f);
    assert_close(getf(DARAN_PROP_TORQUE_CONSTANT), 0.05f * g);
    setf(DARAN_PROP_TURNS_PER_STEP, g / 200.0f);
    assert_close(getf(DARAN_PROP_STEPS_PER_TURN), 200.0f);
    setf(DARAN_PROP_CONTROLLER_VEL_RAMP_RATE, 4.0f);
    assert_close(getf(DARAN_PROP_VEL_RAMP_RATE), 240.0f / g);
    setf(DARAN_PROP_CONTROLLER_TORQUE_RAMP_RATE, 0.25f);
    assert_close(getf(DARAN_PROP_TORQUE_RAMP_RATE), 0.25f * g);
    setf(DARAN_PROP_CONTROLLER_INERTIA, 1e-3f);
    assert_close(getf(DARAN_PROP_LOAD_INERTIA), 1e-3f * g * g);
    setf(DARAN_PROP_TRAP_VEL_LIMIT, 8.0f);
    setf(DARAN_PROP_TRAP_ACCEL_LIMIT, 2.0f);
    setf(DARAN_PROP_TRAP_DECEL_LIMIT, 0.0f);
    assert_close(getf(DARAN_PROP_TRAP_TRAJ_VEL_LIMIT), 480.0f / g);
    assert_close(getf(DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT), 120.0f / g);
    assert_true(getf(DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT) == 0.0f);
    setf(DARAN_PROP_EXTRA_CIRCULAR_SETPOINT_MAX, 2.0f * g);
    assert_close(getf(DARAN_PROP_CIRCULAR_SETPOINT_MAX), 720.0f);
    setf(DARAN_PROP_LOAD_INERTIA, 0.0f);
    setf(DARAN_PROP_TORQUE_CONSTANT, 0.1f);
    setf(DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT, 60.0f);

    /* setpoints and inputs, both ways */
    setf(DARAN_PROP_POS_SETPOINT, 36.0f);
    assert_close(getf(DARAN_PROP_CONTROLLER_POS_SETPOINT), 0.1f * g);
    assert_close(getf(DARAN_PROP_CONTROLLER_INPUT_POS), 0.1f * g);
    setf(DARAN_PROP_CONTROLLER_INPUT_POS, 0.25f * g);
    assert_close(getf(DARAN_PROP_INPUT_POS), 90.0f);
    setf(DARAN_PROP_CONTROLLER_POS_SETPOINT, -0.5f * g);
    assert_close(getf(DARAN_PROP_POS_SETPOINT), -180.0f);
    setf(DARAN_PROP_VEL_SETPOINT, 30.0f);
    assert_close(getf(DARAN_PROP_CONTROLLER_VEL_SETPOINT), 0.5f * g);
    assert_close(getf(DARAN_PROP_CONTROLLER_INPUT_VEL), 0.5f * g);
    setf(DARAN_PROP_CONTROLLER_INPUT_VEL, 2.0f * g);
    assert_close(getf(DARAN_PROP_INPUT_VEL), 120.0f);
    setf(DARAN_PROP_CONTROLLER_VEL_SETPOINT, -g);
    assert_close(getf(DARAN_PROP_VEL_SETPOINT), -60.0f);
    setf(DARAN_PROP_TORQUE_SETPOINT, 0.8f);
    assert_close(getf(DARAN_PROP_CONTROLLER_TORQUE_SETPOINT), 0.8f / g);
    assert_close(getf(DARAN_PROP_CONTROLLER_INPUT_TORQUE), 0.8f / g);
    setf(DARAN_PROP_CONTROLLER_INPUT_TORQUE, 0.1f / g);
    assert_close(getf(DARAN_PROP_INPUT_TORQUE), 0.1f);
    setf(DARAN_PROP_CONTROLLER_TORQUE_SETPOINT, 0.05f / g);
    assert_close(getf(DARAN_PROP_TORQUE_SETPOINT), 0.05f);

    /* estimates, after a real move */
    setf(DARAN_PROP_POS_SETPOINT, 45.0f);
    run(1.0);
    assert_close(getf(DARAN_PROP_ENCODER_POS_ESTIMATE),
                 getf(DARAN_PROP_POS_ESTIMATE) / 360.0f * g);
    setf(DARAN_PROP_VEL_SETPOINT, 6.0f);
    run(0.5);
    assert_close(getf(DARAN_PROP_ENCODER_VEL_ESTIMATE),
                 getf(DARAN_PROP_VEL_ESTIMATE) / 60.0f * g);
    setf(DARAN_PROP_POS_SETPOINT, 0.0f);
    run(1.0);
}

static void test_rotor_views_agree_with_the_output_shaft_at_gear_ratio_1(void **state)
{
    (void)state;
    check_views(1.0f);
}

static void test_rotor_views_agree_with_the_output_shaft_at_gear_ratio_8(void **state)
{
    (void)state;
    check_views(8.0f);
}

/* A rotor-side value that would not fit the stored one is refused, and
 * nothing changes. */
static void test_a_view_that_overflows_its_stored_value_is_refused(void **state)
{
    daran_value_t v;
    (void)state;
    setf(DARAN_PROP_GEAR_RATIO, 1e-30f);
    v.u64 = 0u;
    v.f32 = 3e38f;
    assert_int_equal(daran_sim_hal.set(&drive, DARAN_PROP_TRAP_VEL_LIMIT, v),
                     DARAN_ERR_OUT_OF_RANGE);
    assert_true(getf(DARAN_PROP_TRAP_TRAJ_VEL_LIMIT) == 600.0f);
    v.f32 = 0.0f;
    assert_int_equal(daran_sim_hal.set(&drive, DARAN_PROP_GEAR_RATIO, v), DARAN_ERR_OUT_OF_RANGE);
}

/* Gear 8, cpr 16384, shaft angle 100 deg: the rotor has turned 100/360*8 =
 * 2.2222 turns: turn_abs 2, pos_abs 0.2222*16384 = 3640.9 -> 3640. At -100
 * deg: -2.2222 turns: turn_abs -3, pos_abs 0.7778*16384 -> 12743. */
static void test_encoder_absolute_readings_count_the_rotor_angle(void **state)
{
    (void)state;
    setf(DARAN_PROP_GEAR_RATIO, 8.0f);
    m->raw_pos_deg = 100.0f;
    assert_int_equal(get(DARAN_PROP_ENCODER_TURN_ABS).s32, 2);
    assert_int_equal(get(DARAN_PROP_ENCODER_POS_ABS).s32, 3640);
    assert_close(getf(DARAN_PROP_ENCODER_POS_CIRCULAR), 0.222222f);
    m->raw_pos_deg = -100.0f;
    assert_int_equal(get(DARAN_PROP_ENCODER_TURN_ABS).s32, -3);
    assert_int_equal(get(DARAN_PROP_ENCODER_POS_ABS).s32, 12743);
    assert_close(getf(DARAN_PROP_ENCODER_POS_CIRCULAR), 0.777778f);
    assert_close(getf(DARAN_PROP_ENCODER_POS_ESTIMATE), -2.222222f);
    /* cpr 4096 */
    get(DARAN_PROP_ENCODER_CPR);
    {
        daran_value_t v;
        v.u64 = 0u;
        v.s32 = 4096;
        assert_int_equal(daran_sim_hal.set(&drive, DARAN_PROP_ENCODER_CPR, v), DARAN_OK);
    }
    assert_int_equal(get(DARAN_PROP_ENCODER_POS_ABS).s32, 3185);
}

/* sz at shaft angle 100 deg, gear 8: zero_offset_counts = 100/360*8*16384 =
 * 36408.9. Writing it moves the zero the same way: position jumps, the
 * setpoints jump with it, the shaft stays. */
static void test_zero_offset_counts_is_the_zero_offset_in_rotor_counts(void **state)
{
    (void)state;
    setf(DARAN_PROP_GEAR_RATIO, 8.0f);
    setf(DARAN_PROP_POS_SETPOINT, 100.0f);
    run(1.0);
    daran_sim_hal.action(&drive, DARAN_ACTION_SET_ZERO);
    assert_close(getf(DARAN_PROP_ZERO_OFFSET_COUNTS), m->raw_pos_deg / 360.0f * 8.0f * 16384.0f);
    assert_float_equal(getf(DARAN_PROP_ZERO_OFFSET_COUNTS), 36408.9f, 20.0f);
    assert_true(fabsf(getf(DARAN_PROP_POS_ESTIMATE)) < 1e-3f);
    setf(DARAN_PROP_ZERO_OFFSET_COUNTS, 0.0f);
    assert_close(getf(DARAN_PROP_POS_ESTIMATE), m->raw_pos_deg);
    assert_close(getf(DARAN_PROP_POS_SETPOINT), 100.0f);
    run(1.0);
    assert_float_equal(m->raw_pos_deg, 100.0f, 0.05f);
}

/* motor.config.torque_lim is rotor Nm: 0.1 at gear 8 allows 0.8 Nm at the
 * shaft, below output_shaft.torque_lim 2; the lower applies. */
static void test_motor_torque_lim_acts_at_the_shaft_times_the_gear_ratio(void **state)
{
    (void)state;
    setf(DARAN_PROP_GEAR_RATIO, 8.0f);
    setf(DARAN_PROP_MOTOR_TORQUE_LIM, 0.1f);
    assert_close(daran_sim_model_torque_limit(m), 0.8f);
    setf(DARAN_PROP_SHAFT_TORQUE_LIM, 0.5f);
    assert_close(daran_sim_model_torque_limit(m), 0.5f);
    /* controller.config.vel_limit is rotor turn/s: 10 at gear 8 = 75 r/min */
    assert_close(daran_sim_model_vel_limit_rpm(m), 75.0f);
}

/* The controller works rotor-side as ODrive's does: at gear 8 the rotor's
 * inertia counts 64 times at the shaft and so do the gains, so a small step
 * (no saturation) follows the same course as at gear 1 (with the plant's
 * friction scaled by g^2 as well). */
static void test_a_geared_drive_keeps_the_dynamics_of_its_rotor(void **state)
{
    static daran_sim_drive_t direct;
    int k;
    float worst = 0.0f;
    (void)state;
    daran_sim_drive_init(&direct, 1u, 1000u);
    setf(DARAN_PROP_GEAR_RATIO, 8.0f);
    m->par.viscous_friction *= 64.0f; /* the friction scaled alike */
    m->par.coulomb_friction *= 64.0f;
    setf(DARAN_PROP_POS_SETPOINT, 0.5f);
    {
        daran_value_t v;
        v.u64 = 0u;
        v.f32 = 0.5f;
        assert_int_equal(daran_sim_hal.set(&direct, DARAN_PROP_POS_SETPOINT, v), DARAN_OK);
    }
    for (k = 0; k < 500; k++) {
        daran_sim_model_tick(m);
        daran_sim_model_tick(&direct.model);
        if (fabsf(daran_sim_model_pos_deg(m) - daran_sim_model_pos_deg(&direct.model)) > worst) {
            worst = fabsf(daran_sim_model_pos_deg(m) - daran_sim_model_pos_deg(&direct.model));
        }
    }
    print_message("0.5 deg step, gear 8 against gear 1: largest difference %.2g deg\n",
                  (double)worst);
    assert_true(worst < 1e-3f);
    assert_float_equal(daran_sim_model_pos_deg(m), 0.5f, 0.02f);
}

/* 0.5 Nm into a blocked shaft: Iq = Iq_setpoint = 5 A, Id = 0, the bridge
 * puts out R Iq = 1.5 V (the shaft stands: no back-EMF, no cross-coupling),
 * Ibus = ibus. */
static void test_motor_measurements_follow_the_model(void **state)
{
    float va;
    float vb;
    (void)state;
    setf(DARAN_PROP_LOAD_INERTIA, 1.0e6f);
    setf(DARAN_PROP_TORQUE_SETPOINT, 0.5f);
    run(0.1);
    assert_close(getf(DARAN_PROP_IQ_SETPOINT), 5.0f);
    assert_float_equal(getf(DARAN_PROP_IQ_MEASURED), 5.0f, 1e-3f);
    assert_true(getf(DARAN_PROP_ID_MEASURED) == 0.0f);
    assert_true(getf(DARAN_PROP_ID_SETPOINT) == 0.0f);
    assert_true(getf(DARAN_PROP_IBUS_MEASURED) == getf(DARAN_PROP_IBUS));
    va = getf(DARAN_PROP_FINAL_V_ALPHA);
    vb = getf(DARAN_PROP_FINAL_V_BETA);
    assert_float_equal(sqrtf(va * va + vb * vb), 1.5f, 1e-3f);
    assert_close(getf(DARAN_PROP_EFFECTIVE_CURRENT_LIM), 25.0f);
    setf(DARAN_PROP_REQUESTED_CURRENT_RANGE, 10.0f);
    assert_close(getf(DARAN_PROP_EFFECTIVE_CURRENT_LIM), 9.8f);
    assert_close(daran_sim_model_torque_limit(m), 0.98f);
    assert_int_equal(get(DARAN_PROP_MOTOR_IS_CALIBRATED).u32, 1u);
    assert_int_equal(get(DARAN_PROP_ENCODER_IS_READY).u32, 1u);
    assert_int_equal(get(DARAN_PROP_ENCODER_INDEX_FOUND).u32, 1u);
    assert_true(getf(DARAN_PROP_ENCODER_BATTERY_VOLTAGE) > 3.0f);
    assert_true(getf(DARAN_PROP_ENCODER_VOLTAGE) > 3.0f);
    /* idle: the bridge is off */
    setu(DARAN_PROP_REQUESTED_STATE, DARAN_STATE_IDLE);
    run(0.01);
    assert_true(getf(DARAN_PROP_FINAL_V_ALPHA) == 0.0f);
    assert_true(getf(DARAN_PROP_IQ_MEASURED) == 0.0f);
}

static void test_serial_number_halves_are_its_low_and_high_words(void **state)
{
    (void)state;
    assert_int_equal(get(DARAN_PROP_SERIAL_NUMBER_L).u32, 2026000001u);
    assert_int_equal(get(DARAN_PROP_SERIAL_NUMBER_H).u32, 0u);
    drive.serial_number = 0x123456789ABCDEF0ull;
    assert_int_equal(get(DARAN_PROP_SERIAL_NUMBER_L).u32, 0x9ABCDEF0u);
    assert_int_equal(get(DARAN_PROP_SERIAL_NUMBER_H).u32, 0x12345678u);
}

/* A q's cruise and rate are the trap_traj properties: q 1 90 30 60 sets
 * vel_limit 30 r/min (0.5 turn/s rotor) and accel = decel 60 (r/min)/s
 * (1 (turn/s)/s). */
static void test_q_settings_are_the_trap_traj_properties(void **state)
{
    daran_move_t q = {DARAN_MOVE_TRAPEZOID, DARAN_GIVEN_VEL | DARAN_GIVEN_RATE, 90.0f, 30.0f,
                      0.0f, 60.0f, 0.0f, 0.0f};
    (void)state;
    assert_int_equal(daran_sim_hal.move(&drive, &q), DARAN_OK);
    assert_close(getf(DARAN_PROP_TRAP_TRAJ_VEL_LIMIT), 30.0f);
    assert_close(getf(DARAN_PROP_TRAP_TRAJ_ACCEL_LIMIT), 60.0f);
    assert_close(getf(DARAN_PROP_TRAP_TRAJ_DECEL_LIMIT), 60.0f);
    assert_close(getf(DARAN_PROP_TRAP_VEL_LIMIT), 0.5f);
    assert_close(getf(DARAN_PROP_TRAP_ACCEL_LIMIT), 1.0f);
    assert_close(getf(DARAN_PROP_TRAP_DECEL_LIMIT), 1.0f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_every_property_reads_and_every_writable_one_takes_a_new_value, setup),
        cmocka_unit_test_setup(test_error_registers_take_only_zero, setup),
        cmocka_unit_test_setup(test_rotor_views_agree_with_the_output_shaft_at_gear_ratio_1, setup),
        cmocka_unit_test_setup(test_rotor_views_agree_with_the_output_shaft_at_gear_ratio_8, setup),
        cmocka_unit_test_setup(test_a_view_that_overflows_its_stored_value_is_refused, setup),
        cmocka_unit_test_setup(test_encoder_absolute_readings_count_the_rotor_angle, setup),
        cmocka_unit_test_setup(test_zero_offset_counts_is_the_zero_offset_in_rotor_counts, setup),
        cmocka_unit_test_setup(test_motor_torque_lim_acts_at_the_shaft_times_the_gear_ratio, setup),
        cmocka_unit_test_setup(test_a_geared_drive_keeps_the_dynamics_of_its_rotor, setup),
        cmocka_unit_test_setup(test_motor_measurements_follow_the_model, setup),
        cmocka_unit_test_setup(test_serial_number_halves_are_its_low_and_high_words, setup),
        cmocka_unit_test_setup(test_q_settings_are_the_trap_traj_properties, setup),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
